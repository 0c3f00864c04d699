#pragma once
// Minecraft's crack over a block being dug: a pack's textures/block/destroy_stage_0.png .. _9.png,
// one per tenth of the digging, multiplied over the block's faces.

#include <string>

namespace terrasol {

inline constexpr int kCrackStages = 10;

// The stage's block texture name (as the atlas knows it).
inline std::string crackTextureName(int stage) {
  return "destroy_stage_" + std::to_string(stage);
}

}  // namespace terrasol
