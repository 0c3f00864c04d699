#include "render/cave_culling.h"

#include <cmath>
#include <deque>
#include <glm/vec2.hpp>

namespace terrasol {
namespace {

constexpr glm::ivec3 kSteps[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
constexpr int kDown = 2, kUp = 3;

struct Step {
  glm::ivec3 at;       // section x, index, z
  int entered;         // the face it was entered through, -1 for the camera's
  unsigned travelled;  // directions taken from the camera (bit d): never go back against one
};

}  // namespace

SectionSet::SectionSet(glm::ivec2 centreChunk, int radius)
    : centre_(centreChunk),
      radius_(radius),
      side_(2 * radius + 1),
      cells_(static_cast<std::size_t>(side_ * side_ * kSectionCount), 0) {}

const std::uint8_t* SectionSet::cell(glm::ivec3 s) const {
  const int dx = s.x - centre_.x + radius_, dz = s.z - centre_.y + radius_;
  if (dx < 0 || dx >= side_ || dz < 0 || dz >= side_ || s.y < 0 || s.y >= kSectionCount) return nullptr;
  return &cells_[static_cast<std::size_t>((s.y * side_ + dz) * side_ + dx)];
}

SectionSet reachableSections(const SectionMeshes& meshes, glm::dvec3 camera, const FrustumPlanes& planes,
                             int radius) {
  const glm::ivec3 eye(static_cast<int>(std::floor(camera.x / 16.0)),
                       static_cast<int>(std::floor((camera.y - kMinY) / 16.0)),
                       static_cast<int>(std::floor(camera.z / 16.0)));
  SectionSet seen({eye.x, eye.z}, radius);
  const auto inView = [&](glm::ivec3 s) {
    const glm::dvec3 corner(s.x * 16.0, kMinY + s.y * 16.0, s.z * 16.0);
    return boxVisible(planes, glm::vec3(corner - camera), 16.0f);
  };

  std::deque<Step> queue;
  const auto reach = [&](glm::ivec3 s, int entered, unsigned travelled) {
    std::uint8_t* mark = seen.cell(s);
    if (!mark || *mark || !inView(s)) return;
    *mark = SectionSet::kMember;
    queue.push_back({s, entered, travelled});
  };
  if (eye.y >= 0 && eye.y < kSectionCount) {
    reach(eye, -1, 0u);
  } else {
    // Above or below the world: every section of the nearest layer, entered from outside.
    const bool above = eye.y >= kSectionCount;
    for (int dz = -radius; dz <= radius; ++dz)
      for (int dx = -radius; dx <= radius; ++dx) {
        reach({eye.x + dx, above ? kSectionCount - 1 : 0, eye.z + dz}, above ? kUp : kDown,
              1u << (above ? kDown : kUp));
      }
  }
  while (!queue.empty()) {
    const Step step = queue.front();
    queue.pop_front();
    const FaceLinks links = meshes.faceLinks({step.at.x, step.at.y, step.at.z});
    for (int d = 0; d < 6; ++d) {
      if (step.travelled & (1u << (d ^ 1))) continue;  // back towards the camera
      if (step.entered >= 0 && !linked(links, step.entered, d)) continue;
      reach(step.at + kSteps[d], d ^ 1, step.travelled | (1u << d));
    }
  }
  return seen;
}

SectionSet sectionsLitFrom(const SectionMeshes& meshes, glm::vec3 toLight, glm::dvec3 centre, int radius) {
  const glm::ivec3 mid(static_cast<int>(std::floor(centre.x / 16.0)), 0,
                       static_cast<int>(std::floor(centre.z / 16.0)));
  // Per section: the faces it has been entered by (bits 0..5), and kMember once it is reached.
  SectionSet entered({mid.x, mid.z}, radius);
  // The ways a ray moves: along each axis where -toLight has a component.
  unsigned along = 0;
  for (int d = 0; d < 6; ++d) {
    if (glm::dot(glm::vec3(kSteps[d]), -toLight) > 0.0f) along |= 1u << d;
  }
  std::deque<Step> queue;
  const auto enter = [&](glm::ivec3 s, int face) {
    std::uint8_t* mark = entered.cell(s);
    if (!mark || (*mark & (1u << face))) return;
    *mark |= static_cast<std::uint8_t>((1u << face) | SectionSet::kMember);
    queue.push_back({s, face, 0u});
  };
  // Rays come in through every face of the square's boundary that looks towards the light.
  for (int y = 0; y < kSectionCount; ++y)
    for (int dz = -radius; dz <= radius; ++dz)
      for (int dx = -radius; dx <= radius; ++dx) {
        const glm::ivec3 s(mid.x + dx, y, mid.z + dz);
        for (int d = 0; d < 6; ++d) {
          if (!(along & (1u << (d ^ 1))))
            continue;  // face d looks towards the light when rays move along d ^ 1
          if (!entered.cell(s + kSteps[d])) enter(s, d);
        }
      }
  while (!queue.empty()) {
    const Step step = queue.front();
    queue.pop_front();
    const FaceLinks links = meshes.faceLinks({step.at.x, step.at.y, step.at.z});
    for (int d = 0; d < 6; ++d) {
      if ((along & (1u << d)) && linked(links, step.entered, d)) enter(step.at + kSteps[d], d ^ 1);
    }
  }
  return entered;
}

}  // namespace terrasol
