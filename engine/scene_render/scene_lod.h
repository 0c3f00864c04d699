#pragma once
// A scene's far terrain (render.lod): tiles from its generator round each frame's camera, built before
// the frame is drawn, and the chunks its world draws in full detail as the mask that hides them.

#include <glm/vec3.hpp>
#include <memory>

#include "lod/lod_terrain.h"
#include "render/lod_meshes.h"
#include "scene/scene_world.h"

namespace terrasol {

class SceneLod {
 public:
  // Null when the scene asks for none or its generator cannot be sampled without chunks.
  static std::unique_ptr<SceneLod> create(const LodSettings& settings, const SceneWorld& world,
                                          LodPalette palette);

  // Builds what a camera at `camera` needs and shows it in `meshes`.
  void update(glm::dvec3 camera, LodMeshes& meshes);
  LodTerrainStats stats() const { return terrain_.stats(); }
  // The longest wait for a frame's tiles so far: the first frame's, which builds them all.
  double longestUpdateMs() const { return longestMs_; }

 private:
  SceneLod(const LodSettings& settings, const SceneWorld& world, LodPalette palette);

  const SceneWorld& world_;
  LodSettings settings_;
  LodTerrain terrain_;
  double longestMs_ = 0.0;
};

}  // namespace terrasol
