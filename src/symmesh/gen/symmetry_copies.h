/// The copies of a reflective or reflective-rotational templated structure (Algorithms 6.1,
/// 6.4, 6.5), in 2D and 3D: S_k = T_{1,k} ∘ T_{1,1}^-1, the same for every template, closed
/// under composition, with a reflection — spec/generation.md#reflective. Internal to gen/.
#pragma once
#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/rigid_transformation.h"
#include "symmesh/core/templated_structure.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::gen::support {

/// How generate() uses the symmetry of the structure (spec/generation.md).
enum class Symmetry { none, rotational, reflective, combined };

/// The index of the copy equal to t, exactly: the certified interval boxes of the entries pick
/// the candidates (equal values have meeting intervals), an exact comparison decides among them.
/// With `closed` (the copies are known to be closed under composition and t is a product of
/// copies), a single candidate is the copy: t's exact value lies in its own box and in the box of
/// the copy it equals, so that copy is a candidate; no exact comparison is needed then.
template <class FT, int D>
std::optional<std::size_t> copy_index(const std::vector<core::RigidTransformation<FT, D>>& copies,
                                      const core::RigidTransformation<FT, D>& t,
                                      bool closed = false) {
  const auto meet = [](const FT& a, const FT& b) {
    const auto [al, ah] = CGAL::to_interval(a);
    const auto [bl, bh] = CGAL::to_interval(b);
    return !(ah < bl || bh < al);
  };
  std::vector<std::size_t> candidates;
  for (std::size_t k = 0; k < copies.size(); ++k) {
    bool candidate = true;
    for (int r = 0; r < D && candidate; ++r) {
      candidate = meet(copies[k].translation_part()[r], t.translation_part()[r]);
      for (int c = 0; c < D && candidate; ++c)
        candidate = meet(copies[k].matrix()[r][c], t.matrix()[r][c]);
    }
    if (candidate) candidates.push_back(k);
  }
  if (closed && candidates.size() == 1) return candidates[0];
  for (std::size_t k : candidates)
    if (copies[k] == t) return k;
  return std::nullopt;
}

namespace detail {
/// Whether the copies are exactly the dihedral group {r^j, r^j ∘ m : j < n/2} of a rotation r of
/// order n/2 >= 3 and a reflection m with (m ∘ r)^2 = I: then they are closed under composition,
/// decided with O(n) exact products instead of the n^2 of the general check. r is the rotation
/// of smallest angle (largest trace, by intervals); every copy must be matched exactly once.
template <class FT, int D>
bool dihedral(const std::vector<core::RigidTransformation<FT, D>>& copies) {
  const std::size_t n = copies.size();
  if (n < 6 || n % 2 != 0) return false;
  std::optional<std::size_t> r, m;
  double best = -1e300;
  for (std::size_t k = 1; k < n; ++k) {
    if (CGAL::sign(copies[k].determinant_of_linear_part()) < 0) {
      if (!m) m = k;
      continue;
    }
    double trace = 0;
    for (int d = 0; d < D; ++d) trace += CGAL::to_double(copies[k].matrix()[d][d]);
    if (trace > best) best = trace, r = k;
  }
  if (!r || !m) return false;
  const auto& rot = copies[*r];
  const auto& refl = copies[*m];
  const core::RigidTransformation<FT, D> id;
  if (!(refl * refl == id) || !(refl * rot * refl * rot == id)) return false;
  std::vector<bool> seen(n, false);
  core::RigidTransformation<FT, D> power = id;
  for (std::size_t j = 0; j < n / 2; ++j) {
    for (const auto& t : {power, power * refl}) {
      const auto k = copy_index(copies, t);
      if (!k || seen[*k]) return false;
      seen[*k] = true;
    }
    power = rot * power;
  }
  return power == id;
}
} // namespace detail

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
    // A template placed as template 1 (T_{i,0} = T_{1,0}, e.g. both the identity) needs no
    // product: T_{i,k} = S_k ∘ T_{1,0} = T_{1,k}.
    const bool placed_as_first =
        x.instances[i][0].transformation == x.instances[0][0].transformation;
    for (std::size_t k = 1; k < n; ++k)
      if (!(placed_as_first
                ? x.instances[i][k].transformation == x.instances[0][k].transformation
                : x.instances[i][k].transformation == copies[k] * x.instances[i][0].transformation))
        fail("T_{" + std::to_string(i + 1) + "," + std::to_string(k + 1) + "} is not S_" +
             std::to_string(k + 1) + " ∘ T_{" + std::to_string(i + 1) + ",1}");
  }
  const auto find = [&](const core::RigidTransformation<FT, D>& t) {
    for (std::size_t k = 0; k < n; ++k)
      if (copies[k] == t) return k;
    return n;
  };
  // A large dihedral group (the 2n half-slices of an n-fold object) is recognised in O(n).
  if (kind == Symmetry::combined && n > 16 && detail::dihedral(copies)) return copies;
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

/// Copy 0 of every template with those copies k in [first, last) whose carrier cells may meet
/// it (certified interval boxes of the cells: the exact work then grows with the copies that
/// are near, not with all): `near[t]` is the copy index of instance t of every template of
/// `structure` (near[0] = 0). With a group of copies, whatever involves two copies (k, l) is the
/// image under S_l of what involves (copy of S_l^-1 S_k, copy 0), so the instance overlaps
/// (Eq. 4.2) and the interfaces of the whole structure are those of this one (all copies:
/// [1, n)), moved by the group; the rotational method asks for the copies 2 .. n/2.
template <class FT, int D>
struct CopiesNearCopyZero {
  core::TemplatedStructure<FT, D> structure;
  std::vector<std::size_t> near;
};

template <class FT, int D>
CopiesNearCopyZero<FT, D> copies_near_copy_zero(const core::TemplatedStructure<FT, D>& x,
                                                std::size_t first = 1,
                                                std::size_t last = SIZE_MAX) {
  const auto cell_boxes = [&](std::size_t k) {
    std::vector<core::EnclosingBox<FT, D>> out;
    for (std::size_t i = 0; i < x.templates.size(); ++i) {
      const auto& c = x.templates[i].mesh;
      std::vector<core::Point<FT, D>> pts;
      for (const auto& p : c.points) pts.push_back(x.instances[i][k].transformation(p));
      for (const auto& e : c.elements)
        if (e.dim() == D) out.push_back(core::EnclosingBox<FT, D>::of(pts, e));
    }
    return out;
  };
  CopiesNearCopyZero<FT, D> out;
  out.near.push_back(0);
  const auto zero = cell_boxes(0);
  const std::size_t n = x.instances.empty() ? 0 : x.instances[0].size();
  for (std::size_t k = first; k < std::min(last, n); ++k) {
    bool meet = false;
    for (const auto& b : cell_boxes(k))
      for (const auto& a : zero) meet = meet || a.overlaps(b);
    if (meet) out.near.push_back(k);
  }
  out.structure.templates = x.templates;
  for (const auto& list : x.instances) {
    out.structure.instances.emplace_back();
    for (std::size_t k : out.near) out.structure.instances.back().push_back(list[k]);
  }
  return out;
}

/// Eq. 4.2 under a group of copies: every overlap is the image of one with copy 0, so only the
/// copies near copy 0 are checked; the witness is named by x's own instance numbers.
template <class FT, int D>
std::optional<core::OverlapWitness> copy_zero_overlap(const core::TemplatedStructure<FT, D>& x) {
  const auto near = copies_near_copy_zero(x);
  // Pairs of two other copies are images of pairs with copy 0, which are decided.
  const auto with_copy_zero = [](core::InstanceId a, core::InstanceId b) {
    return a.g == 0 || b.g == 0;
  };
  auto overlap = core::find_instance_overlap(near.structure, 0, with_copy_zero);
  if (overlap) {
    overlap->a.g = near.near[overlap->a.g];
    overlap->b.g = near.near[overlap->b.g];
  }
  return overlap;
}

} // namespace symmesh::gen::support
