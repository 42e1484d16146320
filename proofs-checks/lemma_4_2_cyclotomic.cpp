// Lemma 4.2 (Interface conformity) over K_m — spec/lemmas.md#lemma-4-2, spec/number-type.md
//
// The properties of lemma_4_2_interface_conformity.cpp re-run on ROTATIONAL structures whose
// coordinates and instance transformations lie in the real cyclotomic field K_m
// (symmesh::number::Cyclotomic): a slice template in the wedge of angle 2π/n (radii on both
// bounding rays, a zipper triangulation of the strip, the centre triangle, rational interior
// points), instanced by rot(2πi/n), i = 0..n-1, n ∈ {3, 4, 5, 6, 8, 10, 12, 16}, in K_m with
// m = lcm(4, n) (sometimes 2 or 3 times that), possibly after a global rational motion.
// Γ a templated structure with mesh templates. If for all neighbouring instances
//  (i)  us(interf(Γ, T_a, T_b)) = interf_geo(Γ, T_a, T_b) and
//  (ii) T_a(IP_{a,b}) = T_b(IP_{b,a}),
// then AT(Γ) is conforming. The checker is core::check_interface_conformity<Cyclotomic, 2>, the
// conclusion is decided independently by core::find_nonconformity over all elements of AT;
// consecutive slices share their ray vertices only through exact equality in K_m (rot(2πi/n) ∘
// rot(2π/n) = rot(2π(i+1)/n) exactly).
// Counterexample: different interior radii on the two rays (hypothesis (i) dropped: the instance
// interfaces are not conforming): the checker reports condition (i) on a neighbouring pair and
// the structure instance is not conforming, although the instances do not overlap (Eq. 4.2).
#include "proofs-checks/cyclotomic_generators.h"
#include "proofs-checks/line_mesh_cases.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/interface_conformity.h"

namespace symmesh::proofs {
namespace {

using namespace cyclo;

constexpr const char* kLemma = "Lemma_4_2";

auto record(const RotationalStructure& s) {
  return rotational_failure_record(kLemma, s);
}
auto picture(const RotationalStructure& s) {
  return rotational_failure_picture(s);
}

/// The generator's promise: well-formed (templates are meshes), and with `eq_4_2` also a
/// templated structure (no two instances overlap, Eq. 4.2).
void well_formed(const RotationalStructure& s, bool eq_4_2) {
  SYMMESH_PROOF_ASSERT(s.x.is_well_formed(), record(s), picture(s));
  if (eq_4_2)
    SYMMESH_PROOF_ASSERT(!core::find_instance_overlap(s.x).has_value(), record(s), picture(s));
}

/// holds: equal radii satisfy (i) and (ii) on every neighbouring pair; AT must be conforming,
/// with the centre and the ray vertices shared exactly: AT has 1 + n·(template vertices - 1 - k)
/// vertices, k the number of template vertices on one ray (shared with the neighbouring slice).
void sufficiency(const RotationalStructure& s) {
  well_formed(s, false);
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  RC_TAG("n = " + std::to_string(s.n), "K_" + std::to_string(s.m));
  SYMMESH_PROOF_ASSERT(v.holds && v.pairs_checked == std::size_t(s.n * (s.n - 1) / 2), record(s),
                       picture(s));
  SYMMESH_PROOF_ASSERT(core::structure_instance_conforming(si), record(s), picture(s));
  const std::size_t tv = s.x.templates[0].mesh.points.size();
  std::size_t ray = 0; // template vertices on the ray at angle 0 (other than the centre)
  for (const auto& p : s.x.templates[0].mesh.points)
    if (p[1].is_zero() && !p[0].is_zero()) ++ray;
  SYMMESH_PROOF_ASSERT(si.at.mesh.points.size() == std::size_t(s.n) * (tv - 1 - ray) + 1, record(s),
                       picture(s));
}

/// spec/lemmas.md#lemma-4-2-rotational: for T_{i,k} = R^k ∘ T_{i,0} the check up to the
/// rotation (pairs with copy 0 only), on the full meshes and on their boundary complexes (what
/// `generate --method rotational` certifies with), gives the verdict of the direct check of AT.
void rotation_reduction_equals_direct(const RotationalStructure& s) {
  const bool direct = core::structure_instance_conforming(core::apply_template(s.x));
  RC_TAG(direct ? "AT conforming" : "AT not conforming");
  SYMMESH_PROOF_ASSERT(core::check_interface_conformity_up_to_rotation(s.x).holds == direct,
                       record(s), picture(s));
  SYMMESH_PROOF_ASSERT(
      core::check_interface_conformity_up_to_rotation(core::boundary_structure(s.x)).holds ==
          direct,
      record(s), picture(s));
}
void rotation_reduction_agrees(const RotationalStructure& s) {
  well_formed(s, true);
  rotation_reduction_equals_direct(s);
}

/// Rotation invariance dropped: a copy of the slice far away comes first (so it is "copy 0"),
/// then two consecutive slices with different radii, which do not conform. No pair with copy 0
/// meets, so the reduced check certifies, while AT is not conforming.
rc::Gen<RotationalStructure> not_rotation_invariant() {
  return rc::gen::map(rotational_structure(false), [](RotationalStructure s) {
    auto& list = s.x.instances[0];
    const KPoint far = make_point(Cyclotomic(1000), Cyclotomic(0));
    auto w = list[0];
    w.transformation = KMotion::translation(far) * w.transformation;
    list = {w, list[0], list[1]};
    s.recipe = "far copy first, then the first two slices of " + s.recipe;
    return s;
  });
}
void rotation_reduction_without_invariance(const RotationalStructure& s) {
  SYMMESH_PROOF_ASSERT(core::check_interface_conformity_up_to_rotation(s.x).holds, record(s),
                       picture(s));
  SYMMESH_PROOF_ASSERT(!core::structure_instance_conforming(core::apply_template(s.x)), record(s),
                       picture(s));
}

/// spec/lemmas.md#lemma-4-2-line-meshes over K_m: the boundary complexes split uniformly for a
/// random size h, decided face by face for all pairs and up to the rotation (pairs of copy 0 and a
/// copy k <= n/2);
/// both verdicts equal the direct check of AT of the written-out line meshes. `rotation` is the
/// count passed as rotation_copies (0: all pairs only).
void line_mesh_reduction_equals_direct(const RotationalStructure& s, std::size_t rotation) {
  const int num = *rc::gen::inRange(1, 4), den = *rc::gen::inRange(1, 9);
  const Cyclotomic h = Cyclotomic(mpq_class(num, den));
  for (const std::size_t r : {std::size_t(0), rotation}) {
    const auto c = uniform_case<Cyclotomic>(s.x, h, r);
    const auto v = line_mesh_verdicts(c);
    RC_TAG(v.direct ? "AT conforming" : "AT not conforming");
    auto t = s;
    t.x = c.actual;
    t.recipe = "line meshes for h = " + std::to_string(num) + "/" + std::to_string(den) +
               (r > 0 ? ", up to the rotation, of " : ", all pairs, of ") + s.recipe;
    SYMMESH_PROOF_ASSERT(v.face_by_face == v.direct, record(t), picture(t));
  }
}

void conclusion_only(const RotationalStructure& s) {
  SYMMESH_PROOF_ASSERT(core::structure_instance_conforming(core::apply_template(s.x)), record(s),
                       picture(s));
}

/// The checker and the direct test agree (Eq. 4.2 holds for every rotational structure); a
/// negative verdict names a genuinely neighbouring pair and condition (i).
void checker_agrees(const RotationalStructure& s) {
  well_formed(s, true);
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  const bool direct = core::structure_instance_conforming(si);
  RC_TAG(direct ? "AT conforming" : "AT not conforming");
  SYMMESH_PROOF_ASSERT(v.holds == direct, record(s), picture(s));
  SYMMESH_PROOF_ASSERT(direct == s.same_radii, record(s), picture(s));
  if (!v.holds) {
    const auto a = si.index_of(v.a), b = si.index_of(v.b);
    SYMMESH_PROOF_ASSERT(v.condition == 1, record(s), picture(s));
    SYMMESH_PROOF_ASSERT(a != b && core::geometry_interface_nonempty(si, a, b), record(s),
                         picture(s));
  }
}

/// Different radii: (i) fails on a pair of consecutive slices and AT is not conforming.
void different_radii(const RotationalStructure& s) {
  well_formed(s, true);
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  SYMMESH_PROOF_ASSERT(!v.holds && v.condition == 1, record(s), picture(s));
  // the failing pair is two consecutive slices: T_a^{-1} T_b = rot(±2π/n) (up to the global
  // motion, which cancels)
  const auto rel = s.x.tf(v.a).inverse() * s.x.tf(v.b);
  const auto f = CyclotomicField::get(s.m);
  const auto origin = make_point(0, 0);
  SYMMESH_PROOF_ASSERT(rel == rotation(f, 1, s.n, origin) || rel == rotation(f, -1, s.n, origin),
                       record(s), picture(s));
  SYMMESH_PROOF_ASSERT(!core::structure_instance_conforming(si), record(s), picture(s));
}

} // namespace

void register_lemma_4_2_cyclotomic(std::vector<Property>& p) {
  p.push_back(
      {kLemma, "cyclotomic_rotational_sufficiency_2d", 2, Kind::holds,
       "Lemma 4.2 over K_m: rotational templated meshes (a slice of angle 2π/n with "
       "equal radii on both rays, instanced by rot(2πi/n)) satisfy (i) and (ii) on all "
       "n(n-1)/2 neighbouring pairs, and AT is conforming with the ray vertices shared "
       "exactly",
       [] { return rc::detail::toProperty([] { sufficiency(*rotational_structure(true)); }); },
       [] {
         return rc::detail::toProperty([] { conclusion_only(*rotational_structure(false)); });
       }});
  p.push_back({kLemma,
               "cyclotomic_rotational_checker_agrees_2d",
               2,
               Kind::holds,
               "Lemma 4.2 and its converse over K_m: on rotational structures (equal or "
               "different radii) the interface-conformity checker's verdict equals the direct "
               "conformity check of AT (and equal radii), a failure naming a neighbouring pair "
               "and condition (i)",
               [] {
                 return rc::detail::toProperty(
                     [] { checker_agrees(*rotational_structure(chance(50))); });
               },
               {}});
  p.push_back({kLemma, "cyclotomic_rotation_reduction_agrees_2d", 2, Kind::holds,
               "Lemma 4.2 up to the rotation (pairs with copy 0 only; spec/lemmas.md#lemma-4-2-"
               "rotational) over K_m: on rotational structures (equal or different radii), on the "
               "meshes and on their boundary complexes, the verdict equals the direct check of AT",
               [] {
                 return rc::detail::toProperty(
                     [] { rotation_reduction_agrees(*rotational_structure(chance(50))); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { rotation_reduction_equals_direct(*not_rotation_invariant()); });
               }});
  p.push_back({kLemma, "cyclotomic_line_mesh_reduction_agrees_2d", 2, Kind::holds,
               "Lemma 4.2 face by face on uniform line meshes over K_m (spec/lemmas.md#lemma-4-2-"
               "line-meshes): the boundary complexes of rotational structures split for a random "
               "size, decided for all pairs and up to the rotation; both verdicts equal the "
               "direct check of AT of the written-out line meshes",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *rotational_structure(chance(50));
                   well_formed(s, true);
                   line_mesh_reduction_equals_direct(s, std::size_t(s.n));
                 });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { line_mesh_reduction_equals_direct(*not_rotation_invariant(), 1); });
               }});
  p.push_back(
      {kLemma,
       "cyclotomic_rotation_reduction_needs_invariance_2d",
       2,
       Kind::counterexample,
       "Without T_{i,k} = R^k ∘ T_{i,0} the reduction is unsound: a far copy listed first, then "
       "two non-conforming slices; no pair with copy 0 meets, the reduced check certifies, AT "
       "is not conforming",
       [] {
         return rc::detail::toProperty(
             [] { rotation_reduction_without_invariance(*not_rotation_invariant()); });
       },
       {}});
  p.push_back(
      {kLemma,
       "cyclotomic_different_radii_counterexample_2d",
       2,
       Kind::counterexample,
       "Lemma 4.2 over K_m without (i) (different interior radii on the two rays of the "
       "slice, same outer radius): the instances do not overlap, the checker reports "
       "condition (i) for two consecutive slices and AT is not conforming",
       [] { return rc::detail::toProperty([] { different_radii(*rotational_structure(false)); }); },
       {}});
}

} // namespace symmesh::proofs
