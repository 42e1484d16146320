/// Definition 2.2 (Multi-region geometry, region, region interface), Eq. 2.1, 2.2 —
/// spec/definitions.md#def-2-2
///
/// A linear multi-region geometry (G, ξ̃) is stored by a carrier: a face-complete, conforming,
/// pure D-dimensional simplicial complex whose cells each carry one region id. region(i) is the
/// union of the cells with id i, G the union of all cells, and ξ̃(x) (Eq. 2.2) the set of ids of
/// the regions containing x. The carrier is a representation only: every query is about the
/// point sets, never about the carrier's simplices.
///
/// Conditions of Def 2.2, computable form (spec/definitions.md#def-2-2):
///  (i) every region is a geometry of dimension D: it has at least one D-simplex;
///  (ii) the regions form a manifold partition of G: they cover G (by construction) and two
///       regions meet in a set of lower dimension — true because the carrier is conforming
///       (two different D-cells have disjoint interiors) and every cell has exactly one id.
#pragma once
#include "symmesh/core/element_complex.h"

#include <map>
#include <ostream>
#include <set>
#include <vector>

namespace symmesh::core {

template <class FT, int D>
struct MultiRegionGeometry {
  ElementComplex<FT, D> carrier;      ///< face-complete, conforming, pure D-dimensional
  std::map<Simplex, int> cell_region; ///< the region id of every D-simplex of the carrier

  std::set<int> region_ids() const {
    std::set<int> out;
    for (const auto& [c, r] : cell_region) out.insert(r);
    return out;
  }

  /// region((G, ξ̃), i) as the carrier's cells with id i and all their faces.
  ElementComplex<FT, D> region(int i) const {
    ElementComplex<FT, D> out;
    out.points = carrier.points;
    for (const auto& [c, r] : cell_region)
      if (r == i)
        for (const auto& f : faces(c)) out.elements.push_back(f);
    out.normalize();
    return out;
  }

  /// ξ̃(x), Eq. 2.2: the ids of all regions that contain x (empty outside G).
  std::set<int> xi(const Point<FT, D>& x) const {
    std::set<int> out;
    for (const auto& [c, r] : cell_region)
      if (!out.count(r) && point_in_simplex<FT, D>(carrier.coords(c), x)) out.insert(r);
    return out;
  }

  /// x ∈ interf((G, ξ̃), i_1, ..., i_k) (Eq. 2.1 = Eq. 2.2): x lies in every listed region.
  bool in_interface(const std::vector<int>& ids, const Point<FT, D>& x) const {
    const auto here = xi(x);
    for (int i : ids)
      if (!here.count(i)) return false;
    return true;
  }

  bool is_valid(std::ostream* why = nullptr) const {
    if (cell_region.empty()) {
      if (why) *why << "a multi-region geometry needs at least one region";
      return false;
    }
    if (!is_face_complete(carrier, why) || !is_conforming(carrier, why)) return false;
    for (const auto& e : carrier.elements) {
      if (e.dim() == D) {
        if (!cell_region.count(e)) {
          if (why) *why << "a D-simplex of the carrier has no region id";
          return false;
        }
      } else if (coface_cells(carrier, e).empty()) {
        if (why)
          *why << "the carrier is not pure D-dimensional (a " << e.dim() << "-simplex is "
               << "no face of a D-simplex)";
        return false;
      }
    }
    for (const auto& [c, r] : cell_region)
      if (c.dim() != D || !carrier.contains(c)) {
        if (why) *why << "region id " << r << " is attached to something that is not a D-simplex";
        return false;
      }
    return true;
  }
};

} // namespace symmesh::core
