// The crack on a block being dug (FrameInputs::crack): Minecraft's destroy_stage textures multiplied
// into the G-buffer's albedo. It changes only pixels whose surface lies in the dug block's cell, darkens
// them on the whole, grows with its stage, and the pass is left out when nothing is dug.

#include <algorithm>
#include <filesystem>
#include <glm/common.hpp>
#include <optional>

#include "assets/crack_textures.h"
#include "assets/image.h"
#include "core/paths.h"
#include "scene_render/scene_render.h"
#include "support/frame_probe.h"
#include "support/gl_test.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TERRASOL_SOURCE_DIR) / "tests" / "scenes";

using testing::skipReason;

// Calls `visit(point, before, after)` for each pixel `after` changed from `before` (by more than
// rounding), with the world point of the surface under it (from the read-back depth; none for sky).
template <class Visit>
void forEachChanged(const RenderedFrame& before, const RenderedFrame& after, Visit visit) {
  const glm::ivec2 size = before.pixels.size;
  for (int y = 0; y < size.y; ++y) {
    for (int x = 0; x < size.x; ++x) {
      const int row = size.y - 1 - y;  // the image's rows run top first
      const std::uint8_t* a = before.image.pixel(x, row);
      const std::uint8_t* b = after.image.pixel(x, row);
      if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) <= 3) continue;
      const float depth = before.pixels.depth[static_cast<std::size_t>(y * size.x + x)];
      std::optional<glm::dvec3> point;
      if (depth < 1.0f) point = before.geometry.camera + testing::pixelPoint(before, x, y, depth);
      visit(point, a, b);
    }
  }
}

struct Changed {
  int inCell = 0, outside = 0;
  double brightnessBefore = 0.0, brightnessAfter = 0.0;  // summed over the changed pixels
};

// The changed pixels, sorted by whether their surface lies in `cell` (grown by `slack` blocks).
Changed compare(const RenderedFrame& before, const RenderedFrame& after, const WorldBox& cell, double slack) {
  Changed out;
  forEachChanged(before, after,
                 [&](const std::optional<glm::dvec3>& p, const std::uint8_t* a, const std::uint8_t* b) {
                   const bool in = p && glm::all(glm::greaterThanEqual(*p, cell.min - slack)) &&
                                   glm::all(glm::lessThanEqual(*p, cell.max + slack));
                   (in ? out.inCell : out.outside) += 1;
                   out.brightnessBefore += a[0] + a[1] + a[2];
                   out.brightnessAfter += b[0] + b[1] + b[2];
                 });
  return out;
}

// Of the pixels changed on the cell's +z face, the share whose texel in `crack` is drawn (alpha at
// least 0.1) when the face takes the texture with u along +x and v down from its top, as Minecraft
// lays it on (or mirrored left to right).
double drawnShare(const RenderedFrame& before, const RenderedFrame& after, const WorldBox& cell,
                  const Image& crack, bool mirrored) {
  int changed = 0, drawn = 0;
  const auto texel = [&](double t) {
    return std::clamp(static_cast<int>(t * crack.width), 0, crack.width - 1);
  };
  forEachChanged(before, after,
                 [&](const std::optional<glm::dvec3>& p, const std::uint8_t*, const std::uint8_t*) {
                   if (!p || std::abs(p->z - cell.max.z) > 0.02) return;
                   const double u = mirrored ? cell.max.x - p->x : p->x - cell.min.x, v = cell.max.y - p->y;
                   ++changed;
                   drawn += crack.pixel(texel(u), texel(v))[3] >= 26;
                 });
  return changed ? static_cast<double>(drawn) / changed : 0.0;
}

class CrackTest : public testing::GlTest {};

TEST_F(CrackTest, TheCrackMarksOnlyTheDugBlockDarkensItAndGrowsWithItsStage) {
  SceneFile scene = loadScene(kScenes / "stone_closeup.json");  // a stone wall, the camera 2.2 blocks off
  scene.antialiasing = Antialiasing::None;
  SceneRenderer renderer(scene);
  FrameRequest request;
  request.readBack = true;
  request.checkNan = true;
  const RenderedFrame plain = renderer.renderFrame(0, request);
  EXPECT_EQ(skipReason(plain, "crack"), "no block is being dug");

  const WorldBox cell{{1.0, 65.0, 0.0}, {2.0, 66.0, 1.0}};  // the stone the camera looks at
  std::vector<Changed> stages;
  RenderedFrame cracked;
  for (int stage : {0, 4, kCrackStages - 1}) {
    request.crack = BlockCrack{cell, stage};
    cracked = renderer.renderFrame(0, request);
    EXPECT_EQ(skipReason(cracked, "crack"), "(ran)");
    EXPECT_EQ(cracked.nanPixels, 0u);
    saveImage(testing::testOutputDir() / ("crack_stage_" + std::to_string(stage) + ".png"), cracked.image);
    stages.push_back(compare(plain, cracked, cell, 0.02));
    EXPECT_EQ(stages.back().outside, 0) << "stage " << stage << " marked a pixel outside the dug block";
    EXPECT_LT(stages.back().brightnessAfter, stages.back().brightnessBefore) << "stage " << stage;
  }
  EXPECT_GT(stages[0].inCell, 10);
  EXPECT_GT(stages[1].inCell, stages[0].inCell);
  EXPECT_GT(stages[2].inCell, 3 * stages[1].inCell / 2);
  // The crack lies on the face the right way round: where the last stage's texture draws.
  const Image last = loadImage(resourcePackDir() / "default" / "assets" / "minecraft" / "textures" / "block" /
                               (crackTextureName(kCrackStages - 1) + ".png"));
  const double share = drawnShare(plain, cracked, cell, last, false);
  EXPECT_GT(share, 0.9);
  EXPECT_LT(drawnShare(plain, cracked, cell, last, true), share - 0.2) << "mirrored, it would not match";

  // A cell with no surface in it (the air in front of the wall) changes nothing.
  request.crack = BlockCrack{{{1.0, 65.0, 1.0}, {2.0, 66.0, 2.0}}, kCrackStages - 1};
  const Changed air = compare(plain, renderer.renderFrame(0, request), cell, 0.02);
  EXPECT_EQ(air.inCell + air.outside, 0);
  context_->checkErrors("cracks");
}

}  // namespace
}  // namespace terrasol
