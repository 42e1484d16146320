/// Union-find over vertex numbers, for shared vertex bookkeeping —
/// spec/mesh-data-structures.md#compact-svb
///
/// The smaller representative wins, so every class is named by its first member and the
/// numbering of the assembled structure instance does not depend on the order of unions. Parents
/// are 32-bit: the array is fresh memory in the timed SVB step, and on this project's machines
/// every fresh page costs a page fault (about 10 µs on the benchmark VM).
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace symmesh::mesh {

class UnionFind {
public:
  /// \pre n < 2^32
  explicit UnionFind(std::size_t n) {
    if (n > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("UnionFind: more than 2^32 - 1 members");
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), std::uint32_t(0));
  }

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
    parent_[b] = std::uint32_t(a);
    return true;
  }
  bool is_valid() const {
    for (std::size_t x = 0; x < parent_.size(); ++x)
      if (parent_[x] > x) return false; // representatives are the smallest members
    return true;
  }

private:
  std::vector<std::uint32_t> parent_;
};

} // namespace symmesh::mesh
