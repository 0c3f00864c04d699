#include "assets/atlas.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <set>

#include "assets/labpbr.h"
#include "assets/mipmap.h"
#include "support/pack_builder.h"

namespace terrasol {
namespace {

using testing::solidImage;

LoadedTexture texture(const std::string& name, Image albedo, Image normal, Image specular) {
  LoadedTexture t;
  t.name = name;
  t.albedo.push_back(std::move(albedo));
  t.normal.push_back(std::move(normal));
  t.specular.push_back(std::move(specular));
  return t;
}

LoadedTexture plain(const std::string& name, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  return texture(name, solidImage(16, 16, r, g, b), solidImage(16, 16, 127, 127, 255, 255),
                 solidImage(16, 16, 0, 0, 0, 0));
}

// The slot (x, y, size) of `tile` at `level`.
std::array<int, 3> slot(const Atlas& a, int tile, int level) {
  const int size = a.slotSize >> level;
  return {(tile % a.columns) * size, (tile / a.columns) * size, size};
}

// The reflection pass leaves out views whose textures are all rough: each texture's smoothest texel.
TEST(Atlas, EachTexturesSmoothnessIsItsSmoothestTexel) {
  Image polished = solidImage(16, 16, 40, 0, 0, 255);
  polished.pixel(9, 3)[0] = 204;  // one texel of smoothness 0.8
  const Atlas a =
      buildAtlas({plain("rough", 90, 90, 90), texture("polished", solidImage(16, 16, 200, 200, 200),
                                                      solidImage(16, 16, 127, 127, 255, 255), polished)});
  const std::vector<float> smoothness = textureSmoothness(a);
  ASSERT_EQ(smoothness.size(), 2u);
  EXPECT_FLOAT_EQ(smoothness[static_cast<std::size_t>(a.find("rough"))], 0.0f);
  EXPECT_FLOAT_EQ(smoothness[static_cast<std::size_t>(a.find("polished"))], 204.0f / 255.0f);
}

TEST(Atlas, ThreeAlignedAtlasesWithMipsDownToOneTexelAndNoBleeding) {
  const Atlas a = buildAtlas({plain("red", 255, 0, 0), plain("blue", 0, 0, 255), plain("green", 0, 255, 0)});
  EXPECT_EQ(a.tileSize, 16);
  EXPECT_EQ(a.levels(), 5);  // 16, 8, 4, 2, 1
  for (int level = 0; level < a.levels(); ++level) {
    const auto& albedo = a.albedo[static_cast<std::size_t>(level)];
    EXPECT_EQ(albedo.width, a.normal[static_cast<std::size_t>(level)].width);
    EXPECT_EQ(albedo.height, a.specular[static_cast<std::size_t>(level)].height);
    for (int tile = 0; tile < 3; ++tile) {
      const auto [sx, sy, size] = slot(a, tile, level);
      for (int y = sy; y < sy + size; ++y)
        for (int x = sx; x < sx + size; ++x) {
          const std::uint8_t* p = albedo.pixel(x, y);
          ASSERT_EQ(p[0], tile == 0 ? 255 : 0) << "level " << level << " tile " << tile;
          ASSERT_EQ(p[2], tile == 1 ? 255 : 0) << "level " << level << " tile " << tile;
        }
    }
  }
  const glm::vec4 r = a.tileRect(a.textures[static_cast<std::size_t>(a.find("blue"))].firstTile);
  EXPECT_FLOAT_EQ((r.z - r.x) * static_cast<float>(a.albedo[0].width), 16.0f);
}

TEST(Atlas, OpenGlConventionNormalMapsAreFlippedToLabPbrs) {
  LoadedTexture gl = texture("gl", solidImage(16, 16, 1, 1, 1), solidImage(16, 16, 127, 0, 255),
                             solidImage(16, 16, 0, 0, 0, 0));
  gl.openGlNormals = true;
  LoadedTexture dx = texture("dx", solidImage(16, 16, 1, 1, 1), solidImage(16, 16, 127, 0, 255),
                             solidImage(16, 16, 0, 0, 0, 0));
  const Atlas a = buildAtlas({gl, dx});
  EXPECT_EQ(a.normal[0].pixel(16, 16)[1], 255) << "OpenGL green up becomes DirectX green down";
  EXPECT_EQ(a.normal[0].pixel(48, 16)[1], 0);
}

TEST(Atlas, PaddingRepeatsTheOppositeEdge) {
  Image gradient(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      std::uint8_t* p = gradient.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 16), p[1] = static_cast<std::uint8_t>(y * 16), p[2] = 0,
      p[3] = 255;
    }
  const Atlas a =
      buildAtlas({texture("g", gradient, solidImage(16, 16, 127, 127, 255), solidImage(16, 16, 0, 0, 0, 0))});
  // The tile starts 8 texels into its slot; the texel left of it is the tile's right edge.
  EXPECT_EQ(a.albedo[0].pixel(7, 8)[0], 15 * 16);
  EXPECT_EQ(a.albedo[0].pixel(8, 7)[1], 15 * 16);
  EXPECT_EQ(a.albedo[0].pixel(24, 8)[0], 0);
}

TEST(Mipmap, AlbedoIsAveragedInLinearLightAndWeightedByAlpha) {
  Image img(2, 2);
  const std::uint8_t texels[4][4] = {{255, 0, 0, 255}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
  for (int i = 0; i < 4; ++i) std::copy(texels[i], texels[i] + 4, img.pixel(i % 2, i / 2));
  const Image half = mip::halveAlbedo(img);
  EXPECT_EQ(half.pixel(0, 0)[0], 255) << "transparent texels must not darken the colour";
  EXPECT_EQ(half.pixel(0, 0)[3], 64);
  // Black and white average to linear 0.5, which is sRGB 188, not 128.
  Image bw(2, 2);
  for (int i = 0; i < 4; ++i) {
    const std::uint8_t v = i % 2 ? 255 : 0;
    std::uint8_t* p = bw.pixel(i % 2, i / 2);
    p[0] = p[1] = p[2] = v, p[3] = 255;
  }
  EXPECT_NEAR(mip::halveAlbedo(bw).pixel(0, 0)[0], 188, 1);
}

TEST(Mipmap, SparseLeavesKeepTheirCoverageInTheDistance) {
  Image leaves(16, 16);
  for (int i = 0; i < 256; ++i) {
    std::uint8_t* p = leaves.pixel(i % 16, i / 16);
    p[0] = p[1] = p[2] = 120;
    p[3] = (i * 37 % 100) < 40 ? 255 : 0;  // 40 % leaf, scattered
  }
  const Atlas a = buildAtlas(
      {texture("leaves", leaves, solidImage(16, 16, 127, 127, 255), solidImage(16, 16, 0, 0, 0, 0))});
  ASSERT_TRUE(a.textures[0].cutout);
  const double full = mip::coverage(a.albedo[0], {8, 8, 16, 16});
  for (int level = 1; level < a.levels() - 1; ++level) {
    const int size = 16 >> level;
    const double c =
        mip::coverage(a.albedo[static_cast<std::size_t>(level)], {size / 2, size / 2, size, size});
    // Averaging 2x2 blocks leaves only a few alpha values to choose between: at level 1 this pattern
    // can have 9 % or 69 % coverage and nothing in between, hence the tolerance.
    // A 2x2 tile has coverage 0, 25, 50, 75 or 100 %: there only "not vanished" can be asked.
    if (size >= 4) {
      EXPECT_NEAR(c, full, 0.3) << "level " << level;
    }
    EXPECT_GT(c, 0.0) << "level " << level;
    // Nor do they go dark: the texels that pass keep the leaf colour, not a blend with the holes.
    const std::uint8_t* centre = a.albedo[static_cast<std::size_t>(level)].pixel(size, size);
    if (centre[3] >= 128) {
      EXPECT_NEAR(centre[0], 120, 2) << "level " << level;
    }
  }
  // Plain averaging makes 40 % leaves a 0.4 alpha everywhere, which the alpha test drops: they vanish.
  const Image plain = mip::halveAlbedo(mip::halveAlbedo(mip::halveAlbedo(a.albedo[0])));
  EXPECT_LT(mip::coverage(plain, {1, 1, 2, 2}), 0.3);
  EXPECT_GT(mip::coverage(a.albedo[3], {1, 1, 2, 2}), 0.2);
}

TEST(Mipmap, NormalsStayUnitLength) {
  Image img(2, 2);
  std::uint8_t a[4], b[4];
  labpbr::encodeNormal(glm::normalize(glm::vec3(1, 0, 1)), 1.0f, 0.0f, a);
  labpbr::encodeNormal(glm::normalize(glm::vec3(-1, 0, 1)), 0.0f, 0.25f, b);
  std::copy(a, a + 4, img.pixel(0, 0));
  std::copy(a, a + 4, img.pixel(1, 1));
  std::copy(b, b + 4, img.pixel(1, 0));
  std::copy(b, b + 4, img.pixel(0, 1));
  const auto n = labpbr::decodeNormal(mip::halveNormal(img).pixel(0, 0));
  EXPECT_NEAR(glm::length(n.normal), 1.0f, 1e-3f);
  EXPECT_NEAR(n.normal.z, 1.0f, 0.01f) << "tilted left and right average to straight up";
  EXPECT_NEAR(n.ao, 0.5f, 0.01f);
}

Image quad(const std::uint8_t t[4][4]) {
  Image img(2, 2);
  for (int i = 0; i < 4; ++i) std::copy(t[i], t[i] + 4, img.pixel(i % 2, i / 2));
  return img;
}

TEST(Mipmap, SpecularNeverBlendsAcrossMetalsEmissionOrPorosityAndSubsurface) {
  // Metal ids: the majority wins, never an in-between value.
  const std::uint8_t metals[4][4] = {
      {200, 230, 0, 255}, {100, 10, 0, 255}, {200, 230, 0, 255}, {100, 12, 0, 255}};
  const Image m = mip::halveSpecular(quad(metals));
  EXPECT_EQ(m.pixel(0, 0)[1], 230);
  EXPECT_EQ(m.pixel(0, 0)[0], 150) << "smoothness still averages";
  const std::uint8_t mixed[4][4] = {{0, 231, 0, 255}, {0, 234, 0, 255}, {0, 231, 0, 255}, {0, 237, 0, 255}};
  EXPECT_EQ(mip::halveSpecular(quad(mixed)).pixel(0, 0)[1], 231);
  const std::uint8_t dielectric[4][4] = {
      {0, 0, 0, 255}, {0, 100, 0, 255}, {0, 200, 0, 255}, {0, 229, 0, 255}};
  EXPECT_EQ(mip::halveSpecular(quad(dielectric)).pixel(0, 0)[1], 132);
  // Emission 255 means "none": three of four none stays none; mostly emissive averages the emissive ones.
  const std::uint8_t glow[4][4] = {{0, 0, 0, 255}, {0, 0, 0, 255}, {0, 0, 0, 255}, {0, 0, 0, 0}};
  EXPECT_EQ(mip::halveSpecular(quad(glow)).pixel(0, 0)[3], 255);
  const std::uint8_t lit[4][4] = {{0, 0, 0, 200}, {0, 0, 0, 254}, {0, 0, 0, 255}, {0, 0, 0, 100}};
  EXPECT_EQ(mip::halveSpecular(quad(lit)).pixel(0, 0)[3], 185);
  // Porosity 0..64 and subsurface 65..255 are separate ranges.
  const std::uint8_t sss[4][4] = {{0, 0, 60, 255}, {0, 0, 200, 255}, {0, 0, 180, 255}, {0, 0, 190, 255}};
  EXPECT_EQ(mip::halveSpecular(quad(sss)).pixel(0, 0)[2], 190);
  // Alpha 0 is data: it does not weight anything.
  const std::uint8_t zeroAlpha[4][4] = {
      {200, 20, 10, 0}, {200, 20, 10, 0}, {100, 20, 10, 0}, {100, 20, 10, 0}};
  EXPECT_EQ(mip::halveSpecular(quad(zeroAlpha)).pixel(0, 0)[0], 150);
  EXPECT_EQ(mip::halveSpecular(quad(zeroAlpha)).pixel(0, 0)[3], 0);
}

TEST(Atlas, MetalIdsAndAlphaZeroSpecularSurviveTheWholeMipChain) {
  Image spec(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) {
      std::uint8_t* p = spec.pixel(x, y);
      p[0] = 220;                              // smooth
      p[1] = (x / 4 + y / 4) % 2 ? 230 : 231;  // iron and gold checker
      p[2] = 0;
      p[3] = 0;  // alpha 0 on every texel, as real packs do
    }
  const Atlas a = buildAtlas(
      {texture("metal", solidImage(16, 16, 200, 200, 200), solidImage(16, 16, 127, 127, 255), spec)});
  for (int level = 0; level < a.levels(); ++level) {
    const auto [sx, sy, size] = slot(a, 0, level);
    std::set<int> ids;
    for (int y = sy; y < sy + size; ++y)
      for (int x = sx; x < sx + size; ++x) {
        const std::uint8_t* p = a.specular[static_cast<std::size_t>(level)].pixel(x, y);
        ids.insert(p[1]);
        ASSERT_EQ(p[0], 220) << "level " << level;
        ASSERT_EQ(p[3], 0) << "level " << level;
      }
    for (int id : ids) EXPECT_TRUE(id == 230 || id == 231) << "level " << level << " made id " << id;
  }
}

}  // namespace
}  // namespace terrasol
