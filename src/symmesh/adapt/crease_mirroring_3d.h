/// Mirror insertion at acute creases and thin parts: Technique 5.8's protection in 3D below 45°
/// (Section 5.2.5, Figure 5.17) — spec/adaptation.md#tmesh-adaptation.
///
/// Two boundary planes P1, P2 of a template that meet along a line L with a small dihedral angle
/// (or are parallel and close) encroach on each other: bisection near L shrinks both sides in turn
/// without end. Let M be the reflection in the bisector plane B of the crease (it swaps the two
/// half-planes). For a triangle T in P1 with diametral sphere S (centre o in P1), the power of a
/// point q with respect to S and to M(S) differs by |q - o|^2 - |q - M(o)|^2, which is linear in q,
/// zero on B and positive on M(o)'s side. So a point q of P2 on that side inside S lies strictly
/// inside M(S), i.e. M(q) lies strictly inside T's circumcircle in P1. Inserting M(q) into P1 is a
/// Bowyer–Watson insertion that destroys T, and the points it adds are mirror images of points
/// already there: once the vertex sets of the two legs near L are mirror images and each leg is
/// a planar Delaunay triangulation, no leg triangle's diametral ball holds a point of the other
/// leg (the margin is strictly positive off L, so rounding does not undo it). Where M(q) falls
/// outside the leg, the caller bisects as before.
#pragma once
#include "symmesh/adapt/adaptation_work.h"

#include <array>
#include <map>
#include <optional>
#include <vector>

namespace symmesh::adapt::work {

/// The planes of a template's boundary (boundary triangles clustered by outward unit normal and
/// offset, up to 1e-9 of the template's extent) and the pairs of them that face each other: the
/// outward normals n1, n2 with -1 < n1 . n2 < -1/2, i.e. the template lies in a wedge of less
/// than 60° between them (an acute crease, or a thin wedge such as a half-slice of a TSV, whose
/// mirror faces meet at the axis beyond the via). For each such pair, the reflection in the plane
/// m . x = c with m = (n1 - n2) / |n1 - n2| swaps the two planes (their bisector). Parallel
/// planes (n1 . n2 = -1 up to 1e-9: the faces of a thin layer, top and bottom) are left to
/// bisection: mirroring across their mid-plane carried points from layer to layer of the TSV
/// liners (related faces face the next layer), and the 8-TSV slice hit the refinement cap.
///
/// Pairs in a wedge between 60° and 90° (-1/2 <= n1 . n2 < -1e-9) are kept apart in `near_right`:
/// Delaunay refinement in 3D is guaranteed to end only where boundary planes meet at 90° or more,
/// and below that it may ping-pong too (the 87.2° crease of the tsv-half-32 oxide, where the mirror
/// face meets the liner, bisected edges down to 1e-6 until TetGen gave up), but mirroring at every
/// such crease left slivers flat to rounding on the 64- and 128-TSV slices. So such a pair mirrors
/// only once refinement at its crease was seen to ping-pong (NearRightCreases).
struct FacingPlanes {
  struct Plane {
    std::array<double, 3> n{}; ///< outward unit normal
    double d = 0;              ///< n . x = d
  };
  struct Mirror {
    std::array<double, 3> m{};
    double c = 0;
  };
  double scale = 1; ///< the template's extent
  std::vector<Plane> planes;
  std::map<std::array<IndexType, 3>, int> triangle_plane; ///< by sorted vertices
  std::vector<std::vector<int>> vertex_planes;            ///< the planes of a vertex's triangles
  std::map<std::pair<int, int>, Mirror> mirrors;          ///< facing pairs (i < j)
  std::map<std::pair<int, int>, Mirror> near_right;       ///< pairs in 60°..90°, not mirrored
};

/// The near-right crease pairs (FacingPlanes::near_right) of each template that mirror: those at
/// which a boundary edge to bisect was already shorter than 1/16 of the template's shortest input
/// edge (watch). Kept by plane, not by index, as the planes are found anew every round.
class NearRightCreases {
public:
  explicit NearRightCreases(const Session& s);
  /// Marks the near-right pairs of template t's planes that edge {a, b} touches (each plane holds
  /// a or b), when the edge is that short.
  void watch(const FacingPlanes& fp, std::size_t t, IndexType a, IndexType b, const Work& w);
  /// Moves the marked pairs of fp (template t) from near_right to mirrors.
  void apply(FacingPlanes& fp, std::size_t t) const;

private:
  using PlanePair = std::pair<FacingPlanes::Plane, FacingPlanes::Plane>;
  bool is_marked(const FacingPlanes& fp, std::size_t t, std::pair<int, int> ij) const;
  std::vector<double> short_edge_;
  std::vector<std::vector<PlanePair>> marked_;
};

/// The boundary planes and facing pairs of every template; near-right pairs mirror where
/// `creases` marked them.
std::vector<FacingPlanes> facing_planes(const Session& s,
                                        const NearRightCreases* creases = nullptr);

/// The mirror image of boundary vertex q of w onto the plane of boundary triangle f of w, when q
/// lies on a plane that faces f's (FacingPlanes), not on f's plane itself, and the image lies
/// strictly inside f's circumcircle.
std::optional<std::array<double, 3>> crease_mirror(const Work& w, const FacingPlanes& planes,
                                                   const std::array<IndexType, 3>& f, IndexType q);

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
