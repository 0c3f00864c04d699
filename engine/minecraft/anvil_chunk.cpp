#include "minecraft/anvil_chunk.h"

#include <algorithm>
#include <bit>
#include <set>

#include "core/error.h"
#include "minecraft/biome_table.h"
#include "minecraft/data_versions.h"

namespace terrasol {
namespace {

using nbt::Tag;
using nbt::TagType;

// What one section's palette maps to, and how many of its cells each entry covers.
struct SectionStates {
  std::vector<MappedState> states;
  std::vector<std::string> names;
};

class ChunkDecoder {
 public:
  ChunkDecoder(BlockStateMapper& mapper, std::string_view what, bool withLight)
      : mapper_(mapper), what_(what), withLight_(withLight) {}

  AnvilChunk decode(const Tag& root, ChunkPos expected) {
    AnvilChunk out;
    const Tag* version = root.find("DataVersion");
    out.dataVersion = version && version->isInteger() ? static_cast<int>(version->integer()) : 0;
    if (out.dataVersion < kDataVersion1_13)
      fail("DataVersion " + std::to_string(out.dataVersion) +
           " is from before Minecraft 1.13, whose numeric block ids Terrasol does not read");
    const bool modern = out.dataVersion >= kDataVersion1_18;
    // 1.13 to 1.17 keep everything under "Level".
    const Tag* level = modern ? &root : root.find("Level", TagType::Compound);
    if (!level) fail("no Level compound");
    checkPosition(*level, expected);
    const Tag* status = level->find("Status", TagType::String);
    out.status = status ? status->string() : "";
    out.full = isFullStatus(out.status);
    if (!out.full) return out;

    out.chunk = std::make_unique<Chunk>(expected);
    const Tag* sections = level->find(modern ? "sections" : "Sections", TagType::List);
    if (sections) {
      for (const Tag& section : sections->items()) {
        decodeSection(section, out, modern);
        if (modern) decodeBiomes(section);
      }
      if (withLight_) out.light = storedLight(*sections);
    }
    if (!modern) decodeOldBiomes(*level);
    applyTints(*out.chunk);
    out.unknownNames.assign(unknown_.begin(), unknown_.end());
    out.chunk->compact();
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(std::string(what_) + ": " + message);
  }

  void checkPosition(const Tag& level, ChunkPos expected) const {
    const Tag* x = level.find("xPos");
    const Tag* z = level.find("zPos");
    if (!x || !z || !x->isInteger() || !z->isInteger()) fail("no xPos/zPos");
    if (x->integer() != expected.x || z->integer() != expected.z)
      fail("says it is chunk (" + std::to_string(x->integer()) + ", " + std::to_string(z->integer()) +
           ") but sits in the slot of (" + std::to_string(expected.x) + ", " + std::to_string(expected.z) +
           ")");
  }

  void decodeSection(const Tag& section, AnvilChunk& out, bool modern) {
    const Tag* y = section.find("Y");
    if (!y || !y->isInteger()) fail("a section without Y");
    const int sectionY = static_cast<int>(static_cast<std::int8_t>(y->integer()));
    const Tag* palette = nullptr;
    const Tag* data = nullptr;
    if (modern) {
      const Tag* states = section.find("block_states", TagType::Compound);
      if (!states) return;  // a light-only section
      palette = states->find("palette", TagType::List);
      data = states->find("data", TagType::LongArray);
    } else {
      palette = section.find("Palette", TagType::List);
      data = section.find("BlockStates", TagType::LongArray);
    }
    if (!palette || palette->items().empty()) return;  // light only (1.13's Y = -1)
    const int index = sectionY - (kMinY >> kChunkShift);
    if (index < 0 || index >= kSectionCount) return;  // beyond Terrasol's height
    const std::string where = "section Y=" + std::to_string(sectionY);

    std::vector<MappedState> states;
    states.reserve(palette->items().size());
    for (const Tag& entry : palette->items()) states.push_back(mapEntry(entry, out.dataVersion, where));

    Section& target = out.chunk->section(index);
    const std::size_t n = states.size();
    if (n == 1 && !data) {
      target.fill(states[0].id);
      count(states[0], Section::kVolume, out);
      return;
    }
    if (!data) fail(where + ": a palette of " + std::to_string(n) + " with no block data");
    const int bits = std::max(4, static_cast<int>(std::bit_width(n - 1)));
    std::vector<std::uint16_t> indices(Section::kVolume);
    unpack(data->longs(), bits, out.dataVersion >= kDataVersionUnspannedLongs, indices, where);
    std::vector<std::size_t> uses(n, 0);
    Section::Blocks& blocks = target.mutableBlocks();
    for (int i = 0; i < Section::kVolume; ++i) {
      const std::uint16_t p = indices[static_cast<std::size_t>(i)];
      if (p >= n)
        fail(where + ": palette index " + std::to_string(p) + " past its " + std::to_string(n) + " entries");
      blocks[static_cast<std::size_t>(i)] = states[p].id;
      ++uses[p];
    }
    for (std::size_t p = 0; p < n; ++p) count(states[p], uses[p], out);
  }

  // 1.18 on: a section's 4 x 4 x 4 biome cells, (y << 4 | z << 2 | x), ceil(log2(palette)) bits
  // each (none for one entry), unspanned.
  void decodeBiomes(const Tag& section) {
    const Tag* y = section.find("Y");
    const Tag* biomes = section.find("biomes", TagType::Compound);
    if (!y || !biomes) return;
    const int index = static_cast<int>(static_cast<std::int8_t>(y->integer())) - (kMinY >> kChunkShift);
    const Tag* palette = biomes->find("palette", TagType::List);
    if (index < 0 || index >= kSectionCount || !palette || palette->items().empty()) return;
    std::vector<MinecraftBiome> biomeOf;
    for (const Tag& name : palette->items())
      biomeOf.push_back(minecraftBiome(name.string()).value_or(minecraftPlains()));
    std::array<MinecraftBiome, kBiomeCells>& cells =
        sectionBiomes_[static_cast<std::size_t>(index)].emplace();
    const Tag* data = biomes->find("data", TagType::LongArray);
    const int bits = static_cast<int>(std::bit_width(biomeOf.size() - 1));
    if (!data || bits == 0) {
      cells.fill(biomeOf[0]);
      return;
    }
    const int perLong = 64 / bits;
    const auto longs = data->longs();
    if (longs.size() < static_cast<std::size_t>((kBiomeCells + perLong - 1) / perLong))
      fail("section Y=" + std::to_string(y->integer()) + ": too few longs of biome data");
    for (int i = 0; i < kBiomeCells; ++i) {
      const auto word = static_cast<std::uint64_t>(longs[static_cast<std::size_t>(i / perLong)]);
      const std::size_t p = (word >> ((i % perLong) * bits)) & ((std::uint64_t{1} << bits) - 1);
      if (p >= biomeOf.size())
        fail("section Y=" + std::to_string(y->integer()) + ": biome index past its palette");
      cells[static_cast<std::size_t>(i)] = biomeOf[p];
    }
  }

  // 1.13 to 1.17: numeric ids, per column (256, before 1.15) or per 4 x 4 x 4 cell from y = 0 (1024).
  void decodeOldBiomes(const Tag& level) {
    const Tag* biomes = level.find("Biomes", TagType::IntArray);
    if (!biomes) return;
    const auto ids = biomes->ints();
    const auto biome = [](int id) { return minecraftBiome(id).value_or(minecraftPlains()); };
    if (ids.size() == kChunkArea) {
      oldColumns_.emplace();
      for (std::size_t i = 0; i < kChunkArea; ++i) (*oldColumns_)[i] = biome(ids[i]);
    } else if (ids.size() == 1024) {
      for (int cell = 0; cell < 1024; ++cell) {
        const int section = (cell >> 6) - (kMinY >> kChunkShift);  // 16 cell layers of 4: 4 sections
        auto& cells = sectionBiomes_[static_cast<std::size_t>(section)];
        if (!cells) cells.emplace().fill(minecraftPlains());
        (*cells)[static_cast<std::size_t>(cell & 63)] = biome(ids[static_cast<std::size_t>(cell)]);
      }
    }
  }

  // Each column takes the biome where its highest block stands (plains where the chunk names none).
  void applyTints(Chunk& chunk) const {
    const int x0 = chunk.pos().minBlockX(), z0 = chunk.pos().minBlockZ();
    for (int z = 0; z < kChunkSize; ++z)
      for (int x = 0; x < kChunkSize; ++x) {
        MinecraftBiome biome = minecraftPlains();
        if (oldColumns_) {
          biome = (*oldColumns_)[static_cast<std::size_t>(columnIndex(x, z))];
        } else {
          const int top = std::max(chunk.highestBlock(x, z), kMinY);
          if (const auto& cells = sectionBiomes_[static_cast<std::size_t>(sectionOf(top))])
            biome =
                (*cells)[static_cast<std::size_t>(((top & kLastCell) >> 2) << 4 | (z >> 2) << 2 | (x >> 2))];
        }
        chunk.setTint(x, z, minecraftBiomeTint(biome, x0 + x, z0 + z));
      }
  }

  // The sections' SkyLight and BlockLight arrays, or nothing when the chunk keeps none.
  std::optional<StoredLight> storedLight(const Tag& sections) const {
    StoredLight light;
    bool any = false;
    for (const Tag& section : sections.items()) {
      const Tag* y = section.find("Y");
      if (!y || !y->isInteger()) continue;
      const int index = static_cast<int>(static_cast<std::int8_t>(y->integer())) - (kMinY >> kChunkShift);
      if (index < 0 || index >= kSectionCount) continue;
      for (const auto& [name, target] :
           {std::pair{"SkyLight", &light.sky}, std::pair{"BlockLight", &light.block}}) {
        const Tag* array = section.find(name, TagType::ByteArray);
        if (!array) continue;
        if (array->bytes().size() != 2048)
          fail(std::string(name) + " of section Y=" + std::to_string(y->integer()) + " holds " +
               std::to_string(array->bytes().size()) + " bytes, not 2048");
        (*target)[static_cast<std::size_t>(index)].assign(array->bytes().begin(), array->bytes().end());
        any = true;
      }
    }
    if (!any) return std::nullopt;
    return light;
  }

  static void count(const MappedState& s, std::size_t cells, AnvilChunk& out) {
    if (!s.known) out.unknownCells += cells;
    if (s.droppedProperties) out.droppedPropertyCells += cells;
  }

  // Unpacks 4096 indices of `bits` each. Spanning: a bit stream over the longs, low bits first.
  // Unspanned: floor(64 / bits) indices a long, the top bits unused.
  void unpack(std::span<const std::int64_t> longs, int bits, bool unspanned, std::vector<std::uint16_t>& out,
              const std::string& where) const {
    const std::uint64_t mask = (std::uint64_t{1} << bits) - 1;
    const int perLong = 64 / bits;
    const std::size_t expected =
        unspanned ? (Section::kVolume + perLong - 1) / perLong : Section::kVolume * bits / 64;
    if (longs.size() != expected)
      fail(where + ": " + std::to_string(longs.size()) + " longs of block data, " + std::to_string(expected) +
           " expected for " + std::to_string(bits) + " bits " + (unspanned ? "(1.16 on)" : "(before 1.16)"));
    if (unspanned) {
      for (int i = 0; i < Section::kVolume; ++i) {
        const auto word = static_cast<std::uint64_t>(longs[static_cast<std::size_t>(i / perLong)]);
        out[static_cast<std::size_t>(i)] =
            static_cast<std::uint16_t>((word >> ((i % perLong) * bits)) & mask);
      }
      return;
    }
    for (int i = 0; i < Section::kVolume; ++i) {
      const std::size_t bit = static_cast<std::size_t>(i) * static_cast<std::size_t>(bits);
      const std::size_t word = bit / 64, shift = bit % 64;
      std::uint64_t v = static_cast<std::uint64_t>(longs[word]) >> shift;
      if (shift + static_cast<std::size_t>(bits) > 64)
        v |= static_cast<std::uint64_t>(longs[word + 1]) << (64 - shift);
      out[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(v & mask);
    }
  }

  MappedState mapEntry(const Tag& entry, int dataVersion, const std::string& where) {
    const Tag* name = entry.find("Name", TagType::String);
    if (!name) fail(where + ": a palette entry without a Name");
    properties_.clear();
    if (const Tag* props = entry.find("Properties", TagType::Compound)) {
      for (std::size_t i = 0; i < props->items().size(); ++i) {
        const Tag& v = props->items()[i];
        if (v.type() == TagType::String) properties_.emplace_back(props->memberNames()[i], v.string());
      }
    }
    const MappedState s = mapper_.map(name->string(), properties_, dataVersion);
    if (!s.known) unknown_.insert(name->string());
    return s;
  }

  BlockStateMapper& mapper_;
  std::string_view what_;
  bool withLight_;
  static constexpr int kBiomeCells = 64;  // 4 x 4 x 4 a section
  std::array<std::optional<std::array<MinecraftBiome, kBiomeCells>>, kSectionCount> sectionBiomes_;
  std::optional<std::array<MinecraftBiome, kChunkArea>> oldColumns_;  // before 1.15: one biome a column
  StateProperties properties_;
  std::set<std::string> unknown_;
};

}  // namespace

bool isFullStatus(std::string_view status) {
  constexpr std::string_view kMinecraft = "minecraft:";
  if (status.starts_with(kMinecraft)) status.remove_prefix(kMinecraft.size());
  // "fullchunk" and "postprocessed" are 1.13's finished chunks; "full" since 1.14.
  return status == "full" || status == "fullchunk" || status == "postprocessed";
}

AnvilChunk decodeAnvilChunk(const nbt::Tag& root, ChunkPos expected, BlockStateMapper& mapper,
                            std::string_view what, bool withLight) {
  return ChunkDecoder(mapper, what, withLight).decode(root, expected);
}

namespace {

std::uint8_t nibble(const std::vector<std::uint8_t>& data, int x, int localY, int z) {
  const int i = localY << 8 | z << 4 | x;
  const std::uint8_t byte = data[static_cast<std::size_t>(i >> 1)];
  return static_cast<std::uint8_t>(i & 1 ? byte >> 4 : byte & 0x0F);
}

}  // namespace

std::uint8_t StoredLight::skyAt(int x, int y, int z) const {
  const int own = sectionOf(y);
  const std::vector<std::uint8_t>& data = sky[static_cast<std::size_t>(own)];
  if (!data.empty()) return nibble(data, x, y - sectionMinY(own), z);
  // Minecraft writes no array for a section whose light is all 0 (an empty DataLayer): below the
  // highest array, a missing one is dark; above them all is open sky.
  for (int s = own + 1; s < kSectionCount; ++s)
    if (!sky[static_cast<std::size_t>(s)].empty()) return 0;
  return kMaxLight;
}

std::uint8_t StoredLight::blockAt(int x, int y, int z) const {
  const std::vector<std::uint8_t>& data = block[static_cast<std::size_t>(sectionOf(y))];
  return data.empty() ? 0 : nibble(data, x, y - sectionMinY(sectionOf(y)), z);
}

}  // namespace terrasol
