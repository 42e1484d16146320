// Lemma 2.1 (Intersection of meshes) — spec/lemmas.md#lemma-2-1
//
// For meshes M1, M2: (i) M1 ∩ M2 is finite, (ii) face-complete, (iii) conforming; (iv) if
// M1 ∪ M2 is conforming then us(M1 ∩ M2) = us(M1) ∩ us(M2). Figure 2.7 (a line and a vertex
// at an interior point of it) shows that (iv) needs the conforming union.
//
// The two meshes come over their own point arrays and are compared after exact vertex
// identification (core::unify), as element sets of points.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_2_1";

template <int D>
using Pair = Described<std::pair<Complex<D>, Complex<D>>>;

template <int D>
auto record(const Pair<D>& c) {
  return [&c] {
    return complexes_record<D>(kLemma, c.recipe, {{"M1", c.value.first}, {"M2", c.value.second}});
  };
}
template <int D>
auto picture(const Pair<D>& c) {
  return [&c] {
    return complex_picture<D>(core::set_union(core::unify(c.value.first, c.value.second).first,
                                              core::unify(c.value.first, c.value.second).second));
  };
}

/// us(M1) ∩ us(M2) ⊆ us(M1 ∩ M2), decided with witnesses: the relative interiors of the
/// elements of a face-complete conforming mesh partition its underlying space, so a point of
/// us(M1) ∩ us(M2) lies in relint(E1) ∩ relint(E2) for unique E1 ∈ M1, E2 ∈ M2, and it lies in
/// us(M1 ∩ M2) iff E1 = E2 ∈ M1 ∩ M2. Any point of relint(E1) ∩ relint(E2) (the LP witness)
/// therefore decides the pair. (⊇ holds trivially: every element of M1 ∩ M2 is in both.)
template <int D>
bool underlying_space_of_intersection_is_intersection(const Complex<D>& m1, const Complex<D>& m2) {
  const auto meet = core::intersection(m1, m2);
  for (const auto& e1 : m1.elements) {
    const auto p1 = m1.coords(e1);
    const auto b1 = core::box_of<Exact, D>(p1);
    for (const auto& e2 : m2.elements) {
      // equal elements are common ones; a proper face lies in the other's relative boundary
      if (e1.is_face_of(e2) || e2.is_face_of(e1)) continue;
      const auto p2 = m2.coords(e2);
      if (!b1.overlaps(core::box_of<Exact, D>(p2))) continue;
      const auto cp = core::common_point<Exact, D>({{p1, true}, {p2, true}});
      if (cp.strict_meet && !core::point_in_underlying_space(meet, cp.witness)) return false;
    }
  }
  return true;
}

/// (i)–(iii): M1 ∩ M2 is finite (no more elements than either mesh), face-complete, conforming.
template <int D>
void intersection_properties(const Pair<D>& c) {
  const auto [m1, m2] = core::unify(c.value.first, c.value.second);
  const auto meet = core::intersection(m1, m2);
  RC_TAG(meet.elements.empty() ? "empty intersection" : "non-empty intersection");
  SYMMESH_PROOF_ASSERT(meet.elements.size() <= std::min(m1.elements.size(), m2.elements.size()),
                       record(c), picture(c));
  SYMMESH_PROOF_ASSERT(core::is_face_complete(meet), record(c), picture(c));
  SYMMESH_PROOF_ASSERT(core::is_conforming(meet), record(c), picture(c));
}

/// (iv) with its hypothesis asserted first (the generator's promise).
template <int D>
void underlying_space(const Pair<D>& c, bool check_hypothesis) {
  const auto [m1, m2] = core::unify(c.value.first, c.value.second);
  if (check_hypothesis)
    SYMMESH_PROOF_ASSERT(core::is_conforming(core::set_union(m1, m2)), record(c), picture(c));
  SYMMESH_PROOF_ASSERT(underlying_space_of_intersection_is_intersection<D>(m1, m2), record(c),
                       picture(c));
}

/// Figure 2.7 family: the union is not conforming and us(M1 ∩ M2) != us(M1) ∩ us(M2).
template <int D>
void figure_2_7(const Pair<D>& c) {
  const auto [m1, m2] = core::unify(c.value.first, c.value.second);
  SYMMESH_PROOF_ASSERT(!core::is_conforming(core::set_union(m1, m2)), record(c), picture(c));
  SYMMESH_PROOF_ASSERT(!underlying_space_of_intersection_is_intersection<D>(m1, m2), record(c),
                       picture(c));
}

/// M1 is not face-complete (a cell lost a facet), M2 is its face completion.
template <int D>
Pair<D> with_completion(const Described<Complex<D>>& m) {
  return {{m.value, core::face_completion(m.value)}, m.recipe + "; M2 = fc(M1)"};
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma, "intersection_finite_face_complete_conforming" + d, D, Kind::holds,
               "Lemma 2.1 (i)-(iii): for two meshes (sub-meshes of one triangulation, or two "
               "different triangulations / Figure 2.7), M1 ∩ M2 is finite, face-complete and "
               "conforming",
               [] {
                 return rc::detail::toProperty([] {
                   intersection_properties<D>(*rc::gen::oneOf(
                       meshes_with_conforming_union<D>(), meshes_with_nonconforming_union<D>()));
                 });
               },
               [] {
                 return rc::detail::toProperty([] {
                   intersection_properties<D>(with_completion<D>(*non_face_complete_complex<D>()));
                 });
               }});
  p.push_back(
      {kLemma,
       "input_not_face_complete" + d,
       D,
       Kind::counterexample,
       "Lemma 2.1 (ii) without 'M1 is face-complete': M1 a triangulation missing one facet, "
       "M2 its face completion; M1 ∩ M2 is not face-complete",
       [] {
         return rc::detail::toProperty([] {
           const auto c = with_completion<D>(*non_face_complete_complex<D>());
           const auto [m1, m2] = core::unify(c.value.first, c.value.second);
           SYMMESH_PROOF_ASSERT(!core::is_face_complete(core::intersection(m1, m2)), record<D>(c),
                                picture<D>(c));
         });
       },
       {}});
  p.push_back({kLemma,
               "input_not_conforming" + d,
               D,
               Kind::counterexample,
               "Lemma 2.1 (iii) without 'M1 is conforming': M1 = M2 = the element union of two "
               "different triangulations of one point set; M1 ∩ M2 is not conforming",
               [] {
                 return rc::detail::toProperty([] {
                   const auto m = *nonconforming_complex<D>();
                   const Pair<D> c{{m.value, m.value}, m.recipe + "; M2 = M1"};
                   SYMMESH_PROOF_ASSERT(!core::is_conforming(core::intersection(m.value, m.value)),
                                        record<D>(c), picture<D>(c));
                 });
               },
               {}});
  p.push_back({kLemma, "underlying_space_of_intersection" + d, D, Kind::holds,
               "Lemma 2.1 (iv): if M1 ∪ M2 is conforming (sub-meshes of one triangulation, over "
               "separate point arrays) then us(M1 ∩ M2) = us(M1) ∩ us(M2)",
               [] {
                 return rc::detail::toProperty(
                     [] { underlying_space<D>(*meshes_with_conforming_union<D>(), true); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { underlying_space<D>(*meshes_with_nonconforming_union<D>(), false); });
               }});
  p.push_back({kLemma,
               "figure_2_7_counterexample" + d,
               D,
               Kind::counterexample,
               "Lemma 2.1 (iv) without the conforming union (Figure 2.7: a line and a vertex at a "
               "random interior rational point of it; two different triangulations): M1 ∪ M2 is "
               "not conforming and us(M1 ∩ M2) != us(M1) ∩ us(M2)",
               [] {
                 return rc::detail::toProperty(
                     [] { figure_2_7<D>(*meshes_with_nonconforming_union<D>()); });
               },
               {}});
}

} // namespace

void register_lemma_2_1(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
