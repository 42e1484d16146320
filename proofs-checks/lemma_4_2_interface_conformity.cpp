// Lemma 4.2 (Interface conformity) — spec/lemmas.md#lemma-4-2
//
// Γ a templated structure with mesh templates. If for all neighbouring instances
//  (i)  us(interf(Γ, T_a, T_b)) = interf_geo(Γ, T_a, T_b) and
//  (ii) T_a(IP_{a,b}) = T_b(IP_{b,a}),
// then AT(Γ) is conforming (Γ is a templated mesh).
//
// The core implements (i)–(ii) as a checker (core::check_interface_conformity); the conclusion
// is decided independently by the direct conformity test of AT (core::find_nonconformity over
// all elements of the structure instance). Both must agree: the lemma gives "checker ⇒ direct",
// its converse (AT conforming ⇒ (i), (ii) for structures obeying Eq. 4.2) gives the other way.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/interface_conformity.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_4_2";

/// Failure records of this lemma's generated structures (see generators.h).
template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kLemma, s);
}
using gen::picture;

/// The conclusion: AT(Γ) is conforming (that this makes it a multi-region mesh is checked in
/// at_multi_region_equivalence.cpp).
template <int D>
void conclusion(const GeneratedStructure<D>& s, const core::StructureInstance<Exact, D>& si) {
  SYMMESH_PROOF_ASSERT(core::structure_instance_conforming(si), record(s), picture(s));
}

/// holds: the valid tier satisfies (i) and (ii) on every neighbouring pair by construction
/// (Lemma 6.1 / 6.2, identical opposite sides, splitting a conforming mesh); the conclusion must
/// follow.
template <int D>
void sufficiency(const GeneratedStructure<D>& s) {
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  RC_TAG(v.pairs_checked > 0 ? "has neighbouring instances" : "no neighbours");
  SYMMESH_PROOF_ASSERT(v.holds, record(s), picture(s)); // the generator's promise
  conclusion<D>(s, si);
}

template <int D>
void conclusion_only(const GeneratedStructure<D>& s) {
  conclusion<D>(s, core::apply_template(s.x));
}

/// The checker and the direct test agree on templated structures (Eq. 4.2 holds); a negative
/// verdict names a genuinely neighbouring pair and condition 1 or 2.
template <int D>
void checker_agrees(const GeneratedStructure<D>& s) {
  SYMMESH_PROOF_ASSERT(!core::find_instance_overlap(s.x).has_value(), record(s), picture(s));
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  const bool direct = core::structure_instance_conforming(si);
  RC_TAG(direct ? "AT conforming" : "AT not conforming");
  SYMMESH_PROOF_ASSERT(v.holds == direct, record(s), picture(s));
  if (!v.holds) {
    const auto a = si.index_of(v.a), b = si.index_of(v.b);
    // Spec note: with exact vertex identification (i) alone decides a pair's conformity, so
    // (ii) never fails where (i) holds; the first failing condition is always (i).
    SYMMESH_PROOF_ASSERT(v.condition == 1, record(s), picture(s));
    SYMMESH_PROOF_ASSERT(a != b && core::geometry_interface_nonempty(si, a, b), record(s),
                         picture(s));
  }
}

/// On every input (Eq. 4.2 possibly violated) the checker is sound: it never certifies a
/// non-conforming AT. Where Eq. 4.2 holds it also agrees with the direct test.
template <int D>
void checker_sound(const GeneratedStructure<D>& s) {
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  const bool direct = core::structure_instance_conforming(si);
  const bool structure = !core::find_instance_overlap(s.x).has_value();
  RC_TAG(structure ? "templated structure" : "instances overlap");
  SYMMESH_PROOF_ASSERT(!v.holds || direct, record(s), picture(s));
  if (structure) SYMMESH_PROOF_ASSERT(v.holds == direct, record(s), picture(s));
}

/// Figure 4.4: the interface side (face) is split differently in the two instances: (i) fails
/// on that pair and AT is not conforming.
template <int D>
void figure_4_4(const GeneratedStructure<D>& s) {
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  SYMMESH_PROOF_ASSERT(!v.holds && v.condition == 1, record(s), picture(s));
  SYMMESH_PROOF_ASSERT(!core::structure_instance_conforming(si), record(s), picture(s));
}

/// spec/lemmas.md#lemma-4-2-boundary: with Eq. 4.2, Lemma 4.2 on the boundary complexes
/// (what `symmesh generate` certifies with) gives the verdict of the direct check of AT(Γ).
template <int D>
void reduction_equals_direct(const GeneratedStructure<D>& s) {
  const auto v = core::check_interface_conformity_on_boundaries(s.x);
  const bool direct = core::structure_instance_conforming(core::apply_template(s.x));
  RC_TAG(direct ? "AT conforming" : "AT not conforming");
  SYMMESH_PROOF_ASSERT(v.holds == direct, record(s), picture(s));
}

template <int D>
void boundary_reduction_agrees(const GeneratedStructure<D>& s) {
  SYMMESH_PROOF_ASSERT(!core::find_instance_overlap(s.x).has_value(), record(s), picture(s));
  reduction_equals_direct<D>(s);
}

/// Eq. 4.2 dropped: a triangulation and a small simplex strictly inside one of its cells (both
/// instanced by the identity). The boundaries do not meet, so the reduction certifies, while
/// AT(Γ) is not conforming.
template <int D>
rc::Gen<GeneratedStructure<D>> simplex_inside_a_cell() {
  return rc::gen::exec([] {
    const auto c = *rc::gen::suchThat(triangulation<D>(), [](const Described<Complex<D>>& t) {
      return t.value.cell_dimension() == D;
    });
    const auto& m = c.value;
    core::Simplex cell{};
    for (const auto& e : m.elements)
      if (e.dim() == D) {
        cell = e;
        break;
      }
    const auto corners = m.coords(cell);
    Point<D> centroid;
    for (int d = 0; d < D; ++d) {
      Exact sum = 0;
      for (const auto& q : corners) sum += q[d];
      centroid[d] = sum / Exact(D + 1);
    }
    PointSet<D> inner;
    for (const auto& q : corners) {
      Point<D> r;
      for (int d = 0; d < D; ++d) r[d] = centroid[d] + (q[d] - centroid[d]) / Exact(4);
      inner.push_back(r);
    }
    GeneratedStructure<D> s;
    s.x.templates.push_back({"mesh", core::TemplateKind::mesh, m});
    s.x.templates.push_back({"inner simplex", core::TemplateKind::mesh, simplex_complex<D>(inner)});
    s.x.instances = {{core::InstanceSpec<Exact, D>{}}, {core::InstanceSpec<Exact, D>{}}};
    s.recipe = "a simplex shrunk by 1/4 inside a cell of " + c.recipe;
    return s;
  });
}

template <int D>
void boundary_reduction_without_eq_4_2(const GeneratedStructure<D>& s) {
  SYMMESH_PROOF_ASSERT(core::check_interface_conformity_on_boundaries(s.x).holds, record(s),
                       picture(s));
  SYMMESH_PROOF_ASSERT(!core::structure_instance_conforming(core::apply_template(s.x)), record(s),
                       picture(s));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma, "sufficiency" + d, D, Kind::holds,
       "Lemma 4.2: on valid templated meshes (reflections, orthogonal reflections, "
       "translation grids with identical opposite sides, multi-template splits, global "
       "motions) (i) and (ii) hold for all neighbouring instances and AT is conforming "
       "and a valid multi-region mesh",
       [] { return rc::detail::toProperty([] { sufficiency<D>(*valid_templated_mesh<D>()); }); },
       [] {
         return rc::detail::toProperty([] { conclusion_only<D>(*figure_4_4_structure<D>()); });
       }});
  p.push_back(
      {kLemma,
       "checker_agrees_with_direct" + d,
       D,
       Kind::holds,
       "Lemma 4.2 and its converse: on templated structures (valid and Figure 4.4-like) "
       "the interface-conformity checker's verdict equals the direct conformity check of "
       "AT, and a failure names a neighbouring pair and condition (i) (spec note: (i) "
       "implies (ii) under exact vertex identification)",
       [] { return rc::detail::toProperty([] { checker_agrees<D>(*templated_structure<D>()); }); },
       {}});
  p.push_back(
      {kLemma,
       "checker_sound_on_any_input" + d,
       D,
       Kind::holds,
       "Lemma 4.2 checker on any structure (overlapping instances included): it never "
       "certifies a non-conforming AT, and agrees with the direct check where Eq. 4.2 holds",
       [] { return rc::detail::toProperty([] { checker_sound<D>(*any_structure<D>()); }); },
       {}});
  p.push_back(
      {kLemma,
       "figure_4_4_counterexample" + d,
       D,
       Kind::counterexample,
       "Lemma 4.2 without (i) (Figure 4.4): a translated template whose interface side is "
       "subdivided differently; the checker reports condition (i) and AT is not conforming",
       [] { return rc::detail::toProperty([] { figure_4_4<D>(*figure_4_4_structure<D>()); }); },
       {}});
  p.push_back(
      {kLemma, "boundary_reduction_agrees" + d, D, Kind::holds,
       "Lemma 4.2 on the templates' boundary complexes (the generator's certificate): on "
       "templated structures (Eq. 4.2) its verdict equals the direct conformity check of AT",
       [] {
         return rc::detail::toProperty(
             [] { boundary_reduction_agrees<D>(*templated_structure<D>()); });
       },
       [] {
         return rc::detail::toProperty(
             [] { reduction_equals_direct<D>(*simplex_inside_a_cell<D>()); });
       }});
  p.push_back(
      {kLemma,
       "boundary_reduction_needs_eq_4_2" + d,
       D,
       Kind::counterexample,
       "Without Eq. 4.2 the boundary reduction is unsound: a simplex strictly inside a cell "
       "of another instance has disjoint boundaries (certified) but AT is not conforming",
       [] {
         return rc::detail::toProperty(
             [] { boundary_reduction_without_eq_4_2<D>(*simplex_inside_a_cell<D>()); });
       },
       {}});
}

} // namespace

void register_lemma_4_2(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
