#version 450 core
// Depth only: the reflection pass's first draw of the translucent quads, so the march drawn over them
// next (GL_LEQUAL) runs once per pixel, on the nearest.

void main() {}
