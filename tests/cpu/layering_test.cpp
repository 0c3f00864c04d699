// Keeps the arrows between folders pointing one way (docs/architecture.md): a folder may include
// only the folders listed for it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "support/world_support.h"

namespace {

// The engine folders each engine folder may include: its own and those it links.
const std::map<std::string, std::set<std::string>> kAllowed = {
    {"core", {"core"}},
    {"world", {"core", "world"}},
    {"minecraft", {"core", "world", "minecraft"}},
    {"light", {"core", "world", "light"}},
    {"lod", {"core", "world", "lod"}},
    {"mesh", {"core", "world", "mesh"}},
    {"assets", {"core", "assets"}},
    {"audio", {"core", "assets", "audio"}},
    {"shaderpack", {"core", "world", "assets", "shaderpack"}},
    {"render", {"core", "assets", "mesh", "lod", "render"}},
    {"pack_render", {"core", "world", "assets", "mesh", "lod", "render", "shaderpack", "pack_render"}},
    {"platform", {"core", "platform"}},
    {"scene", {"core", "world", "minecraft", "light", "lod", "mesh", "assets", "scene"}},
    {"pipeline", {"core", "world", "minecraft", "light", "mesh", "pipeline"}},
    {"scene_render",
     {"core", "world", "minecraft", "light", "lod", "mesh", "assets", "render", "shaderpack", "pack_render",
      "scene", "scene_render"}},
};

const std::set<std::string> kEngine = [] {
  std::set<std::string> folders;
  for (const auto& [folder, allowed] : kAllowed) folders.insert(folder);
  return folders;
}();

// One wrong-way include, named by file and line.
struct Violation {
  std::string where, what;
};

// Checks every source file under `root`/`area`: an include with a folder ("render/x.h") must name an
// engine folder that `allowed(folder)` admits; one without ("x.h") must be a file beside the
// includer, so game/ and tools/ (leaves over the engine) are reached by no other folder.
std::vector<Violation> check(const std::filesystem::path& root, const std::string& area,
                             const std::function<std::set<std::string>(const std::string&)>& allowed,
                             int* files) {
  const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<Violation> found;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root / area)) {
    const auto ext = entry.path().extension();
    if (ext != ".h" && ext != ".cpp") continue;
    ++*files;
    const std::string folder = *std::filesystem::relative(entry.path(), root / area).begin();
    const std::set<std::string> ok = allowed(folder);
    std::ifstream in(entry.path());
    int lineNo = 0;
    for (std::string line; std::getline(in, line);) {
      ++lineNo;
      std::smatch m;
      if (!std::regex_search(line, m, include)) continue;
      const std::string target = m[1].str();
      const auto slash = target.find('/');
      const std::string where = entry.path().string() + ":" + std::to_string(lineNo);
      if (slash == std::string::npos) {
        if (!std::filesystem::exists(entry.path().parent_path() / target)) {
          found.push_back(
              {where, "includes \"" + target + "\", which is not beside it (another folder's own header)"});
        }
      } else if (const std::string prefix = target.substr(0, slash); !kEngine.contains(prefix)) {
        found.push_back({where, "includes " + prefix + "/, which is not an engine folder"});
      } else if (!ok.contains(prefix)) {
        found.push_back({where, area + "/" + folder + " must not include " + prefix + "/"});
      }
    }
  }
  return found;
}

std::string describe(const std::vector<Violation>& violations) {
  std::string text;
  for (const Violation& v : violations) text += v.where + ": " + v.what + "\n";
  return text;
}

const std::filesystem::path kRoot = TERRASOL_SOURCE_DIR;

TEST(Layering, EngineFoldersIncludeOnlyWhatTheyMayDependOn) {
  int files = 0;
  const auto violations = check(
      kRoot, "engine",
      [](const std::string& folder) {
        EXPECT_TRUE(kAllowed.contains(folder)) << "engine/" << folder << " has no layering rule here";
        return kAllowed.contains(folder) ? kAllowed.at(folder) : std::set<std::string>{};
      },
      &files);
  EXPECT_TRUE(violations.empty()) << describe(violations);
  EXPECT_GT(files, 100);
}

// game/ and tools/ are leaves: they include the engine and their own folder's files, never each other's.
TEST(Layering, GameAndToolsAreLeavesOverTheEngine) {
  int files = 0;
  const auto engine = [](const std::string&) { return kEngine; };
  auto violations = check(kRoot, "game", engine, &files);
  const auto tools = check(kRoot, "tools", engine, &files);
  violations.insert(violations.end(), tools.begin(), tools.end());
  EXPECT_TRUE(violations.empty()) << describe(violations);
  EXPECT_GT(files, 40);
}

// The check itself: a wrong-way include and a header reached across folders are both caught.
TEST(Layering, TheCheckCatchesAWrongWayIncludeAndAnotherFoldersHeader) {
  const auto dir = terrasol::testing::scratchDir("layering");
  std::filesystem::create_directories(dir / "engine" / "world");
  std::ofstream(dir / "engine" / "world" / "bad.cpp")
      << "#include \"render/gbuffer.h\"\n#include \"game_world.h\"\n";
  int files = 0;
  const auto violations = check(
      dir, "engine", [](const std::string& f) { return kAllowed.at(f); }, &files);
  ASSERT_EQ(violations.size(), 2u) << describe(violations);
  EXPECT_NE(violations[0].what.find("engine/world must not include render/"), std::string::npos);
  EXPECT_NE(violations[1].what.find("game_world.h"), std::string::npos);
}

}  // namespace
