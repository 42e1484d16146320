/// P1 Lagrange element matrices on a simplex — spec/fem.md#p1
///
/// Section 7.6 assembles the Laplace operator with piecewise linear (P1) Lagrange elements. On a
/// D-simplex with vertices x_0 … x_D, the barycentric gradients are the rows of J⁻¹ (J = [x_1 −
/// x_0, …, x_D − x_0]) and ∇λ_0 = −Σ ∇λ_k, so the stiffness matrix is K_ij = |T| ∇λ_i · ∇λ_j and
/// the mass matrix M_ij = |T| (1 + δ_ij) / ((D + 1)(D + 2)). A rigid motion leaves both unchanged,
/// which is why a template's matrices serve every instance (Algorithm 7.2).
#pragma once
#include <array>
#include <cmath>
#include <stdexcept>

namespace symmesh::fem {

template <int D>
using ElementMatrix = std::array<std::array<double, D + 1>, D + 1>;

/// |det J| / D! of the simplex whose vertex coordinates are x[0..D] (D numbers each), and the
/// barycentric gradients, computed in Real (double; long double for the extended-precision
/// reference of spec/fem.md#tcsr). \pre the simplex is not flat (throws std::invalid_argument)
template <int D, class Real = double>
Real barycentric_gradients(const std::array<const Real*, D + 1>& x,
                           std::array<std::array<Real, D>, D + 1>& grad) {
  Real j[D][D];
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) j[r][c] = x[std::size_t(c + 1)][r] - x[0][r]; // column c: edge c
  Real det = 0;
  Real inv[D][D];
  if constexpr (D == 2) {
    det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    inv[0][0] = j[1][1];
    inv[0][1] = -j[0][1];
    inv[1][0] = -j[1][0];
    inv[1][1] = j[0][0];
  } else {
    static_assert(D == 3, "P1 elements in 2D and 3D");
    inv[0][0] = j[1][1] * j[2][2] - j[1][2] * j[2][1];
    inv[0][1] = j[0][2] * j[2][1] - j[0][1] * j[2][2];
    inv[0][2] = j[0][1] * j[1][2] - j[0][2] * j[1][1];
    inv[1][0] = j[1][2] * j[2][0] - j[1][0] * j[2][2];
    inv[1][1] = j[0][0] * j[2][2] - j[0][2] * j[2][0];
    inv[1][2] = j[0][2] * j[1][0] - j[0][0] * j[1][2];
    inv[2][0] = j[1][0] * j[2][1] - j[1][1] * j[2][0];
    inv[2][1] = j[0][1] * j[2][0] - j[0][0] * j[2][1];
    inv[2][2] = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    det = j[0][0] * inv[0][0] + j[0][1] * inv[1][0] + j[0][2] * inv[2][0];
  }
  if (!(det != 0) || !std::isfinite(det))
    throw std::invalid_argument("P1 element: a cell is flat or has non-finite coordinates");
  // Row k of J⁻¹ is ∇λ_{k+1}.
  for (int k = 0; k < D; ++k)
    for (int c = 0; c < D; ++c) grad[std::size_t(k + 1)][std::size_t(c)] = inv[k][c] / det;
  for (int c = 0; c < D; ++c) {
    Real s = 0;
    for (int k = 1; k <= D; ++k) s += grad[std::size_t(k)][std::size_t(c)];
    grad[0][std::size_t(c)] = -s;
  }
  return std::abs(det) / Real(D == 2 ? 2 : 6);
}

/// K_ij = |T| ∇λ_i · ∇λ_j, computed in Real and rounded to double once per entry.
template <int D, class Real = double>
ElementMatrix<D> p1_stiffness(const std::array<const Real*, D + 1>& x) {
  std::array<std::array<Real, D>, D + 1> g{};
  const Real volume = barycentric_gradients<D, Real>(x, g);
  ElementMatrix<D> k{};
  for (int a = 0; a <= D; ++a)
    for (int b = 0; b <= D; ++b) {
      Real s = 0;
      for (int c = 0; c < D; ++c)
        s += g[std::size_t(a)][std::size_t(c)] * g[std::size_t(b)][std::size_t(c)];
      k[std::size_t(a)][std::size_t(b)] = double(volume * s);
    }
  return k;
}

/// M_ij = |T| (1 + δ_ij) / ((D + 1)(D + 2)).
template <int D, class Real = double>
ElementMatrix<D> p1_mass(const std::array<const Real*, D + 1>& x) {
  std::array<std::array<Real, D>, D + 1> g{};
  const Real volume = barycentric_gradients<D, Real>(x, g);
  ElementMatrix<D> m{};
  for (int a = 0; a <= D; ++a)
    for (int b = 0; b <= D; ++b)
      m[std::size_t(a)][std::size_t(b)] =
          double(volume * Real(a == b ? 2 : 1) / Real((D + 1) * (D + 2)));
  return m;
}

} // namespace symmesh::fem
