// Section 5.2.3 (flips) — spec/adaptation.md#flips
//
// Claim: a flip of an interior face of a mesh template (2-2 in 2D; 2-3, 3-2 and 4-4 in 3D) maps a
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
    if constexpr (D == 2) {
      r = adapt::flip_2_2(y, i, f);
    } else if (f.dim() == 2) {
      r = adapt::flip_2_3(y, i, f);
    } else {
      r = adapt::flip_3_2(y, i, f);
      const int diagonal = *rc::gen::inRange<int>(0, 2);
      for (int k = 0; k < 2 && !r; ++k) r = adapt::flip_4_4(y, i, f, (diagonal + k) % 2);
    }
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
  RC_TAG(!r       ? "no flippable face"
         : D == 2 ? "2-2"
                  : std::to_string(r.removed.size()) + "-" + std::to_string(r.added.size()));
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

/// The 4-4 flip of the axis to the ring diagonal `diagonal` (0: c0 c2, 1: c1 c3).
adapt::FlipResult four_four(Structure<3>& y, int diagonal) {
  return adapt::flip_4_4(y, 0, adapt::simplex_of({0, 1}), diagonal);
}

void four_four_flip_is_the_flip_at_every_instance(bool reflex) {
  const auto s = *four_tetrahedra_around_an_axis(reflex);
  const int diagonal = *rc::gen::inRange<int>(0, 2);
  Structure<3> y = s.x;
  const auto r = four_four(y, diagonal);
  RC_TAG(reflex ? "reflex ring" : "convex ring", r ? "flipped" : "refused");
  // Exactly the diagonal that stays inside the octahedron is taken.
  SYMMESH_PROOF_ASSERT(bool(r) == (!reflex || diagonal == 0), record<3>(s), picture(s));
  if (!r) {
    SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(y) == adapt::structure_instance_cells(s.x),
                         record<3>(s), picture(s));
    return;
  }
  const core::VertexId g = core::VertexId(2 + diagonal), h = core::VertexId(4 + diagonal);
  for (const auto& c : r.added)
    SYMMESH_PROOF_ASSERT(std::count(c.v.begin(), c.v.end(), g) == 1 &&
                             std::count(c.v.begin(), c.v.end(), h) == 1,
                         record<3>(s), picture(s));
  SYMMESH_PROOF_ASSERT(is_templated_mesh<3>(y), record<3>(s), picture(s));
  const auto expected =
      at_with_replaced_cells<3>(s.x, 0, s.x.templates[0].mesh.points, r.removed, r.added);
  SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(y) == expected, record<3>(s), picture(s));
}

/// Dropped hypothesis "each new cell has the old cells' orientation sign": the reflex
/// octahedron cut along the diagonal c1 c3, which leaves it.
void four_four_flip_without_the_sign_test() {
  const auto s = *four_tetrahedra_around_an_axis(true);
  Structure<3> y = s.x;
  const auto around = adapt::co_cells(y.templates[0].mesh, adapt::simplex_of({0, 1}));
  adapt::replace_cells(y, 0, around,
                       {adapt::simplex_of({0, 3, 4, 5}), adapt::simplex_of({0, 3, 5, 2}),
                        adapt::simplex_of({1, 3, 5, 4}), adapt::simplex_of({1, 3, 2, 5})});
  SYMMESH_PROOF_ASSERT(is_templated_mesh<3>(y), record<3>(s), picture(s));
}

template <int D>
void add(std::vector<Property>& p) {
  p.push_back({kClaim, "interior_flip_is_the_flip_at_every_instance" + dim_suffix(D), D,
               Kind::holds,
               "Section 5.2.3: a flip of an interior face of a random template (2-2 in 2D; 2-3, "
               "3-2 or 4-4 in 3D) gives a templated mesh whose AT is the input's AT with that flip "
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
  p.push_back(
      {kClaim, "four_four_flip_is_the_flip_at_every_instance_3d", 3, Kind::holds,
       "Section 5.2.3: the 4-4 flip of the axis of a random octahedron template (four "
       "tetrahedra around it, instanced twice) is made exactly when the new diagonal "
       "stays inside (convex ring: both; reflex ring: one), gives a templated mesh, and "
       "AT is the input's AT with that flip at both instances",
       [] {
         return rc::detail::toProperty(
             [] { four_four_flip_is_the_flip_at_every_instance(*rc::gen::arbitrary<bool>()); });
       },
       [] { return rc::detail::toProperty([] { four_four_flip_without_the_sign_test(); }); }});
}

} // namespace symmesh::proofs
