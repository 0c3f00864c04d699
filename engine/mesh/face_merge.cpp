#include "mesh/face_merge.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/assert.h"
#include "core/model_units.h"
#include "world/coords.h"

namespace terrasol {
namespace {

// Per face (Direction order): the axis of the normal, of the tangent (u) and of up (v), and whether
// tangent and up point along their axis or against it.
struct Axes {
  int n, t, b;
  bool tAlong, bAlong;
};
constexpr int axisOf(const float (&v)[3]) {
  return v[0] != 0.0f ? 0 : v[1] != 0.0f ? 1 : 2;
}
constexpr auto kAxes = [] {
  std::array<Axes, 6> axes{};
  for (int d = 0; d < 6; ++d) {
    const FaceBasis& f = kFaceBases[d];
    const int t = axisOf(f.tangent), b = axisOf(f.up);
    axes[static_cast<std::size_t>(d)] = {axisOf(f.normal), t, b, f.tangent[t] > 0.0f, f.up[b] > 0.0f};
  }
  return axes;
}();

int coordinate(const PackedVertex& v, int axis) {
  return axis == 0 ? v.x32() : axis == 1 ? v.y32() : v.z32();
}

// The UV the mesher gives corner c of a full face, and a merged quad w x h faces across.
std::uint32_t cornerUv(int c, int w, int h) {
  return PackedVertex::packUv(kCornerSigns[c][0] > 0 ? kModelUnits * w : 0,
                              kCornerSigns[c][1] > 0 ? 0 : kModelUnits * h);
}

// A face that can merge, where it lies: its plane (face and height along the normal) and its cell in
// the plane, along the tangent's and up's axes.
struct Candidate {
  int plane, i, j;
  std::uint32_t quad;
};

// The tint's blue, which shares the uv word (the light word holds the rest of the tint).
int tintBlue(const PackedVertex& v) {
  return PackedVertex::kTintBlue.get(v.uv);
}

// A full block face (1 x 1 in its plane, corners in the mesher's order) with one light and tint at
// all corners.
bool candidate(const PackedVertex* q, Candidate& out) {
  const int face = q[0].face();
  if (face >= 6 || q[1].light != q[0].light || q[2].light != q[0].light || q[3].light != q[0].light)
    return false;
  const Axes& a = kAxes[static_cast<std::size_t>(face)];
  const int height = coordinate(q[0], a.n);
  int tMin = coordinate(q[0], a.t), bMin = coordinate(q[0], a.b);
  for (int c = 1; c < 4; ++c) {
    tMin = std::min(tMin, coordinate(q[c], a.t));
    bMin = std::min(bMin, coordinate(q[c], a.b));
  }
  // On the section's 16 x 16 grid of cells: a model's face can lie beyond its block, past the grid.
  if (tMin % 32 != 0 || bMin % 32 != 0 || tMin >= 16 * 32 || bMin >= 16 * 32) return false;
  for (int c = 0; c < 4; ++c) {
    const bool tHigh = (kCornerSigns[c][0] > 0) == a.tAlong, bHigh = (kCornerSigns[c][1] > 0) == a.bAlong;
    if (q[c].material != q[0].material || (q[c].uv & PackedVertex::kUvBits) != cornerUv(c, 1, 1) ||
        tintBlue(q[c]) != tintBlue(q[0]) || coordinate(q[c], a.n) != height ||
        coordinate(q[c], a.t) != tMin + (tHigh ? 32 : 0) ||
        coordinate(q[c], a.b) != bMin + (bHigh ? 32 : 0)) {
      return false;
    }
  }
  out.plane = face * 1024 + height;
  out.i = tMin / 32;
  out.j = bMin / 32;
  return true;
}

}  // namespace

std::size_t mergeFaces(PackedVertices& quads) {
  TERRASOL_ASSERT(quads.size() % 4 == 0,
                  "face merge: " + std::to_string(quads.size()) + " vertices are not whole quads");
  // Out, in this order: quads both views draw, faces that merged (the light's view), merged quads.
  // Per thread and kept between calls, like the mesher's writers: no allocation once warm.
  thread_local PackedVertices both, faces, merged;
  thread_local std::vector<Candidate> candidates;
  both.clear();
  faces.clear();
  merged.clear();
  candidates.clear();
  const auto append = [](PackedVertices& to, const PackedVertex* q, QuadRole role) {
    for (int c = 0; c < 4; ++c) {
      PackedVertex v = q[c];
      v.setRole(role);
      to.push_back(v);
    }
  };
  for (std::size_t k = 0; k < quads.size() / 4; ++k) {
    Candidate c;
    if (candidate(&quads[k * 4], c)) {
      c.quad = static_cast<std::uint32_t>(k);
      candidates.push_back(c);
    } else {
      append(both, &quads[k * 4], QuadRole::Both);
    }
  }
  if (candidates.size() < 2) return 0;
  // By plane, then row by row: each plane's candidates are visited in the grid's order.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.plane != b.plane ? a.plane < b.plane : a.j != b.j ? a.j < b.j : a.i < b.i;
  });

  constexpr std::uint32_t kNone = ~0u;
  // Quad per cell of one plane, kNone where none is (left): every quad placed is taken out again, so
  // the grid is empty between planes.
  std::array<std::uint32_t, kChunkArea> grid;
  grid.fill(kNone);
  const auto cell = [](int i, int j) { return static_cast<std::size_t>(j * kChunkSize + i); };
  const auto at = [&](int i, int j) { return grid[cell(i, j)]; };
  std::size_t facesMerged = 0;
  for (std::size_t first = 0, last = 0; first < candidates.size(); first = last) {
    for (; last < candidates.size() && candidates[last].plane == candidates[first].plane; ++last) {
      TERRASOL_ASSERT(candidates[last].i < kChunkSize && candidates[last].j < kChunkSize,
                      "face merge: a face off the grid");
      grid[cell(candidates[last].i, candidates[last].j)] = candidates[last].quad;
    }
    const Axes& a = kAxes[static_cast<std::size_t>(candidates[first].plane / 1024)];
    for (std::size_t k = first; k < last; ++k) {
      const int i = candidates[k].i, j = candidates[k].j;
      const std::uint32_t q = at(i, j);
      if (q == kNone) continue;  // taken by a rectangle already
      const auto same = [&](int x, int y) {
        const std::uint32_t r = at(x, y);
        return r != kNone && quads[r * 4].material == quads[q * 4].material &&
               quads[r * 4].light == quads[q * 4].light && tintBlue(quads[r * 4]) == tintBlue(quads[q * 4]);
      };
      // The widest run along i, then as many rows of it along j as match whole.
      int w = 1, h = 1;
      while (i + w < kChunkSize && same(i + w, j)) ++w;
      const auto rowMatches = [&](int y) {
        for (int x = i; x < i + w; ++x)
          if (!same(x, y)) return false;
        return true;
      };
      while (j + h < kChunkSize && rowMatches(j + h)) ++h;
      if (w * h == 1) {
        append(both, &quads[q * 4], QuadRole::Both);
        grid[cell(i, j)] = kNone;
        continue;
      }
      PackedVertex out[4];
      for (int c = 0; c < 4; ++c) {
        // Corner c of the merged quad is corner c of the face in that corner of the rectangle.
        const int ci = (kCornerSigns[c][0] > 0) == a.tAlong ? i + w - 1 : i;
        const int cj = (kCornerSigns[c][1] > 0) == a.bAlong ? j + h - 1 : j;
        out[c] = quads[at(ci, cj) * 4 + static_cast<std::uint32_t>(c)];
        out[c].uv = (out[c].uv & ~PackedVertex::kUvBits) | cornerUv(c, w, h);
      }
      append(merged, out, QuadRole::Merged);
      for (int y = j; y < j + h; ++y)
        for (int x = i; x < i + w; ++x) {
          append(faces, &quads[at(x, y) * 4], QuadRole::Faces);
          grid[cell(x, y)] = kNone;
        }
      facesMerged += static_cast<std::size_t>(w * h);
    }
  }
  quads.resize(both.size() + faces.size() + merged.size());
  auto to = std::copy(both.begin(), both.end(), quads.begin());
  to = std::copy(faces.begin(), faces.end(), to);
  std::copy(merged.begin(), merged.end(), to);
  return facesMerged;
}

}  // namespace terrasol
