/// Building blocks of the proofs-checks generators (internal to proofs-checks): RapidCheck picks,
/// random exact point sets, CGAL's exact Delaunay and regular triangulations, orthogonal rational
/// frames and rigid motions — spec/traceability.md#lemma-to-proofs-checks
///
/// Everything is exact: points are rationals k/q with q in {1, 2} on small grids, frames are
/// pairwise orthogonal integer vectors, rotations are Pythagorean (2D) or integer quaternions
/// (3D), triangulations are CGAL's exact Delaunay / regular triangulations over Epeck. The picks
/// are only valid inside rc::gen::exec. Only the generator sources include this header.
#pragma once
#include "proofs-checks/generators.h"

#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/respect.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_3.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <type_traits>

namespace symmesh::proofs::gen::detail {

using core::Simplex;
using core::VertexId;

using K = CGAL::Epeck;
static_assert(std::is_same_v<K::FT, Exact>,
              "the generators build points of the core's number type");

using Cell = std::vector<VertexId>;
template <int D>
using Coords = std::array<Exact, D>;

// ----- picks: only valid inside rc::gen::exec ------------------------------------------------

/// A uniform pick in [lo, hi]. rc::gen::inRange narrows its range with RapidCheck's size (at
/// size 0 it always yields lo), so it is evaluated at full size here: the generators scale
/// their structures with the size themselves. Shrinking still moves picks towards lo.
inline int pick(int lo, int hi) {
  return *rc::gen::resize(100, rc::gen::inRange(lo, hi + 1));
}
inline bool chance(int percent) {
  return pick(0, 99) < percent;
}
inline Exact rational(int num, int den) {
  return Exact(num) / Exact(den);
}

/// k/q on [lo, hi], q = 2 one time in four: halves make midpoints and degeneracies common.
inline Exact grid_value(int lo, int hi) {
  const int q = chance(25) ? 2 : 1;
  return rational(pick(lo * q, hi * q), q);
}
/// A grid value strictly inside (lo, hi).
inline Exact inner_value(int lo, int hi) {
  const int q = chance(40) ? 2 : 1;
  return rational(pick(lo * q + 1, hi * q - 1), q);
}

template <int D>
Point<D> make_point(const Coords<D>& c) {
  Point<D> p;
  for (int i = 0; i < D; ++i) p[i] = c[i];
  return p;
}

template <int D>
Point<D> centroid(const PointSet<D>& pts) {
  Point<D> c = core::zero_point<Exact, D>();
  for (const auto& p : pts) c = c + p;
  return core::scaled<Exact, D>(c, Exact(1) / Exact(int(pts.size())));
}

template <int D>
PointSet<D> dedupe(const PointSet<D>& pts) {
  std::set<Point<D>, core::PointLess<Exact, D>> seen;
  PointSet<D> out;
  for (const auto& p : pts)
    if (seen.insert(p).second) out.push_back(p);
  return out;
}

template <int D>
bool full_dimensional(const PointSet<D>& pts) {
  if (pts.size() < std::size_t(D + 1)) return false;
  core::Matrix<Exact> m;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    std::vector<Exact> row(D);
    for (int d = 0; d < D; ++d) row[d] = pts[i][d] - pts[0][d];
    m.push_back(row);
  }
  return core::rank(m) == std::size_t(D);
}

inline Point<3> cross(const Point<3>& a, const Point<3>& b) {
  Point<3> r;
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
  return r;
}

// ----- exact triangulations ------------------------------------------------------------------

template <int D>
struct Cgal;

template <>
struct Cgal<2> {
  using Dt = CGAL::Delaunay_triangulation_2<K>;
  using Rt = CGAL::Regular_triangulation_2<K>;
  static K::Point_2 point(const Point<2>& p) { return K::Point_2(p[0], p[1]); }
  static Point<2> back(const K::Point_2& p) { return make_point<2>({p.x(), p.y()}); }
  template <class Tr, class F>
  static void for_each_cell(const Tr& t, F&& f) {
    for (auto c = t.finite_faces_begin(); c != t.finite_faces_end(); ++c) f(c, 3);
  }
};

template <>
struct Cgal<3> {
  using Dt = CGAL::Delaunay_triangulation_3<K>;
  using Rt = CGAL::Regular_triangulation_3<K>;
  static K::Point_3 point(const Point<3>& p) { return K::Point_3(p[0], p[1], p[2]); }
  static Point<3> back(const K::Point_3& p) { return make_point<3>({p.x(), p.y(), p.z()}); }
  template <class Tr, class F>
  static void for_each_cell(const Tr& t, F&& f) {
    for (auto c = t.finite_cells_begin(); c != t.finite_cells_end(); ++c) f(c, 4);
  }
};

template <int D>
using PointIndex = std::map<Point<D>, VertexId, core::PointLess<Exact, D>>;

template <int D>
PointIndex<D> index_of(const PointSet<D>& pts) {
  PointIndex<D> idx;
  for (std::size_t i = 0; i < pts.size(); ++i) idx.emplace(pts[i], VertexId(i));
  return idx;
}

/// Cells of the exact Delaunay triangulation of distinct points (empty if not full-dimensional).
template <int D>
std::vector<Cell> delaunay_cells(const PointSet<D>& pts) {
  typename Cgal<D>::Dt dt;
  for (const auto& p : pts) dt.insert(Cgal<D>::point(p));
  std::vector<Cell> cells;
  if (dt.dimension() != D) return cells;
  const auto idx = index_of<D>(pts);
  Cgal<D>::for_each_cell(dt, [&](auto c, int n) {
    Cell cell;
    for (int k = 0; k < n; ++k) cell.push_back(idx.at(Cgal<D>::back(c->vertex(k)->point())));
    cells.push_back(cell);
  });
  return cells;
}

/// Cells of the regular triangulation with the given weights; hidden points are not vertices.
template <int D>
std::vector<Cell> regular_cells(const PointSet<D>& pts, const std::vector<int>& weights) {
  typename Cgal<D>::Rt rt;
  for (std::size_t i = 0; i < pts.size(); ++i)
    rt.insert(typename Cgal<D>::Rt::Weighted_point(Cgal<D>::point(pts[i]), Exact(weights[i])));
  std::vector<Cell> cells;
  if (rt.dimension() != D) return cells;
  const auto idx = index_of<D>(pts);
  Cgal<D>::for_each_cell(rt, [&](auto c, int n) {
    Cell cell;
    for (int k = 0; k < n; ++k)
      cell.push_back(idx.at(Cgal<D>::back(c->vertex(k)->point().point())));
    cells.push_back(cell);
  });
  return cells;
}

/// The mesh of the given cells and all their faces. With `compact`, only used points are kept
/// (in order of first use); otherwise the point array is `pts` itself.
template <int D>
Complex<D> complex_from_cells(const PointSet<D>& pts, const std::vector<Cell>& cells,
                              bool compact = true) {
  Complex<D> c;
  std::vector<VertexId> to(pts.size());
  if (compact) {
    const VertexId none = VertexId(-1);
    std::fill(to.begin(), to.end(), none);
    for (const auto& cell : cells)
      for (VertexId v : cell)
        if (to[v] == none) {
          to[v] = VertexId(c.points.size());
          c.points.push_back(pts[v]);
        }
  } else {
    for (std::size_t i = 0; i < pts.size(); ++i) to[i] = VertexId(i);
    c.points = pts;
  }
  for (const auto& cell : cells) {
    std::vector<VertexId> ids;
    for (VertexId v : cell) ids.push_back(to[v]);
    const Simplex s = Simplex::from_range(ids.data(), ids.data() + ids.size());
    for (const auto& f : core::faces(s)) c.elements.push_back(f);
  }
  c.normalize();
  return c;
}

/// The cells of a complex as point tuples (used to re-express sub-complexes).
template <int D>
std::vector<Cell> cells_of(const Complex<D>& c) {
  std::vector<Cell> out;
  for (const auto& s : c.cells()) out.push_back(Cell(s.begin(), s.end()));
  return out;
}

/// Random weights: 0 on `keep` points (boundary points, which are then never hidden), small
/// non-negative integers elsewhere.
inline std::vector<int> random_weights(std::size_t n, const std::vector<bool>& keep) {
  std::vector<int> w(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (!keep[i]) w[i] = pick(0, 6);
  return w;
}

/// Delaunay (about 60%) or regular triangulation; `on_hull[i]` marks points on the boundary of
/// the intended hull, which keep weight 0 so that no hull point gets hidden.
template <int D>
std::pair<std::vector<Cell>, std::string> some_triangulation(const PointSet<D>& pts,
                                                             const std::vector<bool>& on_hull) {
  if (chance(60)) return {delaunay_cells<D>(pts), "delaunay"};
  const auto w = random_weights(pts.size(), on_hull);
  std::ostringstream os;
  os << "regular(w=";
  for (int x : w) os << x;
  os << ")";
  return {regular_cells<D>(pts, w), os.str()};
}

template <int D>
std::string points_text(const PointSet<D>& pts) {
  std::string s = "[";
  for (std::size_t i = 0; i < pts.size(); ++i) s += (i ? " " : "") + text<D>(pts[i]);
  return s + "]";
}

// ----- random point sets ----------------------------------------------------------------------

/// n points in [0, 4]^D, a third of them on lines through earlier points (collinear / coplanar
/// configurations), always full-dimensional (a unit corner simplex is added if needed).
template <int D>
PointSet<D> random_point_set(int n) {
  PointSet<D> pts;
  for (int i = 0; i < n; ++i) {
    if (pts.size() >= 2 && chance(30)) {
      const auto& a = pts[pick(0, int(pts.size()) - 1)];
      const auto& b = pts[pick(0, int(pts.size()) - 1)];
      static const int num[] = {-1, 1, 1, 2, 3};
      static const int den[] = {1, 2, 3, 1, 2};
      const int k = pick(0, 4);
      pts.push_back(a + core::scaled<Exact, D>(b - a, rational(num[k], den[k])));
      continue;
    }
    Coords<D> c;
    for (int d = 0; d < D; ++d) c[d] = grid_value(0, 4);
    pts.push_back(make_point<D>(c));
  }
  pts = dedupe<D>(pts);
  if (!full_dimensional<D>(pts)) {
    Coords<D> c{};
    for (int d = 0; d < D; ++d) c[d] = 0;
    pts.push_back(make_point<D>(c));
    for (int d = 0; d < D; ++d) {
      Coords<D> e{};
      for (int k = 0; k < D; ++k) e[k] = k == d ? 5 : 0;
      pts.push_back(make_point<D>(e));
    }
    pts = dedupe<D>(pts);
  }
  return pts;
}

/// D+1 points and a few more; 3D stays smaller because the exact conformity checks cost one LP
/// per pair of elements.
inline int point_count(int size, int dim) {
  return dim + 1 +
         (dim == 2 ? pick(0, std::min(6, 1 + size / 15)) : pick(0, std::min(2, size / 35)));
}

// ----- frames: pairwise orthogonal rational axes ------------------------------------------------

/// x = origin + Σ c_j axis_j with pairwise orthogonal integer axes: frame coordinates turn boxes,
/// orthants and hyperplanes c_j = const into rational sets in general position.
template <int D>
struct Frame {
  Point<D> origin;
  std::array<Point<D>, D> axis;
  std::string text;

  Point<D> at(const Coords<D>& c) const {
    Point<D> p = origin;
    for (int j = 0; j < D; ++j) p = p + core::scaled<Exact, D>(axis[j], c[j]);
    return p;
  }
  /// The hyperplane c_j = c as {x : n·x = d}.
  Exact offset(int j, const Exact& c) const {
    return core::dot<Exact, D>(axis[j], origin) + c * core::dot<Exact, D>(axis[j], axis[j]);
  }
  Motion<D> reflection(int j, const Exact& c) const {
    return Motion<D>::reflection(axis[j], offset(j, c));
  }
  Motion<D> translation(int j, const Exact& c) const {
    return Motion<D>::translation(core::scaled<Exact, D>(axis[j], c));
  }
};

template <int D>
Point<D> small_vector(int lo, int hi) {
  Coords<D> c;
  bool zero = true;
  for (int d = 0; d < D; ++d) {
    c[d] = pick(lo, hi);
    if (c[d] != 0) zero = false;
  }
  if (zero) c[0] = 1; // a direction, never the zero vector
  return make_point<D>(c);
}

/// Largest k >= 1 with k^2 |b|^2 <= |a|^2: used to shorten long axes by an integer factor, so
/// that frame boxes are not needlessly elongated.
inline int length_ratio(const Point<3>& a, const Point<3>& b) {
  const Exact aa = core::dot<Exact, 3>(a, a), bb = core::dot<Exact, 3>(b, b);
  int k = 1;
  while (Exact((k + 1) * (k + 1)) * bb <= aa) ++k;
  return k;
}

template <int D>
Frame<D> random_frame();

template <>
inline Frame<2> random_frame<2>() {
  Frame<2> f;
  f.origin = make_point<2>({Exact(pick(-2, 2)), Exact(pick(-2, 2))});
  if (chance(35)) {
    f.axis[0] = make_point<2>({Exact(1), Exact(0)});
    f.axis[1] = make_point<2>({Exact(0), Exact(1)});
    f.text = "axis frame at " + text<2>(f.origin);
    return f;
  }
  const auto n = small_vector<2>(-2, 2);
  f.axis[0] = n;
  f.axis[1] = make_point<2>({-n[1], n[0]});
  f.text = "frame n=" + text<2>(n) + " at " + text<2>(f.origin);
  return f;
}

template <>
inline Frame<3> random_frame<3>() {
  Frame<3> f;
  f.origin = make_point<3>({Exact(pick(-2, 2)), Exact(pick(-2, 2)), Exact(pick(-2, 2))});
  if (chance(35)) {
    for (int j = 0; j < 3; ++j) {
      Coords<3> e{};
      for (int d = 0; d < 3; ++d) e[d] = d == j ? 1 : 0;
      f.axis[j] = make_point<3>(e);
    }
    f.text = "axis frame at " + text<3>(f.origin);
    return f;
  }
  const auto n = small_vector<3>(-2, 2);
  int k = 0; // the coordinate axis least parallel to n
  for (int d = 1; d < 3; ++d)
    if (CGAL::abs(n[d]) < CGAL::abs(n[k])) k = d;
  Coords<3> e{};
  for (int d = 0; d < 3; ++d) e[d] = d == k ? 1 : 0;
  auto u = cross(n, make_point<3>(e));
  auto w = cross(n, u);
  u = core::scaled<Exact, 3>(u, Exact(1) / Exact(length_ratio(u, n)));
  w = core::scaled<Exact, 3>(w, Exact(1) / Exact(length_ratio(w, n)));
  f.axis = {n, u, w};
  f.text = "frame n=" + text<3>(n) + " at " + text<3>(f.origin);
  return f;
}

// ----- rigid motions ----------------------------------------------------------------------------

template <int D>
Described<Motion<D>> random_rotation();

template <>
inline Described<Motion<2>> random_rotation<2>() {
  const int a = pick(-3, 3), b = pick(-3, 3);
  const Point<2> c = make_point<2>({grid_value(-2, 2), grid_value(-2, 2)});
  if (a == 0 && b == 0) return {Motion<2>(), "I"};
  const Exact q = Exact(a * a + b * b);
  const Exact cs = Exact(a * a - b * b) / q, sn = Exact(2 * a * b) / q;
  return {Motion<2>::rotation_2d(cs, sn, c),
          "rot(cos=" + text(cs) + ", sin=" + text(sn) + ", c=" + text<2>(c) + ")"};
}

template <>
inline Described<Motion<3>> random_rotation<3>() {
  const int w = pick(-2, 2), x = pick(-2, 2), y = pick(-2, 2), z = pick(-2, 2);
  const Point<3> c = make_point<3>({grid_value(-2, 2), grid_value(-2, 2), grid_value(-2, 2)});
  if (w == 0 && x == 0 && y == 0 && z == 0) return {Motion<3>(), "I"};
  std::ostringstream os;
  os << "quat(" << w << "," << x << "," << y << "," << z << ", c=" << text<3>(c) << ")";
  return {Motion<3>::rotation_quaternion(w, x, y, z, c), os.str()};
}

/// One global rigid motion: a rational rotation, sometimes composed with a reflection.
template <int D>
Described<Motion<D>> random_motion() {
  auto r = random_rotation<D>();
  if (chance(30)) {
    const auto n = small_vector<D>(-2, 2);
    const Exact d = grid_value(-2, 2);
    r.value = Motion<D>::reflection(n, d) * r.value;
    r.recipe = "refl(" + text<D>(n) + "," + text(d) + ")∘" + r.recipe;
  }
  return r;
}

/// AT of the result is g(AT(s)): either T' = g∘T (templates unchanged) or the templates move
/// too and T' = g∘T∘g^{-1} (metamorphic: every verdict must be unchanged).
template <int D>
GeneratedStructure<D> moved(GeneratedStructure<D> s, const Described<Motion<D>>& g,
                            bool conjugate) {
  const auto gi = g.value.inverse();
  for (std::size_t i = 0; i < s.x.templates.size(); ++i) {
    if (conjugate)
      for (auto& p : s.x.templates[i].mesh.points) p = g.value(p);
    for (auto& inst : s.x.instances[i])
      inst.transformation =
          conjugate ? g.value * inst.transformation * gi : g.value * inst.transformation;
  }
  s.recipe += std::string(conjugate ? "; conjugated by " : "; moved by ") + g.recipe;
  return s;
}

template <int D>
GeneratedStructure<D> maybe_moved(GeneratedStructure<D> s, int percent) {
  if (!chance(percent)) return s;
  const auto g = random_motion<D>();
  return moved<D>(std::move(s), g, chance(50));
}

} // namespace symmesh::proofs::gen::detail
