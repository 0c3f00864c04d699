// LabPBR 1.3 decoding, the same rules as engine/assets/labpbr.cpp (the reference);
// tests/gl/glsl_reference_test.cpp runs these on every texel value against it.

// _n: rg = normal xy in LabPBR's DirectX convention (green points down the texture), b = AO.
// Returns the tangent-space normal with +y up the texture and z >= 0; |xy| > 1 lands on the rim.
vec3 labpbrNormal(vec4 texel) {
  vec2 xy = texel.rg * 2.0 - 1.0;
  // 8 bits cannot hold the centre (127.5): 127 and 128 both mean flat, exactly, as a pack's
  // default _n (127, 127) and NO_NORMAL_MAPS's vertex normal do.
  xy = mix(xy, vec2(0.0), lessThan(abs(xy), vec2(1.5 / 255.0)));
  xy.y = -xy.y;
  float xy2 = dot(xy, xy);
  if (xy2 > 1.0) return vec3(xy * inversesqrt(xy2), 0.0);
  return vec3(xy, sqrt(1.0 - xy2));
}

struct Material {
  float smoothness;
  float roughness;  // (1 - smoothness)^2
  vec3 f0;
  bool metal;       // G >= 230: no diffuse
  float emission;   // 0..1; alpha 255 means none
};

// `spec` is the raw _s texel, `albedo` linear.
Material labpbrMaterial(vec4 spec, vec3 albedo) {
  Material m;
  m.smoothness = spec.r;
  m.roughness = (1.0 - spec.r) * (1.0 - spec.r);
  int g = int(spec.g * 255.0 + 0.5);
  m.metal = g >= 230;
  const vec3 metals[8] = LABPBR_METAL_F0;
  m.f0 = g <= 229 ? vec3(float(g) / 255.0) : g <= 237 ? metals[g - 230] : albedo;
  int a = int(spec.a * 255.0 + 0.5);
  m.emission = a == 255 ? 0.0 : float(a) / 254.0;
  return m;
}
