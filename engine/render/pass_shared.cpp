#include "render/pass_shared.h"

#include <algorithm>

namespace terrasol {

namespace {

// The maps no loaded pack has: nothing to sample (block_surface.glsl) and nothing to keep for them.
// Props always carry a material (metallic-roughness becomes a LabPBR _s texel), and may have normal maps.
GBufferContents contentsFor(const Atlas& atlas, const RendererOptions& options) {
  return {!options.leaveOutAbsentMaps || atlas.anyNormalMap || options.props.normalMaps,
          !options.leaveOutAbsentMaps || atlas.anySpecularMap || options.props.any};
}

}  // namespace

PassShared::PassShared(const Atlas& atlas, const TintPalette& tints, const CloudMap& cloudMap,
                       const RendererOptions& options)
    : options(options),
      contents(contentsFor(atlas, options)),
      smoothness(contents.specular ? textureSmoothness(atlas) : std::vector<float>{}),
      maxSmoothness(smoothness.empty() ? 0.0f : *std::max_element(smoothness.begin(), smoothness.end())),
      emission(contents.specular ? textureEmission(atlas) : std::vector<float>{}),
      textures(atlas, tints),
      empty(gl::VertexArray::create()) {
  if (options.clouds.mode != CloudMode::Off && !cloudMap.empty()) clouds.emplace(cloudMap);
}

std::vector<ShaderDefine> PassShared::skyDefines() const {
  std::vector<ShaderDefine> defines;
  if (clouds) {
    defines.push_back({"CLOUDS", "1"});
    if (options.clouds.mode == CloudMode::Fancy) defines.push_back({"CLOUDS_FANCY", "1"});
    if (options.clouds.mode == CloudMode::Volumetric) defines.push_back({"CLOUDS_VOLUMETRIC", "1"});
    if (options.clouds.shadows) defines.push_back({"CLOUD_SHADOWS", "1"});
  }
  if (options.fog.density > 0.0f) defines.push_back({"HEIGHT_FOG", "1"});
  return defines;
}

LinkedProgram VariantBuilder::operator()(const char* vertex, const char* fragment,
                                         std::vector<ShaderDefine> extra) const {
  std::string name = std::string(fragment).substr(0, std::string(fragment).find('.'));
  for (const ShaderDefine& d : extra) {
    name += "+";
    name += d.name;
    if (d.value != "1") name += "=" + d.value;
  }
  shared_.variants.push_back(name);
  std::vector<ShaderDefine> defines = rendererDefines();
  for (auto& d : extra) defines.push_back(std::move(d));
  return linkProgram(shaders_, {{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}, defines);
}

std::vector<ShaderDefine> with(std::vector<ShaderDefine> a, const std::vector<ShaderDefine>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<ShaderDefine> lightingDefines(const RendererOptions& options) {
  std::vector<ShaderDefine> defines;
  if (options.ggxSpecular) defines.push_back({"SPECULAR_GGX", "1"});
  if (options.shadow.enabled) {
    // The filter is fixed per renderer, so each shader holds only its own taps: a software rasterizer
    // runs every branch that any pixel of a block takes, and a loop over a uniform count costs more.
    // Neither define: one tap.
    defines.push_back({"SHADOWS", "1"});
    if (const int n = std::clamp(options.shadow.pcfSamples, 0, 8); n > 0) {
      if (options.shadow.pcfPattern == PcfPattern::Disk) {
        defines.push_back({"PCF_DISK", "1"});
      } else if (options.shadow.pcfPattern == PcfPattern::Tent) {
        defines.push_back({"PCF_TENT", "1"});
      } else {
        defines.push_back({"PCF_GRID_SIDE", std::to_string(2 * n + 1)});
      }
    }
  }
  return defines;
}

void bindForOpaqueGeometry(const GBuffer& gbuffer) {
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer.geometryFramebuffer());
  glViewport(0, 0, gbuffer.size().x, gbuffer.size().y);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
  glDisable(GL_BLEND);
}

std::vector<ShaderDefine> surfaceDefines(const RendererOptions& options) {
  std::vector<ShaderDefine> defines;
  if (options.reflections.enabled) defines.push_back({"REFLECTIONS", "1"});
  if (options.water.waves) defines.push_back({"WAVES", "1"});
  return defines;
}

}  // namespace terrasol
