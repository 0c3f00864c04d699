#pragma once
// A pack's settings from its programs' `const` directives (OptiFine shaders.txt "Constants", "Color
// attachments", "Texture formats"): the sixteen colour buffers' formats, clears and clear colours, the
// shadow map's resolution, distance and filtering, the sun path's rotation, the noise texture's size,
// the half-lives. Read from every program the pack has in the frame's order, a later one overriding
// an earlier one, as a pack declares each once where it likes. GL-free: formats are names the
// renderer maps onto GL's.

#include <array>
#include <glm/vec4.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shaderpack/pack_directives.h"

namespace terrasol {

// One of OptiFine's buffer formats ("RGBA16F", "R11F_G11F_B10F", ...).
struct PackFormat {
  std::string_view name;
  int channels;
  enum class Kind { Unorm, Snorm, Float, Int, Uint, Packed } kind;
};
// Nothing for a name OptiFine does not list.
std::optional<PackFormat> packFormat(std::string_view name);

struct PackBuffer {
  PackFormat format = *packFormat("RGBA8");
  bool clear = true;
  // Nothing: colortex0 is cleared to the fog colour (alpha 1), colortex1 to 1, the rest to 0.
  std::optional<glm::vec4> clearColor;
  bool mipmap = false;  // some program asks for its mipmaps (colortexNMipmapEnabled)
};

struct PackSettings {
  std::array<PackBuffer, kPackColorBuffers> buffers;
  int shadowMapResolution = 1024;
  float shadowDistance = 160.0f;
  float shadowIntervalSize = 2.0f;
  // The pack's const, degrees; without one Terrasol keeps its world's (the renderer decides).
  std::optional<float> sunPathRotation;
  int noiseTextureResolution = 256;
  bool shadowHardwareFiltering = false;
  std::array<bool, 2> shadowtexNearest{false, false};
  std::array<bool, 2> shadowcolorNearest{false, false};
  float eyeBrightnessHalflife = 10.0f;  // ticks
  float ambientOcclusionLevel = 1.0f;
};

// `directives` of the pack's programs in the frame's order. Throws Error naming `pack` for a format
// OptiFine does not list or a clear colour that is not a vec4 of numbers.
PackSettings packSettings(const std::vector<ProgramDirectives>& directives, const std::string& pack);

}  // namespace terrasol
