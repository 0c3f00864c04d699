// terrasol-map: renders a generator's output, or a Minecraft save, to PNG from above.
//   terrasol-map [--seed N] [--generator terrain|flat|void] [--center X,Z] [--size BLOCKS] --out FILE
//   --minecraft PATH  a Minecraft Java save instead of a generator (read-only); without --center, the
//                     middle of where its player starts
//   --slice   draw a vertical cut along x at the centre's z (y from -64 at the bottom to 320 at the top)
//   --biomes  draw the terrain generator's biomes (one colour each, printed with their share)
// Chunks are made on all cores. The top view colours each column by its highest block seen from
// above (its top texture's mean colour in the default pack, tinted by the column's biome), brighter
// where it stands higher than its northern neighbour and darker where lower, as Minecraft's maps shade.

#include <charconv>
#include <cmath>
#include <cstdio>
#include <future>
#include <glm/common.hpp>
#include <map>
#include <string>
#include <thread>

#include "assets/image.h"
#include "core/error.h"
#include "core/paths.h"
#include "core/tool_main.h"
#include "minecraft/minecraft_source.h"
#include "scene/block_colours.h"
#include "world/generator.h"
#include "world/terrain_generator.h"

namespace terrasol {
namespace {

struct MapOptions {
  GeneratorSettings generator;
  std::filesystem::path minecraft;
  bool centred = false;
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
    else if (arg == "--minecraft")
      o.minecraft = value();
    else if (arg == "--center") {
      const std::string v = value();
      const auto comma = v.find(',');
      if (comma == std::string::npos) throw Error(arg + ": expected X,Z");
      o.centerX = static_cast<int>(parseNumber(arg, v.substr(0, comma)));
      o.centerZ = static_cast<int>(parseNumber(arg, v.substr(comma + 1)));
      o.centred = true;
    } else
      throw Error("unknown option '" + arg + "'");
  }
  if (o.out.empty() || o.size < 16 || o.size > 8192) {
    throw Error(
        "usage: terrasol-map [--seed N | --minecraft PATH] [--size 16..8192] [--slice | --biomes] --out "
        "FILE");
  }
  return o;
}

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

// Each state's colour from above (scene/block_colours.h, the default pack); alpha 0 for what the view
// looks through (air, plants that cover little of their cell).
struct MapPalette {
  std::vector<TopColour> colours;
  std::vector<bool> seen;
  TintPalette tints;
};
MapPalette paletteOf(const BlockRegistry& blocks) {
  PackStack packs;
  packs.push(ResourcePack::open(resourcePackDir() / "default"));
  const BlockAtlas atlas = buildBlockAtlas(blocks, packs);
  MapPalette palette{blockTopColours(blocks, atlas), std::vector<bool>(blocks.size()), atlas.tints};
  for (std::size_t i = 0; i < blocks.size(); ++i)
    palette.seen[i] =
        palette.colours[i].texture.a >= 0.3f && blocks[static_cast<BlockId>(i)].shape != BlockShape::Cross;
  return palette;
}

int run(int argc, char** argv) {
  const MapOptions o = parse(argc, argv);
  const BlockRegistry blocks = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  if (o.biomes) return biomeMap(o, blocks);
  std::unique_ptr<ChunkGenerator> generator;
  MapOptions at = o;
  if (!o.minecraft.empty()) {
    auto save = std::make_unique<MinecraftChunkSource>(o.minecraft, blocks);
    for (const std::string& p : save->problems()) std::printf("problem: %s\n", p.c_str());
    if (!o.centred) {
      const glm::dvec3 start = save->startPosition();
      at.centerX = static_cast<int>(std::floor(start.x));
      at.centerZ = static_cast<int>(std::floor(start.z));
    }
    generator = std::move(save);
  } else {
    generator = makeGenerator(o.generator, blocks);
  }
  const MapPalette palette = paletteOf(blocks);
  const int x0 = at.centerX - o.size / 2, z0 = o.slice ? at.centerZ : at.centerZ - o.size / 2;
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
  auto chunkAt = [&](int x, int z) -> const Chunk& {
    return *chunks[static_cast<std::size_t>(chunkOf(z) - chunkOf(z0))]
                  [static_cast<std::size_t>(chunkOf(x) - chunkOf(x0))];
  };
  auto blockAt = [&](int x, int y, int z) { return chunkAt(x, z).get(localOf(x), y, localOf(z)); };
  // A state's colour in column (x, z): tinted by the column's biome.
  auto colourAt = [&](BlockId id, int x, int z) {
    const glm::vec4 c = palette.colours[id].in(palette.tints, chunkAt(x, z).tint(localOf(x), localOf(z)));
    return glm::dvec3(glm::clamp(glm::vec3(c), 0.0f, 1.0f)) * 255.0;
  };

  // The highest block seen from above in a column, and its y (kMinY - 1 for none).
  const auto topAt = [&](int x, int z) {
    for (int y = kMaxY - 1; y >= kMinY; --y) {
      const BlockId id = blockAt(x, y, z);
      if (palette.seen[id]) return std::pair{id, y};
    }
    return std::pair{kAir, kMinY - 1};
  };
  Image image(o.size, o.slice ? kMaxY - kMinY : o.size);
  for (int py = 0; py < image.height; ++py)
    for (int px = 0; px < image.width; ++px) {
      glm::dvec3 c(0.0);
      if (o.slice) {
        const BlockId id = blockAt(x0 + px, kMaxY - 1 - py, z0);
        c = palette.seen[id] ? colourAt(id, x0 + px, z0) : glm::dvec3(170, 200, 255);
      } else {
        const auto [id, y] = topAt(x0 + px, z0 + py);
        // The northern neighbour (the row above), inside the drawn area.
        const int north = py > 0 ? topAt(x0 + px, z0 + py - 1).second : y;
        const double shade = y < north ? 0.8 : y > north ? 1.1 : 0.95;
        if (y >= kMinY) c = glm::min(colourAt(id, x0 + px, z0 + py) * shade, glm::dvec3(255.0));
      }
      std::uint8_t* p = image.pixel(px, py);
      for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(c[k] + 0.5);
      p[3] = 255;
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
