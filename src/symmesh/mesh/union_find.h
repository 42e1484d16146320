/// Union-find over vertex numbers, for shared vertex bookkeeping —
/// spec/mesh-data-structures.md#compact-svb
///
/// The smaller representative wins, so every class is named by its first member and the
/// numbering of the assembled structure instance does not depend on the order of unions.
#pragma once
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace symmesh::mesh {

class UnionFind {
public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  /// True when a and b were in different classes.
  bool unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (b < a) std::swap(a, b);
    parent_[b] = a;
    return true;
  }
  bool is_valid() const {
    for (std::size_t x = 0; x < parent_.size(); ++x)
      if (parent_[x] > x) return false; // representatives are the smallest members
    return true;
  }

private:
  std::vector<std::size_t> parent_;
};

} // namespace symmesh::mesh
