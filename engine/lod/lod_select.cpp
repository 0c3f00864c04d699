#include "lod/lod_select.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace terrasol {
namespace {

struct Rect {
  glm::dvec2 min, max;
};

Rect rectOf(LodTileKey key) {
  const glm::dvec2 min(key.minBlockX(), key.minBlockZ());
  return {min, min + glm::dvec2(key.spanBlocks())};
}

double distanceTo(const Rect& r, glm::dvec2 p) {
  return glm::length(glm::max(glm::dvec2(0.0), glm::max(r.min - p, p - r.max)));
}

// The full-detail square in blocks.
Rect blocksOf(const ChunkSquare& s) {
  return {glm::dvec2(s.min) * double(kChunkSize), glm::dvec2(s.max + 1) * double(kChunkSize)};
}

bool overlaps(const Rect& a, const Rect& b) {  // sharing an edge counts
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}
bool inside(const Rect& a, const Rect& b) {
  return a.min.x >= b.min.x && a.min.y >= b.min.y && a.max.x <= b.max.x && a.max.y <= b.max.y;
}

struct Selector {
  const LodView& view;
  const LodLevels& levels;
  std::optional<Rect> reach, covered;
  std::vector<std::pair<double, LodSelected>> out;

  void visit(LodTileKey key) {
    const Rect r = rectOf(key);
    const double d = distanceTo(r, view.camera);
    if (d > view.distance) return;
    if (covered && inside(r, *covered)) return;
    const bool touches = reach && overlaps(r, *reach);
    const bool split = key.level > levels.minLevel &&
                       (d < levels.detail * key.spanBlocks() || (touches && key.level > kLodChunkLevel));
    if (!split) {
      out.push_back({d, {key, touches}});
      return;
    }
    for (int i = 0; i < 4; ++i) visit({key.level - 1, 2 * key.x + (i & 1), 2 * key.z + (i >> 1)});
  }
};

}  // namespace

std::vector<LodSelected> selectLodTiles(const LodView& view, const LodLevels& levels) {
  if (view.distance <= 0.0) return {};
  Selector s{view, levels, std::nullopt, std::nullopt, {}};
  if (view.reach) s.reach = blocksOf(*view.reach);
  if (view.covered) s.covered = blocksOf(*view.covered);
  int root = std::max(levels.minLevel, 0);
  while (root < kLodMaxLevel && (kLodTileCells << root) < view.distance) ++root;
  const auto span = static_cast<double>(kLodTileCells << root);
  const int x0 = static_cast<int>(std::floor((view.camera.x - view.distance) / span));
  const int x1 = static_cast<int>(std::floor((view.camera.x + view.distance) / span));
  const int z0 = static_cast<int>(std::floor((view.camera.y - view.distance) / span));
  const int z1 = static_cast<int>(std::floor((view.camera.y + view.distance) / span));
  for (int z = z0; z <= z1; ++z)
    for (int x = x0; x <= x1; ++x) s.visit({root, x, z});
  std::stable_sort(s.out.begin(), s.out.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<LodSelected> tiles;
  tiles.reserve(s.out.size());
  for (const auto& [d, t] : s.out) tiles.push_back(t);
  return tiles;
}

}  // namespace terrasol
