#include "render/atlas_textures.h"

#include "assets/atlas.h"
#include "core/paths.h"
#include "support/gl_test.h"

namespace terrasol {
namespace {

class AtlasTexturesTest : public testing::GlTest {};

// The default pack's atlases reach the GPU bit for bit, every level, albedo as sRGB.
TEST_F(AtlasTexturesTest, UploadsEveryLevelExactly) {
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  std::vector<PackProblem> problems;
  std::vector<LoadedTexture> textures;
  for (const char* name : {"stone", "oak_leaves", "gold_block", "glowstone", "water_still"}) {
    textures.push_back(loadBlockTexture(packs, {name}, problems));
  }
  ASSERT_TRUE(problems.empty());
  const Atlas atlas = buildAtlas(textures);
  const AtlasTextures gpu(atlas);
  context_->checkErrors("uploading the atlases");

  GLint format = 0, levels = 0;
  glGetTextureLevelParameteriv(gpu.albedo(), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  EXPECT_EQ(format, GL_SRGB8_ALPHA8);
  glGetTextureLevelParameteriv(gpu.specular(), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  EXPECT_EQ(format, GL_RGBA8) << "LabPBR data must not be sRGB-decoded";
  glGetTextureParameteriv(gpu.normal(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  EXPECT_EQ(levels, atlas.levels());

  for (int level = 0; level < atlas.levels(); ++level) {
    const auto& expected = atlas.specular[static_cast<std::size_t>(level)];
    std::vector<std::uint8_t> back(expected.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(gpu.specular(), level, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(back.size()),
                      back.data());
    EXPECT_EQ(back, expected.rgba) << "specular level " << level;
    const auto& albedo = atlas.albedo[static_cast<std::size_t>(level)];
    back.resize(albedo.rgba.size());
    glGetTextureImage(gpu.albedo(), level, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(back.size()),
                      back.data());
    EXPECT_EQ(back, albedo.rgba) << "albedo level " << level;
  }
}

}  // namespace
}  // namespace terrasol
