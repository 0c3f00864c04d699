#include "core/assert.h"

#include <gtest/gtest.h>

#include <string>

namespace terrasol {
namespace {

TEST(AssertDeathTest, AFailureNamesTheFileLineConditionAndMessage) {
  const int sections = 24;
  EXPECT_DEATH(TERRASOL_ASSERT(sections < 16), "assert_test.cpp:[0-9]+: assertion failed: sections < 16\n");
  EXPECT_DEATH(TERRASOL_ASSERT(sections < 16, "section " + std::to_string(sections)),
               "assertion failed: sections < 16: section 24");
}

TEST(Assert, APassingCheckBuildsNoMessage) {
  int built = 0;
  const auto message = [&] {
    ++built;
    return std::string("never");
  };
  TERRASOL_ASSERT(built == 0, message());
  EXPECT_EQ(built, 0);
}

}  // namespace
}  // namespace terrasol
