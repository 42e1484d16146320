/// Definition 3.1 (refined mesh) — spec/definitions.md#def-3-1
///
/// (R, ξ̃) refines (M, ξ) when every cell of M is the union of cells of R, each cell of R lying in
/// exactly one ("its parent") cell of M with the parent's region. The dissertation prints the
/// inclusion the other way round ("every cell C in R can be represented by a union of cells of
/// M"), which would make R the coarser mesh and contradicts its next sentence (every refined cell
/// has exactly one parent); spec/traceability.md lists the slip. Checked exactly: a cell of R
/// lies in a cell of M iff its vertices have non-negative barycentric coordinates there (cells are
/// convex); the children of a parent cover it iff their volumes add up to its volume, since the
/// children of a mesh have disjoint interiors.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/multi_region_mesh.h"

#include <map>
#include <optional>
#include <ostream>
#include <vector>

namespace symmesh::core {

/// |det(c_1 − c_0, …, c_D − c_0)| of a D-simplex: D! times its volume, exactly.
template <class FT, int D>
FT simplex_volume_times_factorial(const std::vector<Point<FT, D>>& c) {
  const FT d = signed_volume_times_factorial<FT, D>(c);
  return d < FT(0) ? -d : d;
}

/// The cell of M holding cell c (all of c's vertices in its closure), if any: the first such in
/// M's cell order.
template <class FT, int D>
std::optional<Simplex> parent_cell(const ElementComplex<FT, D>& m,
                                   const std::vector<Point<FT, D>>& c) {
  for (const auto& p : m.cells()) {
    const auto b = m.coords(p);
    bool inside = true;
    for (std::size_t k = 0; k < c.size() && inside; ++k) {
      const auto mu = barycentric<FT, D>(b, c[k]);
      inside = mu.has_value();
      for (std::size_t i = 0; inside && i < mu->size(); ++i) inside = (*mu)[i] >= FT(0);
    }
    if (inside) return p;
  }
  return std::nullopt;
}

/// Def 3.1 (as corrected above): r refines m.
/// \pre m and r are pure D-dimensional multi-region meshes (Def 2.6); checked, else throws
/// std::invalid_argument
template <class FT, int D>
bool is_refinement(const MultiRegionMesh<FT, D>& m, const MultiRegionMesh<FT, D>& r,
                   std::ostream* why = nullptr) {
  if (!is_mesh(m.mesh) || !is_mesh(r.mesh) || m.mesh.cell_dimension() != D ||
      r.mesh.cell_dimension() != D)
    throw std::invalid_argument("is_refinement: both must be pure D-dimensional meshes");
  std::map<Simplex, FT> covered; // parent -> D!·volume of its children
  for (const auto& c : r.mesh.cells()) {
    const auto coords = r.mesh.coords(c);
    const auto parent = parent_cell<FT, D>(m.mesh, coords);
    if (!parent) {
      if (why) *why << "a cell of the refinement lies in no cell of the mesh";
      return false;
    }
    if (r.cell_region.at(c) != m.cell_region.at(*parent)) {
      if (why) *why << "a cell of the refinement has another region than its parent";
      return false;
    }
    covered[*parent] += simplex_volume_times_factorial<FT, D>(coords);
  }
  for (const auto& p : m.mesh.cells())
    if (covered[p] != simplex_volume_times_factorial<FT, D>(m.mesh.coords(p))) {
      if (why) *why << "a cell of the mesh is not the union of the cells inside it";
      return false;
    }
  return true;
}

} // namespace symmesh::core
