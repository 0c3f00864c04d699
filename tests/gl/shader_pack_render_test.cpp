// Shader packs on the GL context: every program of the two real test packs (shaderLABS'
// Shadow-Tutorial, `#version 120`, and Base-330, `330 compatibility`), of a legacy OptiFine-style pack
// and of Terrasol's example pack rewritten, compiled and linked;
// OptiFine's buffer flips checked by a pack written here that passes values through four composite
// passes; a broken pack leaves Terrasol's pipeline drawing with the pack's file and line.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "assets/image.h"
#include "core/paths.h"
#include "pack_render/pack_program.h"
#include "pack_render/pack_renderer.h"
#include "scene_render/scene_render.h"
#include "scene_render/shadow_truth.h"
#include "shaderpack/pack_macros.h"
#include "support/gl_test.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

const std::filesystem::path kSource(TERRASOL_SOURCE_DIR);

std::filesystem::path vendored(const std::string& name) {
  return kSource / "tests" / "shaderpacks" / name;
}

std::filesystem::path writePack(const std::string& name,
                                const std::vector<std::pair<std::string, std::string>>& files) {
  const auto dir = testing::scratchDir(name);
  std::filesystem::remove_all(dir);
  for (const auto& [path, text] : files) {
    std::filesystem::create_directories((dir / "shaders" / path).parent_path());
    std::ofstream(dir / "shaders" / path) << text;
  }
  return dir;
}

// A small scene drawn with `pack`.
SceneFile packScene(const std::filesystem::path& pack) {
  SceneFile scene = loadScene(kSource / "tests" / "scenes" / "paths" / "shaderpack_base_330.json");
  scene.shaderpack = pack;
  scene.width = 32;
  scene.height = 18;
  return scene;
}

// The colour at the middle of the packScene frame drawn with `pack` (its buffers at `renderScale`).
glm::ivec3 centre(const std::filesystem::path& pack, float renderScale = 1.0f) {
  SceneFile scene = packScene(pack);
  scene.renderScale = renderScale;
  SceneRenderer renderer(scene);
  EXPECT_TRUE(renderer.shaderPack()) << renderer.stats().shaderpackError;
  const Image image = renderer.renderFrame(0).image;
  const std::uint8_t* p = image.pixel(image.width / 2, image.height / 2);
  return {p[0], p[1], p[2]};
}

using ShaderPackRenderTest = testing::GlTest;

TEST_F(ShaderPackRenderTest, EveryProgramOfTheTestPacksCompilesAndLinks) {
  const ShaderPreprocessor shaders(shaderDir());
  const PreprocessedShader block = packVertexReader(shaders, PackInput::Block);
  const PreprocessedShader screen = packVertexReader(shaders, PackInput::Screen);
  const PreprocessedShader sky = packVertexReader(shaders, PackInput::Sky);
  int built = 0;
  for (const std::filesystem::path& path :
       {vendored("Shadow-Tutorial"), vendored("Base-330"), vendored("OptiFine-Legacy"),
        kSource / "shaderpacks" / "terrasol-example"}) {
    const ShaderPack pack = ShaderPack::open(path);
    const std::string name = pack.name();
    for (const std::string& program : pack.programs()) {
      const bool onScreen = !program.starts_with("gbuffers_") && !program.starts_with("shadow");
      const bool inSky = program.starts_with("gbuffers_sky");
      const PackInput input = onScreen ? PackInput::Screen : inSky ? PackInput::Sky : PackInput::Block;
      const PackProgramSource source{&pack,        *pack.program(program),
                                     input,        !onScreen,
                                     packMacros(), onScreen ? &screen : inSky ? &sky : &block};
      const PackGlProgram gl(source);
      EXPECT_NE(gl.id(), 0u) << name << " " << program;
      ++built;
    }
  }
  EXPECT_EQ(built, 13 + 18 + 4 + 7)
      << "Shadow-Tutorial's 13 programs, Base-330's 18, OptiFine-Legacy's 4, the example's 7";
}

TEST_F(ShaderPackRenderTest, TheTestPacksDrawTheirProgramsInOptiFinesOrder) {
  SceneRenderer tutorial(packScene(vendored("Shadow-Tutorial")));
  ASSERT_TRUE(tutorial.shaderPack()) << tutorial.stats().shaderpackError;
  EXPECT_EQ(tutorial.shaderPack()->programNames(),
            (std::vector<std::string>{"shadow", "gbuffers_skybasic", "gbuffers_skytextured",
                                      "gbuffers_terrain", "gbuffers_water: gbuffers_terrain", "composite"}));
  FrameRequest request;
  request.timed = true;
  request.checkNan = true;
  const RenderedFrame frame = tutorial.renderFrame(0, request);
  std::vector<std::string> passes;
  for (const PassTiming& t : frame.timings) passes.push_back(t.pass);
  EXPECT_EQ(passes, (std::vector<std::string>{"shadow", "sky", "terrain", "water", "composite", "final"}));
  EXPECT_EQ(frame.nanPixels, 0u);
  EXPECT_GT(frame.stats.sectionsDrawn, 0);

  SceneRenderer base(packScene(vendored("Base-330")));
  ASSERT_TRUE(base.shaderPack()) << base.stats().shaderpackError;
  EXPECT_EQ(base.shaderPack()->programNames(),
            (std::vector<std::string>{"gbuffers_skybasic", "gbuffers_skytextured", "gbuffers_terrain",
                                      "deferred", "gbuffers_water", "composite"}));
  context_->checkErrors("drawing the test packs");
}

// Four composite passes hand values on through colortex1 and colortex2: each pass reads what the
// passes before wrote (the written buffers flip), a pass reading the buffer it writes sees the old
// value, and flip.<program>.<buffer> flips a buffer the pass did not write.
TEST_F(ShaderPackRenderTest, CompositePassesFlipTheBuffersTheyWrite) {
  const std::string vertex =
      "#version 120\nvarying vec2 uv;\nvoid main() { gl_Position = ftransform(); uv = gl_MultiTexCoord0.xy; "
      "}\n";
  const std::string samplers =
      "#version 120\nuniform sampler2D colortex1;\nuniform sampler2D colortex2;\nvarying vec2 uv;\n";
  std::vector<std::pair<std::string, std::string>> files = {
      {"composite.vsh", vertex},
      {"composite.fsh", samplers + "void main() {\n/* DRAWBUFFERS:1 */\n  gl_FragData[0] = vec4(0.25);\n}\n"},
      {"composite1.vsh", vertex},
      {"composite1.fsh", samplers + "void main() {\n/* DRAWBUFFERS:2 */\n"
                                    "  gl_FragData[0] = texture2D(colortex1, uv) + vec4(0.25);\n}\n"},
      {"composite2.vsh", vertex},
      {"composite2.fsh", samplers +
                             "void main() {\n/* DRAWBUFFERS:1 */\n"
                             "  gl_FragData[0] = texture2D(colortex1, uv) + texture2D(colortex2, uv);\n}\n"},
      {"composite3.vsh", vertex},
      {"composite3.fsh",
       samplers +
           "void main() {\n/* DRAWBUFFERS:0 */\n"
           "  gl_FragData[0] = vec4(texture2D(colortex1, uv).r, texture2D(colortex2, uv).r, 0.0, 1.0);\n}\n"},
  };
  const std::filesystem::path pack = writePack("flip_pack", files);
  const glm::ivec3 flipped = centre(pack);
  EXPECT_NEAR(flipped.x, 191, 1) << "0.25 + (0.25 + 0.25)";
  EXPECT_NEAR(flipped.y, 128, 1) << "0.25 + 0.25";
  EXPECT_EQ(centre(pack, 0.5f), flipped) << "buffers at half the size, scaled up to the target";

  files.push_back({"shaders.properties", "flip.composite2.colortex2=true\n"});
  const glm::ivec3 forced = centre(writePack("flip_pack_forced", files));
  EXPECT_NEAR(forced.x, 191, 1);
  EXPECT_EQ(forced.y, 0) << "colortex2 flipped back to the buffer composite1 did not write: cleared";
}

// The NaN count reads the pack's float buffers: a pack that writes NaN into one is caught.
TEST_F(ShaderPackRenderTest, NanInAPacksFloatBufferIsCounted) {
  const std::string vertex = "#version 120\nvoid main() { gl_Position = ftransform(); }\n";
  const auto pack = writePack(
      "nan_pack",
      {{"composite.vsh", vertex},
       {"composite.fsh",
        "#version 120\n/* const int colortex1Format = RGBA16F; */\nuniform float frameTimeCounter;\n"
        "void main() {\n/* DRAWBUFFERS:1 */\n  gl_FragData[0] = vec4(sqrt(-1.0 - frameTimeCounter));\n}\n"}});
  SceneRenderer renderer(packScene(pack));
  ASSERT_TRUE(renderer.shaderPack()) << renderer.stats().shaderpackError;
  FrameRequest request;
  request.checkNan = true;
  EXPECT_EQ(renderer.renderFrame(0, request).nanPixels, 32u * 18u) << "every pixel of colortex1";
}

// shaders.properties' switches reach the picture: texture.noise replaces the random noise with the
// pack's image, and oldLighting shades faces by direction in gl_Color.
TEST_F(ShaderPackRenderTest, ShadersPropertiesSwitchesChangeThePicture) {
  const std::string vertex =
      "#version 120\nvarying vec2 uv;\nvoid main() { gl_Position = ftransform(); uv = gl_MultiTexCoord0.xy; "
      "}\n";
  std::vector<std::pair<std::string, std::string>> files = {
      {"final.vsh", vertex},
      {"final.fsh",
       "#version 120\nuniform sampler2D noisetex;\nvarying vec2 uv;\n"
       "void main() { gl_FragColor = texture2D(noisetex, uv); }\n"},
  };
  const auto dir = writePack("noise_pack", files);
  Image red(4, 4);
  for (int i = 0; i < 16; ++i)
    std::copy_n(std::array<std::uint8_t, 4>{255, 0, 0, 255}.data(), 4, &red.rgba[i * 4]);
  std::filesystem::create_directories(dir / "shaders" / "tex");
  saveImage(dir / "shaders" / "tex" / "noise.png", red);
  std::ofstream(dir / "shaders" / "shaders.properties") << "texture.noise=tex/noise.png\n";
  EXPECT_EQ(centre(dir), glm::ivec3(255, 0, 0));

  // Base-330 draws gl_Color straight into the picture: with oldLighting the sides darken.
  const auto base = testing::scratchDir("base_old_lighting");
  std::filesystem::remove_all(base);
  std::filesystem::copy(vendored("Base-330"), base, std::filesystem::copy_options::recursive);
  const auto brightness = [&](const std::filesystem::path& pack) {
    SceneRenderer renderer(packScene(pack));
    const Image image = renderer.renderFrame(0).image;
    long sum = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
      sum += image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2];
    return sum;
  };
  const long plain = brightness(base);
  std::ofstream(base / "shaders" / "shaders.properties") << "oldLighting=true\n";
  EXPECT_LT(brightness(base), plain) << "faces turned from the sky are shaded";
}

TEST_F(ShaderPackRenderTest, ABrokenPackLeavesTerrasolsPipelineDrawingWithItsFileAndLine) {
  const auto pack = writePack(
      "broken_pack",
      {{"gbuffers_terrain.vsh", "#version 120\nvoid main() { gl_Position = ftransform(); }\n"},
       {"gbuffers_terrain.fsh", "#version 120\nvoid main() {\n  gl_FragData[0] = notDeclared;\n}\n"}});
  SceneRenderer renderer(packScene(pack));
  EXPECT_FALSE(renderer.shaderPack());
  EXPECT_NE(renderer.stats().shaderpackError.find("gbuffers_terrain.fsh:3"), std::string::npos)
      << renderer.stats().shaderpackError;
  const RenderedFrame frame = renderer.renderFrame(0);
  EXPECT_GT(frame.stats.sectionsDrawn, 0) << "Terrasol's pipeline drew";
}

// Terrasol's example pack draws its shadows as Terrasol's pipeline does (a warped map, PCF) and names
// its shadow term for reports: measured against the ray-traced truth, it misclassifies within a
// percentage point of Terrasol's own.
TEST_F(ShaderPackRenderTest, TheExamplePacksShadowsMatchTheTruthAsTerrasolsOwnDo) {
  for (const char* name : {"shadow_noon", "shadow_low_sun"}) {
    const SceneFile scene = loadScene(kSource / "tests" / "scenes" / (std::string(name) + ".json"));
    SceneFile withPack = scene;
    withPack.shaderpack = kSource / "shaderpacks" / "terrasol-example";
    FrameRequest request;
    request.readBack = true;
    request.checkNan = true;
    const auto misclassified = [&](const SceneFile& s) {
      SceneRenderer renderer(s);
      EXPECT_TRUE(s.shaderpack.empty() || renderer.shaderPack()) << renderer.stats().shaderpackError;
      const RenderedFrame frame = renderer.renderFrame(0, request);
      EXPECT_EQ(frame.nanPixels, 0u) << name;
      EXPECT_TRUE(frame.geometry.shadowMapShown) << name;
      const ShadowCounts c =
          measureShadowError(renderer.world(), frame.pixels, frame.geometry, scene.shadow.distance).total;
      EXPECT_GT(c.evaluated, 10000u) << name;
      return 100.0 * static_cast<double>(c.falseShadow + c.falseLit) /
             static_cast<double>(std::max<std::size_t>(c.evaluated, 1));
    };
    const double own = misclassified(scene);
    const double pack = misclassified(withPack);
    EXPECT_LE(pack, own + 1.0) << name << ": the example pack " << pack << " %, Terrasol's own " << own
                               << " %";
  }
}

// The example pack's block.properties tags water (id 1) and its vertex stage ripples it with the time:
// a second (20 ticks) later the water has moved and little else has; without the tag it stays put.
TEST_F(ShaderPackRenderTest, WaterTaggedByBlockPropertiesMovesWithTheTime) {
  const auto changedPixels = [&](const std::filesystem::path& pack) {
    SceneFile scene = packScene(pack);
    scene.width = 96;
    scene.height = 54;
    scene.cameraPath.reset();
    scene.cameraPosition = {0.5, 68.0, 8.0};
    scene.cameraLookAt = {0.0, 63.0, -10.0};
    scene.time = 6000;
    const Image first = SceneRenderer(scene).renderFrame(0).image;
    scene.time = 6020;  // a second later
    const Image next = SceneRenderer(scene).renderFrame(0).image;
    int changed = 0;
    for (std::size_t i = 0; i < first.rgba.size(); i += 4) {
      int most = 0;
      for (std::size_t c = 0; c < 3; ++c)
        most = std::max(most, std::abs(int(first.rgba[i + c]) - int(next.rgba[i + c])));
      changed += most > 8;
    }
    return changed;
  };
  const std::filesystem::path example = kSource / "shaderpacks" / "terrasol-example";
  const int tagged = changedPixels(example);
  // The same pack without its block.properties: mc_Entity.x is -1 everywhere.
  const auto copy = testing::scratchDir("example_untagged");
  std::filesystem::remove_all(copy);
  std::filesystem::copy(example, copy, std::filesystem::copy_options::recursive);
  std::filesystem::remove(copy / "shaders" / "block.properties");
  const int untagged = changedPixels(copy);
  EXPECT_GT(tagged, 100) << "the pond's surface moved";
  std::printf("pixels changed in a second: %d with water tagged, %d without\n", tagged, untagged);
  EXPECT_LT(untagged * 20, tagged) << "little but the tagged water moves in a second (the sun, a little)";
  context_->checkErrors("two ticks");
}

}  // namespace
}  // namespace terrasol
