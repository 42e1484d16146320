/// Definition A.19 (parameterized element) and Definition A.20 (k-interpolation combination),
/// Eq. A.17–A.19 — spec/definitions.md#def-a-19
///
/// I_T (Eq. A.18/A.19) is evaluated exactly. Def A.19's restrictions (i)–(iii) are not decidable
/// for an arbitrary continuous f; for the k-interpolation combinations they are decided where a
/// closed form exists: k = 1 (a segment, any dimension: t_1 ≠ t_2) and k = 2 in the plane. There
/// the Jacobian determinant J(a_1, a_2) = u×v + a_1 (u×w) + a_2 (w×v), with u = t_2 − t_1,
/// v = t_3 − t_1, w = t_1 − t_2 − t_3 + t_4, is affine (the a_1 a_2 term is w×w = 0). With
/// J ≥ 0 at the four corners and J > 0 at the centre (or the mirror), J > 0 on the open square,
/// the boundary runs once round the weakly convex polygon t_1 t_2 t_4 t_3, and I_T is a
/// homeomorphism onto it: (i)–(iii) hold. If J changes sign the map folds, and the image of the
/// fold, an interior parameter, lies on bnd*(P) — (ii) fails; J ≡ 0 at the centre means zero area.
/// Trilinear maps (k = 3, hexahedra) have no such form and are out of scope with the hexahedra.
#pragma once
#include "symmesh/core/point.h"

#include <stdexcept>
#include <vector>

namespace symmesh::core {

/// I_{(t_1..t_{2^k})}(α_1..α_k), Eq. A.18 with Eq. A.19 for k = 1.
/// \pre alpha is not empty and t.size() == 2^alpha.size(); checked, else std::invalid_argument
template <class FT, int D>
Point<FT, D> interpolation_combination(const std::vector<Point<FT, D>>& t,
                                       const std::vector<FT>& alpha) {
  const std::size_t k = alpha.size();
  if (k == 0 || k > 16 || t.size() != (std::size_t(1) << k))
    throw std::invalid_argument("interpolation_combination: needs 2^k points for k parameters");
  if (k == 1) return scaled<FT, D>(t[0], FT(1) - alpha[0]) + scaled<FT, D>(t[1], alpha[0]);
  const std::vector<FT> head(alpha.begin(), alpha.end() - 1);
  const std::size_t half = t.size() / 2;
  const std::vector<Point<FT, D>> lower(t.begin(), t.begin() + long(half));
  const std::vector<Point<FT, D>> upper(t.begin() + long(half), t.end());
  return scaled<FT, D>(interpolation_combination(lower, head), FT(1) - alpha.back()) +
         scaled<FT, D>(interpolation_combination(upper, head), alpha.back());
}

namespace detail {
template <class FT>
FT cross(const Point<FT, 2>& a, const Point<FT, 2>& b) {
  return a[0] * b[1] - a[1] * b[0];
}
} // namespace detail

/// Def A.19 for P(I_T): k = 1 in any dimension, k = 2 in the plane (see above).
/// \pre t.size() == 2, or t.size() == 4 and D == 2; checked, else std::invalid_argument
template <class FT, int D>
bool is_parameterized_element(const std::vector<Point<FT, D>>& t) {
  if (t.size() == 2) return t[0] != t[1];
  if constexpr (D == 2) {
    if (t.size() == 4) {
      const auto u = t[1] - t[0], v = t[2] - t[0];
      const auto w = (t[0] - t[1]) + (t[3] - t[2]);
      const FT j0 = detail::cross(u, v), ju = detail::cross(u, w), jv = detail::cross(w, v);
      const FT corners[4] = {j0, j0 + ju, j0 + jv, j0 + ju + jv};
      const FT centre2 = FT(2) * j0 + ju + jv; // 2 J(1/2, 1/2)
      bool all_nonneg = true, all_nonpos = true;
      for (const auto& c : corners) all_nonneg = all_nonneg && c >= FT(0);
      for (const auto& c : corners) all_nonpos = all_nonpos && c <= FT(0);
      return (all_nonneg && centre2 > FT(0)) || (all_nonpos && centre2 < FT(0));
    }
  }
  throw std::invalid_argument(
      "is_parameterized_element: decided for k = 1, and k = 2 in the plane");
}

} // namespace symmesh::core
