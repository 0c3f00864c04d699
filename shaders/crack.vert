#version 450 core
// The twelve triangles of a box's faces from gl_VertexID (no vertex buffer), counter-clockwise seen
// from outside. Corner c has x from bit 0, y from bit 1, z from bit 2.

uniform mat4 u_viewProjection;  // camera-relative, as the G-buffer was drawn
uniform vec3 u_boxMin, u_boxMax;  // the box, camera-relative

const int kCorners[36] = int[](0, 4, 6, 0, 6, 2,   // -x
                               1, 3, 7, 1, 7, 5,   // +x
                               0, 1, 5, 0, 5, 4,   // -y
                               2, 6, 7, 2, 7, 3,   // +y
                               0, 2, 3, 0, 3, 1,   // -z
                               4, 5, 7, 4, 7, 6);  // +z

void main() {
  int c = kCorners[gl_VertexID];
  vec3 p = vec3((c & 1) != 0 ? u_boxMax.x : u_boxMin.x, (c & 2) != 0 ? u_boxMax.y : u_boxMin.y,
                (c & 4) != 0 ? u_boxMax.z : u_boxMin.z);
  gl_Position = u_viewProjection * vec4(p, 1.0);
}
