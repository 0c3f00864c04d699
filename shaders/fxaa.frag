#version 450 core
// FXAA (Lottes' fast approximate anti-aliasing, the 3.11 "quality" idea in a short form) over the final
// image: where the luma around a pixel changes sharply, find the edge's direction and its ends along
// it, and blend the pixel with its neighbour across the edge by how far it lies from the nearer end,
// or by how much it stands out of its neighbourhood (sub-pixel specks). Runs on the display-encoded
// image, as FXAA expects. Whole-texel fetches only: filtered lookups cost far more on llvmpipe.

layout(binding = 0) uniform sampler2D u_image;  // sRGB-encoded, tone mapped

layout(location = OUT_COLOR) out vec4 o_color;

const float kEdgeThreshold = 0.125;      // relative luma range below which nothing is done
const float kEdgeThresholdMin = 0.0312;  // absolute, for dark regions
const float kSubpixel = 0.75;            // how much isolated specks are softened
const int kSearchSteps = 6;
const int kSearchStep[kSearchSteps] = int[](1, 1, 2, 2, 4, 8);

ivec2 g_last;  // the last texel

vec3 texel(ivec2 p) { return texelFetch(u_image, clamp(p, ivec2(0), g_last), 0).rgb; }
float lumaAt(ivec2 p) { return dot(texel(p), LUMA_WEIGHTS); }

void main() {
  g_last = textureSize(u_image, 0) - 1;
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 centre = texel(p);
  float m = dot(centre, LUMA_WEIGHTS);
  float n = lumaAt(p + ivec2(0, 1)), s = lumaAt(p - ivec2(0, 1));
  float e = lumaAt(p + ivec2(1, 0)), w = lumaAt(p - ivec2(1, 0));
  float highest = max(max(max(n, s), max(e, w)), m);
  float lowest = min(min(min(n, s), min(e, w)), m);
  float range = highest - lowest;
  if (range < max(kEdgeThresholdMin, highest * kEdgeThreshold)) {
    o_color = vec4(centre, 1.0);
    return;
  }
  float ne = lumaAt(p + ivec2(1, 1)), nw = lumaAt(p + ivec2(-1, 1));
  float se = lumaAt(p + ivec2(1, -1)), sw = lumaAt(p - ivec2(1, 1));

  // Sub-pixel: how far the centre stands out of the 3x3 average.
  float average = (2.0 * (n + s + e + w) + ne + nw + se + sw) / 12.0;
  float speck = smoothstep(0.0, 1.0, clamp(abs(average - m) / range, 0.0, 1.0));
  float subpixelBlend = speck * speck * kSubpixel;

  // The edge runs along x when luma changes most from row to row.
  float rows = abs(nw + sw - 2.0 * w) + 2.0 * abs(n + s - 2.0 * m) + abs(ne + se - 2.0 * e);
  float columns = abs(nw + ne - 2.0 * n) + 2.0 * abs(w + e - 2.0 * m) + abs(sw + se - 2.0 * s);
  bool alongX = rows >= columns;
  ivec2 along = alongX ? ivec2(1, 0) : ivec2(0, 1);
  ivec2 across = alongX ? ivec2(0, 1) : ivec2(1, 0);
  float positive = alongX ? n : e, negative = alongX ? s : w;
  float gradient = abs(positive - m), opposite = positive;
  if (abs(negative - m) > gradient) {
    across = -across;
    gradient = abs(negative - m);
    opposite = negative;
  }

  // Walk both ways along the edge (the average of the pixel's row and the one across) until its luma
  // leaves the edge's.
  float edgeLuma = 0.5 * (m + opposite);
  float scaled = 0.25 * gradient;
  int up = 0, down = 0;
  float endUp = 0.0, endDown = 0.0;
  bool doneUp = false, doneDown = false;
  for (int i = 0; i < kSearchSteps && !(doneUp && doneDown); ++i) {
    if (!doneUp) {
      up += kSearchStep[i];
      endUp = 0.5 * (lumaAt(p + along * up) + lumaAt(p + across + along * up)) - edgeLuma;
      doneUp = abs(endUp) >= scaled;
    }
    if (!doneDown) {
      down += kSearchStep[i];
      endDown = 0.5 * (lumaAt(p - along * down) + lumaAt(p + across - along * down)) - edgeLuma;
      doneDown = abs(endDown) >= scaled;
    }
  }
  // Pixel centres lie half a texel inside the walk's ends.
  float distanceUp = float(up) - 0.5, distanceDown = float(down) - 0.5;
  bool upNearer = distanceUp < distanceDown;
  float nearest = min(distanceUp, distanceDown);
  // Blend only when the nearer end's luma changes the other way than the centre's (a real end).
  bool rightEnd = ((upNearer ? endUp : endDown) < 0.0) != (m - edgeLuma < 0.0);
  float edgeBlend = rightEnd ? 0.5 - nearest / (distanceUp + distanceDown) : 0.0;
  float blend = max(edgeBlend, subpixelBlend);
  o_color = vec4(mix(centre, texel(p + across), blend), 1.0);
}
