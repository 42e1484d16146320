// Bounding box of drawn 2D points (double, for pictures only; nothing is decided from it).
#pragma once
#include <algorithm>
#include <array>
#include <limits>

namespace symmesh::io::detail {

struct PlotBox {
  double minx = std::numeric_limits<double>::max(), miny = minx;
  double maxx = std::numeric_limits<double>::lowest(), maxy = maxx;
  void add(const std::array<double, 2>& p) {
    minx = std::min(minx, p[0]);
    miny = std::min(miny, p[1]);
    maxx = std::max(maxx, p[0]);
    maxy = std::max(maxy, p[1]);
  }
  double span_x() const { return maxx - minx; }
  double span_y() const { return maxy - miny; }
};

} // namespace symmesh::io::detail
