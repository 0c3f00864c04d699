#include "core/paths.h"

#include <gtest/gtest.h>
#include <unistd.h>

namespace terrasol {
namespace {

// ctest runs each test in its own process, so dataRoot() is first computed after the chdir.
TEST(Paths, DataIsFoundFromAnyWorkingDirectory) {
  ASSERT_EQ(chdir("/"), 0);
  EXPECT_TRUE(std::filesystem::is_regular_file(shaderDir() / "gbuffer.vert"));
  EXPECT_TRUE(std::filesystem::is_regular_file(resourcePackDir() / "default" / "pack.mcmeta"));
  EXPECT_TRUE(std::filesystem::equivalent(dataRoot(), TERRASOL_SOURCE_DIR));
}

}  // namespace
}  // namespace terrasol
