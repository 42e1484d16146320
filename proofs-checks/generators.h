/// RapidCheck generators of meshes and templated structures — spec/traceability.md#generators
///
/// Tiered by precondition, as the proofs-checks need them:
///   valid_templated_mesh ⊂ templated_structure ⊂ any_structure.
/// Every coordinate is an exact rational with a small denominator on a coarse grid, so that
/// collinear / coplanar / cocircular points and shared faces are common rather than rare. All
/// generators are built with rc::gen::exec from integer picks, so RapidCheck shrinks the picks
/// (fewer points, smaller numbers, no global motion) and every case is reproducible from the
/// seed the runner prints. Each generated value carries the recipe that built it; the recipe is
/// what RapidCheck prints for a failing case.
#pragma once
#include <rapidcheck.h>

#include "symmesh/core/kernel.h"
#include "symmesh/core/multi_region_mesh.h"
#include "symmesh/core/templated_structure.h"

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace symmesh::proofs::gen {

using symmesh::Exact;
template <int D>
using Point = core::Point<Exact, D>;
template <int D>
using Complex = core::ElementComplex<Exact, D>;
template <int D>
using Structure = core::TemplatedStructure<Exact, D>;
template <int D>
using Motion = core::RigidTransformation<Exact, D>;
template <int D>
using MultiRegion = core::MultiRegionMesh<Exact, D>;
template <int D>
using PointSet = std::vector<Point<D>>;

/// A generated value and the recipe that made it.
template <class T>
struct Described {
  T value;
  std::string recipe;
};
template <class T>
std::ostream& operator<<(std::ostream& os, const Described<T>& d) {
  return os << d.recipe;
}

/// What a structure generator guarantees by construction (the tiers of the design brief).
enum class Tier { valid_templated_mesh, templated_structure, any };

template <int D>
struct GeneratedStructure {
  Structure<D> x;
  std::string recipe;
  Tier tier = Tier::any;
  /// us(AT(x)) is convex, so AT(x) triangulates its vertex set (needed by Lemmas 2.5 / 4.5).
  bool convex = false;
};
template <int D>
std::ostream& operator<<(std::ostream& os, const GeneratedStructure<D>& s) {
  return os << s.recipe;
}

// ---------------------------------------------------------------------------------------------
// Chapter 2: simplex meshes of point sets
// ---------------------------------------------------------------------------------------------

/// A triangulation of a random point set (Def 2.8: us = conv(points)): exact Delaunay, or a
/// regular triangulation with random weights (usually not Delaunay). Hidden points are dropped.
template <int D>
rc::Gen<Described<Complex<D>>> triangulation();
template <int D>
rc::Gen<Described<Complex<D>>> delaunay_triangulation();
template <int D>
rc::Gen<Described<Complex<D>>> regular_triangulation();

/// Two meshes whose union is conforming: sub-meshes (of any cell dimension <= D) of one
/// triangulation, the second over its own relabelled point array (Lemma 2.1 iv hypothesis).
template <int D>
rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>> meshes_with_conforming_union();

/// Two meshes whose union is not conforming: Figure 2.7 (a line and a vertex at a random
/// interior rational point of it) or two different triangulations of one point set.
template <int D>
rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>> meshes_with_nonconforming_union();

/// A face-complete complex without dangling elements that is not conforming: the element union
/// of two different triangulations of the same point set.
template <int D>
rc::Gen<Described<Complex<D>>> nonconforming_complex();

/// A mesh missing one facet of one of its cells (not face-complete).
template <int D>
rc::Gen<Described<Complex<D>>> non_face_complete_complex();

/// A multi-region mesh: a triangulation with region ids 1..3 by hyperplane side or at random.
template <int D>
rc::Gen<Described<MultiRegion<D>>> multi_region_mesh();

/// A non-conforming "multi-region mesh" whose region 1 holds a violating pair.
template <int D>
rc::Gen<Described<MultiRegion<D>>> nonconforming_multi_region();

/// Lemma 2.3: a simplex E and two convex sets A = conv(a), B = conv(b).
template <int D>
struct RespectCase {
  PointSet<D> e, a, b;
};
/// E respects A and E respects B (checked exactly while generating).
template <int D>
rc::Gen<Described<RespectCase<D>>> respect_both();
/// E respects A but not B: B is a simplex with a facet hyperplane through an interior point
/// of E, so that E ∩ (A ∩ B) cuts E's interior.
template <int D>
rc::Gen<Described<RespectCase<D>>> respect_one_only();

/// Lemma 2.4: a mesh with independent descriptions of the geometry it conforms to.
template <int D>
struct GeometryCase {
  Complex<D> mesh;             ///< M, a triangulation of `points`
  PointSet<D> points;          ///< G = conv(points) = us(M)
  Complex<D> other_mesh;       ///< another triangulation of `points`: G = us(other_mesh)
  MultiRegion<D> multi;        ///< (M', ξ) from a reflected template (two convex regions)
  std::vector<int> region_ids; ///< the region ids of `multi`
  std::vector<PointSet<D>> region_hulls; ///< region(G, i) = conv(region_hulls[k])
};
template <int D>
rc::Gen<Described<GeometryCase<D>>> geometry_conforming_case();

/// Lemma 2.4 dropped: a triangulation M of `points` and a convex G = conv(points) ∩ conv(cut)
/// whose boundary hyperplane passes through the interior of a cell: us(M) != G.
template <int D>
struct NonConformingGeometryCase {
  Complex<D> mesh;
  PointSet<D> points;
  PointSet<D> cut;
};
template <int D>
rc::Gen<Described<NonConformingGeometryCase<D>>> geometry_not_conforming_case();

/// Lemma 2.5 / 4.5 dropped (convexity): a flat simplex and its reflection across a hyperplane
/// through one vertex, tilted by a small rational slope. The two instances touch in that vertex,
/// every facet is locally Delaunay, yet the flat simplex's circumball holds the mirror's vertices.
template <int D>
rc::Gen<GeneratedStructure<D>> flat_simplex_v_shape();

// ---------------------------------------------------------------------------------------------
// Chapters 4 and 6: templated structures
// ---------------------------------------------------------------------------------------------

/// Lemma 6.1: a triangulated template on the positive side n·x >= d of a rational hyperplane
/// (several points exactly on it, or only one, or none), instances I and refl_{n,d}.
template <int D>
rc::Gen<GeneratedStructure<D>> reflective_structure();

/// Lemma 6.1 dropped: the template has a cell with vertices strictly on both sides of H.
template <int D>
rc::Gen<GeneratedStructure<D>> crossing_reflective_structure();

/// Lemma 6.2 / Algorithm 6.4: a template in the positive orthant of k (2 <= k <= D) pairwise
/// orthogonal rational hyperplanes, instanced by all 2^k compositions of the reflections.
template <int D>
struct OrthogonalReflections {
  GeneratedStructure<D> s;
  std::vector<Point<D>> normals;
  std::vector<Exact> offsets;
};
template <int D>
std::ostream& operator<<(std::ostream& os, const OrthogonalReflections<D>& o) {
  return os << o.s.recipe;
}
template <int D>
rc::Gen<OrthogonalReflections<D>> orthogonal_reflections();

/// Lemma 6.2 dropped: two rational reflective symmetries at 45 degrees (the square group, 8
/// instances of a template in the wedge 0 <= y <= x), normals[0] = (1, 0), normals[1] ⟂ x = y.
template <int D>
rc::Gen<OrthogonalReflections<D>> non_orthogonal_reflections();

/// A translation grid of a box template whose opposite sides carry identical subdivisions
/// (2D: Delaunay / regular triangulation of a box with subdivided sides; 3D: a stack of
/// triangular prisms, or Kuhn-subdivided boxes whose opposite faces carry translated diagonals).
template <int D>
rc::Gen<GeneratedStructure<D>> translation_grid();

/// Figure 4.4: a translated box template whose interface side (face) is subdivided differently
/// from the opposite one: a templated structure whose structure instance is not conforming
/// (3D: the 5-tetrahedron box, whose opposite faces carry crossing diagonals, or a square pyramid
/// and its half turn about an axis in the base plane, which meet with crossing base diagonals).
template <int D>
rc::Gen<GeneratedStructure<D>> figure_4_4_structure();

/// Lemma 4.5: a templated mesh with convex us(AT) whose template facets are all template-aware
/// locally Delaunay (Delaunay templates, interface facets not encroached).
template <int D>
rc::Gen<GeneratedStructure<D>> delaunay_templated_mesh();

/// Lemma 4.5 dropped (template-aware locally Delaunay): a flat simplex reflected across its own
/// long facet; the instance interface facet is not locally Delaunay in AT.
template <int D>
rc::Gen<GeneratedStructure<D>> encroached_reflection();

/// Section 5.2.3's 4-4 flip: one template of four tetrahedra around the axis (vertices 0, 1) of
/// an octahedron over the ring of vertices 2..5, instanced twice (sharing a face when the ring is
/// convex, a vertex when it is reflex). A reflex ring keeps only the diagonal 2-4 inside.
rc::Gen<GeneratedStructure<3>> four_tetrahedra_around_an_axis(bool reflex);

/// Technique 5.8's protection balls (Figure 5.17): one triangle template (0,0), (1,0), (p, q)
/// with a corner of 5.7°–42° at the origin (0 < q < p, legs of different lengths), reflected
/// across both legs (three instances around the corner).
rc::Gen<GeneratedStructure<2>> acute_wedge();

/// Tiers. valid: reflective, orthogonal reflections, translation grids, each possibly split into
/// 2-3 templates by cell centroid and moved by one global rigid motion. structure: valid plus
/// Figure 4.4 families. any: structure plus overlapping instances (Eq. 4.2 violated).
template <int D>
rc::Gen<GeneratedStructure<D>> valid_templated_mesh();
template <int D>
rc::Gen<GeneratedStructure<D>> templated_structure();
template <int D>
rc::Gen<GeneratedStructure<D>> any_structure();

/// AT equivalence dropped ("templates are meshes"): a valid structure whose templates have lost
/// their lower-dimensional faces (not face-complete), so AT is conforming but not a mesh.
template <int D>
rc::Gen<GeneratedStructure<D>> non_mesh_template_structure();

// ---------------------------------------------------------------------------------------------
// Shared helpers for the lemma files (no RapidCheck inside)
// ---------------------------------------------------------------------------------------------

/// Text of an exact number, "n" or "n/d".
std::string text(const Exact& x);
template <int D>
std::string text(const Point<D>& p);

/// The complex of one simplex given by its vertices (all faces included).
template <int D>
Complex<D> simplex_complex(const PointSet<D>& vertices);

/// "_2d" / "_3d", for property names.
inline std::string dim_suffix(int dimension) {
  return dimension == 2 ? "_2d" : "_3d";
}

// ---------------------------------------------------------------------------------------------
// Failure records (SYMMESH_PROOF_ASSERT producers; called only when an assertion fails)
// ---------------------------------------------------------------------------------------------

/// The templated-structure JSON of x with "description" naming the lemma and the recipe; it can
/// be read back with `symmesh check`.
template <int D>
std::string structure_record(const std::string& lemma, const std::string& recipe,
                             const Structure<D>& x);
/// The structure instance drawn as SVG (2D), or "" (3D).
template <int D>
std::string structure_picture(const Structure<D>& x);

/// Producers for SYMMESH_PROOF_ASSERT on a generated structure: called only on failure.
template <int D>
auto structure_failure_record(const char* lemma, const GeneratedStructure<D>& s) {
  return [lemma, &s] { return structure_record<D>(lemma, s.recipe, s.x); };
}
template <int D>
auto picture(const GeneratedStructure<D>& s) {
  return [&s] { return structure_picture<D>(s.x); };
}

/// {"lemma", "recipe", "complexes": {name: <complex JSON>}}.
template <int D>
std::string complexes_record(const std::string& lemma, const std::string& recipe,
                             const std::vector<std::pair<std::string, Complex<D>>>& parts);
/// The complex drawn as SVG (2D), or "" (3D).
template <int D>
std::string complex_picture(const Complex<D>& c);

/// Producers for SYMMESH_PROOF_ASSERT on a single mesh M: called only on failure.
template <int D>
auto complex_failure_record(const char* lemma, const std::string& recipe, const Complex<D>& m) {
  return [lemma, recipe, &m] { return complexes_record<D>(lemma, recipe, {{"M", m}}); };
}
template <int D>
auto picture(const Complex<D>& m) {
  return [&m] { return complex_picture<D>(m); };
}

} // namespace symmesh::proofs::gen

// ---------------------------------------------------------------------------------------------
// Appendix A: linear sets, intersection partition, refinement (Lemmas A.3, A.4)
// ---------------------------------------------------------------------------------------------

#include "symmesh/core/intersection_partition.h"

namespace symmesh::proofs::gen {

template <int D>
using LinearCell = core::ConvexCell<Exact, D>;
template <int D>
using Linear = core::LinearSet<Exact, D>;
template <int D>
using LinearFamily = std::vector<Linear<D>>;

/// Two linear sets A, B (Lemma A.3).
template <int D>
struct LinearPair {
  Linear<D> a, b;
};

/// Lemma A.3: two geometries (linear manifolds) with conforming representations (every two cells
/// meet in a common face): points, segments, convex polygons, fans and chord splits of convex
/// polygons, boundary chains, polyominoes of up to three squares, and in 3D folded rectangles;
/// in 3D on a few shared planes (coplanar pairs are common). B is independent, a translate of A,
/// built on an edge or a vertex of A, A itself, or (3D) on a plane through a vertex of A. Grid
/// coordinates make shared vertices, collinear overlaps and touching the rule.
template <int D>
rc::Gen<Described<LinearPair<D>>> linear_manifold_pair();

/// Lemma A.3 counterexample (Figure A.7): B a rectangle (one cell or two triangles), A a
/// C-shaped conforming polygon touching B along part of an edge and, elsewhere, in one point, so
/// A ∩ B = segment ∪ isolated point; moved by a random rigid motion (3D: on a random plane).
template <int D>
rc::Gen<Described<LinearPair<D>>> figure_a7_pair();

/// Lemma A.3 with a non-conforming representation of A: a triangle over [0, L] and, below it, a
/// triangle split at a T-junction t ∈ (0, L); B a segment (3D: or a triangle off A's plane) on
/// the line through [0, L] around t. A ∩ B is a segment, but ip(A, B) holds overlapping pieces.
template <int D>
rc::Gen<Described<LinearPair<D>>> nonconforming_representation_pair();

/// Lemma A.4: a geometry X, its conforming triangulation (for checks independent of
/// intersection_partition.h) and two coverings S, P of X.
template <int D>
struct PartitionCase {
  Linear<D> x;
  Complex<D> x_mesh;
  LinearFamily<D> s, p;
};

/// S and P manifold partitions of X: X a convex polygon (one cell or a fan) cut by random lines
/// (often through vertices), a polyomino cut by axis-parallel lines, or (3D) a folded pair of
/// rectangles cut across the fold; cuts split one element or all; sometimes lower-dimensional
/// elements (X on a cut line, an edge, a vertex) are added.
template <int D>
rc::Gen<Described<PartitionCase<D>>> manifold_partitions();

/// Lemma A.4 dropped: P a manifold partition, S only a covering: X ∩ {h >= -c} and X ∩ {h <= c}
/// for a line h = 0 through the centroid of a 2-cell of X ∩ (a 2-cell of P) and c half the
/// largest |h| over that cell's vertices, so the two overlap inside the refinement.
template <int D>
rc::Gen<Described<PartitionCase<D>>> covering_and_partition();

/// "[v0 v1 ...]" and "{cell, cell, ...}".
template <int D>
std::string cell_text(const LinearCell<D>& c);
template <int D>
std::string linear_text(const Linear<D>& a);

/// The cells' fan triangulations with all faces over one point array (equal points merged): a
/// conforming mesh of A when A's representation is conforming.
template <int D>
Complex<D> linear_set_complex(const Linear<D>& a);

/// Failure records of linear sets: {"lemma", "recipe", "complexes": {name: complex}} and the
/// union drawn as SVG (2D) or "" (3D).
template <int D>
std::string linear_sets_record(const std::string& lemma, const std::string& recipe,
                               const std::vector<std::pair<std::string, Linear<D>>>& parts);
template <int D>
std::string linear_sets_picture(const std::vector<Linear<D>>& parts);

} // namespace symmesh::proofs::gen
