/// Definition 6.3 (slice) about a general centre and, in 3D, a general axis; Eq. 6.10–6.17 —
/// spec/definitions.md#def-6-3
///
/// S_{c,v,σ,α}(B) = {x ∈ B : (x − c)·n_1 ≥ 0 ∧ (x − c)·n_2 ≥ 0}. Eq. 6.14/6.15 obtain n_1, n_2 by
/// the frame R of Eq. 6.6, which needs square roots (and is printed wrongly, see the slips). The
/// half-planes need no frame: with u the starting direction (u ⟂ v, the ray at angle σ) and
/// rot = rot_{c,v,α} the rotation the slice spans, n_1 = v × u and n_2 = −(v × A u), A the linear
/// part of rot (in 2D, v × w is the quarter turn (−w_y, w_x)). Lengths do not matter for the
/// signs, so an exact rotation (rational, or over the cyclotomic field) gives an exact slice.
/// The two half-planes describe the slice only for α ≤ 180° (spec/traceability.md, slips).
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/geometry_conforming.h"
#include "symmesh/core/refined_mesh.h"
#include "symmesh/core/rigid_transformation.h"

#include <ostream>
#include <vector>

namespace symmesh::core {

template <class FT, int D>
struct RotationalSlice {
  Point<FT, D> center;                 ///< c
  Point<FT, D> axis;                   ///< v (3D; ignored in 2D)
  Point<FT, D> start;                  ///< u: direction of the starting half-plane, u ⟂ v
  RigidTransformation<FT, D> rotation; ///< rot_{c,v,α}: the spanning angle α

  /// v × w in 3D, the quarter turn of w in 2D.
  Point<FT, D> turn(const Point<FT, D>& w) const {
    Point<FT, D> r;
    if constexpr (D == 2) {
      r[0] = -w[1];
      r[1] = w[0];
    } else {
      r[0] = axis[1] * w[2] - axis[2] * w[1];
      r[1] = axis[2] * w[0] - axis[0] * w[2];
      r[2] = axis[0] * w[1] - axis[1] * w[0];
    }
    return r;
  }

  Point<FT, D> n1() const { return turn(start); } ///< Eq. 6.11 / 6.14
  Point<FT, D> n2() const {                       ///< Eq. 6.12 / 6.15
    const auto end = rotation(center + start) - center;
    return scaled<FT, D>(turn(end), FT(-1));
  }

  /// x ∈ S (Eq. 6.10 / 6.13).
  bool contains(const Point<FT, D>& x) const {
    const auto d = x - center;
    return dot<FT, D>(d, n1()) >= FT(0) && dot<FT, D>(d, n2()) >= FT(0);
  }

  /// u ≠ 0, u ⟂ v ≠ 0 (3D), rot is proper and fixes c (and c + v in 3D), and spans at most 180°
  /// towards the turned side (n_1 · A u ≥ 0).
  bool is_valid(std::ostream* why = nullptr) const {
    auto fail = [&](const char* m) {
      if (why) *why << m;
      return false;
    };
    if (start == zero_point<FT, D>()) return fail("the starting direction is zero");
    if (rotation.determinant_of_linear_part() != FT(1))
      return fail("the slice's rotation is not proper");
    if (rotation(center) != center) return fail("the rotation does not fix the centre");
    if constexpr (D == 3) {
      if (axis == zero_point<FT, D>()) return fail("the axis is zero");
      if (dot<FT, D>(axis, start) != FT(0)) return fail("the starting direction is not ⟂ axis");
      if (rotation(center + axis) != center + axis) return fail("the rotation is not about v");
    }
    if (dot<FT, D>(n1(), rotation(center + start) - center) < FT(0))
      return fail("the spanning angle exceeds 180 degrees");
    return true;
  }
};

namespace detail {
template <class FT, int D>
ElementComplex<FT, D> transformed(ElementComplex<FT, D> e, const RigidTransformation<FT, D>& t) {
  for (auto& p : e.points) p = t(p);
  return e;
}
} // namespace detail

/// Def 6.1 / 6.2 for a set given by a complex: t(us(e)) = us(e), exact (Def 2.10 both ways).
/// \pre e is face-complete and conforming
template <class FT, int D>
bool has_symmetry(const ElementComplex<FT, D>& e, const RigidTransformation<FT, D>& t) {
  return geometry_conforms(detail::transformed(e, t), e);
}

/// Eq. 6.16 / 6.17: b = ⋃_{k<n} rot^k(piece) with piece ⊆ S (so piece ⊆ S(b)), n the order of rot.
/// Exact: piece's vertices lie in S; rot^n = I; the copies lie in b, have pairwise disjoint
/// interiors and n · vol(piece) = vol(b) (a rest of b would have positive volume).
/// \pre b and piece are pure D-dimensional meshes, s.is_valid(), n >= 1
template <class FT, int D>
bool reconstructs_by_rotation(const ElementComplex<FT, D>& b, const ElementComplex<FT, D>& piece,
                              const RotationalSlice<FT, D>& s, int n, std::ostream* why = nullptr) {
  auto fail = [&](const char* m) {
    if (why) *why << m;
    return false;
  };
  for (const auto& p : piece.points)
    if (!s.contains(p)) return fail("the piece leaves the slice");
  RigidTransformation<FT, D> power;
  std::vector<std::vector<Point<FT, D>>> copies;
  FT piece_volume = 0;
  for (const auto& c : piece.cells())
    piece_volume += simplex_volume_times_factorial<FT, D>(piece.coords(c));
  for (int k = 0; k < n; ++k, power = s.rotation * power)
    for (const auto& c : piece.cells()) {
      auto coords = piece.coords(c);
      for (auto& p : coords) p = power(p);
      if (!cell_covered_by<FT, D>(coords, b)) return fail("a rotated copy of the piece leaves b");
      copies.push_back(coords);
    }
  if (!power.is_identity()) return fail("rot^n is not the identity");
  std::vector<Box<FT, D>> boxes;
  for (const auto& c : copies) boxes.push_back(box_of<FT, D>(c));
  bool disjoint = true;
  for_each_overlapping_pair<FT, D>(boxes, [&](std::size_t i, std::size_t j) {
    disjoint = !relative_interiors_meet<FT, D>(copies[i], copies[j]);
    return disjoint;
  });
  if (!disjoint) return fail("two rotated copies overlap");
  FT total = 0;
  for (const auto& c : b.cells()) total += simplex_volume_times_factorial<FT, D>(b.coords(c));
  if (FT(n) * piece_volume != total) return fail("the rotated copies do not fill b");
  return true;
}

} // namespace symmesh::core
