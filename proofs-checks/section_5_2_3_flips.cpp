// Section 5.2.3 (flips) — spec/adaptation.md#flips
//
// Claim: a flip of an interior face of a mesh template (2-2 in 2D; 2-3 and 3-2 in 3D) maps a
// templated mesh to a templated mesh, and its structure instance is AT with the same flip made
// at every instance of the template.
// Counterexample (dropped hypothesis "the flipped cells are in one template instance",
// Figure 5.13): the flip of the two AT cells on either side of an instance interface facet,
// pulled back into the first cell's template, breaks Lemma 4.2 — the template now reaches into
// its neighbour, so instances overlap or AT is no longer conforming.
#include "proofs-checks/adaptation_support.h"
#include "proofs-checks/registry.h"
#include "symmesh/adapt/flips.h"

namespace symmesh::proofs {
namespace {

using namespace gen;
using namespace adaptation;

constexpr const char* kClaim = "Section_5_2_3";

template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kClaim, s);
}
using gen::picture;

/// Tries the flips of template i's faces from a random starting place; the first one made.
template <int D>
adapt::FlipResult first_flip(Structure<D>& y, std::size_t i) {
  std::vector<core::Simplex> faces;
  const auto& m = y.templates[i].mesh;
  for (const auto& e : m.elements)
    if (e.dim() == D - 1 || (D == 3 && e.dim() == 1)) faces.push_back(e);
  if (faces.empty()) return {};
  const auto start = std::size_t(*rc::gen::inRange<int>(0, int(faces.size())));
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const auto& f = faces[(start + k) % faces.size()];
    adapt::FlipResult r;
    if constexpr (D == 2)
      r = adapt::flip_2_2(y, i, f);
    else
      r = f.dim() == 2 ? adapt::flip_2_3(y, i, f) : adapt::flip_3_2(y, i, f);
    if (r) return r;
  }
  adapt::FlipResult none;
  none.refused = "no flippable face";
  return none;
}

template <int D>
void flip_is_the_flip_at_every_instance(const GeneratedStructure<D>& s) {
  const auto& x = s.x;
  const auto i = std::size_t(*rc::gen::inRange<int>(0, int(x.templates.size())));
  Structure<D> y = x;
  const auto r = first_flip<D>(y, i);
  RC_TAG(r ? "flipped" : "no flippable face");
  if (!r) {
    SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(y) == adapt::structure_instance_cells(x),
                         record(s), picture(s));
    return;
  }
  SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(y), record(s), picture(s));
  const auto expected =
      at_with_replaced_cells<D>(x, i, x.templates[i].mesh.points, r.removed, r.added);
  SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(y) == expected, record(s), picture(s));
}

/// The flip of the cells on both sides of an interface facet, pulled back into one template:
/// template i's cell (f, a) becomes the cells (f \ q, a, b'') for every vertex q of f, where b''
/// is the neighbour's apex in template i's frame. \pre x has an interface facet
template <int D>
Structure<D> flip_across_interface(const Structure<D>& x) {
  const auto facets = interface_neighbours<D>(x);
  RC_PRE(!facets.empty());
  const auto& n = facets[std::size_t(*rc::gen::inRange<int>(0, int(facets.size())))];
  Structure<D> y = x;
  auto& m = y.templates[n.i].mesh;
  const auto b = core::VertexId(m.points.size());
  m.points.push_back(x.tf(n.own).inverse()(n.neighbour_apex));
  const auto cell = adapt::co_cells(m, n.facet)[0];
  const auto a = adapt::opposite_vertices(cell, n.facet)[0];
  std::vector<core::Simplex> added;
  for (core::VertexId q : n.facet) {
    std::vector<core::VertexId> ids{a, b};
    for (core::VertexId r : n.facet)
      if (r != q) ids.push_back(r);
    added.push_back(adapt::simplex_of(ids));
  }
  adapt::replace_cells(y, n.i, {cell}, added);
  return y;
}

template <int D>
void add(std::vector<Property>& p) {
  p.push_back({kClaim, "interior_flip_is_the_flip_at_every_instance" + dim_suffix(D), D,
               Kind::holds,
               "Section 5.2.3: a flip of an interior face of a random template (2-2 in 2D; 2-3 "
               "or 3-2 in 3D) gives a templated mesh whose AT is the input's AT with that flip "
               "made at every instance of the template",
               [] {
                 return rc::detail::toProperty(
                     [] { flip_is_the_flip_at_every_instance<D>(*valid_templated_mesh<D>()); });
               },
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *valid_templated_mesh<D>();
                   SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(flip_across_interface<D>(s.x)),
                                        record(s), picture(s));
                 });
               }});
  p.push_back({kClaim,
               "flip_across_an_instance_interface_breaks_lemma_4_2" + dim_suffix(D),
               D,
               Kind::counterexample,
               "Section 5.2.3 / Figure 5.13: the flip of the two AT cells on either side of an "
               "instance interface facet, pulled back into one template, is no templated mesh "
               "(Eq. 4.2 or the Lemma 4.2 conformity fails)",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *valid_templated_mesh<D>();
                   SYMMESH_PROOF_ASSERT(!is_templated_mesh<D>(flip_across_interface<D>(s.x)),
                                        record(s), picture(s));
                 });
               },
               {}});
}

} // namespace

void register_section_5_2_3(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
