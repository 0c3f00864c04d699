// terrasol-map: renders a generator's output to PNG, to look at terrain while tuning it.
//   terrasol-map [--seed N] [--generator terrain|flat|void] [--center X,Z] [--size BLOCKS] --out FILE
//   --slice   draw a vertical cut along x at the centre's z (y from -64 at the bottom to 320 at the top)
//   --biomes  draw the terrain generator's biomes (one colour each, printed with their share)
// Chunks are generated on all cores; the top view shades the highest block by its height.

#include <charconv>
#include <cstdio>
#include <future>
#include <map>
#include <string>
#include <thread>

#include "assets/image.h"
#include "core/error.h"
#include "core/paths.h"
#include "core/tool_main.h"
#include "world/generator.h"
#include "world/terrain_generator.h"

namespace terrasol {
namespace {

struct MapOptions {
  GeneratorSettings generator;
  int centerX = 0, centerZ = 0, size = 512;
  bool slice = false, biomes = false;
  std::string out;
};

std::int64_t parseNumber(const std::string& arg, const std::string& text) {
  std::int64_t v = 0;
  const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || p != text.data() + text.size())
    throw Error(arg + ": not a number: '" + text + "'");
  return v;
}

MapOptions parse(int argc, char** argv) {
  MapOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Error(arg + ": missing value");
      return argv[++i];
    };
    if (arg == "--seed")
      o.generator.seed = static_cast<std::uint64_t>(parseNumber(arg, value()));
    else if (arg == "--generator")
      o.generator.type = value();
    else if (arg == "--size")
      o.size = static_cast<int>(parseNumber(arg, value()));
    else if (arg == "--slice")
      o.slice = true;
    else if (arg == "--biomes")
      o.biomes = true;
    else if (arg == "--out")
      o.out = value();
    else if (arg == "--center") {
      const std::string v = value();
      const auto comma = v.find(',');
      if (comma == std::string::npos) throw Error(arg + ": expected X,Z");
      o.centerX = static_cast<int>(parseNumber(arg, v.substr(0, comma)));
      o.centerZ = static_cast<int>(parseNumber(arg, v.substr(comma + 1)));
    } else
      throw Error("unknown option '" + arg + "'");
  }
  if (o.out.empty() || o.size < 16 || o.size > 8192) {
    throw Error("usage: terrasol-map [--seed N] [--size 16..8192] [--slice | --biomes] --out FILE");
  }
  return o;
}

const std::map<std::string, std::array<int, 3>> kColours = {
    {"stone", {125, 125, 125}},      {"dirt", {134, 96, 67}},         {"grass_block", {95, 159, 53}},
    {"sand", {219, 207, 163}},       {"gravel", {136, 126, 126}},     {"bedrock", {60, 60, 60}},
    {"water", {52, 95, 218}},        {"lava", {230, 100, 20}},        {"snow_block", {245, 250, 250}},
    {"oak_log", {110, 85, 50}},      {"oak_leaves", {50, 120, 30}},   {"short_grass", {110, 170, 60}},
    {"dandelion", {240, 220, 40}},   {"poppy", {220, 30, 30}},        {"coal_ore", {50, 50, 50}},
    {"iron_ore", {200, 160, 130}},   {"gold_ore", {250, 220, 80}},    {"glowstone", {255, 230, 140}},
    {"sandstone", {216, 203, 155}},  {"ice", {160, 190, 240}},        {"snow", {245, 250, 250}},
    {"birch_log", {216, 215, 210}},  {"birch_leaves", {90, 140, 60}}, {"spruce_log", {58, 37, 16}},
    {"spruce_leaves", {40, 90, 50}}, {"acacia_log", {103, 96, 86}},   {"acacia_leaves", {90, 130, 40}},
    {"cactus", {80, 130, 40}},       {"dead_bush", {148, 100, 40}},   {"fern", {80, 140, 50}},
};

// A colour per biome (world/biomes.h order).
constexpr std::array<std::array<std::uint8_t, 3>, kBiomeCount> kBiomeColours = {{
    {40, 60, 170},
    {220, 210, 150},
    {140, 190, 90},
    {40, 110, 40},
    {120, 170, 110},
    {50, 90, 80},
    {235, 240, 245},
    {230, 200, 110},
    {180, 170, 80},
    {130, 130, 130},
}};

int biomeMap(const MapOptions& o, const BlockRegistry& blocks) {
  const TerrainGenerator gen(o.generator.seed, blocks);
  Image image(o.size, o.size);
  std::array<std::size_t, kBiomeCount> counts{};
  for (int py = 0; py < o.size; ++py)
    for (int px = 0; px < o.size; ++px) {
      const Biome b = gen.biomeAt(o.centerX - o.size / 2 + px, o.centerZ - o.size / 2 + py);
      ++counts[static_cast<std::size_t>(b)];
      const auto& c = kBiomeColours[static_cast<std::size_t>(b)];
      std::uint8_t* p = image.pixel(px, py);
      p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
    }
  saveImage(o.out, image);
  for (int b = 0; b < kBiomeCount; ++b) {
    std::printf("%-13s %5.1f %%\n", std::string(biomeName(static_cast<Biome>(b))).c_str(),
                100.0 * static_cast<double>(counts[static_cast<std::size_t>(b)]) /
                    (static_cast<double>(o.size) * o.size));
  }
  std::printf("wrote %s (%dx%d)\n", o.out.c_str(), image.width, image.height);
  return 0;
}

int run(int argc, char** argv) {
  const MapOptions o = parse(argc, argv);
  const BlockRegistry blocks = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  if (o.biomes) return biomeMap(o, blocks);
  const auto generator = makeGenerator(o.generator, blocks);
  std::vector<std::array<std::uint8_t, 3>> palette(blocks.size(), {255, 0, 255});
  for (BlockId id = 0; id < blocks.size(); ++id) {
    if (const auto it = kColours.find(blocks[id].name); it != kColours.end()) {
      palette[id] = {static_cast<std::uint8_t>(it->second[0]), static_cast<std::uint8_t>(it->second[1]),
                     static_cast<std::uint8_t>(it->second[2])};
    }
  }
  const int x0 = o.centerX - o.size / 2, z0 = o.slice ? o.centerZ : o.centerZ - o.size / 2;
  const int chunksX = (o.size + 15) / 16 + 1, chunksZ = o.slice ? 1 : chunksX;
  // Generate chunk rows in parallel; each task returns its finished chunks.
  std::vector<std::future<std::vector<std::unique_ptr<Chunk>>>> rows;
  for (int j = 0; j < chunksZ; ++j) {
    rows.push_back(std::async(std::launch::async, [&, j] {
      std::vector<std::unique_ptr<Chunk>> row;
      for (int i = 0; i < chunksX; ++i) {
        row.push_back(std::make_unique<Chunk>(ChunkPos{chunkOf(x0) + i, chunkOf(z0) + j}));
        generator->generate(*row.back());
      }
      return row;
    }));
  }
  std::vector<std::vector<std::unique_ptr<Chunk>>> chunks;
  for (auto& r : rows) chunks.push_back(r.get());
  auto blockAt = [&](int x, int y, int z) {
    const auto& c = chunks[static_cast<std::size_t>(chunkOf(z) - chunkOf(z0))]
                          [static_cast<std::size_t>(chunkOf(x) - chunkOf(x0))];
    return c->get(localOf(x), y, localOf(z));
  };

  Image image(o.size, o.slice ? kMaxY - kMinY : o.size);
  for (int py = 0; py < image.height; ++py)
    for (int px = 0; px < image.width; ++px) {
      std::array<std::uint8_t, 3> c{0, 0, 0};
      if (o.slice) {
        const BlockId id = blockAt(x0 + px, kMaxY - 1 - py, z0);
        c = id == kAir ? std::array<std::uint8_t, 3>{170, 200, 255} : palette[id];
      } else {
        for (int y = kMaxY - 1; y >= kMinY; --y) {
          const BlockId id = blockAt(x0 + px, y, z0 + py);
          if (id == kAir) continue;
          const double shade = 0.55 + 0.45 * (y - kMinY) / 200.0;
          for (int k = 0; k < 3; ++k)
            c[k] = static_cast<std::uint8_t>(std::min(255.0, palette[id][k] * shade));
          break;
        }
      }
      std::uint8_t* p = image.pixel(px, py);
      p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
    }
  saveImage(o.out, image);
  std::printf("wrote %s (%dx%d)\n", o.out.c_str(), image.width, image.height);
  return 0;
}

}  // namespace
}  // namespace terrasol

int main(int argc, char** argv) {
  return terrasol::guardedMain("terrasol-map", [&] { return terrasol::run(argc, argv); });
}
