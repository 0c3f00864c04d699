#pragma once
// What the block-file generators share (shaped_blocks.cpp, block_family_files.cpp): JSON written in
// Minecraft's layout, two-space indented, keys in Minecraft's order. Internal to packgen.

#include <array>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
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

// A variant's model turned by x and y degrees.
inline Json variant(const std::string& model, int x = 0, int y = 0) {
  Json v{{"model", block(model)}};
  if (x != 0) v["x"] = x;
  if (y != 0) v["y"] = y;
  return v;
}

// A variant's model turned by x and y degrees; uvlock keeps its textures on the world's grid.
inline Json turned(const std::string& model, int x, int y) {
  Json v{{"model", block(model)}};
  if (x != 0) v["x"] = x;
  if (y != 0) v["y"] = y;
  if (x != 0 || y != 0) v["uvlock"] = true;
  return v;
}

// A JSON number written as Minecraft writes it: whole numbers without a fraction.
inline Json number(double v) {
  return v == static_cast<int>(v) ? Json(static_cast<int>(v)) : Json(v);
}

// A model element: a box from `from` to `to` (1/16 units) whose faces listed in `faces` ("d" down, "u" up,
// "n", "s", "w", "e") show `texture` ("#name" or "block/name") with uv from their place; a face on the
// cell's boundary culls against a neighbour that hides it, as Minecraft's templates set their cullfaces.
Json box(std::array<double, 3> from, std::array<double, 3> to, const std::string& texture,
         std::string_view faces = "dunswe");
// `box` turned about the vertical axis through its centre by `angle` degrees (22.5 or 45, either way).
Json turnedBox(std::array<double, 3> from, std::array<double, 3> to, const std::string& texture,
               std::string_view faces, double angle);
// A model of elements over block/block, its particle the first texture named.
Json elementModel(const Json& textures, const Json& elements);
// A model on a parent template with textures.
inline Json child(const std::string& parent, const Json& textures) {
  return Json{{"parent", parent}, {"textures", textures}};
}
// A blockstates file of one model for every state.
inline Json single(const std::string& model) {
  return Json{{"variants", {{"", {{"model", block(model)}}}}}};
}

// A block of one model drawn in every state: the model and its blockstates file.
void addModelBlock(const std::string& name, const Json& model, std::vector<GeneratedFile>& out);

// Copper's ages: the prefix of each age's blocks ("" is fresh copper).
inline constexpr std::array<const char*, 4> kCopperAges{"", "exposed_", "weathered_", "oxidized_"};
// The four horizontal facings and the y turn that brings a model made facing north to them.
inline constexpr std::array<std::pair<const char*, int>, 4> kFacings = {
    {{"north", 0}, {"east", 90}, {"south", 180}, {"west", 270}}};
// Variants for `facing`, each the model `model(facing)` turned to face it; `prefix` is the rest of the key.
Json facingVariants(const std::function<std::string(const std::string& facing)>& model,
                    const std::string& prefix = "", bool uvlock = false);

// Variants for the six directions of `facing` for a model made pointing up (rods, buds).
Json pointingVariants(const std::string& model, const std::string& prefix = "");
// Variants for the six directions of `facing` for a model made facing north (dispensers, observers).
Json frontVariants(const std::string& model, const std::string& prefix = "");
// Variants for a model made along y turned to each `axis`.
Json axisVariants(const std::string& model);
// A pane-like block (glass panes, bars): Minecraft's glass-pane templates on `pane` and `edge`.
void addPane(const std::string& name, const std::string& pane, const std::string& edge,
             std::vector<GeneratedFile>& out);

// The families by job: block-entity blocks as static models (furniture_files.cpp), work stations
// (workshop_files.cpp), cakes, candles, lanterns, metalwork and flower pots (home_files.cpp),
// redstone (redstone_files.cpp), plants (plant_files.cpp) and full blocks with their own faces
// (cube_files.cpp).
void addFurnitureFiles(std::vector<GeneratedFile>& out);
void addWorkshopFiles(std::vector<GeneratedFile>& out);
void addHomeFiles(std::vector<GeneratedFile>& out);
void addRedstoneFiles(std::vector<GeneratedFile>& out);
void addPlantFiles(std::vector<GeneratedFile>& out);
void addCubeFiles(std::vector<GeneratedFile>& out);

// The other families' files (block_family_files.cpp): bark blocks, carpets, glass panes, the newer
// woods as oak's files renamed, pressure plates and columns; and those blocks' names.
void addFamilyFiles(std::vector<GeneratedFile>& out);

}  // namespace terrasol::packgen
