/// Definition A.11 (co-face, co-facet) and Definition A.12 (neighbour element), Eq. A.10–A.14 and
/// the shorthands Eq. A.33–A.37 — spec/definitions.md#def-a-12
///
/// Every query is relative to an element space 𝓔 given as an ElementComplex: faces_𝓔(E) are the
/// elements of 𝓔 that are faces of E, E itself included (Eq. A.6), so E is its own neighbour by
/// Eq. A.13. In a face-complete complex two elements are neighbours iff they share a vertex; in
/// one that is not face-complete only the faces present count. The shorthands A.33–A.37 are the
/// same functions over the mesh element space; Eq. A.36 prints neighbors_{𝔈^n,i,k} where
/// neighbors_{𝔈^n} is meant (spec/traceability.md, slips).
#pragma once
#include "symmesh/core/element_complex.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace symmesh::core {

namespace detail {
template <class FT, int D>
void require_element(const ElementComplex<FT, D>& x, const Simplex& e, const char* who) {
  if (!x.contains(e)) throw std::invalid_argument(std::string(who) + ": E is not an element");
}
} // namespace detail

/// faces_{𝓔,j}(E) (Eq. A.7 relative to 𝓔): the elements of x that are faces of e and have
/// dimension j; every dimension when j < 0.
template <class FT, int D>
std::vector<Simplex> faces_in(const ElementComplex<FT, D>& x, const Simplex& e, int j = -1) {
  std::vector<Simplex> out;
  for (const auto& f : faces(e))
    if ((j < 0 || f.dim() == j) && x.contains(f)) out.push_back(f);
  std::sort(out.begin(), out.end());
  return out;
}

/// cofaces_𝓔(E) (Eq. A.10), cofaces_{𝓔,k}(E) (Eq. A.11) when k >= 0.
/// \pre e is an element of x
template <class FT, int D>
std::vector<Simplex> cofaces(const ElementComplex<FT, D>& x, const Simplex& e, int k = -1) {
  detail::require_element(x, e, "cofaces");
  std::vector<Simplex> out;
  for (const auto& f : x.elements)
    if ((k < 0 || f.dim() == k) && e.is_face_of(f)) out.push_back(f);
  return out;
}

/// cofacets_𝓔(E) = cofaces_{𝓔, DIM(E)+1}(E) (Eq. A.12). \pre e is an element of x
template <class FT, int D>
std::vector<Simplex> cofacets(const ElementComplex<FT, D>& x, const Simplex& e) {
  return cofaces(x, e, e.dim() + 1);
}

namespace detail {
inline bool meet(const std::vector<Simplex>& a, const std::vector<Simplex>& b) {
  for (const auto& s : a)
    if (std::binary_search(b.begin(), b.end(), s)) return true;
  return false;
}
} // namespace detail

/// neighbors_𝓔(E) (Eq. A.13): the elements sharing a face of x with e (e included).
/// \pre e is an element of x
template <class FT, int D>
std::vector<Simplex> neighbours(const ElementComplex<FT, D>& x, const Simplex& e) {
  detail::require_element(x, e, "neighbours");
  const auto mine = faces_in(x, e);
  std::vector<Simplex> out;
  for (const auto& n : x.elements)
    if (detail::meet(mine, faces_in(x, n))) out.push_back(n);
  return out;
}

/// neighbors_{𝓔,j,k}(E) (Eq. A.14): the k-dimensional elements sharing a j-dimensional face of x
/// with e. \pre e is an element of x
template <class FT, int D>
std::vector<Simplex> neighbours(const ElementComplex<FT, D>& x, const Simplex& e, int j, int k) {
  detail::require_element(x, e, "neighbours");
  const auto mine = faces_in(x, e, j);
  std::vector<Simplex> out;
  for (const auto& n : x.elements)
    if (n.dim() == k && detail::meet(mine, faces_in(x, n, j))) out.push_back(n);
  return out;
}

} // namespace symmesh::core
