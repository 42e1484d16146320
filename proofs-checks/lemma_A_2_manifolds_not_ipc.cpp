// Lemma A.2 (𝔐^n is not IPC), its proof's construction in 𝔏^n —
// spec/intersection-partition.md#lemma-a-2
//
// The proof takes C ⊆ X, f = dist(·, C), A = graph of f and B = X × {0}: A ∩ B = C. With
// C = {0} ∪ {1/m : m ∈ ℕ} no finite manifold partition of C exists. The infinite set is not
// representable; its truncations C_N = {0} ∪ {1/m : m <= N} are, and A_N (a piecewise-linear
// graph of dist(·, C_N) over [0, 1]) is a linear 1-manifold. The property checks the proof's two
// steps on them: A_N ∩ B = C_N exactly, and every manifold partition of it needs one element per
// point — N + 1 elements, unbounded in N, which is why the limit has none.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/intersection_partition.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_A_2";

template <int D>
Point<D> at(const Exact& x, const Exact& y) {
  Point<D> p = core::zero_point<Exact, D>();
  p[0] = x;
  p[1] = y;
  return p;
}

/// C_N sorted ascending, A_N = graph of dist(·, C_N) over [0, 1] (two segments per gap), B.
template <int D>
LinearPair<D> construction(int n, std::vector<Exact>& c) {
  c = {Exact(0)};
  for (int m = n; m >= 1; --m) c.push_back(Exact(1) / m);
  LinearPair<D> out;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    const Exact mid = (c[i] + c[i + 1]) / 2, h = (c[i + 1] - c[i]) / 2;
    out.a.cells.push_back(core::make_convex_cell<Exact, D>({at<D>(c[i], 0), at<D>(mid, h)}));
    out.a.cells.push_back(core::make_convex_cell<Exact, D>({at<D>(mid, h), at<D>(c[i + 1], 0)}));
  }
  out.b.cells.push_back(core::make_convex_cell<Exact, D>({at<D>(0, 0), at<D>(1, 0)}));
  return out;
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma,
               "proof_construction_needs_a_cell_per_point" + d,
               D,
               Kind::holds,
               "Lemma A.2's construction truncated to C_N = {0} ∪ {1/m : m <= N}: the graph A_N of "
               "dist(·, C_N) meets B = [0,1] x {0} exactly in C_N, as N + 1 isolated points, so a "
               "manifold partition of A_N ∩ B has N + 1 elements (unbounded as N grows)",
               [] {
                 return rc::detail::toProperty([] {
                   const int n = *rc::gen::inRange(1, 40);
                   std::vector<Exact> c;
                   const auto pair = construction<D>(n, c);
                   const auto parts = core::ip<Exact, D>(pair.a, pair.b);
                   std::vector<Point<D>> points;
                   for (const auto& cell : parts) {
                     RC_ASSERT(cell.dim == 0);
                     points.push_back(cell.vertices[0]);
                   }
                   std::sort(points.begin(), points.end(), core::PointLess<Exact, D>());
                   std::vector<Point<D>> expected;
                   for (const auto& x : c) expected.push_back(at<D>(x, 0));
                   RC_ASSERT(points == expected);
                   std::vector<Linear<D>> elements;
                   for (const auto& cell : parts) elements.push_back(core::linear_set(cell));
                   const auto meet = core::union_of<Exact, D>(elements);
                   RC_ASSERT((core::is_manifold_partition<Exact, D>(elements, meet)));
                   RC_ASSERT(elements.size() == std::size_t(n) + 1);
                   // Without any one element it no longer covers A_N ∩ B.
                   const std::size_t drop = *rc::gen::inRange<std::size_t>(0, elements.size());
                   auto fewer = elements;
                   fewer.erase(fewer.begin() + std::ptrdiff_t(drop));
                   RC_ASSERT((!core::is_covering<Exact, D>(fewer, meet)));
                 });
               },
               {}});
}

} // namespace

void register_lemma_A_2(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
