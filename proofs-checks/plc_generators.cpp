// RapidCheck generators of PLCs and their triangulations (see plc_generators.h). CGAL is kept in
// this translation unit.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wrestrict"

#include "proofs-checks/plc_generators.h"

#include "proofs-checks/generator_support.h"

#include "symmesh/core/constrained_delaunay.h"
#include "symmesh/core/edge_protected.h"
#include "symmesh/core/templated_structure.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Regular_triangulation_3.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <type_traits>

namespace symmesh::proofs::gen {

using core::Simplex;
using core::VertexId;
// Shared with the other generators (generator_support.h).
using detail::chance;
using detail::dedupe;
using detail::full_dimensional;
using detail::grid_value;
using detail::K;
using detail::pick;
using detail::points_text;
using detail::rational;

namespace {

/// n grid points in [0, hi]^D (halves one time in four), full-dimensional.
template <int D>
PointSet<D> grid_points(int n, int hi) {
  PointSet<D> pts;
  for (int k = 0; k < n; ++k) {
    Point<D> p;
    for (int d = 0; d < D; ++d) p[d] = grid_value(0, hi);
    pts.push_back(p);
  }
  pts = dedupe<D>(pts);
  if (!full_dimensional<D>(pts)) {
    for (int k = 0; k <= D; ++k) {
      Point<D> p = core::zero_point<Exact, D>();
      if (k > 0) p[k - 1] = hi;
      pts.push_back(p);
    }
    pts = dedupe<D>(pts);
  }
  return pts;
}

using Cell = std::vector<VertexId>;

/// The multi-region mesh of the given cells over `pts`, keeping only used points.
template <int D>
MultiRegion<D> make_multi(const PointSet<D>& pts, const std::vector<std::pair<Cell, int>>& cells) {
  MultiRegion<D> m;
  const VertexId none = VertexId(-1);
  std::vector<VertexId> to(pts.size(), none);
  for (const auto& [cell, r] : cells) {
    std::vector<VertexId> ids;
    for (VertexId v : cell) {
      if (to[v] == none) {
        to[v] = VertexId(m.mesh.points.size());
        m.mesh.points.push_back(pts[v]);
      }
      ids.push_back(to[v]);
    }
    const Simplex s = Simplex::from_range(ids.data(), ids.data() + ids.size());
    m.cell_region[s] = r;
    for (const auto& f : core::faces(s)) m.mesh.elements.push_back(f);
  }
  m.mesh.normalize();
  return m;
}

template <int D>
using PointIndex = std::map<Point<D>, VertexId, core::PointLess<Exact, D>>;

// ----- CGAL ----------------------------------------------------------------------------------

using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_intersections_tag>;
using Dt2 = CGAL::Delaunay_triangulation_2<K>;
using Dt3 = CGAL::Delaunay_triangulation_3<K>;
using Rt3 = CGAL::Regular_triangulation_3<K>;

K::Point_2 cgal(const Point<2>& p) {
  return K::Point_2(p[0], p[1]);
}
K::Point_3 cgal(const Point<3>& p) {
  return K::Point_3(p[0], p[1], p[2]);
}
Point<2> back(const K::Point_2& p) {
  Point<2> q;
  q[0] = p.x();
  q[1] = p.y();
  return q;
}
Point<3> back(const K::Point_3& p) {
  Point<3> q;
  q[0] = p.x();
  q[1] = p.y();
  q[2] = p.z();
  return q;
}

/// Cells of CGAL's exact Delaunay triangulation of distinct full-dimensional points.
template <int D>
std::vector<Cell> delaunay_cells(const PointSet<D>& pts) {
  PointIndex<D> idx;
  for (std::size_t i = 0; i < pts.size(); ++i) idx.emplace(pts[i], VertexId(i));
  std::vector<Cell> cells;
  if constexpr (D == 2) {
    Dt2 dt;
    for (const auto& p : pts) dt.insert(cgal(p));
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      cells.push_back({idx.at(back(f->vertex(0)->point())), idx.at(back(f->vertex(1)->point())),
                       idx.at(back(f->vertex(2)->point()))});
  } else {
    Dt3 dt;
    for (const auto& p : pts) dt.insert(cgal(p));
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
      Cell cell;
      for (int k = 0; k < 4; ++k) cell.push_back(idx.at(back(c->vertex(k)->point())));
      cells.push_back(cell);
    }
  }
  return cells;
}

std::vector<Cell> regular_cells_3(const PointSet<3>& pts, const std::vector<int>& w) {
  PointIndex<3> idx;
  for (std::size_t i = 0; i < pts.size(); ++i) idx.emplace(pts[i], VertexId(i));
  Rt3 rt;
  for (std::size_t i = 0; i < pts.size(); ++i)
    rt.insert(Rt3::Weighted_point(cgal(pts[i]), Exact(w[i])));
  std::vector<Cell> cells;
  for (auto c = rt.finite_cells_begin(); c != rt.finite_cells_end(); ++c) {
    Cell cell;
    for (int k = 0; k < 4; ++k) cell.push_back(idx.at(back(c->vertex(k)->point().point())));
    cells.push_back(cell);
  }
  return cells;
}

/// The Delaunay tetrahedralization of pts is unique: no two adjacent cells are cospherical and
/// no hull facet has a fourth coplanar point.
bool delaunay_unique_3(const PointSet<3>& pts) {
  if (!full_dimensional<3>(pts)) return false;
  Dt3 dt;
  for (const auto& p : pts) dt.insert(cgal(p));
  if (dt.number_of_vertices() != pts.size()) return false;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    for (int i = 0; i < 4; ++i) {
      const auto n = c->neighbor(i);
      if (dt.is_infinite(n)) {
        int coplanar = 0;
        for (const auto& p : pts)
          if (CGAL::orientation(c->vertex((i + 1) % 4)->point(), c->vertex((i + 2) % 4)->point(),
                                c->vertex((i + 3) % 4)->point(), cgal(p)) == CGAL::COPLANAR)
            ++coplanar;
        if (coplanar > 3) return false;
        continue;
      }
      const auto q = n->vertex(n->index(c))->point();
      if (CGAL::side_of_bounded_sphere(c->vertex(0)->point(), c->vertex(1)->point(),
                                       c->vertex(2)->point(), c->vertex(3)->point(),
                                       q) == CGAL::ON_BOUNDARY)
        return false;
    }
  return true;
}

// ----- 2D: CDT of random points and segments -----------------------------------------------

/// Random segments between the points: no point in a segment's relative interior, no two
/// segments crossing, overlapping or meeting in a T.
std::vector<std::pair<VertexId, VertexId>> random_segments(const PointSet<2>& pts, int tries) {
  std::vector<std::pair<VertexId, VertexId>> out;
  auto inside = [](const Point<2>& a, const Point<2>& b, const Point<2>& x) {
    return x != a && x != b && core::point_on_segment<Exact, 2>(a, b, x);
  };
  for (int t = 0; t < tries; ++t) {
    const VertexId i = VertexId(pick(0, int(pts.size()) - 1));
    const VertexId j = VertexId(pick(0, int(pts.size()) - 1));
    if (i == j) continue;
    bool ok = true;
    for (const auto& x : pts) ok = ok && !inside(pts[i], pts[j], x);
    for (const auto& [a, b] : out) {
      if (!ok) break;
      if ((a == i && b == j) || (a == j && b == i))
        ok = false;
      else if (core::relative_interiors_meet<Exact, 2>({pts[i], pts[j]}, {pts[a], pts[b]}))
        ok = false;
    }
    if (ok) out.push_back({i, j});
  }
  return out;
}

struct Cdt2Case {
  PlcCase<2> c;
  std::set<Simplex> constrained; ///< the 1-cells of P as edges of M
};

Cdt2Case random_cdt_case(int size) {
  const auto pts = grid_points<2>(pick(4, 6 + size / 12), 6);
  const auto segs = random_segments(pts, pick(0, int(pts.size())));
  Cdt cdt;
  PointIndex<2> idx;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    idx.emplace(pts[i], VertexId(i));
    cdt.insert(cgal(pts[i]));
  }
  for (const auto& [a, b] : segs) cdt.insert_constraint(cgal(pts[a]), cgal(pts[b]));
  std::map<Cdt::Face_handle, int> face_id;
  std::vector<Cdt::Face_handle> faces;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    face_id[f] = int(faces.size());
    faces.push_back(f);
  }
  std::vector<int> comp(faces.size(), -1);
  int ncomp = 0;
  for (std::size_t s = 0; s < faces.size(); ++s) {
    if (comp[s] >= 0) continue;
    std::vector<std::size_t> stack{s};
    comp[s] = ncomp;
    while (!stack.empty()) {
      const auto f = faces[stack.back()];
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const auto n = f->neighbor(i);
        if (cdt.is_infinite(n) || cdt.is_constrained(std::make_pair(f, i))) continue;
        const int k = face_id.at(n);
        if (comp[k] < 0) {
          comp[k] = ncomp;
          stack.push_back(std::size_t(k));
        }
      }
    }
    ++ncomp;
  }
  std::vector<int> region(static_cast<std::size_t>(ncomp));
  for (auto& r : region) r = pick(1, 3);
  const int hole = ncomp >= 2 && chance(30) ? pick(0, ncomp - 1) : -1;
  std::vector<std::pair<Cell, int>> cells;
  for (std::size_t k = 0; k < faces.size(); ++k) {
    if (comp[k] == hole) continue;
    Cell cell;
    for (int i = 0; i < 3; ++i) cell.push_back(idx.at(back(faces[k]->vertex(i)->point())));
    cells.push_back({cell, region[std::size_t(comp[k])]});
  }
  Cdt2Case out;
  out.c.mesh = make_multi<2>(pts, cells);
  out.c.plc = core::plc_of_multi_region_mesh(out.c.mesh);
  PointIndex<2> midx;
  for (std::size_t i = 0; i < out.c.mesh.mesh.points.size(); ++i)
    midx.emplace(out.c.mesh.mesh.points[i], VertexId(i));
  for (std::size_t c : out.c.plc.cells_of_dimension(1))
    out.constrained.insert(out.c.plc.cells[c].pieces[0]);
  int dangling = 0;
  for (const auto& [a, b] : segs) { // segments inside a region stay as dangling 1-cells
    const auto ia = midx.find(pts[a]), ib = midx.find(pts[b]);
    if (ia == midx.end() || ib == midx.end()) continue;
    const Simplex e{ia->second, ib->second};
    if (!out.c.mesh.mesh.contains(e) || out.constrained.count(e)) continue;
    out.c.plc.cells.push_back(core::PlcCell{1, {e}, 0});
    out.constrained.insert(e);
    ++dangling;
  }
  out.c.recipe = "CDT of " + points_text<2>(pts) + " with " + std::to_string(segs.size()) +
                 " segments, " + std::to_string(ncomp) + " components" +
                 (hole >= 0 ? ", one cut out" : "") + ", " + std::to_string(dangling) +
                 " dangling segments";
  return out;
}

/// Flips up to k unconstrained edges whose two triangles form a strictly convex quadrilateral.
int random_flips(MultiRegion<2>& m, const std::set<Simplex>& constrained, int k) {
  int done = 0;
  for (int t = 0; t < k; ++t) {
    std::map<Simplex, std::vector<Simplex>> around;
    for (const auto& [c, r] : m.cell_region)
      for (const auto& e : core::facets(c)) around[e].push_back(c);
    std::vector<std::pair<Simplex, std::vector<Simplex>>> flippable;
    for (const auto& [e, cs] : around) {
      if (cs.size() != 2 || constrained.count(e)) continue;
      VertexId c = 0, d = 0;
      for (VertexId v : cs[0])
        if (!e.has_vertex(v)) c = v;
      for (VertexId v : cs[1])
        if (!e.has_vertex(v)) d = v;
      const auto& P = m.mesh.points;
      const int s1 = core::detail::orientation_sign<Exact>(P[c], P[d], P[e.v[0]]);
      const int s2 = core::detail::orientation_sign<Exact>(P[c], P[d], P[e.v[1]]);
      if (s1 * s2 < 0) flippable.push_back({e, {Simplex{e.v[0], c, d}, Simplex{e.v[1], c, d}}});
    }
    if (flippable.empty()) break;
    const auto& [e, repl] = flippable[std::size_t(pick(0, int(flippable.size()) - 1))];
    const auto old = around.at(e);
    const int r = m.cell_region.at(old[0]);
    for (const auto& c : old) m.cell_region.erase(c);
    for (const auto& c : repl) m.cell_region[c] = r;
    ++done;
  }
  m.mesh.elements.clear();
  for (const auto& [c, r] : m.cell_region)
    for (const auto& f : core::faces(c)) m.mesh.elements.push_back(f);
  m.mesh.normalize();
  return done;
}

// ----- 3D: PLCs induced by tetrahedralizations ----------------------------------------------

/// Region ids of cells: by the side of a random plane through the points' box, at random, or one.
template <int D>
std::vector<int> random_regions(const PointSet<D>& pts, const std::vector<Cell>& cells,
                                std::string* how) {
  std::vector<int> out(cells.size(), 1);
  const int mode = pick(0, 2);
  if (mode == 0) {
    *how = "one region";
    return out;
  }
  if (mode == 1) {
    for (auto& r : out) r = pick(1, 2);
    *how = "random regions";
    return out;
  }
  Point<D> n;
  for (int d = 0; d < D; ++d) n[d] = pick(-2, 2);
  n[0] = n[0] == 0 ? Exact(1) : n[0];
  const Exact off = pick(0, 6);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    Point<D> c = core::zero_point<Exact, D>();
    for (VertexId v : cells[k]) c = c + pts[v];
    out[k] = core::dot<Exact, D>(n, c) * Exact(1) / Exact(D + 1) < off ? 1 : 2;
  }
  *how = "regions by the plane " + text<D>(n) + "·x = " + text(off);
  return out;
}

PlcCase<3> random_tetrahedral_case(const PointSet<3>& pts, bool delaunay, bool allow_removal) {
  std::vector<Cell> cells;
  std::string how;
  if (delaunay) {
    cells = delaunay_cells<3>(pts);
    how = "delaunay";
  } else {
    std::vector<int> w(pts.size());
    for (auto& x : w) x = pick(0, 6);
    cells = regular_cells_3(pts, w);
    how = "regular(w=";
    for (int x : w) how += std::to_string(x);
    how += ")";
  }
  std::string rhow;
  const auto regions = random_regions<3>(pts, cells, &rhow);
  std::vector<std::pair<Cell, int>> rc;
  for (std::size_t k = 0; k < cells.size(); ++k) rc.push_back({cells[k], regions[k]});
  PlcCase<3> out;
  int removed = 0;
  if (allow_removal && rc.size() > 2 && chance(30)) {
    auto fewer = rc;
    const int k = pick(1, std::min(2, int(rc.size()) - 1));
    for (int i = 0; i < k; ++i) fewer.erase(fewer.begin() + pick(0, int(fewer.size()) - 1));
    out.mesh = make_multi<3>(pts, fewer);
    out.plc = core::plc_of_multi_region_mesh(out.mesh);
    if (out.mesh.is_valid() && out.plc.is_multi_region()) removed = k;
  }
  if (removed == 0) {
    out.mesh = make_multi<3>(pts, rc);
    out.plc = core::plc_of_multi_region_mesh(out.mesh);
  }
  out.recipe = how + " of " + points_text<3>(pts) + ", " + rhow +
               (removed ? ", " + std::to_string(removed) + " cells removed" : "");
  return out;
}

/// Lemma 2.5's V-shape (two flat simplices touching in a vertex) with P = its boundary.
template <int D>
PlcCase<D> v_shape_case() {
  const auto s = *flat_simplex_v_shape<D>();
  const auto mesh = core::apply_template(s.x).at.mesh;
  PlcCase<D> out;
  out.mesh.mesh = mesh;
  for (const auto& c : mesh.cells()) out.mesh.cell_region[c] = 1;
  out.plc = core::plc_of_multi_region_mesh(out.mesh);
  out.recipe = "Lemma 2.5's V-shape, P = its boundary: " + s.recipe;
  return out;
}

template <int D>
Point<D> integer_point(int lo, int hi) {
  Point<D> p;
  for (int d = 0; d < D; ++d) p[d] = pick(lo, hi);
  return p;
}

/// A signed permutation of the coordinates followed by a translation (exact, rigid).
template <int D>
PointSet<D> moved(const PointSet<D>& pts, std::string* how) {
  std::vector<int> perm(D);
  for (int d = 0; d < D; ++d) perm[d] = d;
  for (int d = D - 1; d > 0; --d) std::swap(perm[d], perm[pick(0, d)]);
  std::vector<int> sign(D);
  for (auto& s : sign) s = chance(50) ? -1 : 1;
  const auto t = integer_point<D>(-3, 3);
  PointSet<D> out;
  for (const auto& p : pts) {
    Point<D> q;
    for (int d = 0; d < D; ++d) q[d] = Exact(sign[d]) * p[perm[d]] + t[d];
    out.push_back(q);
  }
  *how = "moved by " + text<D>(t);
  return out;
}

/// Edge-protected 3D PLCs in general position (see plc_for_cdt).
bool per_region_delaunay_unique(const Plc<3>& p) {
  const auto g = p.geometry();
  for (int r : g.region_ids()) {
    PointSet<3> v;
    for (const auto& x : p.vertex_points())
      if (g.xi(x).count(r)) v.push_back(x);
    if (!delaunay_unique_3(v)) return false;
  }
  return true;
}

std::optional<Described<Plc<3>>> waist_plc() {
  // a triangle W on z = 0, points above and below, regions conv(W ∪ A) and conv(W ∪ B)
  PointSet<3> w, a, b;
  for (int k = 0; k < 3; ++k) {
    Point<3> p = integer_point<3>(-9, 9);
    p[2] = 0;
    w.push_back(p);
  }
  const int na = pick(1, 3), nb = pick(1, 3);
  for (int k = 0; k < na; ++k) {
    Point<3> p = integer_point<3>(-9, 9);
    p[2] = pick(1, 9);
    a.push_back(p);
  }
  for (int k = 0; k < nb; ++k) {
    Point<3> p = integer_point<3>(-9, 9);
    p[2] = -pick(1, 9);
    b.push_back(p);
  }
  PointSet<3> up = w, down = w;
  up.insert(up.end(), a.begin(), a.end());
  down.insert(down.end(), b.begin(), b.end());
  up = dedupe<3>(up);
  down = dedupe<3>(down);
  if (!delaunay_unique_3(up) || !delaunay_unique_3(down)) return std::nullopt;
  PointSet<3> all = w;
  all.insert(all.end(), a.begin(), a.end());
  all.insert(all.end(), b.begin(), b.end());
  all = dedupe<3>(all);
  PointIndex<3> idx;
  for (std::size_t i = 0; i < all.size(); ++i) idx.emplace(all[i], VertexId(i));
  std::vector<std::pair<Cell, int>> cells;
  for (const auto& [pts, r] : {std::make_pair(up, 1), std::make_pair(down, 2)})
    for (const auto& c : delaunay_cells<3>(pts)) {
      Cell cell;
      for (VertexId v : c) cell.push_back(idx.at(pts[v]));
      cells.push_back({cell, r});
    }
  const auto m = make_multi<3>(all, cells);
  if (!m.is_valid()) return std::nullopt;
  return Described<Plc<3>>{core::plc_of_multi_region_mesh(m),
                           "two convex pieces glued along the triangle " + points_text<3>(w) +
                               ", above " + points_text<3>(a) + ", below " + points_text<3>(b)};
}

} // namespace

// ----- public generators -----------------------------------------------------------------------

template <int D>
rc::Gen<PlcCase<D>> plc_with_triangulation() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      if (chance(16)) return v_shape_case<D>();
      if constexpr (D == 2) {
        auto c = random_cdt_case(size);
        if (chance(40)) {
          const int k = random_flips(c.c.mesh, c.constrained, pick(1, 3));
          c.c.recipe += ", then " + std::to_string(k) + " flips";
        }
        return c.c;
      } else {
        return random_tetrahedral_case(grid_points<3>(pick(5, 6 + size / 20), 4), chance(50), true);
      }
    });
  });
}

template <int D>
rc::Gen<PlcCase<D>> plc_with_steiner_triangulation() {
  return rc::gen::exec([] {
    const auto pts = grid_points<D>(pick(D + 1, D + 4), 4);
    const auto cells = delaunay_cells<D>(pts);
    std::vector<std::pair<Cell, int>> one;
    for (const auto& c : cells) one.push_back({c, 1});
    PlcCase<D> out;
    out.plc = core::plc_of_multi_region_mesh(make_multi<D>(pts, one));
    const auto& cell = cells[std::size_t(pick(0, int(cells.size()) - 1))];
    Point<D> q = core::zero_point<Exact, D>();
    int total = 0;
    for (VertexId v : cell) {
      const int w = pick(1, 3);
      q = q + core::scaled<Exact, D>(pts[v], Exact(w));
      total += w;
    }
    q = core::scaled<Exact, D>(q, Exact(1) / Exact(total));
    auto with = pts;
    with.push_back(q);
    std::vector<std::pair<Cell, int>> mc;
    for (const auto& c : delaunay_cells<D>(with)) mc.push_back({c, 1});
    out.mesh = make_multi<D>(with, mc);
    out.recipe = "P = boundary of the Delaunay triangulation of " + points_text<D>(pts) +
                 "; M = Delaunay triangulation with the Steiner point " + text<D>(q);
    return out;
  });
}

template <int D>
rc::Gen<PlcCase<D>> flat_pair_across_interface() {
  return rc::gen::exec([] {
    const int L = pick(2, 4);
    const Exact h1 = rational(1, pick(3, 6)), h2 = rational(1, pick(3, 6));
    PointSet<D> pts;
    if constexpr (D == 2) {
      const Exact foot = rational(pick(-2 * L + 1, 2 * L - 1), 2);
      pts = {Point<2>{{Exact(-L), Exact(0)}}, Point<2>{{Exact(L), Exact(0)}}, Point<2>{{foot, h1}},
             Point<2>{{foot, -h2}}};
    } else {
      const Exact f = rational(L, 3);
      pts = {Point<3>{{Exact(0), Exact(0), Exact(0)}}, Point<3>{{Exact(L), Exact(0), Exact(0)}},
             Point<3>{{Exact(0), Exact(L), Exact(0)}}, Point<3>{{f, f, h1}}, Point<3>{{f, f, -h2}}};
    }
    std::string how;
    pts = moved<D>(pts, &how);
    Cell base;
    for (int k = 0; k < D; ++k) base.push_back(VertexId(k));
    Cell c1 = base, c2 = base;
    c1.push_back(VertexId(D));
    c2.push_back(VertexId(D + 1));
    PlcCase<D> out;
    out.mesh = make_multi<D>(pts, {{c1, 1}, {c2, 2}});
    out.plc = core::plc_of_multi_region_mesh(out.mesh);
    out.recipe = "flat pair across an interface: L=" + std::to_string(L) + " h=" + text(h1) + ", " +
                 text(h2) + ", " + how;
    return out;
  });
}

template <int D>
rc::Gen<Described<Plc<D>>> plc_for_cdt() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      if constexpr (D == 2) {
        auto c = random_cdt_case(size);
        return Described<Plc<2>>{c.c.plc, c.c.recipe};
      } else {
        for (int attempt = 0; attempt < 60; ++attempt) {
          std::optional<Described<Plc<3>>> cand;
          if (chance(50)) {
            cand = waist_plc();
          } else {
            PointSet<3> pts;
            const int n = pick(5, 6 + size / 25);
            for (int k = 0; k < n; ++k) pts.push_back(integer_point<3>(0, 30));
            pts = dedupe<3>(pts);
            if (!full_dimensional<3>(pts)) continue;
            auto c = random_tetrahedral_case(pts, true, true);
            cand = Described<Plc<3>>{c.plc, c.recipe};
          }
          if (!cand || !cand->value.is_multi_region()) continue;
          if (!core::is_edge_protected(cand->value)) continue;
          if (!per_region_delaunay_unique(cand->value)) continue;
          return *cand;
        }
        // fallback: one tetrahedron (edge-protected, general position)
        const PointSet<3> t{
            Point<3>{{Exact(0), Exact(0), Exact(0)}}, Point<3>{{Exact(3), Exact(0), Exact(0)}},
            Point<3>{{Exact(0), Exact(4), Exact(0)}}, Point<3>{{Exact(1), Exact(1), Exact(5)}}};
        return Described<Plc<3>>{
            core::plc_of_multi_region_mesh(make_multi<3>(t, {{{0, 1, 2, 3}, 1}})),
            "one tetrahedron (fallback)"};
      }
    });
  });
}

template <int D>
MultiRegion<D> constrained_delaunay_construction(const Plc<D>& p) {
  const auto g = p.geometry();
  PointIndex<D> idx;
  PointSet<D> pts;
  auto id = [&](const Point<D>& x) {
    auto [it, inserted] = idx.emplace(x, VertexId(pts.size()));
    if (inserted) pts.push_back(x);
    return it->second;
  };
  std::vector<std::pair<Cell, int>> cells;
  auto keep = [&](const PointSet<D>& corners, int only_region) {
    Point<D> c = core::zero_point<Exact, D>();
    for (const auto& x : corners) c = c + x;
    c = core::scaled<Exact, D>(c, Exact(1) / Exact(D + 1));
    const auto here = g.xi(c);
    if (here.empty() || (only_region > 0 && !here.count(only_region))) return;
    Cell cell;
    for (const auto& x : corners) cell.push_back(id(x));
    cells.push_back({cell, only_region > 0 ? only_region : *here.begin()});
  };
  if constexpr (D == 2) {
    Cdt cdt;
    for (const auto& x : p.vertex_points()) cdt.insert(cgal(x));
    for (std::size_t c : p.cells_of_dimension(1)) {
      const auto [a, b] = core::segment_ends(p, c);
      cdt.insert_constraint(cgal(p.carrier.points[a]), cgal(p.carrier.points[b]));
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      keep({back(f->vertex(0)->point()), back(f->vertex(1)->point()), back(f->vertex(2)->point())},
           0);
  } else {
    for (int r : g.region_ids()) {
      Dt3 dt;
      for (const auto& x : p.vertex_points())
        if (g.xi(x).count(r)) dt.insert(cgal(x));
      for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
        PointSet<3> corners;
        for (int k = 0; k < 4; ++k) corners.push_back(back(c->vertex(k)->point()));
        keep(corners, r);
      }
    }
  }
  return make_multi<D>(pts, cells);
}

template <int D>
rc::Gen<Described<Plc<D>>> plc_without_cdt() {
  return rc::gen::exec([] {
    if constexpr (D == 2) {
      // a convex quadrilateral a, b, c, d (counter-clockwise) with both diagonals
      const int s = pick(2, 5);
      PointSet<2> q{Point<2>{{Exact(0), Exact(-pick(1, 3))}}, Point<2>{{Exact(s), Exact(0)}},
                    Point<2>{{Exact(0), Exact(pick(1, 3))}},
                    Point<2>{{Exact(-pick(1, 3)), Exact(0)}}};
      std::string how;
      q = moved<2>(q, &how);
      // the diagonals cross at x = a + t (c − a), found exactly
      const auto& a = q[0];
      const auto& b = q[1];
      const auto& c = q[2];
      const auto& d = q[3];
      const Point<2> u = c - a, w = d - b, e = b - a;
      const Exact den = u[0] * w[1] - u[1] * w[0];
      const Exact t = (e[0] * w[1] - e[1] * w[0]) / den;
      const Point<2> x = a + core::scaled<Exact, 2>(u, t);
      Plc<2> p;
      p.carrier.points = {a, b, c, d, x};
      const VertexId X = 4;
      std::vector<Simplex> tris{Simplex{0, 1, X}, Simplex{1, 2, X}, Simplex{2, 3, X},
                                Simplex{3, 0, X}};
      for (const auto& tr : tris)
        for (const auto& f : core::faces(tr)) p.carrier.elements.push_back(f);
      p.carrier.normalize();
      p.vertices = {0, 1, 2, 3};
      p.cells.push_back(core::PlcCell{2, tris, 1});
      for (VertexId i = 0; i < 4; ++i)
        p.cells.push_back(core::PlcCell{1, {Simplex{i, (i + 1) % 4}}, 0});
      p.cells.push_back(core::PlcCell{1, {Simplex{0, X}, Simplex{2, X}}, 0});
      p.cells.push_back(core::PlcCell{1, {Simplex{1, X}, Simplex{3, X}}, 0});
      return Described<Plc<2>>{p, "convex quadrilateral " + points_text<2>(q) +
                                      " with both diagonals (" + how + ")"};
    } else {
      // Schönhardt: bottom triangle, top = bottom turned by a Pythagorean angle and lifted; each
      // side quadrilateral b_i b_{i+1} t_{i+1} t_i split along b_i t_{i+1} (the reflex diagonal)
      const std::vector<std::pair<int, int>> turns{{4, 3}, {12, 5}, {15, 8}, {24, 7}};
      const auto [cn, sn] = turns[std::size_t(pick(0, int(turns.size()) - 1))];
      const int hyp = cn == 4 ? 5 : (cn == 12 ? 13 : (cn == 15 ? 17 : 25));
      const Exact co = rational(cn, hyp), si = rational(sn, hyp);
      const int r = pick(2, 4);
      const Exact h = pick(2, 6);
      PointSet<3> v;
      const std::vector<std::pair<int, int>> base{{2 * r, 0}, {-r, 2 * r}, {-r, -2 * r}};
      for (const auto& [x, y] : base) v.push_back(Point<3>{{Exact(x), Exact(y), Exact(0)}});
      for (const auto& [x, y] : base) v.push_back(Point<3>{{co * x - si * y, si * x + co * y, h}});
      std::string how;
      v = moved<3>(v, &how);
      std::vector<Simplex> tris{Simplex{0, 1, 2}, Simplex{3, 4, 5}};
      for (VertexId i = 0; i < 3; ++i) {
        const VertexId j = (i + 1) % 3;
        tris.push_back(Simplex{i, j, VertexId(3 + j)});
        tris.push_back(Simplex{i, VertexId(3 + j), VertexId(3 + i)});
      }
      Point<3> c = core::zero_point<Exact, 3>();
      for (const auto& x : v) c = c + x;
      c = core::scaled<Exact, 3>(c, Exact(1) / Exact(6));
      Plc<3> p;
      p.carrier.points = v;
      p.carrier.points.push_back(c);
      const VertexId C = 6;
      std::vector<Simplex> tets;
      for (const auto& t : tris) tets.push_back(Simplex{t.v[0], t.v[1], t.v[2], C});
      for (const auto& t : tets)
        for (const auto& f : core::faces(t)) p.carrier.elements.push_back(f);
      p.carrier.normalize();
      p.vertices = {0, 1, 2, 3, 4, 5};
      p.cells.push_back(core::PlcCell{3, tets, 1});
      std::set<Simplex> edges;
      for (const auto& t : tris) {
        p.cells.push_back(core::PlcCell{2, {t}, 0});
        for (const auto& e : core::facets(t)) edges.insert(e);
      }
      for (const auto& e : edges) p.cells.push_back(core::PlcCell{1, {e}, 0});
      return Described<Plc<3>>{p, "Schönhardt prism, turn (" + text(co) + ", " + text(si) +
                                      "), r=" + std::to_string(r) + " h=" + text(h) + ", " + how};
    }
  });
}

template <int D>
bool triangulation_of_vertices_exists(const Plc<D>& p) {
  const auto verts = p.vertex_points();
  const auto dom = p.domain();
  auto volume = [](const PointSet<D>& s) {
    core::Matrix<Exact> m;
    for (int i = 1; i <= D; ++i) {
      std::vector<Exact> row(D);
      for (int d = 0; d < D; ++d) row[d] = s[i][d] - s[0][d];
      m.push_back(row);
    }
    const Exact det = core::determinant(m);
    return det < 0 ? -det : det;
  };
  Exact target = 0;
  for (const auto& c : dom.cells()) target += volume(dom.coords(c));
  // s ⊆ us(P): s respects P iff it respects the lower-dimensional elements (the argument of
  // core::mesh_respects_plc)
  std::vector<core::ElementComplex<Exact, D>> lower;
  for (VertexId v : p.vertices) {
    core::ElementComplex<Exact, D> k;
    k.points = p.carrier.points;
    k.elements = {Simplex{v}};
    lower.push_back(k);
  }
  for (std::size_t c = 0; c < p.cells.size(); ++c)
    if (p.cells[c].dimension < D) lower.push_back(p.cell_complex(c));
  auto respects_lower_dimensional = [&](const PointSet<D>& s) {
    for (const auto& k : lower)
      if (!core::respects_plc_element<Exact, D>(s, k)) return false;
    return true;
  };
  std::vector<PointSet<D>> cand;
  std::vector<Exact> vol;
  const int n = int(verts.size());
  std::vector<int> idx(D + 1);
  for (int i = 0; i <= D; ++i) idx[i] = i;
  while (n >= D + 1) {
    PointSet<D> s;
    for (int i : idx) s.push_back(verts[std::size_t(i)]);
    if (core::affinely_independent<Exact, D>(s) && core::cell_covered_by<Exact, D>(s, dom) &&
        respects_lower_dimensional(s)) {
      cand.push_back(s);
      vol.push_back(volume(s));
    }
    int k = D;
    while (k >= 0 && idx[k] == n - D - 1 + k) --k;
    if (k < 0) break;
    ++idx[k];
    for (int j = k + 1; j <= D; ++j) idx[j] = idx[j - 1] + 1;
  }
  if (cand.size() > 20) throw std::invalid_argument("triangulation_of_vertices_exists: too big");
  std::vector<std::size_t> chosen;
  std::function<bool(std::size_t, Exact)> search = [&](std::size_t from, Exact sum) {
    if (sum == target) return true;
    for (std::size_t i = from; i < cand.size(); ++i) {
      if (target < sum + vol[i]) continue;
      bool disjoint = true;
      for (std::size_t j : chosen)
        disjoint = disjoint && !core::relative_interiors_meet<Exact, D>(cand[i], cand[j]);
      if (!disjoint) continue;
      chosen.push_back(i);
      if (search(i + 1, sum + vol[i])) return true;
      chosen.pop_back();
    }
    return false;
  };
  return search(0, Exact(0));
}

template <int D>
std::string plc_case_record(const char* lemma, const PlcCase<D>& c) {
  return complexes_record<D>(lemma, c.recipe, {{"P carrier", c.plc.carrier}, {"M", c.mesh.mesh}});
}

#define SYMMESH_INSTANTIATE_PLC_GENERATORS(D)                                                      \
  template rc::Gen<PlcCase<D>> plc_with_triangulation<D>();                                        \
  template rc::Gen<PlcCase<D>> plc_with_steiner_triangulation<D>();                                \
  template rc::Gen<PlcCase<D>> flat_pair_across_interface<D>();                                    \
  template rc::Gen<Described<Plc<D>>> plc_for_cdt<D>();                                            \
  template MultiRegion<D> constrained_delaunay_construction<D>(const Plc<D>&);                     \
  template rc::Gen<Described<Plc<D>>> plc_without_cdt<D>();                                        \
  template bool triangulation_of_vertices_exists<D>(const Plc<D>&);                                \
  template std::string plc_case_record<D>(const char*, const PlcCase<D>&);

SYMMESH_INSTANTIATE_PLC_GENERATORS(2)
SYMMESH_INSTANTIATE_PLC_GENERATORS(3)

} // namespace symmesh::proofs::gen
