#pragma once
// Every C++ constant the renderer's shaders use, as #defines for the preprocessor: binding slots,
// the G-buffer layout, the mesher's face bases and LabPBR's predefined metals. Shaders never copy a
// number by hand.

#include <vector>

#include "assets/shader_source.h"

namespace terrasol {

std::vector<ShaderDefine> rendererDefines();

}  // namespace terrasol
