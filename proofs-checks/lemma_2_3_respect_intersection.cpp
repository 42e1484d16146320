// Lemma 2.3 (Respectness of intersection) — spec/lemmas.md#lemma-2-3
//
// If E respects A and E respects B then E respects A ∩ B. Here E is a simplex (any dimension
// <= D) and A, B are convex polytopes given by point sets; respect is decided exactly by
// core::respects (E ∩ X is a union of faces of E).
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/respect.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_2_3";

template <int D>
auto record(const Described<RespectCase<D>>& c) {
  return [&c] {
    return complexes_record<D>(kLemma, c.recipe, {{"E", simplex_complex<D>(c.value.e)}});
  };
}
template <int D>
auto picture(const Described<RespectCase<D>>& c) {
  return [&c] { return complex_picture<D>(simplex_complex<D>(c.value.e)); };
}

template <int D>
bool respects_intersection(const RespectCase<D>& r) {
  return core::respects<Exact, D>(r.e, {r.a, r.b});
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma, "respect_of_intersection" + d, D, Kind::holds,
       "Lemma 2.3: a simplex E respecting convex sets A and B (containing E, disjoint from "
       "it, meeting it in a face, or random) respects A ∩ B",
       [] {
         return rc::detail::toProperty([] {
           const auto c = *respect_both<D>();
           SYMMESH_PROOF_ASSERT(respects_intersection<D>(c.value), record<D>(c), picture<D>(c));
         });
       },
       [] {
         return rc::detail::toProperty([] {
           const auto c = *respect_one_only<D>();
           SYMMESH_PROOF_ASSERT(respects_intersection<D>(c.value), record<D>(c), picture<D>(c));
         });
       }});
  p.push_back(
      {kLemma,
       "b_not_respected" + d,
       D,
       Kind::counterexample,
       "Lemma 2.3 without 'E respects B' (B a simplex whose facet hyperplane cuts E through "
       "its centroid, A containing E): E respects A, not B, and not A ∩ B",
       [] {
         return rc::detail::toProperty([] {
           const auto c = *respect_one_only<D>();
           SYMMESH_PROOF_ASSERT((core::respects<Exact, D>(c.value.e, {c.value.a})), record<D>(c),
                                picture<D>(c));
           SYMMESH_PROOF_ASSERT((!core::respects<Exact, D>(c.value.e, {c.value.b})), record<D>(c),
                                picture<D>(c));
           SYMMESH_PROOF_ASSERT(!respects_intersection<D>(c.value), record<D>(c), picture<D>(c));
         });
       },
       {}});
}

} // namespace

void register_lemma_2_3(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
