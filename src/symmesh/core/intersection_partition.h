/// Definitions A.26 (Covering, partition), A.27 (Manifold partition), A.29 (Intersection
/// partition), A.30 (Partition refinement); Lemmas A.3 and A.4 —
/// spec/intersection-partition.md#def-a-26, #def-a-27, #def-a-29, #def-a-30
///
/// A linear set is a finite union of convex cells (convex_cell.h), the representation
/// A = ∪_{i=1}^k A_i of a geometry in the proof of Lemma A.3 and in Def A.29. Set-level
/// questions (equality, covering) are decided on point sets, never on the representation:
/// A = ∪ A_i equals B = ∪ B_j iff every A_i lies in ∪ B_j and every B_j in ∪ A_i, and a cell c lies
/// in a finite union of closed cells iff the top-dimensional pieces c ∩ B_j cover c (a finite
/// union of lower-dimensional closed sets has empty relative interior in c, so it cannot fill a
/// gap). For segments the pieces are parameter intervals; for polygons, c minus each piece is
/// split into convex parts until nothing of positive area is left.
///
/// Def A.27 asks int*_k(S_i) ∩ int*_k(S_j) = ∅ for k = DIM(X). For a k-manifold X ⊇ S_i, S_j this
/// holds iff no k-cell of S_i and k-cell of S_j meet in a k-dimensional set (invariance of domain:
/// a k-dimensional relatively open piece of X is open in X, and conversely an open subset of X has
/// positive k-measure), which is what is_manifold_partition decides.
#pragma once
#include "symmesh/core/convex_cell.h"

#include <algorithm>
#include <ostream>
#include <vector>

namespace symmesh::core {

template <class FT, int D>
struct LinearSet {
  std::vector<ConvexCell<FT, D>> cells; ///< the elements A_i of A = ∪ A_i

  /// Sorts and deduplicates the representation; the point set is unchanged.
  void normalize() {
    std::sort(cells.begin(), cells.end(), ConvexCellLess<FT, D>());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  }
  bool empty() const { return cells.empty(); }
  /// Every cell is canonical (ConvexCell::is_valid).
  bool is_valid(std::ostream* why = nullptr) const;
};

/// DIM(A): the largest cell dimension, -1 for the empty set.
template <class FT, int D>
int dimension(const LinearSet<FT, D>& a) {
  int d = -1;
  for (const auto& c : a.cells) d = std::max(d, c.dim);
  return d;
}

/// The set of one cell.
template <class FT, int D>
LinearSet<FT, D> linear_set(const ConvexCell<FT, D>& c) {
  return LinearSet<FT, D>{{c}};
}

/// ∪ S for a family of linear sets (representations concatenated, then normalized).
template <class FT, int D>
LinearSet<FT, D> union_of(const std::vector<LinearSet<FT, D>>& s) {
  LinearSet<FT, D> out;
  for (const auto& a : s) out.cells.insert(out.cells.end(), a.cells.begin(), a.cells.end());
  out.normalize();
  return out;
}

/// x ∈ A.
template <class FT, int D>
bool contains(const LinearSet<FT, D>& a, const Point<FT, D>& x);

/// c ⊆ ∪ B (exact; see the file comment).
/// \pre c and the cells of b are valid (not checked)
template <class FT, int D>
bool covered_by(const ConvexCell<FT, D>& c, const LinearSet<FT, D>& b);

/// A ⊆ B as point sets.
template <class FT, int D>
bool subset_of(const LinearSet<FT, D>& a, const LinearSet<FT, D>& b);

/// A = B as point sets (the representations may differ).
template <class FT, int D>
bool union_equals(const LinearSet<FT, D>& a, const LinearSet<FT, D>& b);

/// Every cell of A of dimension < DIM(A) lies in the union of A's DIM(A)-cells: a necessary
/// condition for A to be a manifold (Def A.6: every point has a DIM(A)-dimensional neighbourhood).
template <class FT, int D>
bool is_pure_dimensional(const LinearSet<FT, D>& a);

/// Def A.29, Eq. A.39: ip(A, B) = {A_i ∩ B_j : A_i ∩ B_j ≠ ∅} over the representations of A and B,
/// as a set (sorted, no two cells equal).
/// \pre a.is_valid() and b.is_valid() (throws std::invalid_argument)
template <class FT, int D>
std::vector<ConvexCell<FT, D>> ip(const LinearSet<FT, D>& a, const LinearSet<FT, D>& b);

/// Def A.30, Eq. A.41: refine(S, P) = ∪_{A ∈ S, B ∈ P} ip(A, B), as a set of one-cell linear sets
/// (sorted, no two equal), so that it is again a family that refine, is_covering and
/// is_manifold_partition accept.
/// \pre every element of s and p is valid (throws std::invalid_argument)
template <class FT, int D>
std::vector<LinearSet<FT, D>> refine(const std::vector<LinearSet<FT, D>>& s,
                                     const std::vector<LinearSet<FT, D>>& p);

/// Def A.26: S is a covering of X: every S_i is non-empty and X = ∪ S_i.
template <class FT, int D>
bool is_covering(const std::vector<LinearSet<FT, D>>& s, const LinearSet<FT, D>& x,
                 std::ostream* why = nullptr);

/// Def A.27: S is a covering of X and int*_k(S_i) ∩ int*_k(S_j) = ∅ for S_i ≠ S_j, k = DIM(X).
/// Elements of dimension < k are allowed and may overlap anything. S is a set: entries that are
/// equal as point sets are one element. X and the S_i must be manifolds; of that, the necessary
/// condition "pure-dimensional" is checked (a non-pure X or S_i makes the answer false), the rest
/// (no pinch points) is the caller's precondition.
/// \pre X and every S_i is a manifold (partly checked, see above)
template <class FT, int D>
bool is_manifold_partition(const std::vector<LinearSet<FT, D>>& s, const LinearSet<FT, D>& x,
                           std::ostream* why = nullptr);

} // namespace symmesh::core
