// Small exact fixtures shared by the definition tests: points from exact coordinates and the face
// completion of a list of cells.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/kernel.h"

#include <vector>

namespace symmesh::test {

inline core::Point<Exact, 2> p2(Exact x, Exact y) {
  core::Point<Exact, 2> p;
  p[0] = x;
  p[1] = y;
  return p;
}

inline core::Point<Exact, 3> p3(Exact x, Exact y, Exact z) {
  core::Point<Exact, 3> p;
  p[0] = x;
  p[1] = y;
  p[2] = z;
  return p;
}

/// The face completion of `cells` over `points`, normalized.
template <int D>
core::ElementComplex<Exact, D> complex_of(const std::vector<core::Point<Exact, D>>& points,
                                          const std::vector<core::Simplex>& cells) {
  core::ElementComplex<Exact, D> c;
  c.points = points;
  c.elements = cells;
  auto f = core::face_completion(c);
  f.normalize();
  return f;
}

} // namespace symmesh::test
