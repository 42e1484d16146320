/// Definition 2.8 (triangulation of a point set) — spec/definitions.md#def-2-8
///
/// M triangulates S when us(M) = conv(S) and elem_0(M) = S. Decided exactly without a convex
/// hull: with elem_0(M) = S every cell lies in conv(S), so us(M) ⊆ conv(S), and for a mesh of
/// D-cells us(M) = conv(S) iff us(M) is convex — iff every boundary facet (one co-face cell) has
/// all of S on the side of its cell. If us(M) were not convex, a segment between two generic
/// interior points would leave it through the relative interior of a boundary facet into the
/// open outer half-space of that facet and could not come back to its end point, which lies in
/// conv(S), on the inner side. Orientation signs only.
#pragma once
#include "symmesh/core/element_complex.h"

#include <algorithm>
#include <map>
#include <ostream>
#include <set>
#include <stdexcept>
#include <vector>

namespace symmesh::core {

namespace detail {
/// sign of det(q_1 − q_0, …, q_D − q_0) for D + 1 points.
template <class FT, int D>
int orientation(const std::vector<Point<FT, D>>& q) {
  const FT d = signed_volume_times_factorial<FT, D>(q);
  return d > FT(0) ? 1 : (d < FT(0) ? -1 : 0);
}

template <class FT, int D>
struct PointLess {
  bool operator()(const Point<FT, D>& a, const Point<FT, D>& b) const {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
  }
};
} // namespace detail

/// Def 2.8: m is a triangulation of s.
/// \pre s affinely spans R^D (D + 1 affinely independent points); checked, else
/// std::invalid_argument (a lower-dimensional S is triangulated in its own flat)
template <class FT, int D>
bool is_triangulation_of_points(const ElementComplex<FT, D>& m, const std::vector<Point<FT, D>>& s,
                                std::ostream* why = nullptr) {
  Matrix<FT> span;
  for (std::size_t i = 1; i < s.size(); ++i) {
    std::vector<FT> row;
    for (int d = 0; d < D; ++d) row.push_back(s[i][d] - s[0][d]);
    span.push_back(row);
  }
  if (s.empty() || rank(span) != std::size_t(D))
    throw std::invalid_argument("is_triangulation_of_points: S does not span R^D");
  if (!is_mesh(m, why)) return false;
  if (m.cell_dimension() != D) {
    if (why) *why << "the cells are not D-simplices";
    return false;
  }
  std::set<Point<FT, D>, detail::PointLess<FT, D>> vertices, points(s.begin(), s.end());
  for (const auto& v : m.elements_of_dimension(0)) vertices.insert(m.points.at(*v.begin()));
  if (vertices != points) {
    if (why) *why << "elem_0(M) != S";
    return false;
  }
  std::map<Simplex, std::vector<Simplex>> cells_on; // facet -> its co-face cells
  for (const auto& c : m.cells())
    for (const auto& f : facets(c)) cells_on[f].push_back(c);
  for (const auto& [f, cells] : cells_on) {
    if (cells.size() != 1) continue;
    auto q = m.coords(f);
    const Simplex& c = cells.front();
    VertexId apex = *std::find_if(c.begin(), c.end(), [&](VertexId v) { return !f.has_vertex(v); });
    q.push_back(m.points.at(apex));
    const int inner = detail::orientation<FT, D>(q);
    for (const auto& p : s) {
      q.back() = p;
      if (detail::orientation<FT, D>(q) == -inner) {
        if (why) *why << "us(M) != conv(S): a point of S lies beyond a boundary facet";
        return false;
      }
    }
  }
  return true;
}

} // namespace symmesh::core
