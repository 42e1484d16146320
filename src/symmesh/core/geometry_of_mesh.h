/// Definition 2.11 (geometry of a mesh), Eq. 2.9 — spec/definitions.md#def-2-11
///
/// geo((M, ξ)) = (us(M), ξ̃) with ξ̃(x) = ⋃ { ξ(E) : E ∈ M, x ∈ E }: the multi-region geometry a
/// multi-region mesh describes. ξ(E) of any element is the union of its co-face cells' regions
/// (Eq. 2.4), so ξ̃(x) is the set of regions of the cells whose closure holds x — empty exactly
/// off us(M) (for a pure mesh every element is a face of a cell). Exact point-in-simplex tests.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/multi_region_mesh.h"

#include <set>

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

} // namespace symmesh::core
