/// The copies of a reflective or reflective-rotational templated structure (Algorithms 6.1,
/// 6.4, 6.5), in 2D and 3D: S_k = T_{1,k} ∘ T_{1,1}^-1, the same for every template, closed
/// under composition, with a reflection — spec/generation.md#reflective. Internal to gen/.
#pragma once
#include "symmesh/core/rigid_transformation.h"
#include "symmesh/core/templated_structure.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::gen::support {

/// How generate() uses the symmetry of the structure (spec/generation.md).
enum class Symmetry { none, rotational, reflective, combined };

/// Algorithms 6.1/6.4 (reflective) and 6.5 (combined), on templated input: the copies
/// S_k = T_{1,k} ∘ T_{1,1}^-1 must be the same for every template (T_{i,k} = S_k ∘ T_{i,0}) and
/// form a finite group containing a reflection; `reflective` asks that every S_k be an involution
/// (I and one reflection, or the four compositions of two orthogonal reflections, Alg. 6.4),
/// `combined` that the group also contain a rotation of order >= 3 (the dihedral group of a
/// reflective-rotational object, Alg. 6.5). Returns the copies, or throws naming the reason.
template <class FT, int D>
std::vector<core::RigidTransformation<FT, D>>
symmetry_copies(const core::TemplatedStructure<FT, D>& x, Symmetry kind) {
  const std::string method = kind == Symmetry::reflective ? "reflective" : "combined";
  const auto fail = [&](const std::string& why) {
    throw std::invalid_argument("--method " + method + ": not a " +
                                (kind == Symmetry::reflective
                                     ? std::string("reflective")
                                     : std::string("reflective-rotational")) +
                                " structure: " + why);
  };
  const std::size_t n = x.instances.empty() ? 0 : x.instances[0].size();
  if (n < 2) fail("template 1 needs at least 2 instances");
  std::vector<core::RigidTransformation<FT, D>> copies;
  const auto t0_inv = x.instances[0][0].transformation.inverse();
  for (const auto& inst : x.instances[0]) copies.push_back(inst.transformation * t0_inv);
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    if (x.instances[i].size() != n)
      fail("template " + std::to_string(i + 1) + " has " + std::to_string(x.instances[i].size()) +
           " instances, template 1 has " + std::to_string(n));
    for (std::size_t k = 1; k < n; ++k)
      if (!(x.instances[i][k].transformation == copies[k] * x.instances[i][0].transformation))
        fail("T_{" + std::to_string(i + 1) + "," + std::to_string(k + 1) + "} is not S_" +
             std::to_string(k + 1) + " ∘ T_{" + std::to_string(i + 1) + ",1}");
  }
  const auto find = [&](const core::RigidTransformation<FT, D>& t) {
    for (std::size_t k = 0; k < n; ++k)
      if (copies[k] == t) return k;
    return n;
  };
  bool reflection = false, long_rotation = false;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b)
      if (find(copies[a] * copies[b]) == n)
        fail("the copies are not closed under composition (S_" + std::to_string(a + 1) + " ∘ S_" +
             std::to_string(b + 1) + ")");
    const bool involution = (copies[a] * copies[a]).is_identity();
    if (copies[a].determinant_of_linear_part() < 0)
      reflection = true;
    else if (!involution)
      long_rotation = true;
    if (kind == Symmetry::reflective && !involution)
      fail("S_" + std::to_string(a + 1) + " is not a reflection or a half turn");
  }
  if (!reflection) fail("no copy is a reflection");
  if (kind == Symmetry::combined && !long_rotation) fail("no copy is a rotation of order >= 3");
  return copies;
}

} // namespace symmesh::gen::support
