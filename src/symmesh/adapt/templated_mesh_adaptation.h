/// Section 5.2 and Technique 5.8 on a generated templated mesh (.tmesh) —
/// spec/adaptation.md#tmesh-adaptation
///
/// The exact operations of this folder act on core::TemplatedStructure, whose structure instance
/// identifies equal points. A generated mesh has double coordinates and identifies vertices by
/// its compact SVB instead (mesh/templated_mesh.h), so these operations keep the SVB in step: a
/// vertex put on a template boundary edge is put on every related edge — the edges the
/// identification tables map it to, closed under the tables — and identified with its copies
/// there (Section 5.2.4). Everything else happens inside one template at a time, so every
/// instance of it changes alike and the mesh stays templated (Definition 4.4) by construction.
/// Decisions are exact predicates on the double coordinates (CGAL's filtered predicates):
/// template-local tests in template coordinates, interface tests (Definition 4.10) on the
/// instances' images. No distance is compared with a tolerance.
#pragma once
#include "symmesh/mesh/progress.h"
#include "symmesh/mesh/templated_mesh.h"

#include <compare>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::adapt {

/// Edge {a, b} (a < b) of template `t`.
struct TemplateEdge {
  std::size_t t = 0;
  mesh::IndexType a = 0, b = 0;
  auto operator<=>(const TemplateEdge&) const = default;
};

/// An adaptation that could not reach its goal within its bounds (the CLI's exit 1).
class AdaptationLimit : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Gives every instance pair that shares a template boundary edge a direct identification. The
/// generator keeps only a spanning set of pairs (an edge of I and J may be identified through a
/// third instance K that contains its end points but not the edge); bisection finds related
/// edges through direct pairs only. Returns the number of pairs added.
/// \pre t.is_valid()
std::size_t expand_identifications(mesh::TemplatedMeshCompactSvb& t);

/// Bisects every given template edge at its midpoint and, closed under the identification
/// tables, every related template boundary edge; each new vertex is identified with its copies.
/// Every cell on a bisected edge is split in two (in place, so orientation is kept). Returns the
/// number of template edges bisected.
/// \pre expand_identifications(t) was applied; every edge is an edge of its template
std::size_t bisect_edges(mesh::TemplatedMeshCompactSvb& t, const std::vector<TemplateEdge>& edges);

/// 2D: Lawson flips of template-interior edges until every template-interior edge is locally
/// Delaunay (Section 5.2.3: template boundary edges are never flipped). Returns the flip count.
/// \pre t.templated.point_dimension == 2
std::size_t make_templates_delaunay(mesh::TemplatedMeshCompactSvb& t);

/// 2D: the instance-interface edges that are not template-aware locally Delaunay (Definition
/// 4.10): the apex across the interface, in AT's coordinates, lies strictly inside the
/// circumcircle of the edge's cell. Each edge once, as an edge of the from-template.
/// \pre t.templated.point_dimension == 2
std::vector<TemplateEdge> non_tald_edges(const mesh::TemplatedMeshCompactSvb& t);

struct DelaunayReport {
  std::size_t rounds = 0, flips = 0, bisections = 0;
  std::size_t vertices_deleted = 0;     ///< 3D: template-interior vertices of slivers
  std::size_t vertices_inserted = 0;    ///< 3D: centroids of slivers on boundary vertices
  std::size_t crease_mirror_points = 0; ///< 3D: mirror images across acute creases (copies)
};

/// Technique 5.8 in the plane: Lawson flips in every template, then, while some interface edge
/// is not template-aware locally Delaunay, a split point is inserted at every related edge and
/// the templates are flipped again. The split point is the midpoint, or, on an edge with one end
/// at an acute template corner, the power-of-two distance from that corner nearest to half the
/// length (protection balls on concentric shells, against the ping-pong encroachment of
/// Figure 5.17; spec/adaptation.md). Then every interior edge of AT is locally Delaunay, so AT is
/// a constrained Delaunay triangulation of its domain (Delaunay when the domain is convex,
/// Lemma 4.5). Throws AdaptationLimit naming an offending edge after `max_rounds` rounds.
/// In 3D (technique_5_8_3d.cpp), a boundary triangle encroached by a point of the other leg of
/// an acute crease gets that point's mirror image (crease_mirroring_3d.h) unless
/// `crease_mirrors` is false (the property's dropped hypothesis).
/// \pre t.templated.point_dimension is 2 or 3, expand_identifications(t) was applied
DelaunayReport make_delaunay(mesh::TemplatedMeshCompactSvb& t, std::size_t max_rounds,
                             mesh::Progress* progress = nullptr, bool crease_mirrors = true);

struct SmoothReport {
  std::size_t interior_moves = 0; ///< template-interior vertices moved
  std::size_t boundary_moves = 0; ///< template-boundary vertices moved, related copies counted
};

/// Section 5.2.2, Laplacian smoothing over `iterations` Gauss–Seidel sweeps. A template-interior
/// vertex moves to the mean of its neighbours. A template-boundary vertex moves only inside its
/// boundary patch: where its boundary facets form one flat disk, it moves to the mean of its
/// boundary neighbours; in 3D, where they form two flat half-disks meeting in a straight crease
/// through it, it moves along the crease to the midpoint of the crease's two ends (on an exact
/// crease only when that rounded point lies exactly on it). Flat and straight are decided by
/// exact predicates, then, for what they find bent, up to the rounding of the coordinates (within
/// 1e-9 of the farthest link vertex: the slanted planes of the n-gon slices), a coordinate that
/// the whole link shares is kept exactly. Every vertex related to it through
/// the identification tables moves with it to the image of that place (Equation 5.1); a vertex
/// where the boundary bends otherwise, or one that the tables relate inconsistently (an irregular
/// instance graph, Figure 4.11), stays. A move is made when every cell around every moved vertex
/// stays positively oriented (exact) and, with `improve_only`, their smallest quality grows.
SmoothReport smooth_vertices(mesh::TemplatedMeshCompactSvb& t, std::size_t iterations,
                             bool improve_only);

namespace detail {
/// smooth_vertices (not improve-only) with each template-boundary vertex moved alone, its
/// related vertices left to their own moves: the dropped hypothesis of Equation 5.1 (a related
/// vertex whose link is not the image of v's, e.g. on the other side of a T-junction, moves
/// elsewhere or not at all, and the interface opens).
SmoothReport smooth_vertices_unlinked(mesh::TemplatedMeshCompactSvb& t, std::size_t iterations);
/// smooth_vertices (not improve-only) with `tolerance` in place of the 1e-9 within which rounded
/// boundary points count as one plane or one line: 0 is exact predicates only (a slanted patch's
/// vertices stay), and a tolerance of 2 or more takes every closed fan for a flat disk — the
/// dropped hypothesis (a vertex moves only within its patch): corner and crease vertices move off
/// the boundary.
SmoothReport smooth_vertices_with_flatness(mesh::TemplatedMeshCompactSvb& t, std::size_t iterations,
                                           double tolerance);
} // namespace detail

/// One instance image of a template cell, as --refine-where sees it.
struct CellView {
  double centroid[3] = {0, 0, 0}; ///< in AT's coordinates (split_where: the template's)
  double size = 0;                ///< longest edge
  double quality = 0;             ///< smallest angle (2D) or dihedral angle (3D), degrees
  std::size_t template_index = 0, instance = 0;
  mesh::RegionIdType region = 0;
};
using CellPredicate = std::function<bool(const CellView&)>;

/// Parses "TERM [and TERM]…", TERM = "NAME OP NUMBER", NAME one of x y z size quality region
/// template instance, OP one of < <= > >= == !=. Throws std::invalid_argument naming the token.
CellPredicate parse_cell_predicate(const std::string& expression);

/// As parse_cell_predicate, for --split-where: a template's cells in template coordinates, so
/// NAME is one of x y z size quality template (region and instance differ between instances).
CellPredicate parse_template_cell_predicate(const std::string& expression);

/// A template split by split_where: the template, the new template that took the cells that
/// satisfied the predicate, and their number.
struct TemplateSplit {
  std::size_t template_index = 0, new_template = 0, cells = 0;
};

/// Section 5.2.1 template splitting (split_template, adapt/tmesh_template_cloning.h) of every
/// template with cells on both sides of `where`, evaluated on the template's own cells
/// (CellView::centroid in template coordinates; region and instance are 0). The cells that
/// satisfy it become a new template, instanced like the old one; AT is unchanged. Templates
/// made by the splits are not split again. Returns the splits in template order.
std::vector<TemplateSplit> split_where(mesh::TemplatedMeshCompactSvb& t,
                                       const CellPredicate& where);

/// Section 5.2.4 refinement: the longest edge of every template cell with an instance image that
/// satisfies `where` is bisected (with its related edges). Returns the edges bisected.
/// \pre expand_identifications(t) was applied
std::size_t refine_where(mesh::TemplatedMeshCompactSvb& t, const CellPredicate& where);

struct ImproveReport {
  std::size_t rounds = 0, moves = 0, flips = 0;
};

/// Section 5.2.6: rounds of quality-improving smoothing (smooth_vertices with `improve_only`:
/// template-boundary vertices only inside their patch) and flips inside templates — Delaunay
/// flips in 2D, quality-raising 2-3/3-2 flips in 3D; template boundary facets are never flipped —
/// until a round changes nothing or `max_rounds` is reached.
ImproveReport improve_quality(mesh::TemplatedMeshCompactSvb& t, std::size_t max_rounds);

/// The smallest cell quality of AT (it is a template's: rigid maps keep angles): smallest angle
/// in 2D, smallest dihedral angle in 3D, degrees.
double smallest_quality(const mesh::TemplatedMeshCompactSvb& t);

/// A combinatorial certificate that AT conforms: every template cell is positively oriented
/// (exact), no facet of AT (vertices numbered through the SVB) lies in more than two cells, and
/// the measure of AT's boundary facets is `expected_boundary` (a vertex hanging on an interface
/// leaves the interface's facets on the boundary of both sides). And the coordinates agree with
/// the numbering: the two instances of every identified vertex pair put it at one point, up to
/// the rounding of their transformations (1e-9 relative).
struct ConformityCertificate {
  bool holds = true;
  std::string why;
  std::size_t cells = 0, boundary_facets = 0;
  double boundary_measure = 0;
};
/// \pre t.is_valid(); `expected_boundary` < 0 skips the boundary comparison
ConformityCertificate certify_conformity(const mesh::TemplatedMeshCompactSvb& t,
                                         double expected_boundary = -1);

} // namespace symmesh::adapt
