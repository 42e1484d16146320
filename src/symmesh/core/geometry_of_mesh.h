/// Definition 2.11 (geometry of a mesh), Eq. 2.9; Eq. 2.6 (region interface, pointwise) —
/// spec/definitions.md#def-2-11, #eq-2-6
///
/// geo((M, ξ)) = (us(M), ξ̃) with ξ̃(x) = ⋃ { ξ(E) : E ∈ M, x ∈ E }: the multi-region geometry a
/// multi-region mesh describes. ξ(E) of any element is the union of its co-face cells' regions
/// (Eq. 2.4), so ξ̃(x) is the set of regions of the cells whose closure holds x — empty exactly
/// off us(M) (for a pure mesh every element is a face of a cell). Exact point-in-simplex tests.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/multi_region_mesh.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <vector>

namespace symmesh::core {

/// ξ̃(x) of Eq. 2.9. \pre m is a multi-region mesh whose cells carry regions (Def 2.6)
template <class FT, int D>
std::set<int> geometry_regions_at(const MultiRegionMesh<FT, D>& m, const Point<FT, D>& x) {
  std::set<int> out;
  for (const auto& [cell, region] : m.cell_region)
    if (point_in_simplex<FT, D>(m.mesh.coords(cell), x)) out.insert(region);
  return out;
}

/// x ∈ us(M), the first component of geo((M, ξ)).
template <class FT, int D>
bool in_geometry(const MultiRegionMesh<FT, D>& m, const Point<FT, D>& x) {
  return point_in_underlying_space(m.mesh, x);
}

/// interf((M, ξ), i_1..i_k) as Eq. 2.6 prints it: the elements E with {i_1..i_k} ⊆ ξ̃(x) for
/// every x ∈ E, i.e. E ⊆ us(region(i_j)) for every j — decided as a point set by exact
/// `simplex_covered_by`, not by the co-face bookkeeping of Eq. 2.5
/// (`MultiRegionMesh::region_interface`), so that the equality the dissertation states between
/// the two is checked rather than assumed. \pre m.is_valid() (a conforming multi-region mesh);
/// checked, else std::invalid_argument
template <class FT, int D>
ElementComplex<FT, D> pointwise_region_interface(const MultiRegionMesh<FT, D>& m,
                                                 const std::vector<int>& ids) {
  if (!m.is_valid()) throw std::invalid_argument("pointwise_region_interface: not a valid mesh");
  std::vector<ElementComplex<FT, D>> regions;
  for (int i : ids) regions.push_back(m.region(i));
  ElementComplex<FT, D> out;
  out.points = m.mesh.points;
  for (const auto& e : m.mesh.elements) {
    const auto c = m.mesh.coords(e);
    if (std::all_of(regions.begin(), regions.end(),
                    [&](const auto& r) { return simplex_covered_by<FT, D>(c, r); }))
      out.elements.push_back(e);
  }
  out.normalize();
  return out;
}

} // namespace symmesh::core
