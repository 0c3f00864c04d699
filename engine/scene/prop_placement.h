#pragma once
// Where a scene's prop goes in the world, and the voxel light it stands in: plain C++, no GL.

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "assets/gltf_model.h"
#include "light/light_engine.h"
#include "scene/scene_file.h"

namespace terrasol {

// Model space to world: p_world = position + basis * p_model. The basis is R * scale with
// R = yaw about +y, then pitch about +x, then roll about +z (right-handed, degrees), so a uniform
// scale leaves `rotation` fit for normals and tangents.
struct PropTransform {
  glm::dvec3 position{0.0};
  glm::mat3 basis{1.0f};
  glm::mat3 rotation{1.0f};
};
PropTransform propTransform(const glm::dvec3& position, const glm::vec3& rotationDegrees, float scale);
PropTransform propTransform(const SceneProp& prop);
glm::dvec3 toWorld(const PropTransform& t, const glm::vec3& modelPoint);

// The world box around a model's box (min, max in model space) once placed.
struct WorldBounds {
  glm::dvec3 min{0.0}, max{0.0};
};
WorldBounds placedBounds(const PropTransform& t, const glm::vec3& min, const glm::vec3& max);

// Block and sky light (0..1) at world points, smooth like the mesher's: the trilinear blend of the
// 8 cells whose centres surround the point, leaving out cells of full opacity (light never enters
// them) and renormalising over the rest. A point with all 8 cells solid is dark.
std::vector<glm::vec2> smoothLightAt(const World& world, const LightEngine& light,
                                     std::span<const glm::dvec3> points);

// smoothLightAt every vertex of a placed model, meshes in order (what render/props.h takes).
std::vector<glm::vec2> modelLight(const Model& model, const PropTransform& t, const World& world,
                                  const LightEngine& light);

// A model file placed by several props is loaded once.
class ModelCache {
 public:
  // The model's index; loads it on first use (Error naming the file when it cannot be read).
  int load(const std::filesystem::path& file);
  const Model& operator[](int index) const { return models_[static_cast<std::size_t>(index)]; }

 private:
  std::vector<std::filesystem::path> files_;
  std::vector<Model> models_;
};

}  // namespace terrasol
