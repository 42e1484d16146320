/// Mirror insertion at acute creases: Technique 5.8's protection in 3D below 45° (Section 5.2.5,
/// Figure 5.17) — spec/adaptation.md#tmesh-adaptation.
///
/// Two boundary planes P1, P2 of a template that meet along a crease line L with a small dihedral
/// angle encroach on each other: bisection near L shrinks both sides in turn without end. Let M
/// be the reflection in the bisector plane B of the crease (it swaps the two half-planes). For a
/// triangle T in P1 with diametral sphere S (centre o in P1), the power of a point q with
/// respect to S and to M(S) differs by |q - o|^2 - |q - M(o)|^2, which is linear in q, zero on
/// B and positive on M(o)'s side. So a point q of P2 on that side inside S lies strictly inside
/// M(S), i.e. M(q) lies strictly inside T's circumcircle in P1. Inserting M(q) into P1 is a
/// Bowyer–Watson insertion that destroys T, and the points it adds are mirror images of points
/// already there: once the vertex sets of the two legs near L are mirror images and each leg is
/// a planar Delaunay triangulation, no leg triangle's diametral ball holds a point of the other
/// leg (the margin is strictly positive off L, so rounding does not undo it). Where M(q) falls
/// outside the leg, the caller bisects as before.
#pragma once
#include "symmesh/adapt/adaptation_work.h"

#include <array>
#include <optional>
#include <vector>

namespace symmesh::adapt::work {

/// An acute crease of a template: boundary edge {a, b} where the template's cells meet with a
/// dihedral angle sum below 60° (the protection threshold of acute_corners), the unit normals of
/// the planes of its two boundary triangles, and the unit normal of the bisector plane through
/// the crease whose reflection swaps the two half-planes.
struct AcuteCrease {
  IndexType a = -1, b = -1;
  std::array<double, 3> origin{};           ///< the position of a
  std::array<std::array<double, 3>, 2> n{}; ///< the two leg planes
  std::array<double, 3> bisector{};
};

/// The acute creases of every template.
std::vector<std::vector<AcuteCrease>> acute_crease_edges(const Session& s);

/// The mirror of boundary vertex q of w onto the plane of triangle (x0, x1, x2) of w's boundary,
/// when that triangle lies on one leg plane of an acute crease of w and q on the other, off the
/// crease line, and the mirror lies strictly inside the triangle's circumcircle.
std::optional<std::array<double, 3>> crease_mirror(const Work& w,
                                                   const std::vector<AcuteCrease>& creases,
                                                   const std::array<const double*, 3>& x,
                                                   IndexType q);

/// A point to insert on the boundary of template t, in the plane with unit normal `normal`.
struct BoundaryPoint {
  std::size_t t = 0;
  std::array<double, 3> x{}, normal{};
};

/// Section 5.2.4 on a boundary facet: inserts each point into the boundary triangle of its
/// template that holds it (coplanar, up to the rounding of the coordinates), splitting that
/// triangle in three or, next to one of its edges, that edge (both boundary triangles on it), and
/// into every related triangle or edge through the identification tables, at the same
/// barycentric coordinates, recording the new pairs in the tables. Points that lie in no such
/// triangle, or next to one of its vertices, are skipped. The templates whose boundary changed
/// are re-tetrahedralized. Returns, per point, the template boundary points inserted for it
/// (copies counted; 0 when it was skipped).
std::vector<std::size_t> insert_boundary_points(Session& s,
                                                const std::vector<BoundaryPoint>& points);

} // namespace symmesh::adapt::work
