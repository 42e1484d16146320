/// RapidCheck generators of PLCs and their triangulations (Lemmas 2.6, 2.7) —
/// spec/traceability.md#generators
///
/// Everything is exact (Epeck rationals); CGAL's exact (constrained) Delaunay triangulations build
/// the inputs and, for Lemma 2.7, the construction; the checks of the lemmas use the core's own
/// predicates (constrained_delaunay.h), never CGAL's.
#pragma once
#include "proofs-checks/generators.h"
#include "symmesh/core/plc.h"

#include <optional>
#include <string>

namespace symmesh::proofs::gen {

template <int D>
using Plc = core::Plc<Exact, D>;

/// A PLC P and a multi-region mesh M on it, with the recipe that made them.
template <int D>
struct PlcCase {
  Plc<D> plc;
  MultiRegion<D> mesh;
  std::string recipe;
};
template <int D>
std::ostream& operator<<(std::ostream& os, const PlcCase<D>& c) {
  return os << c.recipe;
}

/// Lemma 2.6 hypotheses: a multi-region PLC P and a triangulation M of P (vertices(M) =
/// vertices(P), M respects P, us(M) = us(P)).
///  2D: CGAL's exact CDT of random grid points and random non-crossing segments; regions are the
///      components of the triangles across unconstrained edges (random ids), one component may be
///      cut out as a hole; the segments inside a region stay as dangling 1-cells; in 40% of the
///      cases 1-3 unconstrained edges are flipped afterwards (mostly not constrained Delaunay).
///  3D: the PLC induced by an exact Delaunay or regular (random weights) tetrahedralization with
///      regions by a plane or at random, sometimes with cells removed (non-convex domains);
///      coplanar facets of one interface are merged into one polygonal facet.
///  Both, one time in six: Lemma 2.5's V-shaped pair of flat simplices with P = its boundary.
template <int D>
rc::Gen<PlcCase<D>> plc_with_triangulation();

/// Lemma 2.6 without vertices(M) = vertices(P): P induced by the Delaunay triangulation of random
/// points (one region, boundary facets only), M the Delaunay triangulation of the points and one
/// Steiner point strictly inside a cell.
template <int D>
rc::Gen<PlcCase<D>> plc_with_steiner_triangulation();

/// Two flat simplices on either side of an interface facet (two regions): M is constrained
/// Delaunay, the interface facet is not locally Delaunay (L in 2..4, heights 1/q, q >= 3, moved by
/// an integer translation and a signed coordinate permutation).
template <int D>
rc::Gen<PlcCase<D>> flat_pair_across_interface();

/// Lemma 2.7 inputs. 2D: the PLCs of plc_with_triangulation (any, edge-protected or not).
/// 3D: edge-protected multi-region PLCs in general position (every per-region Delaunay
/// tetrahedralization unique): induced by Delaunay tetrahedralizations with regions and removed
/// cells, or two convex pieces glued along a triangle (regions above and below it), whose
/// constrained Delaunay tetrahedralization is not Delaunay.
template <int D>
rc::Gen<Described<Plc<D>>> plc_for_cdt();

/// Lemma 2.7 construction from P alone. 2D: CGAL's exact constrained Delaunay triangulation of
/// the vertices and 1-cells of P (exact intersections: crossing segments get a new vertex),
/// triangles kept where their centroid lies in a D-cell, with that cell's region. 3D: per region,
/// CGAL's exact Delaunay tetrahedralization of the vertices of P in that region, cells kept where
/// their centroid lies in the region.
template <int D>
MultiRegion<D> constrained_delaunay_construction(const Plc<D>& p);

/// Hypothesis-dropping PLC inputs of Lemma 2.7. 2D: a convex quadrilateral with both diagonals as
/// segments (they cross outside a vertex: condition (iv) of Def 2.3 fails). 3D: Schönhardt's
/// twisted triangular prism (not edge-protected), random size, twist and translation.
template <int D>
rc::Gen<Described<Plc<D>>> plc_without_cdt();

/// Exhaustive search, for tiny P only: is there a set of D-simplices on the vertices of P, each
/// inside us(P) and respecting P, with pairwise disjoint interiors and total volume vol(us(P))?
/// (That is a triangulation of the vertices of P that respects and geometry-conforms to P.)
/// \pre at most 20 candidate simplices (throws otherwise)
template <int D>
bool triangulation_of_vertices_exists(const Plc<D>& p);

/// {"lemma", "recipe", "complexes": {"P carrier", "M"}} and the SVG (2D) of M.
template <int D>
std::string plc_case_record(const char* lemma, const PlcCase<D>& c);

} // namespace symmesh::proofs::gen
