#pragma once
// What the textures of made and grown things share (device_textures.cpp, face_textures.cpp,
// growth_textures.cpp, natural_textures.cpp): frames, holes, copper's ages, redstone dust, bold signs
// on a cube. Internal to packgen.

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "recipes.h"

namespace terrasol::packgen {

using Recipe = std::function<Texel(int, int)>;

// Each named recipe as a still texture.
void addAll(std::vector<GeneratedTexture>& out, const std::vector<std::pair<std::string, Recipe>>& recipes);

Texel tinted(Texel t, glm::vec3 colour);
Texel glowing(Texel t, int emission);
// Within `width` texels of the texture's edge.
bool rim(int x, int y, int width = 1);
// A frame of `frame` round a field of `field`: the faces of machines and tables.
Texel framed(int x, int y, const Texel& field, glm::vec3 frame);
// `t` with a one-texel rim of `frame`.
Texel edged(Texel t, int x, int y, glm::vec3 frame);
// A dark round hole of radius `r` at (cx, cy) in `around`.
Texel hole(int x, int y, int cx, int cy, int r, const Texel& around);
// Grooves round the rim and in a square: chiseled stone and metal.
Texel chiseled(int x, int y, const Texel& ground);

// Copper in its four ages: bare metal turning to a green patina.
inline constexpr std::array<std::pair<const char*, std::array<int, 3>>, 4> kCopper = {
    {{"", {192, 107, 79}},
     {"exposed_", {161, 125, 103}},
     {"weathered_", {108, 153, 110}},
     {"oxidized_", {82, 162, 132}}}};
Texel copperAt(int x, int y, std::size_t age);

// Redstone dust: a dot, or a line running down the texture.
Texel dust(int x, int y, bool line);

// A cube of sixteen texels showing a single bold sign in 2x2 texels: the operator's blocks, note blocks...
Texel sign(int x, int y, glm::vec3 base, glm::vec3 ink, const std::array<const char*, 8>& glyph);
inline constexpr std::array<const char*, 8> kArrow = {"........", "...##...", "..####..", ".##..##.",
                                                      "...##...", "...##...", "...##...", "........"};
inline constexpr std::array<const char*, 8> kNote = {"........", "....###.", "....#.#.", "....#...",
                                                     "..###...", ".####...", "..##....", "........"};
inline constexpr std::array<const char*, 8> kRing = {"........", "..####..", ".#....#.", ".#.##.#.",
                                                     ".#.##.#.", ".#....#.", "..####..", "........"};
inline constexpr std::array<const char*, 8> kPlain = {"........", "........", "........", "........",
                                                      "........", "........", "........", "........"};

// The coloured blocks (candles, shulker boxes, glazed terracotta, heads), the fronted blocks of wood
// and stone, and Minecraft's own face names for work stations and redstone (face_textures.cpp).
void addColouredTextures(std::vector<GeneratedTexture>& out);
void addFrontTextures(std::vector<GeneratedTexture>& out);
void addFaceTextures(std::vector<GeneratedTexture>& out);

}  // namespace terrasol::packgen
