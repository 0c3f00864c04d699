#pragma once
// A shader pack as Terrasol's second pipeline: the pack's programs over the same section meshes, atlas
// and culling as the deferred renderer, in OptiFine's order, each a node of the frame graph:
//   shadow       the pack's shadow program from the sun (or moon) -> shadowtex0/1, shadowcolor0/1
//   sky          gbuffers_skybasic (discs), gbuffers_skytextured (sun, moon)
//   terrain      gbuffers_terrain: opaque, then cutout with the alpha test
//   deferredN    full-screen programs over the buffers
//   water        gbuffers_water: translucent terrain, blended
//   compositeN   full-screen programs over the buffers
//   final        to the target (colortex0 copied there when the pack has none)
// A program the pack lacks falls back along OptiFine's chain or leaves its node out. GL thread only.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "assets/atlas.h"
#include "assets/image.h"
#include "core/day_cycle.h"
#include "core/tint_palette.h"
#include "mesh/block_mesh_table.h"
#include "pack_render/pack_program.h"
#include "pack_render/pack_shadow_maps.h"
#include "pack_render/pack_sky.h"
#include "pack_render/pack_targets.h"
#include "pack_render/pack_textures.h"
#include "render/block_textures.h"
#include "render/frame_inputs.h"
#include "render/gbuffer.h"
#include "render/pass_clock.h"
#include "render/section_draw.h"
#include "render/section_meshes.h"
#include "render/world_renderer.h"
#include "shaderpack/pack_frame_uniforms.h"
#include "shaderpack/shader_pack.h"
#include "shaderpack/shader_properties.h"

namespace terrasol {

class PackRenderer final : public WorldRenderer {
 public:
  // Builds every program the frame runs. Throws Error naming the pack's file and line: a source that
  // does not preprocess, rewrite, compile or link, or malformed properties. `entityIds`: mc_Entity.xy
  // per atlas texture id (pack_render/pack_entities.h).
  // `shadowCasterCulling`: leave out of the shadow pass the sections whose shadow can fall on nothing
  // in view (render/shadow_receivers.h), as Terrasol's own shadow pass does.
  PackRenderer(const ShaderPack& pack, const ShaderPreprocessor& shaders, const Atlas& atlas,
               const TintPalette& tints, const std::vector<glm::vec2>& entityIds,
               bool shadowCasterCulling = true);
  ~PackRenderer();

  void render(const FrameInputs& frame, const SectionMeshes& meshes, GLuint framebuffer, glm::ivec2 size,
              std::vector<PassTiming>* timings = nullptr) override;

  const FrameStats& lastFrame() const override { return stats_; }
  // Where the last frame looked from, for reports; shadowMapShown when the pack has a shadow program
  // and names its shadow term for reports (shaders.properties: terrasol.report.shadow, .normal).
  const FrameGeometry& lastGeometry() const override { return geometry_; }
  // The last frame as the shadow report reads a G-buffer: the opaque depth, the pack's normal (as the
  // vertex normal, octahedral) and its shadow term (in scene's alpha); nothing when the pack names no
  // buffers for them. Slow: reads them back.
  std::optional<GBufferPixels> readReport() const;
  // Pixels holding NaN or Inf in the last frame's float buffers (slow: reads them back).
  std::size_t nonFinitePixels() const { return targets_ ? targets_->nonFinitePixels() : 0; }
  const std::string& packName() const { return packName_; }
  // The programs built, in the frame's order ("gbuffers_water: gbuffers_terrain" for a fallback).
  const std::vector<std::string>& programNames() const { return names_; }
  // Uniforms and samplers some program declares that Terrasol does not set, "program: name".
  std::vector<std::string> unknownUniforms() const;

 private:
  enum class StageKind { Shadow, SkyBasic, SkyTextured, Terrain, Deferred, Water, Composite, Final };
  struct Stage;
  struct FrameState;
  const Stage* stageOf(StageKind kind) const;
  PackView viewFor(const FrameInputs& inputs, glm::ivec2 size, float sunPathRotation, const DayState& day);
  std::vector<VisibleSection> shadowCasters(const FrameState& frame);
  void drawBlocks(const Stage& stage, const FrameState& frame, const std::vector<VisibleSection>& sections,
                  MeshLayer layer, DrawOrder order, FrameStats* stats);
  void drawShadow(const Stage& shadow, const FrameState& frame, const std::vector<VisibleSection>& casters);
  void drawSky(const FrameState& frame);
  void drawTerrain(const Stage& terrain, const FrameState& frame);
  void drawWater(const Stage* water, const FrameState& frame);
  void drawScreen(const Stage& stage, const FrameState& frame);

  std::string packName_;
  ShaderProperties properties_;
  PackSettings settings_;
  BlockTextures blockTextures_;
  std::unique_ptr<PackTextures> textures_;
  std::unique_ptr<PackShadowMaps> shadowMaps_;
  std::vector<Stage> stages_;
  std::vector<std::string> names_;
  std::optional<PackTargets> targets_;
  std::bitset<kPackColorBuffers> usedBuffers_;
  PackSky sky_;
  PackHistory history_;
  PackUniforms uniforms_;
  int frameCounter_ = 0;
  std::int64_t lastTicks_ = 0;
  bool gpuTimer_;
  bool shadowCasterCulling_;
  bool drawSun_ = true, drawMoon_ = true;  // shaders.properties sun, moon
  FrameStats stats_;
  FrameGeometry geometry_;
  std::optional<int> reportShadow_, reportNormal_;  // buffers named by terrasol.report.*
  glm::mat4 lastModelView_{1.0f};
};

// The pack at `path` (a folder or .zip) read, its block.properties mapped onto `blocks` through the
// mesher's `table`, and its renderer built. Throws Error naming the pack's file and line.
std::unique_ptr<PackRenderer> loadShaderPack(const std::filesystem::path& path,
                                             const ShaderPreprocessor& shaders, const BlockRegistry& blocks,
                                             const BlockMeshTable& table, const Atlas& atlas,
                                             const TintPalette& tints, bool shadowCasterCulling = true);

}  // namespace terrasol
