/// Definition 4.2 (mesh decomposition, mesh block, mesh template, mesh instance) —
/// spec/definitions.md#def-4-2
///
/// ((M_1, ξ_1), …, (M_k, ξ_k)) decomposes (M, ξ) when (i) the blocks form a mesh partition
/// (Def 2.5) of M of one cell dimension and (ii) ξ_i = ξ on the elements of M_i off bnd(M_i).
/// Blocks are over M's point array. (𝒯, ζ) is a mesh template of a block with transformation T
/// when T maps 𝒯's elements exactly onto the block's and every cell keeps its region. The
/// dissertation prints (T(M_i), ζ ∘ T^{-1}) = (M_i, ξ_i), with M_i on both sides; T(𝒯) is meant
/// (spec/traceability.md, slips). Only rigid T are used (the text after Def 4.2).
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/multi_region_mesh.h"
#include "symmesh/core/rigid_transformation.h"

#include <algorithm>
#include <map>
#include <ostream>
#include <vector>

namespace symmesh::core {

/// Def 4.2 (i), (ii).
template <class FT, int D>
bool is_mesh_decomposition(const MultiRegionMesh<FT, D>& m,
                           const std::vector<MultiRegionMesh<FT, D>>& blocks,
                           std::ostream* why = nullptr) {
  std::vector<ElementComplex<FT, D>> parts;
  for (const auto& b : blocks) parts.push_back(b.mesh);
  if (!is_mesh_partition(m.mesh, parts, why)) return false;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (parts[i].cell_dimension() != m.mesh.cell_dimension()) {
      if (why) *why << "block " << i << " has another cell dimension than the mesh";
      return false;
    }
    const auto bnd = mesh_boundary(parts[i]);
    for (const auto& e : parts[i].elements)
      if (!bnd.contains(e) && blocks[i].xi(e) != m.xi(e)) {
        if (why) *why << "block " << i << ": ξ_i differs from ξ on an interior element";
        return false;
      }
  }
  return true;
}

namespace detail {
/// An element as the sorted list of its vertex coordinates (point-array independent).
template <class FT, int D>
std::vector<Point<FT, D>> element_key(const std::vector<Point<FT, D>>& c) {
  auto k = c;
  std::sort(k.begin(), k.end(), [](const Point<FT, D>& a, const Point<FT, D>& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
  });
  return k;
}

template <class FT, int D>
struct KeyLess {
  bool operator()(const std::vector<Point<FT, D>>& a, const std::vector<Point<FT, D>>& b) const {
    return std::lexicographical_compare(
        a.begin(), a.end(), b.begin(), b.end(), [](const Point<FT, D>& p, const Point<FT, D>& q) {
          return std::lexicographical_compare(p.begin(), p.end(), q.begin(), q.end());
        });
  }
};

/// element key -> region of the cell (-1 for lower-dimensional elements).
template <class FT, int D, class Map>
std::map<std::vector<Point<FT, D>>, int, KeyLess<FT, D>>
keyed_elements(const MultiRegionMesh<FT, D>& m, Map&& map_point) {
  std::map<std::vector<Point<FT, D>>, int, KeyLess<FT, D>> out;
  for (const auto& e : m.mesh.elements) {
    auto c = m.mesh.coords(e);
    for (auto& p : c) p = map_point(p);
    const auto r = m.cell_region.find(e);
    out[element_key<FT, D>(c)] = r == m.cell_region.end() ? -1 : r->second;
  }
  return out;
}
} // namespace detail

/// Def 4.2: (templ, ζ) is a mesh template of `block` with transformation t.
template <class FT, int D>
bool is_mesh_instance(const MultiRegionMesh<FT, D>& templ, const MultiRegionMesh<FT, D>& block,
                      const RigidTransformation<FT, D>& t, std::ostream* why = nullptr) {
  const auto image =
      detail::keyed_elements<FT, D>(templ, [&](const Point<FT, D>& p) { return t(p); });
  const auto target = detail::keyed_elements<FT, D>(block, [](const Point<FT, D>& p) { return p; });
  if (image != target) {
    if (why) *why << "T(template) differs from the block in an element or a cell's region";
    return false;
  }
  return true;
}

} // namespace symmesh::core
