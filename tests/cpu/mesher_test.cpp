#include "mesh/mesher.h"

#include <gtest/gtest.h>

#include <chrono>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <stdexcept>
#include <string>
#include <thread>

#include "light/light_engine.h"
#include "mesh/mesh_scheduler.h"
#include "support/mesh_world.h"
#include "support/world_support.h"
#include "world/generator.h"

namespace terrasol {
namespace {

using testing::defaultBlocks;

// A lit world of 3 x 3 chunks to build shapes in; textures are numbered block * 6 + face.
struct MeshWorld : testing::MeshWorld {
  explicit MeshWorld(const std::string& generator = "void")
      : testing::MeshWorld(
            BlockMeshTable(defaultBlocks(),
                           [](BlockId id, int face) { return static_cast<std::uint16_t>(id * 6 + face); }),
            generator) {}
};

// Vertices of the face of `mesh` with texture `texture` (the first such quad).
std::vector<PackedVertex> quadWithTexture(const MeshData& mesh, int texture) {
  for (std::size_t i = 0; i < mesh.vertices.size(); i += 4) {
    if (mesh.vertices[i].texture() == texture)
      return {mesh.vertices.begin() + i, mesh.vertices.begin() + i + 4};
  }
  return {};
}

TEST(Mesher, VertexIs16Bytes) {
  EXPECT_EQ(sizeof(PackedVertex), 16u);
}

TEST(Mesher, FaceCountsForKnownShapes) {
  MeshWorld w;
  w.set({3, 70, 3}, "stone");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 6u);
  w.set({4, 70, 3}, "stone");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 10u);
  for (int y = 70; y <= 71; ++y)
    for (int z = 3; z <= 4; ++z)
      for (int x = 3; x <= 4; ++x) w.set({x, y, z}, "stone");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 24u) << "a 2x2x2 cube shows 4 faces per side";
}

TEST(Mesher, CullingRulesForGlassLeavesAndWater) {
  MeshWorld w;
  w.set({3, 70, 3}, "glass");
  w.set({4, 70, 3}, "glass");
  EXPECT_EQ(w.quads(MeshLayer::Cutout), 10u) << "glass hides glass";
  w.set({3, 72, 3}, "oak_leaves");
  w.set({4, 72, 3}, "oak_leaves");
  EXPECT_EQ(w.quads(MeshLayer::Cutout), 22u) << "leaves show their inner faces";
  w.set({8, 70, 8}, "stone");
  w.set({9, 70, 8}, "ice");
  EXPECT_EQ(w.quads(MeshLayer::Opaque), 6u) << "stone shows its face to ice (not opaque)";
  EXPECT_EQ(w.quads(MeshLayer::Translucent), 5u) << "ice hides its face against stone";
}

TEST(Mesher, LeavesShowOnlyTheFacesNearTheCrownsSurface) {
  // A 5^3 crown: along each axis a row of five leaf blocks keeps its outer face and the inner face
  // just behind it at each end; the three faces deeper in are left out. 6 sides x 25 rows x 2.
  MeshWorld w;
  for (int y = 70; y <= 74; ++y)
    for (int z = 4; z <= 8; ++z)
      for (int x = 4; x <= 8; ++x) w.set({x, y, z}, "oak_leaves");
  EXPECT_EQ(w.quads(MeshLayer::Cutout), 300u) << "all 6 x 125 faces would be 750";
  // One more leaf on the -x side with stone beyond it: the stone hides the leaf's outer face, and
  // also the inner face behind that, which nothing could be seen through; with air there both show.
  w.set({3, 72, 6}, "oak_leaves");
  w.set({2, 72, 6}, "stone");
  const std::size_t withStone = w.quads(MeshLayer::Cutout);
  w.set({2, 72, 6}, "air");
  EXPECT_EQ(w.quads(MeshLayer::Cutout), withStone + 2);
}

TEST(Mesher, WaterSurfacesSitLowerUnlessWaterIsAbove) {
  MeshWorld w;
  w.set({3, 70, 3}, "water");
  w.set({4, 70, 3}, "water");
  auto mesh = w.mesh();
  const auto& water = mesh.layers[static_cast<std::size_t>(MeshLayer::Translucent)];
  EXPECT_EQ(water.faces(), 10u) << "water hides water";
  int highest = 0;
  for (const auto& v : water.vertices) highest = std::max(highest, v.y32());
  EXPECT_EQ(highest, (70 & 15) * 32 + 28) << "2/16 below the block top";
  w.set({3, 71, 3}, "water");
  mesh = w.mesh();
  int top = 0;
  for (const auto& v : mesh.layers[static_cast<std::size_t>(MeshLayer::Translucent)].vertices)
    top = std::max(top, v.y32());
  EXPECT_EQ(top, (71 & 15) * 32 + 28);
  const int lowerTop = defaultBlocks().id("water") * 6 + 3;
  int fullHeightLower = 0;
  for (const auto& v : mesh.layers[2].vertices)
    if (v.texture() == lowerTop && v.z32() >= 3 * 32 && v.z32() <= 4 * 32 && v.x32() <= 4 * 32 &&
        v.y32() == (70 & 15) * 32 + 32)
      ++fullHeightLower;
  EXPECT_EQ(fullHeightLower, 0) << "the covered water has no top face";
}

TEST(Mesher, WaterUnderAStoneCeilingIsLitFromItself) {
  MeshWorld w;
  w.set({3, 70, 3}, "water");
  w.set({3, 71, 3}, "stone");
  const auto mesh = w.mesh();
  const auto top = quadWithTexture(mesh.layers[static_cast<std::size_t>(MeshLayer::Translucent)],
                                   defaultBlocks().id("water") * 6 + 3);
  ASSERT_EQ(top.size(), 4u) << "the surface 2/16 below the stone still shows";
  for (const auto& v : top) {
    EXPECT_GT(v.skyLight4(), 0) << "not lit from the opaque block above";
    EXPECT_GT(v.ao(), 0);
  }
}

TEST(Mesher, PlantsTorchesAndTints) {
  MeshWorld w;
  w.set({3, 69, 3}, "grass_block");
  w.set({3, 70, 3}, "short_grass");
  w.set({6, 70, 6}, "torch");
  w.set({8, 70, 8}, "oak_leaves");
  const auto mesh = w.mesh();
  const auto& cutout = mesh.layers[static_cast<std::size_t>(MeshLayer::Cutout)];
  EXPECT_EQ(cutout.quads(), 4u + 5u + 6u) << "cross: 2 double-sided planes; torch: 4 sides and a top";
  for (const auto& v : cutout.vertices) {
    const BlockId id = static_cast<BlockId>(v.texture() / 6);
    const int expected = id == defaultBlocks().id("short_grass")  ? 1
                         : id == defaultBlocks().id("oak_leaves") ? 2
                                                                  : 0;
    EXPECT_EQ(v.tint(), expected) << defaultBlocks()[id].name;
  }
  const auto below = w.mesh({0, sectionOf(69), 0});
  for (const auto& v : below.layers[0].vertices) {
    EXPECT_EQ(v.tint(), v.face() == static_cast<int>(Direction::Up) ? 1 : 0)
        << "grass blocks tint only the top";
  }
}

// The renderer's TBN comes from kFaceBases: every quad's corners must agree with its face's basis
// (counter-clockwise seen from the normal's side, u growing along the tangent, v shrinking along up).
// It found the torch's west and east sides wound inside out.
TEST(Mesher, QuadsAgreeWithTheFaceBases) {
  MeshWorld w;
  w.set({3, 69, 3}, "stone");
  w.set({3, 70, 3}, "short_grass");
  w.set({6, 70, 6}, "torch");
  w.set({9, 70, 9}, "water");
  int checked = 0;
  for (const auto& layer : w.mesh().layers)
    for (std::size_t q = 0; q < layer.vertices.size(); q += 4) {
      const PackedVertex* v = &layer.vertices[q];
      auto pos = [&](int i) { return glm::vec3(v[i].x32(), v[i].y32(), v[i].z32()); };
      const FaceBasis& b = kFaceBases[v[0].face()];
      const glm::vec3 n(b.normal[0], b.normal[1], b.normal[2]), t(b.tangent[0], b.tangent[1], b.tangent[2]),
          up(b.up[0], b.up[1], b.up[2]);
      const bool mirrored = v[0].face() == 7 || v[0].face() == 9;
      EXPECT_NEAR(glm::dot(glm::cross(t, up), n), mirrored ? -1.0f : 1.0f, 1e-5f);
      const glm::vec3 geometric = glm::normalize(glm::cross(pos(1) - pos(0), pos(2) - pos(0)));
      EXPECT_GT(glm::dot(geometric, n), 0.99f) << "face " << v[0].face();
      for (int i = 1; i < 4; ++i) {
        const glm::vec3 d = pos(i) - pos(0);
        const float du = static_cast<float>(v[i].u() - v[0].u()),
                    dv = static_cast<float>(v[i].v() - v[0].v());
        if (du != 0.0f) {
          EXPECT_GT(glm::dot(d, t) * du, 0.0f) << "face " << v[0].face();
        }
        if (dv != 0.0f) {
          EXPECT_LT(glm::dot(d, up) * dv, 0.0f) << "face " << v[0].face();
        }
      }
      ++checked;
    }
  EXPECT_GT(checked, 6 + 8 + 5 + 1);
}

// Up face of a floor block with walls beside the cell in front of it.
std::vector<PackedVertex> floorTop(MeshWorld& w) {
  const auto mesh = w.mesh();
  return quadWithTexture(mesh.layers[0], defaultBlocks().id("stone") * 6 + 3);
}

TEST(Mesher, AmbientOcclusionAtCornersAndTheDiagonalFlip) {
  MeshWorld w;
  w.set({4, 70, 4}, "stone");  // the floor block; its top face looks at (4, 71, 4)
  auto q = floorTop(w);
  ASSERT_EQ(q.size(), 4u);
  for (const auto& v : q) EXPECT_EQ(v.ao(), 3);
  // Up face frame: t = +x, b = -z; corners (-,-) (+,-) (+,+) (-,+).
  w.set({5, 71, 4}, "stone");  // beside corners 1 and 2
  q = floorTop(w);
  EXPECT_EQ(q[0].ao(), 3);
  EXPECT_EQ(q[1].ao(), 2);
  EXPECT_EQ(q[2].ao(), 2);
  EXPECT_EQ(q[3].ao(), 3);
  w.set({5, 71, 4}, "air");
  w.set({3, 71, 4}, "stone");  // side 1 of corner 0
  w.set({4, 71, 5}, "stone");  // side 2 of corner 0: both sides -> 0
  q = floorTop(w);
  // AO was 0, 2, 3, 2: the 0-2 diagonal (0 + 3) is darker than 1-3 (2 + 2), so the quad starts at
  // corner 1 and is split along 1-3.
  EXPECT_EQ(q[0].ao(), 2);
  EXPECT_EQ(q[1].ao(), 3);
  EXPECT_EQ(q[2].ao(), 2);
  EXPECT_EQ(q[3].ao(), 0);
}

TEST(Mesher, SmoothLightAveragesTheFourCellsInFront) {
  MeshWorld w;
  w.set({4, 70, 4}, "stone");
  w.set({4, 71, 4},
        "torch");  // in the cell in front of the floor's top face: 14 there, 13 beside, 12 diagonal
  const auto mesh = w.mesh();
  const auto q = quadWithTexture(mesh.layers[0], defaultBlocks().id("stone") * 6 + 3);
  ASSERT_EQ(q.size(), 4u);
  for (const auto& v : q) {
    EXPECT_EQ(v.blockLight4(), 4 * (14 + 13 + 13 + 12) / 4);
    EXPECT_EQ(v.skyLight4(), 60) << "open sky";
  }
  // An opaque cell beside the corner is left out of the average (and so is the diagonal behind two).
  w.set({5, 71, 4}, "stone");
  const auto q2 = quadWithTexture(w.mesh().layers[0], defaultBlocks().id("stone") * 6 + 3);
  EXPECT_EQ(q2[1].blockLight4(), (4 * (14 + 13 + 12) + 1) / 3);
}

// The extremes of the packed sums: four cells of full light in both channels give exactly 60 (no
// field carries into the next), a lone open cell beside three opaque ones keeps its own level, and a
// corner with both sides opaque ignores the open diagonal.
TEST(Mesher, SmoothLightSumsHoldAtFullLightAndWithOneOpenCell) {
  MeshWorld w;
  SectionSnapshot s;
  s.pos = {0, 4, 0};
  s.blocks.fill(kAir);
  s.opaque.fill(0);
  s.light.fill(SectionSnapshot::lightTerm(false, 15, 15));
  const BlockId stone = defaultBlocks().id("stone");
  auto solid = [&](int x, int y, int z) {
    const auto i = static_cast<std::size_t>(SectionSnapshot::index(x, y, z));
    s.blocks[i] = stone;
    s.opaque[i] = 1;
    s.light[i] = 0;
  };
  solid(8, 8, 8);
  const auto top = quadWithTexture(meshSection(s, w.table).layers[0], stone * 6 + 3);
  ASSERT_EQ(top.size(), 4u);
  for (const auto& v : top) {
    EXPECT_EQ(v.blockLight4(), 60);
    EXPECT_EQ(v.skyLight4(), 60);
    EXPECT_EQ(v.ao(), 3);
  }
  // Walls on two sides of the cell above: the corner between them is fully occluded and lit by the
  // front cell alone, even though the diagonal cell is open and lit.
  s.light[static_cast<std::size_t>(SectionSnapshot::index(8, 9, 8))] =
      SectionSnapshot::lightTerm(false, 3, 0);
  solid(9, 9, 8);
  solid(8, 9, 9);
  const auto walled = quadWithTexture(meshSection(s, w.table).layers[0], stone * 6 + 3);
  ASSERT_EQ(walled.size(), 4u);
  int occluded = 0;
  for (const auto& v : walled) {
    if (v.ao() != 0) continue;
    ++occluded;
    EXPECT_EQ(v.blockLight4(), 12);
    EXPECT_EQ(v.skyLight4(), 0);
  }
  EXPECT_EQ(occluded, 1);
}

TEST(Mesher, FacesAgainstNeighboursAcrossSectionAndChunkBorders) {
  MeshWorld w;
  const SectionPos s{0, sectionOf(64), 0};
  w.set({15, 64, 5}, "stone");  // on the chunk's east edge, the section's bottom layer
  EXPECT_EQ(w.quads(MeshLayer::Opaque, s), 6u);
  w.set({16, 64, 5}, "stone");  // in the next chunk
  EXPECT_EQ(w.quads(MeshLayer::Opaque, s), 5u);
  w.set({15, 63, 5}, "stone");  // in the section below
  EXPECT_EQ(w.quads(MeshLayer::Opaque, s), 4u);
  w.light.chunkUnloading({1, 0});
  w.world.removeChunk({1, 0});
  EXPECT_EQ(w.quads(MeshLayer::Opaque, s), 5u) << "an unloaded neighbour shows the face until it loads";
}

TEST(Mesher, EmptyAndBuriedSectionsAreSkippedBeforeCopying) {
  MeshWorld w("flat");
  SectionSnapshot snapshot;
  EXPECT_EQ(captureSection(w.world, {0, sectionOf(200), 0}, snapshot), CaptureResult::Empty);
  EXPECT_EQ(captureSection(w.world, {0, sectionOf(20), 0}, snapshot), CaptureResult::Buried)
      << "stone from y 1 to 59";
  EXPECT_EQ(captureSection(w.world, {0, sectionOf(60), 0}, snapshot), CaptureResult::Captured);
  w.set({3, 40, 3}, "air");  // a hole in the section above makes the stone below visible
  EXPECT_EQ(captureSection(w.world, {0, sectionOf(20), 0}, snapshot), CaptureResult::Buried);
  w.set({3, 32, 3}, "air");  // the bottom layer of the section above: now the top of y 16..31 is exposed
  EXPECT_EQ(captureSection(w.world, {0, sectionOf(20), 0}, snapshot), CaptureResult::Captured);
  EXPECT_EQ(captureSection(w.world, {7, 0, 7}, snapshot), CaptureResult::Empty) << "no chunk there";
}

TEST(Mesher, EditsAndRevertsGiveTheSameMeshAsFresh) {
  MeshWorld w("terrain");
  const int surface = w.gen->surfaceHeight(8, 8);
  const SectionPos s{0, sectionOf(surface), 0};
  const auto fresh = w.mesh(s);
  ASSERT_GT(fresh.quads(), 50u);
  std::vector<std::pair<BlockPos, BlockId>> undo;
  const char* placed[] = {"torch", "stone", "air", "glowstone", "water", "glass"};
  for (int i = 0; i < 30; ++i) {
    const BlockPos p{(i * 7) % 16, surface - 3 + i % 7, (i * 5) % 16};
    undo.emplace_back(p, w.world.getBlock(p));
    w.set(p, placed[i % 6]);
  }
  EXPECT_NE(w.mesh(s).quads(), fresh.quads());
  for (auto it = undo.rbegin(); it != undo.rend(); ++it) {
    if (auto change = w.world.setBlock(it->first, it->second)) w.light.blockChanged(*change);
  }
  const auto again = w.mesh(s);
  for (int l = 0; l < kMeshLayers; ++l) {
    const auto& a = fresh.layers[static_cast<std::size_t>(l)].vertices;
    const auto& b = again.layers[static_cast<std::size_t>(l)].vertices;
    ASSERT_EQ(a.size(), b.size()) << "layer " << l;
    EXPECT_TRUE(a == b) << "layer " << l;
  }
}

// Edits go through light, then only the touched sections are remeshed on workers, and what comes
// back equals meshing those sections directly.
TEST(MeshScheduler, RemeshesExactlyTheSectionsAnEditTouches) {
  MeshWorld w("flat");
  MeshScheduler scheduler(w.table, 2);
  w.light.takeChangedSections();
  const BlockPos edits[] = {{15, 64, 0}, {4, 64, 4}};  // a chunk corner on a section bottom; a plain spot
  for (const auto& p : edits) {
    w.set(p, "glowstone");
    scheduler.markBlockChanged(p);
  }
  for (const auto& s : w.light.takeChangedSections()) scheduler.markDirty(s);
  EXPECT_GT(scheduler.dirty(), 4u);
  std::vector<SectionMesh> results;
  for (int i = 0; i < 10000 && (scheduler.dirty() > 0 || scheduler.inFlight() > 0); ++i) {
    for (auto& m : scheduler.update(w.world)) results.push_back(std::move(m));
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ASSERT_FALSE(results.empty());
  bool sawEdited = false;
  for (const auto& m : results) {
    EXPECT_LE(std::abs(m.pos.x), 1);
    EXPECT_LE(std::abs(m.pos.section - sectionOf(64)), 1)
        << "light 15 reaches one section up or down at most";
    const auto direct = w.mesh(m.pos);
    for (int l = 0; l < kMeshLayers; ++l) {
      ASSERT_EQ(m.layers[static_cast<std::size_t>(l)].vertices.size(),
                direct.layers[static_cast<std::size_t>(l)].vertices.size());
    }
    sawEdited = sawEdited || (m.pos == SectionPos{0, sectionOf(64), 0} && m.quads() > 0);
  }
  EXPECT_TRUE(sawEdited);
  for (const auto& m : results)
    EXPECT_NE(m.pos, (SectionPos{0, sectionOf(200), 0})) << "untouched sections stay";
}

// A mesher that throws: the section is named on the main thread, and no mesh replaces its old one.
TEST(MeshScheduler, AFailedSectionIsNamedAndKeepsItsOldMesh) {
  MeshWorld w("flat");
  const SectionPos broken{0, sectionOf(64), 0};
  MeshScheduler scheduler(w.table, 1, [&](const SectionSnapshot& snapshot, const BlockMeshTable& table) {
    if (snapshot.pos == broken) throw std::runtime_error("a mesher bug");
    return meshWithLinks(snapshot, table);
  });
  w.set({4, 64, 4}, "glowstone");  // something to draw in both sections
  w.set({20, 64, 4}, "glowstone");
  scheduler.markDirty(broken);
  scheduler.markDirty({1, sectionOf(64), 0});
  std::vector<SectionMesh> results;
  std::vector<MeshFailure> failures;
  for (int i = 0; i < 10000 && (scheduler.dirty() > 0 || scheduler.inFlight() > 0); ++i) {
    for (auto& m : scheduler.update(w.world)) results.push_back(std::move(m));
    for (auto& f : scheduler.takeFailures()) failures.push_back(std::move(f));
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].pos, (SectionPos{1, sectionOf(64), 0}));
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures[0].pos, broken);
  EXPECT_EQ(failures[0].message(),
            "meshing section (0, " + std::to_string(sectionOf(64)) + ", 0) failed: a mesher bug");
}

// A quad's footprint: its face, its height along the normal and its extent on the three axes (1/32).
struct Footprint {
  int face, lo[3], hi[3];
};
Footprint footprintOf(const PackedVertex* q) {
  Footprint f{q[0].face(), {512, 512, 512}, {0, 0, 0}};
  for (int c = 0; c < 4; ++c) {
    const int at[3] = {q[c].x32(), q[c].y32(), q[c].z32()};
    for (int a = 0; a < 3; ++a) {
      f.lo[a] = std::min(f.lo[a], at[a]);
      f.hi[a] = std::max(f.hi[a], at[a]);
    }
  }
  return f;
}
bool inside(const Footprint& small, const Footprint& big) {
  if (small.face != big.face) return false;
  for (int a = 0; a < 3; ++a)
    if (small.lo[a] < big.lo[a] || small.hi[a] > big.hi[a]) return false;
  return true;
}

// Every merged quad stands for exactly the faces stored for the light's view in its rectangle, all of
// its material and light, and its UV runs as theirs do, one texture per block from its corner.
void expectMergedQuadsMatchTheirFaces(const MeshData& layer, std::size_t& merged, std::size_t& facesMerged) {
  std::vector<const PackedVertex*> faces, quads;
  for (std::size_t q = 0; q < layer.quads(); ++q) {
    const PackedVertex* v = &layer.vertices[q * 4];
    if (v->role() == QuadRole::Faces) faces.push_back(v);
    if (v->role() == QuadRole::Merged) quads.push_back(v);
  }
  std::vector<int> coveredBy(faces.size(), 0);
  for (const PackedVertex* m : quads) {
    const Footprint big = footprintOf(m);
    const FaceBasis& basis = kFaceBases[m[0].face()];
    int area = 1;
    for (int a = 0; a < 3; ++a) area *= big.hi[a] > big.lo[a] ? (big.hi[a] - big.lo[a]) / 32 : 1;
    int inRectangle = 0;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!inside(footprintOf(faces[f]), big)) continue;
      ++inRectangle;
      ++coveredBy[f];
      EXPECT_EQ(faces[f][0].light, m[0].light);
      EXPECT_EQ(faces[f][0].texture(), m[0].texture());
      EXPECT_EQ(faces[f][0].tint(), m[0].tint());
    }
    EXPECT_GT(area, 1);
    EXPECT_EQ(inRectangle, area) << "a merged quad replaces the faces of its whole rectangle";
    for (int c = 0; c < 4; ++c) {
      EXPECT_EQ(m[c].light, m[0].light);
      // From corner 3 (u = 0, v = 0: the texture's top left), u grows along the tangent and v against up.
      const glm::vec3 d(m[c].x32() - m[3].x32(), m[c].y32() - m[3].y32(), m[c].z32() - m[3].z32());
      EXPECT_EQ(m[3].u(), 0);
      EXPECT_EQ(m[3].v(), 0);
      EXPECT_EQ(static_cast<float>(m[c].u()) * 2.0f,
                glm::dot(d, glm::vec3(basis.tangent[0], basis.tangent[1], basis.tangent[2])));
      EXPECT_EQ(static_cast<float>(m[c].v()) * 2.0f,
                -glm::dot(d, glm::vec3(basis.up[0], basis.up[1], basis.up[2])));
    }
  }
  for (std::size_t f = 0; f < faces.size(); ++f) EXPECT_EQ(coveredBy[f], 1) << "each merged face in one quad";
  merged += quads.size();
  facesMerged += faces.size();
}

TEST(Mesher, MergedQuadsStandForExactlyTheFacesTheyJoin) {
  MeshWorld w("terrain");
  const int surface = w.gen->surfaceHeight(8, 8);
  w.set({8, surface + 1, 8}, "torch");  // light that varies across the ground: those faces stay apart
  w.set({3, surface + 1, 3}, "water");
  const auto mesh = w.mesh({0, sectionOf(surface), 0});
  std::size_t merged = 0, facesMerged = 0;
  for (const auto& layer : mesh.layers) expectMergedQuadsMatchTheirFaces(layer, merged, facesMerged);
  EXPECT_GT(merged, 5u);
  EXPECT_GT(facesMerged, 2 * merged);
  const auto& opaque = mesh.layers[static_cast<std::size_t>(MeshLayer::Opaque)];
  EXPECT_LT(opaque.quads() - facesMerged, opaque.faces()) << "the camera's view draws fewer quads";
}

TEST(Mesher, AnOpenFloorIsOneQuadSeenFromAbove) {
  MeshWorld w;
  for (int z = 0; z < 16; ++z)
    for (int x = 0; x < 16; ++x) w.set({x, 64, z}, "stone");
  const auto mesh = w.mesh();
  const auto& opaque = mesh.layers[static_cast<std::size_t>(MeshLayer::Opaque)];
  std::vector<const PackedVertex*> tops;
  for (std::size_t q = 0; q < opaque.quads(); ++q) {
    const PackedVertex* v = &opaque.vertices[q * 4];
    if (v->face() == static_cast<int>(Direction::Up) && v->role() != QuadRole::Faces) tops.push_back(v);
  }
  ASSERT_EQ(tops.size(), 1u) << "256 tops under one light merge whole";
  EXPECT_EQ(tops[0]->role(), QuadRole::Merged);
  const Footprint f = footprintOf(tops[0]);
  EXPECT_EQ(f.hi[0] - f.lo[0], 512);
  EXPECT_EQ(f.hi[2] - f.lo[2], 512);
  std::size_t merged = 0, facesMerged = 0;
  expectMergedQuadsMatchTheirFaces(opaque, merged, facesMerged);
  EXPECT_GE(facesMerged, 256u);
}

// A cell holding water besides its block draws the water too: seagrass (always in water) alone in
// the air shows six faces of water, its top lowered; water beside it hides the faces between them, as
// water beside water does; a waterlogged pane joins them, a dry one does not.
TEST(Mesher, WaterloggedCellsDrawTheirWater) {
  MeshWorld w;
  w.set({3, 70, 3}, "seagrass");
  EXPECT_EQ(w.quads(MeshLayer::Translucent), 6u) << "seagrass's water";
  w.set({4, 70, 3}, "water");
  EXPECT_EQ(w.quads(MeshLayer::Translucent), 5u + 5u) << "the faces between them hidden";
  w.set({5, 70, 3}, "glass_pane[waterlogged=true]");
  EXPECT_EQ(w.quads(MeshLayer::Translucent), 5u + 4u + 5u);
  w.set({5, 70, 3}, "glass_pane[waterlogged=false]");
  EXPECT_EQ(w.quads(MeshLayer::Translucent), 5u + 5u);
}

}  // namespace
}  // namespace terrasol
