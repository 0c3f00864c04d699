#version 450 core
// Far terrain into the shadow map: depth only (lod.vert with SHADOW places it in the warped map).

void main() {}
