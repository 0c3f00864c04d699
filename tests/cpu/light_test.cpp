#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <set>
#include <thread>
#include <tuple>

#include "light/changed_sections.h"
#include "light/level_words.h"
#include "light/light_engine.h"
#include "light/light_frame.h"
#include "support/lit_world.h"
#include "support/reference_light.h"
#include "support/world_support.h"
#include "world/chunk_streamer.h"
#include "world/generator.h"

namespace terrasol {
namespace {

using testing::compareWithReference;
using testing::defaultBlocks;
using testing::LitWorld;

int manhattan(const BlockPos& a, const BlockPos& b) {
  return std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z);
}

// Checks the exact diamond of a source of `level` at `at` in open air.
void expectDiamond(const LitWorld& w, const BlockPos& at, int level) {
  for (int dy = -16; dy <= 16; ++dy)
    for (int dz = -16; dz <= 16; ++dz)
      for (int dx = -16; dx <= 16; ++dx) {
        const BlockPos p = at.offset(dx, dy, dz);
        if (!inWorldHeight(p.y)) continue;
        ASSERT_EQ(w.block(p), std::max(0, level - manhattan(p, at))) << p.x << "," << p.y << "," << p.z;
      }
}

TEST(Light, TorchInOpenAirMakesADiamondFrom14To1) {
  LitWorld w("void");
  w.loadArea(-1, -1, 1, 1);
  const BlockPos torch{8, 64, 8};
  w.set(torch, "torch");
  expectDiamond(w, torch, 14);
  EXPECT_EQ(w.sky(torch.offset(3, -100, 2)), 15);  // a void world is open sky everywhere
  EXPECT_EQ(compareWithReference(w.world), "");
  w.set(torch, "air");
  expectDiamond(w, torch, 0);
}

// Clearing light reads a cell's block (for its own emission) only in sections that hold an emitter.
TEST(Light, RemovingLightReadsBlocksOnlyInSectionsWithAnEmitter) {
  LitWorld w("void");
  w.loadArea(-1, -1, 1, 1);
  const BlockPos torch{8, 72, 8};
  w.set(torch, "torch");
  w.light.resetStats();
  w.set(torch, "air");
  expectDiamond(w, torch, 0);
  EXPECT_GT(w.light.stats().lightWrites, 1000u);
  EXPECT_EQ(w.light.stats().blockReads, 0u);

  // With a second torch in the section, every cleared cell there must check whether it emits.
  const BlockPos other{2, 72, 2};
  w.set(other, "torch");
  w.set(torch, "torch");
  w.light.resetStats();
  w.set(torch, "air");
  EXPECT_GT(w.light.stats().blockReads, 100u);
  EXPECT_EQ(w.block(other), 14);
  EXPECT_EQ(compareWithReference(w.world), "");
}

// The counters behind the benchmarks' block_reads_per_set: a torch on a grass plain writes each cell
// it lights once and reads each of their blocks once (the torch's own for its emission), plus the
// ground under every cell bright enough to pass light down.
TEST(Light, CountsEveryLevelWrittenAndEveryBlockRead) {
  LitWorld w("flat");
  w.loadArea(-1, -1, 1, 1);
  const BlockPos torch{8, 64, 8};
  ASSERT_TRUE(defaultBlocks()[w.world.getBlock(torch.offset(0, -1, 0))].isOpaqueCube());
  ASSERT_EQ(w.world.getBlock(torch), kAir);
  w.light.resetStats();
  w.set(torch, "torch");
  std::uint64_t lit = 0, ground = 0;
  for (int dz = -14; dz <= 14; ++dz)
    for (int dx = -14; dx <= 14; ++dx) {
      ground += w.block(torch.offset(dx, 0, dz)) >= 2;
      for (int dy = 0; dy <= 14; ++dy) lit += w.block(torch.offset(dx, dy, dz)) > 0;
    }
  EXPECT_EQ(lit, 1834u);
  EXPECT_EQ(w.light.stats().lightWrites, lit);
  EXPECT_EQ(w.light.stats().blockReads, lit + ground);

  w.light.resetStats();
  w.set(torch, "air");
  EXPECT_EQ(w.light.stats().lightWrites, lit);
  EXPECT_EQ(w.light.stats().blockReads, 0u);
}

TEST(Light, EveryKindOfBorderIsCrossed) {
  LitWorld w("void");
  w.loadArea(-2, -2, 1, 1);
  // On a chunk corner and a section corner at once: the diamond spans 4 chunks and 2 section layers.
  for (const BlockPos at :
       {BlockPos{-1, -1, -1}, BlockPos{0, 15, 0}, BlockPos{15, 16, -16}, BlockPos{-16, 319, 15}}) {
    w.set(at, "glowstone");
    expectDiamond(w, at, 15);
    EXPECT_EQ(compareWithReference(w.world), "");
    w.set(at, "air");
    expectDiamond(w, at, 0);
  }
}

TEST(Light, GlowstoneInAClosedRoomStaysInside) {
  LitWorld w("flat");
  w.loadArea(-1, -1, 1, 1);
  w.fill({-4, 70, -4}, {4, 76, 4}, "stone");
  w.fill({-3, 71, -3}, {3, 75, 3}, "air");
  const BlockPos glow{0, 73, 0};
  w.set(glow, "glowstone");
  EXPECT_EQ(w.block(glow), 15);
  EXPECT_EQ(w.block({1, 73, 0}), 14);
  EXPECT_EQ(w.block({3, 75, 3}), 15 - 3 - 2 - 3);
  EXPECT_EQ(w.block({-4, 73, 0}), 0) << "walls are opaque";
  EXPECT_EQ(w.block({-5, 73, 0}), 0) << "no light gets out";
  EXPECT_EQ(w.sky({0, 72, 0}), 0) << "a closed room has no sky light";
  EXPECT_EQ(w.sky({0, 77, 0}), 15);
  EXPECT_EQ(compareWithReference(w.world), "");
}

TEST(Light, A100BlockShaftFillsWithSkyAndEmptiesWhenCapped) {
  LitWorld w("flat", "bedrock,199*stone");  // solid to y = 199
  w.loadArea(-1, -1, 1, 1);
  for (int y = 199; y >= 100; --y) w.set({5, y, 5}, "air");
  for (int y = 100; y < 200; ++y) ASSERT_EQ(w.sky({5, y, 5}), 15) << y;
  EXPECT_EQ(w.sky({5, 99, 5}), 0);
  EXPECT_EQ(w.sky({6, 150, 5}), 0);
  EXPECT_EQ(compareWithReference(w.world), "");
  w.set({5, 200, 5}, "stone");  // capping it removes 100 sources at once
  for (int y = 100; y < 200; ++y) ASSERT_EQ(w.sky({5, y, 5}), 0) << y;
  EXPECT_EQ(compareWithReference(w.world), "");
  w.set({5, 200, 5}, "air");
  EXPECT_EQ(w.sky({5, 100, 5}), 15);
  w.set({5, 230, 5}, "glass");  // opacity 0: still open sky
  EXPECT_EQ(w.sky({5, 100, 5}), 15);
  EXPECT_EQ(compareWithReference(w.world), "");
}

TEST(Light, WaterAndLeavesAttenuateSkyLight) {
  LitWorld w("flat");
  w.loadArea(-1, -1, 1, 1);
  // A pool 10 deep and 21 wide: straight down it loses 1 per block.
  w.fill({-10, 54, -10}, {10, 63, 10}, "water");
  for (int depth = 0; depth < 10; ++depth) EXPECT_EQ(w.sky({0, 63 - depth, 0}), 14 - depth) << depth;
  // A canopy of leaves: the leaves get 14, the air right under them 13.
  w.fill({-10, 80, -10}, {10, 80, 10}, "oak_leaves");
  EXPECT_EQ(w.sky({0, 80, 0}), 14);
  EXPECT_EQ(w.sky({0, 79, 0}), 13);
  EXPECT_EQ(w.sky({0, 81, 0}), 15);
  // Torch light through water: opacity 1 costs the same as air.
  w.set({0, 58, 0}, "torch");
  EXPECT_EQ(w.block({0, 58, 3}), 11);
  EXPECT_EQ(compareWithReference(w.world), "");
}

TEST(Light, RemovingOneOfTwoFullSourcesInACaveLeavesTheOther) {
  LitWorld w("flat", "bedrock,199*stone");
  w.loadArea(-1, -1, 1, 1);
  w.fill({-12, 100, -12}, {12, 116, 12}, "air");  // a closed cave 25 x 17 x 25
  const BlockPos a{-3, 108, 0}, b{4, 108, 0};
  w.set(a, "glowstone");
  w.set(b, "glowstone");
  EXPECT_EQ(w.block({0, 108, 0}), 12);
  w.set(a, "air");
  for (int x = -12; x <= 12; ++x) EXPECT_EQ(w.block({x, 108, 0}), std::max(0, 15 - std::abs(x - b.x))) << x;
  EXPECT_EQ(compareWithReference(w.world), "");
}

TEST(Light, TopAndBottomOfTheWorld) {
  LitWorld w("void");
  w.loadArea(0, 0, 0, 0);
  w.set({3, 319, 3}, "oak_leaves");
  EXPECT_EQ(w.sky({3, 319, 3}), 14);  // lit from the sky above the world, through its own opacity
  EXPECT_EQ(w.sky({3, 318, 3}), 14);  // from the open-sky columns beside it, not 13 from above
  w.set({4, 319, 3}, "stone");
  EXPECT_EQ(w.sky({4, 319, 3}), 0);
  w.set({8, -64, 8}, "torch");
  EXPECT_EQ(w.block({8, -64, 8}), 14);
  EXPECT_EQ(w.block({8, -63, 8}), 13);
  EXPECT_EQ(w.light.lightAt({8, -65, 8}, LightChannel::Block), 0);
  EXPECT_EQ(w.light.lightAt({8, 320, 8}, LightChannel::Sky), 15);
  EXPECT_EQ(compareWithReference(w.world), "");
  w.set({3, 319, 3}, "air");
  w.set({4, 319, 3}, "air");
  EXPECT_EQ(w.sky({3, 318, 3}), 15);
  EXPECT_EQ(compareWithReference(w.world), "");
}

TEST(Light, UnloadedChunksActOpaqueAndLoadOrderDoesNotMatter) {
  LitWorld w("flat");
  w.load({0, 0});
  w.set({15, 70, 8}, "glowstone");
  EXPECT_EQ(w.block({16, 70, 8}), 0);  // not loaded: nothing there
  w.load({1, 0});
  EXPECT_EQ(w.block({16, 70, 8}), 14) << "light flows into a chunk when it loads";
  EXPECT_EQ(compareWithReference(w.world), "");
  w.light.chunkUnloading({0, 0});
  w.world.removeChunk({0, 0});
  EXPECT_EQ(w.block({16, 70, 8}), 0) << "and back out when its source unloads";
  EXPECT_EQ(compareWithReference(w.world), "");
}

TEST(Light, ReportsChangedSectionsIncludingNeighboursWhoseHaloChanged) {
  LitWorld w("void");
  w.loadArea(-1, -1, 1, 1);
  w.light.takeChangedSections();
  w.set({0, 0, 0}, "torch");  // a section corner: light reaches 8 sections around it
  const auto changed = w.light.takeChangedSections();
  auto has = [&](SectionPos s) { return std::find(changed.begin(), changed.end(), s) != changed.end(); };
  EXPECT_TRUE(has({0, sectionOf(0), 0}));
  EXPECT_TRUE(has({-1, sectionOf(-1), -1}));
  EXPECT_FALSE(has({0, sectionOf(40), 0})) << "light 14 cannot reach y = 32";
  EXPECT_TRUE(w.light.takeChangedSections().empty());
  w.set({8, 100, 8}, "cobblestone");
  w.light.takeChangedSections();
  w.set({8, 100, 8}, "stone");  // same light properties: nothing to redo
  EXPECT_TRUE(w.light.takeChangedSections().empty());
  // This torch's light ends at level 1 on three faces of its section: the sections beyond them get
  // no light, but their halos changed.
  w.set({2, 66, 2}, "torch");
  const auto halos = w.light.takeChangedSections();
  const int section = sectionOf(66);
  for (const SectionPos s :
       {SectionPos{1, section, 0}, SectionPos{0, section + 1, 0}, SectionPos{0, section, 1}}) {
    EXPECT_TRUE(std::find(halos.begin(), halos.end(), s) != halos.end())
        << "section " << s.x << " " << s.section << " " << s.z << " not reported";
  }
  EXPECT_EQ(w.block({16, 66, 2}), 0);
  EXPECT_EQ(w.block({15, 66, 2}), 1);
}

TEST(Light, RelightingASectionRepairsItAndChangesNothingCorrect) {
  LitWorld w("terrain");
  w.loadArea(-1, -1, 1, 1);
  w.set({3, 100, 3}, "glowstone");
  const int surface = w.gen->surfaceHeight(8, 8);
  const SectionPos section{0, sectionOf(surface), 0};
  w.light.relightSection(section);
  EXPECT_EQ(compareWithReference(w.world), "") << "relighting correct light must not change it";
  // Scramble the section's light, then relight it.
  ChunkLight& light = w.world.chunk({0, 0})->light();
  for (int i = 0; i < Section::kVolume; i += 7) {
    light.block[static_cast<std::size_t>(section.section)].set(i, static_cast<std::uint8_t>(i % 16));
    light.sky[static_cast<std::size_t>(section.section)].set(i, static_cast<std::uint8_t>((i / 7) % 16));
  }
  EXPECT_NE(compareWithReference(w.world), "");
  w.light.relightSection(section);
  EXPECT_EQ(compareWithReference(w.world), "");
}

// relightSection solves the section on its own, then checks its faces: a section relit from darkness
// only gains light (the solved levels are written as they are), a section that held light it cannot
// have had may have lit its neighbours with it (it is relit the general way, which removes that).
TEST(Light, RelightingASectionFromDarknessOrFromLightThatIsGoneMatchesAFullRecompute) {
  LitWorld w("terrain");
  w.loadArea(-1, -1, 1, 1);
  const int surface = w.gen->surfaceHeight(8, 8);
  w.set({0, surface + 2, 7}, "glowstone");  // on the section's west face: its light leaves the chunk
  w.set({15, surface - 3, 15}, "torch");
  Chunk& chunk = *w.world.chunk({0, 0});
  for (const int section : {sectionOf(surface) - 1, sectionOf(surface), sectionOf(surface) + 1}) {
    chunk.light().block[static_cast<std::size_t>(section)].fill(0);
    chunk.light().sky[static_cast<std::size_t>(section)].fill(0);
    w.light.relightSection({0, section, 0});
    EXPECT_EQ(compareWithReference(w.world), "") << "section " << section << " relit from darkness";
  }
  // Torches go without the light engine hearing of it; their light, in this section and beyond, goes
  // with the relight.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(0, 15), height(surface - 12, surface + 12);
  std::vector<BlockPos> torches;
  for (int i = 0; i < 24; ++i) {
    const BlockPos at{coord(rng), height(rng), coord(rng)};
    if (w.world.getBlock(at) != kAir) continue;
    w.set(at, "torch");
    torches.push_back(at);
  }
  ASSERT_GT(torches.size(), 8u);
  for (const BlockPos& at : torches) {
    ASSERT_TRUE(w.world.setBlock(at, kAir));
    w.light.relightSection({0, sectionOf(at.y), 0});
    ASSERT_EQ(compareWithReference(w.world), "")
        << "after removing the torch at " << at.x << " " << at.y << " " << at.z;
  }
}

TEST(Light, ByteWordsCompareEveryPairOfLevels) {
  for (int a = 0; a < 16; ++a)
    for (int b = 0; b < 16; ++b)
      for (const int k : {0, 1, 5, 7}) {
        const std::uint64_t before = static_cast<std::uint64_t>(a) << (8 * k) | 0x0F000000,
                            after = static_cast<std::uint64_t>(b) << (8 * k) | 0x0F000000;
        const std::uint64_t bit = std::uint64_t{0x80} << (8 * k);
        EXPECT_EQ(light::lowerBytes(before, after), b < a ? bit : 0) << a << " -> " << b << " in cell " << k;
        EXPECT_EQ(light::changedBytes(before, after), a != b ? bit : 0)
            << a << " -> " << b << " in cell " << k;
      }
}

// A section whose levels are replaced whole marks the faces of the cells that changed.
TEST(Light, ByteWordsMarkTheFacesOfTheirChangedCells) {
  for (int k = 0; k < Section::kVolume; ++k) {
    const std::uint64_t changed = std::uint64_t{0x80} << (8 * (k % 8));
    ASSERT_EQ(light::writeMarksOfBytes(k / 8, changed), light::kWriteMarks[static_cast<std::size_t>(k)])
        << "cell " << k;
  }
  EXPECT_EQ(light::writeMarksOfBytes(100, 0), 0u);
}

// Changed sections are appended with repeats; each comes out once, however many times and however
// far apart (past the point where repeats are folded between takes) it was added.
TEST(Light, ChangedSectionsComeOutOnceEach) {
  light::ChangedSections changed;
  const SectionPos far{-1'875'000, 23, 1'875'000}, near{0, 4, -1};
  for (int round = 0; round < 3; ++round)
    for (int i = 0; i < 5000; ++i) changed.add(i % 7, i % 24, -(i % 3));
  changed.add(far.x, far.section, far.z);
  changed.add(near.x, near.section, near.z);
  std::vector<SectionPos> taken = changed.take();
  // i % 3 follows from i % 24, so the loop adds 7 * 24 = 168 distinct sections, `near` among them.
  EXPECT_EQ(taken.size(), 169u);
  std::set<std::tuple<int, int, int>> distinct;
  for (const SectionPos& p : taken) distinct.insert({p.x, p.section, p.z});
  EXPECT_EQ(distinct.size(), taken.size());
  EXPECT_TRUE(distinct.contains({far.x, far.section, far.z}));
  EXPECT_TRUE(distinct.contains({near.x, near.section, near.z}));
  EXPECT_TRUE(changed.take().empty());
}

// Updates work on one byte per level; packing must give back exactly the NibbleArray's bytes.
TEST(Light, LevelsUnpackAndPackInNibbleArrayOrder) {
  NibbleArray nibbles;
  for (int i = 0; i < Section::kVolume; ++i) nibbles.set(i, static_cast<std::uint8_t>((i * 7 + i / 16) & 15));
  std::array<std::uint8_t, Section::kVolume> levels;
  light::unpackNibbles(nibbles.bytes(), levels.data());
  for (int i = 0; i < Section::kVolume; ++i)
    ASSERT_EQ(levels[static_cast<std::size_t>(i)], nibbles.get(i)) << i;
  NibbleArray::Bytes packed;
  EXPECT_EQ(light::packNibbles(levels.data(), packed.data()), -1);
  EXPECT_TRUE(std::equal(packed.begin(), packed.end(), nibbles.bytes()));

  // One level throughout is reported, whatever the level; one cell apart in either nibble is not.
  for (const std::uint8_t level : {0, 7, 15}) {
    levels.fill(level);
    EXPECT_EQ(light::packNibbles(levels.data(), packed.data()), level);
    for (const int odd : {4094, 4095, 17}) {
      levels[static_cast<std::size_t>(odd)] = level ^ 1;
      EXPECT_EQ(light::packNibbles(levels.data(), packed.data()), -1) << int{level} << " " << odd;
      levels[static_cast<std::size_t>(odd)] = level;
    }
  }
}

// Packing writes back only the bands of layers marked as written, and frees a section's bytes only
// when the bands it skipped have the same one level as those it wrote.
TEST(Light, PackingWritesTheMarkedLayersAndFreesOnlyWhatIsUniform) {
  light::LightFrame frame;
  std::array<light::Level, Section::kVolume> slab{};
  auto pack = [&](NibbleArray& layer, unsigned marks) {
    light::SectionRef r;
    r.layer = &layer;
    r.levels = slab.data();
    r.marks = marks;
    return frame.pack(r);
  };
  const int lastBand = light::kBands - 1, inLastBand = Section::kVolume - 96;
  const int bandCells = light::kLayersPerBand * 256;

  // A uniform section (0) whose lower band of layers is now all 15: the other bands keep their 0.
  NibbleArray was0;
  std::fill(slab.begin(), slab.begin() + bandCells, light::Level{15});
  EXPECT_EQ(pack(was0, light::bandMark(0)), light::bandMark(0));
  EXPECT_FALSE(was0.isUniform());
  EXPECT_EQ(was0.get(bandCells - 1), 15);
  EXPECT_EQ(was0.get(bandCells), 0);
  EXPECT_EQ(was0.get(Section::kVolume - 1), 0);

  // A section with bytes whose lower band goes back to 0: a 3 in its upper band keeps them.
  slab.fill(light::Level{0});
  NibbleArray mixed;
  mixed.set(inLastBand, 3);
  mixed.set(7, 9);
  EXPECT_EQ(pack(mixed, light::bandMark(0)), light::bandMark(0));
  ASSERT_FALSE(mixed.isUniform());
  EXPECT_EQ(mixed.get(7), 0);
  EXPECT_EQ(mixed.get(inLastBand), 3);
  // Once the upper band is written back to 0 too, nothing is kept.
  EXPECT_EQ(pack(mixed, light::bandMark(lastBand)), light::bandMark(lastBand));
  EXPECT_TRUE(mixed.isUniform());
  EXPECT_EQ(mixed.get(inLastBand), 0);
}

// Sections of one level are read from one shared slab; the first write gives a section its own,
// holding that level, and the others still read theirs.
TEST(Light, SectionsOfOneLevelShareASlabUntilWritten) {
  LitWorld w("flat");
  w.loadArea(0, 0, 1, 0);
  const light::ChunkWindow window(w.world, {0, 0}, {1, 0});
  light::LightFrame frame;
  frame.reset(window, LightChannel::Block);
  auto refAt = [&](int x, int y, int z) -> light::SectionRef& {
    std::uint32_t pos = 0;
    EXPECT_TRUE(frame.toFrame(x, y, z, pos));
    return frame.ref(light::LightFrame::refIndex(pos));
  };
  light::SectionRef& a = refAt(0, 40, 0);  // both under the ground: block light 0 throughout
  light::SectionRef& b = refAt(16, 40, 0);
  ASSERT_TRUE(a.shared && b.shared);
  EXPECT_EQ(a.levels, b.levels);

  light::Level* own = frame.own(a);
  EXPECT_FALSE(a.shared);
  EXPECT_NE(own, b.levels);
  EXPECT_TRUE(std::all_of(own, own + Section::kVolume, [](light::Level l) { return l == light::Level{0}; }));
  own[123] = light::Level{7};
  EXPECT_EQ(b.levels[123], light::Level{0});
  EXPECT_EQ(frame.own(a), own);  // once
}

// A section whose light goes back to one level (a torch taken away in the dark) stores no bytes again.
TEST(Light, SectionsBackToOneLevelKeepNoBytes) {
  LitWorld w("void");
  w.loadArea(-1, -1, 1, 1);
  auto lightBytes = [&] {
    std::size_t bytes = 0;
    for (int z = -1; z <= 1; ++z)
      for (int x = -1; x <= 1; ++x) bytes += w.world.chunk({x, z})->light().memoryBytes();
    return bytes;
  };
  const std::size_t before = lightBytes();
  const BlockPos torch{15, 64, 0};  // on a corner of its section: the light spreads into eight
  w.set(torch, "torch");
  EXPECT_GE(lightBytes(), before + 8 * NibbleArray::kBytes);
  w.set(torch, "air");
  EXPECT_EQ(lightBytes(), before);
  expectDiamond(w, torch, 0);

  // A stone in the open sky shades the cells below it; taken away, the sky is 15 throughout again.
  w.set({3, 70, 3}, "stone");
  EXPECT_GE(lightBytes(), before + NibbleArray::kBytes);
  w.set({3, 70, 3}, "air");
  EXPECT_EQ(lightBytes(), before);
  EXPECT_EQ(compareWithReference(w.world), "");
}

// The streamer tells the light engine before it removes a chunk and after it adds one, so light stays
// exactly right while the player walks away and back.
TEST(Light, StaysCorrectWhileChunksStreamInAndOut) {
  World world(defaultBlocks());
  LightEngine light(world);
  const auto gen = makeGenerator({"terrain", 5, {}}, defaultBlocks());
  ChunkStreamer streamer(world, *gen, nullptr, 2, 1);
  streamer.setHooks([&](ChunkPos p) { light.chunkLoaded(p); }, [&](ChunkPos p) { light.chunkUnloading(p); });
  auto settle = [&](ChunkPos center) {
    for (int i = 0; i < 20000 && (streamer.update(center), streamer.pending() > 0); ++i) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    streamer.update(center);
  };
  settle({0, 0});
  if (auto change = world.setBlock({8, 120, 8}, defaultBlocks().id("glowstone"))) light.blockChanged(*change);
  for (const ChunkPos c : {ChunkPos{2, 0}, ChunkPos{4, 1}, ChunkPos{1, 1}, ChunkPos{0, 0}}) {
    settle(c);
    ASSERT_EQ(compareWithReference(world), "") << "centre " << c.x << "," << c.z;
  }
}

// 100 000 random edits (shaped blocks among them), many on section and chunk borders, with chunks loading and
// unloading in random order; after every batch the incremental light equals a recompute from scratch.
TEST(Light, IncrementalUpdatesMatchAFullRecompute) {
  LitWorld w("flat", "bedrock,40*stone,dirt,grass_block");
  std::mt19937 rng(20261121);
  std::vector<ChunkPos> area;
  for (int z = -2; z <= 1; ++z)
    for (int x = -2; x <= 1; ++x) area.push_back({x, z});
  std::shuffle(area.begin(), area.end(), rng);
  std::vector<std::unique_ptr<Chunk>> unloaded;
  for (std::size_t i = 0; i < area.size(); ++i) {
    if (i < 10) {
      w.load(area[i]);
    } else {
      unloaded.push_back(std::make_unique<Chunk>(area[i]));
      w.gen->generate(*unloaded.back());
    }
  }
  const char* palette[] = {"air",
                           "air",
                           "air",
                           "stone",
                           "stone",
                           "glass",
                           "oak_leaves",
                           "water",
                           "torch",
                           "glowstone",
                           "lava",
                           "ice",
                           "stone_slab",
                           "stone_slab[type=top]",
                           "stone_slab[type=double]",
                           "oak_stairs[facing=north]",
                           "oak_stairs[facing=east,half=top]"};
  auto coordinate = [&](int lo, int hi) {
    // Half the edits sit on a border: local 0 or 15.
    const int v = lo + static_cast<int>(rng() % static_cast<unsigned>(hi - lo));
    return (rng() & 1) ? (v & ~15) + ((rng() & 1) ? 15 : 0) : v;
  };
  int edits = 0;
  for (int batch = 0; batch < 100; ++batch) {
    // Sometimes a chunk loads or unloads (keeping its blocks, as a save would).
    if (batch % 5 == 4 && !unloaded.empty()) {
      const std::size_t k = rng() % unloaded.size();
      const ChunkPos pos = unloaded[k]->pos();
      w.world.insertChunk(std::move(unloaded[k]));
      unloaded.erase(unloaded.begin() + static_cast<std::ptrdiff_t>(k));
      w.light.chunkLoaded(pos);
    } else if (batch % 5 == 2 && w.world.chunkCount() > 4) {
      std::vector<ChunkPos> loaded;
      w.world.forEachChunk([&](const Chunk& c) { loaded.push_back(c.pos()); });
      std::sort(loaded.begin(), loaded.end());
      const ChunkPos pos = loaded[rng() % loaded.size()];
      w.light.chunkUnloading(pos);
      unloaded.push_back(w.world.removeChunk(pos));
    }
    for (int i = 0; i < 1000; ++i, ++edits) {
      const BlockPos p{coordinate(-32, 32), coordinate(24, 104), coordinate(-32, 32)};
      w.set(p, palette[rng() % std::size(palette)]);
    }
    const std::string mismatch = compareWithReference(w.world);
    ASSERT_EQ(mismatch, "") << "after batch " << batch << " (" << edits << " edits)";
  }
  EXPECT_EQ(edits, 100000);
}

}  // namespace
}  // namespace terrasol
