// Lemma A.3 (𝔏^n is IPC) with Definition A.29 (intersection partition) —
// spec/intersection-partition.md#lemma-a-3
//
// For geometries A = ∪ A_i and B = ∪ B_j, ip(A, B) = {A_i ∩ B_j ≠ ∅} is a finite set of linear
// cells whose union is A ∩ B, each of dimension <= min(DIM A, DIM B), and — when A ∩ B is a
// manifold and both representations are conforming — a manifold partition of A ∩ B.
//
// ip is checked against an oracle that never clips: the vertices of A_i ∩ B_j are among the
// vertices of either cell lying in the other and the crossing points of their edges (and, in 3D,
// of an edge with the other cell's plane), so conv of those candidates lying in both cells is
// A_i ∩ B_j. Pointwise, membership in A and in B must equal membership in ∪ ip on all vertices,
// edge midpoints, centroids and candidates.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/linear_algebra.h"

#include <algorithm>

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_A_3";

template <int D>
auto record(const Described<LinearPair<D>>& c) {
  return [&c] {
    const auto parts = core::ip<Exact, D>(c.value.a, c.value.b);
    return linear_sets_record<D>(kLemma, c.recipe,
                                 {{"A", c.value.a}, {"B", c.value.b}, {"ip", Linear<D>{parts}}});
  };
}
template <int D>
auto picture(const Described<LinearPair<D>>& c) {
  return [&c] { return linear_sets_picture<D>({c.value.a, c.value.b}); };
}

/// Candidate vertices of a ∩ b: vertices of one cell, pairwise edge crossings and (3D) crossings
/// of edges with the other cell's plane. Not filtered.
template <int D>
PointSet<D> candidates(const LinearCell<D>& a, const LinearCell<D>& b) {
  PointSet<D> out = a.vertices;
  out.insert(out.end(), b.vertices.begin(), b.vertices.end());
  const auto ea = core::cell_edges<Exact, D>(a), eb = core::cell_edges<Exact, D>(b);
  for (const auto& e : ea)
    for (const auto& f : eb) {
      // e0 + s (e1 - e0) = f0 + t (f1 - f0): unique only for coplanar, non-parallel lines.
      core::Matrix<Exact> m(D, std::vector<Exact>(2));
      std::vector<Exact> rhs(D);
      for (int d = 0; d < D; ++d) {
        m[d][0] = e[1][d] - e[0][d];
        m[d][1] = f[0][d] - f[1][d];
        rhs[d] = f[0][d] - e[0][d];
      }
      if (auto st = core::solve_unique<Exact>(m, rhs))
        out.push_back(e[0] + core::scaled<Exact, D>(e[1] - e[0], (*st)[0]));
    }
  if constexpr (D == 3) {
    auto plane_crossings = [&out](const std::vector<PointSet<3>>& edges, const LinearCell<3>& c) {
      if (c.dim < 2) return;
      const auto& v = c.vertices;
      const Point<3> u = v[1] - v[0], w = v[2] - v[0];
      const Point<3> n{
          {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]}};
      for (const auto& e : edges) {
        const Exact denom = core::dot<Exact, 3>(n, e[1] - e[0]);
        if (denom == 0) continue;
        const Exact s = core::dot<Exact, 3>(n, v[0] - e[0]) / denom;
        out.push_back(e[0] + core::scaled<Exact, 3>(e[1] - e[0], s));
      }
    };
    plane_crossings(ea, b);
    plane_crossings(eb, a);
  }
  return out;
}

/// conv{candidates in a and in b}: a ∩ b computed without clipping.
template <int D>
std::optional<LinearCell<D>> oracle_intersection(const LinearCell<D>& a, const LinearCell<D>& b) {
  PointSet<D> in;
  for (const auto& p : candidates<D>(a, b))
    if (core::contains<Exact, D>(a, p) && core::contains<Exact, D>(b, p)) in.push_back(p);
  if (in.empty()) return std::nullopt;
  return core::make_convex_cell<Exact, D>(in);
}

template <int D>
std::vector<LinearCell<D>> oracle_ip(const Linear<D>& a, const Linear<D>& b) {
  std::vector<LinearCell<D>> out;
  for (const auto& ca : a.cells)
    for (const auto& cb : b.cells)
      if (auto q = oracle_intersection<D>(ca, cb)) out.push_back(*q);
  std::sort(out.begin(), out.end(), core::ConvexCellLess<Exact, D>());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

template <int D>
PointSet<D> sample_points(const Linear<D>& a, const Linear<D>& b) {
  PointSet<D> out;
  for (const auto* x : {&a, &b})
    for (const auto& c : x->cells) {
      out.insert(out.end(), c.vertices.begin(), c.vertices.end());
      out.push_back(core::centroid<Exact, D>(c));
      for (const auto& e : core::cell_edges<Exact, D>(c))
        out.push_back(core::scaled<Exact, D>(e[0] + e[1], Exact(1) / 2));
    }
  for (const auto& ca : a.cells)
    for (const auto& cb : b.cells) {
      const auto k = candidates<D>(ca, cb);
      out.insert(out.end(), k.begin(), k.end());
    }
  return out;
}

template <int D>
std::vector<Linear<D>> as_family(const std::vector<LinearCell<D>>& cells) {
  std::vector<Linear<D>> out;
  for (const auto& c : cells) out.push_back(core::linear_set<Exact, D>(c));
  return out;
}

/// Distinct elements of dimension k = DIM(∪ cells) meet in dimension < k: Def A.27's condition
/// read for a finite union of manifolds (A ∩ B need not be a manifold, Figure A.7).
template <int D>
bool top_interiors_disjoint(const std::vector<LinearCell<D>>& cells) {
  int k = -1;
  for (const auto& c : cells) k = std::max(k, c.dim);
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (std::size_t j = i + 1; j < cells.size(); ++j)
      if (cells[i].dim == k && cells[j].dim == k)
        if (auto q = core::intersect<Exact, D>(cells[i], cells[j]); q && q->dim == k) return false;
  return true;
}

/// The whole conclusion of Lemma A.3 on one pair (RC assertions inside).
template <int D>
void check_ip(const Described<LinearPair<D>>& c) {
  const auto& a = c.value.a;
  const auto& b = c.value.b;
  const auto parts = core::ip<Exact, D>(a, b);
  const Linear<D> both{parts};
  const int bound = std::min(core::dimension<Exact, D>(a), core::dimension<Exact, D>(b));
  bool cells_ok = true;
  for (const auto& q : parts) cells_ok = cells_ok && q.is_valid() && q.dim <= bound;
  SYMMESH_PROOF_ASSERT(cells_ok, record<D>(c), picture<D>(c));
  SYMMESH_PROOF_ASSERT((parts == oracle_ip<D>(a, b)), record<D>(c), picture<D>(c));
  SYMMESH_PROOF_ASSERT((core::subset_of<Exact, D>(both, a) && core::subset_of<Exact, D>(both, b)),
                       record<D>(c), picture<D>(c));
  bool pointwise = true;
  for (const auto& p : sample_points<D>(a, b))
    pointwise = pointwise && (core::contains<Exact, D>(a, p) && core::contains<Exact, D>(b, p)) ==
                                 core::contains<Exact, D>(both, p);
  SYMMESH_PROOF_ASSERT(pointwise, record<D>(c), picture<D>(c));
  SYMMESH_PROOF_ASSERT(top_interiors_disjoint<D>(parts), record<D>(c), picture<D>(c));
  // Each DIM(A ∩ B)-dimensional element is needed: the others do not cover it (a negative
  // coverage question, so that the union tests above can also fail).
  bool needed = true;
  const int k = core::dimension<Exact, D>(both);
  for (std::size_t i = 0; i < parts.size() && needed; ++i) {
    if (parts[i].dim != k) continue;
    Linear<D> rest{parts};
    rest.cells.erase(rest.cells.begin() + std::ptrdiff_t(i));
    needed = !core::covered_by<Exact, D>(parts[i], rest);
  }
  SYMMESH_PROOF_ASSERT(needed, record<D>(c), picture<D>(c));
  const bool pure = !parts.empty() && core::is_pure_dimensional<Exact, D>(both);
  RC_TAG("dim(A ∩ B) = " + std::to_string(core::dimension<Exact, D>(both)) +
         (parts.empty() || pure ? "" : ", not pure"));
  if (pure)
    SYMMESH_PROOF_ASSERT((core::is_manifold_partition<Exact, D>(as_family<D>(parts), both)),
                         record<D>(c), picture<D>(c));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma, "ip_is_intersection_partition" + d, D, Kind::holds,
       "Lemma A.3 / Def A.29: for geometries A, B with conforming representations, ip(A, B) is a "
       "set of valid linear cells of dimension <= min(DIM A, DIM B), equal to the clipping-free "
       "oracle {conv(candidate vertices in A_i and B_j)}, with union A ∩ B (contained in A and "
       "B; pointwise equal on vertices, midpoints, centroids, edge crossings), whose distinct "
       "DIM(A ∩ B)-dimensional elements have disjoint interiors, and which is a manifold "
       "partition of A ∩ B (Def A.27) whenever A ∩ B is pure-dimensional",
       [] { return rc::detail::toProperty([] { check_ip<D>(*linear_manifold_pair<D>()); }); },
       [] {
         return rc::detail::toProperty(
             [] { check_ip<D>(*nonconforming_representation_pair<D>()); });
       }});
  p.push_back(
      {kLemma,
       "figure_a7_intersection_not_manifold" + d,
       D,
       Kind::counterexample,
       "Figure A.7 / Eq. A.40: two geometries (pure 2D polygons) whose intersection is a segment "
       "plus an isolated point; A ∩ B = ∪ ip(A, B) is not pure-dimensional, hence not a "
       "manifold: the naive refinement {A ∩ B} leaves 𝔐^n, only the partition ip(A, B) stays "
       "in the element space",
       [] {
         return rc::detail::toProperty([] {
           const auto c = *figure_a7_pair<D>();
           const auto parts = core::ip<Exact, D>(c.value.a, c.value.b);
           const Linear<D> both{parts};
           SYMMESH_PROOF_ASSERT((core::is_pure_dimensional<Exact, D>(c.value.a) &&
                                 core::is_pure_dimensional<Exact, D>(c.value.b) &&
                                 core::dimension<Exact, D>(c.value.a) == 2 &&
                                 core::dimension<Exact, D>(c.value.b) == 2),
                                record<D>(c), picture<D>(c));
           SYMMESH_PROOF_ASSERT((parts == oracle_ip<D>(c.value.a, c.value.b)), record<D>(c),
                                picture<D>(c));
           SYMMESH_PROOF_ASSERT((core::dimension<Exact, D>(both) == 1), record<D>(c),
                                picture<D>(c));
           SYMMESH_PROOF_ASSERT((!core::is_pure_dimensional<Exact, D>(both)), record<D>(c),
                                picture<D>(c));
         });
       },
       {}});
  p.push_back(
      {kLemma,
       "nonconforming_representation" + d,
       D,
       Kind::counterexample,
       "Lemma A.3 without a conforming representation of A (a T-junction on a triangle's edge): "
       "A ∩ B is a segment (a 1-manifold), yet ip(A, B) holds overlapping segments and is no "
       "manifold partition of A ∩ B",
       [] {
         return rc::detail::toProperty([] {
           const auto c = *nonconforming_representation_pair<D>();
           const auto parts = core::ip<Exact, D>(c.value.a, c.value.b);
           const Linear<D> both{parts};
           SYMMESH_PROOF_ASSERT(
               (core::dimension<Exact, D>(both) == 1 && core::is_pure_dimensional<Exact, D>(both)),
               record<D>(c), picture<D>(c));
           SYMMESH_PROOF_ASSERT(!(core::is_manifold_partition<Exact, D>(as_family<D>(parts), both)),
                                record<D>(c), picture<D>(c));
         });
       },
       {}});
}

} // namespace

void register_lemma_A_3(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
