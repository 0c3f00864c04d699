#pragma once
// glTF 2.0 models (.gltf with external or embedded buffers, and .glb) as plain data, read through
// tinygltf with images decoded by OpenImageIO: static meshes flattened through the node hierarchy into
// model space, indices of any type, normals and tangents generated when missing, and the
// metallic-roughness materials. Every problem (a missing buffer, an accessor outside its buffer, a
// corrupt image, a required extension we lack) is an Error naming the file and the place.

#include <cstdint>
#include <filesystem>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "assets/image.h"

namespace terrasol {

struct ModelVertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};  // xyz unit, w = bitangent sign
  glm::vec2 uv{0.0f};
};

enum class AlphaMode { Opaque, Mask, Blend };

// Image indices refer to Model::images; -1 when the material has no such texture.
struct ModelMaterial {
  glm::vec4 baseColor{1.0f};
  int baseColorImage = -1;
  float metallic = 1.0f, roughness = 1.0f;
  int metallicRoughnessImage = -1;  // roughness in G, metallic in B
  int normalImage = -1;
  float normalScale = 1.0f;
  glm::vec3 emissive{0.0f};
  int emissiveImage = -1;
  int occlusionImage = -1;  // R
  float occlusionStrength = 1.0f;
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
};

// One primitive placed by one node, in model space: triangles.
struct ModelMesh {
  std::vector<ModelVertex> vertices;
  std::vector<std::uint32_t> indices;  // three per triangle
  int material = -1;                   // index into Model::materials, -1 for glTF's default material
  bool generatedNormals = false, generatedTangents = false;
};

struct Model {
  std::vector<ModelMesh> meshes;
  std::vector<ModelMaterial> materials;
  std::vector<Image> images;       // RGBA8, as stored (base colour and emissive are sRGB)
  glm::vec3 min{0.0f}, max{0.0f};  // bounds of every vertex
  std::size_t vertexCount() const;
};

// Throws Error naming the file and what is wrong.
Model loadModel(const std::filesystem::path& file);
// The bytes of a .glb or a .gltf (told apart by the binary magic); external files resolve against
// `baseDir`. `name` names the input in errors.
Model parseModel(const std::vector<std::uint8_t>& bytes, const std::string& name,
                 const std::filesystem::path& baseDir);

}  // namespace terrasol
