#version 450 core
// The twelve edges of a box as 24 line vertices, made from gl_VertexID (no vertex buffer).
// Corner c has x from bit 0, y from bit 1, z from bit 2.

uniform mat4 u_viewProjection;  // camera-relative
uniform vec3 u_min, u_max;      // the box, camera-relative

const ivec2 kEdges[12] = ivec2[](ivec2(0, 1), ivec2(2, 3), ivec2(4, 5), ivec2(6, 7),   // along x
                                 ivec2(0, 2), ivec2(1, 3), ivec2(4, 6), ivec2(5, 7),   // along y
                                 ivec2(0, 4), ivec2(1, 5), ivec2(2, 6), ivec2(3, 7));  // along z

void main() {
  ivec2 edge = kEdges[gl_VertexID / 2];
  int c = (gl_VertexID & 1) == 0 ? edge.x : edge.y;
  vec3 p = vec3((c & 1) != 0 ? u_max.x : u_min.x, (c & 2) != 0 ? u_max.y : u_min.y, (c & 4) != 0 ? u_max.z : u_min.z);
  gl_Position = u_viewProjection * vec4(p, 1.0);
}
