/// Linear cells: closed convex polytopes of dimension 0, 1 or 2 (points, segments, convex
/// polygons; in 3D planar polygons) — spec/intersection-partition.md#convex-cells
///
/// The elements A_i of a geometry A = ∪ A_i (Def A.25, Eq. A.29) and their pairwise intersections
/// A_i ∩ B_j (Def A.29, Eq. A.39) are all of this kind, so one exact representation serves both:
/// the extreme points in a canonical order. Canonical means that two cells are equal as point
/// sets iff their `vertices` are equal as sequences:
///  - dim 0: the point; dim 1: the two end points, lexicographically ascending;
///  - dim 2: the extreme points (no three consecutive collinear) in cyclic order, starting at the
///    lexicographically smallest one and running towards its lexicographically smaller
///    neighbour. This fixes the orientation without reference to any normal vector, so the form
///    does not depend on the input order or on the projection used to compute the hull.
///
/// The functions are templates on (FT, D) declared here and explicitly instantiated for the core's
/// number types in intersection_partition.cpp (add a line there for a new FT).
#pragma once
#include "symmesh/core/point.h"

#include <algorithm>
#include <optional>
#include <ostream>
#include <vector>

namespace symmesh::core {

template <class FT, int D>
struct ConvexCell {
  int dim = -1;                       ///< 0, 1 or 2
  std::vector<Point<FT, D>> vertices; ///< extreme points in canonical order (see above)

  /// Canonical form: `vertices` are exactly the extreme points of their convex hull, affinely
  /// of dimension `dim` (coplanar in 3D), in the canonical order.
  bool is_valid(std::ostream* why = nullptr) const;
};

/// Exact set equality (the representation is canonical).
template <class FT, int D>
bool operator==(const ConvexCell<FT, D>& a, const ConvexCell<FT, D>& b) {
  return a.dim == b.dim && a.vertices == b.vertices;
}
template <class FT, int D>
bool operator!=(const ConvexCell<FT, D>& a, const ConvexCell<FT, D>& b) {
  return !(a == b);
}

/// A strict weak order on canonical cells (dimension, then vertices lexicographically), so that
/// sets of cells can be sorted and deduplicated exactly.
template <class FT, int D>
struct ConvexCellLess {
  bool operator()(const ConvexCell<FT, D>& a, const ConvexCell<FT, D>& b) const {
    if (a.dim != b.dim) return a.dim < b.dim;
    return std::lexicographical_compare(a.vertices.begin(), a.vertices.end(), b.vertices.begin(),
                                        b.vertices.end(), PointLess<FT, D>());
  }
};

/// The convex hull of a finite point set, canonical. Duplicates are merged, points that are not
/// extreme (inside, or collinear on an edge) are dropped, and the affine dimension is detected
/// exactly.
/// \pre points is non-empty and its affine hull has dimension <= 2 (throws std::invalid_argument)
template <class FT, int D>
ConvexCell<FT, D> make_convex_cell(const std::vector<Point<FT, D>>& points);

/// x ∈ c (closed cell).
/// \pre c.is_valid() (not checked: called in inner loops)
template <class FT, int D>
bool contains(const ConvexCell<FT, D>& c, const Point<FT, D>& x);

/// x ∈ int*(c), the relative interior (Def A.8): c itself for a point, the open segment, the
/// polygon without its edges.
/// \pre c.is_valid() (not checked)
template <class FT, int D>
bool relative_interior_contains(const ConvexCell<FT, D>& c, const Point<FT, D>& x);

/// a ∩ b exactly, as a canonical cell, or nullopt if empty. Covers every case: coplanar polygons
/// (polygon, segment or point), non-coplanar polygons in 3D (segment or point), collinear or
/// crossing segments, segment against polygon, and points.
/// \pre a.is_valid() and b.is_valid() (not checked)
template <class FT, int D>
std::optional<ConvexCell<FT, D>> intersect(const ConvexCell<FT, D>& a, const ConvexCell<FT, D>& b);

/// c ∩ {x : normal·x >= offset}, or nullopt if empty.
/// \pre c.is_valid() (not checked)
template <class FT, int D>
std::optional<ConvexCell<FT, D>> clip_halfspace(const ConvexCell<FT, D>& c,
                                                const Point<FT, D>& normal, const FT& offset);

/// Simplices (as vertex lists) whose union is c: the cell itself for dim <= 1, a fan from the
/// first vertex for a polygon. Lets simplex-based predicates of element_complex.h run on cells.
template <class FT, int D>
std::vector<std::vector<Point<FT, D>>> triangulate(const ConvexCell<FT, D>& c);

/// The edges of c: none for a point, the segment itself, or the polygon's boundary edges.
template <class FT, int D>
std::vector<std::vector<Point<FT, D>>> cell_edges(const ConvexCell<FT, D>& c) {
  std::vector<std::vector<Point<FT, D>>> out;
  const auto& v = c.vertices;
  if (c.dim == 1) out.push_back({v[0], v[1]});
  if (c.dim == 2)
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back({v[i], v[(i + 1) % v.size()]});
  return out;
}

/// The average of the vertices: a point of int*(c).
template <class FT, int D>
Point<FT, D> centroid(const ConvexCell<FT, D>& c) {
  Point<FT, D> s = zero_point<FT, D>();
  for (const auto& p : c.vertices) s = s + p;
  return scaled<FT, D>(s, FT(1) / FT(int(c.vertices.size())));
}

} // namespace symmesh::core
