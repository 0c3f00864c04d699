// Keeps the arrows between folders pointing one way (docs/architecture.md): a folder may include
// only the folders listed for it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>

namespace {

const std::map<std::string, std::set<std::string>> kAllowed = {
    {"core", {"core"}},
    {"world", {"core", "world"}},
    {"light", {"core", "world", "light"}},
    {"mesh", {"core", "world", "mesh"}},
    {"assets", {"core", "assets"}},
    {"render", {"core", "assets", "mesh", "render"}},
    {"platform", {"core", "platform"}},
    {"scene", {"core", "world", "light", "mesh", "assets", "scene"}},
};

TEST(Layering, EngineFoldersIncludeOnlyWhatTheyMayDependOn) {
  const std::filesystem::path engine = std::filesystem::path(TERRASOL_SOURCE_DIR) / "engine";
  const std::regex include(R"re(^\s*#\s*include\s*"([a-z_]+)/)re");
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(engine)) {
    const auto ext = entry.path().extension();
    if (ext != ".h" && ext != ".cpp") continue;
    ++files;
    const std::string folder = *std::filesystem::relative(entry.path(), engine).begin();
    ASSERT_TRUE(kAllowed.contains(folder)) << "engine/" << folder << " has no layering rule here";
    std::ifstream in(entry.path());
    int lineNo = 0;
    for (std::string line; std::getline(in, line);) {
      ++lineNo;
      std::smatch m;
      if (std::regex_search(line, m, include) && !kAllowed.at(folder).contains(m[1].str())) {
        ADD_FAILURE() << entry.path().string() << ":" << lineNo << ": engine/" << folder << " must not include "
                      << m[1].str() << "/";
      }
    }
  }
  EXPECT_GT(files, 10);
}

}  // namespace
