// Lemma 2.6 (Constrained Delaunay Lemma) — spec/lemmas.md#lemma-2-6
//
// For a multi-region PLC P and a simplex mesh M with DIM_cell(M) = n that respects and
// geometry-conforms to P: M is constrained Delaunay ⇔ every facet of M not included in a facet of
// P is constrained Delaunay ⇔ every such facet is locally Delaunay.
//
// Spec correction: the lemma (Shewchuk's) needs M to be a triangulation of P, i.e. also
// vertices(M) = vertices(P); the dissertation omits this, and Def 2.23 makes every simplex with a
// Steiner vertex not constrained Delaunay, so "locally Delaunay ⇒ constrained Delaunay" fails
// without it (counterexample `steiner_vertex`). The holds property runs on exact CDTs, on CDTs
// with flipped edges and on Delaunay and regular tetrahedralizations with regions (constrained
// Delaunay and not), and on Lemma 2.5's V-shaped counterexamples with P = their boundary: those
// are constrained Delaunay although not Delaunay, which is what Lemma 2.6 says of them.
#include "proofs-checks/plc_generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/constrained_delaunay.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_2_6";

template <int D>
auto record(const PlcCase<D>& c) {
  return [&c] { return plc_case_record<D>(kLemma, c); };
}
template <int D>
auto picture(const PlcCase<D>& c) {
  return [&c] { return complex_picture<D>(c.mesh.mesh); };
}

struct Statements {
  bool constrained_delaunay = false, free_facets_cd = false, free_facets_ld = false;
};

template <int D>
Statements statements(const PlcCase<D>& c) {
  const core::ConstrainedDelaunay<Exact, D> cd(c.plc, c.mesh.mesh);
  return {cd.mesh_is_constrained_delaunay(), cd.free_facets_constrained_delaunay(),
          cd.free_facets_locally_delaunay()};
}

/// The conclusion: the three statements agree.
template <int D>
void equivalence(const PlcCase<D>& c) {
  const auto s = statements<D>(c);
  RC_TAG(s.constrained_delaunay ? "constrained Delaunay" : "not constrained Delaunay");
  SYMMESH_PROOF_ASSERT(s.constrained_delaunay == s.free_facets_cd &&
                           s.free_facets_cd == s.free_facets_ld,
                       record<D>(c), picture<D>(c));
  if (c.recipe.rfind("Lemma 2.5", 0) == 0) { // Lemma 2.6 is what Lemma 2.5's counterexample meets
    RC_TAG("Lemma 2.5 V-shape");
    SYMMESH_PROOF_ASSERT(s.constrained_delaunay && !core::is_delaunay_mesh(c.mesh.mesh),
                         record<D>(c), picture<D>(c));
  }
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma, "constrained_delaunay_lemma" + d, D, Kind::holds,
               "Lemma 2.6: for a triangulation M of a multi-region PLC P (CDTs, CDTs after flips, "
               "Delaunay and regular tetrahedralizations with regions and holes, Lemma 2.5's "
               "V-shapes with P = their boundary) 'M is constrained Delaunay', 'every facet not "
               "in a facet of P is constrained Delaunay' and 'every such facet is locally "
               "Delaunay' agree; the V-shapes are constrained Delaunay but not Delaunay",
               [] {
                 return rc::detail::toProperty([] {
                   const auto c = *plc_with_triangulation<D>();
                   // the rest of "M is a triangulation of P" is checked (std::invalid_argument)
                   // by ConstrainedDelaunay's constructor: P multi-region, M a D-mesh respecting
                   // P with us(M) = us(P)
                   SYMMESH_PROOF_ASSERT(core::same_vertices(c.mesh.mesh, c.plc), record<D>(c),
                                        picture<D>(c));
                   equivalence<D>(c);
                 });
               },
               [] {
                 return rc::detail::toProperty([] {
                   const auto c = *plc_with_steiner_triangulation<D>();
                   equivalence<D>(c);
                 });
               }});
  p.push_back({kLemma,
               "steiner_vertex" + d,
               D,
               Kind::counterexample,
               "Lemma 2.6 needs vertices(M) = vertices(P) (missing in the dissertation): with one "
               "Steiner vertex in a Delaunay triangulation M of a PLC's vertices, every facet not "
               "in a facet of P is locally Delaunay, but M is not constrained Delaunay",
               [] {
                 return rc::detail::toProperty([] {
                   const auto c = *plc_with_steiner_triangulation<D>();
                   const auto s = statements<D>(c);
                   SYMMESH_PROOF_ASSERT(!core::same_vertices(c.mesh.mesh, c.plc) &&
                                            s.free_facets_ld && !s.constrained_delaunay,
                                        record<D>(c), picture<D>(c));
                 });
               },
               {}});
  p.push_back({kLemma,
               "facet_inside_plc_facet" + d,
               D,
               Kind::counterexample,
               "Lemma 2.6 counts only facets not included in a facet of P: two flat simplices "
               "across an interface facet form a constrained Delaunay mesh (the lemma's three "
               "statements hold) whose interface facet is not locally Delaunay",
               [] {
                 return rc::detail::toProperty([] {
                   const auto c = *flat_pair_across_interface<D>();
                   const auto s = statements<D>(c);
                   SYMMESH_PROOF_ASSERT(s.constrained_delaunay && s.free_facets_cd &&
                                            s.free_facets_ld &&
                                            !core::all_facets_locally_delaunay(c.mesh.mesh),
                                        record<D>(c), picture<D>(c));
                 });
               },
               {}});
}

} // namespace

void register_lemma_2_6(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
