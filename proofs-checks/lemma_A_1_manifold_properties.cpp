// Lemma A.1 (Manifold properties) on linear cells — spec/intersection-partition.md#lemma-a-1
//
// For convex cells (manifolds of 𝔏^n) A, B and C = A ∩ B (exact): (ii) C ⊆ B implies
// DIM(C) <= DIM(B); (iii) for k = DIM(B), int*_k(C) ⊆ int*_k(B); (iv) for k = max(DIM A, DIM B),
// int*_k(A ∩ B) = int*_k(A) ∩ int*_k(B). int*_k of a cell is its relative interior when its
// dimension is k and empty otherwise, so (iii) and (iv) are checked at the centroids, which lie in
// the relative interiors. Dropping k >= DIM(B) in (iii): an edge of a triangle is a 1-manifold
// with non-empty int*_1, while int*_1 of the triangle is empty. The holds property's dropped
// variant asserts (iv) also on two crossing segments, which lie in no common k-manifold.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/intersection_partition.h"
#include "symmesh/core/linear_algebra.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_A_1";

template <int D>
auto record(const Described<LinearPair<D>>& c) {
  return [&c] {
    return linear_sets_record<D>(kLemma, c.recipe, {{"A", c.value.a}, {"B", c.value.b}});
  };
}
template <int D>
auto picture(const Described<LinearPair<D>>& c) {
  return [&c] { return linear_sets_picture<D>({c.value.a, c.value.b}); };
}

/// x ∈ int*_k(c): c has dimension k and x is in its relative interior.
template <int D>
bool in_int_k(const LinearCell<D>& c, int k, const Point<D>& x) {
  return c.dim == k && core::relative_interior_contains<Exact, D>(c, x);
}

/// a and b have dimension k and span the same affine k-flat (so both lie in one k-manifold).
template <int D>
bool same_flat(const LinearCell<D>& a, const LinearCell<D>& b) {
  if (a.dim != b.dim) return false;
  core::Matrix<Exact> rows;
  for (const auto* c : {&a, &b})
    for (const auto& v : c->vertices) {
      std::vector<Exact> r(D);
      for (int i = 0; i < D; ++i) r[i] = v[i] - a.vertices[0][i];
      rows.push_back(r);
    }
  return int(core::rank(rows)) == a.dim;
}

/// (iv) at the centroids of A ∩ B and of B.
template <int D>
bool interiors_of_intersection(const LinearCell<D>& a, const LinearCell<D>& b) {
  const auto c = core::intersect<Exact, D>(a, b);
  const int k = std::max(a.dim, b.dim);
  if (c) {
    const auto x = core::centroid<Exact, D>(*c);
    if (in_int_k<D>(*c, k, x) != (in_int_k<D>(a, k, x) && in_int_k<D>(b, k, x))) return false;
  }
  const auto y = core::centroid<Exact, D>(b);
  return !(in_int_k<D>(a, k, y) && in_int_k<D>(b, k, y)) || (c && c->dim == k);
}

/// (ii)-(iv) on every pair of cells; `common_manifold` false also asserts (iv) where A and B lie
/// in no common k-manifold (the hypothesis the correction adds, dropped).
template <int D>
bool manifold_properties(const LinearPair<D>& pair, bool common_manifold = true) {
  for (const auto& a : pair.a.cells)
    for (const auto& b : pair.b.cells) {
      const auto c = core::intersect<Exact, D>(a, b);
      if (!c) continue;
      if (c->dim > b.dim || c->dim > a.dim) return false; // (ii)
      const auto x = core::centroid<Exact, D>(*c);
      if (in_int_k<D>(*c, b.dim, x) && !in_int_k<D>(b, b.dim, x)) return false; // (iii)
      // (iv) needs A and B inside one k-manifold (see the counterexample below).
      if ((!common_manifold || std::max(a.dim, b.dim) == D || same_flat<D>(a, b)) &&
          !interiors_of_intersection<D>(a, b))
        return false;
    }
  return true;
}

/// Two segments crossing transversally at B's midpoint (1-manifolds in R^D, in no common one).
template <int D>
LinearPair<D> crossing_segments(int a, int b) {
  const auto p = [](int x, int y) {
    Point<D> q = core::zero_point<Exact, D>();
    q[0] = x;
    q[1] = y;
    return q;
  };
  LinearPair<D> out;
  out.a.cells = {core::make_convex_cell<Exact, D>({p(-a, 0), p(a, 0)})};
  out.b.cells = {core::make_convex_cell<Exact, D>({p(0, -b), p(0, b)})};
  return out;
}

/// (iv) for the crossing segments: the midpoint is in int*_1(A) ∩ int*_1(B), but A ∩ B is a
/// point and int*_1 of it is empty.
template <int D>
bool crossing_segments_satisfy_iv(int a, int b) {
  const auto pair = crossing_segments<D>(a, b);
  return interiors_of_intersection<D>(pair.a.cells.front(), pair.b.cells.front());
}

/// (iii) without k >= DIM(B): A an edge of a 2-cell B, k = DIM(A) = 1.
template <int D>
bool edge_interior_in_cell_interior(const LinearPair<D>& pair) {
  for (const auto& b : pair.b.cells) {
    if (b.dim != 2) continue;
    const auto a = core::make_convex_cell<Exact, D>({b.vertices[0], b.vertices[1]});
    const auto x = core::centroid<Exact, D>(a);
    return !in_int_k<D>(a, 1, x) || in_int_k<D>(b, 1, x);
  }
  RC_DISCARD("no 2-cell in B");
  return true;
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma, "manifold_properties" + d, D, Kind::holds,
               "Lemma A.1 (ii)-(iv) on every pair of cells of two random geometries: the "
               "intersection has dimension <= both, its k-interior lies in the cell's k-interior, "
               "and k-interiors of the intersection are the intersection of k-interiors",
               [] {
                 return rc::detail::toProperty([] {
                   const auto c = *linear_manifold_pair<D>();
                   SYMMESH_PROOF_ASSERT(manifold_properties<D>(c.value), record<D>(c),
                                        picture<D>(c));
                 });
               },
               [] {
                 return rc::detail::toProperty([] {
                   const int a = *rc::gen::inRange(1, 20), b = *rc::gen::inRange(1, 20);
                   const Described<LinearPair<D>> c{crossing_segments<D>(a, b),
                                                    "segments crossing at B's midpoint"};
                   SYMMESH_PROOF_ASSERT(manifold_properties<D>(c.value, false), record<D>(c),
                                        picture<D>(c));
                 });
               }});
  p.push_back({kLemma,
               "interior_below_cell_dimension" + d,
               D,
               Kind::counterexample,
               "Lemma A.1 (iii) without k >= DIM(B): for an edge A of a triangle B and k = 1, "
               "int*_1(A) is not empty but int*_1(B) is, so int*_k(A) ⊆ int*_k(B) fails",
               [] {
                 return rc::detail::toProperty([] {
                   const auto c = *linear_manifold_pair<D>();
                   SYMMESH_PROOF_ASSERT(!edge_interior_in_cell_interior<D>(c.value), record<D>(c),
                                        picture<D>(c));
                 });
               },
               {}});
  p.push_back({kLemma,
               "transversal_crossing" + d,
               D,
               Kind::counterexample,
               "Lemma A.1 (iv) as stated is false without A and B lying in one k-manifold: two "
               "segments crossing at an interior point have int*_1(A) ∩ int*_1(B) ≠ ∅ but "
               "int*_1(A ∩ B) = ∅ (correction in spec/intersection-partition.md)",
               [] {
                 return rc::detail::toProperty([] {
                   const int a = *rc::gen::inRange(1, 20), b = *rc::gen::inRange(1, 20);
                   RC_ASSERT(!crossing_segments_satisfy_iv<D>(a, b));
                 });
               },
               {}});
}

} // namespace

void register_lemma_A_1(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
