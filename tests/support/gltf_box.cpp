#include "support/gltf_box.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <vector>

namespace terrasol::testing {

std::filesystem::path writeBoxGltf(const std::filesystem::path& dir, const nlohmann::json& material) {
  // Four corners per face, counter-clockwise seen from outside, the face's normal on each.
  struct Face {
    std::array<float, 3> normal, u, v;
  };
  const std::array<Face, 6> faces = {{{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
                                      {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                                      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
                                      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                                      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
                                      {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}}}};
  std::vector<float> positions, normals;
  std::vector<std::uint16_t> indices;
  for (const Face& f : faces) {
    const auto base = static_cast<std::uint16_t>(positions.size() / 3);
    for (const auto [su, sv] : {std::array{-1, -1}, std::array{1, -1}, std::array{1, 1}, std::array{-1, 1}}) {
      for (int k = 0; k < 3; ++k) {
        positions.push_back(
            0.5f * (f.normal[k] + static_cast<float>(su) * f.u[k] + static_cast<float>(sv) * f.v[k]));
        normals.push_back(f.normal[k]);
      }
    }
    for (const int i : {0, 1, 2, 0, 2, 3}) indices.push_back(static_cast<std::uint16_t>(base + i));
  }
  const std::size_t indexBytes = indices.size() * 2, vertexBytes = positions.size() * 4;
  std::ofstream bin(dir / "box.bin", std::ios::binary);
  bin.write(reinterpret_cast<const char*>(indices.data()), static_cast<std::streamsize>(indexBytes));
  bin.write(reinterpret_cast<const char*>(positions.data()), static_cast<std::streamsize>(vertexBytes));
  bin.write(reinterpret_cast<const char*>(normals.data()), static_cast<std::streamsize>(vertexBytes));
  bin.close();

  nlohmann::json red = {
      {"name", "Red"},
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.0, 0.0, 1.0}}, {"metallicFactor", 0.0}}}};
  red.merge_patch(material);
  const nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}, {"generator", "Terrasol tests"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 1}, {"NORMAL", 2}}}, {"indices", 0}, {"material", 0}}}}}}},
      {"materials", {red}},
      {"buffers", {{{"uri", "box.bin"}, {"byteLength", indexBytes + 2 * vertexBytes}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", indexBytes}, {"target", 34963}},
        {{"buffer", 0},
         {"byteOffset", indexBytes},
         {"byteLength", 2 * vertexBytes},
         {"byteStride", 12},
         {"target", 34962}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5123}, {"count", indices.size()}, {"type", "SCALAR"}},
        {{"bufferView", 1},
         {"componentType", 5126},
         {"count", 24},
         {"type", "VEC3"},
         {"min", {-0.5, -0.5, -0.5}},
         {"max", {0.5, 0.5, 0.5}}},
        {{"bufferView", 1},
         {"byteOffset", vertexBytes},
         {"componentType", 5126},
         {"count", 24},
         {"type", "VEC3"},
         {"min", {-1.0, -1.0, -1.0}},
         {"max", {1.0, 1.0, 1.0}}}}}};
  const auto file = dir / "box.gltf";
  std::ofstream(file) << gltf.dump(1);
  return file;
}

}  // namespace terrasol::testing
