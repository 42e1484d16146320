/// Points and vectors of R^D with exact coordinates — spec/definitions.md#points
///
/// A point is a plain array of D exact numbers, so that every algorithm of the core is written
/// once for D = 2 and D = 3 and equality of points is exact coordinate equality.
#pragma once
#include <array>
#include <cstddef>

namespace symmesh::core {

/// A distinct type (not an alias of std::array) so that FT and D are deducible in calls.
template <class FT, int D>
struct Point : std::array<FT, D> {};

template <class FT, int D>
Point<FT, D> operator-(const Point<FT, D>& a, const Point<FT, D>& b) {
  Point<FT, D> r;
  for (int i = 0; i < D; ++i) r[i] = a[i] - b[i];
  return r;
}

template <class FT, int D>
Point<FT, D> operator+(const Point<FT, D>& a, const Point<FT, D>& b) {
  Point<FT, D> r;
  for (int i = 0; i < D; ++i) r[i] = a[i] + b[i];
  return r;
}

template <class FT, int D>
Point<FT, D> scaled(const Point<FT, D>& a, const FT& s) {
  Point<FT, D> r;
  for (int i = 0; i < D; ++i) r[i] = a[i] * s;
  return r;
}

template <class FT, int D>
FT dot(const Point<FT, D>& a, const Point<FT, D>& b) {
  FT s = 0;
  for (int i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}

/// The cross product a × b of two 3D vectors, exactly (one expression everywhere, so that lazy
/// numbers built from it have one interval enclosure).
template <class FT>
Point<FT, 3> cross(const Point<FT, 3>& a, const Point<FT, 3>& b) {
  Point<FT, 3> r;
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
  return r;
}

template <class FT, int D>
Point<FT, D> zero_point() {
  Point<FT, D> r;
  for (int i = 0; i < D; ++i) r[i] = 0;
  return r;
}

/// Lexicographic order, used to identify exactly-equal points (apply-template, Eq. 4.3).
template <class FT, int D>
struct PointLess {
  bool operator()(const Point<FT, D>& a, const Point<FT, D>& b) const {
    for (int i = 0; i < D; ++i) {
      if (a[i] < b[i]) return true;
      if (b[i] < a[i]) return false;
    }
    return false;
  }
};

} // namespace symmesh::core
