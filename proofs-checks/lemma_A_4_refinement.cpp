// Lemma A.4 (Refinement of manifold partition is manifold partition) with Definition A.30 —
// spec/intersection-partition.md#lemma-a-4
//
// For manifold partitions S, P of a geometry X, refine(S, P) = ∪ ip(A, B) is a manifold partition
// of X. Besides core::is_manifold_partition, two checks that do not use intersection_partition.h's
// set algebra: every refinement cell (fan-triangulated) is covered by X's conforming triangulation
// (element_complex.h's simplex_covered_by), and the 2-cells of the refinement have the same total
// area as X (componentwise over the three coordinate projections in 3D, so cells of different
// planes add up), which with disjoint interiors means that they fill X.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/element_complex.h"

#include <array>
#include <sstream>

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_A_4";

template <int D>
auto record(const Described<PartitionCase<D>>& c) {
  return [&c] {
    std::vector<std::pair<std::string, Linear<D>>> parts{{"X", c.value.x}};
    for (std::size_t i = 0; i < c.value.s.size(); ++i)
      parts.emplace_back("S" + std::to_string(i + 1), c.value.s[i]);
    for (std::size_t i = 0; i < c.value.p.size(); ++i)
      parts.emplace_back("P" + std::to_string(i + 1), c.value.p[i]);
    const auto r = core::refine<Exact, D>(c.value.s, c.value.p);
    for (std::size_t i = 0; i < r.size(); ++i)
      parts.emplace_back("R" + std::to_string(i + 1), r[i]);
    return linear_sets_record<D>(kLemma, c.recipe, parts);
  };
}
template <int D>
auto picture(const Described<PartitionCase<D>>& c) {
  return [&c] { return linear_sets_picture<D>(core::refine<Exact, D>(c.value.s, c.value.p)); };
}

/// Twice the absolute area of the projections of the 2-cells onto the coordinate planes.
template <int D>
std::array<Exact, 3> twice_projected_area(const std::vector<LinearCell<D>>& cells) {
  std::array<Exact, 3> total{Exact(0), Exact(0), Exact(0)};
  for (const auto& c : cells) {
    if (c.dim != 2) continue;
    const auto& v = c.vertices;
    for (int k = 0; k < (D == 3 ? 3 : 1); ++k) {
      const int i = D == 3 ? (k + 1) % 3 : 0, j = D == 3 ? (k + 2) % 3 : 1;
      Exact a = 0;
      for (std::size_t m = 0; m < v.size(); ++m) {
        const auto& p = v[m];
        const auto& q = v[(m + 1) % v.size()];
        a += p[i] * q[j] - q[i] * p[j];
      }
      total[k] += a < 0 ? Exact(-a) : a;
    }
  }
  return total;
}

template <int D>
std::vector<LinearCell<D>> cells_of(const LinearFamily<D>& f) {
  std::vector<LinearCell<D>> out;
  for (const auto& e : f) out.insert(out.end(), e.cells.begin(), e.cells.end());
  return out;
}

template <int D>
void check_refinement(const Described<PartitionCase<D>>& c) {
  const auto& x = c.value.x;
  const auto r = core::refine<Exact, D>(c.value.s, c.value.p);
  bool single = true;
  for (const auto& e : r) single = single && e.cells.size() == 1 && e.is_valid();
  SYMMESH_PROOF_ASSERT(single, record<D>(c), picture<D>(c));
  std::ostringstream why;
  const bool partition = core::is_manifold_partition<Exact, D>(r, x, &why);
  if (!partition) RC_LOG(why.str());
  SYMMESH_PROOF_ASSERT(partition, record<D>(c), picture<D>(c));
  // Without any one of its X-dimensional elements R is no covering: nothing else fills that
  // element's interior (this makes the covering test falsifiable here).
  const int k = core::dimension<Exact, D>(x);
  bool needed = true;
  for (std::size_t i = 0; i < r.size() && needed; ++i) {
    if (r[i].cells[0].dim != k) continue;
    auto rest = r;
    rest.erase(rest.begin() + std::ptrdiff_t(i));
    needed = !core::is_covering<Exact, D>(rest, x);
  }
  SYMMESH_PROOF_ASSERT(needed, record<D>(c), picture<D>(c));
  bool inside = true;
  for (const auto& e : r)
    for (const auto& t : core::triangulate<Exact, D>(e.cells[0]))
      inside = inside && core::simplex_covered_by<Exact, D>(t, c.value.x_mesh);
  SYMMESH_PROOF_ASSERT(inside, record<D>(c), picture<D>(c));
  SYMMESH_PROOF_ASSERT(
      (twice_projected_area<D>(cells_of<D>(r)) == twice_projected_area<D>(x.cells)), record<D>(c),
      picture<D>(c));
  // Def A.30 is symmetric in S and P (both results are sorted one-cell sets).
  SYMMESH_PROOF_ASSERT(
      (cells_of<D>(core::refine<Exact, D>(c.value.p, c.value.s)) == cells_of<D>(r)), record<D>(c),
      picture<D>(c));
  bool lower = false;
  for (const auto* f : {&c.value.s, &c.value.p})
    for (const auto& e : *f) lower = lower || core::dimension<Exact, D>(e) < k;
  RC_TAG(lower ? "lower-dimensional elements" : "pure elements",
         r.size() > 6 ? "|refine| > 6" : "|refine| <= 6");
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma, "refinement_is_manifold_partition" + d, D, Kind::holds,
       "Lemma A.4 / Def A.30: for manifold partitions S, P of a geometry X (convex polygons, "
       "fans, polyominoes, folded rectangles; cut by lines through vertices, centroids or grid "
       "points; with lower-dimensional elements), refine(S, P) is a set of single linear cells, "
       "a manifold partition of X, covered by X's triangulation, of X's total area, and equal "
       "to refine(P, S)",
       [] {
         return rc::detail::toProperty([] {
           const auto c = *manifold_partitions<D>();
           SYMMESH_PROOF_ASSERT((core::is_manifold_partition<Exact, D>(c.value.s, c.value.x) &&
                                 core::is_manifold_partition<Exact, D>(c.value.p, c.value.x)),
                                record<D>(c), picture<D>(c));
           check_refinement<D>(c);
         });
       },
       [] {
         return rc::detail::toProperty([] { check_refinement<D>(*covering_and_partition<D>()); });
       }});
  p.push_back({kLemma,
               "covering_only" + d,
               D,
               Kind::counterexample,
               "Lemma A.4 with S only a covering (two elements overlapping in a strip of positive "
               "area): refine(S, P) is still a covering of X (parts i-iii of the proof need no "
               "partition), but not a manifold partition",
               [] {
                 return rc::detail::toProperty([] {
                   const auto c = *covering_and_partition<D>();
                   const auto& x = c.value.x;
                   SYMMESH_PROOF_ASSERT((core::is_covering<Exact, D>(c.value.s, x) &&
                                         !core::is_manifold_partition<Exact, D>(c.value.s, x) &&
                                         core::is_manifold_partition<Exact, D>(c.value.p, x)),
                                        record<D>(c), picture<D>(c));
                   const auto r = core::refine<Exact, D>(c.value.s, c.value.p);
                   SYMMESH_PROOF_ASSERT((core::is_covering<Exact, D>(r, x)), record<D>(c),
                                        picture<D>(c));
                   SYMMESH_PROOF_ASSERT(!(core::is_manifold_partition<Exact, D>(r, x)),
                                        record<D>(c), picture<D>(c));
                 });
               },
               {}});
}

} // namespace

void register_lemma_A_4(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
