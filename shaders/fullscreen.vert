#version 450 core
// One triangle covering the screen; no vertex buffer (draw 3 vertices with an empty vertex array).
// It lies on the far plane (depth 1), where the lighting and sky draws' depth tests split the screen
// into pixels something was drawn on and sky.

out vec2 v_ndc;

void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);  // (0,0) (2,0) (0,2)
  v_ndc = corner * 2.0 - 1.0;
  gl_Position = vec4(v_ndc, 1.0, 1.0);
}
