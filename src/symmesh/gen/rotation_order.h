/// Section 6.3 with Algorithm 6.2, in 2D and 3D: the exact check that a templated structure is a
/// rotational slice structure, every template instanced by T_{i,k} = R^k ∘ T_{i,0} for one
/// rotation R of order n (about a point in 2D, about an axis in 3D) —
/// spec/generation.md#rotational. Internal to gen/.
#pragma once
#include "symmesh/core/templated_structure.h"
#include "symmesh/gen/generation_support.h"
#include "symmesh/number/cyclotomic.h"

#include <CGAL/Lazy_exact_nt.h>

#include <cstddef>
#include <string>
#include <type_traits>

namespace symmesh::gen::support {

/// The common case of rotation_order, decided without products: every T_{i,k} is exactly the
/// rotation by 2πk/n about the origin (in 3D: about the z axis) (so T_{i,0} = I and R = rot(2π/n),
/// of order n), each entry compared with the field's own value of cos / sin (elements of K_m are
/// equal iff their coefficients are). False: not this case (the general check decides).
template <class FT, int D>
bool rotations_about_origin(const core::TemplatedStructure<FT, D>& x, std::size_t n) {
  if constexpr (!std::is_same_v<FT, LazyCyclotomic>) {
    return false;
  } else {
    number::CyclotomicFieldPtr field;
    for (const auto& list : x.instances)
      for (const auto& inst : list)
        for (const auto& row : inst.transformation.matrix())
          for (const auto& v : row)
            if (!field) field = CGAL::exact(v).field();
    if (!field || field->m() % long(n) != 0 || field->m() % 4 != 0) return false;
    // The input entries are exact leaves: compare their exact values (coefficient vectors).
    const auto value = [](const LazyCyclotomic& v) -> const number::Cyclotomic& {
      return CGAL::exact(v);
    };
    for (const auto& list : x.instances)
      for (std::size_t k = 0; k < n; ++k) {
        const auto& t = list[k].transformation;
        const auto& m = t.matrix();
        const long kk = long(k), nn = long(n);
        if (!(field->is_cos_2pi(value(m[0][0]), kk, nn) &&
              field->is_cos_2pi(value(m[1][1]), kk, nn) &&
              field->is_sin_2pi(value(m[1][0]), kk, nn) &&
              field->is_sin_2pi(value(m[0][1]), kk, nn, -1) &&
              value(t.translation_part()[0]).is_zero() && value(t.translation_part()[1]).is_zero()))
          return false;
        if constexpr (D == 3) {
          // About the z axis: the third row and column are those of the identity.
          if (!(field->is_cos_2pi(value(m[2][2]), 0, 1) && value(m[0][2]).is_zero() &&
                value(m[1][2]).is_zero() && value(m[2][0]).is_zero() && value(m[2][1]).is_zero() &&
                value(t.translation_part()[2]).is_zero()))
            return false;
        }
      }
    return true;
  }
}

/// Section 6.3 with Algorithm 6.2: the number n of rotated copies when every template's
/// instances are T_{i,k} = R^k ∘ T_{i,0} for one rotation R ≠ I with R^n = I (exact), else 0
/// with the reason in `why`. R = T_{1,2} ∘ T_{1,1}^-1; the check is T_{i,k} = R ∘ T_{i,k-1} for
/// k = 1..n, indices mod n (so R^n ∘ T_{i,0} = T_{i,0}, i.e. R^n = I): one product per instance.
/// (R^d = I for some d < n would repeat an instance, which Eq. 4.2 refuses.)
template <class FT, int D>
std::size_t rotation_order(const core::TemplatedStructure<FT, D>& x, std::string& why) {
  const std::size_t n = x.instances.empty() ? 0 : x.instances[0].size();
  if (n < 2) {
    why = "template '" + x.templates[0].name + "' needs at least 2 rotated instances";
    return 0;
  }
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    if (x.instances[i].size() != n) {
      why = "template '" + x.templates[i].name + "' has " + std::to_string(x.instances[i].size()) +
            " instances, not the " + std::to_string(n) + " rotated copies";
      return 0;
    }
  if (rotations_about_origin(x, n)) return n;
  const auto r = x.instances[0][1].transformation * x.instances[0][0].transformation.inverse();
  if (r.is_identity() || !(r.determinant_of_linear_part() > 0)) {
    why = "T_{1,2} ∘ T_{1,1}^-1 is not a rotation";
    return 0;
  }
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    for (std::size_t k = 1; k <= n; ++k) {
      if (i == 0 && k == 1) continue; // R's definition
      if (!(x.instances[i][k % n].transformation == r * x.instances[i][k - 1].transformation)) {
        why = k < n ? "T_{" + std::to_string(i + 1) + "," + std::to_string(k + 1) +
                          "} is not R ∘ T_{" + std::to_string(i + 1) + "," + std::to_string(k) + "}"
                    : "the rotation T_{1,2} ∘ T_{1,1}^-1 does not have order " + std::to_string(n);
        return 0;
      }
    }
  return n;
}

} // namespace symmesh::gen::support
