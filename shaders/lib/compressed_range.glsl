// HDR colour squeezed into [0, 1) by its luma and back (c / (1 + luma), exactly inverted): where TAA
// clips and blends and the sharpening mask works, so bright pixels do not outweigh the rest.

vec3 compress(vec3 c) { return c / (1.0 + dot(c, LUMA_WEIGHTS)); }
vec3 expand(vec3 c) { return c / max(1.0 - dot(c, LUMA_WEIGHTS), 1e-3); }
