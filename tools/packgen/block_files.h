#pragma once
// What the block-file generators share (shaped_blocks.cpp, block_family_files.cpp): JSON written in
// Minecraft's layout, two-space indented, keys in Minecraft's order. Internal to packgen.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "packgen.h"

namespace terrasol::packgen {

using Json = nlohmann::ordered_json;

// "block/<name>": a model's or texture's resource name.
inline std::string block(const std::string& name) {
  return "block/" + name;
}

// A blockstates file (kind "blockstates") or a block model (any other kind) named `name`.
inline GeneratedFile file(const std::string& kind, const std::string& name, const Json& json) {
  const std::string dir =
      kind == "blockstates" ? "assets/minecraft/blockstates/" : "assets/minecraft/models/block/";
  return {dir + name + ".json", json.dump(2) + "\n"};
}

// A variant's model turned by x and y degrees; uvlock keeps its textures on the world's grid.
inline Json turned(const std::string& model, int x, int y) {
  Json v{{"model", block(model)}};
  if (x != 0) v["x"] = x;
  if (y != 0) v["y"] = y;
  if (x != 0 || y != 0) v["uvlock"] = true;
  return v;
}

// The other families' files (block_family_files.cpp): bark blocks, carpets, glass panes, the newer
// woods as oak's files renamed, pressure plates and columns; and those blocks' names.
void addFamilyFiles(std::vector<GeneratedFile>& out);
void addFamilyBlockNames(std::vector<std::string>& names);

}  // namespace terrasol::packgen
