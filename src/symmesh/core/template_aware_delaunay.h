/// Definition 4.10 (template-aware locally Delaunay) — spec/definitions.md#def-4-10
///
/// A facet E of mesh template X_i is template-aware locally Delaunay if T_{i,g}(E) is locally
/// Delaunay in AT(Γ) for every instance g of X_i. Lemma 4.5 (with the convexity correction of
/// spec/lemmas.md#lemma-4-5) turns "every template facet is" into "AT(Γ) is Delaunay".
#pragma once
#include "symmesh/core/delaunay.h"
#include "symmesh/core/templated_structure.h"

namespace symmesh::core {

/// \pre si = apply_template(x) and facet is a (D-1)-element of template i
template <class FT, int D>
bool is_template_aware_locally_delaunay(const StructureInstance<FT, D>& si, std::size_t i,
                                        const Simplex& facet) {
  for (std::size_t k = 0; k < si.ids.size(); ++k) {
    if (si.ids[k].i != i) continue;
    std::array<VertexId, 4> g{};
    for (int v = 0; v < facet.n; ++v) g[v] = si.vertex_map[k][facet.v[v]];
    if (!is_locally_delaunay_in(si.at.mesh, Simplex::from_range(g.data(), g.data() + facet.n)))
      return false;
  }
  return true;
}

/// Every facet of every mesh template is template-aware locally Delaunay.
template <class FT, int D>
bool all_template_facets_template_aware_locally_delaunay(const TemplatedStructure<FT, D>& x,
                                                         const StructureInstance<FT, D>& si) {
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    for (const auto& f : x.templates[i].mesh.elements_of_dimension(D - 1))
      if (!is_template_aware_locally_delaunay(si, i, f)) return false;
  return true;
}

} // namespace symmesh::core
