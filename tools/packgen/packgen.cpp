#include "packgen.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "assets/crack_textures.h"
#include "assets/labpbr.h"
#include "recipes.h"
#include "world/noise.h"

namespace terrasol::packgen {

namespace {

// --- encoding ------------------------------------------------------------------------------------

std::uint8_t byte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

GeneratedTexture encode(const std::string& name, const Canvas& c, int frames, int frametime) {
  const int h = kSize * frames;
  GeneratedTexture g{name, Image(kSize, h), Image(kSize, h), Image(kSize, h), ""};
  auto at = [&](int x, int y) -> const Texel& {
    const int frame = y / kSize, ly = ((y % kSize) + kSize) % kSize, lx = ((x % kSize) + kSize) % kSize;
    return c[static_cast<std::size_t>((frame * kSize + ly) * kSize + lx)];
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Texel& t = at(x, y);
      const int fy = y / kSize * kSize, ly = y % kSize;  // wrap within the frame
      auto height = [&](int dx, int dy) { return at(x + dx, fy + (ly + dy + kSize) % kSize).height; };
      // Normal from the height field (+y up the texture, rows run down), 3 texels per unit height.
      const glm::vec3 n(-(height(1, 0) - height(-1, 0)) * 1.5f, (height(0, 1) - height(0, -1)) * 1.5f, 1.0f);
      const float around = 0.25f * (height(1, 0) + height(-1, 0) + height(0, 1) + height(0, -1));
      const float ao = std::clamp(1.0f - 2.0f * std::max(0.0f, around - t.height), 0.3f, 1.0f);
      std::uint8_t* a = g.albedo.pixel(x, y);
      a[0] = byte(t.color.r), a[1] = byte(t.color.g), a[2] = byte(t.color.b), a[3] = byte(t.alpha);
      labpbr::encodeNormal(glm::normalize(n), ao, 0.25f * (1.0f - std::max(t.height, 1.0f / 255.0f)),
                           g.normal.pixel(x, y));
      std::uint8_t* s = g.specular.pixel(x, y);
      s[0] = static_cast<std::uint8_t>(std::clamp(t.smoothness, 0, 255));
      s[1] = static_cast<std::uint8_t>(std::clamp(t.f0, 0, 255));
      s[2] = static_cast<std::uint8_t>(std::clamp(t.porosity, 0, 255));
      s[3] = static_cast<std::uint8_t>(std::clamp(t.emission, 0, 255));
    }
  if (frames > 1) {
    g.mcmeta = "{\n  \"animation\": {\n    \"frametime\": " + std::to_string(frametime) +
               ",\n    \"interpolate\": true\n  }\n}\n";
  }
  return g;
}

}  // namespace

GeneratedTexture still(const std::string& name, const std::function<Texel(int, int)>& f) {
  return encode(name, paint(1, [&f](int x, int y, int) { return f(x, y); }), 1, 1);
}

std::vector<GeneratedTexture> generateDefaultTextures() {
  std::vector<GeneratedTexture> out;
  out.push_back(still("stone", stone));
  out.push_back(still("cobblestone", cobblestone));
  out.push_back(still("dirt", dirt));
  out.push_back(still("sand", [](int x, int y) {
    Texel t = rock(101, x, y, rgb(219, 207, 163), 0.06f);
    t.porosity = 35;
    t.smoothness = 25;
    return t;
  }));
  out.push_back(still("gravel", [](int x, int y) {
    const Cells c = voronoi(111, x, y, 12);
    Texel t = rock(112, x, y, rgb(136, 126, 126) * (0.7f + 0.5f * hash01(113, c.id, 0)), 0.1f);
    t.height = std::clamp(1.0f - c.d1 / 4.0f, 0.2f, 1.0f);
    return t;
  }));
  out.push_back(still("bedrock", [](int x, int y) { return rock(121, x, y, rgb(85, 85, 85), 0.5f); }));
  out.push_back(still("grass_block_top", [](int x, int y) {
    Texel t = rock(131, x, y, glm::vec3(0.62f), 0.15f);  // grey: tinted by the grass colour
    t.porosity = 60;
    return t;
  }));
  out.push_back(still("grass_block_side", [](int x, int y) {
    const int fringe = 3 + static_cast<int>(hash01(141, x, 0) * 3);
    if (y < fringe) {
      Texel t = rock(142, x, y, rgb(95, 159, 53), 0.15f);
      t.height = 1.0f;
      return t;
    }
    return dirt(x, y);
  }));
  // Under snow (snowy=true): dirt with a deeper fringe of snow hanging over its top.
  out.push_back(still("grass_block_snow", [](int x, int y) {
    const int fringe = 4 + static_cast<int>(hash01(143, x, 0) * 3);
    if (y < fringe) {
      Texel t = rock(144, x, y, rgb(245, 250, 250), 0.03f);
      t.smoothness = 70;
      t.porosity = 160;
      return t;
    }
    return dirt(x, y);
  }));
  out.push_back(still("ice", [](int x, int y) {
    Texel t = rock(151, x, y, rgb(160, 190, 240), 0.08f);
    t.alpha = 0.78f;
    t.smoothness = 235;
    t.f0 = 5;
    t.porosity = 0;
    return t;
  }));
  out.push_back(still("snow", [](int x, int y) {
    Texel t = rock(161, x, y, rgb(245, 250, 250), 0.03f);
    t.smoothness = 70;
    t.porosity = 160;  // subsurface scattering
    return t;
  }));
  out.push_back(still("oak_log", logSide));
  out.push_back(still("oak_log_top", logTop));
  out.push_back(still("oak_leaves", leaves));
  out.push_back(still("oak_planks", planks));
  out.push_back(still("glass", glass));
  out.push_back(still("short_grass", [](int x, int y) { return plant(x, y, 171, glm::vec3(-1.0f)); }));
  out.push_back(still("dandelion", [](int x, int y) { return plant(x, y, 172, rgb(250, 215, 40)); }));
  out.push_back(still("poppy", [](int x, int y) { return plant(x, y, 173, rgb(215, 30, 30)); }));
  out.push_back(still("coal_ore", [](int x, int y) { return ore(x, y, 181, rgb(45, 45, 45), 12); }));
  out.push_back(still("iron_ore", [](int x, int y) { return ore(x, y, 182, rgb(216, 175, 147), 230); }));
  out.push_back(still("gold_ore", [](int x, int y) { return ore(x, y, 183, rgb(250, 220, 80), 231); }));
  out.push_back(
      still("iron_block", [](int x, int y) { return metalBlock(x, y, rgb(220, 220, 220), 230, 210); }));
  out.push_back(
      still("gold_block", [](int x, int y) { return metalBlock(x, y, rgb(250, 210, 60), 231, 230); }));
  out.push_back(
      still("copper_block", [](int x, int y) { return metalBlock(x, y, rgb(192, 107, 79), 234, 190); }));
  out.push_back(still("glowstone", glowstone));
  out.push_back(still("torch", torch));
  out.push_back(encode("water_still",
                       paint(8, [](int x, int y, int f) { return liquid(x, y, f, false, false); }), 8, 3));
  out.push_back(
      encode("water_flow", paint(8, [](int x, int y, int f) { return liquid(x, y, f, false, true); }), 8, 2));
  out.push_back(
      encode("lava_still", paint(8, [](int x, int y, int f) { return liquid(x, y, f, true, false); }), 8, 4));
  out.push_back(
      encode("lava_flow", paint(8, [](int x, int y, int f) { return liquid(x, y, f, true, true); }), 8, 3));
  addCraftedTextures(out);
  addFamilyTextures(out);
  addBuildingBlockTextures(out);
  addPlantTextures(out);
  addDeviceTextures(out);
  addGrowthTextures(out);
  addNaturalTextures(out);
  return out;
}

void writeDefaultPack(const std::filesystem::path& dir) {
  const auto blockDir = dir / "assets" / "minecraft" / "textures" / "block";
  std::filesystem::create_directories(blockDir);
  for (const auto& t : generateDefaultTextures()) {
    saveImage(blockDir / (t.name + ".png"), t.albedo);
    saveImage(blockDir / (t.name + "_n.png"), t.normal);
    saveImage(blockDir / (t.name + "_s.png"), t.specular);
    if (!t.mcmeta.empty()) std::ofstream(blockDir / (t.name + ".png.mcmeta")) << t.mcmeta;
  }
  const std::vector<Image> cracks = generateCracks();
  for (int stage = 0; stage < kCrackStages; ++stage)
    saveImage(blockDir / (crackTextureName(stage) + ".png"), cracks[static_cast<std::size_t>(stage)]);
  const auto colormapDir = dir / "assets" / "minecraft" / "textures" / "colormap";
  std::filesystem::create_directories(colormapDir);
  for (const auto& c : generateColormaps()) saveImage(colormapDir / (c.name + ".png"), c.map);
  const auto environmentDir = dir / "assets" / "minecraft" / "textures" / "environment";
  std::filesystem::create_directories(environmentDir);
  saveImage(environmentDir / "clouds.png", generateClouds());
  for (const GeneratedFile& f : generateShapedBlockFiles()) {
    std::filesystem::create_directories((dir / f.path).parent_path());
    std::ofstream(dir / f.path, std::ios::binary) << f.text;
  }
}

}  // namespace terrasol::packgen
