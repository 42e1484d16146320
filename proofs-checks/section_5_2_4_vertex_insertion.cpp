// Section 5.2.4 (vertex insertion and refinement) — spec/adaptation.md#insertion
//
// Claims: (a) a point inserted strictly inside a template (the centroid of a random cell)
// gives a templated mesh whose AT is the input's with that cell split at every instance;
// (b) a point inserted on an instance interface facet of a template and, through the instances'
// transformations, at every related facet gives a templated mesh (Lemma 4.2 holds).
// Dropped hypothesis of (b) ("induces the insertion of vertices in all direct and indirect
// neighboring mesh templates"): the same point inserted in its own template only leaves the
// neighbour's facet whole, and AT is no longer conforming.
#include "proofs-checks/adaptation_support.h"
#include "proofs-checks/registry.h"
#include "symmesh/adapt/vertex_insertion.h"

namespace symmesh::proofs {
namespace {

using namespace gen;
using namespace adaptation;

constexpr const char* kClaim = "Section_5_2_4";

template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kClaim, s);
}
using gen::picture;

template <int D>
void interior_insertion_splits_every_instance(const GeneratedStructure<D>& s) {
  const auto& x = s.x;
  const auto i = std::size_t(*rc::gen::inRange<int>(0, int(x.templates.size())));
  const auto cells = x.templates[i].mesh.cells();
  const auto c = cells[std::size_t(*rc::gen::inRange<int>(0, int(cells.size())))];
  Structure<D> y = x;
  const auto v = adapt::insert_interior_vertex(y, i, centroid<D>(x, i, c));
  SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(y), record(s), picture(s));
  std::vector<core::Simplex> added;
  for (core::VertexId q : c) {
    std::vector<core::VertexId> ids;
    for (core::VertexId r : c) ids.push_back(r == q ? v : r);
    added.push_back(adapt::simplex_of(ids));
  }
  SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(y) ==
                           at_with_replaced_cells<D>(x, i, y.templates[i].mesh.points, {c}, added),
                       record(s), picture(s));
}

/// Inserts the centroid of a random interface facet: at every related facet (`related`), or in
/// its own template only. \pre x has an interface facet
template <int D>
Structure<D> insert_on_interface(const Structure<D>& x, bool related) {
  const auto facets = interface_facets<D>(x);
  RC_PRE(!facets.empty());
  const auto [i, f] = facets[std::size_t(*rc::gen::inRange<int>(0, int(facets.size())))];
  Structure<D> y = x;
  if (related) {
    const auto n = adapt::insert_boundary_vertex(y, i, centroid<D>(x, i, f));
    RC_TAG(n > 1 ? "inserted at related facets" : "one facet");
  } else {
    adapt::split_at(y, i, centroid<D>(x, i, f));
  }
  return y;
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kClaim,
               "interior_insertion_splits_every_instance" + d,
               D,
               Kind::holds,
               "Section 5.2.4: inserting the centroid of a random cell of a random template "
               "gives a templated mesh whose AT is the input's with that cell split at every "
               "instance",
               [] {
                 return rc::detail::toProperty([] {
                   interior_insertion_splits_every_instance<D>(*valid_templated_mesh<D>());
                 });
               },
               {}});
  p.push_back({kClaim, "boundary_insertion_at_related_facets_keeps_lemma_4_2" + d, D, Kind::holds,
               "Section 5.2.4: inserting the centroid of an instance interface facet into it and "
               "into every related facet (closed under the instances' transformations) gives a "
               "templated mesh",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *valid_templated_mesh<D>();
                   SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(insert_on_interface<D>(s.x, true)),
                                        record(s), picture(s));
                 });
               },
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *valid_templated_mesh<D>();
                   SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(insert_on_interface<D>(s.x, false)),
                                        record(s), picture(s));
                 });
               }});
}

} // namespace

void register_section_5_2_4(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
