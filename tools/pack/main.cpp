// terrasol-pack: checks resource packs and builds their atlases, for pack authors.
//   terrasol-pack inspect PACK...             one line per problem, then a summary; exit 1 on errors
//   terrasol-pack atlas PACK... --out DIR     albedo/normal/specular atlases and their mip levels as PNG
//   terrasol-pack coverage PACK...            the top pack's block textures the blocks do not draw, then
//                                             "used U of N block textures"
//   terrasol-pack blocks PACK...              every block, its state count and how the stack draws it
//                                             (model, derived, nothing, placeholder), then
//                                             "blocks B, states S, drawn D, placeholder P"
// Packs are stacked bottom to top in the order given; the default pack is not added implicitly.

#include <chrono>
#include <cstdio>
#include <exception>
#include <set>
#include <string>
#include <vector>

#include "assets/atlas.h"
#include "core/error.h"
#include "core/paths.h"
#include "core/tool_main.h"
#include "scene/block_atlas.h"
#include "scene/pack_blocks.h"
#include "scene/texture_coverage.h"
#include "world/block_registry.h"

namespace terrasol {
namespace {

int usage() {
  std::fputs(
      "usage: terrasol-pack inspect PACK...\n"
      "       terrasol-pack atlas PACK... --out DIR\n"
      "       terrasol-pack coverage PACK...\n"
      "       terrasol-pack blocks PACK...\n",
      stderr);
  return 2;
}

std::string companionBase(const std::string& file) {
  for (const char* suffix : {"_n.png", "_s.png"}) {
    if (file.size() > 6 && file.ends_with(suffix)) return file.substr(0, file.size() - 6);
  }
  return "";
}

int inspect(const PackStack& packs) {
  std::vector<PackProblem> problems;
  int textures = 0, normals = 0, speculars = 0, animations = 0;
  // Every base texture of every pack, as the game would load it through the whole stack.
  std::set<std::string> names;
  for (const auto& pack : packs.packs()) {
    for (const auto& file : pack->blockTextureFiles()) {
      const std::string base = companionBase(file);
      if (!base.empty()) {
        if (!pack->blockTexture(base + ".png")) {
          problems.push_back(
              {PackProblem::Severity::Warning,
               pack->files().displayName(*pack->blockTexture(file)) + ": no base texture " + base + ".png"});
        }
        continue;
      }
      names.insert(file.substr(0, file.size() - 4));
    }
  }
  for (const auto& name : names) {
    const LoadedTexture t = loadBlockTexture(packs, {name}, problems);
    ++textures;
    normals += t.hasNormalMap;
    speculars += t.hasSpecularMap;
    animations += t.animation.has_value();
  }
  int errors = 0, warnings = 0;
  for (const auto& p : problems) {
    const bool error = p.severity == PackProblem::Severity::Error;
    errors += error;
    warnings += !error;
    std::printf("%s: %s\n", error ? "error" : "warning", p.message.c_str());
  }
  std::printf("%d textures, %d with _n, %d with _s, %d animated; %d warnings, %d errors\n", textures, normals,
              speculars, animations, warnings, errors);
  return errors > 0 ? 1 : 0;
}

// The registry the game builds with `packs`: Minecraft's table, blocks.json, and the blocks the packs add.
BlockRegistry registryFor(const PackStack& packs) {
  std::vector<PackProblem> problems;
  BlockRegistry blocks =
      withPackBlocks(BlockRegistry::load(resourcePackDir() / "default" / "blocks.json"), packs, problems);
  for (const PackProblem& p : problems) std::printf("warning: %s\n", p.message.c_str());
  return blocks;
}

int atlas(const PackStack& packs, const std::filesystem::path& out) {
  const BlockRegistry blocks = registryFor(packs);
  const auto start = std::chrono::steady_clock::now();
  const BlockAtlas blockAtlas = buildBlockAtlas(blocks, packs);  // exactly what the renderer gets
  const Atlas& built = blockAtlas.atlas;
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  for (const auto& p : blockAtlas.problems) {
    std::printf("%s: %s\n", p.severity == PackProblem::Severity::Error ? "error" : "warning",
                p.message.c_str());
  }
  std::filesystem::create_directories(out);
  for (int level = 0; level < built.levels(); ++level) {
    const std::string suffix = level == 0 ? "" : "_mip" + std::to_string(level);
    saveImage(out / ("albedo" + suffix + ".png"), built.albedo[static_cast<std::size_t>(level)]);
    saveImage(out / ("normal" + suffix + ".png"), built.normal[static_cast<std::size_t>(level)]);
    saveImage(out / ("specular" + suffix + ".png"), built.specular[static_cast<std::size_t>(level)]);
  }
  std::printf(
      "%zu textures in %d tiles of %dx%d, %d mip levels, %dx%d atlas, built in %.1f ms; written to %s\n",
      built.textures.size(), built.columns * built.rows, built.tileSize, built.tileSize, built.levels(),
      built.albedo[0].width, built.albedo[0].height, ms, out.string().c_str());
  return 0;
}

int coverage(const PackStack& packs) {
  const BlockRegistry blocks = registryFor(packs);
  const TextureCoverage c = textureCoverage(blocks, packs);
  const std::set<std::string> variants(c.variants.begin(), c.variants.end()),
      layers(c.emissiveLayers.begin(), c.emissiveLayers.end()),
      older(c.superseded.begin(), c.superseded.end());
  for (const std::string& name : c.unused) {
    const char* why = variants.contains(name) ? " (a numbered variant)"
                      : layers.contains(name) ? " (an emissive layer)"
                      : older.contains(name)  ? " (an older name; the pack has the current one)"
                                              : "";
    std::printf("unused: %s%s\n", name.c_str(), why);
  }
  const std::size_t total = c.used.size() + c.unused.size();
  const std::size_t nameable = total - c.variants.size() - c.emissiveLayers.size() - c.superseded.size();
  std::printf("unused: %zu numbered variants, %zu emissive layers, %zu older names, %zu other\n",
              c.variants.size(), c.emissiveLayers.size(), c.superseded.size(), c.otherUnused());
  std::printf("used %zu of %zu block textures; %zu of %zu a model could name\n", c.used.size(), total,
              c.used.size(), nameable);
  return 0;
}

int listBlocks(const PackStack& packs) {
  const BlockRegistry blocks = registryFor(packs);
  const BlockAtlas atlas = buildBlockAtlas(blocks, packs);
  for (const auto& p : atlas.problems) {
    if (p.severity == PackProblem::Severity::Error) std::printf("error: %s\n", p.message.c_str());
  }
  const std::vector<BlockDrawing> drawings = blockDrawings(blocks, atlas);
  std::size_t drawn = 0, placeholders = 0;
  for (std::size_t i = 0; i < blocks.blockCount(); ++i) {
    const BlockType& type = blocks.block(i);
    std::printf("%s %u %s%s\n", type.name.c_str(), static_cast<unsigned>(type.stateCount),
                std::string(kBlockDrawings.nameOf(drawings[i])).c_str(),
                i >= blocks.blocksBeforePacks() ? " (a pack's own block)" : "");
    drawn += drawings[i] == BlockDrawing::Model || drawings[i] == BlockDrawing::Derived;
    placeholders += drawings[i] == BlockDrawing::Placeholder;
  }
  std::printf("blocks %zu, states %zu, drawn %zu, placeholder %zu\n", blocks.blockCount(), blocks.size(),
              drawn, placeholders);
  return 0;
}

int run(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string command = argv[1];
  PackStack packs;
  std::filesystem::path out;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else {
      packs.push(ResourcePack::open(arg));
    }
  }
  if (packs.packs().empty()) return usage();
  if (command == "inspect") return inspect(packs);
  if (command == "coverage") return coverage(packs);
  if (command == "blocks") return listBlocks(packs);
  if (command == "atlas" && !out.empty()) return atlas(packs, out);
  return usage();
}

}  // namespace
}  // namespace terrasol

int main(int argc, char** argv) {
  return terrasol::guardedMain("terrasol-pack", [&] { return terrasol::run(argc, argv); });
}
