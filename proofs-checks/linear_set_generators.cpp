// RapidCheck generators of linear sets for the proofs-checks of Appendix A: manifold pairs
// (Lemma A.1), intersection-partition cases (Lemma A.3, Figure A.7), manifold partitions and
// coverings for refinement (Lemma A.4) (see generators.h).
#include "proofs-checks/generator_support.h"

namespace symmesh::proofs::gen {

using namespace detail;

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
