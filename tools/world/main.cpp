// terrasol-world: what Terrasol reads of a Minecraft Java save (read-only; nothing is written to it).
//   terrasol-world info PATH [--json FILE]   the version, regions and chunks read, chunks by status,
//                                            block states, and cells whose block nothing knows
//   terrasol-world light PATH [--json FILE] [--differences FILE]
//                                            Terrasol's sky and block light against the save's own,
//                                            over full chunks whose eight neighbours are full: cells
//                                            compared, the share equal per channel, a histogram of
//                                            differences; --differences lists the first differing cells
// PATH is a save folder (level.dat and region/), a folder holding region/, or a bare region folder.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/error.h"
#include "core/paths.h"
#include "core/tool_main.h"
#include "light_compare.h"
#include "minecraft/minecraft_save.h"

namespace terrasol {
namespace {

int usage() {
  std::fputs(
      "usage: terrasol-world info PATH [--json FILE]\n"
      "       terrasol-world light PATH [--json FILE] [--differences FILE]\n",
      stderr);
  return 2;
}

struct Survey {
  std::size_t chunks = 0, full = 0, damaged = 0, unknownCells = 0, droppedPropertyCells = 0, blockCells = 0;
  int newestDataVersion = 0;  // of the chunks read: the version of a save without level.dat
  std::map<std::string, std::size_t> byStatus;
  std::set<BlockId> states;
  std::set<std::string> unknownNames;
  std::vector<std::string> problems;
};

Survey survey(const MinecraftSave& save, const BlockRegistry& blocks) {
  Survey s;
  s.problems = save.problems();
  BlockStateMapper mapper(blocks, kAir);
  for (const ChunkPos pos : save.chunks()) {
    ++s.chunks;
    try {
      const std::optional<AnvilChunk> chunk = save.load(pos, mapper);
      if (!chunk) continue;
      ++s.byStatus[chunk->status.empty() ? "(none)" : chunk->status];
      s.newestDataVersion = std::max(s.newestDataVersion, chunk->dataVersion);
      if (!chunk->full) continue;
      ++s.full;
      s.unknownCells += chunk->unknownCells;
      s.droppedPropertyCells += chunk->droppedPropertyCells;
      s.unknownNames.insert(chunk->unknownNames.begin(), chunk->unknownNames.end());
      for (int i = 0; i < kSectionCount; ++i) {
        const Section& section = chunk->chunk->section(i);
        if (section.isUniform()) {
          s.states.insert(section.uniformBlock());
          if (section.uniformBlock() != kAir) s.blockCells += Section::kVolume;
          continue;
        }
        for (const BlockId id : *section.blocks()) {
          s.states.insert(id);
          s.blockCells += id != kAir;
        }
      }
    } catch (const Error& e) {
      ++s.damaged;
      s.problems.push_back(std::string(e.what()) + "; chunk left out");
    }
  }
  return s;
}

int info(const std::filesystem::path& path, const std::filesystem::path& jsonFile) {
  const BlockRegistry blocks = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  const auto start = std::chrono::steady_clock::now();
  const MinecraftSave save(path);
  const Survey s = survey(save, blocks);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // level.dat's, else the newest chunk's (a bare region folder).
  const int dataVersion = save.level().dataVersion ? save.level().dataVersion : s.newestDataVersion;
  for (const std::string& p : s.problems) std::printf("problem: %s\n", p.c_str());
  for (const std::string& name : s.unknownNames) std::printf("unknown block: %s\n", name.c_str());
  std::printf(
      "save %s: %s\n", path.string().c_str(),
      save.level().versionName.empty() ? "no level.dat" : ("Minecraft " + save.level().versionName).c_str());
  if (dataVersion)
    std::printf("data version %d%s\n", dataVersion, save.level().dataVersion ? "" : " (the newest chunk's)");
  if (const auto& p = save.level().player) std::printf("player at %.1f %.1f %.1f\n", p->x, p->y, p->z);
  if (const auto& s = save.level().spawn) std::printf("spawn at %d %d %d\n", s->x, s->y, s->z);
  std::printf("regions in %s\n", save.regionDir().string().c_str());
  for (const auto& [status, n] : s.byStatus) std::printf("status %s: %zu chunks\n", status.c_str(), n);
  std::printf(
      "chunks %zu, full %zu, damaged %zu, block states %zu, block cells %zu, unknown cells %zu, "
      "cells with dropped properties %zu (%.2f s)\n",
      s.chunks, s.full, s.damaged, s.states.size(), s.blockCells, s.unknownCells, s.droppedPropertyCells,
      seconds);
  if (!jsonFile.empty()) {
    nlohmann::json j;
    j["data_version"] = dataVersion;
    j["version"] = save.level().versionName;
    j["chunks"] = s.chunks;
    j["full_chunks"] = s.full;
    j["damaged_chunks"] = s.damaged;
    j["unknown_cells"] = s.unknownCells;
    j["dropped_property_cells"] = s.droppedPropertyCells;
    j["block_cells"] = s.blockCells;
    j["block_states"] = s.states.size();
    j["status"] = s.byStatus;
    j["unknown_blocks"] = s.unknownNames;
    j["problems"] = s.problems;
    writeFileAtomically(jsonFile, j.dump(2) + "\n");
  }
  return 0;
}

nlohmann::json channelJson(const ChannelComparison& c, std::uint64_t cells) {
  nlohmann::json histogram = nlohmann::json::object();
  for (int d = -kMaxLight; d <= kMaxLight; ++d)
    if (const auto n = c.differences[static_cast<std::size_t>(d + kMaxLight)])
      histogram[std::to_string(d)] = n;
  return {{"equal_pct", c.equalPercent(cells)}, {"equal", c.equal}, {"differences", histogram}};
}

void printChannel(const char* name, const ChannelComparison& c, std::uint64_t cells) {
  std::printf("%s light: %.4f %% equal", name, c.equalPercent(cells));
  for (int d = -kMaxLight; d <= kMaxLight; ++d)
    if (const auto n = c.differences[static_cast<std::size_t>(d + kMaxLight)]; n && d != 0)
      std::printf(", %+d: %llu", d, static_cast<unsigned long long>(n));
  std::printf("\n");
}

int light(const std::filesystem::path& path, const std::filesystem::path& jsonFile,
          const std::filesystem::path& differencesFile) {
  const BlockRegistry blocks = BlockRegistry::load(resourcePackDir() / "default" / "blocks.json");
  const auto start = std::chrono::steady_clock::now();
  const LightComparison c = compareLight(path, blocks);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("compared %llu cells in %llu chunks (%.1f s)\n", static_cast<unsigned long long>(c.cells),
              static_cast<unsigned long long>(c.chunks), seconds);
  printChannel("sky", c.sky, c.cells);
  printChannel("block", c.block, c.cells);
  if (!differencesFile.empty()) {
    std::string text;
    for (const LightDifference& d : c.samples)
      text += std::string(d.sky ? "sky" : "block") + " " + std::to_string(d.pos.x) + " " +
              std::to_string(d.pos.y) + " " + std::to_string(d.pos.z) + ": terrasol " +
              std::to_string(d.ours) + ", minecraft " + std::to_string(d.theirs) + "\n";
    writeFileAtomically(differencesFile, text);
  }
  if (!jsonFile.empty()) {
    const nlohmann::json j = {{"compared_cells", c.cells},
                              {"compared_chunks", c.chunks},
                              {"sky", channelJson(c.sky, c.cells)},
                              {"block", channelJson(c.block, c.cells)}};
    writeFileAtomically(jsonFile, j.dump(2) + "\n");
  }
  return 0;
}

int run(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string command = argv[1];
  std::filesystem::path path, json, differences;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--json" && i + 1 < argc) {
      json = argv[++i];
    } else if (arg == "--differences" && i + 1 < argc) {
      differences = argv[++i];
    } else if (path.empty()) {
      path = arg;
    } else {
      return usage();
    }
  }
  if (command == "info" && !path.empty()) return info(path, json);
  if (command == "light" && !path.empty()) return light(path, json, differences);
  return usage();
}

}  // namespace
}  // namespace terrasol

int main(int argc, char** argv) {
  return terrasol::guardedMain("terrasol-world", [&] { return terrasol::run(argc, argv); });
}
