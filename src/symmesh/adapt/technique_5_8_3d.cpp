// Technique 5.8 in 3D on a generated templated mesh (Section 5.2.5) —
// spec/adaptation.md#tmesh-adaptation: boundary-triangulation flips, insertions at encroached
// and not template-aware locally Delaunay interface triangles, constrained Delaunay
// re-tetrahedralization of each template (TetGen) and sliver removal, in rounds.
#include "symmesh/adapt/adaptation_work.h"
#include "symmesh/adapt/crease_mirroring_3d.h"
#include "symmesh/gen/tetrahedral_mesher.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace symmesh::adapt::work {
namespace {
/// The facets of a template with the cells on them (one: a template boundary facet; two: an
/// interior facet), keyed by their sorted vertices.
using FacetMap = std::map<std::array<IndexType, 3>, std::vector<IndexType>>;
FacetMap facet_map_3d(const Work& w) {
  FacetMap out;
  for (IndexType ci = 0; ci < IndexType(w.cells.size()); ++ci)
    for (const auto& f : facets_of(w, w.cells[std::size_t(ci)]))
      out[{f[0], f[1], f[2]}].push_back(ci);
  return out;
}

/// Template vertices bucketed in a uniform grid, to find the ones near a ball quickly; the
/// decisions are the exact predicates on the candidates.
struct PointGrid {
  double h = 1;
  std::unordered_map<std::uint64_t, std::vector<IndexType>> cells;
  static std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) {
    const auto u = [](std::int64_t v) { return std::uint64_t(v + (1 << 20)) & 0x1fffff; };
    return u(i) << 42 | u(j) << 21 | u(k);
  }
  explicit PointGrid(const Work& w) {
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (std::size_t v = 0; v < w.vertex_count(); ++v)
      for (int i = 0; i < 3; ++i) {
        lo[i] = v == 0 ? w.p(IndexType(v))[i] : std::min(lo[i], w.p(IndexType(v))[i]);
        hi[i] = v == 0 ? w.p(IndexType(v))[i] : std::max(hi[i], w.p(IndexType(v))[i]);
      }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
    h = extent / std::max(1.0, std::cbrt(double(w.vertex_count())));
    for (std::size_t v = 0; v < w.vertex_count(); ++v) {
      const double* q = w.p(IndexType(v));
      cells[key(std::int64_t(std::floor(q[0] / h)), std::int64_t(std::floor(q[1] / h)),
                std::int64_t(std::floor(q[2] / h)))]
          .push_back(IndexType(v));
    }
  }
  /// The vertices in the grid cells a ball of radius r around c touches (a superset).
  template <class F>
  void near(const double* c, double r, F&& visit) const {
    std::int64_t lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::int64_t(std::floor((c[i] - r) / h));
      hi[i] = std::int64_t(std::floor((c[i] + r) / h));
    }
    // A ball much larger than the grid (the circumball of a flat boundary triangle) covers more
    // grid cells than are occupied: then look at the occupied ones.
    double box = 1;
    for (int i = 0; i < 3; ++i) box *= double(hi[i] - lo[i] + 1);
    if (box > double(cells.size())) {
      const auto coordinate = [](std::uint64_t key, int shift) {
        return std::int64_t((key >> shift) & 0x1fffff) - (1 << 20);
      };
      for (const auto& [key, vertices] : cells) {
        const std::int64_t ijk[3] = {coordinate(key, 42), coordinate(key, 21), coordinate(key, 0)};
        bool in = true;
        for (int i = 0; i < 3; ++i) in = in && ijk[i] >= lo[i] && ijk[i] <= hi[i];
        if (in)
          for (IndexType v : vertices) visit(v);
      }
      return;
    }
    for (auto i = lo[0]; i <= hi[0]; ++i)
      for (auto j = lo[1]; j <= hi[1]; ++j)
        for (auto k = lo[2]; k <= hi[2]; ++k) {
          const auto it = cells.find(key(i, j, k));
          if (it != cells.end())
            for (IndexType v : it->second) visit(v);
        }
  }
};

/// x -> A^T (x - b): the inverse of a rigid transformation.
void apply_inverse(const mesh::Transformation& t, const double* x, double* out) {
  for (int i = 0; i < 3; ++i) {
    out[i] = 0;
    for (int j = 0; j < 3; ++j)
      out[i] += t.matrix[std::size_t(j * 3 + i)] * (x[j] - t.translation[std::size_t(j)]);
  }
}

P3 image3(const Session& s, std::size_t instance, IndexType v) {
  double q[3];
  s.transformation(instance).apply(s.w[s.template_of[instance]].p(v), q);
  return P3(q[0], q[1], q[2]);
}

/// An instance pair (i, j) across an interface, and its vertex map from i's template to j's.
struct InterfacePair {
  std::size_t i = 0, j = 0;
  const std::unordered_map<IndexType, IndexType>* map = nullptr;
};

/// One instance pair per identification table and direction, the first in the list. The pairs
/// that share a table are congruent: the table fixes where j's interface vertices lie in i's
/// frame (identified vertices coincide: adapt::certify_conformity checks the input), and for
/// instances that meet without overlapping that fixes T_i^-1 T_j. The interface steps decide in
/// template terms (template edges, mirror points in template coordinates), so one pair decides for
/// all. (The tsv-half-32 slices have 256 identifications over 6 tables; testing every pair was most
/// of a round.)
std::vector<InterfacePair> pair_per_table(const mesh::TemplatedMeshCompactSvb& t,
                                          const std::vector<TableIndex>& index,
                                          bool both_directions) {
  std::vector<InterfacePair> out;
  std::set<std::pair<IndexType, bool>> seen;
  for (const auto& id : t.identifications)
    for (bool forward : {true, false}) {
      if ((!forward && !both_directions) || !seen.insert({id.table, forward}).second) continue;
      const auto& table = index[std::size_t(id.table)];
      if (forward)
        out.push_back({std::size_t(id.from_instance), std::size_t(id.to_instance), &table.fwd});
      else
        out.push_back({std::size_t(id.to_instance), std::size_t(id.from_instance), &table.bwd});
    }
  return out;
}

/// One round's view of the templates: facets, boundary triangles and point grids.
struct Round3 {
  std::vector<FacetMap> facets;
  std::vector<PointGrid> grids;
  explicit Round3(const Session& s) {
    for (const auto& w : s.w) {
      facets.push_back(facet_map_3d(w));
      grids.emplace_back(w);
      on_boundary.emplace_back(w.vertex_count(), 0);
      for (const auto& [f, around] : facets.back())
        if (around.size() == 1)
          for (IndexType v : f) on_boundary.back()[std::size_t(v)] = 1;
    }
  }
  std::vector<std::vector<char>> on_boundary;
  bool is_interior_vertex(std::size_t t, IndexType v) const {
    return !on_boundary[t][std::size_t(v)];
  }
  bool is_boundary(std::size_t t, std::array<IndexType, 3> f) const {
    std::sort(f.begin(), f.end());
    const auto it = facets[t].find(f);
    return it != facets[t].end() && it->second.size() == 1;
  }
};

/// The longest edge of triangle f of template t.
TemplateEdge longest_edge_of(const Work& w, std::size_t t, const std::array<IndexType, 3>& f) {
  IndexType a = -1, b = -1;
  longest_edge(w, f.data(), 3, a, b);
  return edge_of(t, a, b);
}

/// The interface triangles of instance pair (i, j) through a table map: triangle f of i's
/// template whose vertices the map sends onto a boundary triangle of j's template.
template <class F>
void for_each_interface_triangle(const Session& s, const Round3& r, std::size_t i, std::size_t j,
                                 const std::unordered_map<IndexType, IndexType>& map, F&& visit) {
  const std::size_t ti = s.template_of[i], tj = s.template_of[j];
  for (const auto& [f, around] : r.facets[ti]) {
    if (around.size() != 1) continue;
    std::array<IndexType, 3> g{};
    bool all = true;
    for (int k = 0; k < 3 && all; ++k) {
      const auto it = map.find(f[std::size_t(k)]);
      all = it != map.end();
      if (all) g[std::size_t(k)] = it->second;
    }
    if (all && r.is_boundary(tj, g)) visit(f, around[0], g);
  }
}

/// The edge of encroached boundary triangle f (corners `x`, in the coordinates of the encroaching
/// point q) to bisect: an edge whose diametral ball holds q — the longest such — as Delaunay
/// refinement splits an encroached segment before the facet around it, which keeps the
/// refinement near a crease from shrinking both sides in turn; else f's longest edge.
TemplateEdge edge_to_split(const Work& w, std::size_t t, const std::array<IndexType, 3>& f,
                           const std::array<P3, 3>& x, const P3& q) {
  std::optional<TemplateEdge> best;
  double len = -1;
  for (int k = 0; k < 3; ++k) {
    const P3 &u = x[std::size_t(k)], &v = x[std::size_t((k + 1) % 3)];
    if (CGAL::side_of_bounded_sphere(u, v, q) != CGAL::ON_BOUNDED_SIDE) continue;
    const double l = CGAL::squared_distance(u, v);
    if (l > len) len = l, best = edge_of(t, f[std::size_t(k)], f[std::size_t((k + 1) % 3)]);
  }
  return best ? *best : longest_edge_of(w, t, f);
}

/// Whether some sphere through triangle (a, b, c) — centre o + h n on the line through its
/// circumcentre o along its unit normal n, |h| <= 2 rho (rho its circumradius) — holds none of
/// the points strictly inside: then the triangle is a face of their Delaunay tetrahedralization.
/// Point q is inside that sphere iff |q - o|^2 - rho^2 < 2 h (q - o).n, one bound on h per point,
/// so this is a one-dimensional feasibility question. The diametral ball (h = 0) alone is
/// stricter: next to a crease at an acute angle it holds the points of the other facet, and
/// refining for it there does not end. Beyond 4.5 rho from o no such sphere reaches. Decided in
/// floating point: the tetrahedralization built on it is checked exactly afterwards.
/// `worst` is set to a point that rules the sphere out.
bool delaunay_face(const P3& a, const P3& b, const P3& c, const std::vector<P3>& points,
                   std::optional<P3>& worst) {
  const P3 o = CGAL::circumcenter(a, b, c);
  const double rho2 = CGAL::squared_distance(o, a), rho = std::sqrt(rho2);
  auto nv = CGAL::cross_product(b - a, c - a);
  const double nn = std::sqrt(nv.squared_length());
  if (!(nn > 0)) return false;
  nv = nv / nn;
  double lo = -2 * rho, hi = 2 * rho;
  for (const auto& q : points) {
    const auto d = q - o;
    const double power = d.squared_length() - rho2, height = d * nv;
    // inside for h with power < 2 h height: keep h where power >= 2 h height.
    if (height > 0)
      hi = std::min(hi, power / (2 * height));
    else if (height < 0)
      lo = std::max(lo, power / (2 * height));
    else if (power < 0)
      lo = hi + 1;
    if (!(lo <= hi)) {
      worst = q;
      return false;
    }
  }
  return true;
}

/// Triangle (a, b, c)'s circumcentre o, squared circumradius rho2 and the distance from o beyond
/// which no sphere that delaunay_face considers reaches (4.5 rho, with a margin for rounding).
struct TriangleReach {
  P3 o;
  double rho2, reach;
  std::array<double, 3> centre;
};
TriangleReach reach_of(const P3& a, const P3& b, const P3& c) {
  const P3 o = CGAL::circumcenter(a, b, c);
  const double rho2 = CGAL::squared_distance(o, a);
  return {o, rho2, 4.5 * std::sqrt(rho2) * (1 + 1e-6), {o.x(), o.y(), o.z()}};
}

/// What the encroachment step does next: edges to bisect, and points to insert on template
/// boundary triangles (mirror images across the bisector of two facing planes: an acute crease or
/// a thin wedge, crease_mirroring_3d.h), each triangle
/// they resolve with the edge to bisect instead when none of its mirror points can be inserted
/// (it falls outside the leg, or onto a vertex).
struct Encroached {
  std::vector<TemplateEdge> edges;
  std::vector<BoundaryPoint> mirrors;
  std::vector<std::pair<TemplateEdge, std::vector<std::size_t>>> fallback;
};

/// The unit normal of triangle (a, b, c).
std::array<double, 3> unit_normal(const double* a, const double* b, const double* c) {
  auto n = cross3(sub3(b, a), sub3(c, a));
  const double l = std::sqrt(dot3(n, n));
  for (auto& x : n) x /= l;
  return n;
}

/// Collects the mirror images, across the bisector of facing planes of template t, of the vertices
/// `near` of t inside the diametral ball (centre o, squared radius rho2, in the coordinates `image`
/// puts them in) of boundary triangle f of t, and their indices in `out` into `used`.
using SeenMirrors = std::map<std::tuple<std::size_t, double, double, double>, std::size_t>;
template <class Image>
void mirror_encroaching(const Session& s, const std::vector<FacingPlanes>& facing, std::size_t t,
                        const std::array<IndexType, 3>& f, const std::vector<IndexType>& near,
                        const P3& o, double rho2, Image&& image, SeenMirrors& seen,
                        std::vector<BoundaryPoint>& out, std::vector<std::size_t>& used) {
  const auto& w = s.w[t];
  if (facing[t].mirrors.empty()) return;
  for (IndexType q : near) {
    if (!(CGAL::squared_distance(o, image(q)) < rho2)) continue;
    const auto p = crease_mirror(w, facing[t], f, q);
    if (!p) continue;
    const auto [it, fresh] = seen.emplace(std::tuple{t, (*p)[0], (*p)[1], (*p)[2]}, out.size());
    if (fresh) out.push_back({t, *p, unit_normal(w.p(f[0]), w.p(f[1]), w.p(f[2]))});
    used.push_back(it->second);
  }
}

/// Technique 5.8, step "boundary facets Delaunay": the template boundary triangles that are no
/// Delaunay face (delaunay_face) of the vertices near them — of their own template, and, for an
/// interface triangle, of the instance across it too (AT's coordinates). Each is resolved by the
/// mirror images of the encroaching points that lie on a plane facing its own, where there are
/// such points, else by bisecting an edge. With every boundary triangle a Delaunay
/// face, the constrained Delaunay tetrahedralization of a template is Delaunay.
Encroached encroached_boundary(const Session& s, const Round3& r,
                               const std::vector<TableIndex>& index,
                               const std::vector<FacingPlanes>& facing) {
  std::set<TemplateEdge> bad;
  Encroached out;
  SeenMirrors seen;
  std::vector<std::size_t> used;
  std::vector<P3> near;
  std::vector<IndexType> near_i, near_j;
  for (std::size_t t = 0; t < s.w.size(); ++t) {
    const auto& w = s.w[t];
    for (const auto& entry : r.facets[t]) {
      if (entry.second.size() != 1) continue;
      const auto& f = entry.first;
      const P3 a = p3(w.p(f[0])), b = p3(w.p(f[1])), c = p3(w.p(f[2]));
      const auto [o, rho2, reach, oc] = reach_of(a, b, c);
      near.clear();
      near_i.clear();
      r.grids[t].near(oc.data(), reach, [&](IndexType q) {
        if (q != f[0] && q != f[1] && q != f[2]) near.push_back(p3(w.p(q))), near_i.push_back(q);
      });
      std::optional<P3> by;
      if (delaunay_face(a, b, c, near, by)) continue;
      used.clear();
      mirror_encroaching(
          s, facing, t, f, near_i, o, rho2, [&](IndexType q) { return p3(w.p(q)); }, seen,
          out.mirrors, used);
      if (used.empty())
        bad.insert(edge_to_split(w, t, f, {a, b, c}, *by));
      else
        out.fallback.push_back({edge_to_split(w, t, f, {a, b, c}, *by), used});
    }
  }
  for (const auto& [i, j, map] : pair_per_table(s.t, index, true)) {
    const auto ti = s.template_of[i], tj = s.template_of[j];
    for_each_interface_triangle(s, r, i, j, *map, [&](const auto& f, IndexType, const auto& g) {
      const P3 a = image3(s, i, f[0]), b = image3(s, i, f[1]), c = image3(s, i, f[2]);
      const auto [o, rho2, reach, oc] = reach_of(a, b, c);
      near.clear();
      near_i.clear();
      near_j.clear();
      // Both sides: the sphere must be empty of the two instances' vertices at once.
      double local[3];
      apply_inverse(s.transformation(i), oc.data(), local);
      r.grids[ti].near(local, reach, [&](IndexType q) {
        if (q != f[0] && q != f[1] && q != f[2])
          near.push_back(image3(s, i, q)), near_i.push_back(q);
      });
      apply_inverse(s.transformation(j), oc.data(), local);
      r.grids[tj].near(local, reach, [&](IndexType q) {
        if (q != g[0] && q != g[1] && q != g[2])
          near.push_back(image3(s, j, q)), near_j.push_back(q);
      });
      std::optional<P3> by;
      if (delaunay_face(a, b, c, near, by)) return;
      // Facing planes of either template: the mirror goes into that template's copy of the
      // triangle.
      used.clear();
      mirror_encroaching(
          s, facing, ti, f, near_i, o, rho2, [&](IndexType q) { return image3(s, i, q); }, seen,
          out.mirrors, used);
      mirror_encroaching(
          s, facing, tj, g, near_j, o, rho2, [&](IndexType q) { return image3(s, j, q); }, seen,
          out.mirrors, used);
      if (used.empty())
        bad.insert(edge_to_split(s.w[ti], ti, f, {a, b, c}, *by));
      else
        out.fallback.push_back({edge_to_split(s.w[ti], ti, f, {a, b, c}, *by), used});
    });
  }
  out.edges.assign(bad.begin(), bad.end());
  return out;
}

} // namespace

/// The template boundary triangles (sorted vertices).
std::vector<std::array<IndexType, 3>> surface_of(const Work& w) {
  std::vector<std::array<IndexType, 3>> out;
  for (const auto& [f, around] : facet_map_3d(w))
    if (around.size() == 1) out.push_back(f);
  return out;
}

/// Replaces the cells of template `w` by TetGen's constrained Delaunay tetrahedralization of its
/// vertices and the given boundary triangles.
void retetrahedralize_template(Work& w, const std::vector<std::array<IndexType, 3>>& surface) {
  gen::SurfaceInput in;
  for (std::size_t v = 0; v < w.vertex_count(); ++v)
    in.points.push_back({w.p(IndexType(v))[0], w.p(IndexType(v))[1], w.p(IndexType(v))[2]});
  for (const auto& f : surface)
    in.triangles.push_back({std::size_t(f[0]), std::size_t(f[1]), std::size_t(f[2])});
  const auto out = gen::constrained_delaunay_tetrahedralization(in);
  Work fresh;
  fresh.d = 3;
  for (const auto& q : out.points) fresh.add_vertex(q.data());
  for (const auto& c : out.tetrahedra)
    fresh.add_cell({IndexType(c[0]), IndexType(c[1]), IndexType(c[2]), IndexType(c[3])});
  w = std::move(fresh);
}

namespace {
/// Replaces every template's cells by TetGen's constrained Delaunay tetrahedralization of its
/// vertices and its boundary triangles (kept as they are; TetGen's Steiner points, if any, are
/// template-interior and come last).
void retetrahedralize(Session& s, const Round3& r) {
  for (std::size_t t = 0; t < s.w.size(); ++t) {
    std::vector<std::array<IndexType, 3>> surface;
    for (const auto& [f, around] : r.facets[t])
      if (around.size() == 1) surface.push_back(f);
    retetrahedralize_template(s.w[t], surface);
  }
}

/// Whether every instance's matrix is a signed permutation (translations, mirrors, quarter
/// turns). Then the copies of a point on the interfaces of a template are exact, and points
/// cospherical in the object are cospherical in the doubles. A rotation by 2π/n rounds those
/// copies, which makes ties up to rounding systematic (every slice interface of a TSV).
bool signed_permutation_matrices(const Session& s) {
  for (std::size_t i = 0; i < s.template_of.size(); ++i) {
    const auto& m = s.transformation(i).matrix;
    for (std::size_t r = 0; r < 3; ++r) {
      int nonzero = 0;
      for (std::size_t c = 0; c < 3; ++c) {
        const double x = m[r * 3 + c];
        if (x != 0 && x != 1 && x != -1) return false;
        nonzero += x != 0;
      }
      if (nonzero != 1) return false;
    }
  }
  return true;
}

/// |D| / L^5 for apex e and cell c: D the in-sphere determinant det[q_i - e, |q_i - e|^2], L the
/// largest distance among the five points. A perturbation of the coordinates by this fraction of
/// L can change the in-sphere sign, so an apex inside by no more than ~1e-9 is a tie up to
/// rounding — the sliver of four cocircular points has no stable circumsphere, while D scales
/// with its volume (tests/cli/delaunay_check.py measures the same).
double insphere_measure(const Work& w, const Cell& c, IndexType e) {
  double m[4][4];
  double span = 0;
  for (int i = 0; i < 4; ++i) {
    double sq = 0;
    for (int k = 0; k < 3; ++k) {
      m[i][k] = w.p(c[std::size_t(i)])[k] - w.p(e)[k];
      sq += m[i][k] * m[i][k];
    }
    m[i][3] = sq;
    span = std::max(span, std::sqrt(sq));
    for (int j = 0; j < 4; ++j) {
      double dd = 0;
      for (int k = 0; k < 3; ++k) {
        const double x = w.p(c[std::size_t(i)])[k] - w.p(c[std::size_t(j)])[k];
        dd += x * x;
      }
      span = std::max(span, std::sqrt(dd));
    }
  }
  const auto det3 = [](double a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  double det = 0;
  for (int j = 0; j < 4; ++j) {
    double minor[3][3];
    for (int i = 1; i < 4; ++i)
      for (int k = 0, kk = 0; k < 4; ++k)
        if (k != j) minor[i - 1][kk++] = m[i][k];
    det += (j % 2 ? -1 : 1) * m[0][j] * det3(minor);
  }
  return span > 0 ? std::abs(det) / std::pow(span, 5) : 0;
}

/// An interior facet of a template that is not locally Delaunay: the apex of cell `across`
/// lies strictly inside the circumsphere of cell `cell` (exact in-sphere sign on the doubles).
struct NonLocallyDelaunay {
  std::size_t t = 0;
  std::array<IndexType, 3> facet{};
  IndexType cell = -1;
  IndexType apex = -1;
};

/// The interior facets of the templates that are not locally Delaunay, by the exact in-sphere
/// sign: a cospherical tie (the apex on the circumsphere) is locally Delaunay. With
/// `ties_up_to_rounding`, an apex inside by |D| / L^5 <= 1e-9 is a tie too (rotated copies).
std::vector<NonLocallyDelaunay> non_ld_facets(const Session& s, const Round3& r,
                                              bool ties_up_to_rounding) {
  std::vector<NonLocallyDelaunay> out;
  for (std::size_t t = 0; t < s.w.size(); ++t) {
    const auto& w = s.w[t];
    for (const auto& [f, around] : r.facets[t]) {
      if (around.size() != 2) continue;
      for (std::size_t side = 0; side < 2; ++side) {
        const Cell& c = w.cells[std::size_t(around[side])];
        const IndexType e = apex(w.cells[std::size_t(around[1 - side])], f);
        if (CGAL::side_of_bounded_sphere(p3(w.p(c[0])), p3(w.p(c[1])), p3(w.p(c[2])), p3(w.p(c[3])),
                                         p3(w.p(e))) == CGAL::ON_BOUNDED_SIDE &&
            !(ties_up_to_rounding && insphere_measure(w, c, e) <= 1e-9)) {
          out.push_back({t, f, around[side], e});
          break;
        }
      }
    }
  }
  return out;
}

std::size_t remove_slivers(Session& s) {
  std::size_t flips = 0;
  for (std::size_t t = 0; t < s.w.size(); ++t) {
    auto& w = s.w[t];
    const CellTest ok = [&](const Cell& c) { return robustly_positive(w, c); };
    for (bool again = true; again;) {
      again = false;
      for (IndexType ci = 0; ci < IndexType(w.cells.size()); ++ci) {
        if (ok(w.cells[std::size_t(ci)])) continue;
        bool flipped = false;
        for (int p = 0; p < 4 && !flipped; ++p)
          for (int q = p + 1; q < 4 && !flipped; ++q)
            flipped = remove_edge(w, ci, p, q, ok, 6, false);
        for (int skip = 0; skip < 4 && !flipped; ++skip)
          flipped = quality_flip_2_3(w, ci, skip, &ok);
        if (!flipped) continue;
        ++flips;
        again = true;
      }
    }
  }
  return flips;
}

/// The cells of the templates that are flat to rounding, as (template, cell).
std::vector<std::pair<std::size_t, IndexType>> not_positive_everywhere(const Session& s) {
  std::vector<std::pair<std::size_t, IndexType>> out;
  for (std::size_t t = 0; t < s.w.size(); ++t)
    for (IndexType ci = 0; ci < IndexType(s.w[t].cells.size()); ++ci)
      if (!robustly_positive(s.w[t], s.w[t].cells[std::size_t(ci)])) out.emplace_back(t, ci);
  return out;
}

/// Definition 4.10 in 3D: the longest edges of the interface triangles whose cell on one side
/// has the apex across the interface strictly inside its circumsphere (AT's coordinates).
std::vector<TemplateEdge> non_tald_3d(const Session& s, const Round3& r,
                                      const std::vector<TableIndex>& index) {
  std::set<TemplateEdge> bad;
  for (const auto& [i, j, map] : pair_per_table(s.t, index, false)) {
    const auto ti = s.template_of[i], tj = s.template_of[j];
    for_each_interface_triangle(s, r, i, j, *map, [&](const auto& f, IndexType ci, auto g) {
      std::sort(g.begin(), g.end());
      const IndexType cj = r.facets[tj].at(g)[0];
      const Cell& a = s.w[ti].cells[std::size_t(ci)];
      const Cell& b = s.w[tj].cells[std::size_t(cj)];
      const P3 qa = image3(s, i, apex(a, f)), qb = image3(s, j, apex(b, g));
      const bool inside_a =
          CGAL::side_of_bounded_sphere(image3(s, i, a[0]), image3(s, i, a[1]), image3(s, i, a[2]),
                                       image3(s, i, a[3]), qb) == CGAL::ON_BOUNDED_SIDE;
      const bool inside_b =
          CGAL::side_of_bounded_sphere(image3(s, j, b[0]), image3(s, j, b[1]), image3(s, j, b[2]),
                                       image3(s, j, b[3]), qa) == CGAL::ON_BOUNDED_SIDE;
      if (inside_a || inside_b) bad.insert(longest_edge_of(s.w[ti], ti, f));
    });
  }
  return {bad.begin(), bad.end()};
}

/// Whether boundary edge {a, b} between boundary triangles (a, b, c) and (a, b, d) of w should be
/// flipped to {c, d} (Lawson, in the plane of a flat boundary patch): the two triangles lie in one
/// plane up to the rounding of the coordinates (d within 1e-9 of the longest edge of it — the
/// written coordinates of a slanted plane are not exactly coplanar), the quadrilateral is
/// strictly convex, and d lies strictly inside the circle through a, b, c (exact).
bool boundary_flip_wanted(const Work& w, IndexType a, IndexType b, IndexType c, IndexType d) {
  const auto n = cross3(sub3(w.p(b), w.p(a)), sub3(w.p(c), w.p(a)));
  const double nn = std::sqrt(dot3(n, n));
  double longest = 0;
  for (IndexType u : {a, b, c, d})
    for (IndexType v : {a, b, c, d}) {
      const auto e = sub3(w.p(u), w.p(v));
      longest = std::max(longest, std::sqrt(dot3(e, e)));
    }
  if (!(nn > 0) || std::abs(dot3(n, sub3(w.p(d), w.p(a)))) / nn > 1e-9 * longest) return false;
  // In-plane orientation of (p, q, r) along n, relative to its scale.
  const auto side = [&](IndexType p, IndexType q, IndexType r) {
    return dot3(cross3(sub3(w.p(q), w.p(p)), sub3(w.p(r), w.p(p))), n) / (nn * longest * longest);
  };
  const double eps = 1e-12; // a strictly convex quadrilateral, not one flat to rounding
  if (!(side(a, b, c) * side(a, b, d) < -eps * eps && side(c, d, a) * side(c, d, b) < -eps * eps))
    return false;
  return CGAL::side_of_bounded_sphere(p3(w.p(a)), p3(w.p(b)), p3(w.p(c)), p3(w.p(d))) ==
         CGAL::ON_BOUNDED_SIDE;
}

/// One flip of the boundary triangulation: template t, edge {a, b} -> {c, d}.
struct SurfaceFlip {
  std::size_t t = 0;
  IndexType a = 0, b = 0, c = 0, d = 0;
};

/// Lawson flips of the template boundary triangulations inside flat patches, each made at every
/// related edge at once (closed under the identification tables) and only when it is wanted in
/// every template it touches, so interfaces stay conforming and a tie decided differently by the
/// rounding of two copies is left alone. The templates whose boundary changed are
/// re-tetrahedralized. Returns the flips (related copies counted).
std::size_t surface_lawson(Session& s, std::size_t max_sweeps) {
  std::size_t flips = 0;
  for (std::size_t sweep = 0; sweep < max_sweeps; ++sweep) {
    const auto index = index_tables(s.t);
    std::vector<std::set<std::array<IndexType, 3>>> surf(s.w.size());
    std::vector<std::map<std::pair<IndexType, IndexType>, std::vector<IndexType>>> wings(
        s.w.size());
    for (std::size_t t = 0; t < s.w.size(); ++t)
      for (const auto& f : surface_of(s.w[t])) {
        surf[t].insert(f);
        for (int k = 0; k < 3; ++k) {
          const IndexType u = f[std::size_t(k)], v = f[std::size_t((k + 1) % 3)],
                          x = f[std::size_t((k + 2) % 3)];
          wings[t][std::minmax(u, v)].push_back(x);
        }
      }
    const auto tri = [](IndexType u, IndexType v, IndexType x) {
      std::array<IndexType, 3> f{u, v, x};
      std::sort(f.begin(), f.end());
      return f;
    };
    std::vector<std::set<std::array<IndexType, 3>>> touched(s.w.size());
    std::vector<char> changed(s.w.size(), 0);
    std::size_t made = 0;
    for (std::size_t t = 0; t < s.w.size(); ++t)
      for (const auto& [edge, apexes] : wings[t]) {
        if (apexes.size() != 2) continue;
        const auto [a, b] = edge;
        if (!boundary_flip_wanted(s.w[t], a, b, apexes[0], apexes[1])) continue;
        std::vector<SurfaceFlip> closure{{t, a, b, apexes[0], apexes[1]}};
        std::set<std::tuple<std::size_t, IndexType, IndexType>> seen{{t, a, b}};
        bool ok = true;
        for (std::size_t next = 0; next < closure.size() && ok; ++next)
          for (std::size_t k = 0; k < s.t.tables.size() && ok; ++k)
            for (bool forward : {true, false}) {
              const SurfaceFlip m = closure[next];
              const auto& table = s.t.tables[k];
              if (std::size_t(forward ? table.from_template : table.to_template) != m.t) continue;
              const auto& map = forward ? index[k].fwd : index[k].bwd;
              const auto ia = map.find(m.a), ib = map.find(m.b);
              if (ia == map.end() || ib == map.end()) continue;
              const auto ic = map.find(m.c), id = map.find(m.d);
              const auto other = std::size_t(forward ? table.to_template : table.from_template);
              const auto [ra, rb] = std::minmax(ia->second, ib->second);
              if (!seen.insert({other, ra, rb}).second) continue;
              // The related edge must be a flat boundary edge with the related wings.
              if (ic == map.end() || id == map.end() ||
                  !surf[other].count(tri(ra, rb, ic->second)) ||
                  !surf[other].count(tri(ra, rb, id->second))) {
                // An edge of the interface's rim: the wing across it lies elsewhere.
                ok = false;
                break;
              }
              if (!boundary_flip_wanted(s.w[other], ra, rb, ic->second, id->second)) {
                ok = false;
                break;
              }
              closure.push_back({other, ra, rb, ic->second, id->second});
            }
        if (!ok) continue;
        // Each triangle flips at most once a sweep, and the new edge must be new.
        for (const auto& m : closure)
          if (touched[m.t].count(tri(m.a, m.b, m.c)) || touched[m.t].count(tri(m.a, m.b, m.d)) ||
              !surf[m.t].count(tri(m.a, m.b, m.c)) || !surf[m.t].count(tri(m.a, m.b, m.d)) ||
              wings[m.t].count(std::minmax(m.c, m.d)))
            ok = false;
        if (!ok) continue;
        for (const auto& m : closure) {
          for (const auto& f : {tri(m.a, m.b, m.c), tri(m.a, m.b, m.d)}) {
            surf[m.t].erase(f);
            touched[m.t].insert(f);
          }
          for (const auto& f : {tri(m.c, m.d, m.a), tri(m.c, m.d, m.b)}) {
            surf[m.t].insert(f);
            touched[m.t].insert(f);
          }
          changed[m.t] = 1;
          ++made;
        }
      }
    if (made == 0) break;
    flips += made;
    for (std::size_t t = 0; t < s.w.size(); ++t)
      if (changed[t]) retetrahedralize_template(s.w[t], {surf[t].begin(), surf[t].end()});
  }
  return flips;
}

/// Deletes template-interior vertices of template t (on no boundary facet, so in no
/// identification table) and re-tetrahedralizes it: the vertices after each deleted one move
/// down, and the tables follow. Fewer points never encroach a boundary triangle.
void delete_interior_vertices(Session& s, std::size_t t, const std::set<IndexType>& gone) {
  auto& w = s.w[t];
  auto surface = surface_of(w);
  std::vector<IndexType> to(w.vertex_count(), -1);
  Work kept;
  kept.d = 3;
  for (IndexType v = 0; v < IndexType(w.vertex_count()); ++v)
    if (!gone.count(v)) to[std::size_t(v)] = kept.add_vertex(w.p(v));
  for (auto& f : surface)
    for (auto& v : f) v = to[std::size_t(v)];
  for (auto& table : s.t.tables)
    for (auto& [a, b] : table.pairs) {
      if (std::size_t(table.from_template) == t) a = to[std::size_t(a)];
      if (std::size_t(table.to_template) == t) b = to[std::size_t(b)];
    }
  w = std::move(kept);
  retetrahedralize_template(w, surface);
}

/// The cells to resolve by vertex deletion or insertion, as (template, vertices): the slivers
/// flat to rounding that no flip removed, or, once there are none, the cells with an interior
/// facet that is not locally Delaunay followed by the apex across it. Both come from points of a
/// symmetric object that lie on one circle or sphere, exactly or up to rounding (a point and its
/// rotated copy on each interface of a slice, at two heights, span an isosceles trapezoid): the
/// Delaunay cell on them is flat to rounding, so remove_slivers flipped it away and left the
/// apex inside by a margin the doubles can just resolve. Such a tie is resolved here unless
/// `ties_up_to_rounding` accepts it (non_ld_facets).
std::vector<std::pair<std::size_t, std::vector<IndexType>>>
degenerate_cells(const Session& s, bool ties_up_to_rounding) {
  std::vector<std::pair<std::size_t, std::vector<IndexType>>> out;
  for (const auto& [t, ci] : not_positive_everywhere(s)) {
    const Cell& c = s.w[t].cells[std::size_t(ci)];
    out.push_back({t, {c.begin(), c.end()}});
  }
  if (!out.empty()) return out;
  const Round3 r(s);
  for (const auto& n : non_ld_facets(s, r, ties_up_to_rounding)) {
    const Cell& c = s.w[n.t].cells[std::size_t(n.cell)];
    out.push_back({n.t, {c[0], c[1], c[2], c[3], n.apex}});
  }
  return out;
}

/// Resolves the degenerate cells (degenerate_cells): their template-interior vertices are
/// deleted, or, when all are boundary vertices, the centroid of the cell is inserted as a
/// template-interior vertex (it lies strictly inside the circumsphere and breaks the tie); then
/// the template is re-tetrahedralized and flat cells flipped away, a few times. Returns the
/// vertices deleted and inserted.
std::pair<std::size_t, std::size_t> resolve_slivers(Session& s, DelaunayReport& rep,
                                                    bool ties_up_to_rounding) {
  std::size_t deleted = 0, inserted = 0;
  for (int attempt = 0; attempt < 16; ++attempt) {
    const auto bad = degenerate_cells(s, ties_up_to_rounding);
    if (bad.empty()) break;
    std::map<std::size_t, std::set<IndexType>> gone;
    std::map<std::size_t, std::vector<std::array<double, 3>>> added;
    std::map<std::size_t, std::set<IndexType>> boundary; // per template, its boundary vertices
    for (const auto& [t, vs] : bad) {
      if (!boundary.count(t))
        for (const auto& f : surface_of(s.w[t])) boundary[t].insert(f.begin(), f.end());
      const auto& on = boundary[t];
      bool interior = false;
      for (IndexType v : vs)
        if (!on.count(v)) gone[t].insert(v), interior = true;
      if (interior) continue;
      std::array<double, 3> m{0, 0, 0};
      for (std::size_t q = 0; q < 4; ++q)
        for (int k = 0; k < 3; ++k) m[std::size_t(k)] += s.w[t].p(vs[q])[k] / 4;
      added[t].push_back(m);
    }
    for (const auto& [t, vs] : gone) {
      delete_interior_vertices(s, t, vs);
      deleted += vs.size();
    }
    for (auto& [t, points] : added) {
      if (gone.count(t)) continue; // indices changed; the next attempt sees the cell again
      const auto surface = surface_of(s.w[t]);
      for (const auto& q : points) s.w[t].add_vertex(q.data());
      retetrahedralize_template(s.w[t], surface);
      inserted += points.size();
    }
    rep.flips += remove_slivers(s);
  }
  return {deleted, inserted};
}

} // namespace

/// Technique 5.8 in 3D: rounds of (1) bisecting the longest edge of every encroached template
/// boundary triangle at every related edge, until none is encroached; (2) the constrained
/// Delaunay tetrahedralization of every template; (3) bisecting the interface triangles that are
/// not template-aware locally Delaunay. Ends when (3) finds none.
DelaunayReport make_delaunay_3d(Session& s, std::size_t max_rounds, mesh::Progress* progress,
                                bool crease_mirrors) {
  DelaunayReport rep;
  const auto limit = [&](const std::string& what) {
    s.store();
    throw AdaptationLimit("Technique 5.8 in 3D: " + what +
                          " (ping-pong encroachment, Figure 5.17: mirror points end it between two "
                          "facing planes, at acute creases and thin wedges, not at other sharp "
                          "features)");
  };
  const auto cell_count = [&] {
    std::size_t n = 0;
    for (const auto& w : s.w) n += w.cells.size();
    return n;
  };
  // Refinement that keeps encroaching (acute boundary angles, Figure 5.17) is stopped by this
  // cap long before the round cap: 16 times the input's template cells.
  const std::size_t max_cells = 16 * cell_count() + 4096;
  NearRightCreases creases(s);
  for (;;) {
    if (cell_count() > max_cells)
      limit("the template boundaries were refined to " + std::to_string(cell_count()) +
            " template cells, over 16 times the input's, and boundary triangles are still "
            "encroached");
    rep.flips += surface_lawson(s, 64);
    auto index = index_tables(s.t);
    std::vector<TemplateEdge> bad;
    std::vector<BoundaryPoint> mirrors;
    std::vector<std::pair<TemplateEdge, std::vector<std::size_t>>> fallback;
    {
      const Round3 r(s);
      const auto facing =
          crease_mirrors ? facing_planes(s, &creases) : std::vector<FacingPlanes>(s.w.size());
      auto e = encroached_boundary(s, r, index, facing);
      // Ping-pong at a near-right crease: its planes mirror from the next round on.
      if (crease_mirrors) {
        for (const auto& edge : e.edges)
          creases.watch(facing[edge.t], edge.t, edge.a, edge.b, s.w[edge.t]);
        for (const auto& [edge, points] : e.fallback)
          creases.watch(facing[edge.t], edge.t, edge.a, edge.b, s.w[edge.t]);
      }
      bad = std::move(e.edges);
      mirrors = std::move(e.mirrors);
      fallback = std::move(e.fallback);
    }
    bool phase_tald = false;
    if (bad.empty() && mirrors.empty()) {
      phase_tald = true;
      {
        const Round3 r(s);
        retetrahedralize(s, r);
      }
      rep.flips += remove_slivers(s);
      // Ties up to rounding are accepted only where rotations round the interface copies, or
      // where mirror points across a slanted crease bisector were rounded (a triangle of one leg
      // and its mirror image lie on one sphere, in the reals).
      const bool ties_up_to_rounding =
          !signed_permutation_matrices(s) || rep.crease_mirror_points > 0;
      const auto [deleted, inserted] = resolve_slivers(s, rep, ties_up_to_rounding);
      rep.vertices_deleted += deleted;
      rep.vertices_inserted += inserted;
      // Deleting vertices renumbers a template's vertices and its tables: index them again.
      if (deleted) index = index_tables(s.t);
      if (const auto flat = not_positive_everywhere(s); !flat.empty()) {
        const Cell& c = s.w[flat.front().first].cells[std::size_t(flat.front().second)];
        throw AdaptationLimit(
            "Technique 5.8 in 3D: template " + std::to_string(flat.front().first) + " cell {" +
            std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
            ", " + std::to_string(c[3]) + "} (and " + std::to_string(flat.size() - 1) +
            " more) is a sliver, flat to rounding, that neither flips nor "
            "vertex deletion or insertion removed");
      }
      const Round3 r(s);
      if (const auto not_ld = non_ld_facets(s, r, ties_up_to_rounding); !not_ld.empty()) {
        const auto& n = not_ld.front();
        throw AdaptationLimit(
            "Technique 5.8 in 3D: template " + std::to_string(n.t) + " facet {" +
            std::to_string(n.facet[0]) + ", " + std::to_string(n.facet[1]) + ", " +
            std::to_string(n.facet[2]) + "} (and " + std::to_string(not_ld.size() - 1) +
            " more) is not locally Delaunay: its points are cospherical up to rounding, and "
            "neither flips nor vertex deletion or insertion resolved the tie");
      }
      bad = non_tald_3d(s, r, index);
      if (bad.empty()) break;
    }
    if (rep.rounds == max_rounds && bad.empty()) {
      const auto& m = mirrors.front();
      limit("after " + std::to_string(max_rounds) + " rounds (--max-rounds), template " +
            std::to_string(m.t) + " boundary triangles at an acute crease are still encroached (" +
            std::to_string(mirrors.size()) + " mirror points to insert)");
    }
    if (rep.rounds == max_rounds) {
      const auto& e = bad.front();
      limit("after " + std::to_string(max_rounds) + " rounds (--max-rounds), template " +
            std::to_string(e.t) + " boundary edge {" + std::to_string(e.a) + ", " +
            std::to_string(e.b) + "} (and " + std::to_string(bad.size() - 1) +
            " more) still belongs to an encroached or not template-aware locally Delaunay "
            "triangle");
    }
    // Protection balls: recomputed every round, as the points put on an acute crease are
    // protected too (in 2D the corners are the input's and never move).
    // Mirror points first: a triangle none of whose mirror points went in (outside the leg, or
    // already a vertex) is bisected. An edge that a mirror point split is left to the next round.
    const auto inserted = insert_boundary_points(s, mirrors);
    std::size_t mirrored = 0;
    for (std::size_t n : inserted) mirrored += n;
    rep.crease_mirror_points += mirrored;
    for (const auto& [e, points] : fallback)
      if (std::none_of(points.begin(), points.end(), [&](std::size_t k) { return inserted[k]; }))
        bad.push_back(e);
    std::sort(bad.begin(), bad.end());
    bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
    if (mirrored)
      std::erase_if(bad, [&](const TemplateEdge& e) {
        return s.w[e.t].cells_with({e.a, e.b}).empty();
      });
    const auto protect = acute_corners(s);
    rep.bisections += bisect(s, bad, &protect);
    ++rep.rounds;
    if (progress) {
      std::size_t cells = 0;
      for (const auto& w : s.w) cells += w.cells.size();
      progress->message("Technique 5.8 round " + std::to_string(rep.rounds) + ": " +
                        std::to_string(bad.size()) + " boundary edges bisected (" +
                        (phase_tald ? "not template-aware locally Delaunay" : "encroached") +
                        "), " + std::to_string(mirrored) + " crease mirror points, " +
                        std::to_string(cells) + " template cells");
    }
  }
  return rep;
}

} // namespace symmesh::adapt::work
