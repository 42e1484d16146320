// Lemma 4.5 (Template-aware Delaunay Lemma) — spec/lemmas.md#lemma-4-5
//
// Γ a templated mesh. If every facet E of every mesh template is template-aware locally
// Delaunay (T_{i,j}(E) is locally Delaunay in AT(Γ) for all instances, Def 4.10), then AT(Γ) is
// Delaunay.
//
// Spec correction: the proof uses Lemma 2.5 on AT(Γ), which needs us(AT(Γ)) convex; the
// dissertation omits this. The holds property runs on templated meshes with convex AT
// (reflected frame boxes, orthant corner simplices, translation grids of boxes); one
// counterexample drops the convexity (a flat simplex and its mirror image touching in a vertex:
// every facet is template-aware locally Delaunay, AT is not Delaunay), the other drops the
// template-aware locally Delaunay property (a flat simplex mirrored across its own base facet).
#include "proofs-checks/generators.h"
#include "symmesh/core/template_aware_delaunay.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/delaunay.h"
#include "symmesh/core/interface_conformity.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_4_5";

/// Failure records of this lemma's generated structures (see generators.h).
template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kLemma, s);
}
using gen::picture;

/// Def 4.10 for every facet of every template: T_{i,g}(E) is locally Delaunay in AT(Γ).
template <int D>
bool all_template_facets_tald(const Structure<D>& x, const core::StructureInstance<Exact, D>& si) {
  return core::all_template_facets_template_aware_locally_delaunay(x, si);
}

template <int D>
void template_aware_delaunay(const GeneratedStructure<D>& s, bool check_hypotheses) {
  const auto si = core::apply_template(s.x);
  if (check_hypotheses) { // the generator's promise: convex AT, TALD facets
    SYMMESH_PROOF_ASSERT(s.convex, record(s), picture(s));
    SYMMESH_PROOF_ASSERT(all_template_facets_tald<D>(s.x, si), record(s), picture(s));
  }
  SYMMESH_PROOF_ASSERT(core::is_delaunay_mesh(si.at.mesh), record(s), picture(s));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma, "template_aware_delaunay" + d, D, Kind::holds,
               "Lemma 4.5: for templated meshes with convex AT (Delaunay templates with no "
               "encroached interface facet: reflections, orthogonal reflections, translation "
               "grids, splits, global motions) whose template facets are all template-aware "
               "locally Delaunay, AT is Delaunay",
               [] {
                 return rc::detail::toProperty(
                     [] { template_aware_delaunay<D>(*delaunay_templated_mesh<D>(), true); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { template_aware_delaunay<D>(*encroached_reflection<D>(), false); });
               }});
  p.push_back(
      {kLemma,
       "facet_not_template_aware_locally_delaunay" + d,
       D,
       Kind::counterexample,
       "Lemma 4.5 without template-aware locally Delaunay facets (a flat simplex mirrored "
       "across its base facet): the base facet is not TALD and AT is not Delaunay",
       [] {
         return rc::detail::toProperty([] {
           const auto s = *encroached_reflection<D>();
           const auto si = core::apply_template(s.x);
           SYMMESH_PROOF_ASSERT(!all_template_facets_tald<D>(s.x, si), record<D>(s), picture<D>(s));
           SYMMESH_PROOF_ASSERT(!core::is_delaunay_mesh(si.at.mesh), record<D>(s), picture<D>(s));
         });
       },
       {}});
  p.push_back(
      {kLemma,
       "non_convex_structure_instance" + d,
       D,
       Kind::counterexample,
       "Lemma 4.5 needs us(AT) convex (missing in the dissertation): a flat simplex and its "
       "mirror image across a tilted hyperplane through one vertex is a templated mesh whose "
       "template facets are all TALD, yet AT is not Delaunay",
       [] {
         return rc::detail::toProperty([] {
           const auto s = *flat_simplex_v_shape<D>();
           const auto si = core::apply_template(s.x);
           SYMMESH_PROOF_ASSERT(core::structure_instance_conforming(si), record<D>(s),
                                picture<D>(s));
           SYMMESH_PROOF_ASSERT(all_template_facets_tald<D>(s.x, si), record<D>(s), picture<D>(s));
           SYMMESH_PROOF_ASSERT(!core::is_delaunay_mesh(si.at.mesh), record<D>(s), picture<D>(s));
         });
       },
       {}});
}

} // namespace

void register_lemma_4_5(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
