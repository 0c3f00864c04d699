#include "assets/atlas.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "assets/mipmap.h"

namespace terrasol {
namespace {

constexpr int kMaxTile = 512;

Image scaleTo(const Image& src, int size) {
  if (src.width == size && src.height == size) return src;
  return resizeImage(src, size, size, false);
}

// Copies `tile` into the slot at (sx, sy) of `atlas`, the band around it wrapping the tile.
void placeTile(Image& atlas, int sx, int sy, const Image& tile) {
  const int t = tile.width, slot = 2 * t, pad = t / 2;
  for (int y = 0; y < slot; ++y) {
    const int ty = ((y - pad) % t + t) % t;
    for (int x = 0; x < slot; ++x) {
      const int tx = ((x - pad) % t + t) % t;
      std::memcpy(atlas.pixel(sx + x, sy + y), tile.pixel(tx, ty), 4);
    }
  }
}

// Texels either clearly cut away or clearly solid, and some of each: an alpha-tested texture.
bool isCutout(const Image& image) {
  int clear = 0, solid = 0;
  const int n = image.width * image.height;
  for (int i = 0; i < n; ++i) {
    const std::uint8_t a = image.rgba[static_cast<std::size_t>(i) * 4 + 3];
    clear += a < 26;
    solid += a > 229;
  }
  return clear > 0 && solid > 0 && clear + solid >= n * 9 / 10;
}

}  // namespace

glm::vec4 Atlas::tileRect(int tile) const {
  const int pad = tileSize / 2;
  const float x = static_cast<float>((tile % columns) * slotSize + pad);
  const float y = static_cast<float>((tile / columns) * slotSize + pad);
  const float w = static_cast<float>(columns * slotSize), h = static_cast<float>(rows * slotSize);
  return {x / w, y / h, (x + static_cast<float>(tileSize)) / w, (y + static_cast<float>(tileSize)) / h};
}

// Per texture, the largest of `value(texel)` over its _s texels in every frame, scaled to 0..1.
template <class Value>
std::vector<float> largestSpecular(const Atlas& atlas, Value value) {
  std::vector<float> out(atlas.textures.size(), 0.0f);
  if (atlas.specular.empty()) return out;
  const Image& level = atlas.specular.front();
  const int pad = atlas.tileSize / 2;
  for (std::size_t t = 0; t < atlas.textures.size(); ++t) {
    std::uint8_t most = 0;
    for (int tile = atlas.textures[t].firstTile;
         tile < atlas.textures[t].firstTile + atlas.textures[t].frames; ++tile) {
      const int x0 = (tile % atlas.columns) * atlas.slotSize + pad,
                y0 = (tile / atlas.columns) * atlas.slotSize + pad;
      for (int y = y0; y < y0 + atlas.tileSize; ++y)
        for (int x = x0; x < x0 + atlas.tileSize; ++x) most = std::max(most, value(level.pixel(x, y)));
    }
    out[t] = static_cast<float>(most) / 255.0f;
  }
  return out;
}

std::vector<float> textureSmoothness(const Atlas& atlas) {
  return largestSpecular(atlas, [](const std::uint8_t* s) { return s[0]; });
}

std::vector<float> textureEmission(const Atlas& atlas) {
  // LabPBR: alpha 255 is no emission, below it alpha / 254 (lib/labpbr.glsl).
  return largestSpecular(atlas, [](const std::uint8_t* s) { return s[3] == 255 ? std::uint8_t{0} : s[3]; });
}

int Atlas::find(const std::string& name) const {
  const auto it = byName.find(name);
  return it == byName.end() ? -1 : it->second;
}

Atlas buildAtlas(const std::vector<LoadedTexture>& textures) {
  Atlas atlas;
  int widest = 1, tiles = 0;
  for (const auto& t : textures) {
    widest = std::max(widest, t.albedo[0].width);
    tiles += static_cast<int>(t.albedo.size());
  }
  atlas.tileSize = std::min(static_cast<int>(std::bit_ceil(static_cast<unsigned>(widest))), kMaxTile);
  atlas.slotSize = 2 * atlas.tileSize;
  atlas.columns =
      std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(std::max(tiles, 1))))));
  atlas.rows = std::max(1, (tiles + atlas.columns - 1) / atlas.columns);
  const int width = atlas.columns * atlas.slotSize, height = atlas.rows * atlas.slotSize;
  Image albedo(width, height), normal(width, height), specular(width, height);

  std::vector<bool> cutoutTiles;
  int tile = 0;
  for (const auto& t : textures) {
    atlas.anyNormalMap = atlas.anyNormalMap || t.hasNormalMap;
    atlas.anySpecularMap = atlas.anySpecularMap || t.hasSpecularMap;
    AtlasTexture entry{t.name, tile, static_cast<int>(t.albedo.size()), t.animation, t.missing, false};
    for (std::size_t f = 0; f < t.albedo.size(); ++f, ++tile) {
      const int sx = (tile % atlas.columns) * atlas.slotSize, sy = (tile / atlas.columns) * atlas.slotSize;
      const Image a = scaleTo(t.albedo[f], atlas.tileSize);
      entry.cutout = entry.cutout || isCutout(a);
      placeTile(albedo, sx, sy, a);
      Image n = scaleTo(t.normal[f], atlas.tileSize);
      if (t.openGlNormals) {  // the atlas holds LabPBR's DirectX convention: green points down
        for (std::size_t i = 1; i < n.rgba.size(); i += 4)
          n.rgba[i] = static_cast<std::uint8_t>(255 - n.rgba[i]);
      }
      placeTile(normal, sx, sy, n);
      placeTile(specular, sx, sy, scaleTo(t.specular[f], atlas.tileSize));
    }
    for (int f = 0; f < entry.frames; ++f) cutoutTiles.push_back(entry.cutout);
    atlas.byName.emplace(entry.name, static_cast<int>(atlas.textures.size()));
    atlas.textures.push_back(std::move(entry));
  }

  // Coverage of each cutout tile at full size, kept at every level.
  std::vector<double> coverage(static_cast<std::size_t>(tiles), 0.0);
  const int pad0 = atlas.tileSize / 2;
  for (int i = 0; i < tiles; ++i) {
    if (!cutoutTiles[static_cast<std::size_t>(i)]) continue;
    const int sx = (i % atlas.columns) * atlas.slotSize, sy = (i / atlas.columns) * atlas.slotSize;
    coverage[static_cast<std::size_t>(i)] =
        mip::coverage(albedo, {sx + pad0, sy + pad0, atlas.tileSize, atlas.tileSize});
  }

  atlas.albedo.push_back(std::move(albedo));
  atlas.normal.push_back(std::move(normal));
  atlas.specular.push_back(std::move(specular));
  for (int size = atlas.tileSize / 2, slot = atlas.slotSize / 2; size >= 1; size /= 2, slot /= 2) {
    Image a = mip::halveAlbedo(atlas.albedo.back());
    for (int i = 0; i < tiles; ++i) {
      if (!cutoutTiles[static_cast<std::size_t>(i)]) continue;
      const int sx = (i % atlas.columns) * slot, sy = (i / atlas.columns) * slot;
      mip::preserveCoverage(a, {sx + size / 2, sy + size / 2, size, size}, {sx, sy, slot, slot},
                            coverage[static_cast<std::size_t>(i)]);
    }
    atlas.albedo.push_back(std::move(a));
    atlas.normal.push_back(mip::halveNormal(atlas.normal.back()));
    atlas.specular.push_back(mip::halveSpecular(atlas.specular.back()));
  }
  return atlas;
}

}  // namespace terrasol
