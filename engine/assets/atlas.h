#pragma once
// Three texture atlases with one shared layout (albedo sRGB, LabPBR normal, LabPBR specular), so one UV
// samples all three, with their mip chains.
//
// Every frame of every texture gets a square slot twice the tile size, aligned to the slot grid: the
// tile sits in the middle, and the band around it repeats the tile's opposite edges (block textures
// tile), so bilinear filtering at a tile edge reads its own texture. Each mip level halves every slot
// exactly, down to a 1-texel tile in a 2-texel slot, so no level ever mixes two textures.

#include <glm/vec4.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "assets/texture_loader.h"

namespace terrasol {

struct AtlasTexture {
  std::string name;
  int firstTile = 0;  // tiles firstTile .. firstTile + frames - 1 hold the strip's frames
  int frames = 1;
  std::optional<Animation> animation;
  bool missing = false;
  bool cutout = false;  // has texels an alpha test discards
};

struct Atlas {
  int tileSize = 16;  // texels of a tile at level 0 (every texture is scaled to this)
  int slotSize = 32;
  int columns = 0, rows = 0;
  std::vector<Image> albedo, normal, specular;  // one image per mip level, level 0 first
  std::vector<AtlasTexture> textures;
  std::unordered_map<std::string, int> byName;
  // Whether any texture came with a _n / _s companion (else those atlases hold only the defaults).
  bool anyNormalMap = false, anySpecularMap = false;

  int levels() const { return static_cast<int>(albedo.size()); }
  // UV rectangle (u0, v0, u1, v1) of a tile's texels, with v = 0 at the top row of the image.
  glm::vec4 tileRect(int tile) const;
  // Index of `name` in textures, or -1.
  int find(const std::string& name) const;
};

// Each texture's highest LabPBR smoothness (_s red, 0..1) over all its frames, by texture index.
std::vector<float> textureSmoothness(const Atlas& atlas);
// Each texture's highest LabPBR emission (_s alpha below 255, 0..1) over all its frames.
std::vector<float> textureEmission(const Atlas& atlas);

// Lays out and builds the atlases. The tile size is the largest frame width, rounded up to a power
// of two (at most 512); smaller textures are scaled up without filtering (pixel art stays crisp).
Atlas buildAtlas(const std::vector<LoadedTexture>& textures);

}  // namespace terrasol
