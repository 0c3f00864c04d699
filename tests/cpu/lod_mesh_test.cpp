// Far terrain's meshes, tile choice and tile store (lod/): quads facing out, tiles of two levels meeting
// with no gap (rays that hit the cells' columns hit the mesh), a disc covered once, edits reaching tiles.

#include "lod/lod_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <vector>

#include "lod/lod_select.h"
#include "lod/lod_terrain.h"

namespace terrasol {
namespace {

constexpr BlockId kGround = 1, kWater = 2;

LodPalette greyPalette() {
  LodPalette p;
  p.blocks.resize(3);
  p.blocks[kWater].top = glm::vec3(0.2f, 0.3f, 0.9f);
  return p;
}

// A tile of hills: heights from a hash, `span` blocks between the lowest and highest.
LodTile hillyTile(LodTileKey key, int base, int span) {
  LodTile tile{key, {}};
  for (int z = 0; z < kLodTileCells; ++z)
    for (int x = 0; x < kLodTileCells; ++x) {
      const unsigned h = (static_cast<unsigned>(key.minBlockX() + x) * 73856093u ^
                          static_cast<unsigned>(key.minBlockZ() + z) * 19349663u) *
                         2654435761u;
      tile.at(x, z) = {base + static_cast<int>((h >> 16) % static_cast<unsigned>(span)), kGround};
    }
  return tile;
}

// A quad of a mesh in world blocks: its corners and the face it shows.
struct WorldQuad {
  glm::dvec3 corner[4];
  glm::dvec3 normal;
};

std::vector<WorldQuad> worldQuads(const LodMesh& mesh) {
  std::vector<WorldQuad> quads;
  const double cell = mesh.key.cellBlocks();
  for (std::size_t q = 0; q + 3 < mesh.vertices.size(); q += 4) {
    WorldQuad w{};
    for (int i = 0; i < 4; ++i) {
      const LodVertex& v = mesh.vertices[q + static_cast<std::size_t>(i)];
      w.corner[i] = {mesh.key.minBlockX() + v.x * cell, static_cast<double>(v.y) / kLodYSteps,
                     mesh.key.minBlockZ() + v.z * cell};
    }
    const int face = static_cast<int>(mesh.vertices[q].material >> kLodFaceShift) & 7;
    const BlockPos o = kDirectionOffsets[face];
    w.normal = {o.x, o.y, o.z};
    quads.push_back(w);
  }
  return quads;
}

TEST(LodMesh, QuadsTurnTheirFrontOutwardsAndStepsGetWalls) {
  LodTile tile{{2, 0, 0}, {}};
  for (LodCell& c : tile.cells) c = {70, kGround};
  tile.at(5, 5).top = 80;  // a pillar of one cell
  const LodMesh mesh = meshLodTile(tile, greyPalette(), false);
  int pillarWalls = 0;
  for (const WorldQuad& q : worldQuads(mesh)) {
    const glm::dvec3 n = glm::cross(q.corner[1] - q.corner[0], q.corner[2] - q.corner[0]);
    if (glm::length(n) < 1e-9) continue;
    EXPECT_GT(glm::dot(n, q.normal), 0.0) << "a quad wound clockwise seen from its face";
    const double top = std::max({q.corner[0].y, q.corner[1].y, q.corner[2].y, q.corner[3].y});
    const double bottom = std::min({q.corner[0].y, q.corner[1].y, q.corner[2].y, q.corner[3].y});
    if (q.normal.y == 0.0 && top == 81.0 && bottom == 71.0) ++pillarWalls;
  }
  EXPECT_EQ(pillarWalls, 4) << "the pillar's four sides, from its neighbours' tops to its own";
  // The flat cells merge: 1023 flat cells are far fewer quads than cells.
  EXPECT_LT(mesh.vertices.size() / 4, 200u);
  EXPECT_EQ(mesh.maxY, 81);
  // Meeting full detail: a top per cell and every wall, so each cell can sink on its own.
  const LodMesh walled = meshLodTile(tile, greyPalette(), true);
  EXPECT_EQ(walled.vertices.size() / 4, static_cast<std::size_t>(kLodTileCells * kLodTileCells * 5));
}

TEST(LodMesh, WaterLiesAtSevenEighthsOfItsBlockAndIsMarked) {
  LodTile tile{{1, 0, 0}, {}};
  for (LodCell& c : tile.cells) c = {50, kGround, 62, kWater};
  const LodMesh mesh = meshLodTile(tile, greyPalette(), false);
  const auto top = std::find_if(mesh.vertices.begin(), mesh.vertices.end(), [](const LodVertex& v) {
    return static_cast<Direction>((v.material >> kLodFaceShift) & 7u) == Direction::Up;
  });
  ASSERT_NE(top, mesh.vertices.end());
  EXPECT_EQ(top->y, (62 + 1) * kLodYSteps - 1);
  EXPECT_EQ((top->material >> kLodWaterShift) & 1u, 1u);
  EXPECT_EQ(mesh.vertices.size() / 4, 1u + 4u * kLodTileCells) << "one top, and the skirts round the tile";
}

// The nearest front face a ray meets, or none.
std::optional<double> nearestHit(const std::vector<WorldQuad>& quads, glm::dvec3 o, glm::dvec3 d) {
  std::optional<double> best;
  for (const WorldQuad& q : quads) {
    if (glm::dot(q.normal, d) >= 0.0) continue;  // culled, as the renderer culls back faces
    const int axis = q.normal.x != 0.0 ? 0 : q.normal.y != 0.0 ? 1 : 2;
    const double t = (q.corner[0][axis] - o[axis]) / d[axis];
    if (t <= 0.0 || (best && t >= *best)) continue;
    const glm::dvec3 p = o + t * d;
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::dvec3& c : q.corner) lo = glm::min(lo, c), hi = glm::max(hi, c);
    bool in = true;
    for (int a = 0; a < 3; ++a)
      if (a != axis) in = in && p[a] >= lo[a] - 1e-9 && p[a] <= hi[a] + 1e-9;
    if (in) best = t;
  }
  return best;
}

// Whether a ray meets any cell's column (from the floor to the cell's surface).
bool hitsColumns(const std::vector<LodTile>& tiles, glm::dvec3 o, glm::dvec3 d) {
  for (const LodTile& tile : tiles) {
    const double cell = tile.key.cellBlocks();
    for (int z = 0; z < kLodTileCells; ++z)
      for (int x = 0; x < kLodTileCells; ++x) {
        const glm::dvec3 lo(tile.key.minBlockX() + x * cell, kMinY, tile.key.minBlockZ() + z * cell);
        const glm::dvec3 hi(lo.x + cell, static_cast<double>(lodSurfaceY(tile.at(x, z))) / kLodYSteps,
                            lo.z + cell);
        double t0 = 0.0, t1 = 1e9;
        for (int a = 0; a < 3; ++a) {
          if (std::abs(d[a]) < 1e-12) {
            if (o[a] < lo[a] || o[a] > hi[a]) t0 = 2e9;
            continue;
          }
          double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
          if (ta > tb) std::swap(ta, tb);
          t0 = std::max(t0, ta), t1 = std::min(t1, tb);
        }
        if (t0 <= t1) return true;
      }
  }
  return false;
}

// A fine tile of hills (cells of 2) beside a coarse plateau (cells of 4) above them, and beyond it a
// coarse valley: every ray that meets a cell's column meets the mesh. Without the skirts at the tiles'
// edges the plateau's cliff would be open where it meets the hills.
TEST(LodMesh, TilesOfTwoLevelsMeetWithNoGap) {
  LodTile plateau{{2, 1, 0}, {}};
  for (LodCell& c : plateau.cells) c = {120, kGround};
  const std::vector<LodTile> tiles = {hillyTile({1, 1, 0}, 60, 40), plateau, hillyTile({2, 2, 0}, 30, 30)};
  std::vector<WorldQuad> quads;
  for (const LodTile& t : tiles)
    for (const WorldQuad& q : worldQuads(meshLodTile(t, greyPalette(), false))) quads.push_back(q);
  int rays = 0, holes = 0;
  for (const glm::dvec3 eye : {glm::dvec3(96, 110, 32), glm::dvec3(70, 140, 50), glm::dvec3(300, 140, 64)})
    for (int i = 0; i < 120; ++i)
      for (int j = 0; j < 60; ++j) {
        const double yaw = i * (2.0 * M_PI / 120.0), pitch = 0.3 - j * (1.5 / 60.0);
        const glm::dvec3 d(std::cos(yaw) * std::cos(pitch), std::sin(pitch), std::sin(yaw) * std::cos(pitch));
        if (!hitsColumns(tiles, eye, d)) continue;
        ++rays;
        holes += nearestHit(quads, eye, d) ? 0 : 1;
      }
  std::printf("%d rays meet the columns, %d of them miss the mesh\n", rays, holes);
  EXPECT_GT(rays, 5000);
  EXPECT_EQ(holes, 0);
}

TEST(LodSelect, LeavesCoverTheDiscOnceAndFullDetailIsLeftOut) {
  LodView view;
  view.camera = {100.0, -37.0};
  view.distance = 2048.0;
  view.covered = ChunkSquare{{2, -6}, {10, 2}};
  view.reach = ChunkSquare{{1, -7}, {11, 3}};
  const std::vector<LodSelected> tiles = selectLodTiles(view, LodLevels{1, 2.0});
  std::set<int> levels;
  for (const LodSelected& t : tiles) {
    levels.insert(t.key.level);
    if (t.touchesFullDetail) {
      EXPECT_LE(t.key.level, kLodChunkLevel) << "cells no wider than a chunk";
    }
  }
  EXPECT_GE(levels.size(), 4u);
  for (int z = -2000; z <= 2000; z += 37)
    for (int x = -2000; x <= 2000; x += 41) {
      const glm::dvec2 p(view.camera.x + x + 0.5, view.camera.y + z + 0.5);
      if (glm::length(p - view.camera) > view.distance) continue;
      const glm::ivec2 chunk(static_cast<int>(std::floor(p.x / 16)), static_cast<int>(std::floor(p.y / 16)));
      int count = 0;
      for (const LodSelected& t : tiles) {
        const double x0 = t.key.minBlockX(), z0 = t.key.minBlockZ(), s = t.key.spanBlocks();
        count += p.x >= x0 && p.x < x0 + s && p.y >= z0 && p.y < z0 + s ? 1 : 0;
      }
      // Full detail's own square: only tiles that reach out of it (sunk there by the renderer).
      if (view.covered->contains(chunk)) {
        ASSERT_LE(count, 1) << "at " << p.x << ", " << p.y;
      } else {
        ASSERT_EQ(count, 1) << "at " << p.x << ", " << p.y;
      }
    }
}

// A source of flat ground whose height can be edited, counting its calls.
struct EditableGround {
  std::mutex mutex;
  std::map<std::pair<int, int>, int> heights;  // edited columns
  std::atomic<int> calls{0};

  LodTile tile(LodTileKey key) {
    ++calls;
    LodTile t{key, {}};
    std::lock_guard lock(mutex);
    for (int z = 0; z < kLodTileCells; ++z)
      for (int x = 0; x < kLodTileCells; ++x) {
        int h = 64;
        for (const auto& [at, y] : heights) {
          const int cx = (at.first - key.minBlockX()) >> key.level,
                    cz = (at.second - key.minBlockZ()) >> key.level;
          if (cx == x && cz == z) h = std::max(h, y);
        }
        t.at(x, z) = {h, kGround};
      }
    return t;
  }
};

TEST(LodTerrain, ASetComesWholeAndAnEditReachesItsTiles) {
  EditableGround ground;
  LodTerrain terrain([&](LodTileKey k) { return ground.tile(k); }, greyPalette(), LodLevels{1, 2.0}, 2);
  LodView view;
  view.camera = {8.0, 8.0};
  view.distance = 600.0;
  view.covered = ChunkSquare{{-2, -2}, {2, 2}};
  view.reach = ChunkSquare{{-3, -3}, {3, 3}};
  terrain.update(view, true);
  const std::optional<LodSet> first = terrain.takeSet();
  ASSERT_TRUE(first);
  EXPECT_EQ(first->meshes.size(), selectLodTiles(view, terrain.levels()).size());
  EXPECT_FALSE(terrain.takeSet()) << "each set once";
  const int calls = ground.calls;
  terrain.update(view, true);
  EXPECT_EQ(ground.calls, calls) << "nothing changed: nothing built";

  // An edit 300 blocks out raises its column; the tile over it is built again, the others kept.
  {
    std::lock_guard lock(ground.mutex);
    ground.heights[{300, 20}] = 120;
  }
  terrain.invalidate(300, 20);
  terrain.update(view, true);
  const std::optional<LodSet> second = terrain.takeSet();
  ASSERT_TRUE(second);
  EXPECT_EQ(ground.calls, calls + 1);
  int raised = 0, kept = 0;
  for (std::size_t i = 0; i < second->meshes.size(); ++i) {
    raised += second->meshes[i]->maxY == 121 ? 1 : 0;
    kept += second->meshes[i] == first->meshes[i] ? 1 : 0;
  }
  EXPECT_EQ(raised, 1);
  EXPECT_EQ(kept, static_cast<int>(first->meshes.size()) - 1);
}

}  // namespace
}  // namespace terrasol
