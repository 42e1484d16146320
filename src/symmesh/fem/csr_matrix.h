/// Compressed sparse row matrix — spec/fem.md#csr
///
/// The conventional storage Section 7.6 compares the templated CSR against: row pointers, column
/// indices (sorted within each row) and values. It is the reference of every TCSR check
/// (Algorithm 7.1 must reproduce it) and of the CSR conjugate gradients.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <vector>

namespace symmesh::fem {

using GlobalIndex = std::int32_t;

struct CsrMatrix {
  std::size_t rows = 0;
  std::vector<std::int64_t> row_start{0}; ///< rows + 1 entries
  std::vector<GlobalIndex> column;        ///< sorted and unique within a row
  std::vector<double> value;

  std::size_t nonzeros() const { return column.size(); }
  std::size_t bytes() const {
    return row_start.size() * sizeof(std::int64_t) + column.size() * sizeof(GlobalIndex) +
           value.size() * sizeof(double);
  }
  /// y = A x. \pre x.size() == y.size() == rows
  void multiply(const double* x, double* y) const {
    for (std::size_t r = 0; r < rows; ++r) {
      double s = 0;
      for (std::int64_t k = row_start[r]; k < row_start[r + 1]; ++k)
        s += value[std::size_t(k)] * x[column[std::size_t(k)]];
      y[r] = s;
    }
  }
  std::vector<double> diagonal() const {
    std::vector<double> d(rows, 0.0);
    for (std::size_t r = 0; r < rows; ++r)
      for (std::int64_t k = row_start[r]; k < row_start[r + 1]; ++k)
        if (std::size_t(column[std::size_t(k)]) == r) d[r] = value[std::size_t(k)];
    return d;
  }
  /// Row pointers monotone, columns in range, sorted and unique per row.
  bool is_valid(std::ostream* why = nullptr) const {
    const auto fail = [&](const char* m) {
      if (why) *why << "CsrMatrix: " << m;
      return false;
    };
    if (row_start.size() != rows + 1 || row_start[0] != 0 ||
        std::size_t(row_start[rows]) != column.size() || value.size() != column.size())
      return fail("array sizes do not match");
    for (std::size_t r = 0; r < rows; ++r) {
      if (row_start[r + 1] < row_start[r]) return fail("row pointers decrease");
      for (std::int64_t k = row_start[r]; k < row_start[r + 1]; ++k) {
        const auto c = column[std::size_t(k)];
        if (c < 0 || std::size_t(c) >= rows) return fail("column out of range");
        if (k > row_start[r] && column[std::size_t(k - 1)] >= c)
          return fail("columns not sorted and unique");
      }
    }
    return true;
  }
};

/// A CSR matrix from the element matrices of simplices: cells(c) gives the D + 1 vertex ids of
/// cell c (an array of at least D + 1 GlobalIndex in [0, n)), element(c) its element matrix
/// (already scaled). Pattern: the union of the cells' vertex pairs (found through the cells of
/// each vertex, so the memory is the pattern plus (D + 1) indices per cell); values summed.
template <int D, class Cells, class Element>
CsrMatrix assemble_csr(std::size_t n, std::size_t cell_count, Cells cells, Element element) {
  std::vector<std::int64_t> first(n + 1, 0);
  for (std::size_t c = 0; c < cell_count; ++c) {
    const auto v = cells(c);
    for (int a = 0; a <= D; ++a) ++first[std::size_t(v[std::size_t(a)]) + 1];
  }
  for (std::size_t r = 0; r < n; ++r) first[r + 1] += first[r];
  std::vector<std::int64_t> fill(first.begin(), first.end() - 1);
  std::vector<std::uint32_t> cells_of(static_cast<std::size_t>(first[n]));
  for (std::size_t c = 0; c < cell_count; ++c) {
    const auto v = cells(c);
    for (int a = 0; a <= D; ++a)
      cells_of[std::size_t(fill[std::size_t(v[std::size_t(a)])]++)] = std::uint32_t(c);
  }
  CsrMatrix m;
  m.rows = n;
  m.row_start.assign(n + 1, 0);
  std::vector<GlobalIndex> seen(n, -1), row;
  for (std::size_t r = 0; r < n; ++r) {
    row.clear();
    for (std::int64_t k = first[r]; k < first[r + 1]; ++k) {
      const auto v = cells(cells_of[std::size_t(k)]);
      for (int a = 0; a <= D; ++a) {
        const GlobalIndex q = v[std::size_t(a)];
        if (seen[std::size_t(q)] == GlobalIndex(r)) continue;
        seen[std::size_t(q)] = GlobalIndex(r);
        row.push_back(q);
      }
    }
    std::sort(row.begin(), row.end());
    m.column.insert(m.column.end(), row.begin(), row.end());
    m.row_start[r + 1] = std::int64_t(m.column.size());
  }
  m.value.assign(m.column.size(), 0.0);
  for (std::size_t c = 0; c < cell_count; ++c) {
    const auto v = cells(c);
    const auto k = element(c);
    for (int a = 0; a <= D; ++a) {
      const std::size_t r = std::size_t(v[std::size_t(a)]);
      const auto* begin = m.column.data() + m.row_start[r];
      const auto* end = m.column.data() + m.row_start[r + 1];
      for (int b = 0; b <= D; ++b) {
        const auto* at = std::lower_bound(begin, end, v[std::size_t(b)]);
        m.value[std::size_t(at - m.column.data())] += k[std::size_t(a)][std::size_t(b)];
      }
    }
  }
  return m;
}

} // namespace symmesh::fem
