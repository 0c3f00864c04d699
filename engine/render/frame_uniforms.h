#pragma once
// Uniforms that several passes set alike: the light and lightmap (lit passes), the sky and fog, the
// shadow lookup (lib/shadow.glsl) and the shadow warp.

#include "render/frame.h"

namespace terrasol {

// Direct light, ambient tint, lightmap, and with `shadow.settings->enabled` the shadow lookup.
void setLightingUniforms(GLuint program, const FrameView& view, const ShadowLookup& shadow);
// The sky and the fog that fades distant surfaces into it (lighting, sky and translucent).
void setSkyUniforms(GLuint program, const FrameView& view);
// `live`: the map shows this frame's light (else the lookup is lit everywhere).
void setShadowUniforms(GLuint program, const ShadowLookup& shadow, bool live);
// The reflected rays' march (lib/ssr.glsl) and the smoothness they fade in from.
void setSsrUniforms(GLuint program, const FrameView& view, const ReflectionSettings& settings);
// Water's waves (lib/waves.glsl): their phase in world time and their origin.
void setWaveUniforms(GLuint program, const FrameInputs& inputs);
// Cascades are never warped.
void setWarpUniforms(GLuint program, const ShadowSettings& settings);

}  // namespace terrasol
