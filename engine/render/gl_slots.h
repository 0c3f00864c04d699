#pragma once
// Binding points shared by C++ and GLSL. Shaders see them only as injected #defines (slotDefines()),
// never as numbers copied by hand.

#include <vector>

#include "assets/shader_source.h"

namespace terrasol::slots {

// Vertex attribute locations.
inline constexpr int kAttribPosition = 0;
inline constexpr int kAttribNormal = 1;
inline constexpr int kAttribColor = 2;

// Fragment outputs of the forward test-scene pass.
inline constexpr int kOutColor = 0;

}  // namespace terrasol::slots

namespace terrasol {

// ATTRIB_POSITION, ATTRIB_NORMAL, ... for the preprocessor.
std::vector<ShaderDefine> slotDefines();

}  // namespace terrasol
