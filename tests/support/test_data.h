#pragma once
// Real third-party inputs (packs, glTF samples) the repository does not hold: core/paths.h testDataDir
// finds them ($TERRASOL_TESTDATA, else shared/testdata beside the data root). A test that needs them is
// skipped, with the reason, where they are absent.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/paths.h"

namespace terrasol::testing {

// The test data folder, or an empty path (then testDataMissing() says why).
inline std::filesystem::path testData() {
  return testDataDir().value_or(std::filesystem::path());
}
inline std::string testDataMissing() {
  std::string why;
  testDataDir(&why);
  return why;
}

}  // namespace terrasol::testing

// In a test body or SetUp(): skips the test when the third-party test data is absent.
#define TERRASOL_SKIP_WITHOUT_TEST_DATA()                                                                \
  do {                                                                                                   \
    if (::terrasol::testing::testData().empty()) GTEST_SKIP() << ::terrasol::testing::testDataMissing(); \
  } while (0)
