#pragma once
// Block models (Minecraft's JSON models) measure positions and texture coordinates in 1/16 of a
// block or of a texture, texels of a 16-pixel texture.

namespace terrasol {

inline constexpr int kModelUnits = 16;  // model units per block, and per texture side

}  // namespace terrasol
