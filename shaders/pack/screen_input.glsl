#version 450 core
// A shader pack's vertex inputs for a full-screen pass (deferred, composite, final): the quad OptiFine
// draws, corners in [0,1]^2 as both position and UV, drawn as a four-vertex strip. Spliced after the
// rewrite's declarations (engine/shaderpack/glsl_rewriter.h).

#include "pack/lib/flat_inputs.glsl"

void tsol_readVertex() {
  vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
  tsol_Vertex = vec4(corner, 0.0, 1.0);
  tsol_Normal = vec3(0.0, 0.0, 1.0);
  tsol_Color = vec4(1.0);
  tsol_MultiTexCoord0 = vec4(corner, 0.0, 1.0);
  tsol_readFlatInputs();
}
