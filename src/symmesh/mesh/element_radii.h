/// Definition 2.15 (min-containment ball, inradius, inball) and Definition 2.18 (radius ratio)
/// for triangles and tetrahedra, in double for reports — spec/definitions.md#def-2-15
///
/// These radii are square roots of rational expressions, so the exact core has only their
/// squared relatives (core/element_quality.h); here they are computed in floating point.
/// Inradius: k-volume times k over the sum of the facet measures (the inball touches every facet).
/// Min-containment ball: the smallest circumball of a face (in the face's own flat) whose centre
/// lies in that face and which holds every vertex — the smallest enclosing ball of a point set
/// is the circumball of its support set, and for a simplex the support set is a face holding its
/// centre. Radius ratio (Def 2.18 for simplices): R_in / R_circ; 1/2 for the equilateral
/// triangle and 1/3 for the regular tetrahedron, its maxima.
#pragma once
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace symmesh::mesh {

using Vertex3 = std::array<double, 3>; ///< 2D points have z = 0

namespace radii_detail {
inline Vertex3 sub(const Vertex3& a, const Vertex3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline double dot(const Vertex3& a, const Vertex3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// Circumcentre of the points p (2 to 4, affinely independent) in their own flat, as barycentric
/// weights: solve G λ' = b with G the Gram matrix of the edge vectors from p[0].
inline std::vector<double> circumcentre_weights(const std::vector<Vertex3>& p) {
  const std::size_t k = p.size() - 1;
  std::vector<std::vector<double>> a(k, std::vector<double>(k + 1));
  for (std::size_t i = 0; i < k; ++i) {
    const auto ei = sub(p[i + 1], p[0]);
    for (std::size_t j = 0; j < k; ++j) a[i][j] = 2 * dot(ei, sub(p[j + 1], p[0]));
    a[i][k] = dot(ei, ei);
  }
  for (std::size_t c = 0; c < k; ++c) { // Gaussian elimination with partial pivoting
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < k; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[piv][c])) piv = r;
    std::swap(a[c], a[piv]);
    if (a[c][c] == 0) throw std::invalid_argument("degenerate simplex");
    for (std::size_t r = 0; r < k; ++r) {
      if (r == c) continue;
      const double f = a[r][c] / a[c][c];
      for (std::size_t j = c; j <= k; ++j) a[r][j] -= f * a[c][j];
    }
  }
  std::vector<double> w(k + 1);
  double rest = 1;
  for (std::size_t i = 0; i < k; ++i) rest -= (w[i + 1] = a[i][k] / a[i][i]);
  w[0] = rest;
  return w;
}

inline Vertex3 combine(const std::vector<Vertex3>& p, const std::vector<double>& w) {
  Vertex3 c{0, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < 3; ++d) c[std::size_t(d)] += w[i] * p[i][std::size_t(d)];
  return c;
}

/// k-volume of a k-simplex, k = 1, 2, 3 (√det of the Gram matrix / k!).
inline double measure(const std::vector<Vertex3>& p) {
  const auto u = sub(p[1], p[0]);
  if (p.size() == 2) return std::sqrt(dot(u, u));
  const auto v = sub(p[2], p[0]);
  const Vertex3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  if (p.size() == 3) return std::sqrt(dot(n, n)) / 2;
  return std::fabs(dot(n, sub(p[3], p[0]))) / 6;
}

inline void require_simplex(const std::vector<Vertex3>& p) {
  if (p.size() != 3 && p.size() != 4)
    throw std::invalid_argument("element radii: a triangle or a tetrahedron is needed");
}
} // namespace radii_detail

/// R_circ (Def 2.14). \pre p is a non-degenerate triangle or tetrahedron
inline double circumradius(const std::vector<Vertex3>& p) {
  radii_detail::require_simplex(p);
  const auto c = radii_detail::combine(p, radii_detail::circumcentre_weights(p));
  const auto d = radii_detail::sub(p[0], c);
  return std::sqrt(radii_detail::dot(d, d));
}

/// R_in (Def 2.15). \pre p is a non-degenerate triangle or tetrahedron
inline double inradius(const std::vector<Vertex3>& p) {
  radii_detail::require_simplex(p);
  double facets = 0;
  for (std::size_t skip = 0; skip < p.size(); ++skip) {
    std::vector<Vertex3> f;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (i != skip) f.push_back(p[i]);
    facets += radii_detail::measure(f);
  }
  return double(p.size() - 1) * radii_detail::measure(p) / facets;
}

/// R_min-cont (Def 2.15). \pre p is a non-degenerate triangle or tetrahedron
inline double min_containment_radius(const std::vector<Vertex3>& p) {
  radii_detail::require_simplex(p);
  double best = circumradius(p);
  const std::size_t n = p.size();
  for (unsigned mask = 1; mask + 1 < (1u << n); ++mask) { // proper faces with >= 2 vertices
    std::vector<Vertex3> f;
    for (std::size_t i = 0; i < n; ++i)
      if (mask & (1u << i)) f.push_back(p[i]);
    if (f.size() < 2) continue;
    const auto w = radii_detail::circumcentre_weights(f);
    bool centre_inside = true;
    for (double x : w) centre_inside = centre_inside && x >= 0;
    if (!centre_inside) continue;
    const auto c = radii_detail::combine(f, w);
    const auto r0 = radii_detail::sub(f[0], c);
    const double r2 = radii_detail::dot(r0, r0);
    bool holds_all = true;
    for (const auto& q : p) {
      const auto d = radii_detail::sub(q, c);
      holds_all = holds_all && radii_detail::dot(d, d) <= r2 * (1 + 1e-12); // rounding only
    }
    if (holds_all) best = std::fmin(best, std::sqrt(r2));
  }
  return best;
}

/// φ_radius (Def 2.18) of a simplex: R_in / R_circ.
inline double radius_ratio(const std::vector<Vertex3>& p) {
  return inradius(p) / circumradius(p);
}

} // namespace symmesh::mesh
