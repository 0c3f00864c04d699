#pragma once
// A small scatter plot drawn straight into an image (no plotting library in Debian's C++ set): axes
// with numbered ticks, points coloured by group, and a polyline through the marked points.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "assets/image.h"

namespace terrasol {

struct PlotPoint {
  double x, y;
  int group;    // colour index
  bool marked;  // on the highlighted polyline (sorted by x)
};

// `xLabel`/`yLabel` use digits, letters a-z, space and ".%+-/()".
Image scatterPlot(const std::vector<PlotPoint>& points, const std::string& xLabel, const std::string& yLabel,
                  const std::vector<std::string>& groupNames, int width = 800, int height = 500);

}  // namespace terrasol
