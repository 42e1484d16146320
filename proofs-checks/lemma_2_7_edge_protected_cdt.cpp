// Lemma 2.7 (Constrained Delaunay mesh of an edge-protected PLC) — spec/lemmas.md#lemma-2-7
//
// For an edge-protected multi-region PLC (P, ξ̃) there is a triangulation (M, ξ) of the vertices
// of P that is constrained Delaunay and geometry-conforms to (P, ξ̃).
//
// The triangulation is constructed with CGAL (2D: exact constrained Delaunay triangulation of the
// vertices and segments; 3D: per region, the exact Delaunay tetrahedralization of the region's
// vertices, for PLCs in general position) and checked with the core's own predicates only:
// a mesh, vertices(M) = vertices(P), M respects P, region-wise geometry-conformity, and Def 2.23
// on every cell (visibility decided exactly). In 2D the hypothesis is not needed (every PLC in
// the plane has a CDT, as the dissertation remarks); the 2D property runs on PLCs with and
// without edge protection, and the 2D counterexample drops condition (iv) of Def 2.3 instead
// (crossing segments). In 3D the counterexample is Schönhardt's prism: not edge-protected, and an
// exhaustive search shows that no triangulation of its vertices exists at all.
#include "proofs-checks/plc_generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/constrained_delaunay.h"
#include "symmesh/core/edge_protected.h"

#include <sstream>

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_2_7";

template <int D>
auto record(const std::string& recipe, const Plc<D>& p, const MultiRegion<D>& m) {
  return [recipe, &p, &m] {
    return complexes_record<D>(kLemma, recipe, {{"P carrier", p.carrier}, {"M", m.mesh}});
  };
}
template <int D>
auto picture(const MultiRegion<D>& m) {
  return [&m] { return complex_picture<D>(m.mesh); };
}

/// The conclusion on the construction: (M, ξ) is a constrained Delaunay triangulation of P.
template <int D>
void conclusion(const Described<Plc<D>>& p) {
  const auto m = constrained_delaunay_construction<D>(p.value);
  std::ostringstream why;
  bool ok = false;
  try {
    ok = core::is_constrained_delaunay_triangulation(m, p.value, &why);
  } catch (const std::invalid_argument& e) {
    why << e.what();
  }
  if (!ok) RC_LOG() << why.str() << "\n";
  SYMMESH_PROOF_ASSERT(ok, record<D>(p.recipe, p.value, m), picture<D>(m));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma, "edge_protected_plc_has_cdt" + d, D, Kind::holds,
       D == 2 ? "Lemma 2.7 in the plane (no edge protection needed): for random multi-region PLCs "
                "(segments, holes, dangling segments) CGAL's exact CDT is a triangulation of "
                "the vertices of P that respects P, geometry-conforms to (P, xi~) and is "
                "constrained Delaunay (checked by Def 2.23 exactly)"
              : "Lemma 2.7: for edge-protected multi-region PLCs in general position (PLCs of "
                "Delaunay tetrahedralizations with regions and holes, two convex pieces glued "
                "along a triangle) the per-region Delaunay tetrahedralization is a triangulation "
                "of the vertices of P that respects P, geometry-conforms to (P, xi~) and is "
                "constrained Delaunay (checked by Def 2.23 exactly)",
       [] {
         return rc::detail::toProperty([] {
           const auto plc = *plc_for_cdt<D>();
           std::ostringstream why;
           bool hyp = plc.value.is_multi_region(&why);
           const bool protected_ = core::is_edge_protected(plc.value);
           RC_TAG(protected_ ? "edge-protected" : "not edge-protected");
           if (D == 3) hyp = hyp && protected_;
           if (!hyp) RC_LOG() << why.str() << "\n";
           const MultiRegion<D> none;
           SYMMESH_PROOF_ASSERT(hyp, record<D>(plc.recipe, plc.value, none), picture<D>(none));
           conclusion<D>(plc);
         });
       },
       [] { return rc::detail::toProperty([] { conclusion<D>(*plc_without_cdt<D>()); }); }});
  p.push_back(
      {kLemma,
       D == 2 ? "crossing_segments_2d" : "schonhardt_prism_3d",
       D,
       Kind::counterexample,
       D == 2 ? "Lemma 2.7 needs a PLC: two crossing segments (Def 2.3 (iv) fails) leave no "
                "triangulation of the vertices that respects them (exhaustive search)"
              : "Lemma 2.7 needs edge protection: Schönhardt's twisted prism is a PLC that is not "
                "edge-protected, and no set of tetrahedra on its vertices triangulates it "
                "(exhaustive search)",
       [] {
         return rc::detail::toProperty([] {
           const auto plc = *plc_without_cdt<D>();
           const MultiRegion<D> none;
           bool dropped = false;
           if constexpr (D == 2) {
             dropped = !plc.value.is_valid();
           } else {
             dropped = plc.value.is_multi_region() && !core::is_edge_protected(plc.value);
           }
           SYMMESH_PROOF_ASSERT(dropped && !triangulation_of_vertices_exists<D>(plc.value),
                                record<D>(plc.recipe, plc.value, none), picture<D>(none));
         });
       },
       {}});
  p.push_back({kLemma,
               "cdt_not_delaunay" + d,
               D,
               Kind::counterexample,
               "Lemma 2.7 promises a constrained Delaunay mesh, not a Delaunay one: for two flat "
               "simplices across an interface the constructed CDT is constrained Delaunay but "
               "neither Delaunay nor locally Delaunay at the interface facet",
               [] {
                 return rc::detail::toProperty([] {
                   const auto c = *flat_pair_across_interface<D>();
                   const auto m = constrained_delaunay_construction<D>(c.plc);
                   SYMMESH_PROOF_ASSERT(core::is_constrained_delaunay_triangulation(m, c.plc) &&
                                            !core::is_delaunay_mesh(m.mesh) &&
                                            !core::all_facets_locally_delaunay(m.mesh),
                                        record<D>(c.recipe, c.plc, m), picture<D>(m));
                 });
               },
               {}});
}

} // namespace

void register_lemma_2_7(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
