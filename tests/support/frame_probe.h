#pragma once
// Reading a rendered frame at a world point: where the point lands in the image and the colour there.

#include <algorithm>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>

#include "scene_render/scene_render.h"

namespace terrasol::testing {

// The colour (0..1, a 3x3 mean) where world point `world` lands in the frame's image.
inline glm::vec3 colourAt(const RenderedFrame& frame, glm::dvec3 world) {
  const glm::vec4 clip =
      frame.geometry.viewProjection * glm::vec4(glm::vec3(world - frame.geometry.camera), 1.0f);
  const int w = frame.image.width, h = frame.image.height;
  const int x = static_cast<int>((clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(w));
  const int y = static_cast<int>((0.5f - clip.y / clip.w * 0.5f) * static_cast<float>(h));
  glm::vec3 sum(0.0f);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const std::uint8_t* p = frame.image.pixel(std::clamp(x + dx, 0, w - 1), std::clamp(y + dy, 0, h - 1));
      sum += glm::vec3(p[0], p[1], p[2]) / 255.0f;
    }
  return sum / 9.0f;
}

// Why the frame left `pass` out, or "(ran)".
inline std::string skipReason(const RenderedFrame& frame, const std::string& pass) {
  for (const FrameStats::Skipped& s : frame.stats.passesSkipped) {
    if (s.pass == pass) return s.why;
  }
  return "(ran)";
}

inline float brightness(glm::vec3 c) {
  return c.r + c.g + c.b;
}

// Frame 0 of `scene`, its float targets read back and checked for NaN and Inf.
inline RenderedFrame measuredFrame(const SceneFile& scene) {
  SceneRenderer renderer(scene);
  FrameRequest request;
  request.readBack = true;
  request.checkNan = true;
  return renderer.renderFrame(0, request);
}

// Pixel (x, y) of the read-back targets (row 0 at the bottom) as a camera-relative point at `depth`
// (1: on the far plane).
inline glm::dvec3 pixelPoint(const RenderedFrame& f, int x, int y, float depth) {
  const glm::ivec2 size = f.pixels.size;
  const glm::vec4 ndc((static_cast<float>(x) + 0.5f) / static_cast<float>(size.x) * 2.0f - 1.0f,
                      (static_cast<float>(y) + 0.5f) / static_cast<float>(size.y) * 2.0f - 1.0f,
                      depth * 2.0f - 1.0f, 1.0f);
  const glm::vec4 p = f.geometry.inverseViewProjection * ndc;
  return glm::dvec3(p) / static_cast<double>(p.w);
}

}  // namespace terrasol::testing
