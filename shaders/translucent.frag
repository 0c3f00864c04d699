#version 450 core
// Translucent pass: water and glass, lit forward with the deferred pass's lighting and blended over
// the lit scene (premultiplied alpha: blend ONE, ONE_MINUS_SRC_ALPHA).

#include "lib/block_surface.glsl"
#include "lib/lighting.glsl"

layout(location = OUT_COLOR) out vec4 o_color;

void main() {
  vec4 albedo = texture(u_atlasAlbedo, v_uv);
  vec4 normalTexel = texture(u_atlasNormal, v_uv);
  Surface s;
  s.albedo = albedo.rgb * v_tint * vertexAo();
  s.normal = mappedNormal(normalTexel);
  s.vertexNormal = vertexNormal();
  s.spec = texture(u_atlasSpecular, v_uv);
  s.blockLight = v_light.x;
  s.skyLight = v_light.y;
  s.materialAo = normalTexel.b;
  vec3 toViewer = -v_position / max(length(v_position), 1e-6);
  vec3 lit = shade(s, toViewer);
  o_color = vec4(lit * albedo.a, albedo.a);
}
