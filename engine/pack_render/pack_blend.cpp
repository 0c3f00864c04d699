#include "pack_render/pack_blend.h"

#include <map>
#include <string>

namespace terrasol {
namespace {

GLenum blendFactor(const std::string& name) {
  static const std::map<std::string, GLenum, std::less<>> kFactors = {
      {"ZERO", GL_ZERO},
      {"ONE", GL_ONE},
      {"SRC_COLOR", GL_SRC_COLOR},
      {"ONE_MINUS_SRC_COLOR", GL_ONE_MINUS_SRC_COLOR},
      {"DST_COLOR", GL_DST_COLOR},
      {"ONE_MINUS_DST_COLOR", GL_ONE_MINUS_DST_COLOR},
      {"SRC_ALPHA", GL_SRC_ALPHA},
      {"ONE_MINUS_SRC_ALPHA", GL_ONE_MINUS_SRC_ALPHA},
      {"DST_ALPHA", GL_DST_ALPHA},
      {"ONE_MINUS_DST_ALPHA", GL_ONE_MINUS_DST_ALPHA},
      {"SRC_ALPHA_SATURATE", GL_SRC_ALPHA_SATURATE},
  };
  return kFactors.at(name);  // packDrawState admits only these
}

}  // namespace

void applyBlend(const PackDrawState& state, const BlendFactors* fallback) {
  if (state.blend && !state.blend->enabled) return glDisable(GL_BLEND);
  if (state.blend) {
    const auto& f = state.blend->factors;
    glEnable(GL_BLEND);
    glBlendFuncSeparate(blendFactor(f[0]), blendFactor(f[1]), blendFactor(f[2]), blendFactor(f[3]));
    return;
  }
  if (!fallback) return glDisable(GL_BLEND);
  glEnable(GL_BLEND);
  glBlendFuncSeparate((*fallback)[0], (*fallback)[1], (*fallback)[2], (*fallback)[3]);
}

}  // namespace terrasol
