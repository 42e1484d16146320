/// Exact linear algebra over an ordered field — spec/definitions.md#exactness
///
/// Small dense systems (at most 5 unknowns) appear in barycentric coordinates, circumcentres and
/// affine-independence tests. Gaussian elimination with exact pivots decides consistency exactly.
#pragma once
#include <optional>
#include <vector>

namespace symmesh::core {

template <class FT>
using Matrix = std::vector<std::vector<FT>>;

/// Solves A x = b for a possibly over-determined A (rows >= cols).
/// Returns nullopt if the system is inconsistent or the solution is not unique.
template <class FT>
std::optional<std::vector<FT>> solve_unique(Matrix<FT> a, std::vector<FT> b) {
  const std::size_t rows = a.size();
  const std::size_t cols = rows ? a[0].size() : 0;
  std::size_t r = 0;
  std::vector<std::size_t> pivot_col;
  for (std::size_t c = 0; c < cols && r < rows; ++c) {
    std::size_t p = r;
    while (p < rows && a[p][c] == 0) ++p;
    if (p == rows) return std::nullopt; // free column: not unique
    std::swap(a[p], a[r]);
    std::swap(b[p], b[r]);
    for (std::size_t i = 0; i < rows; ++i) {
      if (i == r || a[i][c] == 0) continue;
      const FT f = a[i][c] / a[r][c];
      for (std::size_t j = c; j < cols; ++j) a[i][j] -= f * a[r][j];
      b[i] -= f * b[r];
    }
    pivot_col.push_back(c);
    ++r;
  }
  if (r < cols) return std::nullopt;
  for (std::size_t i = r; i < rows; ++i)
    if (b[i] != 0) return std::nullopt; // inconsistent
  std::vector<FT> x(cols);
  for (std::size_t i = 0; i < r; ++i) x[pivot_col[i]] = b[i] / a[i][pivot_col[i]];
  return x;
}

/// Rank of a matrix, exactly.
template <class FT>
std::size_t rank(Matrix<FT> a) {
  const std::size_t rows = a.size();
  const std::size_t cols = rows ? a[0].size() : 0;
  std::size_t r = 0;
  for (std::size_t c = 0; c < cols && r < rows; ++c) {
    std::size_t p = r;
    while (p < rows && a[p][c] == 0) ++p;
    if (p == rows) continue;
    std::swap(a[p], a[r]);
    for (std::size_t i = r + 1; i < rows; ++i) {
      if (a[i][c] == 0) continue;
      const FT f = a[i][c] / a[r][c];
      for (std::size_t j = c; j < cols; ++j) a[i][j] -= f * a[r][j];
    }
    ++r;
  }
  return r;
}

/// Determinant of a square matrix, exactly.
template <class FT>
FT determinant(Matrix<FT> a) {
  const std::size_t n = a.size();
  FT det = 1;
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    while (p < n && a[p][c] == 0) ++p;
    if (p == n) return FT(0);
    if (p != c) {
      std::swap(a[p], a[c]);
      det = -det;
    }
    det *= a[c][c];
    for (std::size_t i = c + 1; i < n; ++i) {
      if (a[i][c] == 0) continue;
      const FT f = a[i][c] / a[c][c];
      for (std::size_t j = c; j < n; ++j) a[i][j] -= f * a[c][j];
    }
  }
  return det;
}

} // namespace symmesh::core
