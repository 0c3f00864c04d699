#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <nlohmann/json.hpp>

#include "assets/block_model.h"
#include "assets/texture_loader.h"
#include "core/error.h"
#include "core/paths.h"
#include "packgen.h"
#include "scene/block_atlas.h"
#include "scene/texture_coverage.h"
#include "support/pack_builder.h"
#include "support/raw_png.h"
#include "support/test_data.h"
#include "support/world_support.h"
#include "support/zip_writer.h"
#include "world/block_table.h"

namespace terrasol {
namespace {

using testing::PackBuilder;
using testing::solidImage;

// A real third-party pack (the test data's), where it is present.
std::filesystem::path pixelPerfection() {
  return testing::testData() / "packs" / "pixel_perfection_ce";
}

std::string problemsText(const std::vector<PackProblem>& problems) {
  std::string text;
  for (const auto& p : problems) text += p.message + "\n";
  return text;
}

LoadedTexture load(const PackStack& stack, std::vector<std::string> names,
                   std::vector<PackProblem>& problems) {
  return loadBlockTexture(stack, names, problems);
}

TEST(ResourcePack, LaterPacksOverrideEarlierOnesAndCompanionsComeFromTheSamePack) {
  PackBuilder low("pack_low");
  low.image("stone.png", solidImage(16, 16, 100, 100, 100))
      .image("stone_s.png", solidImage(16, 16, 200, 230, 0, 255));
  low.image("dirt.png", solidImage(16, 16, 120, 80, 40));
  PackBuilder high("pack_high", "blocks");  // the pre-1.13 folder name
  high.image("stone.png", solidImage(16, 16, 50, 50, 50));
  const PackStack stack = testing::stackOf({low.dir(), high.dir()});
  std::vector<PackProblem> problems;
  const auto stone = load(stack, {"stone"}, problems);
  EXPECT_EQ(stone.albedo[0].pixel(0, 0)[0], 50);
  EXPECT_FALSE(stone.hasSpecularMap) << "the lower pack's _s belongs to the lower pack's art";
  EXPECT_EQ(stone.specular[0].pixel(0, 0)[1], 0);
  EXPECT_EQ(stone.normal[0].pixel(3, 3)[2], 255) << "absent _n reads as (127, 127, 255, 255)";
  const auto dirt = load(stack, {"dirt"}, problems);
  EXPECT_EQ(dirt.albedo[0].pixel(0, 0)[0], 120);
  EXPECT_TRUE(problems.empty()) << problemsText(problems);
}

TEST(ResourcePack, AMissingTextureIsTheCheckerboardWithOneWarningNamingIt) {
  PackBuilder pack("pack_missing");
  const PackStack stack = testing::stackOf({pack.dir()});
  std::vector<PackProblem> problems;
  const auto t = load(stack, {"short_grass", "grass"}, problems);
  EXPECT_TRUE(t.missing);
  EXPECT_EQ(t.albedo[0].pixel(0, 0)[0], 248);
  EXPECT_EQ(t.albedo[0].pixel(8, 0)[0], 0);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("short_grass"), std::string::npos);
  EXPECT_NE(problems[0].message.find("grass.png"), std::string::npos);
  // The fallback name is used when the first is absent.
  pack.image("grass.png", solidImage(16, 16, 1, 2, 3));
  problems.clear();
  EXPECT_FALSE(load(testing::stackOf({pack.dir()}), {"short_grass", "grass"}, problems).missing);
}

TEST(ResourcePack, CompanionsAreResampledToTheBaseSize) {
  PackBuilder pack("pack_resample");
  pack.image("iron_block.png", solidImage(16, 16, 200, 200, 200));
  pack.image("iron_block_n.png", solidImage(32, 32, 127, 127, 255, 255));
  pack.image("iron_block_s.png", solidImage(8, 8, 220, 230, 0, 0));
  std::vector<PackProblem> problems;
  const auto t = load(testing::stackOf({pack.dir()}), {"iron_block"}, problems);
  EXPECT_TRUE(problems.empty()) << problemsText(problems);
  EXPECT_EQ(t.normal[0].width, 16);
  EXPECT_EQ(t.specular[0].width, 16);
  EXPECT_EQ(t.specular[0].pixel(15, 15)[1], 230) << "specular is resampled without blending ids";
  EXPECT_EQ(t.specular[0].pixel(15, 15)[3], 0) << "alpha 0 is kept";
}

TEST(ResourcePack, AnimationsSplitIntoFramesWithTheirTiming) {
  PackBuilder pack("pack_anim");
  Image strip(16, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 16; ++x) {
      std::uint8_t* p = strip.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(y / 16 * 60), p[1] = 0, p[2] = 0, p[3] = 255;
    }
  pack.image("lava_still.png", strip);
  pack.text(
      "lava_still.png.mcmeta",
      R"({"animation": {"frametime": 3, "interpolate": true, "frames": [0, 2, {"index": 3, "time": 7}]}})");
  pack.image("lava_still_n.png", solidImage(16, 16, 127, 127, 255));  // one frame for all
  std::vector<PackProblem> problems;
  const auto t = load(testing::stackOf({pack.dir()}), {"lava_still"}, problems);
  EXPECT_TRUE(problems.empty()) << problemsText(problems);
  ASSERT_TRUE(t.animation);
  EXPECT_EQ(t.albedo.size(), 4u);
  EXPECT_EQ(t.normal.size(), 4u);
  EXPECT_EQ(t.albedo[2].pixel(0, 0)[0], 120);
  EXPECT_TRUE(t.animation->interpolate);
  ASSERT_EQ(t.animation->sequence.size(), 3u);
  EXPECT_EQ(t.animation->sequence[1].index, 2);
  EXPECT_EQ(t.animation->sequence[1].ticks, 3);
  EXPECT_EQ(t.animation->sequence[2].ticks, 7);
  EXPECT_EQ(t.animation->totalTicks(), 13);

  // A companion with its own .png.mcmeta: split by its own layout (here 4 frames of 8 x 8).
  Image normals(8, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 8; ++x) {
      std::uint8_t* p = normals.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(100 + y / 8), p[1] = 127, p[2] = 255, p[3] = 255;
    }
  pack.image("lava_still_n.png", normals);
  pack.text("lava_still_n.png.mcmeta", R"({"animation": {}})");
  problems.clear();
  const auto withOwn = load(testing::stackOf({pack.dir()}), {"lava_still"}, problems);
  EXPECT_TRUE(problems.empty()) << problemsText(problems);
  ASSERT_EQ(withOwn.normal.size(), 4u);
  EXPECT_EQ(withOwn.normal[0].width, 16) << "resampled to the texture's frame size";
  EXPECT_EQ(withOwn.normal[2].pixel(5, 5)[0], 102);
  pack.text("lava_still_n.png.mcmeta", R"({"animation": {"height": 5}})");
  problems.clear();
  load(testing::stackOf({pack.dir()}), {"lava_still"}, problems);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].message.find("lava_still_n.png.mcmeta"), std::string::npos) << problems[0].message;
}

TEST(Animation, FramesFollowGameTimeExactlyForever) {
  const auto anim = parseAnimation(
      R"({"animation": {"frametime": 2, "frames": [0, {"index": 3, "time": 5}, 1]}})", 16, 64, "test.mcmeta");
  ASSERT_TRUE(anim);
  EXPECT_EQ(anim->totalTicks(), 9);
  const int expected[9] = {0, 0, 3, 3, 3, 3, 3, 1, 1};
  for (int t = 0; t < 9; ++t) EXPECT_EQ(frameAt(*anim, t).frame, expected[t]) << t;
  EXPECT_EQ(frameAt(*anim, 1'000'000'000'000 * 9 + 2).frame, 3) << "no drift after 10^13 ticks";
  EXPECT_EQ(frameAt(*anim, -1).frame, 1) << "negative time wraps";
  EXPECT_EQ(frameAt(*anim, 2).next, 1);
  EXPECT_FLOAT_EQ(frameAt(*anim, 3).blend, 0.0f) << "no interpolation asked";
  const auto smooth =
      parseAnimation(R"({"animation": {"frametime": 4, "interpolate": true}})", 16, 32, "s.mcmeta");
  EXPECT_FLOAT_EQ(frameAt(*smooth, 2, 0.5f).blend, 2.5f / 4.0f);
  EXPECT_EQ(frameAt(*smooth, 5).frame, 1);
  EXPECT_EQ(frameAt(*smooth, 5).next, 0);
  EXPECT_FALSE(parseAnimation(R"({"texture": {"blur": true}})", 16, 16, "plain.mcmeta"));
}

// Each bad file gives one error naming it, and the texture falls back to "missing"; nothing crashes.
TEST(ResourcePack, BadInputGivesClearErrorsNamingTheFile) {
  PackBuilder pack("pack_bad");
  pack.text("empty.png", "");
  pack.text("garbage.png", "\x89PNG\r\n\x1a\nthis is not a png");
  // A valid PNG declaring 100 000 x 100 000 pixels (40 GB): refused from its header, before allocating.
  const unsigned char huge[] = {
      0x89, 0x50, 0x4e, 0x47, 0xd,  0xa,  0x1a, 0xa,  0x0,  0x0,  0x0,  0xd,  0x49, 0x48, 0x44, 0x52, 0x0,
      0x1,  0x86, 0xa0, 0x0,  0x1,  0x86, 0xa0, 0x8,  0x6,  0x0,  0x0,  0x0,  0xa8, 0x52, 0xb,  0xc8, 0x0,
      0x0,  0x0,  0x9,  0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x0,  0x0,  0x0,  0x1,  0x0,  0x1,  0x5e,
      0xff, 0x7d, 0xf9, 0x0,  0x0,  0x0,  0x0,  0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  pack.text("huge.png", std::string(reinterpret_cast<const char*>(huge), sizeof huge));
  pack.image("strip.png", solidImage(16, 40, 1, 1, 1));
  pack.text("strip.png.mcmeta", R"({"animation": {}})");
  pack.image("oblong.png", solidImage(16, 40, 1, 1, 1));
  pack.image("meta.png", solidImage(16, 32, 1, 1, 1));
  pack.text("meta.png.mcmeta", R"({"animation": {"frametime": )");
  pack.image("frames.png", solidImage(16, 32, 1, 1, 1));
  pack.text("frames.png.mcmeta", R"({"animation": {"frames": [0, 5]}})");
  // A real PNG cut in half.
  saveImage(pack.file("whole.png"), solidImage(64, 64, 9, 9, 9));
  std::ifstream in(pack.file("whole.png"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  pack.text("truncated.png", bytes.substr(0, bytes.size() / 2));

  const PackStack stack = testing::stackOf({pack.dir()});
  const std::pair<const char*, const char*> cases[] = {
      {"empty", "empty file"},
      {"garbage", "garbage.png"},
      {"huge", "100000x100000"},
      {"strip", "not a stack of 16x16 frames"},
      {"oblong", "not square and has no .mcmeta"},
      {"meta", "meta.png.mcmeta:1:29: invalid JSON"},
      {"frames", "frames.png.mcmeta: animation.frames[1]: is frame 5, but the strip has 2"},
      {"truncated", "truncated.png"},
  };
  for (const auto& [name, expected] : cases) {
    std::vector<PackProblem> problems;
    const auto t = load(stack, {name}, problems);
    EXPECT_TRUE(t.missing) << name;
    ASSERT_EQ(problems.size(), 1u) << name << ": " << problemsText(problems);
    EXPECT_EQ(problems[0].severity, PackProblem::Severity::Error) << name;
    EXPECT_NE(problems[0].message.find(expected), std::string::npos) << name << ": " << problems[0].message;
  }
}

TEST(ResourcePack, SixteenBitGreyAndPaletteImagesAreConverted) {
  PackBuilder pack("pack_formats");
  {  // 16-bit grey + alpha (big-endian samples): white, opaque, but for a mid-grey first pixel
    std::vector<std::uint8_t> samples(16 * 16 * 2 * 2, 0xFF);
    samples[0] = 0x80;
    samples[1] = 0x00;
    testing::writeRawPng(pack.file("deep.png"), 16, 16, 16, testing::PngColour::GreyAlpha, samples);
  }
  std::vector<PackProblem> deepProblems;
  const auto deep = load(testing::stackOf({pack.dir()}), {"deep"}, deepProblems);
  EXPECT_TRUE(deepProblems.empty()) << problemsText(deepProblems);
  EXPECT_EQ(deep.albedo[0].pixel(0, 0)[0], 128);
  EXPECT_EQ(deep.albedo[0].pixel(0, 0)[2], 128) << "grey fills all three colour channels";
  EXPECT_EQ(deep.albedo[0].pixel(1, 0)[3], 255);
  Image grey(16, 16);
  for (auto& v : grey.rgba) v = 77;
  saveImage(pack.file("grey.png"), grey);
  std::vector<PackProblem> problems;
  EXPECT_FALSE(load(testing::stackOf({pack.dir()}), {"grey"}, problems).missing);
  // Palette PNGs (8-, 4-, 2-bit with tRNS) come from the real pack below.
  EXPECT_TRUE(problems.empty()) << problemsText(problems);
}

using testing::writeZip;

std::string pngBytes(const Image& image) {
  const auto file = testing::scratchDir("png_bytes") / "x.png";
  saveImage(file, image);
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(ResourcePack, ZipPacksLoadAndUnsafeEntriesAreRefused) {
  const auto dir = testing::scratchDir("zips");
  const std::string mcmeta = R"({"pack": {"pack_format": 15, "description": "zipped"}})";
  writeZip(dir / "good.zip",
           {{"MyPack/pack.mcmeta", mcmeta},
            {"MyPack/assets/minecraft/textures/block/stone.png", pngBytes(solidImage(16, 16, 42, 42, 42))}});
  std::vector<PackProblem> problems;
  const auto stone = load(testing::stackOf({dir / "good.zip"}), {"stone"}, problems);
  EXPECT_FALSE(stone.missing) << problemsText(problems);
  EXPECT_EQ(stone.albedo[0].pixel(0, 0)[0], 42);
  EXPECT_NE(stone.source.find("good.zip!MyPack/assets"), std::string::npos) << stone.source;

  for (const char* evil : {"../evil.png", "/etc/evil.png", "assets/../../evil.png"}) {
    writeZip(dir / "evil.zip", {{"pack.mcmeta", mcmeta}, {evil, "x"}});
    try {
      ResourcePack::open(dir / "evil.zip");
      ADD_FAILURE() << evil << " was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("evil.zip"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("leaves the pack"), std::string::npos) << e.what();
    }
  }
  std::ofstream(dir / "notazip.zip") << "hello";
  EXPECT_THROW(ResourcePack::open(dir / "notazip.zip"), Error);
}

// Minecraft's own assets as a pack: a client jar (a zip of classes and assets/minecraft/, no
// pack.mcmeta) over the default pack draws a block the default pack leaves as a placeholder with the
// jar's blockstates, model and texture, and its textures override the default's; its extracted
// assets/ folder does the same.
TEST(ResourcePack, MinecraftsJarAndAssetsFolderArePacks) {
  const auto dir = testing::scratchDir("minecraft_jar");
  const std::vector<std::pair<std::string, std::string>> assets = {
      {"assets/minecraft/blockstates/amethyst_block.json",
       R"({"variants": {"": {"model": "block/amethyst_block"}}})"},
      {"assets/minecraft/models/block/amethyst_block.json",
       R"({"textures": {"all": "block/amethyst_block"}, "elements": [{"from": [0, 0, 0], "to": [16, 16, 16],
           "faces": {"down": {"texture": "#all"}, "up": {"texture": "#all"}, "north": {"texture": "#all"},
                     "south": {"texture": "#all"}, "west": {"texture": "#all"}, "east": {"texture": "#all"}}}]})"},
      {"assets/minecraft/textures/block/amethyst_block.png", pngBytes(solidImage(16, 16, 200, 100, 220))},
      {"assets/minecraft/textures/block/stone.png", pngBytes(solidImage(16, 16, 7, 7, 7))}};
  auto jar = assets;
  jar.push_back({"net/minecraft/client/main/Main.class", "\xca\xfe\xba\xbe"});
  writeZip(dir / "1.21.11.jar", jar);
  for (const auto& [name, data] : assets) {
    std::filesystem::create_directories((dir / "extracted" / name).parent_path());
    std::ofstream(dir / "extracted" / name, std::ios::binary) << data;
  }
  // Minecraft's blocks with nothing from blocks.json: each draws by its blockstates or not at all.
  const BlockRegistry blocks =
      BlockRegistry::load(BlockTable::fromFile(BlockTable::shippedFile()),
                          R"({"blocks": [{"name": "air", "shape": "none"}]})", "air.json");
  const auto drawingsOf = [&](const PackStack& stack) {
    const BlockAtlas atlas = buildBlockAtlas(blocks, stack);
    for (const PackProblem& p : atlas.problems) {
      if (p.severity == PackProblem::Severity::Error) ADD_FAILURE() << p.message;
    }
    return blockDrawings(blocks, atlas);
  };
  const std::size_t amethyst = blocks.blockIndex(blocks.id("amethyst_block"));
  EXPECT_EQ(drawingsOf(PackStack{})[amethyst], BlockDrawing::Placeholder);
  for (const auto& minecraft : {dir / "1.21.11.jar", dir / "extracted", dir / "extracted" / "assets"}) {
    PackStack alone;
    alone.push(ResourcePack::open(minecraft));
    EXPECT_EQ(alone.packs().back()->info().description, "Minecraft's assets") << minecraft;
    EXPECT_EQ(drawingsOf(alone)[amethyst], BlockDrawing::Model) << minecraft;
    // Over the default pack its textures win.
    const PackStack stack = testing::stackOf({resourcePackDir() / "default", minecraft});
    std::vector<PackProblem> problems;
    const auto stone = load(stack, {"stone"}, problems);
    EXPECT_EQ(stone.albedo[0].pixel(0, 0)[0], 7) << stone.source;
  }
  // A zip with neither pack.mcmeta nor Minecraft's assets is still not a pack.
  writeZip(dir / "other.zip", {{"readme.txt", "hello"}});
  EXPECT_THROW(ResourcePack::open(dir / "other.zip"), Error);
}

TEST(ResourcePack, MalformedPackMcmetaIsNamed) {
  for (const auto& [text, expected] : std::vector<std::pair<std::string, std::string>>{
           {"{", "invalid JSON"},
           {R"({"pack": {"description": "x"}})", "pack.mcmeta: pack: needs \"pack_format\""},
           {R"({"pack": {"pack_format": "15"}})", "pack.mcmeta: pack.pack_format: expected a whole number"},
           {R"({"pack": {"pack_format": 15}, "terrasol": {"normal_map_convention": "up"}})",
            "normal_map_convention"}}) {
    PackBuilder pack("pack_mcmeta", "block", text);
    try {
      ResourcePack::open(pack.dir());
      ADD_FAILURE() << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("pack.mcmeta"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  PackBuilder gl("pack_gl", "block", R"({"pack": {"pack_format": 15, "description": {"text": "fancy"}},
                                         "terrasol": {"normal_map_convention": "opengl"}})");
  EXPECT_TRUE(ResourcePack::open(gl.dir()).info().openGlNormals);
  EXPECT_THROW(ResourcePack::open(testing::scratchDir("no_pack")), Error);
}

// The real third-party pack: palette PNGs of several bit depths with tRNS, animations, colormaps.
// pack.mcmeta and .png.mcmeta are Minecraft's: keys Terrasol does not read are other readers' and load
// as before, and a key the "terrasol" section does not know is only a warning.
TEST(ResourcePack, MinecraftsOtherKeysLoad) {
  PackBuilder pack("pack_mc_keys", "block", R"({
      "pack": {"pack_format": 34, "supported_formats": [15, 34], "description": {"text": "x"}},
      "overlays": {"entries": [{"formats": [18, 34], "directory": "new"}]},
      "filter": {"block": [{"namespace": "realms"}]},
      "language": {"xx_yy": {"name": "X", "region": "Y", "bidirectional": false}},
      "features": {"enabled": []},
      "terrasol": {"normal_map_convention": "opengl", "normal_maps": "on"}})");
  pack.image("anim.png", solidImage(16, 32, 1, 1, 1));
  pack.text("anim.png.mcmeta",
            R"({"animation": {"frametime": 2, "frames": [1, {"index": 0, "time": 3, "x": 1}],
                                                "mode": "x"},
                                  "texture": {"blur": true, "clamp": false}, "villager": {"hat": "full"},
                                  "gui": {"scaling": {"type": "stretch"}}})");
  const ResourcePack opened = ResourcePack::open(pack.dir());
  EXPECT_EQ(opened.info().packFormat, 34);
  EXPECT_TRUE(opened.info().openGlNormals);
  std::vector<PackProblem> problems;
  const auto t = load(testing::stackOf({pack.dir()}), {"anim"}, problems);
  EXPECT_TRUE(problems.empty()) << problemsText(problems);
  ASSERT_TRUE(t.animation);
  ASSERT_EQ(t.animation->sequence.size(), 2u);
  EXPECT_EQ(t.animation->sequence[1].ticks, 3);
}

TEST(ResourcePack, PixelPerfectionLoadsWithoutErrorsOverTheDefaultPack) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const PackStack stack = testing::stackOf({resourcePackDir() / "default", pixelPerfection()});
  std::vector<PackProblem> problems;
  int animated = 0, loaded = 0;
  for (const auto& pack : stack.packs())
    for (const auto& file : pack->blockTextureFiles()) {
      if (file.ends_with("_n.png") || file.ends_with("_s.png")) continue;
      const auto t = load(stack, {file.substr(0, file.size() - 4)}, problems);
      animated += t.animation.has_value();
      loaded += !t.missing;
    }
  std::size_t errors = 0;
  for (const auto& p : problems) errors += p.severity == PackProblem::Severity::Error;
  EXPECT_EQ(errors, 0u) << problemsText(problems);
  EXPECT_GT(loaded, 900);
  EXPECT_GT(animated, 50);
  const auto water = load(stack, {"water_still"}, problems);
  EXPECT_EQ(water.source.find("pixel_perfection_ce") != std::string::npos, true) << water.source;
  EXPECT_EQ(water.albedo.size(), 16u);  // a 16 x 256 strip
}

// How much of a pack the blocks draw: the top pack's textures (maps and animation files aside), used
// where a block's face or model names them through the stack.
// A pack made for an older Minecraft names some textures the old way (grass_path_top before 1.17,
// reeds before 1.13): they still cover the default pack's, in a block's faces and in a model's; a pack
// with today's name too uses today's.
TEST(TextureCoverage, OlderTextureNamesStillCoverTheDefaultPack) {
  const Image red = testing::solidImage(16, 16, 200, 20, 20);
  PackBuilder old("old_names");
  old.image("grass_path_top.png", red).image("reeds.png", red).image("chain.png", red);
  const PackStack stack = testing::stackOf({resourcePackDir() / "default", old.dir()});
  const TextureCoverage c = textureCoverage(testing::defaultBlocks(), stack);
  EXPECT_EQ(c.used, (std::vector<std::string>{"chain", "grass_path_top", "reeds"}));
  std::vector<PackProblem> problems;
  EXPECT_NE(loadBlockTexture(stack, {"sugar_cane", "reeds"}, problems).source.find("old_names"),
            std::string::npos);
  PackBuilder both("both_names");
  both.image("reeds.png", red).image("sugar_cane.png", red);
  const TextureCoverage b = textureCoverage(testing::defaultBlocks(),
                                            testing::stackOf({resourcePackDir() / "default", both.dir()}));
  EXPECT_EQ(b.used, (std::vector<std::string>{"sugar_cane"}));
}

TEST(TextureCoverage, CountsTheTopPacksTexturesTheBlocksDraw) {
  const Image red = testing::solidImage(16, 16, 200, 20, 20);
  PackBuilder pack("coverage");
  pack.image("stone.png", red)
      .image("stone_n.png", red)
      .image("birch_door_top.png", red)
      .image("oak_planks.png", red);
  pack.image("not_a_block.png", red).text("stone.png.mcmeta", R"({"animation": {}})");
  const PackStack stack = testing::stackOf({resourcePackDir() / "default", pack.dir()});
  const TextureCoverage c = textureCoverage(testing::defaultBlocks(), stack);
  EXPECT_EQ(c.used, (std::vector<std::string>{"birch_door_top", "oak_planks", "stone"}));
  EXPECT_EQ(c.unused, (std::vector<std::string>{"not_a_block"}));
  EXPECT_EQ(c.otherUnused(), 1u);
  // The default pack is all used.
  const TextureCoverage own =
      textureCoverage(testing::defaultBlocks(), testing::stackOf({resourcePackDir() / "default"}));
  EXPECT_TRUE(own.unused.empty()) << own.unused.front();
  EXPECT_GT(own.used.size(), 180u);
}

// What no model could name is told apart: numbered variants of a texture the pack has, OptiFine's
// emissive layers beside their base, and older names beside the current one; look-alikes are not.
TEST(TextureCoverage, SortsTheUnusedByWhyNoModelNamesThem) {
  const Image red = testing::solidImage(16, 16, 200, 20, 20);
  PackBuilder pack("unused_kinds");
  for (const char* name : {"stone", "stone7", "wheat_stage7", "wheat_stage7-1", "torch", "torch_e",
                           "sugar_cane", "reeds", "fire_1", "vine_e", "stone_e"})
    pack.image(std::string(name) + ".png", red);
  const TextureCoverage c = textureCoverage(testing::defaultBlocks(),
                                            testing::stackOf({resourcePackDir() / "default", pack.dir()}));
  EXPECT_EQ(c.variants, (std::vector<std::string>{"stone7", "wheat_stage7-1"}));
  EXPECT_EQ(c.emissiveLayers, (std::vector<std::string>{"stone_e", "torch_e"}));
  EXPECT_EQ(c.superseded, (std::vector<std::string>{"reeds"}));
  // fire_1 is a texture of its own (Minecraft's second fire), vine_e a layer with no vine beside it.
  EXPECT_EQ(c.otherUnused(), 1u);
  EXPECT_NE(std::find(c.used.begin(), c.used.end(), "fire_1"), c.used.end());
}

TEST(TextureCoverage, PixelPerfectionIsPartlyDrawn) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const TextureCoverage c = textureCoverage(
      testing::defaultBlocks(), testing::stackOf({resourcePackDir() / "default", pixelPerfection()}));
  std::printf(
      "pixel_perfection_ce: used %zu of %zu block textures (%zu variants, %zu emissive layers, %zu older)\n",
      c.used.size(), c.used.size() + c.unused.size(), c.variants.size(), c.emissiveLayers.size(),
      c.superseded.size());
  EXPECT_GT(c.used.size(), 150u);
}

// resourcepacks/default is what tools/packgen writes: the generator and the committed files agree.
TEST(DefaultPack, IsExactlyWhatTheGeneratorMakes) {
  const auto dir = resourcePackDir() / "default" / "assets" / "minecraft" / "textures" / "block";
  const auto textures = packgen::generateDefaultTextures();
  EXPECT_GE(textures.size(), 30u);
  for (const auto& t : textures) {
    EXPECT_EQ(loadImage(dir / (t.name + ".png")).rgba, t.albedo.rgba) << t.name;
    EXPECT_EQ(loadImage(dir / (t.name + "_n.png")).rgba, t.normal.rgba) << t.name;
    EXPECT_EQ(loadImage(dir / (t.name + "_s.png")).rgba, t.specular.rgba) << t.name;
  }
}

// The shaped blocks' blockstates and models are the generator's output, and each of those blocks
// draws with them, none as a placeholder.
TEST(DefaultPack, ShapedBlocksAreTheGeneratorsAndDraw) {
  const auto root = resourcePackDir() / "default";
  const auto files = packgen::generateShapedBlockFiles();
  EXPECT_GE(files.size(), 170u);
  for (const packgen::GeneratedFile& f : files) {
    std::ifstream in(root / f.path, std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), f.text) << f.path;
    // Its models stay in their cell: the mesher pulls a corner outside it back in, squashing the model.
    const nlohmann::json model = nlohmann::json::parse(f.text);
    if (!model.contains("elements")) continue;
    for (const auto& e : model["elements"])
      for (const char* corner : {"from", "to"})
        for (const auto& v : e[corner]) EXPECT_TRUE(v >= 0 && v <= 16) << f.path << " " << corner << " " << v;
  }
  const BlockRegistry& blocks = testing::defaultBlocks();
  const BlockAtlas atlas = buildBlockAtlas(blocks, testing::stackOf({root}));
  EXPECT_TRUE(atlas.problems.empty()) << problemsText(atlas.problems);
  const std::vector<BlockDrawing> drawings = blockDrawings(blocks, atlas);
  for (const std::string& name : packgen::shapedBlockNames())
    EXPECT_EQ(drawings[blocks.blockIndex(blocks.id(name))], BlockDrawing::Model) << name;
}

TEST(DefaultPack, CoversEveryBlockWithNormalAndSpecularMaps) {
  const PackStack stack = testing::stackOf({resourcePackDir() / "default"});
  const BlockRegistry& blocks = testing::defaultBlocks();
  std::vector<PackProblem> problems;
  for (BlockId id = 1; id < blocks.size(); ++id)
    for (const auto& face : blocks.faceTextures(id)) {
      // Textured by their models (model_mesh_test), or nothing to draw (cave_air).
      if (blocks[id].shape == BlockShape::Model || blocks[id].shape == BlockShape::None) continue;
      // The stand-in for blocks nothing knows shows the missing texture on purpose.
      if (face == std::vector<std::string>{kMissingTexture}) continue;
      const auto t = load(stack, face, problems);
      EXPECT_FALSE(t.missing) << blocks[id].name;
      EXPECT_TRUE(t.hasNormalMap && t.hasSpecularMap) << blocks[id].name;
    }
  EXPECT_TRUE(problems.empty()) << problemsText(problems);
  // The promised materials: metals by id, emissive glowstone, lava and torch.
  auto specular = [&](const char* name, int x, int y) {
    const LoadedTexture t = load(stack, {name}, problems);
    const std::uint8_t* p = t.specular[0].pixel(x, y);
    return std::array<std::uint8_t, 4>{p[0], p[1], p[2], p[3]};
  };
  EXPECT_EQ(specular("iron_block", 8, 8)[1], 230);
  EXPECT_EQ(specular("gold_block", 8, 8)[1], 231);
  EXPECT_EQ(specular("copper_block", 8, 8)[1], 234);
  EXPECT_LT(specular("lava_still", 8, 8)[3], 255);
  EXPECT_LT(specular("torch", 7, 6)[3], 255) << "the flame glows";
  EXPECT_EQ(specular("torch", 7, 12)[3], 255) << "the stick does not";
  int glowing = 0;
  for (int i = 0; i < 256; ++i) glowing += specular("glowstone", i % 16, i / 16)[3] < 255;
  EXPECT_EQ(glowing, 256);
}

}  // namespace
}  // namespace terrasol
