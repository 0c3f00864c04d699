// Far terrain's meshes, tile choice and tile store (lod/): terraces and heightfields facing out, tiles of
// two levels and both shapes meeting with no gap (rays that reach the floor inside them meet a
// triangle), a disc covered once, edits reaching tiles.

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

#include "core/octahedral.h"
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

glm::dvec3 worldPosition(const LodMesh& mesh, const LodVertex& v) {
  const double cell = mesh.key.cellBlocks();
  return {mesh.key.minBlockX() + v.x * cell / kLodXZSteps, static_cast<double>(v.y) / kLodYSteps,
          mesh.key.minBlockZ() + v.z * cell / kLodXZSteps};
}

// A quad of a terrace mesh in world blocks: its corners and the face it shows.
struct WorldQuad {
  glm::dvec3 corner[4];
  glm::dvec3 normal;
};

std::vector<WorldQuad> worldQuads(const LodMesh& mesh) {
  std::vector<WorldQuad> quads;
  for (std::size_t q = 0; q + 3 < mesh.vertices.size(); q += 4) {
    WorldQuad w{};
    for (int i = 0; i < 4; ++i)
      w.corner[i] = worldPosition(mesh, mesh.vertices[q + static_cast<std::size_t>(i)]);
    const int face = static_cast<int>(mesh.vertices[q].material >> kLodFaceShift) & 7;
    const BlockPos o = kDirectionOffsets[face];
    w.normal = {o.x, o.y, o.z};
    quads.push_back(w);
  }
  return quads;
}

// Any mesh's triangles in world blocks, in drawing order (a terrace quad is two).
struct Triangle {
  glm::dvec3 p[3];
};

std::vector<Triangle> worldTriangles(const LodMesh& mesh) {
  std::vector<Triangle> out;
  const auto add = [&](std::size_t a, std::size_t b, std::size_t c) {
    out.push_back({{worldPosition(mesh, mesh.vertices[a]), worldPosition(mesh, mesh.vertices[b]),
                    worldPosition(mesh, mesh.vertices[c])}});
  };
  if (mesh.indices.empty()) {
    for (std::size_t q = 0; q + 3 < mesh.vertices.size(); q += 4) add(q, q + 1, q + 2), add(q, q + 2, q + 3);
  } else {
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
      add(mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]);
  }
  return out;
}

TEST(LodMesh, TerracesTurnTheirFrontOutwardsAndStepsGetWalls) {
  LodTile tile{{2, 0, 0}, {}};
  for (LodCell& c : tile.cells) c = {70, kGround};
  tile.at(5, 5).top = 80;  // a pillar of one cell
  const LodMesh mesh = meshLodTerraces(tile, greyPalette(), false);
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
  EXPECT_EQ(mesh.maxY, 81);
  EXPECT_EQ(mesh.minY, kMinY) << "the box the renderer culls by reaches the skirts' foot";
  // The flat cells merge: 1023 flat cells are far fewer quads than cells.
  EXPECT_LT(mesh.vertices.size() / 4, 200u);
  EXPECT_TRUE(mesh.indices.empty());
  // Meeting full detail: a top per cell and every wall, so each cell can sink on its own.
  const LodMesh walled = meshLodTerraces(tile, greyPalette(), true);
  EXPECT_EQ(walled.vertices.size() / 4, static_cast<std::size_t>(kLodTileCells * kLodTileCells * 5));
}

TEST(LodMesh, AHeightfieldFacesUpAndOutAndLeansAwayFromHigherCells) {
  const LodTile tile = hillyTile({2, 0, 0}, 60, 30);
  const LodMesh mesh = meshLodHeightfield(tile, greyPalette());
  const glm::dvec3 middle(64.0, 0.0, 64.0);
  int up = 0, out = 0;
  for (const Triangle& t : worldTriangles(mesh)) {
    const glm::dvec3 n = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
    ASSERT_GT(glm::length(n), 1e-9) << "no degenerate triangle";
    if (n.y > 0.0) {
      ++up;
      continue;
    }
    // A skirt: vertical, turned away from the tile's middle.
    EXPECT_NEAR(n.y, 0.0, 1e-9);
    EXPECT_GT(glm::dot(n, (t.p[0] + t.p[1] + t.p[2]) / 3.0 - middle), 0.0) << "a skirt turned inwards";
    ++out;
  }
  EXPECT_EQ(up, 2 * (kLodTileCells + 1) * (kLodTileCells + 1));
  EXPECT_EQ(out, 4 * 2 * (kLodTileCells + 1));
  // Each cell's middle at its height; the normal leans away from the higher neighbour.
  const LodVertex& v = mesh.vertices[static_cast<std::size_t>(6 * (kLodTileCells + 2) + 4)];  // cell (3, 5)
  EXPECT_EQ(v.x, 3 * kLodXZSteps + kLodXZSteps / 2);
  EXPECT_EQ(v.y, lodSurfaceY(tile.at(3, 5)));
  EXPECT_EQ((v.material >> kLodFaceShift) & 7u, kLodFaceSmooth);
  // The normal is the slope's, from the neighbours' heights (1/8 block; cells of 4 blocks), as the
  // shader decodes it.
  const auto rise = [&](int x0, int z0, int x1, int z1) {
    return (lodSurfaceY(tile.at(x1, z1)) - lodSurfaceY(tile.at(x0, z0))) / (8.0 * kLodYSteps);
  };
  const glm::dvec3 slope = glm::normalize(glm::dvec3(-rise(2, 5, 4, 5), 1.0, -rise(3, 4, 3, 6)));
  const glm::dvec3 decoded = octDecode(glm::dvec2(v.cellX, v.cellZ) / 127.5 - 1.0);
  EXPECT_GT(glm::dot(decoded, slope), 0.999);
  EXPECT_GT(std::abs(slope.x) + std::abs(slope.z), 0.1) << "a cell on a slope, so the check means something";
  EXPECT_EQ(mesh.minY, kMinY) << "the box the renderer culls by reaches the skirts' foot";
}

TEST(LodMesh, WaterLiesAtSevenEighthsOfItsBlockAndIsMarked) {
  LodTile tile{{1, 0, 0}, {}};
  for (LodCell& c : tile.cells) c = {50, kGround, 62, kWater};
  for (const LodMesh& mesh :
       {meshLodTerraces(tile, greyPalette(), false), meshLodHeightfield(tile, greyPalette())}) {
    const auto top = std::find_if(mesh.vertices.begin(), mesh.vertices.end(), [](const LodVertex& v) {
      const std::uint32_t face = (v.material >> kLodFaceShift) & 7u;
      return face == kLodFaceSmooth || face == static_cast<std::uint32_t>(Direction::Up);
    });
    ASSERT_NE(top, mesh.vertices.end());
    EXPECT_EQ(top->y, (62 + 1) * kLodYSteps - 1);
    EXPECT_EQ((top->material >> kLodWaterShift) & 1u, 1u);
    if (mesh.indices.empty()) {
      EXPECT_EQ(mesh.vertices.size() / 4, 1u + 4u * kLodTileCells)
          << "one top, and the skirts round the tile";
    }
  }
}

TEST(LodMesh, CoarseCellsMakeAHeightfieldUnlessFullDetailMeetsThemOrACellIsEmpty) {
  EXPECT_TRUE(
      meshLodTile(hillyTile({kLodSmoothLevel - 1, 0, 0}, 60, 8), greyPalette(), false).indices.empty());
  LodTile tile = hillyTile({kLodSmoothLevel, 0, 0}, 60, 8);
  EXPECT_FALSE(meshLodTile(tile, greyPalette(), false).indices.empty());
  EXPECT_TRUE(meshLodTile(tile, greyPalette(), true).indices.empty()) << "full detail meets it";
  tile.at(7, 7) = LodCell{};
  EXPECT_TRUE(meshLodTile(tile, greyPalette(), false).indices.empty()) << "a hole";
}

// The nearest triangle a ray meets from the front, or none (Moller-Trumbore, back faces culled as the
// renderer culls them).
std::optional<double> nearestHit(const std::vector<Triangle>& triangles, glm::dvec3 o, glm::dvec3 d) {
  std::optional<double> best;
  for (const Triangle& t : triangles) {
    const glm::dvec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0];
    if (glm::dot(glm::cross(e1, e2), d) >= 0.0) continue;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12) continue;
    const glm::dvec3 s = o - t.p[0];
    const double u = glm::dot(s, p) / det;
    if (u < -1e-9 || u > 1.0 + 1e-9) continue;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    if (v < -1e-9 || u + v > 1.0 + 1e-9) continue;
    const double dist = glm::dot(e2, q) / det;
    if (dist > 0.0 && (!best || dist < *best)) best = dist;
  }
  return best;
}

// Three tiles side by side: fine hills (cells of 2), a coarse plateau above them (cells of 4) and
// beyond it a coarse valley; the plateau a heightfield and the valley terraces (as if full detail were
// near), then the other way round. Their meshes close over the ground they cover: every ray that
// reaches down to the floor inside them meets a triangle first. Without the skirts at the tiles'
// edges the plateau's cliffs are open where they meet the hills and the valley.
TEST(LodMesh, TilesOfTwoLevelsAndBothShapesMeetWithNoGap) {
  LodTile plateau{{2, 1, 0}, {}};
  for (LodCell& c : plateau.cells) c = {120, kGround};
  const LodTile hills = hillyTile({1, 1, 0}, 60, 40), valley = hillyTile({2, 2, 0}, 30, 30);
  const double x0 = hills.key.minBlockX(), x1 = valley.key.minBlockX() + valley.key.spanBlocks();
  const double z0 = 0.0, z1 = hills.key.spanBlocks();  // the hills are narrower: the footprint they share
  const double floorY = kMinY + 0.5;
  for (const bool plateauTerraces : {false, true}) {
    const auto shape = [&](const LodTile& t, bool terraces) {
      return terraces ? meshLodTerraces(t, greyPalette(), false) : meshLodHeightfield(t, greyPalette());
    };
    std::vector<Triangle> triangles;
    for (const LodMesh& mesh :
         {shape(hills, false), shape(plateau, plateauTerraces), shape(valley, !plateauTerraces)})
      for (const Triangle& t : worldTriangles(mesh)) triangles.push_back(t);
    int rays = 0, holes = 0;
    for (const glm::dvec3 eye : {glm::dvec3(96, 110, 32), glm::dvec3(70, 140, 50), glm::dvec3(300, 100, 60)})
      for (int i = 0; i < 120; ++i)
        for (int j = 0; j < 60; ++j) {
          const double yaw = i * (2.0 * M_PI / 120.0), pitch = -0.02 - j * (1.5 / 60.0);
          const glm::dvec3 d(std::cos(yaw) * std::cos(pitch), std::sin(pitch),
                             std::sin(yaw) * std::cos(pitch));
          const glm::dvec3 atFloor = eye + d * ((floorY - eye.y) / d.y);
          if (atFloor.x <= x0 || atFloor.x >= x1 || atFloor.z <= z0 || atFloor.z >= z1) continue;
          ++rays;
          holes += nearestHit(triangles, eye, d) ? 0 : 1;
        }
    std::printf("plateau as %s: %d rays reach the floor inside the tiles, %d of them miss the meshes\n",
                plateauTerraces ? "terraces" : "a heightfield", rays, holes);
    EXPECT_GT(rays, 2000);
    EXPECT_EQ(holes, 0);
  }
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
