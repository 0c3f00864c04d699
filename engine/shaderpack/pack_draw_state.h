#pragma once
// The draw state shaders.properties sets per program (OptiFine's shaders.properties doc):
// `alphaTest.<program>=off | GREATER 0.5` and `blend.<program>=off | <src> <dst> [<srcAlpha> <dstAlpha>]`
// with GL's factor names, plus the switches `sun`, `moon` and `oldLighting`. GL-free: factors stay
// names the renderer maps onto GL's.

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "shaderpack/shader_properties.h"

namespace terrasol {

struct PackBlend {
  bool enabled = true;
  std::array<std::string, 4> factors;  // src, dst, srcAlpha, dstAlpha: "SRC_ALPHA", "ONE", ...
};

struct PackDrawState {
  std::optional<float> alphaTestRef;  // 0: off; nothing: the program's default
  std::optional<PackBlend> blend;     // nothing: the program's default
};

// GL's blend factor names, without "GL_".
bool isBlendFactor(std::string_view name);

// Throws Error naming the line for a function other than GREATER or GEQUAL, a reference that is not a
// number, or a blend that is not two or four factors.
PackDrawState packDrawState(const ShaderProperties& properties, std::string_view program);

// A switch such as `sun=false`: its value, or `otherwise` without the key. Throws Error naming the
// line for a value that is neither true nor false.
bool packSwitch(const ShaderProperties& properties, std::string_view key, bool otherwise);

}  // namespace terrasol
