// Mirror insertion between facing boundary planes (acute creases, thin wedges) and boundary-facet
// insertion for Technique 5.8 in 3D — spec/adaptation.md#tmesh-adaptation (crease_mirroring_3d.h
// explains why mirroring ends the ping-pong encroachment that bisection does not).
#include "symmesh/adapt/crease_mirroring_3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

namespace symmesh::adapt::work {
namespace {
using Vec = std::array<double, 3>;
using Tri = std::array<IndexType, 3>;

Vec unit(const Vec& v) {
  const double l = std::sqrt(dot3(v, v));
  return l > 0 ? Vec{v[0] / l, v[1] / l, v[2] / l} : Vec{0, 0, 0};
}
Vec minus(const Vec& u, const Vec& v) {
  return {u[0] - v[0], u[1] - v[1], u[2] - v[2]};
}
Vec at(const double* q) {
  return {q[0], q[1], q[2]};
}

Tri tri(IndexType u, IndexType v, IndexType x) {
  Tri f{u, v, x};
  std::sort(f.begin(), f.end());
  return f;
}

/// The boundary triangulation of one template while points are inserted into it.
struct Surface {
  std::set<Tri> tris;
  std::map<std::pair<IndexType, IndexType>, std::vector<IndexType>> wings;
  bool changed = false;
  explicit Surface(const Work& w) {
    for (const auto& f : surface_of(w)) add(f);
  }
  void add(const Tri& f) {
    tris.insert(f);
    for (int k = 0; k < 3; ++k)
      wings[std::minmax(f[std::size_t(k)], f[std::size_t((k + 1) % 3)])].push_back(
          f[std::size_t((k + 2) % 3)]);
  }
  void erase(const Tri& f) {
    tris.erase(f);
    for (int k = 0; k < 3; ++k) {
      auto& list = wings[std::minmax(f[std::size_t(k)], f[std::size_t((k + 1) % 3)])];
      list.erase(std::find(list.begin(), list.end(), f[std::size_t((k + 2) % 3)]));
    }
  }
  bool has_edge(IndexType a, IndexType b) const {
    const auto it = wings.find(std::minmax(a, b));
    return it != wings.end() && !it->second.empty();
  }
};

/// Where a point goes: into triangle v (three vertices) or onto edge v[0] v[1] (v[2] = -1), at
/// barycentric coordinates lambda.
struct Site {
  std::size_t t = 0;
  std::array<IndexType, 3> v{-1, -1, -1};
  std::array<double, 3> lambda{};
  int size() const { return v[2] < 0 ? 2 : 3; }
  std::pair<std::size_t, Tri> key() const {
    Tri k = v;
    std::sort(k.begin(), k.begin() + size());
    return {t, k};
  }
};

/// The boundary triangle of `surface` in the plane of p (normal `normal`) that holds p, as a
/// site: inside it, or on one of its edges when p is within 1e-9 of it (barycentric); none when p
/// is in no such triangle or next to a vertex.
std::optional<Site> locate(const Work& w, const Surface& surface, std::size_t t, const Vec& p,
                           const Vec& normal) {
  std::optional<Site> best;
  Tri best_triangle{};
  double best_min = -1e-9;
  for (const auto& f : surface.tris) {
    const Vec u = at(w.p(f[0])), v = at(w.p(f[1])), x = at(w.p(f[2]));
    const Vec n = unit(cross3(minus(v, u), minus(x, u)));
    if (std::abs(dot3(n, normal)) < 1 - 1e-9) continue;
    const double scale =
        std::sqrt(std::max({dot3(minus(v, u), minus(v, u)), dot3(minus(x, u), minus(x, u)),
                            dot3(minus(p, u), minus(p, u))}));
    if (std::abs(dot3(minus(p, u), n)) > 1e-9 * scale) continue;
    const double area = dot3(cross3(minus(v, u), minus(x, u)), n);
    const double lu = dot3(cross3(minus(v, p), minus(x, p)), n) / area;
    const double lv = dot3(cross3(minus(x, p), minus(u, p)), n) / area;
    const std::array<double, 3> l{lu, lv, 1 - lu - lv};
    const double m = std::min({l[0], l[1], l[2]});
    if (m <= best_min) continue;
    best_min = m;
    best = Site{t, f, l};
    best_triangle = f;
  }
  if (!best) return best;
  int small = 0, which = -1;
  for (int k = 0; k < 3; ++k)
    if (best->lambda[std::size_t(k)] <= 1e-9) ++small, which = k;
  if (small >= 2) return std::nullopt;
  if (small == 1) {
    // On the edge opposite vertex `which`: the projection onto it.
    const IndexType a = best->v[std::size_t((which + 1) % 3)],
                    b = best->v[std::size_t((which + 2) % 3)];
    const Vec ab = minus(at(w.p(b)), at(w.p(a)));
    const double s = dot3(minus(p, at(w.p(a))), ab) / dot3(ab, ab);
    if (!(s > 1e-6 && s < 1 - 1e-6)) return std::nullopt;
    best->v = {a, b, -1};
    best->lambda = {1 - s, s, 0};
  }
  // A point next to a vertex of its triangle (within 1/50 of the triangle's longest edge) would
  // make an edge far shorter than its neighbours, which TetGen cannot always recover without a
  // Steiner point (it aborted on such a surface); the caller bisects instead.
  const auto& f = best->v;
  double longest = 0, nearest = 1e300;
  for (int k = 0; k < best->size(); ++k) {
    const Vec d = minus(p, at(w.p(f[std::size_t(k)])));
    nearest = std::min(nearest, dot3(d, d));
  }
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      const Vec d =
          minus(at(w.p(best_triangle[std::size_t(k)])), at(w.p(best_triangle[std::size_t(l)])));
      longest = std::max(longest, dot3(d, d));
    }
  if (nearest < longest / 2500) return std::nullopt;
  return best;
}

/// The point of site e in its template: its barycentric combination, with every coordinate that
/// its vertices share copied (an axis-parallel facet keeps the point on it exactly).
Vec site_point(const Work& w, const Site& e) {
  Vec q{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    bool shared = true;
    for (int k = 0; k < e.size(); ++k) {
      q[std::size_t(i)] += e.lambda[std::size_t(k)] * w.p(e.v[std::size_t(k)])[i];
      shared = shared && w.p(e.v[std::size_t(k)])[i] == w.p(e.v[0])[i];
    }
    if (shared) q[std::size_t(i)] = w.p(e.v[0])[i];
  }
  return q;
}

/// The sites related to `root` through the identification tables (either way, closed): the
/// image of its vertices must be a boundary triangle, or a boundary edge, of the other template.
std::vector<Site> related_sites(const Session& s, const std::vector<TableIndex>& index,
                                const std::vector<Surface>& surfaces, const Site& root) {
  std::vector<Site> out{root};
  std::set<std::pair<std::size_t, Tri>> seen{root.key()};
  for (std::size_t next = 0; next < out.size(); ++next)
    for (const auto& [map_of, to] : tables_from(s, index, out[next].t)) {
      const Site e = out[next];
      const auto& map = *map_of;
      Site r = e;
      r.t = to;
      bool all = true;
      for (int i = 0; i < e.size() && all; ++i) {
        const auto it = map.find(e.v[std::size_t(i)]);
        all = it != map.end();
        if (all) r.v[std::size_t(i)] = it->second;
      }
      if (!all) continue;
      const auto& other = surfaces[r.t];
      if (r.size() == 3 ? !other.tris.count(tri(r.v[0], r.v[1], r.v[2]))
                        : !other.has_edge(r.v[0], r.v[1]))
        continue;
      if (seen.insert(r.key()).second) out.push_back(r);
    }
  return out;
}

/// Splits the boundary triangle (or both triangles on the edge) of site e at new vertex m.
void split_site(Surface& surface, const Site& e, IndexType m) {
  if (e.size() == 3) {
    const auto [u, v, x] = e.v;
    surface.erase(tri(u, v, x));
    surface.add(tri(u, v, m));
    surface.add(tri(v, x, m));
    surface.add(tri(x, u, m));
  } else {
    const IndexType a = e.v[0], b = e.v[1];
    const auto apexes = surface.wings.at(std::minmax(a, b));
    for (IndexType x : apexes) {
      surface.erase(tri(a, b, x));
      surface.add(tri(a, m, x));
      surface.add(tri(m, b, x));
    }
  }
  surface.changed = true;
}

/// One cluster of boundary triangles: the same outward unit normal and offset, up to 1e-9 (of the
/// template's extent, for the offset).
bool same_plane(const FacingPlanes::Plane& x, const FacingPlanes::Plane& y, double scale) {
  return dot3(x.n, y.n) >= 1 - 1e-9 && std::abs(x.d - y.d) <= 1e-9 * scale;
}

} // namespace

std::vector<FacingPlanes> facing_planes(const Session& s, const NearRightCreases* creases) {
  std::vector<FacingPlanes> out;
  for (const auto& w : s.w) {
    out.emplace_back();
    auto& fp = out.back();
    fp.vertex_planes.resize(w.vertex_count());
    if (w.vertex_count() == 0) continue;
    Vec lo = at(w.p(0)), hi = lo;
    for (std::size_t v = 0; v < w.vertex_count(); ++v)
      for (std::size_t i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], w.p(IndexType(v))[i]);
        hi[i] = std::max(hi[i], w.p(IndexType(v))[i]);
      }
    const Vec extent = minus(hi, lo);
    fp.scale = std::sqrt(dot3(extent, extent));
    // Boundary triangles with the cell's fourth vertex, for the outward normal.
    std::map<Tri, std::vector<IndexType>> apex;
    for (const auto& c : w.cells)
      for (int k = 0; k < 4; ++k) {
        Tri f{};
        for (int i = 0, n = 0; i < 4; ++i)
          if (i != k) f[std::size_t(n++)] = c[std::size_t(i)];
        std::sort(f.begin(), f.end());
        apex[f].push_back(c[std::size_t(k)]);
      }
    for (const auto& [f, e] : apex) {
      if (e.size() != 1) continue;
      Vec n = unit(cross3(sub3(w.p(f[1]), w.p(f[0])), sub3(w.p(f[2]), w.p(f[0]))));
      if (dot3(n, sub3(w.p(e[0]), w.p(f[0]))) > 0) n = {-n[0], -n[1], -n[2]};
      const double d = dot3(n, at(w.p(f[0])));
      int id = -1;
      for (std::size_t k = 0; k < fp.planes.size() && id < 0; ++k)
        if (same_plane({n, d}, fp.planes[k], fp.scale)) id = int(k);
      if (id < 0) {
        id = int(fp.planes.size());
        fp.planes.push_back({n, d});
      }
      fp.triangle_plane[f] = id;
      for (IndexType v : f) {
        auto& list = fp.vertex_planes[std::size_t(v)];
        if (std::find(list.begin(), list.end(), id) == list.end()) list.push_back(id);
      }
    }
    for (std::size_t i = 0; i < fp.planes.size(); ++i)
      for (std::size_t j = i + 1; j < fp.planes.size(); ++j) {
        const auto &a = fp.planes[i], &b = fp.planes[j];
        const double cosine = dot3(a.n, b.n);
        if (!(cosine < -1e-9 && cosine > -1 + 1e-9)) continue;
        const Vec diff = minus(a.n, b.n);
        const double l = std::sqrt(dot3(diff, diff));
        (cosine < -0.5 ? fp.mirrors : fp.near_right)[{int(i), int(j)}] = {
            {diff[0] / l, diff[1] / l, diff[2] / l}, (a.d - b.d) / l};
      }
    if (creases) creases->apply(fp, out.size() - 1);
  }
  return out;
}

NearRightCreases::NearRightCreases(const Session& s) : marked_(s.w.size()) {
  for (const auto& w : s.w) {
    double shortest = std::numeric_limits<double>::infinity();
    for (const auto& c : w.cells)
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
          const Vec e = sub3(w.p(c[std::size_t(i)]), w.p(c[std::size_t(j)]));
          shortest = std::min(shortest, std::sqrt(dot3(e, e)));
        }
    short_edge_.push_back(shortest / 16);
  }
}

bool NearRightCreases::is_marked(const FacingPlanes& fp, std::size_t t,
                                 std::pair<int, int> ij) const {
  const auto& a = fp.planes[std::size_t(ij.first)];
  const auto& b = fp.planes[std::size_t(ij.second)];
  return std::any_of(marked_[t].begin(), marked_[t].end(), [&](const PlanePair& m) {
    return (same_plane(m.first, a, fp.scale) && same_plane(m.second, b, fp.scale)) ||
           (same_plane(m.first, b, fp.scale) && same_plane(m.second, a, fp.scale));
  });
}

void NearRightCreases::watch(const FacingPlanes& fp, std::size_t t, IndexType a, IndexType b,
                             const Work& w) {
  const Vec e = sub3(w.p(a), w.p(b));
  if (!(std::sqrt(dot3(e, e)) < short_edge_[t]) ||
      std::size_t(std::max(a, b)) >= fp.vertex_planes.size())
    return;
  const auto touches = [&](int plane) {
    const auto& pa = fp.vertex_planes[std::size_t(a)];
    const auto& pb = fp.vertex_planes[std::size_t(b)];
    return std::find(pa.begin(), pa.end(), plane) != pa.end() ||
           std::find(pb.begin(), pb.end(), plane) != pb.end();
  };
  for (const auto& [ij, mirror] : fp.near_right)
    if (touches(ij.first) && touches(ij.second) && !is_marked(fp, t, ij))
      marked_[t].push_back({fp.planes[std::size_t(ij.first)], fp.planes[std::size_t(ij.second)]});
}

void NearRightCreases::apply(FacingPlanes& fp, std::size_t t) const {
  for (auto it = fp.near_right.begin(); it != fp.near_right.end();)
    if (is_marked(fp, t, it->first)) {
      fp.mirrors.insert(*it);
      it = fp.near_right.erase(it);
    } else {
      ++it;
    }
}

std::optional<std::array<double, 3>> crease_mirror(const Work& w, const FacingPlanes& planes,
                                                   const std::array<IndexType, 3>& f, IndexType q) {
  Tri key = f;
  std::sort(key.begin(), key.end());
  const auto it = planes.triangle_plane.find(key);
  if (it == planes.triangle_plane.end()) return std::nullopt;
  const int pf = it->second;
  const auto& own = planes.planes[std::size_t(pf)];
  const Vec x = at(w.p(q));
  // On f's plane too: q is on the line where the planes meet, its own mirror image.
  if (std::abs(dot3(own.n, x) - own.d) <= 1e-6 * planes.scale) return std::nullopt;
  const P3 o = CGAL::circumcenter(p3(w.p(f[0])), p3(w.p(f[1])), p3(w.p(f[2])));
  const double rho2 = CGAL::squared_distance(o, p3(w.p(f[0])));
  for (int pq : planes.vertex_planes[std::size_t(q)]) {
    const auto m = planes.mirrors.find(std::minmax(pf, pq));
    if (m == planes.mirrors.end()) continue;
    const double h = 2 * (dot3(m->second.m, x) - m->second.c);
    const Vec p{x[0] - h * m->second.m[0], x[1] - h * m->second.m[1], x[2] - h * m->second.m[2]};
    if (CGAL::squared_distance(o, P3(p[0], p[1], p[2])) < rho2 * (1 - 1e-9)) return p;
  }
  return std::nullopt;
}

std::vector<std::size_t> insert_boundary_points(Session& s,
                                                const std::vector<BoundaryPoint>& points) {
  std::vector<std::size_t> inserted(points.size(), 0);
  if (points.empty()) return inserted;
  auto index = index_tables(s.t);
  std::vector<Surface> surfaces;
  for (const auto& w : s.w) surfaces.emplace_back(w);
  for (std::size_t pi = 0; pi < points.size(); ++pi) {
    const auto& point = points[pi];
    const auto root = locate(s.w[point.t], surfaces[point.t], point.t, point.x, point.normal);
    if (!root) continue;
    const auto sites = related_sites(s, index, surfaces, *root);
    std::map<std::pair<std::size_t, Tri>, IndexType> made;
    for (const auto& e : sites) {
      auto& w = s.w[e.t];
      const Vec q = site_point(w, e);
      const IndexType m = w.add_vertex(q.data());
      split_site(surfaces[e.t], e, m);
      made[e.key()] = m;
    }
    for (std::size_t k = 0; k < s.t.tables.size(); ++k) {
      auto& table = s.t.tables[k];
      for (const auto& e : sites) {
        if (std::size_t(table.from_template) != e.t) continue;
        Tri image{-1, -1, -1};
        bool all = true;
        for (int i = 0; i < e.size() && all; ++i) {
          const auto it = index[k].fwd.find(e.v[std::size_t(i)]);
          all = it != index[k].fwd.end();
          if (all) image[std::size_t(i)] = it->second;
        }
        if (!all) continue;
        std::sort(image.begin(), image.begin() + e.size());
        const auto to = made.find({std::size_t(table.to_template), image});
        if (to == made.end()) continue;
        const IndexType from = made.at(e.key());
        table.pairs.emplace_back(from, to->second);
        index[k].fwd.emplace(from, to->second);
        index[k].bwd.emplace(to->second, from);
      }
    }
    inserted[pi] = sites.size();
  }
  for (std::size_t t = 0; t < s.w.size(); ++t)
    if (surfaces[t].changed)
      retetrahedralize_template(s.w[t], {surfaces[t].tris.begin(), surfaces[t].tris.end()});
  return inserted;
}

} // namespace symmesh::adapt::work
