#include "block_files.h"

#include <cmath>

namespace terrasol::packgen {
namespace {

constexpr std::array<std::pair<char, const char*>, 6> kFaceNames = {
    {{'d', "down"}, {'u', "up"}, {'n', "north"}, {'s', "south"}, {'w', "west"}, {'e', "east"}}};

// The face lies on the cell's boundary: a neighbour that covers that side hides it.
bool onBoundary(char face, const std::array<double, 3>& from, const std::array<double, 3>& to) {
  switch (face) {
    case 'd':
      return from[1] == 0.0;
    case 'u':
      return to[1] == 16.0;
    case 'n':
      return from[2] == 0.0;
    case 's':
      return to[2] == 16.0;
    case 'w':
      return from[0] == 0.0;
    default:
      return to[0] == 16.0;
  }
}

Json corner(const std::array<double, 3>& p) {
  return Json{number(p[0]), number(p[1]), number(p[2])};
}

}  // namespace

Json box(std::array<double, 3> from, std::array<double, 3> to, const std::string& texture,
         std::string_view faces) {
  Json out{{"from", corner(from)}, {"to", corner(to)}};
  Json f = Json::object();
  for (const auto& [letter, name] : kFaceNames) {
    if (faces.find(letter) == std::string_view::npos) continue;
    Json face{{"texture", texture}};
    if (onBoundary(letter, from, to)) face["cullface"] = name;
    f[name] = face;
  }
  out["faces"] = f;
  return out;
}

Json turnedBox(std::array<double, 3> from, std::array<double, 3> to, const std::string& texture,
               std::string_view faces, double angle) {
  Json out = box(from, to, texture, faces);
  for (auto& [name, face] : out["faces"].items()) face.erase("cullface");
  const std::array<double, 3> centre = {(from[0] + to[0]) / 2, (from[1] + to[1]) / 2, (from[2] + to[2]) / 2};
  out["rotation"] = Json{{"origin", corner(centre)}, {"axis", "y"}, {"angle", number(angle)}};
  return out;
}

Json elementModel(const Json& textures, const Json& elements) {
  Json t = textures;
  if (!t.contains("particle")) t["particle"] = textures.begin().value();
  return Json{{"parent", "block/block"}, {"textures", t}, {"elements", elements}};
}

Json facingVariants(const std::function<std::string(const std::string& facing)>& model,
                    const std::string& prefix, bool uvlock) {
  Json variants;
  for (const auto& [facing, y] : kFacings) {
    Json v{{"model", block(model(facing))}};
    if (y != 0) v["y"] = y;
    if (uvlock && y != 0) v["uvlock"] = true;
    variants[prefix + "facing=" + facing] = v;
  }
  return variants;
}

Json pointingVariants(const std::string& model, const std::string& prefix) {
  return Json{
      {prefix + "facing=up", variant(model, 0, 0)},       {prefix + "facing=down", variant(model, 180, 0)},
      {prefix + "facing=north", variant(model, 90, 0)},   {prefix + "facing=east", variant(model, 90, 90)},
      {prefix + "facing=south", variant(model, 90, 180)}, {prefix + "facing=west", variant(model, 90, 270)}};
}

Json frontVariants(const std::string& model, const std::string& prefix) {
  return Json{
      {prefix + "facing=north", variant(model, 0, 0)},   {prefix + "facing=east", variant(model, 0, 90)},
      {prefix + "facing=south", variant(model, 0, 180)}, {prefix + "facing=west", variant(model, 0, 270)},
      {prefix + "facing=up", variant(model, 270, 0)},    {prefix + "facing=down", variant(model, 90, 0)}};
}

void addModelBlock(const std::string& name, const Json& model, std::vector<GeneratedFile>& out) {
  out.push_back(file("model", name, model));
  out.push_back(file("blockstates", name, single(name)));
}

Json axisVariants(const std::string& model) {
  return Json{{"axis=x", variant(model, 90, 90)},
              {"axis=y", variant(model, 0, 0)},
              {"axis=z", variant(model, 90, 0)}};
}

}  // namespace terrasol::packgen
