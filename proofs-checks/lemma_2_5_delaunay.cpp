// Lemma 2.5 (Delaunay Lemma) — spec/lemmas.md#lemma-2-5
//
// For a simplex mesh M in R^n with DIM_cell(M) = n: M is Delaunay ⇔ every facet is Delaunay in
// M ⇔ every facet is locally Delaunay in M.
//
// Spec correction: the lemma (Shewchuk's Delaunay Lemma) needs M to be a triangulation of its
// vertex set, i.e. us(M) convex; the dissertation omits this. The holds property runs on
// triangulations (Delaunay and regular, i.e. Delaunay and non-Delaunay); the counterexample is a
// non-convex mesh (two flat simplices touching in a vertex) whose facets are all locally
// Delaunay while a cell's circumball holds the other simplex's vertices.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/delaunay.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_2_5";

/// Failure records of this lemma's single-mesh cases (see generators.h).
template <int D>
auto record(const std::string& recipe, const Complex<D>& m) {
  return complex_failure_record<D>(kLemma, recipe, m);
}

template <int D>
void equivalence(const Complex<D>& m, const std::string& recipe) {
  const bool delaunay = core::is_delaunay_mesh(m);
  const bool facets = core::all_facets_delaunay(m);
  const bool local = core::all_facets_locally_delaunay(m);
  RC_TAG(delaunay ? "Delaunay" : "not Delaunay");
  SYMMESH_PROOF_ASSERT(delaunay == facets && facets == local, record<D>(recipe, m), picture<D>(m));
  // CGAL's exact Delaunay triangulation must be recognised as Delaunay
  if (recipe.rfind("delaunay", 0) == 0)
    SYMMESH_PROOF_ASSERT(delaunay, record<D>(recipe, m), picture<D>(m));
}

template <int D>
Complex<D> structure_instance_mesh(const GeneratedStructure<D>& s) {
  return core::apply_template(s.x).at.mesh;
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma, "delaunay_lemma" + d, D, Kind::holds,
               "Lemma 2.5: on triangulations of point sets (exact Delaunay, and regular "
               "triangulations with random weights, mostly not Delaunay) 'M is Delaunay', 'every "
               "facet is Delaunay' and 'every facet is locally Delaunay' agree",
               [] {
                 return rc::detail::toProperty([] {
                   const auto m = *triangulation<D>();
                   equivalence<D>(m.value, m.recipe);
                 });
               },
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *flat_simplex_v_shape<D>();
                   equivalence<D>(structure_instance_mesh<D>(s), s.recipe);
                 });
               }});
  p.push_back({kLemma,
               "non_convex_mesh" + d,
               D,
               Kind::counterexample,
               "Lemma 2.5 needs us(M) = conv(vertices(M)) (missing in the dissertation): a flat "
               "simplex and its mirror image across a tilted hyperplane through one vertex form a "
               "mesh whose facets are all locally Delaunay but which is not Delaunay",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *flat_simplex_v_shape<D>();
                   const auto m = structure_instance_mesh<D>(s);
                   SYMMESH_PROOF_ASSERT(core::all_facets_locally_delaunay(m) &&
                                            !core::is_delaunay_mesh(m),
                                        record<D>(s.recipe, m), picture<D>(m));
                 });
               },
               {}});
}

} // namespace

void register_lemma_2_5(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
