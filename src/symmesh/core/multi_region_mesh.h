/// Definition 2.5 (mesh partition), 2.6 (multi-region mesh, region), 2.7 (region interface) —
/// spec/definitions.md#def-2-5, #def-2-6, #def-2-7
///
/// ξ maps every cell to one region id and extends to faces as the union over co-face cells, so a
/// region is the face completion of its cells (Lemma 2.2 proves that it is a mesh).
#pragma once
#include "symmesh/core/element_complex.h"

#include <map>
#include <set>

namespace symmesh::core {

template <class FT, int D>
struct MultiRegionMesh {
  ElementComplex<FT, D> mesh;
  std::map<Simplex, int> cell_region; ///< ξ on cells

  /// ξ(E) := ⋃ ξ(C) over co-face cells C of E (Def 2.6).
  std::set<int> xi(const Simplex& e) const {
    std::set<int> out;
    for (const auto& [c, r] : cell_region)
      if (e.is_face_of(c)) out.insert(r);
    return out;
  }

  std::set<int> region_ids() const {
    std::set<int> out;
    for (const auto& [c, r] : cell_region) out.insert(r);
    return out;
  }

  /// region((M, ξ), i) = {E ∈ M | i ∈ ξ(E)}.
  ElementComplex<FT, D> region(int i) const {
    ElementComplex<FT, D> out;
    out.points = mesh.points;
    for (const auto& [c, r] : cell_region)
      if (r == i)
        for (const auto& f : faces(c)) out.elements.push_back(f);
    out.normalize();
    return out;
  }

  /// interf((M, ξ), i_1, ..., i_k) = ⋂ region(i_j) (Eq. 2.5).
  ElementComplex<FT, D> region_interface(const std::vector<int>& ids) const {
    ElementComplex<FT, D> acc = region(ids.at(0));
    for (std::size_t j = 1; j < ids.size(); ++j) acc = intersection(acc, region(ids[j]));
    return acc;
  }

  bool is_valid(std::ostream* why = nullptr) const {
    if (!is_mesh(mesh, why)) return false;
    const int cd = mesh.cell_dimension();
    for (const auto& c : mesh.elements)
      if (c.dim() == cd && !cell_region.count(c)) {
        if (why) *why << "a cell has no region id";
        return false;
      }
    for (const auto& [c, r] : cell_region)
      if (!mesh.contains(c) || c.dim() != cd) {
        if (why) *why << "region id " << r << " is attached to something that is not a cell";
        return false;
      }
    return true;
  }
};

/// Def 2.5: {M_1..M_k} is a mesh partition of M.
template <class FT, int D>
bool is_mesh_partition(const ElementComplex<FT, D>& m,
                       const std::vector<ElementComplex<FT, D>>& parts,
                       std::ostream* why = nullptr) {
  ElementComplex<FT, D> uni;
  uni.points = m.points;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (!is_mesh(parts[i], why)) {
      if (why) *why << " (part " << i << ")";
      return false;
    }
    uni = set_union(uni, parts[i]);
  }
  if (uni.elements != m.elements) {
    if (why) *why << "the parts do not cover the mesh exactly";
    return false;
  }
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      const auto x = intersection(parts[i], parts[j]);
      const int maxd = std::max(parts[i].cell_dimension(), parts[j].cell_dimension());
      if (!x.elements.empty() && x.cell_dimension() >= maxd) {
        if (why) *why << "parts " << i << " and " << j << " share a cell";
        return false;
      }
    }
  return true;
}

} // namespace symmesh::core
