/// Definition A.1 (closure, interior, boundary) on the underlying space of an element complex —
/// spec/definitions.md#def-a-1
///
/// Def A.1 is about arbitrary subsets of R^D; the computable form is about X = us(𝓔) for a finite
/// conforming complex of closed simplices. X is closed, so cl(X) = X. Only the D-dimensional cells
/// have interior points: a point of X outside every D-cell lies in a lower-dimensional element
/// away from the (closed) union of D-cells, so every neighbourhood leaves X. A point inside the
/// union of D-cells is on bnd(X) iff it lies on a facet with exactly one D-cell co-face: if every
/// facet through it has two, the link of the point is a closed pseudo-manifold in the sphere
/// around it and the cells fill a neighbourhood (conformity rules out overlap). Exact
/// point-in-simplex tests only.
#pragma once
#include "symmesh/core/element_complex.h"

#include <map>
#include <stdexcept>

namespace symmesh::core {

/// x ∈ cl(us(e)) = us(e).
template <class FT, int D>
bool in_closure(const ElementComplex<FT, D>& e, const Point<FT, D>& x) {
  return point_in_underlying_space(e, x);
}

/// x ∈ int(us(e)) in R^D. \pre e is conforming (checked; throws std::invalid_argument)
template <class FT, int D>
bool in_interior(const ElementComplex<FT, D>& e, const Point<FT, D>& x) {
  if (!is_conforming(e)) throw std::invalid_argument("in_interior: the complex is not conforming");
  std::map<Simplex, int> cofaces; // facets of D-cells -> number of D-cells on them
  bool in_cell = false;
  for (const auto& c : e.elements) {
    if (c.dim() != D) continue;
    in_cell = in_cell || point_in_simplex<FT, D>(e.coords(c), x);
    for (const auto& f : facets(c)) ++cofaces[f];
  }
  if (!in_cell) return false;
  for (const auto& [f, k] : cofaces)
    if (k == 1 && point_in_simplex<FT, D>(e.coords(f), x)) return false;
  return true;
}

/// x ∈ bnd(us(e)) = cl \ int. \pre e is conforming
template <class FT, int D>
bool on_boundary(const ElementComplex<FT, D>& e, const Point<FT, D>& x) {
  return in_closure(e, x) && !in_interior(e, x);
}

} // namespace symmesh::core
