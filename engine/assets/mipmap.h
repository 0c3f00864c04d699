#pragma once
// Halving an image (both sides even) for each kind of atlas, keeping the data meaningful:
//   albedo:   averaged in linear light, weighted by alpha (transparent texels lend no colour);
//   normal:   decoded vectors averaged and renormalised, AO and height averaged (LabPBR _n);
//   specular: LabPBR _s rules: smoothness averaged; F0 averaged only among dielectric values
//             (a metal id never blends, the majority wins); porosity and subsurface averaged within
//             their own range; emission averaged unless the block is mostly "none" (255).
// preserveCoverage() then rescales a cutout's alpha so the share of texels that pass the alpha test
// stays what it was at full size (leaves do not thin out in the distance).

#include "assets/image.h"

namespace terrasol::mip {

Image halveAlbedo(const Image& src);
Image halveNormal(const Image& src);
Image halveSpecular(const Image& src);

struct Rect {
  int x, y, w, h;
};

// Share of texels in `rect` with alpha >= 128.
double coverage(const Image& image, const Rect& rect);
// Scales alpha over `apply` so that the coverage of `measure` comes as close as possible to `target`.
void preserveCoverage(Image& image, const Rect& measure, const Rect& apply, double target);

}  // namespace terrasol::mip
