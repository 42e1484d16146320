// RapidCheck generators of the proofs-checks (see generators.h for the tiers).
//
// Everything is exact: points are rationals k/q with q in {1, 2} on small grids, frames are
// pairwise orthogonal integer vectors, rotations are Pythagorean (2D) or integer quaternions
// (3D), triangulations are CGAL's exact Delaunay / regular triangulations over Epeck. CGAL is
// kept in this translation unit only.
// GCC 12 false positives, silenced for this file only: -Wmaybe-uninitialized inside CGAL's
// filtered weighted-point predicates and -Wrestrict in std::string concatenation (GCC bug 105329).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wrestrict"

#include "proofs-checks/generators.h"

#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/respect.h"
#include "symmesh/io/svg.h"
#include "symmesh/io/templated_structure_json.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_3.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <type_traits>

namespace symmesh::proofs::gen {

using core::Simplex;
using core::VertexId;

namespace {

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
int pick(int lo, int hi) {
  return *rc::gen::resize(100, rc::gen::inRange(lo, hi + 1));
}
bool chance(int percent) {
  return pick(0, 99) < percent;
}
Exact rational(int num, int den) {
  return Exact(num) / Exact(den);
}

/// k/q on [lo, hi], q = 2 one time in four: halves make midpoints and degeneracies common.
Exact grid_value(int lo, int hi) {
  const int q = chance(25) ? 2 : 1;
  return rational(pick(lo * q, hi * q), q);
}
/// A grid value strictly inside (lo, hi).
Exact inner_value(int lo, int hi) {
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

Point<3> cross(const Point<3>& a, const Point<3>& b) {
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
std::vector<int> random_weights(std::size_t n, const std::vector<bool>& keep) {
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
int point_count(int size, int dim) {
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
int length_ratio(const Point<3>& a, const Point<3>& b) {
  const Exact aa = core::dot<Exact, 3>(a, a), bb = core::dot<Exact, 3>(b, b);
  int k = 1;
  while (Exact((k + 1) * (k + 1)) * bb <= aa) ++k;
  return k;
}

template <int D>
Frame<D> random_frame();

template <>
Frame<2> random_frame<2>() {
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
Frame<3> random_frame<3>() {
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
Described<Motion<2>> random_rotation<2>() {
  const int a = pick(-3, 3), b = pick(-3, 3);
  const Point<2> c = make_point<2>({grid_value(-2, 2), grid_value(-2, 2)});
  if (a == 0 && b == 0) return {Motion<2>(), "I"};
  const Exact q = Exact(a * a + b * b);
  const Exact cs = Exact(a * a - b * b) / q, sn = Exact(2 * a * b) / q;
  return {Motion<2>::rotation_2d(cs, sn, c),
          "rot(cos=" + text(cs) + ", sin=" + text(sn) + ", c=" + text<2>(c) + ")"};
}

template <>
Described<Motion<3>> random_rotation<3>() {
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

// ----- templated structures --------------------------------------------------------------------

template <int D>
core::Template<Exact, D> make_template(const Complex<D>& mesh, const std::string& name) {
  core::Template<Exact, D> t;
  t.name = name;
  t.kind = core::TemplateKind::mesh;
  t.mesh = mesh;
  return t;
}

template <int D>
Structure<D> single_template(const Complex<D>& mesh, const std::vector<Motion<D>>& tfs,
                             const std::vector<int>& regions) {
  Structure<D> x;
  x.templates.push_back(make_template<D>(mesh, "X1"));
  x.instances.emplace_back();
  for (std::size_t g = 0; g < tfs.size(); ++g)
    x.instances[0].push_back(core::InstanceSpec<Exact, D>{tfs[g], regions[g]});
  return x;
}

std::vector<int> random_regions(std::size_t n) {
  std::vector<int> r;
  const bool same = chance(50);
  for (std::size_t i = 0; i < n; ++i) r.push_back(same ? 1 : pick(1, 2));
  return r;
}

/// Splits template 0 into 2-3 templates by the side of each cell centroid with respect to
/// random hyperplanes (Figure 4.3's multi-template shape); all keep the same instances.
template <int D>
GeneratedStructure<D> split_template(GeneratedStructure<D> s) {
  const auto& base = s.x.templates[0].mesh;
  const auto cells = base.cells();
  if (cells.size() < 2) return s;
  const auto m = small_vector<D>(-2, 2);
  std::vector<Exact> key;
  for (const auto& c : cells) key.push_back(core::dot<Exact, D>(m, centroid<D>(base.coords(c))));
  auto sorted = key;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.size() < 2) return s;
  const int parts = sorted.size() >= 3 && chance(40) ? 3 : 2;
  std::vector<Exact> cuts;
  const int first = pick(1, int(sorted.size()) - parts + 1);
  cuts.push_back(sorted[first]);
  if (parts == 3) cuts.push_back(sorted[pick(first + 1, int(sorted.size()) - 1)]);
  std::vector<std::vector<Cell>> groups(parts);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    int g = 0;
    while (g < int(cuts.size()) && !(key[k] < cuts[g])) ++g;
    groups[g].push_back(Cell(cells[k].begin(), cells[k].end()));
  }
  const auto inst = s.x.instances[0];
  const bool own_regions = chance(50);
  Structure<D> x;
  for (int g = 0; g < parts; ++g) {
    if (groups[g].empty()) continue;
    x.templates.push_back(make_template<D>(complex_from_cells<D>(base.points, groups[g]),
                                           "X1" + std::string(1, char('a' + g))));
    auto list = inst;
    if (own_regions)
      for (auto& spec : list) spec.region = g + 1;
    x.instances.push_back(list);
  }
  for (std::size_t i = 1; i < s.x.templates.size(); ++i) {
    x.templates.push_back(s.x.templates[i]);
    x.instances.push_back(s.x.instances[i]);
  }
  s.x = x;
  s.recipe += "; split into " + std::to_string(parts) + " templates by m=" + text<D>(m);
  return s;
}

// ----- reflective families (Lemma 6.1, 6.2) ----------------------------------------------------

/// Template points in frame coordinates c_0 >= 0: several exactly on c_0 = 0, only one, none,
/// or the corners of a frame box (then the template and AT are convex).
template <int D>
struct HalfSpacePoints {
  PointSet<D> pts;
  std::vector<bool> on_hull;
  std::string mode;
};

template <int D>
HalfSpacePoints<D> half_space_points(const Frame<D>& f, int size, int orthant_axes, bool convex) {
  HalfSpacePoints<D> out;
  std::vector<Coords<D>> cs;
  std::vector<bool> hull;
  auto add = [&](const Coords<D>& c, bool h) {
    cs.push_back(c);
    hull.push_back(h);
  };
  std::array<int, D> extent;
  for (int j = 0; j < D; ++j) extent[j] = pick(2, 3);
  auto lo = [&](int j) { return j < orthant_axes ? 0 : -extent[j]; };
  if (convex && D == 2) {
    // a frame box in the orthant: AT (the box and its mirror images) is a box again
    out.mode = "box";
    for (int mask = 0; mask < (1 << D); ++mask) {
      Coords<D> c;
      for (int j = 0; j < D; ++j) c[j] = (mask >> j) & 1 ? Exact(extent[j]) : Exact(lo(j));
      add(c, true);
    }
    const int on_sides = pick(0, 1 + size / 40);
    for (int k = 0; k < on_sides; ++k) {
      Coords<D> c;
      const int j = pick(0, D - 1);
      for (int i = 0; i < D; ++i) c[i] = i == j ? Exact(lo(i)) : inner_value(lo(i), extent[i]);
      add(c, true);
    }
    const int interior = pick(0, std::min(2, size / 30));
    for (int k = 0; k < interior; ++k) {
      Coords<D> c;
      for (int i = 0; i < D; ++i) c[i] = inner_value(lo(i), extent[i]);
      add(c, false);
    }
  } else if (convex) {
    // the orthant corner simplex: its images under the reflections form a convex cross-polytope
    out.mode = "corner simplex";
    Coords<D> o{};
    for (int j = 0; j < D; ++j) o[j] = 0;
    add(o, true);
    for (int j = 0; j < D; ++j) {
      Coords<D> c = o;
      c[j] = extent[j];
      add(c, true);
    }
    if (size > 30 && chance(40)) {
      Coords<D> c;
      for (int j = 0; j < D; ++j) c[j] = rational(extent[j], 4);
      add(c, false);
    }
  } else {
    const int mode = pick(0, 9);
    const int on_plane =
        mode < 7 ? D + (D == 2 ? pick(0, 2) : pick(0, size / 60)) : (mode < 9 ? 1 : 0);
    out.mode = on_plane == 0 ? "none on H" : (on_plane == 1 ? "one on H" : "several on H");
    for (int k = 0; k < on_plane; ++k) {
      Coords<D> c;
      for (int i = 0; i < D; ++i) c[i] = i == 0 ? Exact(0) : grid_value(lo(i), extent[i]);
      for (int i = 1; i < orthant_axes; ++i) // further orthant hyperplanes get points too
        if (chance(40)) c[i] = 0;
      add(c, true);
    }
    // off H (c_0 > 0 unless several points are on H anyway)
    const int off = (on_plane >= D ? 1 : D + 1 - on_plane) +
                    pick(0, D == 2 ? std::min(3, size / 25) : size / 50);
    for (int k = 0; k < off; ++k) {
      Coords<D> c;
      for (int i = 0; i < D; ++i) c[i] = grid_value(lo(i), extent[i]);
      if (c[0] == 0 && on_plane < D) c[0] = 1;
      bool h = c[0] == 0;
      for (int i = 1; i < orthant_axes; ++i) h = h || c[i] == 0;
      add(c, h);
    }
  }
  // dedupe, keeping each point's hull flag (hull points keep weight 0: never hidden)
  std::set<Point<D>, core::PointLess<Exact, D>> seen;
  for (std::size_t k = 0; k < cs.size(); ++k) {
    const auto p = f.at(cs[k]);
    if (!seen.insert(p).second) continue;
    out.pts.push_back(p);
    out.on_hull.push_back(hull[k]);
  }
  return out;
}

/// All 2^k compositions of the reflections, in the order of Algorithm 6.4.
template <int D>
std::vector<Motion<D>> reflection_group(const std::vector<Motion<D>>& refl) {
  std::vector<Motion<D>> t{Motion<D>(), refl[0]};
  for (std::size_t i = 1; i < refl.size(); ++i) {
    const std::size_t n = t.size();
    for (std::size_t k = 0; k < n; ++k) t.push_back(t[k] * refl[i]);
  }
  return t;
}

template <int D>
rc::Gen<OrthogonalReflections<D>> reflections_impl(int min_k, int max_k, bool force_box) {
  return rc::gen::withSize([=](int size) {
    return rc::gen::exec([=] {
      for (int attempt = 0;; ++attempt) {
        const auto f = random_frame<D>();
        const int k = pick(min_k, max_k);
        // convex ones are full-dimensional; in 3D, 8 instances only of the corner simplex
        const bool box = force_box || attempt >= 5 || chance(35) || (D == 3 && k == 3);
        const auto hp = half_space_points<D>(f, size, k, box);
        if (!full_dimensional<D>(hp.pts)) continue;
        const auto [cells, how] = some_triangulation<D>(hp.pts, hp.on_hull);
        if (cells.empty()) continue;
        OrthogonalReflections<D> o;
        std::vector<Motion<D>> refl;
        for (int j = 0; j < k; ++j) {
          refl.push_back(f.reflection(j, 0));
          o.normals.push_back(f.axis[j]);
          o.offsets.push_back(f.offset(j, 0));
        }
        const auto tfs = reflection_group<D>(refl);
        const auto mesh = complex_from_cells<D>(hp.pts, cells);
        o.s.x = single_template<D>(mesh, tfs, random_regions(tfs.size()));
        o.s.tier = Tier::valid_templated_mesh;
        o.s.convex = box;
        o.s.recipe = std::to_string(k) + " orthogonal reflection(s) in " + f.text + ", " + hp.mode +
                     ", " + how + " of " + points_text<D>(hp.pts);
        return o;
      }
    });
  });
}

// ----- translation families --------------------------------------------------------------------

/// Values strictly inside (0, extent) for the subdivision of a box side.
std::vector<Exact> side_values(int extent, int max_count) {
  std::vector<Exact> v;
  const int n = pick(0, max_count);
  for (int k = 0; k < n; ++k) v.push_back(inner_value(0, extent));
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

/// A different subdivision: add a value that is not yet there, or drop one.
std::vector<Exact> different_side_values(std::vector<Exact> v, int extent) {
  if (!v.empty() && chance(30)) {
    v.erase(v.begin() + pick(0, int(v.size()) - 1));
    return v;
  }
  Exact x = inner_value(0, extent) + (chance(50) ? rational(1, 4) : Exact(0));
  if (!(x < Exact(extent))) x = rational(extent, 2);
  while (std::find(v.begin(), v.end(), x) != v.end()) x = (x + extent) / 2; // stays in (0, extent)
  v.push_back(x);
  std::sort(v.begin(), v.end());
  return v;
}

std::string values_text(const std::vector<Exact>& v) {
  std::string s = "{";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + text(v[i]);
  return s + "}";
}

/// Translations k_j * extent_j * axis_j over a small grid with at least two instances.
template <int D>
std::pair<std::vector<Motion<D>>, std::string> grid_translations(const Frame<D>& f,
                                                                 const std::array<int, D>& ext,
                                                                 int max_instances, int only_axis) {
  std::array<int, D> n;
  int total = 1;
  for (int j = 0; j < D; ++j) {
    n[j] = only_axis < 0 || only_axis == j ? pick(1, 3) : 1;
    if (total * n[j] > max_instances) n[j] = std::max(1, max_instances / total);
    total *= n[j];
  }
  if (total < 2) {
    const int j = only_axis < 0 ? 0 : only_axis;
    total = total / n[j] * 2;
    n[j] = 2;
  }
  std::vector<Motion<D>> t;
  for (int idx = 0; idx < total; ++idx) {
    int r = idx;
    Point<D> v = core::zero_point<Exact, D>();
    for (int j = 0; j < D; ++j) {
      v = v + core::scaled<Exact, D>(f.axis[j], Exact((r % n[j]) * ext[j]));
      r /= n[j];
    }
    t.push_back(Motion<D>::translation(v));
  }
  std::string s = "grid ";
  for (int j = 0; j < D; ++j) s += (j ? "x" : "") + std::to_string(n[j]);
  return {t, s};
}

/// 2D box template [0,W]x[0,H]: side subdivisions `left`, `right` (x = 0, W), `bottom`, `top`,
/// interior points, Delaunay or regular triangulation (boundary points keep weight 0).
Complex<2> box_template_2d(const Frame<2>& f, const std::array<int, 2>& e,
                           const std::vector<Exact>& left, const std::vector<Exact>& right,
                           const std::vector<Exact>& bottom, const std::vector<Exact>& top,
                           int interior, bool delaunay_only, std::string* how) {
  PointSet<2> pts;
  std::vector<bool> hull;
  auto add = [&](const Exact& a, const Exact& b, bool h) {
    pts.push_back(f.at({a, b}));
    hull.push_back(h);
  };
  add(0, 0, true);
  add(e[0], 0, true);
  add(0, e[1], true);
  add(e[0], e[1], true);
  for (const auto& y : left) add(0, y, true);
  for (const auto& y : right) add(e[0], y, true);
  for (const auto& x : bottom) add(x, 0, true);
  for (const auto& x : top) add(x, e[1], true);
  for (int k = 0; k < interior; ++k) add(inner_value(0, e[0]), inner_value(0, e[1]), false);
  auto u = dedupe<2>(pts);
  std::vector<bool> uh;
  for (const auto& p : u) uh.push_back(hull[std::find(pts.begin(), pts.end(), p) - pts.begin()]);
  if (delaunay_only) {
    *how = "delaunay";
    return complex_from_cells<2>(u, delaunay_cells<2>(u));
  }
  auto [cells, h] = some_triangulation<2>(u, uh);
  *how = h;
  return complex_from_cells<2>(u, cells);
}

/// 3D box template [0,e0]x[0,e1]x[0,e2] triangulated without extra points:
///  - Kuhn (Freudenthal) subdivision, 6 tetrahedra around the main diagonal: opposite faces carry
///    translated diagonals, so every grid translation is conforming;
///  - the 5-tetrahedron subdivision (a central tetrahedron on alternate corners): opposite faces
///    carry crossing diagonals, so a translated copy meets it non-conformingly (Figure 4.4 in 3D).
Complex<3> cube_template(const Frame<3>& f, const std::array<int, 3>& e, bool kuhn) {
  PointSet<3> pts;
  for (int mask = 0; mask < 8; ++mask) {
    Coords<3> c;
    for (int j = 0; j < 3; ++j) c[j] = (mask >> j) & 1 ? Exact(e[j]) : Exact(0);
    pts.push_back(f.at(c));
  }
  std::vector<Cell> cells;
  if (kuhn) {
    int perm[3] = {0, 1, 2};
    do {
      Cell c{0};
      int mask = 0;
      for (int k = 0; k < 3; ++k) {
        mask |= 1 << perm[k];
        c.push_back(VertexId(mask));
      }
      cells.push_back(c);
    } while (std::next_permutation(perm, perm + 3));
  } else {
    // central tetrahedron 0, 3, 5, 6 (alternate corners) and the four corners cut off
    cells = {{0, 3, 5, 6}, {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}};
  }
  return complex_from_cells<3>(pts, cells);
}

template <int D>
rc::Gen<GeneratedStructure<D>> translation_impl(bool conforming, bool delaunay_only);

template <>
rc::Gen<GeneratedStructure<2>> translation_impl<2>(bool conforming, bool delaunay_only) {
  return rc::gen::withSize([=](int size) {
    return rc::gen::exec([=] {
      const auto f = random_frame<2>();
      const std::array<int, 2> e{pick(2, 4), pick(2, 4)};
      const int max_side = 1 + size / 50;
      const auto left = side_values(e[1], max_side);
      const auto bottom = side_values(e[0], max_side);
      const auto right = conforming ? left : different_side_values(left, e[1]);
      const auto top = bottom;
      std::string how;
      const int interior = pick(0, std::min(3, size / 30));
      const auto mesh =
          box_template_2d(f, e, left, right, bottom, top, interior, delaunay_only, &how);
      const auto [tfs, grid] =
          grid_translations<2>(f, e, conforming ? 2 + size / 50 : 3, conforming ? -1 : 0);
      GeneratedStructure<2> s;
      s.x = single_template<2>(mesh, tfs, random_regions(tfs.size()));
      s.tier = conforming ? Tier::valid_templated_mesh : Tier::templated_structure;
      s.convex = true;
      s.recipe = std::string(conforming ? "translation " : "figure 4.4 translation ") + grid +
                 " of box " + std::to_string(e[0]) + "x" + std::to_string(e[1]) + " in " + f.text +
                 ", left " + values_text(left) + " right " + values_text(right) + " bottom/top " +
                 values_text(bottom) + ", " + how + " with " + std::to_string(interior) +
                 " interior";
      return s;
    });
  });
}

/// Triangular prism over (0,0), (e0,0), (0,e1) extruded along axis 2 by e2, in 3 tetrahedra;
/// its top face is the translated bottom face, so stacking along axis 2 is conforming.
Complex<3> prism_template(const Frame<3>& f, const std::array<int, 3>& e) {
  PointSet<3> pts;
  for (int z = 0; z < 2; ++z) {
    const Exact h = z ? Exact(e[2]) : Exact(0);
    pts.push_back(f.at({Exact(0), Exact(0), h}));
    pts.push_back(f.at({Exact(e[0]), Exact(0), h}));
    pts.push_back(f.at({Exact(0), Exact(e[1]), h}));
  }
  return complex_from_cells<3>(pts, {{0, 1, 2, 5}, {0, 1, 4, 5}, {0, 3, 4, 5}});
}

/// Square pyramid (base square in c_2 = 0 split by one diagonal, apex above) in 2 tetrahedra.
Complex<3> pyramid_template(const Frame<3>& f, int e, int h) {
  const PointSet<3> pts = {
      f.at({Exact(0), Exact(0), Exact(0)}), f.at({Exact(e), Exact(0), Exact(0)}),
      f.at({Exact(0), Exact(e), Exact(0)}), f.at({Exact(e), Exact(e), Exact(0)}),
      f.at({rational(e, 2), rational(e, 2), Exact(h)})};
  return complex_from_cells<3>(pts, {{0, 1, 3, 4}, {0, 3, 2, 4}});
}

template <>
rc::Gen<GeneratedStructure<3>> translation_impl<3>(bool conforming, bool /*delaunay_only*/) {
  return rc::gen::withSize([=](int size) {
    return rc::gen::exec([=] {
      const auto f = random_frame<3>();
      const std::array<int, 3> e{pick(1, 3), pick(1, 3), pick(1, 3)};
      GeneratedStructure<3> s;
      s.tier = conforming ? Tier::valid_templated_mesh : Tier::templated_structure;
      std::ostringstream os;
      if (conforming && (size < 60 || chance(60))) {
        // a stack of prisms along axis 2 (2 or 3 instances)
        const int n = size < 50 ? 2 : pick(2, 3);
        std::vector<Motion<3>> tfs;
        for (int k = 0; k < n; ++k) tfs.push_back(f.translation(2, Exact(k * e[2])));
        s.x = single_template<3>(prism_template(f, e), tfs, random_regions(tfs.size()));
        s.convex = true;
        os << "translation stack of " << n << " prisms " << e[0] << "x" << e[1] << "x" << e[2]
           << " in " << f.text;
      } else if (!conforming && chance(50)) {
        // Figure 4.4 in 3D by a half turn: the pyramid turned about an axis in its base plane
        // parallel to a side meets itself with the other base diagonal
        const int h = pick(1, 2);
        const auto mesh = pyramid_template(f, e[0], h);
        const auto c = f.at({rational(e[0], 2), rational(e[0], 2), Exact(0)});
        const auto& u = f.axis[0]; // half turn about the line c + t u: quaternion (0, u)
        const auto turn = Motion<3>::rotation_quaternion(0, u[0], u[1], u[2], c);
        s.x = single_template<3>(mesh, {Motion<3>(), turn}, random_regions(2));
        s.convex = true;
        os << "figure 4.4 (half turn) of a square pyramid " << e[0] << "/" << h << " in " << f.text;
      } else {
        const auto mesh = cube_template(f, e, conforming);
        const int axis = conforming ? -1 : pick(0, 2);
        const auto [tfs, grid] = grid_translations<3>(f, e, 2, axis);
        s.x = single_template<3>(mesh, tfs, random_regions(tfs.size()));
        s.convex = true;
        os << (conforming ? "translation " : "figure 4.4 translation ") << grid << " of "
           << (conforming ? "Kuhn" : "5-tetrahedron") << " box " << e[0] << "x" << e[1] << "x"
           << e[2] << " in " << f.text;
      }
      s.recipe = os.str();
      return s;
    });
  });
}

/// Overlapping instances (Eq. 4.2 violated): a box template translated by less than its width.
template <int D>
rc::Gen<GeneratedStructure<D>> overlapping_translation() {
  return rc::gen::exec([] {
    auto s = *translation_impl<D>(true, false);
    auto& list = s.x.instances[0];
    const auto box = core::box_of<Exact, D>(s.x.templates[0].mesh.points);
    Point<D> shift = core::zero_point<Exact, D>();
    shift[0] = (box.hi[0] - box.lo[0]) * rational(1, pick(2, 3));
    list.resize(1);
    list.push_back({list[0].transformation * Motion<D>::translation(shift), pick(1, 2)});
    s.tier = Tier::any;
    s.convex = false;
    s.recipe += "; overlapping: second instance shifted by " + text<D>(shift);
    return s;
  });
}

// ----- encroachment (Lemma 4.5 generator) -------------------------------------------------------

/// Circumcentre of a facet within its own affine hull (midpoint of an edge, circumcentre of a
/// triangle in 3D), exactly.
template <int D>
Point<D> facet_circumcenter(const PointSet<D>& v) {
  if (v.size() == 2) return core::scaled<Exact, D>(v[0] + v[1], rational(1, 2));
  const auto b = v[1] - v[0], c = v[2] - v[0];
  const Exact bb = core::dot<Exact, D>(b, b), cc = core::dot<Exact, D>(c, c),
              bc = core::dot<Exact, D>(b, c);
  const Exact det = bb * cc - bc * bc;
  const Exact alpha = (bb * cc - cc * bc) / (2 * det), beta = (cc * bb - bb * bc) / (2 * det);
  return v[0] + core::scaled<Exact, D>(b, alpha) + core::scaled<Exact, D>(c, beta);
}

/// Vertices strictly inside the diametral ball of an interface facet: a template boundary facet
/// whose image under some instance coincides with the image of a boundary facet under another
/// instance. Such an apex keeps the facet from being locally Delaunay in AT (the mirrored /
/// translated neighbour cell is on the other side); other boundary facets have one co-face cell.
template <int D>
std::vector<Point<D>> encroaching_apexes(const Complex<D>& m, const std::vector<Motion<D>>& tfs) {
  std::map<Simplex, int> count;
  const auto cells = m.cells();
  for (const auto& c : cells)
    for (const auto& f : core::facets(c)) ++count[f];
  // images of the boundary facets under every instance, as sorted point tuples
  using Key = std::vector<Point<D>>;
  auto key = [&](const Simplex& f, const Motion<D>& t) {
    Key k;
    for (VertexId v : f) k.push_back(t(m.points[v]));
    std::sort(k.begin(), k.end(), core::PointLess<Exact, D>());
    return k;
  };
  auto less = [](const Key& a, const Key& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                        core::PointLess<Exact, D>());
  };
  std::map<Key, int, decltype(less)> images(less);
  for (const auto& [f, n] : count)
    if (n == 1)
      for (const auto& t : tfs) ++images[key(f, t)];
  std::vector<Point<D>> out;
  for (const auto& c : cells)
    for (const auto& f : core::facets(c)) {
      if (count[f] != 1) continue;
      bool interface = false;
      for (const auto& t : tfs) interface = interface || images[key(f, t)] > 1;
      if (!interface) continue;
      const auto fv = m.coords(f);
      const auto cc = facet_circumcenter<D>(fv);
      const Exact r2 = core::dot<Exact, D>(fv[0] - cc, fv[0] - cc);
      for (VertexId v : c)
        if (!f.has_vertex(v)) {
          const auto d = m.points[v] - cc;
          if (core::dot<Exact, D>(d, d) < r2) out.push_back(m.points[v]);
        }
    }
  return out;
}

/// Delaunay triangulation of `pts` with encroaching removable points dropped until no interface
/// facet is encroached; fails (empty) if a non-removable point encroaches.
template <int D>
Complex<D> unencroached_delaunay(PointSet<D> pts, const std::vector<bool>& removable_in,
                                 const std::vector<Motion<D>>& tfs) {
  std::vector<bool> removable = removable_in;
  for (int round = 0; round < 12; ++round) {
    const auto mesh = complex_from_cells<D>(pts, delaunay_cells<D>(pts), false);
    const auto bad = encroaching_apexes<D>(mesh, tfs);
    if (bad.empty()) return complex_from_cells<D>(pts, delaunay_cells<D>(pts));
    PointSet<D> keep;
    std::vector<bool> keep_removable;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const bool encroaches = std::find(bad.begin(), bad.end(), pts[i]) != bad.end();
      if (encroaches && !removable[i]) return {};
      if (!encroaches) {
        keep.push_back(pts[i]);
        keep_removable.push_back(removable[i]);
      }
    }
    pts = keep;
    removable = keep_removable;
  }
  return {};
}

// ----- a simplex with vertices -------------------------------------------------------------------

template <int D>
PointSet<D> random_simplex(int k) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    PointSet<D> s;
    for (int i = 0; i <= k; ++i) {
      Coords<D> c;
      for (int d = 0; d < D; ++d) c[d] = grid_value(0, 4);
      s.push_back(make_point<D>(c));
    }
    if (dedupe<D>(s).size() == s.size() && core::affinely_independent<Exact, D>(s)) return s;
  }
  PointSet<D> s; // the corner simplex, should the picks keep coinciding
  for (int i = 0; i <= k; ++i) {
    Coords<D> c;
    for (int d = 0; d < D; ++d) c[d] = i == d + 1 ? 2 : 0;
    s.push_back(make_point<D>(c));
  }
  return s;
}

/// A big simplex on the side m·(x - c) >= 0 whose facet lies in the hyperplane through c.
template <int D>
PointSet<D> half_space_simplex(const Point<D>& c, const Point<D>& m);

template <>
PointSet<2> half_space_simplex<2>(const Point<2>& c, const Point<2>& m) {
  const Point<2> t = make_point<2>({-m[1], m[0]});
  return {c + core::scaled<Exact, 2>(t, 40), c - core::scaled<Exact, 2>(t, 40),
          c + core::scaled<Exact, 2>(m, 40)};
}

template <>
PointSet<3> half_space_simplex<3>(const Point<3>& c, const Point<3>& m) {
  int k = 0;
  for (int d = 1; d < 3; ++d)
    if (CGAL::abs(m[d]) < CGAL::abs(m[k])) k = d;
  Coords<3> e{};
  for (int d = 0; d < 3; ++d) e[d] = d == k ? 1 : 0;
  const auto u = cross(m, make_point<3>(e));
  const auto w = cross(m, u);
  return {c + core::scaled<Exact, 3>(u, 80),
          c - core::scaled<Exact, 3>(u, 40) + core::scaled<Exact, 3>(w, 70),
          c - core::scaled<Exact, 3>(u, 40) - core::scaled<Exact, 3>(w, 70),
          c + core::scaled<Exact, 3>(m, 80)};
}

/// A normal m whose hyperplane through c = centroid(e) separates two vertices of e strictly.
template <int D>
Point<D> cutting_normal(const PointSet<D>& e) {
  const auto c = centroid<D>(e);
  for (int attempt = 0; attempt < 30; ++attempt) {
    const auto m = small_vector<D>(-2, 2);
    bool pos = false, neg = false;
    for (const auto& v : e) {
      const Exact s = core::dot<Exact, D>(m, v - c);
      pos = pos || s > 0;
      neg = neg || s < 0;
    }
    if (pos && neg) return m;
  }
  return e[1] - e[0]; // always separates e[0] from e[1]
}

template <int D>
Complex<D> delaunay_of(const PointSet<D>& pts) {
  return complex_from_cells<D>(pts, delaunay_cells<D>(pts));
}

} // namespace

// =============================================================================================
// public generators
// =============================================================================================

std::string text(const Exact& x) {
  std::ostringstream os;
  os << CGAL::exact(x);
  return os.str();
}

template <int D>
std::string text(const Point<D>& p) {
  std::string s = "(";
  for (int d = 0; d < D; ++d) s += (d ? "," : "") + text(p[d]);
  return s + ")";
}

template <int D>
Complex<D> simplex_complex(const PointSet<D>& vertices) {
  Cell c;
  for (std::size_t i = 0; i < vertices.size(); ++i) c.push_back(VertexId(i));
  return complex_from_cells<D>(vertices, {c}, false);
}

template <int D>
rc::Gen<Described<Complex<D>>> delaunay_triangulation() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      const auto pts = random_point_set<D>(point_count(size, D));
      return Described<Complex<D>>{delaunay_of<D>(pts), "delaunay of " + points_text<D>(pts)};
    });
  });
}

template <int D>
rc::Gen<Described<Complex<D>>> regular_triangulation() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      const auto pts = random_point_set<D>(point_count(size, D));
      const auto w = random_weights(pts.size(), std::vector<bool>(pts.size(), false));
      const auto cells = regular_cells<D>(pts, w);
      std::string ws;
      for (int x : w) ws += std::to_string(x);
      if (cells.empty()) // cannot happen for full-dimensional points (extreme points stay)
        return Described<Complex<D>>{delaunay_of<D>(pts), "delaunay of " + points_text<D>(pts)};
      return Described<Complex<D>>{complex_from_cells<D>(pts, cells),
                                   "regular(w=" + ws + ") of " + points_text<D>(pts)};
    });
  });
}

template <int D>
rc::Gen<Described<Complex<D>>> triangulation() {
  return rc::gen::oneOf(delaunay_triangulation<D>(), regular_triangulation<D>());
}

namespace {
/// A sub-mesh of m: face completion of a random non-empty set of k-simplices of m.
template <int D>
Complex<D> random_submesh(const Complex<D>& m, int k) {
  std::vector<Cell> chosen;
  const auto all = m.elements_of_dimension(k);
  for (const auto& s : all)
    if (chance(50)) chosen.push_back(Cell(s.begin(), s.end()));
  if (chosen.empty()) chosen.push_back(Cell(all[0].begin(), all[0].end()));
  return complex_from_cells<D>(m.points, chosen);
}

/// The same complex over a reversed point array with one extra unused point, so that the pair
/// only compares equal after exact vertex identification (core::unify).
template <int D>
Complex<D> relabelled(const Complex<D>& m) {
  Complex<D> out;
  const std::size_t n = m.points.size();
  out.points.assign(m.points.rbegin(), m.points.rend());
  Point<D> extra = m.points[0];
  extra[0] += 17;
  out.points.push_back(extra);
  for (const auto& e : m.elements) {
    std::vector<VertexId> ids;
    for (VertexId v : e) ids.push_back(VertexId(n - 1 - v));
    out.elements.push_back(Simplex::from_range(ids.data(), ids.data() + ids.size()));
  }
  out.normalize();
  return out;
}
} // namespace

template <int D>
rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>> meshes_with_conforming_union() {
  return rc::gen::exec([] {
    const auto base = *triangulation<D>();
    const int k1 = chance(70) ? D : pick(1, D);
    const int k2 = chance(70) ? D : pick(1, D);
    const auto m1 = random_submesh<D>(base.value, k1);
    const auto m2 = relabelled<D>(random_submesh<D>(base.value, k2));
    return Described<std::pair<Complex<D>, Complex<D>>>{
        {m1, m2},
        "sub-meshes of dimension " + std::to_string(k1) + " and " + std::to_string(k2) +
            " (second relabelled) of " + base.recipe};
  });
}

namespace {
template <int D>
Described<std::pair<Complex<D>, Complex<D>>> figure_2_7() {
  const auto ab = random_simplex<D>(1);
  const int q = pick(2, 7);
  const Exact t = rational(pick(1, q - 1), q);
  const auto p = ab[0] + core::scaled<Exact, D>(ab[1] - ab[0], t);
  return {{simplex_complex<D>(ab), simplex_complex<D>({p})},
          "figure 2.7: line " + text<D>(ab[0]) + "-" + text<D>(ab[1]) +
              " and vertex at t=" + text(t)};
}

/// Two triangulations of one point set over the same (uncompacted) point array.
template <int D>
std::pair<Complex<D>, Complex<D>> two_triangulations(const PointSet<D>& pts, std::string* how) {
  const auto w = random_weights(pts.size(), std::vector<bool>(pts.size(), false));
  std::string ws;
  for (int x : w) ws += std::to_string(x);
  *how = "delaunay and regular(w=" + ws + ") of " + points_text<D>(pts);
  return {complex_from_cells<D>(pts, delaunay_cells<D>(pts), false),
          complex_from_cells<D>(pts, regular_cells<D>(pts, w), false)};
}
} // namespace

template <int D>
rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>> meshes_with_nonconforming_union() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      if (chance(50)) return figure_2_7<D>();
      const auto pts = random_point_set<D>(point_count(size, D) + 1);
      std::string how;
      const auto [a, b] = two_triangulations<D>(pts, &how);
      if (a.elements == b.elements || b.elements.empty()) return figure_2_7<D>();
      return Described<std::pair<Complex<D>, Complex<D>>>{{a, b}, "two triangulations: " + how};
    });
  });
}

template <int D>
rc::Gen<Described<Complex<D>>> nonconforming_complex() {
  return rc::gen::suchThat(rc::gen::withSize([](int size) {
                             return rc::gen::exec([size] {
                               const auto pts = random_point_set<D>(point_count(size, D) + 2);
                               std::string how;
                               const auto [a, b] = two_triangulations<D>(pts, &how);
                               auto u = core::set_union(a, b);
                               return Described<Complex<D>>{u, "element union of " + how};
                             });
                           }),
                           [](const Described<Complex<D>>& c) {
                             // the two triangulations differ (equal ones would give a conforming
                             // union)
                             return core::find_nonconformity(c.value).has_value();
                           });
}

template <int D>
rc::Gen<Described<Complex<D>>> non_face_complete_complex() {
  return rc::gen::exec([] {
    auto m = *triangulation<D>();
    const auto cells = m.value.cells();
    const auto& c = cells[pick(0, int(cells.size()) - 1)];
    const auto fs = core::facets(c);
    const auto f = fs[pick(0, int(fs.size()) - 1)];
    m.value.elements.erase(std::find(m.value.elements.begin(), m.value.elements.end(), f));
    m.recipe += "; one facet of a cell removed";
    return m;
  });
}

template <int D>
rc::Gen<Described<MultiRegion<D>>> multi_region_mesh() {
  return rc::gen::exec([] {
    const auto m = *triangulation<D>();
    MultiRegion<D> mr;
    mr.mesh = m.value;
    const bool by_side = chance(50);
    const auto n = small_vector<D>(-2, 2);
    const Exact d = grid_value(0, 8);
    for (const auto& c : m.value.cells())
      mr.cell_region[c] = by_side
                              ? (core::dot<Exact, D>(n, centroid<D>(m.value.coords(c))) < d ? 1 : 2)
                              : pick(1, 3);
    return Described<MultiRegion<D>>{
        mr, m.recipe + (by_side ? "; regions by side of n=" + text<D>(n) + ", d=" + text(d)
                                : "; random regions")};
  });
}

template <int D>
rc::Gen<Described<MultiRegion<D>>> nonconforming_multi_region() {
  return rc::gen::exec([] {
    const auto m = *nonconforming_complex<D>();
    MultiRegion<D> mr;
    mr.mesh = m.value;
    for (const auto& c : m.value.cells()) mr.cell_region[c] = pick(1, 3);
    const auto bad = core::find_nonconformity(m.value);
    for (auto& [c, r] : mr.cell_region)
      if (bad && (bad->a.is_face_of(c) || bad->b.is_face_of(c))) r = 1;
    return Described<MultiRegion<D>>{mr,
                                     m.recipe + "; random regions, the violating pair in region 1"};
  });
}

// ----- respect (Lemma 2.3)
// ------------------------------------------------------------------------

namespace {
/// A convex set designed to meet e in a union of faces (or to contain / avoid it), or a random one.
template <int D>
std::pair<PointSet<D>, std::string> convex_set_near(const PointSet<D>& e) {
  const auto c = centroid<D>(e);
  switch (pick(0, 4)) {
  case 0: { // contains e
    PointSet<D> a;
    for (const auto& v : e) a.push_back(c + core::scaled<Exact, D>(v - c, Exact(2)));
    if (chance(50)) a.push_back(c + small_vector<D>(-3, 3));
    return {a, "containing"};
  }
  case 1: { // far away
    PointSet<D> a;
    Point<D> shift = core::zero_point<Exact, D>();
    shift[0] = 20;
    for (const auto& v : e) a.push_back(v + shift);
    return {a, "disjoint"};
  }
  case 2:
  case 3: { // meets e exactly in a face F: point reflection of the other vertices through F
    std::vector<int> in;
    for (std::size_t i = 0; i < e.size(); ++i)
      if (chance(50)) in.push_back(int(i));
    if (in.empty()) in.push_back(0);
    PointSet<D> f;
    for (int i : in) f.push_back(e[i]);
    const auto cf = centroid<D>(f);
    PointSet<D> a = f;
    for (std::size_t i = 0; i < e.size(); ++i)
      if (std::find(in.begin(), in.end(), int(i)) == in.end())
        a.push_back(core::scaled<Exact, D>(cf, Exact(2)) - e[i]);
    return {a, "touching a " + std::to_string(in.size() - 1) + "-face"};
  }
  default: {
    PointSet<D> a;
    const int n = pick(1, D + 1);
    for (int k = 0; k < n; ++k) {
      Coords<D> q;
      for (int d = 0; d < D; ++d) q[d] = grid_value(-1, 5);
      a.push_back(make_point<D>(q));
    }
    return {a, "random"};
  }
  }
}
} // namespace

template <int D>
rc::Gen<Described<RespectCase<D>>> respect_both() {
  return rc::gen::suchThat(rc::gen::exec([] {
                             const auto e = random_simplex<D>(pick(1, D));
                             const auto [a, ka] = convex_set_near<D>(e);
                             const auto [b, kb] = convex_set_near<D>(e);
                             return Described<RespectCase<D>>{
                                 {e, a, b},
                                 "E=" + points_text<D>(e) + " A(" + ka + ")=" + points_text<D>(a) +
                                     " B(" + kb + ")=" + points_text<D>(b)};
                           }),
                           [](const Described<RespectCase<D>>& r) {
                             return core::respects<Exact, D>(r.value.e, {r.value.a}) &&
                                    core::respects<Exact, D>(r.value.e, {r.value.b});
                           });
}

template <int D>
rc::Gen<Described<RespectCase<D>>> respect_one_only() {
  return rc::gen::exec([] {
    const auto e = random_simplex<D>(pick(1, D));
    const auto c = centroid<D>(e);
    PointSet<D> a;
    for (const auto& v : e) a.push_back(c + core::scaled<Exact, D>(v - c, Exact(2)));
    const auto m = cutting_normal<D>(e);
    const auto b = half_space_simplex<D>(c, m);
    return Described<RespectCase<D>>{
        {e, a, b},
        "E=" + points_text<D>(e) + " A(containing)=" + points_text<D>(a) +
            " B(cut through centroid, m=" + text<D>(m) + ")=" + points_text<D>(b)};
  });
}

// ----- geometry conformity (Lemma 2.4)
// -------------------------------------------------------------

template <int D>
rc::Gen<Described<GeometryCase<D>>> geometry_conforming_case() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      GeometryCase<D> g;
      std::string how;
      {
        g.points = random_point_set<D>(point_count(size, D));
        const auto [a, b] = two_triangulations<D>(g.points, &how);
        const bool swap = chance(50);
        g.mesh = complex_from_cells<D>(g.points, cells_of<D>(swap ? b : a));
        g.other_mesh = complex_from_cells<D>(g.points, cells_of<D>(swap ? a : b));
        how += swap ? " (M regular)" : " (M delaunay)";
      }
      auto o = *reflections_impl<D>(1, 1, false);
      // two regions, region(G, 1) = conv(template points), region(G, 2) = its mirror image
      o.s.x.instances[0][0].region = 1;
      o.s.x.instances[0][1].region = 2;
      const auto si = core::apply_template(o.s.x);
      g.multi = si.at;
      const auto& tmpl = o.s.x.templates[0].mesh;
      PointSet<D> mirrored;
      for (const auto& p : tmpl.points) mirrored.push_back(o.s.x.instances[0][1].transformation(p));
      g.region_ids = {1, 2};
      g.region_hulls = {tmpl.points, mirrored};
      return Described<GeometryCase<D>>{g, "M, M' = " + how + "; multi-region: " + o.s.recipe};
    });
  });
}

template <int D>
rc::Gen<Described<NonConformingGeometryCase<D>>> geometry_not_conforming_case() {
  return rc::gen::exec([] {
    const auto m = *triangulation<D>();
    const auto cells = m.value.cells();
    const auto& c = cells[pick(0, int(cells.size()) - 1)];
    const auto cv = m.value.coords(c);
    const auto n = cutting_normal<D>(cv);
    NonConformingGeometryCase<D> g;
    g.mesh = m.value;
    g.points = m.value.points;
    g.cut = half_space_simplex<D>(centroid<D>(cv), n);
    return Described<NonConformingGeometryCase<D>>{
        g,
        m.recipe + "; G cut by the hyperplane through a cell centroid with normal " + text<D>(n)};
  });
}

// ----- Delaunay counterexamples (Lemma 2.5 / 4.5)
// ---------------------------------------------------

namespace {
/// A flat simplex on the positive side of x_{D-1} >= 0 with its base facet in x_{D-1} = 0.
/// Returns the vertices (base first, apex last) and the squared "margin" R0^2 - |a - c0|^2 of
/// the apex foot a inside the base circumsphere.
template <int D>
PointSet<D> flat_simplex(int L, Exact h);

template <>
PointSet<2> flat_simplex<2>(int L, Exact h) {
  return {make_point<2>({Exact(-L), Exact(0)}), make_point<2>({Exact(L), Exact(0)}),
          make_point<2>({Exact(0), h})};
}
template <>
PointSet<3> flat_simplex<3>(int L, Exact h) {
  // base on the circle of radius L about the origin, apex above (0, L/3)
  return {
      make_point<3>({Exact(-L), Exact(0), Exact(0)}), make_point<3>({Exact(L), Exact(0), Exact(0)}),
      make_point<3>({Exact(0), Exact(L), Exact(0)}), make_point<3>({Exact(0), rational(L, 3), h})};
}
/// The largest h = 1/q (q >= 3) with h^2 below the apex foot's margin (so the apex is strictly
/// inside the base facet's diametral ball: the facet is encroached).
template <int D>
Exact flat_height(int L) {
  const Exact foot2 = D == 2 ? Exact(0) : rational(L * L, 9);
  const Exact margin = Exact(L * L) - foot2;
  int q = pick(3, 6);
  while (!(rational(1, q * q) < margin)) ++q;
  return rational(1, q);
}
} // namespace

template <int D>
rc::Gen<GeneratedStructure<D>> flat_simplex_v_shape() {
  return rc::gen::exec([] {
    const int L = pick(2, 4);
    const Exact h = flat_height<D>(L);
    const auto v = flat_simplex<D>(L, h);
    // reflecting hyperplane through the vertex (L, 0, ...) tilted by slope s: normal (-s, 0.., 1)
    const Exact s = rational(1, pick(4, 9));
    Point<D> n = core::zero_point<Exact, D>();
    n[0] = -s;
    n[D - 1] = 1;
    const Exact d = core::dot<Exact, D>(n, v[1]);
    const auto mesh = simplex_complex<D>(v);
    GeneratedStructure<D> g;
    g.x = single_template<D>(mesh, {Motion<D>(), Motion<D>::reflection(n, d)}, {1, pick(1, 2)});
    g.tier = Tier::valid_templated_mesh;
    g.convex = false;
    g.recipe = "flat simplex L=" + std::to_string(L) + " h=" + text(h) +
               " reflected across the hyperplane through " + text<D>(v[1]) + " with normal " +
               text<D>(n);
    return maybe_moved<D>(g, 50);
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> encroached_reflection() {
  return rc::gen::exec([] {
    const int L = pick(2, 4);
    const Exact h = flat_height<D>(L);
    const auto v = flat_simplex<D>(L, h);
    Point<D> n = core::zero_point<Exact, D>();
    n[D - 1] = 1;
    GeneratedStructure<D> g;
    g.x = single_template<D>(simplex_complex<D>(v),
                             {Motion<D>(), Motion<D>::reflection(n, Exact(0))}, {1, pick(1, 2)});
    g.tier = Tier::valid_templated_mesh;
    g.convex = true;
    g.recipe = "flat simplex L=" + std::to_string(L) + " h=" + text(h) +
               " reflected across its base facet";
    return maybe_moved<D>(g, 50);
  });
}

// ----- structures
// ------------------------------------------------------------------------------------

template <int D>
rc::Gen<GeneratedStructure<D>> reflective_structure() {
  return rc::gen::exec([] {
    auto o = *reflections_impl<D>(1, 1, false);
    o.s.recipe = "reflective: " + o.s.recipe;
    return maybe_moved<D>(o.s, 40);
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> crossing_reflective_structure() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      const auto f = random_frame<D>();
      // No point lies on H (c_0 != 0) but some lie on either side: the hull crosses H, so some
      // cell meets H, and as no vertex is on H that cell has vertices strictly on both sides
      // (its interior meets H and overlaps its own mirror image).
      std::vector<Coords<D>> cs;
      const int n = point_count(size, D) + 1;
      for (int k = 0; k < n; ++k) {
        Coords<D> c;
        for (int i = 0; i < D; ++i) c[i] = grid_value(i == 0 ? -2 : -3, 3);
        if (c[0] == 0) c[0] = rational(1, 2);
        cs.push_back(c);
      }
      Coords<D> below{}, above{};
      for (int i = 0; i < D; ++i) below[i] = above[i] = 0;
      below[0] = -1;
      above[0] = 2;
      cs.push_back(below);
      cs.push_back(above);
      for (int i = 1; i < D; ++i) { // keep the point set full-dimensional
        Coords<D> e = above;
        e[i] = 2;
        cs.push_back(e);
      }
      PointSet<D> pts;
      for (const auto& c : cs) pts.push_back(f.at(c));
      pts = dedupe<D>(pts);
      GeneratedStructure<D> g;
      g.x = single_template<D>(delaunay_of<D>(pts), {Motion<D>(), f.reflection(0, 0)},
                               {1, pick(1, 2)});
      g.tier = Tier::any;
      g.recipe = "template crossing H: delaunay of " + points_text<D>(pts) + " in " + f.text;
      return maybe_moved<D>(g, 30);
    });
  });
}

template <int D>
rc::Gen<OrthogonalReflections<D>> orthogonal_reflections() {
  return rc::gen::exec([] {
    auto o = *reflections_impl<D>(2, D, false);
    if (chance(40)) {
      const auto g = random_motion<D>();
      const bool conj = chance(50);
      o.s = moved<D>(o.s, g, conj);
      // the symmetry hyperplanes of AT move with g: n' = A n, d' = d + n'·b
      for (std::size_t j = 0; j < o.normals.size(); ++j) {
        Point<D> n2;
        const auto& a = g.value.matrix();
        for (int r = 0; r < D; ++r) {
          n2[r] = 0;
          for (int k = 0; k < D; ++k) n2[r] += a[r][k] * o.normals[j][k];
        }
        o.offsets[j] = o.offsets[j] + core::dot<Exact, D>(n2, g.value.translation_part());
        o.normals[j] = n2;
      }
    }
    return o;
  });
}

template <int D>
rc::Gen<OrthogonalReflections<D>> non_orthogonal_reflections() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      // axes a0 ⟂ a1 of equal length (a rotation by a Pythagorean angle), a2 = e_z in 3D
      const int p = pick(1, 3), q = pick(0, 2);
      std::array<Point<D>, D> axis;
      Point<D> o = core::zero_point<Exact, D>();
      for (int d = 0; d < D; ++d) o[d] = pick(-2, 2);
      axis[0] = core::zero_point<Exact, D>();
      axis[1] = core::zero_point<Exact, D>();
      axis[0][0] = p;
      axis[0][1] = q;
      axis[1][0] = -q;
      axis[1][1] = p;
      if constexpr (D == 3) {
        axis[2] = core::zero_point<Exact, D>();
        axis[2][2] = 1;
      }
      auto at = [&](const Coords<D>& c) {
        Point<D> x = o;
        for (int j = 0; j < D; ++j) x = x + core::scaled<Exact, D>(axis[j], c[j]);
        return x;
      };
      // template in the wedge 0 <= c1 <= c0 <= B (x 0 <= c2 <= Z)
      const int B = pick(2, 4), Z = pick(1, 2);
      std::vector<Coords<D>> cs;
      auto add = [&](const Exact& c0, const Exact& c1) {
        Coords<D> c{};
        c[0] = c0;
        c[1] = c1;
        if constexpr (D == 3) {
          cs.push_back(c);
          c[2] = Z;
        }
        cs.push_back(c);
      };
      add(0, 0);
      add(B, 0);
      add(B, B);
      const int extra = pick(0, 1 + size / 30);
      for (int k = 0; k < extra; ++k) {
        const Exact c0 = grid_value(1, B), c1 = grid_value(0, B);
        add(c0, c1 < c0 ? c1 : c0);
      }
      PointSet<D> pts;
      for (const auto& c : cs) pts.push_back(at(c));
      pts = dedupe<D>(pts);
      const auto mesh = delaunay_of<D>(pts);
      // the 8 signed permutations of (c0, c1) as world motions A S A^T / |a0|^2
      const Exact l2 = Exact(p * p + q * q);
      std::vector<Motion<D>> tfs;
      for (int perm = 0; perm < 2; ++perm)
        for (int sg = 0; sg < 4; ++sg) {
          typename Motion<D>::Mat s{};
          for (int r = 0; r < D; ++r)
            for (int k = 0; k < D; ++k) s[r][k] = 0;
          const int i0 = perm ? 1 : 0, i1 = perm ? 0 : 1;
          s[0][i0] = (sg & 1) ? -1 : 1;
          s[1][i1] = (sg & 2) ? -1 : 1;
          if constexpr (D == 3) s[2][2] = 1;
          typename Motion<D>::Mat m{};
          for (int r = 0; r < D; ++r)
            for (int k = 0; k < D; ++k) {
              Exact sum = 0;
              for (int i = 0; i < D; ++i)
                for (int j = 0; j < D; ++j) // c_j = (x - o)·a_j / |a_j|^2
                  sum += axis[i][r] * s[i][j] * axis[j][k] / (j < 2 ? l2 : Exact(1));
              m[r][k] = sum;
            }
          // x -> o + M (x - o)
          Point<D> b = o;
          for (int r = 0; r < D; ++r)
            for (int k = 0; k < D; ++k) b[r] -= m[r][k] * o[k];
          tfs.push_back(Motion<D>::from_matrix(m, b));
        }
      OrthogonalReflections<D> out;
      out.s.x = single_template<D>(mesh, tfs, std::vector<int>(tfs.size(), 1));
      out.s.tier = Tier::valid_templated_mesh;
      out.s.convex = true;
      out.normals = {axis[0], axis[0] - axis[1]};
      out.offsets = {core::dot<Exact, D>(axis[0], o), core::dot<Exact, D>(axis[0] - axis[1], o)};
      out.s.recipe =
          "square group (reflections at 45 degrees) of the wedge template, a0=" + text<D>(axis[0]) +
          " origin " + text<D>(o) + ", B=" + std::to_string(B) + ", " + points_text<D>(pts);
      return out;
    });
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> translation_grid() {
  return translation_impl<D>(true, false);
}

template <int D>
rc::Gen<GeneratedStructure<D>> figure_4_4_structure() {
  return translation_impl<D>(false, false);
}

template <int D>
rc::Gen<GeneratedStructure<D>> delaunay_templated_mesh() {
  return rc::gen::suchThat(rc::gen::withSize([](int size) {
                             return rc::gen::exec([size] {
                               GeneratedStructure<D> s;
                               const bool translate = D == 2 && chance(30);
                               if (translate) {
                                 s = *translation_impl<D>(true, true);
                               } else {
                                 s = (*reflections_impl<D>(1, D == 3 && size < 50 ? 2 : D, true)).s;
                               }
                               // re-triangulate the template: Delaunay with no encroached boundary
                               // facet
                               auto& tm = s.x.templates[0].mesh;
                               const auto bnd = core::mesh_boundary(tm);
                               std::set<VertexId> on_boundary;
                               for (const auto& e : bnd.elements)
                                 for (VertexId v : e) on_boundary.insert(v);
                               std::vector<bool> removable;
                               for (std::size_t i = 0; i < tm.points.size(); ++i)
                                 removable.push_back(!on_boundary.count(VertexId(i)));
                               std::vector<Motion<D>> tfs;
                               for (const auto& spec : s.x.instances[0])
                                 tfs.push_back(spec.transformation);
                               tm = unencroached_delaunay<D>(tm.points, removable, tfs);
                               s.recipe = "delaunay-repaired " + s.recipe;
                               s.convex = true;
                               if (!tm.elements.empty() && chance(30)) s = split_template<D>(s);
                               return maybe_moved<D>(s, 40);
                             });
                           }),
                           [](const GeneratedStructure<D>& s) {
                             for (const auto& t : s.x.templates)
                               if (t.mesh.elements.empty()) return false;
                             return true;
                           });
}

namespace {
/// Number of cells of AT(x): the exact LPs of the conformity checks grow quadratically with it.
template <int D>
std::size_t at_cells(const Structure<D>& x) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    n += x.templates[i].mesh.cells().size() * x.instances[i].size();
  return n;
}
/// Keeps the structure instance small (so that 300 cases stay fast): a few redraws, then accept.
template <int D>
constexpr std::size_t kMaxAtCells = D == 2 ? 36 : 10;
} // namespace

template <int D>
rc::Gen<GeneratedStructure<D>> valid_templated_mesh() {
  return rc::gen::exec([] {
    GeneratedStructure<D> s;
    for (int attempt = 0; attempt < 4; ++attempt) {
      switch (pick(0, 5)) {
      case 0:
      case 1:
        s = (*reflections_impl<D>(1, 1, false)).s;
        break;
      case 2:
        s = (*reflections_impl<D>(2, 2, false)).s;
        break; // 8 instances only in Lemma 6.2
      case 3:
      case 4:
        s = *translation_impl<D>(true, false);
        break;
      default:
        s = *delaunay_templated_mesh<D>();
        break;
      }
      if (at_cells<D>(s.x) <= kMaxAtCells<D>) break;
    }
    if (chance(35)) s = split_template<D>(s);
    return maybe_moved<D>(s, 40);
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> templated_structure() {
  return rc::gen::exec([] {
    if (chance(55)) return *valid_templated_mesh<D>();
    auto s = *figure_4_4_structure<D>();
    if (chance(30)) s = split_template<D>(s);
    return maybe_moved<D>(s, 40);
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> any_structure() {
  return rc::gen::exec([] {
    switch (pick(0, 4)) {
    case 0:
      return *crossing_reflective_structure<D>();
    case 1:
      return maybe_moved<D>(*overlapping_translation<D>(), 40);
    default:
      return *templated_structure<D>();
    }
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> non_mesh_template_structure() {
  return rc::gen::exec([] {
    auto s = *valid_templated_mesh<D>();
    for (auto& t : s.x.templates) t.mesh.elements = t.mesh.cells();
    s.tier = Tier::any;
    s.recipe += "; templates reduced to their cells (not face-complete)";
    return s;
  });
}

// ----- failure records ---------------------------------------------------------------------------

namespace {
/// The io layer's JSON text as a JSON value (kept as a string should it not parse).
nlohmann::json embedded(const std::string& text) {
  try {
    return nlohmann::json::parse(text);
  } catch (const std::exception&) {
    return text;
  }
}
} // namespace

template <int D>
std::string structure_record(const std::string& lemma, const std::string& recipe,
                             const Structure<D>& x) {
  // The templated-structure format itself, so that `symmesh check FILE` reads the counterexample.
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(io::to_json(x));
  j["description"] = "counterexample of " + lemma + " (" + recipe + ")";
  return j.dump(1);
}

template <int D>
std::string structure_picture(const Structure<D>& x) {
  if constexpr (D == 2)
    return io::structure_svg(x);
  else
    return std::string();
}

template <int D>
std::string complexes_record(const std::string& lemma, const std::string& recipe,
                             const std::vector<std::pair<std::string, Complex<D>>>& parts) {
  nlohmann::json j;
  j["lemma"] = lemma;
  j["recipe"] = recipe;
  for (const auto& [name, c] : parts) j["complexes"][name] = embedded(io::complex_to_json(c));
  return j.dump(1);
}

template <int D>
std::string complex_picture(const Complex<D>& c) {
  if constexpr (D == 2)
    return io::complex_svg(c);
  else
    return std::string();
}

// ----- explicit instantiations
// --------------------------------------------------------------------

#define SYMMESH_INSTANTIATE_GENERATORS(D)                                                          \
  template std::string text<D>(const Point<D>&);                                                   \
  template Complex<D> simplex_complex<D>(const PointSet<D>&);                                      \
  template std::string structure_record<D>(const std::string&, const std::string&,                 \
                                           const Structure<D>&);                                   \
  template std::string structure_picture<D>(const Structure<D>&);                                  \
  template std::string complexes_record<D>(                                                        \
      const std::string&, const std::string&,                                                      \
      const std::vector<std::pair<std::string, Complex<D>>>&);                                     \
  template std::string complex_picture<D>(const Complex<D>&);                                      \
  template rc::Gen<Described<Complex<D>>> triangulation<D>();                                      \
  template rc::Gen<Described<Complex<D>>> delaunay_triangulation<D>();                             \
  template rc::Gen<Described<Complex<D>>> regular_triangulation<D>();                              \
  template rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>>                                   \
  meshes_with_conforming_union<D>();                                                               \
  template rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>>                                   \
  meshes_with_nonconforming_union<D>();                                                            \
  template rc::Gen<Described<Complex<D>>> nonconforming_complex<D>();                              \
  template rc::Gen<Described<Complex<D>>> non_face_complete_complex<D>();                          \
  template rc::Gen<Described<MultiRegion<D>>> multi_region_mesh<D>();                              \
  template rc::Gen<Described<MultiRegion<D>>> nonconforming_multi_region<D>();                     \
  template rc::Gen<Described<RespectCase<D>>> respect_both<D>();                                   \
  template rc::Gen<Described<RespectCase<D>>> respect_one_only<D>();                               \
  template rc::Gen<Described<GeometryCase<D>>> geometry_conforming_case<D>();                      \
  template rc::Gen<Described<NonConformingGeometryCase<D>>> geometry_not_conforming_case<D>();     \
  template rc::Gen<GeneratedStructure<D>> flat_simplex_v_shape<D>();                               \
  template rc::Gen<GeneratedStructure<D>> reflective_structure<D>();                               \
  template rc::Gen<GeneratedStructure<D>> crossing_reflective_structure<D>();                      \
  template rc::Gen<OrthogonalReflections<D>> orthogonal_reflections<D>();                          \
  template rc::Gen<OrthogonalReflections<D>> non_orthogonal_reflections<D>();                      \
  template rc::Gen<GeneratedStructure<D>> translation_grid<D>();                                   \
  template rc::Gen<GeneratedStructure<D>> figure_4_4_structure<D>();                               \
  template rc::Gen<GeneratedStructure<D>> delaunay_templated_mesh<D>();                            \
  template rc::Gen<GeneratedStructure<D>> encroached_reflection<D>();                              \
  template rc::Gen<GeneratedStructure<D>> valid_templated_mesh<D>();                               \
  template rc::Gen<GeneratedStructure<D>> templated_structure<D>();                                \
  template rc::Gen<GeneratedStructure<D>> any_structure<D>();                                      \
  template rc::Gen<GeneratedStructure<D>> non_mesh_template_structure<D>();

SYMMESH_INSTANTIATE_GENERATORS(2)
SYMMESH_INSTANTIATE_GENERATORS(3)

} // namespace symmesh::proofs::gen

// =============================================================================================
// Appendix A: linear sets, intersection partition, refinement (Lemmas A.3, A.4)
// =============================================================================================

namespace symmesh::proofs::gen {
namespace {

template <int D>
LinearCell<D> hull(const PointSet<D>& p) {
  return core::make_convex_cell<Exact, D>(p);
}

template <int D>
Linear<D> linear_of(std::vector<LinearCell<D>> cells) {
  Linear<D> a{std::move(cells)};
  a.normalize();
  return a;
}

template <int D>
PointSet<D> vertices_of(const Linear<D>& a) {
  PointSet<D> out;
  for (const auto& c : a.cells) out.insert(out.end(), c.vertices.begin(), c.vertices.end());
  return dedupe<D>(out);
}

/// The cells' images under f, re-canonicalized (a rotation changes the lexicographic order).
template <int D, class F>
Linear<D> mapped(const Linear<D>& a, F&& f) {
  std::vector<LinearCell<D>> cells;
  for (const auto& c : a.cells) {
    PointSet<D> p;
    for (const auto& v : c.vertices) p.push_back(f(v));
    cells.push_back(hull<D>(p));
  }
  return linear_of<D>(cells);
}

/// A plane of R^D (R^2 itself for D = 2) with grid coordinates (s, t) ↦ o + s u + t v.
template <int D>
struct Sheet {
  Point<D> o, u, v;
  std::string text;
  Point<D> at(const Exact& s, const Exact& t) const {
    return o + core::scaled<Exact, D>(u, s) + core::scaled<Exact, D>(v, t);
  }
};

template <int D>
Sheet<D> random_sheet();

template <>
Sheet<2> random_sheet<2>() {
  return {make_point<2>({Exact(0), Exact(0)}), make_point<2>({Exact(1), Exact(0)}),
          make_point<2>({Exact(0), Exact(1)}), "R^2"};
}

template <>
Sheet<3> random_sheet<3>() {
  // Few planes, so that random pairs are often coplanar or meet along grid lines.
  static const int dirs[5][6] = {{1, 0, 0, 0, 1, 0},
                                 {1, 0, 0, 0, 0, 1},
                                 {0, 1, 0, 0, 0, 1},
                                 {1, 1, 0, 0, 0, 1},
                                 {1, -1, 0, 1, 0, -1}};
  static const int offset_axis[5] = {2, 1, 0, 0, 0};
  static const char* names[5] = {"z=", "y=", "x=", "x-y=", "x+y+z="};
  const int k = pick(0, 4), c = pick(0, 1);
  Sheet<3> s;
  s.u = make_point<3>({Exact(dirs[k][0]), Exact(dirs[k][1]), Exact(dirs[k][2])});
  s.v = make_point<3>({Exact(dirs[k][3]), Exact(dirs[k][4]), Exact(dirs[k][5])});
  Coords<3> o{Exact(0), Exact(0), Exact(0)};
  o[offset_axis[k]] = c;
  s.o = make_point<3>(o);
  s.text = std::string("plane ") + names[k] + std::to_string(c);
  return s;
}

template <int D>
Point<D> sheet_normal(const Sheet<D>& s) {
  if constexpr (D == 3) return cross(s.u, s.v);
  return s.u;
}

template <int D>
Point<D> grid_point(const Sheet<D>& s, int lo, int hi) {
  return s.at(grid_value(lo, hi), grid_value(lo, hi));
}

template <int D>
LinearCell<D> rect(const Sheet<D>& s, const Exact& x0, const Exact& y0, const Exact& x1,
                   const Exact& y1) {
  return hull<D>({s.at(x0, y0), s.at(x1, y0), s.at(x1, y1), s.at(x0, y1)});
}

/// The convex hull of 3-5 grid points (may degenerate to a segment or a point).
template <int D>
LinearCell<D> random_polygon(const Sheet<D>& s) {
  PointSet<D> p;
  const int n = pick(3, 5);
  for (int i = 0; i < n; ++i) p.push_back(grid_point<D>(s, 0, 4));
  return hull<D>(p);
}

/// A convex polygon of positive area.
template <int D>
LinearCell<D> random_2d_polygon(const Sheet<D>& s) {
  const auto c = random_polygon<D>(s);
  if (c.dim == 2) return c;
  return hull<D>({s.at(0, 0), s.at(pick(1, 4), 0), s.at(0, pick(1, 4))});
}

template <int D>
std::vector<LinearCell<D>> fan_of(const LinearCell<D>& c) {
  if (c.dim < 2 || c.vertices.size() == 3) return {c};
  std::vector<LinearCell<D>> out;
  for (std::size_t i = 1; i + 1 < c.vertices.size(); ++i)
    out.push_back(hull<D>({c.vertices[0], c.vertices[i], c.vertices[i + 1]}));
  return out;
}

template <int D>
std::vector<LinearCell<D>> chord_split(const LinearCell<D>& c) {
  const auto& v = c.vertices;
  const int m = int(v.size());
  if (c.dim < 2 || m < 4) return {c};
  const int k = pick(2, m - 2);
  PointSet<D> a(v.begin(), v.begin() + k + 1);
  PointSet<D> b(v.begin() + k, v.end());
  b.push_back(v[0]);
  return {hull<D>(a), hull<D>(b)};
}

/// Consecutive boundary edges of a polygon: a path or the closed loop (a 1-manifold).
template <int D>
std::vector<LinearCell<D>> boundary_chain(const LinearCell<D>& c) {
  if (c.dim < 2) return {c};
  const auto& v = c.vertices;
  const int m = int(v.size());
  const int start = pick(0, m - 1), len = pick(1, m);
  std::vector<LinearCell<D>> out;
  for (int j = 0; j < len; ++j)
    out.push_back(hull<D>({v[(start + j) % m], v[(start + j + 1) % m]}));
  return out;
}

/// 1-3 edge-connected grid squares (unit squares of one size share whole edges: conforming).
template <int D>
std::vector<LinearCell<D>> polyomino(const Sheet<D>& s) {
  const int side = pick(1, 2), x0 = pick(0, 2), y0 = pick(0, 2), n = pick(1, 3);
  static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  std::vector<std::pair<int, int>> sq{{0, 0}};
  while (int(sq.size()) < n) {
    const auto base = sq[pick(0, int(sq.size()) - 1)];
    const int d0 = pick(0, 3);
    for (int k = 0; k < 4; ++k) { // at most two other squares: a free side always exists
      const std::pair<int, int> q{base.first + dx[(d0 + k) % 4], base.second + dy[(d0 + k) % 4]};
      if (std::find(sq.begin(), sq.end(), q) == sq.end()) {
        sq.push_back(q);
        break;
      }
    }
  }
  std::vector<LinearCell<D>> out;
  for (const auto& [a, b] : sq)
    out.push_back(rect<D>(s, Exact(x0 + a * side), Exact(y0 + b * side), Exact(x0 + (a + 1) * side),
                          Exact(y0 + (b + 1) * side)));
  return out;
}

/// Two rectangles sharing the edge t = 0, one in the sheet and one leaving it along w.
std::vector<LinearCell<3>> folded(const Sheet<3>& s, Point<3>* fold_direction) {
  const int x0 = pick(0, 2), len = pick(1, 3), h1 = pick(1, 3), h2 = pick(1, 3);
  Point<3> w = cross(s.u, s.v);
  if (chance(40)) w = w + s.v;
  if (chance(50)) w = core::scaled<Exact, 3>(w, Exact(-1));
  const Point<3> a = s.at(x0, 0), b = s.at(x0 + len, 0);
  const Point<3> up = core::scaled<Exact, 3>(w, Exact(h2));
  if (fold_direction) *fold_direction = s.u;
  return {rect<3>(s, x0, 0, x0 + len, h1), hull<3>({a, b, b + up, a + up})};
}

template <int D>
Described<Linear<D>> random_shape(const Sheet<D>& s) {
  std::vector<LinearCell<D>> cells;
  std::string name;
  switch (pick(0, D == 3 ? 8 : 7)) {
  case 0:
    cells = {hull<D>({grid_point<D>(s, 0, 4)})};
    name = "point";
    break;
  case 1:
    cells = {hull<D>({grid_point<D>(s, 0, 4), grid_point<D>(s, 0, 4)})};
    name = "segment";
    break;
  case 2:
    cells = {random_polygon<D>(s)};
    name = "polygon";
    break;
  case 3:
    cells = fan_of<D>(random_2d_polygon<D>(s));
    name = "fan";
    break;
  case 4:
    cells = chord_split<D>(random_2d_polygon<D>(s));
    name = "chord split";
    break;
  case 5:
    cells = boundary_chain<D>(random_2d_polygon<D>(s));
    name = "boundary chain";
    break;
  case 6:
    cells = polyomino<D>(s);
    name = "polyomino";
    break;
  case 7:
    cells = {hull<D>({grid_point<D>(s, 0, 4), grid_point<D>(s, 0, 4), grid_point<D>(s, 0, 4)})};
    name = "triangle";
    break;
  default:
    if constexpr (D == 3) cells = folded(s, nullptr);
    name = "folded rectangles";
    break;
  }
  return {linear_of<D>(cells), name + " on " + s.text};
}

/// A small vector of the sheet's plane (2D: any), never zero.
template <int D>
Point<D> in_sheet_vector(const Sheet<D>& s) {
  int a = pick(-2, 2), b = pick(-2, 2);
  if (a == 0 && b == 0) a = 1;
  return core::scaled<Exact, D>(s.u, Exact(a)) + core::scaled<Exact, D>(s.v, Exact(b));
}

template <int D>
Described<Linear<D>> translated_to(const Described<Linear<D>>& shape, const Point<D>& anchor) {
  const Point<D> t = anchor - shape.value.cells.front().vertices.front();
  return {mapped<D>(shape.value, [&](const Point<D>& p) { return p + t; }),
          shape.recipe + " moved to " + text<D>(anchor)};
}

} // namespace

template <int D>
std::string cell_text(const LinearCell<D>& c) {
  std::string s = "[";
  for (std::size_t i = 0; i < c.vertices.size(); ++i) s += (i ? " " : "") + text<D>(c.vertices[i]);
  return s + "]";
}

template <int D>
std::string linear_text(const Linear<D>& a) {
  std::string s = "{";
  for (std::size_t i = 0; i < a.cells.size(); ++i) s += (i ? ", " : "") + cell_text<D>(a.cells[i]);
  return s + "}";
}

template <int D>
rc::Gen<Described<LinearPair<D>>> linear_manifold_pair() {
  return rc::gen::exec([] {
    const auto sa = random_sheet<D>();
    auto a = random_shape<D>(sa);
    const auto va = vertices_of<D>(a.value);
    Described<Linear<D>> b;
    switch (pick(0, 5)) {
    case 0:
      b = random_shape<D>(D == 3 && chance(50) ? sa : random_sheet<D>());
      break;
    case 1: {
      const Point<D> t = sa.at(grid_value(-2, 2), grid_value(-2, 2)) - sa.o;
      b = {mapped<D>(a.value, [&](const Point<D>& p) { return p + t; }),
           "A translated by " + text<D>(t)};
      break;
    }
    case 2: {
      const auto& c = a.value.cells[pick(0, int(a.value.cells.size()) - 1)];
      const auto edges = core::cell_edges<Exact, D>(c);
      if (edges.empty()) {
        b = translated_to<D>(random_shape<D>(sa), va[pick(0, int(va.size()) - 1)]);
        break;
      }
      const auto& e = edges[pick(0, int(edges.size()) - 1)];
      if (chance(40)) {
        static const int num[] = {1, 1, 3, 2};
        static const int den[] = {2, 1, 2, 1};
        const int k = pick(0, 3);
        const Point<D> q = e[0] + core::scaled<Exact, D>(e[1] - e[0], rational(num[k], den[k]));
        b = {linear_of<D>({hull<D>({e[0], q})}), "segment along an edge of A"};
      } else {
        Point<D> off = in_sheet_vector<D>(sa);
        if constexpr (D == 3)
          if (chance(50)) off = small_vector<3>(-2, 2);
        b = {linear_of<D>({hull<D>({e[0], e[1], e[0] + off})}), "triangle on an edge of A"};
      }
      break;
    }
    case 3:
      b = translated_to<D>(random_shape<D>(chance(50) ? sa : random_sheet<D>()),
                           va[pick(0, int(va.size()) - 1)]);
      break;
    case 4:
      b = {a.value, "B = A"};
      break;
    default: {
      // Another plane through a vertex of A (3D); in 2D a shape anchored at a vertex.
      auto sb = random_sheet<D>();
      sb.o = va[pick(0, int(va.size()) - 1)];
      b = random_shape<D>(sb);
      b.recipe += " through a vertex of A";
      break;
    }
    }
    std::string moved;
    if (chance(30)) {
      const auto g = random_motion<D>();
      a.value = mapped<D>(a.value, [&](const Point<D>& p) { return g.value(p); });
      b.value = mapped<D>(b.value, [&](const Point<D>& p) { return g.value(p); });
      moved = "; both moved by " + g.recipe;
    }
    return Described<LinearPair<D>>{{a.value, b.value},
                                    "A = " + a.recipe + " " + linear_text<D>(a.value) + "; B = " +
                                        b.recipe + " " + linear_text<D>(b.value) + moved};
  });
}

template <int D>
rc::Gen<Described<LinearPair<D>>> figure_a7_pair() {
  return rc::gen::exec([] {
    const int w = pick(1, 3), h = pick(1, 3);
    const Exact x0 = chance(30) ? rational(pick(1, 2 * w - 1), 2) : Exact(pick(0, w - 1));
    const auto s = random_sheet<D>();
    auto at = [&](const Exact& x, const Exact& y) { return s.at(x, y); };
    auto box = [&](const Exact& a, const Exact& b, const Exact& c, const Exact& d) {
      return rect<D>(s, a, b, c, d);
    };
    std::vector<LinearCell<D>> b;
    if (chance(50))
      b = {box(0, 0, w, h)};
    else
      b = {hull<D>({at(0, 0), at(w, 0), at(w, h)}), hull<D>({at(0, 0), at(w, h), at(0, h)})};
    // The column right of B touches it along x = w; the bar on top comes back left and the
    // triangle hanging from it touches B's top edge in (x0, h) only.
    std::vector<LinearCell<D>> a{
        box(w, 0, w + 1, h),         box(w, h, w + 1, h + 1),
        box(w, h + 1, w + 1, h + 2), box(x0 - 1, h + 1, x0, h + 2),
        box(x0, h + 1, w, h + 2),    hull<D>({at(x0 - 1, h + 1), at(x0, h + 1), at(x0, h)})};
    LinearPair<D> pair{linear_of<D>(a), linear_of<D>(b)};
    std::string recipe = "Figure A.7 with B = [0," + std::to_string(w) + "]x[0," +
                         std::to_string(h) + "] on " + s.text + ", touch point x0 = " + text(x0);
    if (chance(70)) {
      const auto g = random_motion<D>();
      pair.a = mapped<D>(pair.a, [&](const Point<D>& p) { return g.value(p); });
      pair.b = mapped<D>(pair.b, [&](const Point<D>& p) { return g.value(p); });
      recipe += ", moved by " + g.recipe;
    }
    return Described<LinearPair<D>>{pair, recipe};
  });
}

template <int D>
rc::Gen<Described<LinearPair<D>>> nonconforming_representation_pair() {
  return rc::gen::exec([] {
    const int len = pick(2, 4), up = pick(1, 3), down = pick(1, 3);
    const Exact t = inner_value(0, len), apex = grid_value(0, len);
    const Exact b0 = t - rational(pick(1, 4), 2), b1 = t + rational(pick(1, 4), 2);
    const auto s = random_sheet<D>();
    std::vector<LinearCell<D>> a{hull<D>({s.at(0, 0), s.at(len, 0), s.at(apex, up)}),
                                 hull<D>({s.at(0, 0), s.at(t, 0), s.at(t, -down)}),
                                 hull<D>({s.at(t, 0), s.at(len, 0), s.at(t, -down)})};
    LinearCell<D> b = hull<D>({s.at(b0, 0), s.at(b1, 0)});
    std::string shape = "segment";
    if constexpr (D == 3) {
      if (chance(50)) {
        b = hull<D>({s.at(b0, 0), s.at(b1, 0), s.at(t, 0) + sheet_normal<D>(s)});
        shape = "triangle off A's plane";
      }
    }
    LinearPair<D> pair{linear_of<D>(a), linear_of<D>({b})};
    std::string recipe = "T-junction at t = " + text(t) + " on [0," + std::to_string(len) + "] (" +
                         s.text + "), B = " + shape + " over [" + text(b0) + "," + text(b1) + "]";
    if (chance(50)) {
      const auto g = random_motion<D>();
      pair.a = mapped<D>(pair.a, [&](const Point<D>& p) { return g.value(p); });
      pair.b = mapped<D>(pair.b, [&](const Point<D>& p) { return g.value(p); });
      recipe += ", moved by " + g.recipe;
    }
    return Described<LinearPair<D>>{pair, recipe};
  });
}

namespace {

/// A geometry X of dimension 2 and the cuts that split it into manifolds: any line for a convex
/// X, axis-parallel lines for a polyomino (a slanted line through a reflex corner would pinch),
/// planes across the fold for folded rectangles.
template <int D>
struct Region {
  Linear<D> x;
  Sheet<D> sheet;
  enum { general, axis, across_fold } cuts = general;
  Point<D> fold{};
  std::string recipe;
};

template <int D>
Region<D> random_region() {
  Region<D> r;
  r.sheet = random_sheet<D>();
  switch (pick(0, D == 3 ? 3 : 2)) {
  case 0:
    r.x = linear_of<D>({random_2d_polygon<D>(r.sheet)});
    r.recipe = "convex polygon";
    break;
  case 1:
    r.x = linear_of<D>(fan_of<D>(random_2d_polygon<D>(r.sheet)));
    r.recipe = "fan";
    break;
  case 2:
    r.x = linear_of<D>(polyomino<D>(r.sheet));
    r.cuts = Region<D>::axis;
    r.recipe = "polyomino";
    break;
  default:
    if constexpr (D == 3) r.x = linear_of<D>(folded(r.sheet, &r.fold));
    r.cuts = Region<D>::across_fold;
    r.recipe = "folded rectangles";
    break;
  }
  r.recipe += " on " + r.sheet.text + " " + linear_text<D>(r.x);
  return r;
}

/// A cut direction suited to the region (never constant on its 2-cells).
template <int D>
Point<D> cut_direction(const Region<D>& r) {
  const Exact sign = chance(50) ? Exact(1) : Exact(-1);
  switch (r.cuts) {
  case Region<D>::axis:
    return core::scaled<Exact, D>(chance(50) ? r.sheet.u : r.sheet.v, sign);
  case Region<D>::across_fold:
    return core::scaled<Exact, D>(r.fold, sign);
  default:
    return in_sheet_vector<D>(r.sheet);
  }
}

/// {x : w·x >= c} through a vertex of X, the centroid of one of its cells, or a grid point.
template <int D>
std::pair<Point<D>, Exact> random_cut(const Region<D>& r, std::string& recipe) {
  const Point<D> w = cut_direction<D>(r);
  Point<D> through;
  const int how = pick(0, 2);
  if (how == 0) {
    const auto v = vertices_of<D>(r.x);
    through = v[pick(0, int(v.size()) - 1)];
  } else if (how == 1) {
    through = core::centroid<Exact, D>(r.x.cells[pick(0, int(r.x.cells.size()) - 1)]);
  } else {
    through = grid_point<D>(r.sheet, 0, 6);
  }
  recipe += " cut(n=" + text<D>(w) + " through " + text<D>(through) + ")";
  return {w, core::dot<Exact, D>(w, through)};
}

/// The 2-cells of e on either side of {w·x = c}; e itself if one side has no area.
template <int D>
LinearFamily<D> split(const Linear<D>& e, const Point<D>& w, const Exact& c) {
  std::vector<LinearCell<D>> pos, neg;
  for (const auto& cell : e.cells) {
    if (cell.dim < 2) continue;
    if (auto q = core::clip_halfspace<Exact, D>(cell, w, c); q && q->dim == 2) pos.push_back(*q);
    if (auto q = core::clip_halfspace<Exact, D>(cell, core::scaled<Exact, D>(w, Exact(-1)), -c);
        q && q->dim == 2)
      neg.push_back(*q);
  }
  if (pos.empty() || neg.empty()) return {e};
  return {linear_of<D>(pos), linear_of<D>(neg)};
}

/// X ∩ {w·x = c} (segments and points), possibly empty.
template <int D>
Linear<D> on_line(const Linear<D>& x, const Point<D>& w, const Exact& c) {
  std::vector<LinearCell<D>> cells;
  for (const auto& cell : x.cells)
    if (auto q = core::clip_halfspace<Exact, D>(cell, w, c))
      if (auto l = core::clip_halfspace<Exact, D>(*q, core::scaled<Exact, D>(w, Exact(-1)), -c))
        cells.push_back(*l);
  return linear_of<D>(cells);
}

template <int D>
Described<LinearFamily<D>> random_partition(const Region<D>& r) {
  LinearFamily<D> s{r.x};
  std::string recipe;
  const int cuts = pick(0, 3);
  for (int k = 0; k < cuts; ++k) {
    const auto [w, c] = random_cut<D>(r, recipe);
    if (chance(50)) {
      LinearFamily<D> next;
      for (const auto& e : s)
        for (auto& f : split<D>(e, w, c)) next.push_back(std::move(f));
      s = std::move(next);
      recipe += " on all";
    } else {
      const int i = pick(0, int(s.size()) - 1);
      auto parts = split<D>(s[i], w, c);
      s[i] = parts[0];
      if (parts.size() > 1) s.push_back(parts[1]);
      recipe += " on element " + std::to_string(i);
    }
  }
  if (chance(30)) {
    // Lower-dimensional elements are allowed by Def A.27 and may overlap anything.
    switch (pick(0, 2)) {
    case 0: {
      std::string ignored;
      const auto [w, c] = random_cut<D>(r, ignored);
      auto l = on_line<D>(r.x, w, c);
      if (!l.empty()) {
        s.push_back(l);
        recipe += " + X on a line";
      }
      break;
    }
    case 1: {
      const auto edges = core::cell_edges<Exact, D>(r.x.cells[pick(0, int(r.x.cells.size()) - 1)]);
      s.push_back(linear_of<D>({hull<D>(edges[pick(0, int(edges.size()) - 1)])}));
      recipe += " + an edge";
      break;
    }
    default: {
      const auto v = vertices_of<D>(r.x);
      s.push_back(linear_of<D>({hull<D>({v[pick(0, int(v.size()) - 1)]})}));
      recipe += " + a vertex";
      break;
    }
    }
  }
  return {s, std::to_string(s.size()) + " elements:" + recipe};
}

template <int D>
Described<PartitionCase<D>> finish_case(PartitionCase<D> c, std::string recipe) {
  if (chance(30)) {
    const auto g = random_motion<D>();
    auto f = [&](const Point<D>& p) { return g.value(p); };
    c.x = mapped<D>(c.x, f);
    for (auto& e : c.s) e = mapped<D>(e, f);
    for (auto& e : c.p) e = mapped<D>(e, f);
    recipe += "; moved by " + g.recipe;
  }
  c.x_mesh = linear_set_complex<D>(c.x);
  return {c, recipe};
}

} // namespace

template <int D>
rc::Gen<Described<PartitionCase<D>>> manifold_partitions() {
  return rc::gen::exec([] {
    const auto r = random_region<D>();
    const auto s = random_partition<D>(r);
    const auto p = random_partition<D>(r);
    return finish_case<D>({r.x, {}, s.value, p.value},
                          "X = " + r.recipe + "; S: " + s.recipe + "; P: " + p.recipe);
  });
}

template <int D>
rc::Gen<Described<PartitionCase<D>>> covering_and_partition() {
  return rc::gen::exec([] {
    const auto r = random_region<D>();
    const auto p = random_partition<D>(r);
    // y = x ∩ b of positive area (P covers X, so some 2-cells overlap).
    std::vector<LinearCell<D>> ys;
    for (const auto& e : p.value)
      for (const auto& b : e.cells)
        for (const auto& x : r.x.cells)
          if (b.dim == 2 && x.dim == 2)
            if (auto y = core::intersect<Exact, D>(x, b); y && y->dim == 2) ys.push_back(*y);
    const auto y = ys.at(pick(0, int(ys.size()) - 1));
    const Point<D> w = cut_direction<D>(r);
    const Point<D> z = core::centroid<Exact, D>(y);
    Exact m = 0;
    for (const auto& v : y.vertices) {
      const Exact h = core::dot<Exact, D>(w, v - z);
      if (m < h) m = h;
      if (m < -h) m = -h;
    }
    const Exact mid = core::dot<Exact, D>(w, z), c = m / 2;
    const auto lower = split<D>(r.x, w, mid - c), upper = split<D>(r.x, w, mid + c);
    // split returns {positive side, negative side} when both have area.
    const Linear<D> s1 = lower.size() == 2 ? lower[0] : r.x;
    const Linear<D> s2 = upper.size() == 2 ? upper[1] : r.x;
    return finish_case<D>({r.x, {}, {s1, s2}, p.value},
                          "X = " + r.recipe +
                              "; S = X ∩ {h >= -c}, X ∩ {h <= c} for h = " + text<D>(w) + "·(x - " +
                              text<D>(z) + "), c = " + text(c) + "; P: " + p.recipe);
  });
}

template <int D>
Complex<D> linear_set_complex(const Linear<D>& a) {
  PointSet<D> pts;
  PointIndex<D> idx;
  std::vector<Cell> cells;
  for (const auto& c : a.cells)
    for (const auto& simplex : core::triangulate<Exact, D>(c)) {
      Cell cell;
      for (const auto& p : simplex) {
        const auto [it, inserted] = idx.emplace(p, VertexId(pts.size()));
        if (inserted) pts.push_back(p);
        cell.push_back(it->second);
      }
      cells.push_back(cell);
    }
  return complex_from_cells<D>(pts, cells, false);
}

template <int D>
std::string linear_sets_record(const std::string& lemma, const std::string& recipe,
                               const std::vector<std::pair<std::string, Linear<D>>>& parts) {
  std::vector<std::pair<std::string, Complex<D>>> complexes;
  for (const auto& [name, a] : parts) complexes.emplace_back(name, linear_set_complex<D>(a));
  return complexes_record<D>(lemma, recipe, complexes);
}

template <int D>
std::string linear_sets_picture(const std::vector<Linear<D>>& parts) {
  return complex_picture<D>(linear_set_complex<D>(core::union_of<Exact, D>(parts)));
}

#define SYMMESH_INSTANTIATE_LINEAR_GENERATORS(D)                                                   \
  template std::string cell_text<D>(const LinearCell<D>&);                                         \
  template std::string linear_text<D>(const Linear<D>&);                                           \
  template rc::Gen<Described<LinearPair<D>>> linear_manifold_pair<D>();                            \
  template rc::Gen<Described<LinearPair<D>>> figure_a7_pair<D>();                                  \
  template rc::Gen<Described<LinearPair<D>>> nonconforming_representation_pair<D>();               \
  template rc::Gen<Described<PartitionCase<D>>> manifold_partitions<D>();                          \
  template rc::Gen<Described<PartitionCase<D>>> covering_and_partition<D>();                       \
  template Complex<D> linear_set_complex<D>(const Linear<D>&);                                     \
  template std::string linear_sets_record<D>(                                                      \
      const std::string&, const std::string&,                                                      \
      const std::vector<std::pair<std::string, Linear<D>>>&);                                      \
  template std::string linear_sets_picture<D>(const std::vector<Linear<D>>&);

SYMMESH_INSTANTIATE_LINEAR_GENERATORS(2)
SYMMESH_INSTANTIATE_LINEAR_GENERATORS(3)

} // namespace symmesh::proofs::gen
