#include "scene/block_colours.h"

namespace terrasol {
namespace {

constexpr int kUp = static_cast<int>(Direction::Up);
constexpr int kNorth = static_cast<int>(Direction::North);

// Calls f(rgba) for each texel of a texture's level-0 tile in the atlas.
template <class F>
void forEachTexel(const Atlas& atlas, int texture, F&& f) {
  const AtlasTexture& t = atlas.textures[static_cast<std::size_t>(texture)];
  const Image& image = atlas.albedo[0];
  const int pad = atlas.tileSize / 2;
  const int x0 = (t.firstTile % atlas.columns) * atlas.slotSize + pad;
  const int y0 = (t.firstTile / atlas.columns) * atlas.slotSize + pad;
  for (int y = 0; y < atlas.tileSize; ++y)
    for (int x = 0; x < atlas.tileSize; ++x) f(image.pixel(x0 + x, y0 + y));
}

// A texture's mean colour over its opaque texels, and how many of them are opaque.
glm::vec4 meanOf(const Atlas& atlas, int texture) {
  glm::vec3 sum(0.0f);
  int opaque = 0;
  forEachTexel(atlas, texture, [&](const std::uint8_t* p) {
    if (p[3] < 128) return;
    sum += glm::vec3(p[0], p[1], p[2]) / 255.0f;
    ++opaque;
  });
  const float texels = static_cast<float>(atlas.tileSize * atlas.tileSize);
  return opaque ? glm::vec4(sum / static_cast<float>(opaque), static_cast<float>(opaque) / texels)
                : glm::vec4(0.0f);
}

// A texture's mean alpha, 0..1.
float meanAlpha(const Atlas& atlas, int texture) {
  double sum = 0.0;
  forEachTexel(atlas, texture, [&](const std::uint8_t* p) { sum += p[3] / 255.0; });
  return static_cast<float>(sum / (atlas.tileSize * atlas.tileSize));
}

// The quad a model block shows from above: its highest up-facing one, else its first.
const ModelQuad* topQuad(const std::vector<ModelQuad>& quads) {
  const ModelQuad* best = nullptr;
  int bestY = -1;
  for (const ModelQuad& q : quads) {
    if (q.face != kUp) continue;
    if (q.corners32[0][1] > bestY) best = &q, bestY = q.corners32[0][1];
  }
  return best ? best : quads.empty() ? nullptr : &quads.front();
}

}  // namespace

std::vector<TopColour> blockTopColours(const BlockRegistry& blocks, const BlockAtlas& atlas) {
  std::vector<TopColour> colours(blocks.size());
  std::vector<glm::vec4> means(atlas.atlas.textures.size(), glm::vec4(-1.0f));
  const auto mean = [&](int texture) {
    glm::vec4& m = means[static_cast<std::size_t>(texture)];
    if (m.a < 0.0f) m = meanOf(atlas.atlas, texture);
    return m;
  };
  for (BlockId id = 1; id < blocks.size(); ++id) {
    const BlockType& type = blocks[id];
    if (type.shape == BlockShape::None) continue;
    glm::vec4 c(0.0f);
    bool tinted = type.tint != Tint::None;
    if (type.shape == BlockShape::Model) {
      const std::vector<ModelQuad>& quads = atlas.modelQuads[atlas.sameAs[id]];
      const ModelQuad* q = topQuad(quads);
      if (!q) continue;
      c = mean(q->texture);
      tinted = tinted && q->tinted;
    } else {
      c = mean(atlas.textureOf(id, kUp));
    }
    colours[id] = {c, tinted ? type.tint : Tint::None};
  }
  return colours;
}

LodPalette lodPaletteOf(const BlockRegistry& blocks, const BlockAtlas& atlas) {
  const std::vector<TopColour> tops = blockTopColours(blocks, atlas);
  LodPalette palette;
  palette.tints = atlas.tints;
  palette.blocks.resize(blocks.size());
  for (BlockId id = 1; id < blocks.size(); ++id) {
    const BlockType& type = blocks[id];
    LodBlockColour& c = palette.blocks[id];
    c.top = c.side = glm::vec3(tops[id].texture);
    c.topTint = c.sideTint = tops[id].tint;
    if (type.shape == BlockShape::Liquid) c.opacity = meanAlpha(atlas.atlas, atlas.textureOf(id, kUp));
    if (type.shape != BlockShape::Cube) continue;
    c.side = glm::vec3(meanOf(atlas.atlas, atlas.textureOf(id, kNorth)));
    c.sideTint = type.tint == Tint::Grass ? Tint::None : type.tint;
  }
  return palette;
}

}  // namespace terrasol
