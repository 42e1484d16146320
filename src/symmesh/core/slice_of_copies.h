/// Section 6.3, Definition 6.3: rotated copies in slices that tile the full turn —
/// spec/lemmas.md#slice-separation
///
/// When every template's instances are T_{i,k} = R^k ∘ T_{i,0} (k < n, R of order n) and copy 0
/// of every template lies in one slice S of angle 2π/n about R's axis (its centre in 2D) without
/// a vertex on the axis, the n slices R^k(S) have pairwise disjoint interiors and two
/// non-consecutive ones meet only on the axis. So, with no pair of cells decided:
///   - cells of different copies have disjoint interiors (Eq. 4.2 across copies), because a cell's
///     interior lies in the interior of its copy's slice;
///   - cells of non-consecutive copies do not even touch, because a cell of copy 0 lies in the
///     pointed cone S minus the axis (0 is not a convex combination of points of a cone of angle
///     < π unless one of them is 0).
/// Only the pairs inside copy 0 remain for Eq. 4.2. The slice is found by one gift-wrapping sweep
/// over copy 0's points and then verified exactly; it exists only for R turning by 2π/n (an order-n
/// rotation by 2πj/n with j > 1 leaves R^k u strictly inside the slice for some k, and its copies
/// overlap: the counterexample `Section_6_3 slice_separation_needs_the_angle_2d`).
#pragma once
#include "symmesh/core/rotational_slice.h"
#include "symmesh/core/templated_structure.h"

#include <cstddef>
#include <optional>

namespace symmesh::core {

namespace detail {
/// The points of copy 0 of every template, T_{i,0}(p).
template <class FT, int D>
std::vector<Point<FT, D>> copy_zero_points(const TemplatedStructure<FT, D>& x) {
  std::vector<Point<FT, D>> out;
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    for (const auto& p : x.templates[i].mesh.points)
      out.push_back(x.instances[i][0].transformation(p));
  return out;
}

/// The rotation R = T_{1,k} ∘ T_{1,0}^-1 for k = 1 or k = n-1 (R^-1), whichever turns a point
/// off the axis by less than π about the returned axis (3D: the axis is chosen so; 2D: the
/// quarter turn fixes the side). Empty when copy 0 lies on the axis or R turns by π.
template <class FT, int D>
std::optional<RotationalSlice<FT, D>> turning_frame(const TemplatedStructure<FT, D>& x,
                                                    const std::vector<Point<FT, D>>& pts,
                                                    std::size_t n) {
  RotationalSlice<FT, D> s;
  const auto& t0 = x.instances[0][0].transformation;
  s.rotation = x.instances[0][1].transformation * t0.inverse();
  // The centre of the orbit of any point lies on the axis (R permutes the orbit).
  const auto& q = x.templates[0].mesh.points.front();
  Point<FT, D> sum = zero_point<FT, D>();
  for (std::size_t k = 0; k < n; ++k) sum = sum + x.instances[0][k].transformation(q);
  s.center = scaled<FT, D>(sum, FT(1) / FT(int(n)));
  for (const auto& p : pts) {
    if constexpr (D == 3) {
      // Two consecutive chords of p's orbit lie across the axis: d × R d = |d|^2 sin θ times the
      // unit axis about which R turns by θ, so R turns by θ in (0, π) about this axis.
      const auto rp = s.rotation(p);
      const auto d = rp - p;
      s.axis = cross<FT>(d, s.rotation(rp) - rp);
      if (s.axis == zero_point<FT, D>()) continue;
    } else {
      const auto w = p - s.center;
      const auto rw = s.rotation(p) - s.center;
      const FT turn = w[0] * rw[1] - w[1] * rw[0];
      if (turn == FT(0)) continue;
      if (turn < FT(0)) s.rotation = x.instances[0][n - 1].transformation * t0.inverse();
    }
    return s;
  }
  return std::nullopt;
}

/// u ⟂ axis with every point at an angle in [0, π) from it, if the points lie in such a cone: the
/// most clockwise direction (one sweep; the caller verifies the result).
template <class FT, int D>
Point<FT, D> most_clockwise(const RotationalSlice<FT, D>& s, const std::vector<Point<FT, D>>& pts) {
  const auto projected = [&](const Point<FT, D>& p) {
    const auto w = p - s.center;
    if constexpr (D == 3)
      return scaled<FT, D>(w, dot<FT, D>(s.axis, s.axis)) -
             scaled<FT, D>(s.axis, dot<FT, D>(s.axis, w));
    else
      return w;
  };
  Point<FT, D> u = zero_point<FT, D>();
  for (const auto& p : pts) {
    const auto w = projected(p);
    if (w == zero_point<FT, D>()) continue;
    if (u == zero_point<FT, D>() || dot<FT, D>(w, s.turn(u)) < FT(0)) u = w;
  }
  return u;
}
} // namespace detail

namespace detail {
/// A slice S(u, R) (R or R^-1, turning by less than π) that holds copy 0 of every template with
/// no point on the axis, or nothing; its angle is not checked here.
template <class FT, int D>
std::optional<RotationalSlice<FT, D>> slice_holding_copy_zero(const TemplatedStructure<FT, D>& x,
                                                              std::size_t n) {
  if (n < 3 || x.templates.empty() || x.templates[0].mesh.points.empty()) return std::nullopt;
  for (const auto& list : x.instances)
    if (list.size() != n) return std::nullopt;
  const auto pts = copy_zero_points(x);
  auto s = turning_frame(x, pts, n);
  if (!s) return std::nullopt;
  s->start = most_clockwise(*s, pts);
  if (s->start == zero_point<FT, D>() || !s->is_valid()) return std::nullopt;
  for (const auto& p : pts)
    if (!s->contains(p) || s->turn(p - s->center) == zero_point<FT, D>()) return std::nullopt;
  return s;
}

/// R turns by 2π/n: the n directions R^k u are distinct (R has order n) and none lies strictly
/// inside S (for a turn by 2πj/n, j - 1 of them would).
template <class FT, int D>
bool turns_by_one_nth(const RotationalSlice<FT, D>& s, std::size_t n) {
  const auto n1 = s.n1(), n2 = s.n2();
  auto w = s.start;
  for (std::size_t k = 1; k < n; ++k) {
    w = s.rotation.linear(w);
    if (w == s.start) return false;
    if (k >= 2 && dot<FT, D>(w, n1) > FT(0) && dot<FT, D>(w, n2) > FT(0)) return false;
  }
  return true;
}
} // namespace detail

/// The slice S of angle 2π/n that holds copy 0 of every template, no point of it on the axis,
/// or nothing (then the caller decides pair by pair). Exact.
/// \pre n >= 3 and T_{i,k} = R^k ∘ T_{i,0} for every template i and k < n, R of order n
///      (support::rotation_order checks it)
template <class FT, int D>
std::optional<RotationalSlice<FT, D>> slice_of_copy_zero(const TemplatedStructure<FT, D>& x,
                                                         std::size_t n) {
  auto s = detail::slice_holding_copy_zero(x, n);
  if (s && !detail::turns_by_one_nth(*s, n)) return std::nullopt;
  return s;
}

/// Eq. 4.2 for a rotational structure: with the slice of copy 0 (`copy_zero_in_slice` =
/// slice_of_copy_zero(x, n) holds, decided by a caller that needs it for more than this) only
/// the pairs inside copy 0 are decided (spec/lemmas.md#slice-separation); without it,
/// find_instance_overlap(x, n).
/// \pre as slice_of_copy_zero
template <class FT, int D>
std::optional<OverlapWitness> find_instance_overlap_by_slices(const TemplatedStructure<FT, D>& x,
                                                              std::size_t n,
                                                              bool copy_zero_in_slice) {
  if (!copy_zero_in_slice) return find_instance_overlap(x, n);
  TemplatedStructure<FT, D> copy0;
  copy0.templates = x.templates;
  for (const auto& list : x.instances) copy0.instances.push_back({list[0]});
  return find_instance_overlap(copy0);
}

/// As above, deciding slice_of_copy_zero(x, n) itself.
template <class FT, int D>
std::optional<OverlapWitness> find_instance_overlap_by_slices(const TemplatedStructure<FT, D>& x,
                                                              std::size_t n) {
  return find_instance_overlap_by_slices(x, n, slice_of_copy_zero(x, n).has_value());
}

} // namespace symmesh::core
