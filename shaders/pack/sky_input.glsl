#version 450 core
// A shader pack's vertex inputs for the sky, sun and moon (engine/pack_render/pack_sky.h): position
// in player space, colour and UV from a small vertex buffer. Spliced after the rewrite's declarations
// (engine/shaderpack/glsl_rewriter.h).

#include "pack/lib/flat_inputs.glsl"

layout(location = ATTRIB_POSITION) in vec3 tsol_skyPosition;
layout(location = ATTRIB_COLOR) in vec4 tsol_skyColor;
layout(location = ATTRIB_UV) in vec2 tsol_skyUv;

void tsol_readVertex() {
  tsol_Vertex = vec4(tsol_skyPosition, 1.0);
  tsol_Normal = vec3(0.0, 1.0, 0.0);
  tsol_Color = tsol_skyColor;
  tsol_MultiTexCoord0 = vec4(tsol_skyUv, 0.0, 1.0);
  tsol_readFlatInputs();
}
