#pragma once
// glTF props on the GPU: each model's meshes in one vertex and one index buffer with its material
// textures, and the placed instances, each with a transform and the voxel light at its vertices (a
// second vertex buffer, so a model placed twice shares its geometry). The renderer draws them beside
// the blocks (deferred_renderer.h); it never sees the world, so light comes in as data. GL thread only.

#include <epoxy/gl.h>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "assets/gltf_model.h"
#include "render/gl/object.h"

namespace terrasol {

// What the placed props need of the renderer: the shader variants and G-buffer data to build.
struct PropNeeds {
  bool any = false;         // some prop is placed
  bool mask = false;        // alpha mode MASK: the alpha-tested variants
  bool blend = false;       // alpha mode BLEND: the forward translucent variant
  bool normalMaps = false;  // a material has a normal map: the G-buffer keeps surface normals
  bool operator==(const PropNeeds&) const = default;
};

class Props {
 public:
  Props();

  // Uploads a model (its meshes, materials and images); returns its index.
  int addModel(const Model& model);

  struct Placement {
    glm::dvec3 position{0.0};       // of the model's origin
    glm::mat3 basis{1.0f};          // model -> world: rotation x uniform scale
    glm::mat3 rotation{1.0f};       // for normals and tangents
    glm::dvec3 min{0.0}, max{0.0};  // world bounds, for culling
  };
  // `light`: block and sky light 0..1 for every vertex of the model, meshes in Model order.
  int place(int model, const Placement& placement, std::span<const glm::vec2> light);
  void relight(int instance, std::span<const glm::vec2> light);
  void remove(int instance);  // later instances move down one index

  PropNeeds needs() const;
  bool empty() const { return instances_.empty(); }
  std::uint64_t generation() const { return generation_; }  // changes with every placement

  struct Mesh {
    GLsizei indexCount = 0;
    std::uintptr_t indexOffset = 0;  // bytes into the index buffer
    GLint baseVertex = 0;
    int material = 0;
  };
  struct Material {
    ModelMaterial params;
    GLuint baseColor = 0, metallicRoughness = 0, normal = 0, emissive = 0,
           occlusion = 0;  // never 0: defaults
    bool hasNormalMap = false;
  };
  struct GpuModel {
    gl::VertexArray layout;
    gl::Buffer vertices, indices;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;  // the model's, then glTF's default material
    std::vector<gl::Texture> textures;
    std::size_t vertexCount = 0;
  };
  struct Instance {
    int model = 0;
    Placement placement;
    gl::Buffer light;  // vec2 per vertex
  };
  const std::vector<GpuModel>& models() const { return models_; }
  const std::vector<Instance>& instances() const { return instances_; }

  // Binds the material's textures to the prop units (gl_slots.h).
  void bindMaterial(const Material& material) const;

 private:
  gl::Texture white_, whiteSrgb_, flatNormal_;
  std::vector<GpuModel> models_;
  std::vector<Instance> instances_;
  std::uint64_t generation_ = 0;
};

}  // namespace terrasol
