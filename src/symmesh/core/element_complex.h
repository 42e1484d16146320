/// Definitions A.6–A.14 (element space, facets/faces, face-complete, co-faces, conforming,
/// element complex) and Definition 2.4 (mesh), 2.7 (mesh boundary) for simplices —
/// spec/definitions.md#def-a-10, #def-a-13, #def-2-4, #def-2-7
///
/// An element space is stored as a point array plus a set of simplices over it. Checks:
///  - face-complete (Def A.10): every facet of every element is an element;
///  - no dangling elements (Def 2.4 iii): every element is a cell or has a co-face cell;
///  - conforming (Def A.13): every two elements meet in a common face. For simplices this holds
///    iff the face completion has pairwise disjoint relative interiors and no two vertex indices
///    carry equal coordinates (spec/definitions.md#conforming-by-relative-interiors).
#pragma once
#include "symmesh/core/exact_lp.h"
#include "symmesh/core/linear_algebra.h"
#include "symmesh/core/point.h"
#include "symmesh/core/simplex.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <ostream>
#include <tuple>
#include <set>
#include <utility>
#include <sstream>
#include <string>
#include <vector>

namespace symmesh::core {

template <class FT, int D>
struct ElementComplex {
  using PointT = Point<FT, D>;
  std::vector<PointT> points;
  std::vector<Simplex> elements; ///< sorted, unique

  std::vector<PointT> coords(const Simplex& s) const {
    std::vector<PointT> out;
    for (VertexId v : s) out.push_back(points.at(v));
    return out;
  }
  void normalize() {
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
  }
  bool contains(const Simplex& s) const {
    return std::binary_search(elements.begin(), elements.end(), s);
  }
  int cell_dimension() const {
    int d = -1;
    for (const auto& e : elements) d = std::max(d, e.dim());
    return d;
  }
  std::vector<Simplex> cells() const {
    std::vector<Simplex> out;
    const int cd = cell_dimension();
    for (const auto& e : elements)
      if (e.dim() == cd) out.push_back(e);
    return out;
  }
  std::vector<Simplex> elements_of_dimension(int k) const {
    std::vector<Simplex> out;
    for (const auto& e : elements)
      if (e.dim() == k) out.push_back(e);
    return out;
  }
};

/// Affine independence of the vertex coordinates (Def A.15): a k-simplex spans a k-flat.
template <class FT, int D>
bool affinely_independent(const std::vector<Point<FT, D>>& p) {
  if (p.size() <= 1) return true;
  if (int(p.size()) > D + 1) return false;
  Matrix<FT> m;
  for (std::size_t i = 1; i < p.size(); ++i) {
    std::vector<FT> row(D);
    for (int d = 0; d < D; ++d) row[d] = p[i][d] - p[0][d];
    m.push_back(row);
  }
  return rank(m) == p.size() - 1;
}

/// det(c_1 − c_0, …, c_D − c_0) of D + 1 points: D! times the signed volume of their simplex
/// (positive when the vertices are ordered counter-clockwise / right-handed), exactly.
template <class FT, int D>
FT signed_volume_times_factorial(const std::vector<Point<FT, D>>& c) {
  Matrix<FT> m(D, std::vector<FT>(D));
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j)
      m[std::size_t(i)][std::size_t(j)] = c[std::size_t(j + 1)][i] - c[0][i];
  return determinant(m);
}

/// Barycentric coordinates of x with respect to the simplex with vertices b, if x ∈ aff(b).
namespace detail {
/// (u × w) of plane vectors.
template <class FT>
FT cross_2(const Point<FT, 2>& u, const Point<FT, 2>& w) {
  return u[0] * w[1] - u[1] * w[0];
}

/// barycentric() in the plane in closed form (Cramer's rule), for a point, a segment or a
/// triangle with affinely independent vertices; nullopt = degenerate input, use the general
/// solver. The interface and conformity tests ask this for every point near an interface.
template <class FT>
std::optional<std::optional<std::vector<FT>>> barycentric_2(const std::vector<Point<FT, 2>>& b,
                                                            const Point<FT, 2>& x) {
  using Result = std::optional<std::vector<FT>>;
  if (b.size() == 1) return Result(b[0] == x ? Result(std::vector<FT>{FT(1)}) : std::nullopt);
  const Point<FT, 2> u = b[1] - b[0], e = x - b[0];
  if (b.size() == 2) {
    const FT uu = dot<FT, 2>(u, u);
    if (uu == 0) return std::nullopt;
    if (cross_2<FT>(u, e) != 0) return Result(std::nullopt);
    const FT t = dot<FT, 2>(e, u) / uu;
    return Result(std::vector<FT>{FT(1) - t, t});
  }
  if (b.size() != 3) return std::nullopt;
  const Point<FT, 2> w = b[2] - b[0];
  const FT det = cross_2<FT>(u, w);
  if (det == 0) return std::nullopt;
  const FT s = cross_2<FT>(e, w) / det, t = cross_2<FT>(u, e) / det;
  return Result(std::vector<FT>{FT(1) - s - t, s, t});
}
} // namespace detail

template <class FT, int D>
std::optional<std::vector<FT>> barycentric(const std::vector<Point<FT, D>>& b,
                                           const Point<FT, D>& x) {
  if constexpr (D == 2) {
    if (auto r = detail::barycentric_2<FT>(b, x)) return *r;
  }
  const std::size_t m = b.size();
  Matrix<FT> a(D + 1, std::vector<FT>(m));
  std::vector<FT> rhs(D + 1);
  for (int d = 0; d < D; ++d) {
    for (std::size_t j = 0; j < m; ++j) a[d][j] = b[j][d];
    rhs[d] = x[d];
  }
  for (std::size_t j = 0; j < m; ++j) a[D][j] = 1;
  rhs[D] = 1;
  return solve_unique(a, rhs);
}

/// x on the closed segment [p, q], p != q, exactly (collinear, and between the ends).
template <class FT, int D>
bool point_on_segment(const Point<FT, D>& p, const Point<FT, D>& q, const Point<FT, D>& x) {
  const auto d = q - p, e = x - p;
  for (int i = 0; i < D; ++i)
    for (int j = i + 1; j < D; ++j)
      if (d[i] * e[j] - d[j] * e[i] != 0) return false;
  const FT t = dot<FT, D>(e, d);
  return t >= 0 && t <= dot<FT, D>(d, d);
}

namespace detail {
/// x ∈ conv(b) by signs of products of differences, without a division: over K_m a division is
/// an inverse in the field (an extended Euclid on polynomials), and at the interfaces the signs
/// are zero, so decided exactly. b is a triangle or a tetrahedron (in 2D: a triangle) with
/// affinely independent vertices; nullopt for every other case (barycentric decides).
template <class FT, int D>
std::optional<bool> point_in_simplex_by_signs(const std::vector<Point<FT, D>>& b,
                                              const Point<FT, D>& x) {
  if constexpr (D == 2) {
    if (b.size() != 3) return std::nullopt;
    const FT o = cross_2<FT>(b[1] - b[0], b[2] - b[0]);
    if (o == 0) return std::nullopt;
    const bool positive = o > 0;
    for (std::size_t i = 0; i < 3; ++i) {
      const FT s = cross_2<FT>(b[(i + 1) % 3] - b[i], x - b[i]);
      if (positive ? s < 0 : s > 0) return false;
    }
    return true;
  } else if constexpr (D == 3) {
    if (b.size() == 3) {
      // In the triangle's plane, e_i × (x − b_i) = λ_i n with λ_i ≥ 0 exactly when x is on the
      // inner side of edge i; n · (λ_i n) = λ_i |n|² has λ_i's sign.
      const Point<FT, 3> n = cross<FT>(b[1] - b[0], b[2] - b[0]);
      if (n == zero_point<FT, 3>()) return std::nullopt;
      if (dot<FT, 3>(n, x - b[0]) != 0) return false;
      for (std::size_t i = 0; i < 3; ++i)
        if (dot<FT, 3>(n, cross<FT>(b[(i + 1) % 3] - b[i], x - b[i])) < 0) return false;
      return true;
    }
    if (b.size() == 4) {
      // x replaces one vertex at a time; inside iff no orientation has the opposite sign.
      const auto orient = [](const Point<FT, 3>& p, const Point<FT, 3>& q, const Point<FT, 3>& r,
                             const Point<FT, 3>& s) {
        return dot<FT, 3>(q - p, cross<FT>(r - p, s - p));
      };
      const FT o = orient(b[0], b[1], b[2], b[3]);
      if (o == 0) return std::nullopt;
      const bool positive = o > 0;
      for (std::size_t i = 0; i < 4; ++i) {
        std::array<Point<FT, 3>, 4> c{b[0], b[1], b[2], b[3]};
        c[i] = x;
        const FT s = orient(c[0], c[1], c[2], c[3]);
        if (positive ? s < 0 : s > 0) return false;
      }
      return true;
    }
  }
  return std::nullopt;
}
} // namespace detail

/// x ∈ conv(b) for an affinely independent b.
template <class FT, int D>
bool point_in_simplex(const std::vector<Point<FT, D>>& b, const Point<FT, D>& x) {
  if (const auto by_signs = detail::point_in_simplex_by_signs<FT, D>(b, x)) return *by_signs;
  if (b.size() == 2 && !(b[0] == b[1])) return point_on_segment<FT, D>(b[0], b[1], x);
  auto mu = barycentric<FT, D>(b, x);
  if (!mu) return false;
  for (const auto& v : *mu)
    if (v < 0) return false;
  return true;
}

namespace detail {
/// The points of a ∪ b for the candidate planes: those a and b share first, each once. Elements
/// that meet in a common face are separated, if at all, by a plane through that face, so the
/// candidates through shared points come first; a repeated point adds only zero normals and
/// planes already listed.
template <class FT, int D>
std::vector<Point<FT, D>> candidate_points(const std::vector<Point<FT, D>>& a,
                                           const std::vector<Point<FT, D>>& b) {
  const auto in = [](const std::vector<Point<FT, D>>& s, const Point<FT, D>& p) {
    return std::find(s.begin(), s.end(), p) != s.end();
  };
  std::vector<Point<FT, D>> pts, rest;
  for (const auto& p : a) (in(b, p) ? pts : rest).push_back(p);
  for (const auto& q : b)
    if (!in(a, q)) rest.push_back(q);
  pts.insert(pts.end(), rest.begin(), rest.end());
  return pts;
}

/// Interval arithmetic that sets the rounding mode itself, so that every value it computes is a
/// certified enclosure. It only discards candidate separating planes; every decision that
/// certifies something is exact (spec/number-type.md, "Candidate planes discarded on intervals").
using Enclosure = CGAL::Interval_nt<true>;

template <class FT, int D>
std::vector<Point<Enclosure, D>> enclosures(const std::vector<Point<FT, D>>& x) {
  std::vector<Point<Enclosure, D>> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int d = 0; d < D; ++d) out[i][d] = Enclosure(CGAL::to_interval(x[i][d]));
  return out;
}

/// A candidate separating hyperplane through point i of a ∪ b. Kind 0 is orthogonal to the edge
/// (i, j); in the plane kind 1 contains that edge; in space kinds 1..3 contain the edge and the
/// coordinate direction e_{kind-1}, and kind 4 is spanned by points i, j and l.
struct CandidatePlane {
  std::size_t i, j, l;
  int kind;
};

/// The normal of a candidate plane, in any number type (exact, or enclosures for the filter).
template <class NT, int D>
Point<NT, D> candidate_normal(const std::vector<Point<NT, D>>& pts, const CandidatePlane& c) {
  const Point<NT, D> u = pts[c.j] - pts[c.i];
  if (c.kind == 0) return u;
  if constexpr (D == 2) {
    return Point<NT, 2>{{-u[1], u[0]}};
  } else {
    if (c.kind <= 3) {
      Point<NT, 3> nk{{NT(0), NT(0), NT(0)}};
      const int k = c.kind - 1, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      nk[k1] = u[k2];
      nk[k2] = -u[k1];
      return nk;
    }
    const Point<NT, 3> w = pts[c.l] - pts[c.i];
    return Point<NT, 3>{
        {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]}};
  }
}

/// Calls f on every candidate plane of n points, in order, until f returns true.
template <int D, class F>
bool for_each_candidate(std::size_t n, F&& f) {
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (f(CandidatePlane{i, j, j, 0})) return true;
      for (int kind = 1; kind < (D == 2 ? 2 : 4); ++kind)
        if (f(CandidatePlane{i, j, j, kind})) return true;
      if constexpr (D == 3)
        for (std::size_t l = j + 1; l < n; ++l)
          if (f(CandidatePlane{i, j, l, 4})) return true;
    }
  return false;
}

/// Whether the enclosures prove that the plane through p with normal n has a and b on opposite
/// closed sides in neither orientation: for each orientation some point of a or of b is
/// certainly strictly on its wrong side. Such a plane certifies no separation, weak or strict.
template <int D>
bool certainly_not_separating(const std::vector<Point<Enclosure, D>>& a,
                              const std::vector<Point<Enclosure, D>>& b,
                              const Point<Enclosure, D>& p, const Point<Enclosure, D>& n) {
  bool a_below_fails = false, a_above_fails = false; // a ≤ 0 ≤ b, a ≥ 0 ≥ b
  const auto note = [&](const Point<Enclosure, D>& q, bool in_a) {
    const Enclosure s = dot<Enclosure, D>(n, q - p);
    const bool negative = CGAL::certainly(s < 0), positive = CGAL::certainly(s > 0);
    if (in_a ? positive : negative) a_below_fails = true;
    if (in_a ? negative : positive) a_above_fails = true;
    return a_below_fails && a_above_fails;
  };
  for (const auto& q : a)
    if (note(q, true)) return true;
  for (const auto& q : b)
    if (note(q, false)) return true;
  return false;
}

/// Normals of candidate separating hyperplanes through point p_i of a ∪ b (candidate_points):
/// spanned by other points, or containing an edge and a coordinate direction, or orthogonal to
/// an edge. Cheap exact certificates; the LP decides whatever they do not certify. A plane the
/// enclosures already rule out is not formed exactly.
template <class FT, int D, class F>
bool for_each_candidate_plane(const std::vector<Point<FT, D>>& a,
                              const std::vector<Point<FT, D>>& b, F&& test) {
  const auto pts = candidate_points<FT, D>(a, b);
  const auto ipts = enclosures<FT, D>(pts), ia = enclosures<FT, D>(a), ib = enclosures<FT, D>(b);
  return for_each_candidate<D>(pts.size(), [&](const CandidatePlane& c) {
    if (certainly_not_separating<D>(ia, ib, ipts[c.i], candidate_normal<Enclosure, D>(ipts, c)))
      return false;
    return bool(test(pts[c.i], candidate_normal<FT, D>(pts, c)));
  });
}

/// Signs of n·(x - p) over a point set: -1/0/+1 presence flags. Stops once both strict signs
/// are present: the set then straddles the plane, which no separation test can use.
template <class FT, int D>
std::array<bool, 3> side_flags(const std::vector<Point<FT, D>>& x, const Point<FT, D>& p,
                               const Point<FT, D>& n) {
  std::array<bool, 3> f{false, false, false};
  for (const auto& q : x) {
    const FT s = dot<FT, D>(n, q - p);
    f[s < 0 ? 0 : (s > 0 ? 2 : 1)] = true;
    if (f[0] && f[2]) break;
  }
  return f;
}

inline bool straddles(const std::array<bool, 3>& f) {
  return f[0] && f[2];
}

} // namespace detail

namespace detail {
/// Sign of the orientation of (p, q, r) in the plane.
template <class FT>
int orientation_sign(const Point<FT, 2>& p, const Point<FT, 2>& q, const Point<FT, 2>& r) {
  const FT v = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

/// How the line through an edge of a separates the triangle b from a. Both inputs have three
/// points. Returns nullopt when a is degenerate (collinear); otherwise `weak` when some edge line
/// of a has all of b on its closed far side, and `strict` when on its open far side.
struct EdgeSeparation {
  bool weak = false, strict = false;
};
template <class FT>
std::optional<EdgeSeparation> edge_lines_separate(const std::vector<Point<FT, 2>>& a,
                                                  const std::vector<Point<FT, 2>>& b) {
  EdgeSeparation out;
  for (int e = 0; e < 3; ++e) {
    const auto &p = a[e], &q = a[(e + 1) % 3], &r = a[(e + 2) % 3];
    const int inside = orientation_sign<FT>(p, q, r);
    if (inside == 0) return std::nullopt;
    bool weak = true, strict = true;
    for (const auto& x : b) {
      const int s = orientation_sign<FT>(p, q, x) * inside;
      weak = weak && s <= 0;
      strict = strict && s < 0;
      if (!weak) break;
    }
    out.weak = out.weak || weak;
    out.strict = out.strict || strict;
    if (out.strict) break;
  }
  return out;
}

/// Two triangles in the plane by the separating axis theorem: the Minkowski difference a − b is
/// a convex polygon whose edges are parallel to edges of a or b, so a separating line, if any,
/// can be taken through an edge of a or of b. Returns nullopt for degenerate input.
template <class FT>
std::optional<EdgeSeparation> triangles_separation(const std::vector<Point<FT, 2>>& a,
                                                   const std::vector<Point<FT, 2>>& b) {
  const auto ab = edge_lines_separate<FT>(a, b);
  if (!ab) return std::nullopt;
  if (ab->strict) return ab;
  const auto ba = edge_lines_separate<FT>(b, a);
  if (!ba) return std::nullopt;
  return EdgeSeparation{ab->weak || ba->weak, ba->strict};
}

/// relint(a) ∩ relint(b) ≠ ∅ in the plane for a point, segment or triangle against a segment or
/// triangle, by orientation signs only (the separating axis theorem on the edge lines of both;
/// for two segments, crossing or overlapping collinearly). nullopt for degenerate input and for
/// two triangles (triangles_separation), which then take the general test.
template <class FT>
std::optional<bool> plane_relative_interiors_meet(const std::vector<Point<FT, 2>>& a,
                                                  const std::vector<Point<FT, 2>>& b) {
  if (a.size() > b.size()) return plane_relative_interiors_meet<FT>(b, a);
  if (b.size() == 3) {
    const int s = orientation_sign<FT>(b[0], b[1], b[2]);
    if (s == 0 || a.size() == 3) return std::nullopt;
    for (int e = 0; e < 3; ++e) { // a on the closed far side of an edge line of b
      bool outside = true;
      for (const auto& x : a)
        outside = outside && orientation_sign<FT>(b[e], b[(e + 1) % 3], x) * s <= 0;
      if (outside) return false;
    }
    if (a.size() == 1) return true;
    if (a[0] == a[1]) return std::nullopt;
    bool positive = false, negative = false; // b on one closed side of the line through a
    for (const auto& x : b) {
      const int o = orientation_sign<FT>(a[0], a[1], x);
      positive = positive || o > 0;
      negative = negative || o < 0;
    }
    return positive && negative;
  }
  if (b.size() != 2 || b[0] == b[1]) return std::nullopt;
  const Point<FT, 2> u = b[1] - b[0];
  if (a.size() == 1) {
    if (orientation_sign<FT>(b[0], b[1], a[0]) != 0) return false;
    return dot<FT, 2>(a[0] - b[0], u) > 0 && dot<FT, 2>(a[0] - b[1], u) < 0;
  }
  if (a.size() != 2 || a[0] == a[1]) return std::nullopt;
  const int o1 = orientation_sign<FT>(b[0], b[1], a[0]),
            o2 = orientation_sign<FT>(b[0], b[1], a[1]);
  if (o1 == 0 && o2 == 0) { // collinear: the open parameter intervals along u overlap
    const FT t0 = dot<FT, 2>(a[0] - b[0], u), t1 = dot<FT, 2>(a[1] - b[0], u);
    const FT lo = CGAL::max(FT(0), CGAL::min(t0, t1)),
             hi = CGAL::min(dot<FT, 2>(u, u), CGAL::max(t0, t1));
    return lo < hi;
  }
  const int o3 = orientation_sign<FT>(a[0], a[1], b[0]),
            o4 = orientation_sign<FT>(a[0], a[1], b[1]);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

template <class FT, int D>
bool are_two_triangles_in_plane(const std::vector<Point<FT, D>>& a,
                                const std::vector<Point<FT, D>>& b) {
  return D == 2 && a.size() == 3 && b.size() == 3;
}
} // namespace detail

/// A hyperplane puts a and b in opposite closed half-spaces without containing both: then
/// relint(a) ∩ relint(b) = ∅ (a convex set in a closed half-space, not inside its boundary, has
/// its relative interior in the open half-space).
template <class FT, int D>
bool weakly_separated(const std::vector<Point<FT, D>>& a, const std::vector<Point<FT, D>>& b) {
  return detail::for_each_candidate_plane<FT, D>(
      a, b, [&](const Point<FT, D>& p, const Point<FT, D>& n) {
        bool nonzero = false;
        for (int d = 0; d < D; ++d) nonzero = nonzero || n[d] != 0;
        if (!nonzero) return false;
        const auto fa = detail::side_flags<FT, D>(a, p, n);
        if (detail::straddles(fa)) return false;
        const auto fb = detail::side_flags<FT, D>(b, p, n);
        const bool a_in_plane = !fa[0] && !fa[2], b_in_plane = !fb[0] && !fb[2];
        if (a_in_plane && b_in_plane) return false;
        return (!fa[2] && !fb[0]) || (!fa[0] && !fb[2]);
      });
}

/// A hyperplane puts a and b in opposite half-spaces, one of them open: conv a ∩ conv b = ∅.
template <class FT, int D>
bool strictly_separated(const std::vector<Point<FT, D>>& a, const std::vector<Point<FT, D>>& b) {
  return detail::for_each_candidate_plane<FT, D>(
      a, b, [&](const Point<FT, D>& p, const Point<FT, D>& n) {
        const auto fa = detail::side_flags<FT, D>(a, p, n);
        if (detail::straddles(fa)) return false;
        const auto fb = detail::side_flags<FT, D>(b, p, n);
        const bool a_neg = !fa[2], a_pos = !fa[0], b_neg = !fb[2], b_pos = !fb[0];
        return (a_neg && b_pos && (!fa[1] || !fb[1])) || (a_pos && b_neg && (!fa[1] || !fb[1]));
      });
}

namespace detail {
/// The extreme values of coordinate d over a point set.
template <class FT, int D>
std::pair<FT, FT> coordinate_range(const std::vector<Point<FT, D>>& x, int d) {
  FT lo = x[0][d], hi = x[0][d];
  for (const auto& q : x) {
    if (q[d] < lo) lo = q[d];
    if (hi < q[d]) hi = q[d];
  }
  return {lo, hi};
}

/// Some coordinate axis on which the projections of relint(conv a) and relint(conv b) are
/// disjoint. A simplex's relative interior projects to the open interval between its extreme
/// coordinates (every vertex has a positive weight), or to their common value when they are
/// equal. Comparisons only: elements of a mesh that touch across an axis-parallel plane, as
/// neighbours on a grid do, are told apart without forming a separating plane.
template <class FT, int D>
bool axis_projections_separate(const std::vector<Point<FT, D>>& a,
                               const std::vector<Point<FT, D>>& b) {
  for (int d = 0; d < D; ++d) {
    const auto [alo, ahi] = coordinate_range<FT, D>(a, d);
    const auto [blo, bhi] = coordinate_range<FT, D>(b, d);
    const bool a_flat = !(alo < ahi), b_flat = !(blo < bhi);
    if (a_flat && b_flat ? alo != blo
        : a_flat         ? !(blo < alo && alo < bhi)
        : b_flat         ? !(alo < blo && blo < ahi)
                         : !(alo < bhi && blo < ahi))
      return true;
  }
  return false;
}
} // namespace detail

/// relint(conv a) ∩ relint(conv b) ≠ ∅, decided exactly.
template <class FT, int D>
bool relative_interiors_meet(const std::vector<Point<FT, D>>& a,
                             const std::vector<Point<FT, D>>& b) {
  if (a.size() == 1 && b.size() == 1) return a[0] == b[0];
  if (detail::axis_projections_separate<FT, D>(a, b)) return false;
  if constexpr (D == 2) {
    // The common case of overlap and conformity tests: 6 edge lines instead of all candidates.
    if (detail::are_two_triangles_in_plane<FT, D>(a, b))
      if (const auto sep = detail::triangles_separation<FT>(a, b)) return !sep->weak;
    if (const auto meet = detail::plane_relative_interiors_meet<FT>(a, b)) return *meet;
  }
  if (weakly_separated<FT, D>(a, b)) return false;
  if (a.size() == 1) {
    auto mu = barycentric<FT, D>(b, a[0]);
    return mu && std::all_of(mu->begin(), mu->end(), [](const FT& v) { return v > 0; });
  }
  if (b.size() == 1) return relative_interiors_meet<FT, D>(b, a);
  return common_point<FT, D>({{a, true}, {b, true}}).strict_meet;
}

/// conv a ∩ conv b ≠ ∅ (closed sets), decided exactly.
template <class FT, int D>
bool closed_simplices_meet(const std::vector<Point<FT, D>>& a, const std::vector<Point<FT, D>>& b) {
  if constexpr (D == 2) {
    if (detail::are_two_triangles_in_plane<FT, D>(a, b))
      if (const auto sep = detail::triangles_separation<FT>(a, b)) return !sep->strict;
  }
  if (strictly_separated<FT, D>(a, b)) return false;
  return common_point<FT, D>({{a, false}, {b, false}}).closed_meet;
}

/// Exact axis-aligned bounding box, used only to skip pairs that cannot meet.
template <class FT, int D>
struct Box {
  Point<FT, D> lo, hi;
  bool overlaps(const Box& o) const {
    for (int d = 0; d < D; ++d)
      if (hi[d] < o.lo[d] || o.hi[d] < lo[d]) return false;
    return true;
  }
};
template <class FT, int D>
Box<FT, D> box_of(const std::vector<Point<FT, D>>& p) {
  Box<FT, D> b;
  for (int d = 0; d < D; ++d) std::tie(b.lo[d], b.hi[d]) = detail::coordinate_range<FT, D>(p, d);
  return b;
}

/// Calls f(i, j) for every pair i < j of items whose boxes overlap (sweep along x). Any box
/// type with lo[0], hi[0] and overlaps() (exact Box, or an interval enclosure as a filter).
template <class BoxT, class F>
void for_each_overlapping_box_pair(const std::vector<BoxT>& boxes, F&& f) {
  std::vector<std::size_t> order(boxes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return boxes[a].lo[0] < boxes[b].lo[0]; });
  for (std::size_t x = 0; x < order.size(); ++x)
    for (std::size_t y = x + 1; y < order.size(); ++y) {
      if (boxes[order[x]].hi[0] < boxes[order[y]].lo[0]) break;
      if (boxes[order[x]].overlaps(boxes[order[y]]))
        if (!f(std::min(order[x], order[y]), std::max(order[x], order[y]))) return;
    }
}

template <class FT, int D, class F>
void for_each_overlapping_pair(const std::vector<Box<FT, D>>& boxes, F&& f) {
  for_each_overlapping_box_pair(boxes, std::forward<F>(f));
}

/// Face-completion fc(X) (Def A.10, Eq. A.8) for simplices: all faces of all elements.
template <class FT, int D>
ElementComplex<FT, D> face_completion(const ElementComplex<FT, D>& x) {
  ElementComplex<FT, D> out;
  out.points = x.points;
  for (const auto& e : x.elements)
    for (const auto& f : faces(e)) out.elements.push_back(f);
  out.normalize();
  return out;
}

template <class FT, int D>
bool elements_nondegenerate(const ElementComplex<FT, D>& x, std::ostream* why = nullptr) {
  for (const auto& e : x.elements) {
    for (VertexId v : e)
      if (v >= x.points.size()) {
        if (why) *why << "element refers to vertex " << v << " which does not exist";
        return false;
      }
    if (!affinely_independent<FT, D>(x.coords(e))) {
      if (why)
        *why << "element with " << int(e.n) << " vertices is degenerate (not affinely independent)";
      return false;
    }
  }
  return true;
}

/// Def A.10: face-complete. For non-degenerate simplices the facets cover the relative boundary
/// with disjoint relative interiors, so it suffices that every facet is present.
template <class FT, int D>
bool is_face_complete(const ElementComplex<FT, D>& x, std::ostream* why = nullptr) {
  if (!elements_nondegenerate(x, why)) return false;
  for (const auto& e : x.elements)
    for (const auto& f : facets(e))
      if (!x.contains(f)) {
        if (why) *why << "a facet of a " << e.dim() << "-simplex is missing";
        return false;
      }
  return true;
}

/// Def 2.4 (iii): every element is a cell or has a co-face cell.
template <class FT, int D>
bool has_no_dangling_elements(const ElementComplex<FT, D>& x, std::ostream* why = nullptr) {
  const int cd = x.cell_dimension();
  const auto cells = x.cells();
  for (const auto& e : x.elements) {
    if (e.dim() == cd) continue;
    bool has = false;
    for (const auto& c : cells)
      if (e.is_face_of(c)) {
        has = true;
        break;
      }
    if (!has) {
      if (why) *why << "dangling " << e.dim() << "-element (no co-face cell)";
      return false;
    }
  }
  return true;
}

/// A pair of elements whose intersection is not a common face.
struct ConformityViolation {
  Simplex a, b;
};

namespace detail {
/// The simplex on the vertices of a and b together, when there are at most four.
inline std::optional<Simplex> simplex_union(const Simplex& a, const Simplex& b) {
  std::array<VertexId, 8> u{};
  const auto n = std::set_union(a.begin(), a.end(), b.begin(), b.end(), u.begin()) - u.begin();
  if (n > 4) return std::nullopt;
  return Simplex::from_range(u.data(), u.data() + n);
}
} // namespace detail

/// Def A.13 for simplices: checks the face completion for pairwise disjoint relative interiors
/// and for distinct vertex indices with equal coordinates. Returns the first violating pair.
/// Two distinct faces of one non-degenerate simplex have disjoint relative interiors (a point of
/// the simplex has unique barycentric coordinates, and a face's relative interior is where they
/// are positive exactly on its vertices), so a pair whose union is a non-degenerate element of the
/// face completion is decided without geometry; most pairs of neighbouring elements are such.
template <class FT, int D>
std::optional<ConformityViolation> find_nonconformity(const ElementComplex<FT, D>& x) {
  const auto fc = face_completion(x);
  std::vector<Box<FT, D>> boxes;
  for (const auto& e : fc.elements) boxes.push_back(box_of<FT, D>(fc.coords(e)));
  std::vector<signed char> independent(fc.elements.size(), -1); // -1: not yet decided
  const auto faces_of_one_simplex = [&](const Simplex& a, const Simplex& b) {
    const auto u = detail::simplex_union(a, b);
    if (!u) return false;
    const auto it = std::lower_bound(fc.elements.begin(), fc.elements.end(), *u);
    if (it == fc.elements.end() || *it != *u) return false;
    auto& known = independent[std::size_t(it - fc.elements.begin())];
    if (known < 0) known = affinely_independent<FT, D>(fc.coords(*u)) ? 1 : 0;
    return known == 1;
  };
  std::optional<ConformityViolation> bad;
  for_each_overlapping_pair<FT, D>(boxes, [&](std::size_t i, std::size_t j) {
    const Simplex& a = fc.elements[i];
    const Simplex& b = fc.elements[j];
    if (a.is_face_of(b) || b.is_face_of(a)) return true; // relint(face) ⊆ bnd(b)
    if (faces_of_one_simplex(a, b)) return true;
    if (relative_interiors_meet<FT, D>(fc.coords(a), fc.coords(b))) {
      bad = ConformityViolation{a, b};
      return false;
    }
    return true;
  });
  return bad;
}

template <class FT, int D>
bool is_conforming(const ElementComplex<FT, D>& x, std::ostream* why = nullptr) {
  if (!elements_nondegenerate(x, why)) return false;
  if (auto v = find_nonconformity(x)) {
    if (why)
      *why << "a " << v->a.dim() << "-element and a " << v->b.dim()
           << "-element meet outside a common face";
    return false;
  }
  return true;
}

/// Def 2.4: a mesh is finite, face-complete, has no dangling elements, and lies in an element
/// complex (is conforming).
template <class FT, int D>
bool is_mesh(const ElementComplex<FT, D>& x, std::ostream* why = nullptr) {
  if (x.elements.empty()) {
    if (why) *why << "empty element set";
    return false;
  }
  return is_face_complete(x, why) && has_no_dangling_elements(x, why) && is_conforming(x, why);
}

/// cofaces_k(E) (Def A.11) restricted to the cells of x.
template <class FT, int D>
std::vector<Simplex> coface_cells(const ElementComplex<FT, D>& x, const Simplex& e) {
  std::vector<Simplex> out;
  const int cd = x.cell_dimension();
  for (const auto& c : x.elements)
    if (c.dim() == cd && e.is_face_of(c)) out.push_back(c);
  return out;
}

/// Def 2.7: bnd(M) = elements in the relative boundary of us(M). For a mesh whose underlying
/// space is a manifold this is the face completion of the facets with exactly one co-face cell.
/// \pre is_mesh(m) and every facet has at most two co-face cells
template <class FT, int D>
ElementComplex<FT, D> mesh_boundary(const ElementComplex<FT, D>& m) {
  std::map<Simplex, int> count;
  const int cd = m.cell_dimension();
  for (const auto& c : m.elements)
    if (c.dim() == cd)
      for (const auto& f : facets(c)) ++count[f];
  ElementComplex<FT, D> out;
  out.points = m.points;
  for (const auto& [f, k] : count)
    if (k == 1)
      for (const auto& g : faces(f)) out.elements.push_back(g);
  out.normalize();
  return out;
}

/// x ∈ us(E).
template <class FT, int D>
bool point_in_underlying_space(const ElementComplex<FT, D>& e, const Point<FT, D>& x) {
  for (const auto& s : e.elements)
    if (point_in_simplex<FT, D>(e.coords(s), x)) return true;
  return false;
}

namespace detail {
/// Length (k = 1) or area (k = 2) of {s in the standard k-simplex : h_j(s) >= 0}, where
/// h_j(s) = c_j + Σ_i g_{j,i} s_i with parameters s_1..s_k.
template <class FT>
FT clipped_standard_simplex_measure(int k, const std::vector<std::vector<FT>>& halfspaces) {
  using P = std::array<FT, 2>;
  std::vector<P> poly;
  if (k == 1) {
    poly = {P{FT(0), FT(0)}, P{FT(1), FT(0)}};
  } else {
    poly = {P{FT(0), FT(0)}, P{FT(1), FT(0)}, P{FT(0), FT(1)}};
  }
  auto eval = [&](const std::vector<FT>& h, const P& p) {
    FT v = h[0] + h[1] * p[0];
    if (k == 2) v += h[2] * p[1];
    return v;
  };
  for (const auto& h : halfspaces) {
    std::vector<P> next;
    const std::size_t n = poly.size();
    if (n == 0) break;
    if (k == 1) {
      const FT a = eval(h, poly[0]), b = eval(h, poly[1]);
      if (a < 0 && b < 0) return FT(0);
      if (a >= 0 && b >= 0) continue;
      const FT t = a / (a - b);
      const P x{poly[0][0] + t * (poly[1][0] - poly[0][0]), FT(0)};
      poly = a >= 0 ? std::vector<P>{poly[0], x} : std::vector<P>{x, poly[1]};
      continue;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const P& p = poly[i];
      const P& q = poly[(i + 1) % n];
      const FT a = eval(h, p), b = eval(h, q);
      if (a >= 0) next.push_back(p);
      if ((a >= 0) != (b >= 0)) {
        const FT t = a / (a - b);
        next.push_back(P{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
    }
    poly = next;
  }
  if (k == 1) return poly.size() == 2 ? poly[1][0] - poly[0][0] : FT(0);
  FT twice = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P& p = poly[i];
    const P& q = poly[(i + 1) % poly.size()];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return twice / 2;
}
} // namespace detail

/// e ⊆ us(M) for a simplex e, exactly (k <= 2 by measure; k = D by cell_covered_by).
/// The relative interiors of M's elements partition us(M); e ∩ relint(f) has positive k-measure
/// only if aff(e) ⊆ aff(f) and aff(e) lies in no facet hyperplane of f, and then its measure is
/// that of e ∩ f, computed by clipping e's parameter simplex with f's barycentric half-spaces.
/// e ⊆ us(M) iff the measures add up to e's (us(M) is closed).
/// \pre M is face-complete and conforming
template <class FT, int D>
bool simplex_covered_by(const std::vector<Point<FT, D>>& e, const ElementComplex<FT, D>& m);

/// A D-simplex c ⊆ us(M) for a pure D-dimensional mesh M: int(c) is connected, so if no element
/// of bnd(M) meets int(c), int(c) lies wholly inside or wholly outside us(M), and the centroid
/// decides which (closure then gives c itself).
template <class FT, int D>
bool cell_covered_by(const std::vector<Point<FT, D>>& c, const ElementComplex<FT, D>& m) {
  Point<FT, D> centroid = zero_point<FT, D>();
  for (const auto& p : c) centroid = centroid + p;
  centroid = scaled<FT, D>(centroid, FT(1) / FT(int(c.size())));
  if (!point_in_underlying_space(m, centroid)) return false;
  const auto bnd = mesh_boundary(m);
  const auto cbox = box_of<FT, D>(c);
  for (const auto& g : bnd.elements) {
    const auto gp = bnd.coords(g);
    if (!cbox.overlaps(box_of<FT, D>(gp))) continue;
    if (relative_interiors_meet<FT, D>(c, gp)) return false;
  }
  return true;
}

template <class FT, int D>
bool simplex_covered_by(const std::vector<Point<FT, D>>& e, const ElementComplex<FT, D>& m) {
  const int k = int(e.size()) - 1;
  if (k == 0) return point_in_underlying_space(m, e[0]);
  if (k == D && m.cell_dimension() == D) return cell_covered_by<FT, D>(e, m);
  if (k > 2) throw std::invalid_argument("simplex_covered_by: a 3-simplex needs a pure 3D mesh");
  FT total = 0;
  const FT full = k == 1 ? FT(1) : FT(1) / FT(2);
  const auto ebox = box_of<FT, D>(e);
  for (const auto& f : m.elements) {
    if (f.dim() < k) continue;
    const auto fb = m.coords(f);
    if (!ebox.overlaps(box_of<FT, D>(fb))) continue;
    std::vector<std::vector<FT>> mu; // mu[i] = barycentric coordinates of e[i] w.r.t. f
    bool in_aff = true;
    for (const auto& a : e) {
      auto b = barycentric<FT, D>(fb, a);
      if (!b) {
        in_aff = false;
        break;
      }
      mu.push_back(*b);
    }
    if (!in_aff) continue;
    bool in_facet_plane = false;
    std::vector<std::vector<FT>> hs;
    for (std::size_t j = 0; j < fb.size(); ++j) {
      bool all_zero = true;
      for (int i = 0; i <= k; ++i)
        if (mu[i][j] != 0) all_zero = false;
      if (all_zero && fb.size() > 1) {
        in_facet_plane = true;
        break;
      }
      std::vector<FT> h{mu[0][j]};
      for (int i = 1; i <= k; ++i) h.push_back(mu[i][j] - mu[0][j]);
      hs.push_back(h);
    }
    if (in_facet_plane) continue;
    total += detail::clipped_standard_simplex_measure<FT>(k, hs);
  }
  return total == full;
}

/// Intersection of two element sets over the same point array (Lemma 2.1).
template <class FT, int D>
ElementComplex<FT, D> intersection(const ElementComplex<FT, D>& a, const ElementComplex<FT, D>& b) {
  ElementComplex<FT, D> out;
  out.points = a.points;
  std::set_intersection(a.elements.begin(), a.elements.end(), b.elements.begin(), b.elements.end(),
                        std::back_inserter(out.elements));
  return out;
}

template <class FT, int D>
ElementComplex<FT, D> set_union(const ElementComplex<FT, D>& a, const ElementComplex<FT, D>& b) {
  ElementComplex<FT, D> out;
  out.points = a.points;
  std::set_union(a.elements.begin(), a.elements.end(), b.elements.begin(), b.elements.end(),
                 std::back_inserter(out.elements));
  return out;
}

/// Re-expresses two element sets over one point array in which exactly-equal coordinates share
/// one index (so that set operations compare elements as point sets).
template <class FT, int D>
std::pair<ElementComplex<FT, D>, ElementComplex<FT, D>> unify(const ElementComplex<FT, D>& a,
                                                              const ElementComplex<FT, D>& b) {
  std::map<Point<FT, D>, VertexId, PointLess<FT, D>> index;
  std::vector<Point<FT, D>> pts;
  auto remap = [&](const ElementComplex<FT, D>& x) {
    std::vector<VertexId> to(x.points.size());
    for (std::size_t i = 0; i < x.points.size(); ++i) {
      auto [it, inserted] = index.emplace(x.points[i], VertexId(pts.size()));
      if (inserted) pts.push_back(x.points[i]);
      to[i] = it->second;
    }
    ElementComplex<FT, D> y;
    for (const auto& e : x.elements) {
      std::array<VertexId, 4> ids{};
      for (int i = 0; i < e.n; ++i) ids[i] = to[e.v[i]];
      y.elements.push_back(Simplex::from_range(ids.data(), ids.data() + e.n));
    }
    return y;
  };
  auto ua = remap(a);
  auto ub = remap(b);
  ua.points = pts;
  ub.points = pts;
  ua.normalize();
  ub.normalize();
  return {ua, ub};
}

} // namespace symmesh::core
