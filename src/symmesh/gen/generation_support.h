/// Small helpers every generation pipeline stage shares, in 2D and 3D
/// (spec/generation.md#alg-5-6, #alg-5-7): step timing and page faults, exact values of doubles,
/// and the output rounding of exact values. Internal to gen/ (not a public header).
#pragma once
#include "symmesh/core/kernel.h"
#include "symmesh/core/point.h"
#include "symmesh/core/templated_structure.h"
#include "symmesh/mesh/templated_mesh.h"
#include "symmesh/number/cyclotomic.h"

#include <CGAL/Lazy_exact_nt.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>

#include <gmpxx.h>
#include <sys/resource.h>

namespace symmesh::gen::support {

using Clock = std::chrono::steady_clock;
using LazyCyclotomic = CGAL::Lazy_exact_nt<number::Cyclotomic>;

inline double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

inline long minor_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

template <class FT>
FT exact_from_double(double v) {
  const mpq_class q(v); // exact: every finite double is a dyadic rational
  if constexpr (std::is_same_v<FT, Exact>)
    return FT(q);
  else
    return FT(number::Cyclotomic(q));
}

/// The midpoint of v's certified interval when that is at most \p max_width wide — by default
/// 4 units in the last place of its bounds (rounded()'s first case) — else nothing (the caller
/// then finds the double nearest to the exact value).
template <class FT>
std::optional<double> narrow_midpoint(const FT& v, std::optional<double> max_width = {}) {
  const auto [lo, hi] = CGAL::to_interval(v);
  const double w =
      max_width ? *max_width
                : 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo), std::abs(hi));
  if (hi - lo <= w) return lo + (hi - lo) / 2;
  return std::nullopt;
}

/// v within 4 units in the last place: the midpoint of its certified interval when that is so
/// narrow, else the double nearest to its exact value. (CGAL's to_double of a lazy number
/// returns the midpoint as soon as the interval is within 1e-5 relative, which left K_128 output
/// vertices 1e-7 off.)
template <class FT>
double rounded(const FT& v) {
  if (const auto m = narrow_midpoint(v)) return *m;
  return CGAL::to_double(CGAL::exact(v));
}

/// A structure over K_m on Lazy_exact_nt<Cyclotomic> (spec/number-type.md#core-over-k-m): the
/// generators' exact steps run on it, deciding on intervals first.
template <int D>
core::TemplatedStructure<LazyCyclotomic, D>
lazily(const core::TemplatedStructure<number::Cyclotomic, D>& x) {
  return core::convert_numbers<LazyCyclotomic>(
      x, [](const number::Cyclotomic& v) { return LazyCyclotomic(v); });
}

/// An exact rigid transformation rounded for the templated mesh (x -> A x + b, row-major).
template <int D, class T>
mesh::Transformation to_double_transformation(const T& t) {
  mesh::Transformation out;
  for (int r = 0; r < D; ++r) {
    for (int c = 0; c < D; ++c) out.matrix.push_back(rounded(t.matrix()[r][c]));
    out.translation.push_back(rounded(t.translation_part()[r]));
  }
  return out;
}

/// Template t instanced as in `instances`: each instance's transformation (rounded) is appended
/// to tm's list and named by index, with its region.
template <int D, class Instances>
void add_instances(mesh::MeshTemplate& t, const Instances& instances, mesh::TemplatedMesh& tm) {
  for (const auto& inst : instances) {
    t.transformation_indices.push_back(mesh::IndexType(tm.transformations.size()));
    t.region_ids.push_back(mesh::RegionIdType(inst.region));
    tm.transformations.push_back(to_double_transformation<D>(inst.transformation));
  }
}

/// The line mesh of one edge face [a, b] (subdivision point ids): N parts; interior points get
/// local ids first .. first+N-2.
struct FaceLine {
  std::size_t a = 0, b = 0, n = 0, first = 0; ///< n = 0: a vertex face
};

/// N of the line mesh of the edge face [a, b]: the smallest N >= 1 with N·h >= |b - a|, decided
/// exactly (congruent faces get the same N, which Lemma 4.2 needs across a mapping).
template <class FT, int D>
std::size_t parts_for(const core::Point<FT, D>& a, const core::Point<FT, D>& b, const FT& h2,
                      double h) {
  const FT l2 = core::dot<FT, D>(b - a, b - a);
  // A double guess, then the exact smallest N >= 1 with N²h² >= |b - a|².
  const double guess = std::ceil(std::sqrt(CGAL::to_double(l2)) / h);
  std::size_t n = std::max<std::size_t>(1, std::size_t(std::max(1.0, guess)));
  while (n > 1 && exact_from_double<FT>(double(n - 1) * double(n - 1)) * h2 >= l2) --n;
  while (exact_from_double<FT>(double(n) * double(n)) * h2 < l2) ++n;
  return n;
}

} // namespace symmesh::gen::support
