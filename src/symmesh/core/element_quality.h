/// Definitions 2.12–2.14, 2.16, 2.17, 2.19, 2.20 (element quality) in exact form —
/// spec/definitions.md#quality-exact
///
/// Quality measures of simplices whose exact form is rational in the vertex coordinates: squared
/// lengths, squared relative volume (Gram determinant), squared circumradius, the squared cosine of
/// an angle with its sign, the squared radius-edge ratio, and the squared volume-length measure.
/// Comparisons of squares order the measures themselves (all are non-negative), so a quality
/// vector (Def 2.20) of squared scores sorts like the scores. The reports' floating-point values
/// (mesh/quality.h) are their square roots. Not here: the inradius and min-containment ball
/// (Def 2.15) and the radius ratio (Def 2.18) — they need facet areas, i.e. square roots.
#pragma once
#include "symmesh/core/linear_algebra.h"
#include "symmesh/core/point.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace symmesh::core {

/// Def 2.12: the squared shortest and longest edge of a simplex (its vertices).
/// \pre at least two vertices
template <class FT, int D>
std::pair<FT, FT> squared_edge_range(const std::vector<Point<FT, D>>& s) {
  if (s.size() < 2) throw std::invalid_argument("squared_edge_range: a simplex with an edge");
  FT lo = dot<FT, D>(s[1] - s[0], s[1] - s[0]), hi = lo;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const FT l = dot<FT, D>(s[j] - s[i], s[j] - s[i]);
      lo = std::min(lo, l);
      hi = std::max(hi, l);
    }
  return {lo, hi};
}

/// Def 2.13: (k! · Vol*(S))² = det(G), G the Gram matrix of the edge vectors from s[0] — the
/// squared relative volume of a k-simplex in R^D, times (k!)², exactly.
template <class FT, int D>
FT squared_scaled_relative_volume(const std::vector<Point<FT, D>>& s) {
  const std::size_t k = s.size() - 1;
  if (k == 0) return FT(1);
  Matrix<FT> g(k, std::vector<FT>(k));
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) g[i][j] = dot<FT, D>(s[i + 1] - s[0], s[j + 1] - s[0]);
  return determinant(g);
}

/// Def 2.14: the squared circumradius of a k-simplex (the ball through its vertices centred in its
/// affine hull): centre c = s_0 + Σ λ_j e_j with G λ = (|e_i|²/2)_i.
/// \pre the simplex is not degenerate (else std::invalid_argument)
template <class FT, int D>
FT squared_circumradius(const std::vector<Point<FT, D>>& s) {
  const std::size_t k = s.size() - 1;
  if (k == 0) return FT(0);
  Matrix<FT> g(k, std::vector<FT>(k));
  std::vector<FT> rhs(k);
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t j = 0; j < k; ++j) g[i][j] = dot<FT, D>(s[i + 1] - s[0], s[j + 1] - s[0]);
    rhs[i] = g[i][i] / FT(2);
  }
  const auto lambda = solve_unique(g, rhs);
  if (!lambda) throw std::invalid_argument("squared_circumradius: a degenerate simplex");
  Point<FT, D> c = zero_point<FT, D>();
  for (std::size_t j = 0; j < k; ++j) c = c + scaled<FT, D>(s[j + 1] - s[0], (*lambda)[j]);
  return dot<FT, D>(c, c);
}

/// Def 2.16: the angle at vertex a between rays to b and c as (sign of cos, cos²), so that angles
/// compare exactly: a larger signed cos² is a smaller angle.
template <class FT, int D>
std::pair<int, FT> signed_squared_cosine(const Point<FT, D>& a, const Point<FT, D>& b,
                                         const Point<FT, D>& c) {
  const FT uv = dot<FT, D>(b - a, c - a);
  const FT n = dot<FT, D>(b - a, b - a) * dot<FT, D>(c - a, c - a);
  return {uv > FT(0) ? 1 : uv < FT(0) ? -1 : 0, uv * uv / n};
}

/// Def 2.16 for a triangle: the smallest and the largest angle, each as its vertex index.
template <class FT, int D>
std::pair<int, int> smallest_and_largest_angle(const std::vector<Point<FT, D>>& t) {
  const auto key = [&](int v) {
    const auto [sign, c2] = signed_squared_cosine<FT, D>(
        t[std::size_t(v)], t[std::size_t((v + 1) % 3)], t[std::size_t((v + 2) % 3)]);
    return sign >= 0 ? c2 : -c2; // monotone in cos, so decreasing in the angle
  };
  int small = 0, large = 0;
  for (int v = 1; v < 3; ++v) {
    if (key(v) > key(small)) small = v;
    if (key(v) < key(large)) large = v;
  }
  return {small, large};
}

/// Def 2.16 in 3D: the interior dihedral angle of a tetrahedron at edge ab, between its faces abc
/// and abd, as (sign of cos, cos²). Measured in the plane orthogonal to ab: c − a and d − a lose
/// their components along ab (a rational projection), and the angle between the rests is the
/// dihedral angle.
template <class FT>
std::pair<int, FT> signed_squared_dihedral_cosine(const Point<FT, 3>& a, const Point<FT, 3>& b,
                                                  const Point<FT, 3>& c, const Point<FT, 3>& d) {
  const auto e = b - a;
  const FT ee = dot<FT, 3>(e, e);
  const auto across = [&](const Point<FT, 3>& p) {
    const auto w = p - a;
    return w - scaled<FT, 3>(e, dot<FT, 3>(w, e) / ee);
  };
  const auto zero = zero_point<FT, 3>();
  return signed_squared_cosine<FT, 3>(zero, across(c), across(d));
}

/// Def 2.16 for a tetrahedron: the edges (as vertex index pairs) with the smallest and the largest
/// dihedral angle.
template <class FT>
std::pair<std::pair<int, int>, std::pair<int, int>>
smallest_and_largest_dihedral_angle(const std::vector<Point<FT, 3>>& t) {
  std::vector<std::pair<int, int>> edges;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) edges.push_back({i, j});
  const auto key = [&](std::pair<int, int> e) {
    int o[2], n = 0;
    for (int v = 0; v < 4; ++v)
      if (v != e.first && v != e.second) o[n++] = v;
    const auto [sign, c2] =
        signed_squared_dihedral_cosine<FT>(t[std::size_t(e.first)], t[std::size_t(e.second)],
                                           t[std::size_t(o[0])], t[std::size_t(o[1])]);
    return sign >= 0 ? c2 : -c2; // decreasing in the angle
  };
  auto small = edges[0], large = edges[0];
  for (const auto& e : edges) {
    if (key(e) > key(small)) small = e;
    if (key(e) < key(large)) large = e;
  }
  return {small, large};
}

/// Def 2.17: the squared radius-edge ratio R_circ² / l_min².
template <class FT, int D>
FT squared_radius_edge_ratio(const std::vector<Point<FT, D>>& s) {
  return squared_circumradius<FT, D>(s) / squared_edge_range<FT, D>(s).first;
}

/// Def 2.19, Eq. 2.10, squared: Vol(E)² / l_rms^(2D), l_rms² the mean squared edge length, for a
/// D-simplex in R^D (without the normalising constant of Eq. 2.10, which is a fixed factor).
template <class FT, int D>
FT squared_volume_length(const std::vector<Point<FT, D>>& s) {
  FT sum = 0;
  int edges = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j, ++edges)
      sum += dot<FT, D>(s[j] - s[i], s[j] - s[i]);
  const FT mean = sum / FT(edges);
  FT denominator = FT(1);
  for (int d = 0; d < D; ++d) denominator *= mean;
  FT factorial = FT(1);
  for (int d = 2; d <= D; ++d) factorial *= FT(d);
  return squared_scaled_relative_volume<FT, D>(s) / (factorial * factorial) / denominator;
}

/// Def 2.20: the quality vector — the sorted scores of all cells (here of any exact score).
template <class FT, class Cells, class Score>
std::vector<FT> quality_vector(const Cells& cells, Score score) {
  std::vector<FT> v;
  for (const auto& c : cells) v.push_back(score(c));
  std::sort(v.begin(), v.end());
  return v;
}

} // namespace symmesh::core
