#pragma once
// A glTF model the tests write themselves, so prop tests need no third-party files: a unit cube
// centred on its origin, with normals and no texture coordinates, and one red dielectric material
// (base colour 0.8, 0, 0; metallic 0), as the Khronos "Box" sample is.

#include <filesystem>
#include <nlohmann/json.hpp>

namespace terrasol::testing {

// Writes `dir`/box.gltf and its buffer box.bin, with `material` merged over the red material
// (JSON merge patch, e.g. {"alphaMode": "MASK"}); returns the .gltf's path.
std::filesystem::path writeBoxGltf(const std::filesystem::path& dir,
                                   const nlohmann::json& material = nlohmann::json::object());

}  // namespace terrasol::testing
