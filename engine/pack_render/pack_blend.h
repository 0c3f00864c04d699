#pragma once
// A pack program's blending on the GL context: shaders.properties' blend.<program> where the pack sets
// it, else the program's default (vanilla's translucent blend for water, added light for the sun and
// moon, none for the rest). GL thread only.

#include <array>

#include "render/gl/object.h"
#include "shaderpack/pack_draw_state.h"

namespace terrasol {

using BlendFactors = std::array<GLenum, 4>;  // src, dst, srcAlpha, dstAlpha

inline constexpr BlendFactors kTranslucentBlend = {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE,
                                                   GL_ONE_MINUS_SRC_ALPHA};
inline constexpr BlendFactors kAddedBlend = {GL_SRC_ALPHA, GL_ONE, GL_ONE, GL_ZERO};

// Blending as `state` says, else `fallback`, or none when `fallback` is null.
void applyBlend(const PackDrawState& state, const BlendFactors* fallback);

}  // namespace terrasol
