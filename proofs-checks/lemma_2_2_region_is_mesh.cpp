// Lemma 2.2 (Region is a mesh) — spec/lemmas.md#lemma-2-2
//
// For a multi-region mesh (M, ξ), every region region((M, ξ), i) = {E ∈ M | i ∈ ξ(E)} is a
// mesh. The region is computed twice: by the core (face completion of the cells with id i) and
// here from the definition (every element whose ξ contains i); both must agree.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_2_2";

template <int D>
auto record(const Described<MultiRegion<D>>& c) {
  return [&c] { return complexes_record<D>(kLemma, c.recipe, {{"M", c.value.mesh}}); };
}
template <int D>
auto picture(const Described<MultiRegion<D>>& c) {
  return [&c] { return complex_picture<D>(c.value.mesh); };
}

/// region((M, ξ), i) from Definition 2.6 directly: the elements E with i ∈ ξ(E).
template <int D>
std::vector<core::Simplex> region_by_definition(const MultiRegion<D>& m, int i) {
  std::vector<core::Simplex> out;
  for (const auto& e : m.mesh.elements)
    if (m.xi(e).count(i)) out.push_back(e);
  return out;
}

template <int D>
void regions_are_meshes(const Described<MultiRegion<D>>& c) {
  RC_TAG(std::to_string(c.value.region_ids().size()) + " region(s)");
  for (int i : c.value.region_ids()) {
    const auto r = c.value.region(i);
    SYMMESH_PROOF_ASSERT(r.elements == region_by_definition<D>(c.value, i), record(c), picture(c));
    SYMMESH_PROOF_ASSERT(core::is_mesh(r), record(c), picture(c));
  }
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma, "region_is_mesh" + d, D, Kind::holds,
               "Lemma 2.2: for a multi-region mesh (a triangulation with region ids by hyperplane "
               "side or at random) every region {E | i ∈ ξ(E)} equals the face completion of its "
               "cells and is a mesh",
               [] {
                 return rc::detail::toProperty(
                     [] { regions_are_meshes<D>(*multi_region_mesh<D>()); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { regions_are_meshes<D>(*nonconforming_multi_region<D>()); });
               }});
  p.push_back({kLemma,
               "mesh_not_conforming" + d,
               D,
               Kind::counterexample,
               "Lemma 2.2 without 'M is a mesh' (M the element union of two different "
               "triangulations, conflicting cells in region 1): region 1 is not a mesh",
               [] {
                 return rc::detail::toProperty([] {
                   const auto c = *nonconforming_multi_region<D>();
                   SYMMESH_PROOF_ASSERT(!core::is_mesh(c.value.region(1)), record<D>(c),
                                        picture<D>(c));
                 });
               },
               {}});
}

} // namespace

void register_lemma_2_2(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
