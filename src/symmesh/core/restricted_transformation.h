/// Rigid transformations restricted to a domain (Definition A.2 composition of restricted maps;
/// used by template boundary mappings, Definition 4.7) — spec/definitions.md#restriction
///
/// The domain is a linear set given as an element complex. Because rigid maps are affine, two of
/// them agree on a domain iff they agree on every vertex of it.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/rigid_transformation.h"

#include <stdexcept>

namespace symmesh::core {

template <class FT, int D>
struct RestrictedTransformation {
  RigidTransformation<FT, D> map;
  ElementComplex<FT, D> domain;

  bool in_domain(const Point<FT, D>& p) const { return point_in_underlying_space(domain, p); }

  /// \pre p ∈ dom; throws std::domain_error otherwise
  Point<FT, D> operator()(const Point<FT, D>& p) const {
    if (!in_domain(p)) throw std::domain_error("point outside the domain of a restricted map");
    return map(p);
  }

  /// img = map(dom), as an element complex over the transformed points.
  ElementComplex<FT, D> image() const {
    ElementComplex<FT, D> out = domain;
    for (auto& p : out.points) p = map(p);
    return out;
  }

  RestrictedTransformation inverse() const { return {map.inverse(), image()}; }
};

/// T|_A = U|_A: the maps agree on every vertex of A (hence on conv of each element).
template <class FT, int D>
bool agree_on(const RigidTransformation<FT, D>& t, const RigidTransformation<FT, D>& u,
              const ElementComplex<FT, D>& a) {
  for (const auto& e : a.elements)
    for (VertexId v : e)
      if (t(a.points[v]) != u(a.points[v])) return false;
  return true;
}

} // namespace symmesh::core
