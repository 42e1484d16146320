// Linear cells and Definitions A.26-A.30 (covering, manifold partition, intersection partition,
// refinement) — spec/intersection-partition.md
//
// Every operation is half-space clipping of a closed convex point cycle (Sutherland–Hodgman),
// exact in FT: a ∩ b is a's vertex cycle clipped by the closed half-spaces whose intersection is b
// (two opposite ones per equation of aff(b)). Clipping a cycle that runs around the relative
// boundary of a convex set (for a segment: there and back) by a closed half-space yields a cycle
// around the relative boundary of the clipped set, including every degenerate outcome (a
// segment, a point), so one routine covers all dimension cases. Only the number type comes from
// CGAL (the instantiations at the end), so a field type without a CGAL kernel works unchanged.
//
// Definitions only, included by the translation units that instantiate them for one number
// type each (intersection_partition.cpp: rationals; cyclotomic_instantiations.cpp: K_m), so that
// the heavy kernels compile in parallel and once.
#pragma once
#include "symmesh/core/intersection_partition.h"

#include "symmesh/core/kernel.h"

#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

namespace symmesh::core {
namespace {

template <class FT, int D>
using Pts = std::vector<Point<FT, D>>;

/// {x : w·x >= c} (an inequality) or {x : w·x = c} (an equation).
template <class FT, int D>
struct HalfSpace {
  Point<FT, D> w;
  FT c;
};

/// aff(c) as equations and c inside aff(c) as inequalities: c = {eq holds} ∩ {ge holds}.
template <class FT, int D>
struct Constraints {
  std::vector<HalfSpace<FT, D>> eq, ge;
};

template <class FT, int D>
Point<FT, D> negated(const Point<FT, D>& a) {
  return scaled<FT, D>(a, FT(-1));
}

template <class FT, int D>
Point<FT, D> unit(int k) {
  Point<FT, D> e = zero_point<FT, D>();
  e[k] = 1;
  return e;
}

template <class FT, int D>
bool is_zero(const Point<FT, D>& v) {
  for (int i = 0; i < D; ++i)
    if (v[i] != 0) return false;
  return true;
}

/// u ∥ v (either may be zero): all 2x2 minors vanish.
template <class FT, int D>
bool parallel(const Point<FT, D>& u, const Point<FT, D>& v) {
  for (int i = 0; i < D; ++i)
    for (int j = i + 1; j < D; ++j)
      if (u[i] * v[j] != u[j] * v[i]) return false;
  return true;
}

/// The points span at least a plane (duplicates allowed).
template <class FT, int D>
bool spans_plane(const Pts<FT, D>& p) {
  if (p.size() < 3) return false;
  std::size_t i = 1;
  while (i < p.size() && p[i] == p[0]) ++i;
  if (i == p.size()) return false;
  const Point<FT, D> u = p[i] - p[0];
  for (std::size_t k = i + 1; k < p.size(); ++k)
    if (!parallel<FT, D>(u, p[k] - p[0])) return true;
  return false;
}

/// Rotates and orients a convex cycle into the canonical order (convex_cell.h).
template <class FT, int D>
Pts<FT, D> canonical_cycle(const Pts<FT, D>& cyc) {
  const std::size_t n = cyc.size();
  const PointLess<FT, D> less;
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (less(cyc[i], cyc[m])) m = i;
  const bool forward = less(cyc[(m + 1) % n], cyc[(m + n - 1) % n]);
  Pts<FT, D> out;
  for (std::size_t i = 0; i < n; ++i)
    out.push_back(forward ? cyc[(m + i) % n] : cyc[(m + n - i) % n]);
  return out;
}

/// The coordinate dropped to project a plane with normal n injectively onto a coordinate plane.
template <class FT>
int drop_axis(const Point<FT, 3>& n) {
  auto abs = [](const FT& x) { return x < 0 ? FT(-x) : x; };
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (abs(n[k]) < abs(n[i])) k = i;
  return k;
}

template <class FT, int D>
Constraints<FT, D> constraints(const ConvexCell<FT, D>& c) {
  Constraints<FT, D> out;
  const auto& v = c.vertices;
  auto add_eq = [&](const Point<FT, D>& w) { out.eq.push_back({w, dot<FT, D>(w, v[0])}); };
  if (c.dim == 0) {
    for (int k = 0; k < D; ++k) add_eq(unit<FT, D>(k));
    return out;
  }
  if (c.dim == 1) {
    const Point<FT, D> u = v[1] - v[0];
    if constexpr (D == 2) {
      add_eq(Point<FT, 2>{{-u[1], u[0]}});
    } else {
      // u × e_k span u⊥; two non-parallel ones suffice.
      std::vector<Point<FT, 3>> normals;
      for (int k = 0; k < 3 && normals.size() < 2; ++k) {
        const auto n = cross<FT>(u, unit<FT, 3>(k));
        if (is_zero<FT, 3>(n)) continue;
        if (!normals.empty() && parallel<FT, 3>(normals[0], n)) continue;
        normals.push_back(n);
      }
      for (const auto& n : normals) add_eq(n);
    }
    out.ge.push_back({u, dot<FT, D>(u, v[0])});
    out.ge.push_back({negated<FT, D>(u), -dot<FT, D>(u, v[1])});
    return out;
  }
  // A polygon: each edge e_i = v_{i+1} - v_i bounds a half-plane of aff(c) holding the interior.
  const std::size_t n = v.size();
  if constexpr (D == 3) {
    const auto nrm = cross<FT>(v[1] - v[0], v[2] - v[0]);
    add_eq(nrm);
    for (std::size_t i = 0; i < n; ++i) {
      // (e × (x - v_i))·nrm = (nrm × e)·(x - v_i) > 0 inside, as for x = v_2 and i = 0.
      const auto w = cross<FT>(nrm, v[(i + 1) % n] - v[i]);
      out.ge.push_back({w, dot<FT, 3>(w, v[i])});
    }
  } else {
    const Point<FT, 2> a = v[1] - v[0], b = v[2] - v[0];
    const FT s = a[0] * b[1] - a[1] * b[0] > 0 ? FT(1) : FT(-1);
    for (std::size_t i = 0; i < n; ++i) {
      const Point<FT, 2> e = v[(i + 1) % n] - v[i];
      const Point<FT, 2> w{{-e[1] * s, e[0] * s}};
      out.ge.push_back({w, dot<FT, 2>(w, v[i])});
    }
  }
  return out;
}

/// The cycle clipped by {x : w·x >= c}.
template <class FT, int D>
Pts<FT, D> clip(const Pts<FT, D>& cyc, const Point<FT, D>& w, const FT& c) {
  const std::size_t n = cyc.size();
  std::vector<FT> val(n);
  for (std::size_t i = 0; i < n; ++i) val[i] = dot<FT, D>(w, cyc[i]) - c;
  Pts<FT, D> out;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const bool in_i = val[i] >= 0, in_j = val[j] >= 0;
    if (in_i) out.push_back(cyc[i]);
    // A crossing at an end point with value 0 is that (kept) end point itself.
    if (in_i != in_j && val[in_i ? i : j] != 0) {
      const FT t = val[i] / (val[i] - val[j]);
      out.push_back(cyc[i] + scaled<FT, D>(cyc[j] - cyc[i], t));
    }
  }
  return out;
}

/// The cycle clipped by all constraints of c: the cycle's convex hull intersected with c.
template <class FT, int D>
Pts<FT, D> clip_by(Pts<FT, D> cyc, const Constraints<FT, D>& k) {
  for (const auto& h : k.eq) {
    if (cyc.empty()) return cyc;
    cyc = clip<FT, D>(cyc, h.w, h.c);
    if (cyc.empty()) return cyc;
    cyc = clip<FT, D>(cyc, negated<FT, D>(h.w), -h.c);
  }
  for (const auto& h : k.ge) {
    if (cyc.empty()) return cyc;
    cyc = clip<FT, D>(cyc, h.w, h.c);
  }
  return cyc;
}

template <class FT, int D>
struct Bounds {
  Point<FT, D> lo, hi;
  explicit Bounds(const Pts<FT, D>& p) : lo(p[0]), hi(p[0]) {
    for (const auto& q : p)
      for (int d = 0; d < D; ++d) {
        if (q[d] < lo[d]) lo[d] = q[d];
        if (hi[d] < q[d]) hi[d] = q[d];
      }
  }
  bool overlaps(const Bounds& o) const {
    for (int d = 0; d < D; ++d)
      if (hi[d] < o.lo[d] || o.hi[d] < lo[d]) return false;
    return true;
  }
};

template <class FT, int D>
void require_valid(const LinearSet<FT, D>& a, const char* who) {
  std::ostringstream why;
  if (!a.is_valid(&why)) throw std::invalid_argument(std::string(who) + ": " + why.str());
}

template <class FT, int D>
std::vector<ConvexCell<FT, D>> ip_unchecked(const LinearSet<FT, D>& a, const LinearSet<FT, D>& b) {
  std::vector<Bounds<FT, D>> bb;
  for (const auto& c : b.cells) bb.emplace_back(c.vertices);
  std::vector<ConvexCell<FT, D>> out;
  for (const auto& ca : a.cells) {
    const Bounds<FT, D> ba(ca.vertices);
    for (std::size_t j = 0; j < b.cells.size(); ++j) {
      if (!ba.overlaps(bb[j])) continue;
      if (auto q = intersect<FT, D>(ca, b.cells[j])) out.push_back(*q);
    }
  }
  std::sort(out.begin(), out.end(), ConvexCellLess<FT, D>());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

} // namespace

// ----- ConvexCell ------------------------------------------------------------------------------

template <class FT, int D>
ConvexCell<FT, D> make_convex_cell(const std::vector<Point<FT, D>>& points) {
  static_assert(D == 2 || D == 3, "linear cells are implemented for D = 2 and D = 3");
  if (points.empty()) throw std::invalid_argument("make_convex_cell: no points");
  Pts<FT, D> p = points;
  std::sort(p.begin(), p.end(), PointLess<FT, D>());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  ConvexCell<FT, D> out;
  if (p.size() == 1) {
    out.dim = 0;
    out.vertices = p;
    return out;
  }
  const Point<FT, D> u = p[1] - p[0];
  std::size_t k = 2;
  while (k < p.size() && parallel<FT, D>(u, p[k] - p[0])) ++k;
  if (k == p.size()) {
    // Lexicographic order is monotone along a line, so the extremes are its first and last.
    out.dim = 1;
    out.vertices = {p.front(), p.back()};
    return out;
  }
  int ax = 0, ay = 1;
  if constexpr (D == 3) {
    const auto n = cross<FT>(u, p[k] - p[0]);
    for (const auto& q : p)
      if (dot<FT, 3>(n, q - p[0]) != 0)
        throw std::invalid_argument("make_convex_cell: the points span 3 dimensions");
    const int drop = drop_axis<FT>(n);
    ax = drop == 0 ? 1 : 0;
    ay = drop == 2 ? 1 : 2;
  }
  // Andrew's monotone chain in the projection (injective on aff(p)); turns <= 0 are popped, so
  // collinear points on edges are dropped.
  std::vector<std::size_t> idx(p.size());
  std::iota(idx.begin(), idx.end(), std::size_t(0));
  std::sort(idx.begin(), idx.end(), [&](std::size_t i, std::size_t j) {
    if (p[i][ax] != p[j][ax]) return p[i][ax] < p[j][ax];
    return p[i][ay] < p[j][ay];
  });
  auto turn = [&](std::size_t i, std::size_t j, std::size_t l) {
    return (p[j][ax] - p[i][ax]) * (p[l][ay] - p[i][ay]) -
           (p[j][ay] - p[i][ay]) * (p[l][ax] - p[i][ax]);
  };
  std::vector<std::size_t> h(2 * p.size());
  std::size_t m = 0;
  for (std::size_t i = 0; i < idx.size(); ++i) {
    while (m >= 2 && turn(h[m - 2], h[m - 1], idx[i]) <= 0) --m;
    h[m++] = idx[i];
  }
  for (std::size_t i = idx.size() - 1, lower = m + 1; i-- > 0;) {
    while (m >= lower && turn(h[m - 2], h[m - 1], idx[i]) <= 0) --m;
    h[m++] = idx[i];
  }
  Pts<FT, D> cyc;
  for (std::size_t i = 0; i + 1 < m; ++i) cyc.push_back(p[h[i]]);
  out.dim = 2;
  out.vertices = canonical_cycle<FT, D>(cyc);
  return out;
}

template <class FT, int D>
bool ConvexCell<FT, D>::is_valid(std::ostream* why) const {
  auto fail = [&](const char* m) {
    if (why) *why << "convex cell: " << m;
    return false;
  };
  if (dim < 0 || dim > std::min(D, 2)) return fail("dimension out of range");
  if (dim < 2 ? vertices.size() != std::size_t(dim + 1) : vertices.size() < 3)
    return fail("vertex count does not match the dimension");
  ConvexCell<FT, D> canon;
  try {
    canon = make_convex_cell<FT, D>(vertices);
  } catch (const std::invalid_argument&) {
    return fail("the vertices are not coplanar");
  }
  if (canon.dim != dim) return fail("the affine dimension of the vertices differs from dim");
  if (canon.vertices.size() != vertices.size())
    return fail("a vertex is repeated or not extreme (inside, or collinear on an edge)");
  if (canon.vertices != vertices) return fail("the vertices are not in canonical order");
  return true;
}

template <class FT, int D>
bool contains(const ConvexCell<FT, D>& c, const Point<FT, D>& x) {
  if (c.dim == 0) return c.vertices[0] == x;
  const auto k = constraints<FT, D>(c);
  for (const auto& h : k.eq)
    if (dot<FT, D>(h.w, x) != h.c) return false;
  for (const auto& h : k.ge)
    if (dot<FT, D>(h.w, x) < h.c) return false;
  return true;
}

template <class FT, int D>
bool relative_interior_contains(const ConvexCell<FT, D>& c, const Point<FT, D>& x) {
  if (c.dim == 0) return c.vertices[0] == x;
  const auto k = constraints<FT, D>(c);
  for (const auto& h : k.eq)
    if (dot<FT, D>(h.w, x) != h.c) return false;
  for (const auto& h : k.ge)
    if (dot<FT, D>(h.w, x) <= h.c) return false;
  return true;
}

template <class FT, int D>
std::optional<ConvexCell<FT, D>> intersect(const ConvexCell<FT, D>& a, const ConvexCell<FT, D>& b) {
  if (!Bounds<FT, D>(a.vertices).overlaps(Bounds<FT, D>(b.vertices))) return std::nullopt;
  // Clip the shorter cycle: the work is |cycle| × |constraints|.
  const bool swap = b.vertices.size() < a.vertices.size();
  const ConvexCell<FT, D>& s = swap ? b : a;
  const ConvexCell<FT, D>& t = swap ? a : b;
  if (s.dim == 0) return contains<FT, D>(t, s.vertices[0]) ? std::optional(s) : std::nullopt;
  const auto cyc = clip_by<FT, D>(s.vertices, constraints<FT, D>(t));
  if (cyc.empty()) return std::nullopt;
  return make_convex_cell<FT, D>(cyc);
}

template <class FT, int D>
std::optional<ConvexCell<FT, D>> clip_halfspace(const ConvexCell<FT, D>& c,
                                                const Point<FT, D>& normal, const FT& offset) {
  const auto cyc = clip<FT, D>(c.vertices, normal, offset);
  if (cyc.empty()) return std::nullopt;
  return make_convex_cell<FT, D>(cyc);
}

template <class FT, int D>
std::vector<std::vector<Point<FT, D>>> triangulate(const ConvexCell<FT, D>& c) {
  if (c.dim < 2) return {c.vertices};
  std::vector<std::vector<Point<FT, D>>> out;
  for (std::size_t i = 1; i + 1 < c.vertices.size(); ++i)
    out.push_back({c.vertices[0], c.vertices[i], c.vertices[i + 1]});
  return out;
}

// ----- LinearSet -------------------------------------------------------------------------------

template <class FT, int D>
bool LinearSet<FT, D>::is_valid(std::ostream* why) const {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    std::ostringstream w;
    if (!cells[i].is_valid(&w)) {
      if (why) *why << "cell " << i << ": " << w.str();
      return false;
    }
  }
  return true;
}

template <class FT, int D>
bool contains(const LinearSet<FT, D>& a, const Point<FT, D>& x) {
  for (const auto& c : a.cells)
    if (contains<FT, D>(c, x)) return true;
  return false;
}

template <class FT, int D>
bool covered_by(const ConvexCell<FT, D>& c, const LinearSet<FT, D>& b) {
  if (c.dim == 0) return contains<FT, D>(b, c.vertices[0]);
  std::vector<ConvexCell<FT, D>> pieces; // c ∩ B_j of full dimension dim(c)
  for (const auto& cb : b.cells) {
    if (cb.dim < c.dim) continue;
    auto q = intersect<FT, D>(c, cb);
    if (!q || q->dim < c.dim) continue;
    if (*q == c) return true;
    pieces.push_back(*q);
  }
  if (c.dim == 1) {
    // Closed parameter intervals s = u·(x - v0) ∈ [0, u·u] must chain from 0 to u·u.
    const Point<FT, D> u = c.vertices[1] - c.vertices[0];
    std::vector<std::pair<FT, FT>> iv;
    for (const auto& q : pieces) {
      FT s0 = dot<FT, D>(u, q.vertices[0] - c.vertices[0]);
      FT s1 = dot<FT, D>(u, q.vertices[1] - c.vertices[0]);
      if (s1 < s0) std::swap(s0, s1);
      iv.emplace_back(s0, s1);
    }
    std::sort(iv.begin(), iv.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    FT reach = 0;
    for (const auto& [lo, hi] : iv) {
      if (reach < lo) return false;
      if (reach < hi) reach = hi;
    }
    return reach == dot<FT, D>(u, u);
  }
  // Polygon: subtract each piece, keeping c minus the pieces as convex parts of positive area.
  std::vector<Pts<FT, D>> rest{c.vertices};
  for (const auto& q : pieces) {
    const auto k = constraints<FT, D>(q); // q ⊆ aff(c): only its edge half-planes matter
    std::vector<Pts<FT, D>> next;
    for (const auto& r : rest) {
      std::vector<Pts<FT, D>> parts; // r ∩ {h_0..h_{i-1} >= 0} ∩ {h_i <= 0}
      Pts<FT, D> inside = r;
      bool overlaps = true;
      for (const auto& h : k.ge) {
        auto outside = clip<FT, D>(inside, negated<FT, D>(h.w), -h.c);
        if (spans_plane<FT, D>(outside)) parts.push_back(std::move(outside));
        inside = clip<FT, D>(inside, h.w, h.c);
        if (!spans_plane<FT, D>(inside)) {
          overlaps = false; // r ∩ q has no area: r stays whole
          break;
        }
      }
      if (!overlaps) {
        next.push_back(r);
        continue;
      }
      for (auto& part : parts) next.push_back(std::move(part));
    }
    rest = std::move(next);
    if (rest.empty()) return true;
  }
  return rest.empty();
}

template <class FT, int D>
bool subset_of(const LinearSet<FT, D>& a, const LinearSet<FT, D>& b) {
  for (const auto& c : a.cells)
    if (!covered_by<FT, D>(c, b)) return false;
  return true;
}

template <class FT, int D>
bool union_equals(const LinearSet<FT, D>& a, const LinearSet<FT, D>& b) {
  return subset_of<FT, D>(a, b) && subset_of<FT, D>(b, a);
}

template <class FT, int D>
bool is_pure_dimensional(const LinearSet<FT, D>& a) {
  const int k = dimension<FT, D>(a);
  LinearSet<FT, D> top;
  for (const auto& c : a.cells)
    if (c.dim == k) top.cells.push_back(c);
  for (const auto& c : a.cells)
    if (c.dim < k && !covered_by<FT, D>(c, top)) return false;
  return true;
}

template <class FT, int D>
std::vector<ConvexCell<FT, D>> ip(const LinearSet<FT, D>& a, const LinearSet<FT, D>& b) {
  require_valid<FT, D>(a, "ip: A");
  require_valid<FT, D>(b, "ip: B");
  return ip_unchecked<FT, D>(a, b);
}

template <class FT, int D>
std::vector<LinearSet<FT, D>> refine(const std::vector<LinearSet<FT, D>>& s,
                                     const std::vector<LinearSet<FT, D>>& p) {
  for (const auto& a : s) require_valid<FT, D>(a, "refine: S");
  for (const auto& b : p) require_valid<FT, D>(b, "refine: P");
  std::vector<ConvexCell<FT, D>> cells;
  for (const auto& a : s)
    for (const auto& b : p) {
      auto part = ip_unchecked<FT, D>(a, b);
      cells.insert(cells.end(), part.begin(), part.end());
    }
  std::sort(cells.begin(), cells.end(), ConvexCellLess<FT, D>());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::vector<LinearSet<FT, D>> out;
  for (auto& c : cells) out.push_back(linear_set<FT, D>(c));
  return out;
}

template <class FT, int D>
bool is_covering(const std::vector<LinearSet<FT, D>>& s, const LinearSet<FT, D>& x,
                 std::ostream* why) {
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i].empty()) {
      if (why) *why << "element " << i << " is empty";
      return false;
    }
  const auto u = union_of<FT, D>(s);
  if (!subset_of<FT, D>(u, x)) {
    if (why) *why << "the union of the elements is not contained in X";
    return false;
  }
  if (!subset_of<FT, D>(x, u)) {
    if (why) *why << "X is not contained in the union of the elements";
    return false;
  }
  return true;
}

template <class FT, int D>
bool is_manifold_partition(const std::vector<LinearSet<FT, D>>& s, const LinearSet<FT, D>& x,
                           std::ostream* why) {
  if (!is_covering<FT, D>(s, x, why)) return false;
  if (!is_pure_dimensional<FT, D>(x)) {
    if (why) *why << "X is not pure-dimensional, hence not a manifold";
    return false;
  }
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!is_pure_dimensional<FT, D>(s[i])) {
      if (why) *why << "element " << i << " is not pure-dimensional, hence not a manifold";
      return false;
    }
  const int k = dimension<FT, D>(x);
  std::vector<std::vector<ConvexCell<FT, D>>> top(s.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    for (const auto& c : s[i].cells)
      if (c.dim == k) top[i].push_back(c);
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      bool meet = false;
      for (std::size_t a = 0; a < top[i].size() && !meet; ++a)
        for (std::size_t b = 0; b < top[j].size() && !meet; ++b) {
          const auto q = intersect<FT, D>(top[i][a], top[j][b]);
          meet = q && q->dim == k;
        }
      if (meet && !union_equals<FT, D>(s[i], s[j])) {
        if (why)
          *why << "the " << k << "-interiors of elements " << i << " and " << j << " meet (a " << k
               << "-cell of each overlaps the other in dimension " << k << ")";
        return false;
      }
    }
  return true;
}

// ----- explicit instantiations ------------------------------------------------------------------

#define SYMMESH_INSTANTIATE_INTERSECTION_PARTITION(FT, D)                                          \
  template struct ConvexCell<FT, D>;                                                               \
  template struct LinearSet<FT, D>;                                                                \
  template ConvexCell<FT, D> make_convex_cell<FT, D>(const std::vector<Point<FT, D>>&);            \
  template bool contains<FT, D>(const ConvexCell<FT, D>&, const Point<FT, D>&);                    \
  template bool relative_interior_contains<FT, D>(const ConvexCell<FT, D>&, const Point<FT, D>&);  \
  template std::optional<ConvexCell<FT, D>> intersect<FT, D>(const ConvexCell<FT, D>&,             \
                                                             const ConvexCell<FT, D>&);            \
  template std::optional<ConvexCell<FT, D>> clip_halfspace<FT, D>(const ConvexCell<FT, D>&,        \
                                                                  const Point<FT, D>&, const FT&); \
  template std::vector<std::vector<Point<FT, D>>> triangulate<FT, D>(const ConvexCell<FT, D>&);    \
  template bool contains<FT, D>(const LinearSet<FT, D>&, const Point<FT, D>&);                     \
  template bool covered_by<FT, D>(const ConvexCell<FT, D>&, const LinearSet<FT, D>&);              \
  template bool subset_of<FT, D>(const LinearSet<FT, D>&, const LinearSet<FT, D>&);                \
  template bool union_equals<FT, D>(const LinearSet<FT, D>&, const LinearSet<FT, D>&);             \
  template bool is_pure_dimensional<FT, D>(const LinearSet<FT, D>&);                               \
  template std::vector<ConvexCell<FT, D>> ip<FT, D>(const LinearSet<FT, D>&,                       \
                                                    const LinearSet<FT, D>&);                      \
  template std::vector<LinearSet<FT, D>> refine<FT, D>(const std::vector<LinearSet<FT, D>>&,       \
                                                       const std::vector<LinearSet<FT, D>>&);      \
  template bool is_covering<FT, D>(const std::vector<LinearSet<FT, D>>&, const LinearSet<FT, D>&,  \
                                   std::ostream*);                                                 \
  template bool is_manifold_partition<FT, D>(const std::vector<LinearSet<FT, D>>&,                 \
                                             const LinearSet<FT, D>&, std::ostream*);

} // namespace symmesh::core
