/// Section 5.2.1 on a generated templated mesh (.tmesh): template cloning, merging and splitting —
/// spec/adaptation.md#tmesh-cloning
///
/// The exact core clones and merges templates of a TemplatedStructure, whose structure instance
/// identifies equal points (adapt/template_cloning.h). A generated mesh identifies vertices by
/// its compact SVB instead, so here the identification tables follow the instance: a table used
/// by a pair that involves the cloned instance gets a copy that names the new template, and
/// merging renames the merged template in every table (tables that become equal are kept once).
/// Both leave AT unchanged: the same cells, the same coordinates, the same identified vertices.
///
/// Merging is offered for identical templates (the same coordinates, bit for bit, and the same
/// cells) and for templates congruent by an exact motion: R(X_j) = X_i with the doubles taken as
/// the rationals they are, decided without a tolerance (tmesh_template_congruence.cpp). Motions
/// whose images of doubles are doubles qualify (translations, mirrors, signed permutations); a
/// rotation by 2π/n, whose images are rounded, does not (the exact core decides that case
/// exactly, on exact coordinates).
#pragma once
#include "symmesh/mesh/templated_mesh.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace symmesh::adapt {

/// Where a cloned instance went: the new template (the last one) and the instance's new global
/// number (template-major numbering: the last instance).
struct ClonedInstance {
  std::size_t template_index = 0, instance = 0;
};

/// Template cloning: global instance `instance` gets its own copy of its template, appended as
/// the last template; the other instances stay with the original. Instances of the original
/// template after it move down by one in the global numbering.
/// \pre t.is_valid(), `instance` < t.templated.instance_count(), and its template has at least
/// two instances (the original must keep one); else std::invalid_argument
ClonedInstance clone_template(mesh::TemplatedMeshCompactSvb& t, std::size_t instance);

/// Templates i and j have the same vertex coordinates (compared as doubles) in the same order and
/// the same cells.
/// \pre i, j < t.templated.templates.size()
bool identical_templates(const mesh::TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j);

/// Template merging, the inverse of cloning: template j's instances join template i (after i's
/// own), template j is removed and later templates move down by one.
/// \pre t.is_valid(), i != j, both in range, identical_templates(t, i, j); else
/// std::invalid_argument naming the templates
void merge_templates(mesh::TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j);

/// Templates i and j congruent by an exact motion R (R(X_j) = X_i): R is solved over the
/// rationals from j's first cell and each cell of i, corner to corner, and must be orthogonal
/// (A^T A = I exactly) and send every vertex of j exactly onto a distinct vertex of i and every
/// cell of j onto a cell of i. `vertex[v]` is the vertex of i that vertex v of j goes to;
/// `identity` when R is the identity.
struct TemplateCongruence {
  std::vector<mesh::IndexType> vertex;
  bool identity = false;
};
/// nullopt when no such R exists (also for non-simplicial templates or repeated vertices).
/// With `tolerance` > 0, a pair the exact search refuses is searched again up to rounding: R
/// from a cell pair as above, nearly orthogonal (1e-6), made orthonormal (Gram–Schmidt, the
/// translation fitted to the cell), sending every vertex of j within `tolerance` times i's
/// diameter of a distinct vertex of i and every cell of j onto a cell of i — a rotation by
/// 2π/n whose images were rounded (1e-9 is ample: rounding is ~1e-16 of the coordinates).
/// \pre i, j < t.templated.templates.size(), tolerance >= 0
std::optional<TemplateCongruence> template_congruence(const mesh::TemplatedMeshCompactSvb& t,
                                                      std::size_t i, std::size_t j,
                                                      double tolerance = 0);
/// Section 5.2.1, merging congruent templates: template j's instances join template i with the
/// transformations T_{j,g} ∘ R^{-1} (composed over the rationals, each entry rounded once; a
/// signed permutation with representable translations composes exactly), its identification
/// tables renumbered by the vertex map, and j is removed as by merge_templates. AT keeps its cells
/// and its identified vertices; its coordinates agree up to the rounding of the composed
/// transformations.
/// \pre t.is_valid(), i != j, both in range, template_congruence(t, i, j); else
/// std::invalid_argument naming the templates
/// With `tolerance` > 0 also templates congruent up to it (template_congruence); AT's points of
/// j's instances then move by up to that fraction of the diameter (rounding, for 1e-9).
void merge_congruent_templates(mesh::TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j,
                               double tolerance = 0);
/// Merges every template into the first template congruent to it by an exact motion (identical
/// ones included), or with `tolerance` > 0 up to it. Returns the number of templates merged away.
/// \pre t.is_valid(), else std::invalid_argument
std::size_t merge_congruent_templates(mesh::TemplatedMeshCompactSvb& t, double tolerance = 0);
/// Merges every template into the first template identical to it. Returns the number of
/// templates merged away.
/// \pre t.is_valid()
std::size_t merge_identical_templates(mesh::TemplatedMeshCompactSvb& t);

/// Template splitting: the cells of template i with index in `part` become a new template,
/// appended as the last one, with one instance per instance of i (the same transformation and
/// region, in the same order, after every other instance); template i keeps its other cells.
/// Each part keeps the vertices its cells use, in their old order (vertices no cell uses stay in
/// i). The two parts of every instance are identified along the cut (the vertices both parts use)
/// by one new table, and every table that names template i is split into pieces by the parts its
/// vertices went to (a pair with a vertex on the cut goes into the pieces of both parts, so that a
/// facet of either part finds its related facets through one table), so AT keeps its cells and its
/// vertices. Returns the new template's index. \pre t.is_valid(), i in range, `part` a non-empty
/// proper subset of i's cells (indices in range, repeats ignored); else std::invalid_argument
std::size_t split_template(mesh::TemplatedMeshCompactSvb& t, std::size_t i,
                           const std::vector<std::size_t>& part);

namespace detail {
/// split_template with the cut table left out when `identify_cut` is false: the dropped
/// hypothesis of the Section 5.2.1 splitting property (the two parts of an instance are no
/// longer identified along the cut, so AT gains vertices and the cut becomes boundary).
std::size_t split_template(mesh::TemplatedMeshCompactSvb& t, std::size_t i,
                           const std::vector<std::size_t>& part, bool identify_cut);

/// merge_templates without its identity precondition: the dropped hypothesis of the
/// Section 5.2.1 property (a non-identical template's instances take the other's cells).
void merge_templates_unchecked(mesh::TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j);
} // namespace detail

} // namespace symmesh::adapt
