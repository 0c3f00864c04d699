// Shader packs read: programs and OptiFine's fallbacks, world0/, includes as packs write them, the
// macros, the conditionals of .properties files and block.properties. The two packs in
// tests/shaderpacks are real (shaderLABS' Shadow-Tutorial and Base-330, public domain).

#include "shaderpack/shader_pack.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "core/paths.h"
#include "shaderpack/block_properties.h"
#include "shaderpack/pack_directives.h"
#include "shaderpack/pack_macros.h"
#include "shaderpack/pack_settings.h"
#include "support/error_of.h"
#include "support/world_support.h"
#include "support/zip_writer.h"

namespace terrasol {
namespace {

std::filesystem::path vendored(const std::string& name) {
  return std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "shaderpacks" / name;
}

// A pack on disk of `files` (paths inside the pack).
std::filesystem::path writePack(const std::string& name,
                                const std::vector<std::pair<std::string, std::string>>& files) {
  const auto dir = testing::scratchDir(name);
  std::filesystem::remove_all(dir);
  for (const auto& [path, text] : files) {
    std::filesystem::create_directories((dir / path).parent_path());
    std::ofstream(dir / path) << text;
  }
  return dir;
}

using testing::errorOf;

TEST(ShaderPack, TheTestPacksProgramsAreFoundAndFallBackAsInOptiFine) {
  const ShaderPack tutorial = ShaderPack::open(vendored("Shadow-Tutorial"));
  EXPECT_EQ(tutorial.name(), "Shadow-Tutorial");
  const std::vector<std::string> programs = tutorial.programs();
  EXPECT_EQ(programs.size(), 13u);
  EXPECT_EQ(programs.front(), "shadow") << "in the frame's order";
  EXPECT_EQ(programs.back(), "composite");
  EXPECT_FALSE(tutorial.program("gbuffers_water"));
  EXPECT_EQ(tutorial.resolve("gbuffers_water")->name, "gbuffers_terrain");
  EXPECT_EQ(tutorial.resolve("gbuffers_item")->name, "gbuffers_textured") << "item, textured_lit, textured";
  EXPECT_FALSE(tutorial.resolve("final")) << "no fallback: not drawn";
  const std::optional<PackProgram> terrain = tutorial.program("gbuffers_terrain");
  ASSERT_TRUE(terrain);
  EXPECT_EQ(terrain->vertex, "gbuffers_terrain.vsh");
  EXPECT_EQ(terrain->fragment, "gbuffers_terrain.fsh");
  EXPECT_TRUE(terrain->geometry.empty());

  const ShaderPack base = ShaderPack::open(vendored("Base-330"));
  EXPECT_EQ(base.programs().size(), 18u);
  EXPECT_EQ(base.resolve("gbuffers_water")->name, "gbuffers_water");
}

// Every stage of both packs preprocesses with OptiFine's macros; lines from an include map back to it.
TEST(ShaderPack, EveryStageOfTheTestPacksPreprocesses) {
  for (const char* name : {"Shadow-Tutorial", "Base-330"}) {
    const ShaderPack pack = ShaderPack::open(vendored(name));
    for (const std::string& program : pack.programs()) {
      const PackProgram p = *pack.program(program);
      for (const std::string& stage : {p.vertex, p.fragment}) {
        const PreprocessedShader s = pack.source(stage, packMacros());
        EXPECT_NE(s.text.find("#define MC_VERSION 12111"), std::string::npos) << stage;
        EXPECT_EQ(s.text.find("#include"), std::string::npos) << stage;
      }
    }
  }
  const ShaderPack tutorial = ShaderPack::open(vendored("Shadow-Tutorial"));
  const PreprocessedShader shadow = tutorial.source("shadow.vsh", packMacros());
  bool fromDistort = false;
  for (const SourceLocation& l : shadow.lines) fromDistort |= l.file.ends_with("shaders/distort.glsl");
  EXPECT_TRUE(fromDistort) << "distort.glsl's lines are named as its own";
}

TEST(ShaderPack, IncludesAreRelativeOrFromTheRootAndExpandedEachTime) {
  const auto dir = writePack(
      "shaderpack_includes",
      {{"shaders/composite.vsh",
        "#version 120\n#include \"lib/a.glsl\"\n#include \"/lib/b.glsl\"\nvoid main() {}\n"},
       {"shaders/composite.fsh", "#version 120\n#include \"lib/b.glsl\"\n#include \"lib/b.glsl\"\n"},
       {"shaders/lib/a.glsl", "// a\n#include \"b.glsl\"\n"},
       {"shaders/lib/b.glsl", "float b = 1.0;\n"},
       {"shaders/loop.vsh", "#version 120\n#include \"lib/loop1.glsl\"\n"},
       {"shaders/lib/loop1.glsl", "#include \"loop2.glsl\"\n"},
       {"shaders/lib/loop2.glsl", "\n#include \"/lib/loop1.glsl\"\n"},
       {"shaders/deep.vsh", "#version 120\n#include \"d0.glsl\"\n"},
       {"shaders/missing.vsh", "#version 120\n\n#include \"nowhere.glsl\"\n"}});
  for (int i = 0; i < 12; ++i) {
    std::string file = "d";  // built up: GCC 12 warns wrongly on a chain of + here
    file += std::to_string(i);
    file += ".glsl";
    std::ofstream(dir / "shaders" / file) << "#include \"d" << i + 1 << ".glsl\"\n";
  }
  std::ofstream(dir / "shaders" / "d12.glsl") << "float deep;\n";
  const ShaderPack pack = ShaderPack::open(dir);
  const PreprocessedShader v = pack.source("composite.vsh", {});
  // a.glsl's "b.glsl" is lib/b.glsl, beside it; "/lib/b.glsl" is from shaders/; both expand.
  EXPECT_EQ(v.text, "#version 120\n// a\nfloat b = 1.0;\nfloat b = 1.0;\nvoid main() {}\n");
  EXPECT_EQ(v.origin(3).file, pack.displayName("lib/b.glsl"));
  EXPECT_EQ(v.origin(3).line, 1);
  EXPECT_EQ(pack.source("composite.fsh", {}).text, "#version 120\nfloat b = 1.0;\nfloat b = 1.0;\n")
      << "a pack's includes are not once-only: packs guard their own";
  const std::string loop = errorOf([&] { pack.source("loop.vsh", {}); });
  EXPECT_NE(loop.find("lib/loop2.glsl:2"), std::string::npos) << loop;
  EXPECT_NE(loop.find("includes itself"), std::string::npos) << loop;
  const std::string deep = errorOf([&] { pack.source("deep.vsh", {}); });
  EXPECT_NE(deep.find("deeper than 10"), std::string::npos) << deep;
  const std::string missing = errorOf([&] { pack.source("missing.vsh", {}); });
  EXPECT_NE(missing.find("missing.vsh:3"), std::string::npos) << missing;
  EXPECT_NE(missing.find("nowhere.glsl"), std::string::npos) << missing;
}

// A zipped pack reads as the folder does, its messages naming the archive.
TEST(ShaderPack, AZippedPackReadsAsAFolder) {
  const auto zip = testing::scratchDir("shaderpack_zip") / "Zipped.zip";
  testing::writeZip(zip, {{"shaders/composite.vsh", "#version 120\n#include \"lib/x.glsl\"\n"},
                          {"shaders/composite.fsh", "#version 120\n"},
                          {"shaders/lib/x.glsl", "float x;\n"},
                          {"shaders/block.properties", "block.1=stone\n"}});
  const ShaderPack pack = ShaderPack::open(zip);
  EXPECT_EQ(pack.name(), "Zipped.zip");
  EXPECT_EQ(pack.programs(), std::vector<std::string>{"composite"});
  const PreprocessedShader s = pack.source("composite.vsh", {});
  EXPECT_EQ(s.text, "#version 120\nfloat x;\n");
  EXPECT_TRUE(s.origin(2).file.ends_with("/Zipped.zip!shaders/lib/x.glsl")) << s.origin(2).file;
  EXPECT_EQ(pack.text("block.properties"), "block.1=stone\n");
}

TEST(ShaderPack, World0ProgramsReplaceTheRootsAndAFolderWithoutShadersIsRefused) {
  const auto dir =
      writePack("shaderpack_world0", {{"shaders/gbuffers_terrain.vsh", "#version 120\n"},
                                      {"shaders/gbuffers_terrain.fsh", "#version 120\n"},
                                      {"shaders/composite.vsh", "#version 120\n"},
                                      {"shaders/composite.fsh", "#version 120\n"},
                                      {"shaders/world0/gbuffers_terrain.vsh", "#version 120\n"},
                                      {"shaders/world0/gbuffers_terrain.fsh", "#version 120\n"}});
  const ShaderPack pack = ShaderPack::open(dir);
  EXPECT_EQ(pack.program("gbuffers_terrain")->vertex, "world0/gbuffers_terrain.vsh");
  EXPECT_FALSE(pack.program("composite")) << "where world0/ exists, only its programs count";
  const auto empty = writePack("shaderpack_none", {{"readme.txt", "no shaders here"}});
  const std::string refused = errorOf([&] { ShaderPack::open(empty); });
  EXPECT_NE(refused.find("no shaders/ folder"), std::string::npos) << refused;
}

TEST(PackConditions, ExpressionsFollowCsPrecedenceAndMacros) {
  PackMacros m(packMacros());
  m.define("SHADOWS");
  m.define("QUALITY", "2");
  m.define("TWICE", "QUALITY * 2");
  const auto eval = [&](const char* e) { return m.evaluate(e, "test:1"); };
  EXPECT_EQ(eval("MC_VERSION >= 11300"), 1.0);
  EXPECT_EQ(eval("MC_VERSION < 11300"), 0.0);
  EXPECT_EQ(eval("1 + 2 * 3"), 7.0);
  EXPECT_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_EQ(eval("1 || 0 && 0"), 1.0) << "&& binds tighter";
  EXPECT_EQ(eval("!defined(SHADOWS) || defined NOPE"), 0.0);
  EXPECT_EQ(eval("UNKNOWN == 0"), 1.0) << "an unknown name is 0";
  EXPECT_EQ(eval("TWICE == 4 && -QUALITY < 0"), 1.0);
  EXPECT_EQ(eval("MC_RENDER_QUALITY > 0.5"), 1.0);
  EXPECT_EQ(eval("7 % 4 != 3"), 0.0);
  for (const char* bad : {"1 +", "(1", "1 / 0", "2 3", "defined()", "@"}) {
    const std::string e = errorOf([&] { m.evaluate(bad, "pack/block.properties:7"); });
    EXPECT_NE(e.find("pack/block.properties:7"), std::string::npos) << bad << ": " << e;
  }
}

TEST(PackConditions, ConditionalsKeepTheirBranchesLines) {
  PackMacros m;
  m.define("A");
  const auto kept = keptLines(
      "one\n#if defined A\ntwo\n#if 0\nno\n#elif 1\nthree\n#else\nno\n#endif\n#else\nno\n"
      "#endif\n#ifndef A\nno\n#else\nfour\n#endif\n#define B 3\n#if B == 3\nfive\n#endif\n",
      "f", m);
  std::vector<std::string> texts;
  for (const KeptLine& l : kept) texts.push_back(l.text);
  EXPECT_EQ(texts, (std::vector<std::string>{"one", "two", "three", "four", "five"}));
  EXPECT_EQ(kept[2].number, 7);
  PackMacros none;
  EXPECT_NE(errorOf([&] {
              keptLines("#if 1\nx\n", "p.properties", none);
            }).find("p.properties:1: #if without #endif"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { keptLines("x\n#endif\n", "p.properties", none); }).find("p.properties:2"),
            std::string::npos);
}

// Shadow-Tutorial's block.properties for 1.13 and later: saplings, flowers, crops and fire get 10000;
// its "grass", short_grass since 1.20.3, is found by the registry's older names.
TEST(BlockProperties, TheTutorialsMapsPlantsOntoTerrasolsStates) {
  const BlockRegistry& blocks = testing::defaultBlocks();
  const ShaderPack tutorial = ShaderPack::open(vendored("Shadow-Tutorial"));
  const BlockIdMap map =
      parseBlockProperties(*tutorial.text("block.properties"), tutorial.displayName("block.properties"),
                           PackMacros(packMacros()), blocks);
  EXPECT_EQ(map.ids[blocks.id("oak_sapling")], 10000);
  EXPECT_EQ(map.ids[blocks.id("wheat[age=7]")], 10000);
  EXPECT_EQ(map.ids[blocks.id("fire[age=3]")], 10000) << "every state of a block named without properties";
  EXPECT_EQ(map.ids[blocks.id("stone")], -1);
  EXPECT_EQ(map.ids[blocks.id("short_grass")], 10000);
  EXPECT_TRUE(map.unknown.empty()) << "the #else branch's pre-1.13 names (tallgrass, reeds) are not read";
  EXPECT_GT(map.mappedStates(), 100);
}

TEST(BlockProperties, PropertiesFiltersContinuationsAndErrors) {
  const BlockRegistry& blocks = testing::defaultBlocks();
  const BlockIdMap map = parseBlockProperties(
      "# water first\nblock.8=minecraft:water \\\n  oak_log:axis=y\nblock.9=oak_log mod:gadget\n"
      "block.10=oak_leaves:persistent=true:distance=1,2\nlayer.cutout=oak_leaves\n",
      "block.properties", PackMacros(), blocks);
  EXPECT_EQ(map.ids[blocks.id("water")], 8);
  EXPECT_EQ(map.ids[blocks.id("oak_log[axis=y]")], 8) << "named first, kept";
  EXPECT_EQ(map.ids[blocks.id("oak_log[axis=x]")], 9);
  EXPECT_EQ(map.ids[blocks.id("oak_leaves[persistent=true,distance=2]")], 10);
  EXPECT_EQ(map.ids[blocks.id("oak_leaves[persistent=true,distance=3]")], -1);
  EXPECT_EQ(map.ids[blocks.id("oak_leaves[persistent=false,distance=1]")], -1);
  EXPECT_EQ(map.unknown, std::vector<std::string>{"gadget"});
  const std::string bad =
      errorOf([&] { parseBlockProperties("\nblock.x1=stone\n", "bp", PackMacros(), blocks); });
  EXPECT_NE(bad.find("bp:2"), std::string::npos) << bad;
  const std::string noValue =
      errorOf([&] { parseBlockProperties("block.1=oak_log:axis=\n", "bp", PackMacros(), blocks); });
  EXPECT_NE(noValue.find("bp:1"), std::string::npos) << noValue;
}

TEST(PackDirectives, TheTestPacksOutputsAndConstants) {
  const ShaderPack tutorial = ShaderPack::open(vendored("Shadow-Tutorial"));
  const ProgramDirectives terrain = parseDirectives(tutorial.source("gbuffers_terrain.fsh", packMacros()));
  EXPECT_EQ(terrain.drawBuffers, std::vector<int>{0});
  EXPECT_EQ(terrain.flag("shadowtex0Nearest"), true);
  EXPECT_EQ(parseDirectives(tutorial.source("shadow.vsh", packMacros())).number("shadowMapResolution"),
            1024.0)
      << "from distort.glsl, which shadow.vsh includes";
  EXPECT_EQ(parseDirectives(tutorial.source("gbuffers_skybasic.fsh", packMacros())).number("sunPathRotation"),
            30.0);
  const ShaderPack base = ShaderPack::open(vendored("Base-330"));
  EXPECT_EQ(parseDirectives(base.source("gbuffers_block.fsh", packMacros())).drawBuffers,
            std::vector<int>{0});
}

TEST(PackDirectives, TheLastListWinsRenderTargetsFirstAndBadListsNameTheirLine) {
  const auto dir = writePack(
      "shaderpack_directives",
      {{"shaders/a.fsh",
        "#version 120\n/* DRAWBUFFERS:0257 */\n/*DRAWBUFFERS: 13 */\n// const int shadowMapResolution = "
        "4096;\n"
        "const float shadowDistance = 120.0f;\nconst vec4 colortex1ClearColor = vec4(0.0, 0.0, 0.0, 1.0);\n"
        "/*\nconst int colortex0Format = RGBA16F;\n*/\n"},
       {"shaders/b.fsh", "#version 330\n/* RENDERTARGETS: 0, 2 ,11 */\n/* DRAWBUFFERS:01 */\n"},
       {"shaders/c.fsh", "#version 120\n#include \"lib/out.glsl\"\n"},
       {"shaders/lib/out.glsl", "\n/* DRAWBUFFERS:0a */\n"},
       {"shaders/d.fsh", "#version 330\n/* RENDERTARGETS: 0,16 */\n"},
       {"shaders/e.fsh", "#version 330\n/* RENDERTARGETS: 3,3 */\n"},
       {"shaders/f.fsh", "#version 120\n/* DRAWBUFFERS:012345678 */\n"}});
  const ShaderPack pack = ShaderPack::open(dir);
  const ProgramDirectives a = parseDirectives(pack.source("a.fsh", {}));
  EXPECT_EQ(a.drawBuffers, (std::vector<int>{1, 3}));
  EXPECT_FALSE(a.number("shadowMapResolution")) << "a commented-out const is no directive";
  EXPECT_EQ(a.number("shadowDistance"), 120.0);
  EXPECT_EQ(a.constants.at("colortex1ClearColor"), "vec4(0.0, 0.0, 0.0, 1.0)");
  EXPECT_EQ(a.constants.at("colortex0Format"), "RGBA16F") << "read inside a block comment, as packs write it";
  EXPECT_EQ(parseDirectives(pack.source("b.fsh", {})).drawBuffers, (std::vector<int>{0, 2, 11}));
  const std::string c = errorOf([&] { parseDirectives(pack.source("c.fsh", {})); });
  EXPECT_NE(c.find("shaders/lib/out.glsl:2"), std::string::npos) << c;
  for (const char* bad : {"d.fsh", "e.fsh", "f.fsh"}) {
    const std::string e = errorOf([&] { parseDirectives(pack.source(bad, {})); });
    EXPECT_NE(e.find(std::string(bad) + ":2"), std::string::npos) << e;
  }
}

TEST(PackSettings, TheTutorialsShadowAndSunSettings) {
  const ShaderPack tutorial = ShaderPack::open(vendored("Shadow-Tutorial"));
  std::vector<ProgramDirectives> directives;
  for (const std::string& name : tutorial.programs()) {
    const PackProgram p = *tutorial.program(name);
    for (const std::string& stage : {p.vertex, p.fragment})
      directives.push_back(parseDirectives(tutorial.source(stage, packMacros())));
  }
  const PackSettings s = packSettings(directives, tutorial.name());
  EXPECT_EQ(s.shadowMapResolution, 1024);
  EXPECT_EQ(s.sunPathRotation, 30.0f);
  EXPECT_EQ(s.shadowDistance, 160.0f) << "OptiFine's default";
  EXPECT_EQ(s.shadowtexNearest, (std::array<bool, 2>{true, true}));
  EXPECT_EQ(s.shadowcolorNearest, (std::array<bool, 2>{true, false}));
  EXPECT_EQ(s.buffers[0].format.name, "RGBA8");
  EXPECT_TRUE(s.buffers[0].clear);
  EXPECT_FALSE(s.buffers[0].clearColor);
}

TEST(PackSettings, BufferFormatsClearsAndMipmapsByEitherName) {
  ProgramDirectives first, later;
  first.constants = {{"colortex2Format", "RGBA16F"},
                     {"gaux1Format", "R11F_G11F_B10F"},
                     {"colortex3Clear", "false"},
                     {"colortex5ClearColor", "vec4(0.5)"},
                     {"colortex6ClearColor", "vec4(1.0, 0.0, 0.0f, 1.0)"},
                     {"gdepthMipmapEnabled", "true"},
                     {"shadowDistance", "120.0f"},
                     {"noiseTextureResolution", "512"}};
  later.constants = {{"colortex2Format", "RGB8"}};
  const PackSettings s = packSettings({first, later}, "pack");
  EXPECT_EQ(s.buffers[2].format.name, "RGB8") << "the later program's";
  EXPECT_EQ(s.buffers[4].format.name, "R11F_G11F_B10F") << "gaux1 is colortex4";
  EXPECT_EQ(s.buffers[4].format.kind, PackFormat::Kind::Packed);
  EXPECT_FALSE(s.buffers[3].clear);
  EXPECT_EQ(s.buffers[5].clearColor, glm::vec4(0.5f));
  EXPECT_EQ(s.buffers[6].clearColor, glm::vec4(1, 0, 0, 1));
  EXPECT_TRUE(s.buffers[1].mipmap) << "gdepth is colortex1";
  EXPECT_FALSE(s.buffers[0].mipmap);
  EXPECT_EQ(s.shadowDistance, 120.0f);
  EXPECT_EQ(s.noiseTextureResolution, 512);
  ProgramDirectives badFormat, badColour;
  badFormat.constants = {{"colortex7Format", "RGBA64F"}};
  badColour.constants = {{"colortex1ClearColor", "vec3(1.0, 0.0, 0.0)"}};
  const std::string format = errorOf([&] { packSettings({badFormat}, "MyPack"); });
  EXPECT_NE(format.find("MyPack: colortex7Format: 'RGBA64F'"), std::string::npos) << format;
  const std::string colour = errorOf([&] { packSettings({badColour}, "MyPack"); });
  EXPECT_NE(colour.find("colortex1ClearColor"), std::string::npos) << colour;
}

}  // namespace
}  // namespace terrasol
