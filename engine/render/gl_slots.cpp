#include "render/gl_slots.h"

#include <string>

namespace terrasol {

std::vector<ShaderDefine> slotDefines() {
  auto define = [](const char* name, int value) { return ShaderDefine{name, std::to_string(value)}; };
  return {
      define("ATTRIB_POSITION", slots::kAttribPosition),
      define("ATTRIB_NORMAL", slots::kAttribNormal),
      define("ATTRIB_COLOR", slots::kAttribColor),
      define("OUT_COLOR", slots::kOutColor),
  };
}

}  // namespace terrasol
