#include "mesh/model_light.h"

#include <algorithm>
#include <cmath>

#include "mesh/mesh_tables.h"

namespace terrasol {

void interpolateModelLight(const ModelQuad& m, const std::uint32_t (&corner)[4], std::uint32_t (&light)[4]) {
  float block[4], sky[4], ao[4];
  for (int c = 0; c < 4; ++c) {
    const float cells = static_cast<float>((corner[c] >> 12 & 3) + 1);
    block[c] = static_cast<float>(corner[c] & 63) / cells;
    sky[c] = static_cast<float>(corner[c] >> 6 & 63) / cells;
    ao[c] = cells - 1.0f;
  }
  const mesh_tables::FaceFrame& f = mesh_tables::kFaces[static_cast<std::size_t>(m.face)];
  for (std::size_t v = 0; v < 4; ++v) {
    const auto& p = m.corners32[v];
    // The vertex on the face, -1..1 along its tangent and up.
    const float s =
        static_cast<float>(f.t.x * (p[0] - 16) + f.t.y * (p[1] - 16) + f.t.z * (p[2] - 16)) / 16.0f;
    const float r =
        static_cast<float>(f.b.x * (p[0] - 16) + f.b.y * (p[1] - 16) + f.b.z * (p[2] - 16)) / 16.0f;
    float b = 0.0f, k = 0.0f, o = 0.0f;
    for (int c = 0; c < 4; ++c) {
      const float w = (1.0f + static_cast<float>(kCornerSigns[c][0]) * s) *
                      (1.0f + static_cast<float>(kCornerSigns[c][1]) * r) * 0.25f;
      b += w * block[c];
      k += w * sky[c];
      o += w * ao[c];
    }
    const int own = m.ownOcclusion[v];
    const int occlusion = std::min(static_cast<int>(std::lround(o)), own == 2 ? 0 : 3 - own);
    const float cells = static_cast<float>(occlusion + 1);
    light[v] = PackedVertex::kBlockLight.pack(static_cast<int>(std::lround(b * cells))) |
               PackedVertex::kSkyLight.pack(static_cast<int>(std::lround(k * cells))) |
               PackedVertex::kAo.pack(occlusion);
  }
}

}  // namespace terrasol
