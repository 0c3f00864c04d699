#pragma once
// Every C++ constant the renderer's shaders use, as #defines for the preprocessor: binding slots,
// the G-buffer layout, the packed vertex's fields and the mesher's face bases, LabPBR's predefined
// metals, tints, debug views, the sky's radiance and the luma weights. Shaders never copy a number
// by hand.

#include <vector>

#include "assets/shader_source.h"

namespace terrasol {

std::vector<ShaderDefine> rendererDefines();

}  // namespace terrasol
