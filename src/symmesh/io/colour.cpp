// Picture colours — spec/outputs.md#render
#include "symmesh/io/colour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace symmesh::io {
namespace {

using Rgb = std::array<double, 3>;

std::string hex(const Rgb& c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(std::lround(c[0] * 255)),
                int(std::lround(c[1] * 255)), int(std::lround(c[2] * 255)));
  return buf;
}

/// HSV to RGB with h in [0, 360).
Rgb from_hsv(double h, double s, double v) {
  const double c = v * s, hp = h / 60.0;
  const double x = c * (1 - std::fabs(std::fmod(hp, 2.0) - 1));
  static const int order[6][3] = {{0, 1, 2}, {1, 0, 2}, {2, 0, 1}, {2, 1, 0}, {1, 2, 0}, {0, 2, 1}};
  const int sector = std::min(5, int(hp));
  const double part[3] = {c, x, 0};
  Rgb out{};
  for (int k = 0; k < 3; ++k) out[std::size_t(k)] = part[order[sector][k]] + (v - c);
  return out;
}

} // namespace

std::string fill_colour(std::size_t k) {
  static const char* set3[] = {"#8dd3c7", "#ffffb3", "#bebada", "#fb8072", "#80b1d3",
                               "#fdb462", "#b3de69", "#fccde5", "#d9d9d9", "#bc80bd"};
  constexpr std::size_t n = sizeof set3 / sizeof set3[0];
  if (k < n) return set3[k];
  return hex(from_hsv(std::fmod(double(k - n) * 137.508, 360.0), 0.45, 0.95));
}

std::string ramp_colour(double t) {
  // Stops close to viridis at 0, 1/4, 1/2, 3/4, 1: ordered in lightness, readable in grey.
  static const Rgb stops[] = {{0.267, 0.005, 0.329},
                              {0.229, 0.322, 0.546},
                              {0.128, 0.567, 0.551},
                              {0.369, 0.789, 0.383},
                              {0.993, 0.906, 0.144}};
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  const double u = t * 4;
  const std::size_t k = std::min<std::size_t>(3, std::size_t(u));
  const double f = u - double(k);
  Rgb c{};
  for (std::size_t q = 0; q < 3; ++q) c[q] = stops[k][q] * (1 - f) + stops[k + 1][q] * f;
  return hex(c);
}

} // namespace symmesh::io
