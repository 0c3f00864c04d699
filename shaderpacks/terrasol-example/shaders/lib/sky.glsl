// The sky's colour in a view direction: Minecraft's sky colour overhead fading to its fog colour at
// the horizon, as linear light.

uniform vec3 skyColor;
uniform vec3 fogColor;
uniform mat4 gbufferModelView;

vec3 toLinear(vec3 srgb) { return pow(srgb, vec3(2.2)); }

vec3 skyAt(vec3 viewDirection) {
  float up = max(dot(viewDirection, gbufferModelView[1].xyz), 0.0);
  float horizon = 0.25 / (up * up + 0.25);
  return toLinear(mix(skyColor, fogColor, horizon));
}
