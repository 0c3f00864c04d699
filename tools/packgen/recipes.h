#pragma once
// The texel recipes behind the default pack: what each texel of a generated texture holds, the noise
// they are painted with, and the shared recipes (stone, planks, glass...). Internal to packgen.

#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "packgen.h"

namespace terrasol::packgen {

inline constexpr int kSize = 16;

// Everything a recipe paints, per texel: colour, height (0 deep .. 1 surface) and LabPBR specular.
struct Texel {
  glm::vec3 color{0.5f};  // sRGB 0..1
  float alpha = 1.0f;
  float height = 1.0f;
  int smoothness = 40;  // _s R
  int f0 = 10;          // _s G: 0..229 dielectric F0 (10 ~ 0.04), 230..237 metals
  int porosity = 0;     // _s B
  int emission = 255;   // _s A: 255 = none
};
using Canvas = std::vector<Texel>;  // kSize x (kSize * frames), row-major

float hash01(std::uint64_t seed, int x, int y, int z = 0);
// Tileable value noise over a 16-texel period, `cells` cells per period.
float tileNoise(std::uint64_t seed, float x, float y, int cells, int frame = 0);
float fbm(std::uint64_t seed, float x, float y, int frame = 0);
// Distance to the nearest and second-nearest of `count` wrapping feature points, and the nearest's id.
struct Cells {
  float d1, d2;
  int id;
};
Cells voronoi(std::uint64_t seed, int x, int y, int count);
glm::vec3 rgb(int r, int g, int b);
Canvas paint(int frames, const std::function<Texel(int x, int y, int frame)>& f);

// Nothing: a texel a cutout model shows through.
inline Texel clear() {
  Texel t;
  t.alpha = 0.0f;
  return t;
}
Texel rock(std::uint64_t seed, int x, int y, glm::vec3 base, float contrast);
Texel stone(int x, int y);
Texel cobblestone(int x, int y);
Texel dirt(int x, int y);
Texel planks(int x, int y);
Texel logSide(int x, int y);
Texel glass(int x, int y);
Texel logTop(int x, int y);
Texel leaves(int x, int y);
Texel glowstone(int x, int y);
Texel netherrack(int x, int y);
// Minecraft's torch layout: the model shows columns 7..8, the flame in rows 6..8 and the stick below.
Texel torch(int x, int y);
// Minecraft's lantern layout: a metal cage round a glow, and its cap (families.cpp).
Texel lantern(int x, int y);
// Specks of an ore in stone.
Texel ore(int x, int y, std::uint64_t seed, glm::vec3 speck, int specular);
// Water or lava, still or flowing, frame `frame` of its animation.
Texel liquid(int x, int y, int frame, bool lava, bool flowing);
// The same recipes in other colours and seeds, for the other woods, stones and ores.
Texel planksOf(int x, int y, glm::vec3 colour);
Texel logSideOf(int x, int y, glm::vec3 bark);
Texel logTopOf(int x, int y, glm::vec3 bark, glm::vec3 wood);
Texel leavesOf(int x, int y, std::uint64_t seed);
Texel oreIn(int x, int y, std::uint64_t seed, glm::vec3 speck, int specular, Texel (*ground)(int, int));
Texel metalBlock(int x, int y, glm::vec3 base, int metal, int smoothness);
Texel plant(int x, int y, std::uint64_t seed, glm::vec3 flower);

// Minecraft's sixteen dye colours, in its order.
inline constexpr std::array<std::pair<const char*, std::array<int, 3>>, 16> kDyes = {{
    {"white", {233, 236, 236}},
    {"orange", {240, 118, 19}},
    {"magenta", {189, 68, 179}},
    {"light_blue", {58, 175, 217}},
    {"yellow", {248, 197, 39}},
    {"lime", {112, 185, 25}},
    {"pink", {237, 141, 172}},
    {"gray", {62, 68, 71}},
    {"light_gray", {142, 142, 134}},
    {"cyan", {21, 137, 145}},
    {"purple", {121, 42, 172}},
    {"blue", {53, 57, 157}},
    {"brown", {114, 71, 40}},
    {"green", {84, 109, 27}},
    {"red", {160, 39, 34}},
    {"black", {20, 21, 25}},
}};
inline glm::vec3 dye(std::size_t i) {
  return rgb(kDyes[i].second[0], kDyes[i].second[1], kDyes[i].second[2]);
}

// Finishes and patterns shared by the families.
// A rock's colour with a second mineral speckled through it (granite, diorite).
Texel speckled(int x, int y, std::uint64_t seed, glm::vec3 base, glm::vec3 speck, float amount);
// Cut and polished: a bevelled rim, a smooth face that reflects.
Texel polished(Texel t, int x, int y);
// Bricks laid in courses of `rows` texels, every other course shifted by half a brick.
Texel bricks(int x, int y, std::uint64_t seed, glm::vec3 brick, glm::vec3 mortar, int rows, int width);
Texel crack(Texel t, int x, int y);
Texel moss(Texel t, int x, int y, std::uint64_t seed);
Texel smooth(int x, int y, std::uint64_t seed, glm::vec3 colour, float contrast, int smoothness);
Texel terracotta(int x, int y, glm::vec3 colour);

// A wood's door halves and trapdoor: boards running up, a frame, windows (crafted.cpp).
Texel doorBottom(int x, int y, glm::vec3 wood);
Texel doorTop(int x, int y, glm::vec3 wood);
Texel trapdoor(int x, int y, glm::vec3 wood);

// One still texture from a recipe.
GeneratedTexture still(const std::string& name, const std::function<Texel(int, int)>& f);

// The textures of crafted and shaped blocks: doors, trapdoors, ladders, panes, furnaces,
// farmland and paths (crafted.cpp).
void addCraftedTextures(std::vector<GeneratedTexture>& out);
// More stones, the other woods, sandstone, the sixteen colours, crafted blocks, plants, ores, metal
// and gem blocks (families.cpp).
void addFamilyTextures(std::vector<GeneratedTexture>& out);
// Terracotta and concrete powder in sixteen colours, the newer woods' planks, more bricks and tiles,
// stones, soils, corals and weathered coppers (building_blocks.cpp).
void addBuildingBlockTextures(std::vector<GeneratedTexture>& out);
// The made things: redstone, rails, torches, work stations, copper's ages, candles, shulker boxes,
// glazed terracotta, heads (device_textures.cpp).
void addDeviceTextures(std::vector<GeneratedTexture>& out);
// Crops, double plants, corals, vines and cave growths (growth_textures.cpp), and the natural blocks
// with faces of their own (natural_textures.cpp).
void addGrowthTextures(std::vector<GeneratedTexture>& out);
void addNaturalTextures(std::vector<GeneratedTexture>& out);
// Tulips and the other flowers, saplings, mushrooms, the Nether's fungi and roots, seagrass (plants.cpp).
void addPlantTextures(std::vector<GeneratedTexture>& out);

}  // namespace terrasol::packgen
