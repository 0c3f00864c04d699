#pragma once
// Loads the block textures a game needs from a PackStack: the base image (split into frames when
// animated), its _n and _s companions from the same pack (defaults when absent, resampled to the
// base's frame size when they differ), and every problem found, named by file.

#include <string>
#include <vector>

#include "assets/image.h"
#include "assets/resource_pack.h"
#include "assets/texture_meta.h"

namespace terrasol {

struct PackProblem {
  enum class Severity { Warning, Error } severity;
  std::string message;  // "FILE: what is wrong"
};

struct LoadedTexture {
  std::string name;      // the name asked for (first candidate)
  std::string source;    // the file it came from, or "" when missing
  bool missing = false;  // shown as the magenta/black "missing" texture
  bool openGlNormals = false;
  std::optional<Animation> animation;
  // One image per strip frame, all the same size.
  std::vector<Image> albedo, normal, specular;
  bool hasNormalMap = false, hasSpecularMap = false;
};

// Largest texture side accepted from a pack (a 512x strip of frames may be taller).
inline constexpr ImageLimits kTextureLimits{16384, std::int64_t{1} << 24};

// `candidates`: texture names to try in order, e.g. {"short_grass", "grass"}. Never throws for bad
// pack content: problems go to `problems`, and the texture falls back to "missing".
LoadedTexture loadBlockTexture(const PackStack& packs, const std::vector<std::string>& candidates,
                               std::vector<PackProblem>& problems);

// The magenta/black checkerboard Minecraft shows for a texture it cannot find.
Image missingTexture(int size = 16);

}  // namespace terrasol
