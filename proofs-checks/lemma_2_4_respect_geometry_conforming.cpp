// Lemma 2.4 (Respectness of meshes with geometry-conforming property) — spec/lemmas.md#lemma-2-4
//
// (i) If M geometry-conforms to G (us(M) = G), every element of M respects G.
// (ii) If (M, ξ) geometry-conforms to (G, ξ~), every element of region((M, ξ), i) respects
//      region((G, ξ~), i).
// G is described independently of M: as conv(points) for a triangulation M of the points
// (Definition 2.8), as us(M') for another triangulation M' of the same points, and per region
// as the convex hull of a template and of its mirror image (Lemma 6.1 structures).
// An element respects X iff each of its faces does (E ∩ X = ∪ faces ⇔ every face f has
// f ⊆ X or relint(f) ∩ X = ∅), so checking the cells covers every element.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/respect.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_2_4";

/// Failure records of this lemma's single-mesh cases (see generators.h).
template <int D>
auto record(const std::string& recipe, const Complex<D>& m) {
  return complex_failure_record<D>(kLemma, recipe, m);
}

/// Every cell of m respects the convex set G = ⋂ conv(g_j).
template <int D>
bool cells_respect(const Complex<D>& m, const core::ConvexIntersection<Exact, D>& g) {
  for (const auto& c : m.cells())
    if (!core::respects<Exact, D>(m.coords(c), g)) return false;
  return true;
}

template <int D>
void geometry_conforming(const Described<GeometryCase<D>>& c) {
  const auto& g = c.value;
  // (i) with G = conv(points) or with G = us(M') (one description per case: each costs
  // several exact LPs per face of every cell)
  if (*rc::gen::inRange(0, 2) == 0) {
    RC_TAG("G = conv(points)");
    SYMMESH_PROOF_ASSERT(cells_respect<D>(g.mesh, {g.points}), record<D>(c.recipe, g.mesh),
                         picture<D>(g.mesh));
  } else {
    RC_TAG("G = us(M')");
    for (const auto& cell : g.mesh.cells())
      SYMMESH_PROOF_ASSERT(
          (core::respects_underlying_space<Exact, D>(g.mesh.coords(cell), g.other_mesh)),
          record<D>(c.recipe, g.mesh), picture<D>(g.mesh));
  }
  // (ii) region by region
  for (std::size_t k = 0; k < g.region_ids.size(); ++k)
    SYMMESH_PROOF_ASSERT(cells_respect<D>(g.multi.region(g.region_ids[k]), {g.region_hulls[k]}),
                         record<D>(c.recipe, g.multi.mesh), picture<D>(g.multi.mesh));
}

/// The conclusion of (i) on a G that M does not geometry-conform to.
template <int D>
bool respects_cut_geometry(const NonConformingGeometryCase<D>& g) {
  return cells_respect<D>(g.mesh, {g.points, g.cut});
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma, "elements_respect_geometry" + d, D, Kind::holds,
       "Lemma 2.4: every element of a triangulation M of a point set respects G = conv(points) "
       "and G = us(M') for another triangulation M' (i), and every element of each region of a "
       "reflected multi-region mesh respects that region's geometry (ii)",
       [] {
         return rc::detail::toProperty(
             [] { geometry_conforming<D>(*geometry_conforming_case<D>()); });
       },
       [] {
         return rc::detail::toProperty([] {
           const auto c = *geometry_not_conforming_case<D>();
           SYMMESH_PROOF_ASSERT(respects_cut_geometry<D>(c.value),
                                record<D>(c.recipe, c.value.mesh), picture<D>(c.value.mesh));
         });
       }});
  p.push_back(
      {kLemma,
       "mesh_not_geometry_conforming" + d,
       D,
       Kind::counterexample,
       "Lemma 2.4 without geometry-conformity (G = conv(points) cut by a hyperplane through "
       "a cell's centroid, so us(M) != G): some element of M does not respect G",
       [] {
         return rc::detail::toProperty([] {
           const auto c = *geometry_not_conforming_case<D>();
           SYMMESH_PROOF_ASSERT(!respects_cut_geometry<D>(c.value),
                                record<D>(c.recipe, c.value.mesh), picture<D>(c.value.mesh));
         });
       },
       {}});
}

} // namespace

void register_lemma_2_4(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
