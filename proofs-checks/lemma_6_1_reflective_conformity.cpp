// Lemma 6.1 (Reflective symmetry conformity) — spec/lemmas.md#lemma-6-1
//
// For a mesh M with n·x >= d on us(M), Γ = ((M, (I, refl_{n,d}), (r1, r2))) is a templated mesh:
// a templated structure (Eq. 4.2) whose structure instance is conforming. The generator uses
// rational, not only axis-parallel, normals, several / one / no template points exactly on the
// hyperplane, and one global rigid motion (which turns the pair into (g, g∘refl) or conjugates
// it); the hypothesis is checked on the template against the fixed hyperplane of T_1^{-1} T_2.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/interface_conformity.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_6_1";

/// Failure records of this lemma's generated structures (see generators.h).
template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kLemma, s);
}
using gen::picture;

/// R = T_1^{-1} ∘ T_2 is a reflection (R ≠ I, R∘R = I, det = -1) and the template lies on one
/// side of its fixed hyperplane: p - R(p) = 2((n·p - d)/(n·n)) n, so the signs of the
/// multiples agree.
template <int D>
bool template_on_one_side(const Structure<D>& x) {
  const auto r = x.instances[0][0].transformation.inverse() * x.instances[0][1].transformation;
  if (r.is_identity() || !(r * r).is_identity() || r.determinant_of_linear_part() != Exact(-1))
    return false;
  const auto& pts = x.templates[0].mesh.points;
  Point<D> ref = core::zero_point<Exact, D>();
  for (const auto& p : pts)
    if (p != r(p)) {
      ref = p - r(p);
      break;
    }
  for (const auto& p : pts)
    if (core::dot<Exact, D>(p - r(p), ref) < 0) return false;
  return true;
}

template <int D>
void reflective_conclusion(const GeneratedStructure<D>& s) {
  SYMMESH_PROOF_ASSERT(!core::find_instance_overlap(s.x).has_value(), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(core::structure_instance_conforming(core::apply_template(s.x)), record(s),
                       picture(s));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma, "reflective_templated_mesh" + d, D, Kind::holds,
               "Lemma 6.1: a template mesh on the positive side of a rational hyperplane (several, "
               "one or no points on it), instanced by I and refl_{n,d} (with any regions, after a "
               "global rigid motion), is a templated structure with conforming AT",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *reflective_structure<D>();
                   RC_TAG(s.recipe.find("several on H") != std::string::npos ? "interface facet"
                                                                             : "touching or apart");
                   SYMMESH_PROOF_ASSERT(template_on_one_side<D>(s.x), record<D>(s), picture<D>(s));
                   reflective_conclusion<D>(s);
                 });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { reflective_conclusion<D>(*crossing_reflective_structure<D>()); });
               }});
  p.push_back({kLemma,
               "template_crossing_hyperplane" + d,
               D,
               Kind::counterexample,
               "Lemma 6.1 without n·x >= d on the template (a cell with vertices strictly on both "
               "sides): the two instances overlap, so Γ is not a templated structure",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *crossing_reflective_structure<D>();
                   SYMMESH_PROOF_ASSERT(!template_on_one_side<D>(s.x), record<D>(s), picture<D>(s));
                   SYMMESH_PROOF_ASSERT(core::find_instance_overlap(s.x).has_value(), record<D>(s),
                                        picture<D>(s));
                 });
               },
               {}});
}

} // namespace

void register_lemma_6_1(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
