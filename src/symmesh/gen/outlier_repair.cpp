// Outlier repair after TetGen (spec/generation.md#outlier-repair).
#include "symmesh/gen/outlier_repair.h"

#include "symmesh/mesh/quality.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace symmesh::gen {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Tet = std::array<std::size_t, 4>;
using Point = std::array<double, 3>;
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

/// The worst measures of a set of tetrahedra.
struct Worst {
  double radius_edge = 0, min_dihedral_deg = 180;
};

class Repair {
public:
  Repair(const SurfaceInput& s, TetrahedralMeshOutput& m, const OutlierBounds& b)
      : m_(m), b_(b), fixed_(s.points.size()) {
    for (auto f : s.triangles) {
      std::sort(f.begin(), f.end());
      constrained_.push_back(f);
    }
    std::sort(constrained_.begin(), constrained_.end());
    alive_.assign(m.tetrahedra.size(), 1);
    removed_.assign(m.points.size(), 0);
    build_incidence();
  }

  OutlierRepairReport run() {
    OutlierRepairReport r;
    std::vector<std::size_t> outliers;
    Worst all;
    for (std::size_t t = 0; t < m_.tetrahedra.size(); ++t) {
      const auto s = shape(m_.tetrahedra[t]);
      all.radius_edge = std::max(all.radius_edge, s.radius_edge_ratio);
      all.min_dihedral_deg = std::min(all.min_dihedral_deg, s.min_dihedral_deg);
      if (s.radius_edge_ratio > b_.radius_edge || s.min_dihedral_deg < b_.min_dihedral_deg)
        outliers.push_back(t);
    }
    // No change may make the mesh's worst measures worse than TetGen left them.
    limit_.radius_edge = std::min(b_.radius_edge, all.radius_edge);
    limit_.min_dihedral_deg = std::max(b_.min_dihedral_deg, all.min_dihedral_deg);
    r.outliers_before = outliers.size();
    for (std::size_t pass = 0; pass < b_.max_passes && !outliers.empty(); ++pass) {
      touched_.clear();
      std::size_t changes = 0;
      for (std::size_t t : outliers) {
        if (!alive_[t] || !is_outlier(m_.tetrahedra[t])) continue;
        if (flip_around(t)) {
          ++r.flips;
          ++changes;
        } else if (remove_a_vertex(t)) {
          ++r.removals;
          ++changes;
        } else if (move_a_vertex(t)) {
          ++r.moves;
          ++changes;
        }
      }
      if (changes == 0) break;
      // The next pass looks at the outliers that stayed and at every cell a change made.
      outliers.insert(outliers.end(), touched_.begin(), touched_.end());
      std::sort(outliers.begin(), outliers.end());
      outliers.erase(std::unique(outliers.begin(), outliers.end()), outliers.end());
      outliers.erase(std::remove_if(outliers.begin(), outliers.end(),
                                    [&](std::size_t t) {
                                      return !alive_[t] || !is_outlier(m_.tetrahedra[t]);
                                    }),
                     outliers.end());
    }
    // Every outlier left is one that stayed or one a change made: both are in the list.
    for (std::size_t t : outliers) r.outliers_after += alive_[t] && is_outlier(m_.tetrahedra[t]);
    compact();
    return r;
  }

private:
  TetrahedralMeshOutput& m_;
  OutlierBounds b_;
  Worst limit_; ///< how far a change may make a cell worse than the worst it replaces
  std::size_t fixed_;
  std::vector<std::array<std::size_t, 3>> constrained_;
  std::vector<char> alive_;
  std::vector<char> removed_; ///< per point: an added point the repair took out
  // Vertex-to-cell incidence: the cells of the input (CSR) plus the cells a change gave the
  // vertex since; an entry is stale when its cell no longer has the vertex (checked on use).
  std::vector<std::size_t> first_, cells_;
  std::unordered_map<std::size_t, std::vector<std::size_t>> added_;
  std::vector<std::size_t> touched_;

  void build_incidence() {
    first_.assign(m_.points.size() + 1, 0);
    for (const auto& t : m_.tetrahedra)
      for (std::size_t v : t) ++first_[v + 1];
    for (std::size_t v = 0; v < m_.points.size(); ++v) first_[v + 1] += first_[v];
    cells_.resize(first_.back());
    std::vector<std::size_t> at(first_.begin(), first_.end() - 1);
    for (std::size_t t = 0; t < m_.tetrahedra.size(); ++t)
      for (std::size_t v : m_.tetrahedra[t]) cells_[at[v]++] = t;
  }

  static bool has(const Tet& t, std::size_t v) {
    return std::find(t.begin(), t.end(), v) != t.end();
  }

  /// The live cells that contain every vertex of `verts`, in increasing order.
  std::vector<std::size_t> cells_with(std::initializer_list<std::size_t> verts) const {
    const std::size_t v0 = *verts.begin();
    std::vector<std::size_t> out;
    const auto consider = [&](std::size_t t) {
      if (!alive_[t]) return;
      for (std::size_t v : verts)
        if (!has(m_.tetrahedra[t], v)) return;
      out.push_back(t);
    };
    for (std::size_t k = first_[v0]; k < first_[v0 + 1]; ++k) consider(cells_[k]);
    if (const auto it = added_.find(v0); it != added_.end())
      for (std::size_t t : it->second) consider(t);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  bool is_constrained(std::array<std::size_t, 3> f) const {
    std::sort(f.begin(), f.end());
    return std::binary_search(constrained_.begin(), constrained_.end(), f);
  }

  const Point& at(std::size_t v, std::size_t moved, const Point* to) const {
    return v == moved ? *to : m_.points[v];
  }

  int orientation(const Tet& t, std::size_t moved = kNone, const Point* to = nullptr) const {
    const auto p = [&](int k) {
      const Point& q = at(t[std::size_t(k)], moved, to);
      return K::Point_3(q[0], q[1], q[2]);
    };
    return int(CGAL::orientation(p(0), p(1), p(2), p(3)));
  }

  mesh::TetrahedronShape shape(const Tet& t, std::size_t moved = kNone,
                               const Point* to = nullptr) const {
    return mesh::tetrahedron_shape(at(t[0], moved, to).data(), at(t[1], moved, to).data(),
                                   at(t[2], moved, to).data(), at(t[3], moved, to).data());
  }

  bool is_outlier(const Tet& t) const {
    const auto s = shape(t);
    return s.radius_edge_ratio > b_.radius_edge || s.min_dihedral_deg < b_.min_dihedral_deg;
  }

  Worst worst(const std::vector<Tet>& ts, std::size_t moved = kNone,
              const Point* to = nullptr) const {
    Worst w;
    for (const auto& t : ts) {
      const auto s = shape(t, moved, to);
      // A measure rounding made meaningless (a face normal of length zero in doubles) counts as
      // the worst one: std::min and std::max would skip a NaN.
      const bool meaningless = !std::isfinite(s.radius_edge_ratio) ||
                               !std::isfinite(s.min_dihedral_deg) ||
                               !std::isfinite(s.max_dihedral_deg);
      w.radius_edge = meaningless ? std::numeric_limits<double>::infinity()
                                  : std::max(w.radius_edge, s.radius_edge_ratio);
      w.min_dihedral_deg = meaningless ? 0 : std::min(w.min_dihedral_deg, s.min_dihedral_deg);
      if (meaningless) break;
    }
    return w;
  }

  /// The replacement is better: one measure that was beyond its bound improves, and neither
  /// measure ends beyond both its old value and its limit (the bound, or the mesh's worst value
  /// when that is within the bound).
  bool better(const Worst& before, const Worst& after) const {
    if (after.radius_edge > std::max(before.radius_edge, limit_.radius_edge)) return false;
    if (after.min_dihedral_deg < std::min(before.min_dihedral_deg, limit_.min_dihedral_deg))
      return false;
    return (before.radius_edge > b_.radius_edge && after.radius_edge < before.radius_edge) ||
           (before.min_dihedral_deg < b_.min_dihedral_deg &&
            after.min_dihedral_deg > before.min_dihedral_deg);
  }

  void replace(std::size_t t, const Tet& with) {
    m_.tetrahedra[t] = with;
    for (std::size_t v : with) added_[v].push_back(t);
    touched_.push_back(t);
  }

  std::size_t add(const Tet& t, int region) {
    m_.tetrahedra.push_back(t);
    m_.region.push_back(region);
    alive_.push_back(1);
    const std::size_t id = m_.tetrahedra.size() - 1;
    for (std::size_t v : t) added_[v].push_back(id);
    touched_.push_back(id);
    return id;
  }

  /// 2-3 flip of the facet of cell t opposite its vertex k.
  bool flip_2_3(std::size_t t, int k) {
    const Tet c0 = m_.tetrahedra[t];
    const std::size_t d = c0[std::size_t(k)];
    std::array<std::size_t, 3> f{};
    for (int j = 0, n = 0; j < 4; ++j)
      if (j != k) f[std::size_t(n++)] = c0[std::size_t(j)];
    if (is_constrained(f)) return false;
    const auto two = cells_with({f[0], f[1], f[2]});
    if (two.size() != 2) return false;
    const std::size_t u = two[0] == t ? two[1] : two[0];
    if (m_.region[u] != m_.region[t]) return false;
    const Tet c1 = m_.tetrahedra[u];
    std::size_t e = kNone;
    for (std::size_t v : c1)
      if (std::find(f.begin(), f.end(), v) == f.end()) e = v;
    if (e == kNone || !cells_with({d, e}).empty()) return false;
    // c0 is positive; with one facet vertex replaced by e, each of the three is positive exactly
    // when the segment de crosses the facet's interior.
    std::vector<Tet> fresh;
    for (int j = 0; j < 4; ++j) {
      if (j == k) continue;
      Tet n = c0;
      n[std::size_t(j)] = e;
      if (orientation(n) <= 0) return false;
      fresh.push_back(n);
    }
    if (!better(worst({c0, c1}), worst(fresh))) return false;
    replace(t, fresh[0]);
    replace(u, fresh[1]);
    add(fresh[2], m_.region[t]);
    return true;
  }

  /// 3-2 flip of edge {c[p], c[q]} of cell t when exactly three cells close around it.
  bool flip_3_2(std::size_t t, int p, int q) {
    const Tet c = m_.tetrahedra[t];
    const std::size_t d = c[std::size_t(p)], e = c[std::size_t(q)];
    const auto three = cells_with({d, e});
    if (three.size() != 3) return false;
    std::vector<std::pair<std::size_t, int>> ring;
    for (std::size_t u : three) {
      if (m_.region[u] != m_.region[t]) return false;
      for (std::size_t v : m_.tetrahedra[u]) {
        if (v == d || v == e) continue;
        auto it =
            std::find_if(ring.begin(), ring.end(), [&](const auto& r) { return r.first == v; });
        if (it == ring.end())
          ring.emplace_back(v, 1);
        else
          ++it->second;
      }
    }
    if (ring.size() != 3) return false;
    for (const auto& r : ring)
      if (r.second != 2) return false; // the cells do not close around the edge
    const std::size_t a = ring[0].first, b = ring[1].first, cc = ring[2].first;
    for (std::size_t v : {a, b, cc})
      if (is_constrained({d, e, v})) return false;
    if (!cells_with({a, b, cc}).empty()) return false;
    Tet n0{a, b, cc, d};
    const int od = orientation(n0);
    if (od == 0) return false;
    if (od < 0) std::swap(n0[0], n0[1]);
    Tet n1 = n0;
    n1[3] = e;
    // The ring surrounds the edge's line, so the edge crosses triangle abc iff d and e lie on
    // opposite sides of its plane.
    if (orientation(n1) >= 0) return false;
    std::swap(n1[0], n1[1]);
    const std::vector<Tet> old{m_.tetrahedra[three[0]], m_.tetrahedra[three[1]],
                               m_.tetrahedra[three[2]]};
    if (!better(worst(old), worst({n0, n1}))) return false;
    replace(three[0], n0);
    replace(three[1], n1);
    alive_[three[2]] = 0;
    return true;
  }

  bool flip_around(std::size_t t) {
    for (int k = 0; k < 4; ++k)
      if (flip_2_3(t, k)) return true;
    for (int p = 0; p < 4; ++p)
      for (int q = p + 1; q < 4; ++q)
        if (flip_3_2(t, p, q)) return true;
    return false;
  }

  /// Moves v to `to` when every cell around it stays positive and the move is better.
  bool try_move(std::size_t v, const std::vector<std::size_t>& star, const Point& to) {
    if (!std::isfinite(to[0]) || !std::isfinite(to[1]) || !std::isfinite(to[2])) return false;
    std::vector<Tet> cells;
    for (std::size_t t : star) {
      if (orientation(m_.tetrahedra[t], v, &to) <= 0) return false;
      cells.push_back(m_.tetrahedra[t]);
    }
    if (!better(worst(cells), worst(cells, v, &to))) return false;
    m_.points[v] = to;
    touched_.insert(touched_.end(), star.begin(), star.end());
    return true;
  }

  /// A vertex of t that TetGen added inside the domain moves: to the mean of its neighbours
  /// (or halfway there), else by a pattern search along the axes with steps of a fifth, a tenth
  /// and a twentieth of its shortest edge.
  bool move_a_vertex(std::size_t t) {
    const Tet c = m_.tetrahedra[t];
    for (std::size_t v : c) {
      if (v < fixed_) continue; // a surface point never moves
      const auto star = cells_with({v});
      std::vector<std::size_t> around;
      for (std::size_t u : star)
        for (std::size_t w : m_.tetrahedra[u])
          if (w != v) around.push_back(w);
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      Point mean{0, 0, 0};
      double shortest = std::numeric_limits<double>::infinity();
      const Point here = m_.points[v];
      for (std::size_t w : around) {
        double l2 = 0;
        for (int k = 0; k < 3; ++k) {
          mean[std::size_t(k)] += m_.points[w][std::size_t(k)] / double(around.size());
          const double dk = m_.points[w][std::size_t(k)] - here[std::size_t(k)];
          l2 += dk * dk;
        }
        shortest = std::min(shortest, std::sqrt(l2));
      }
      if (try_move(v, star, mean)) return true;
      const Point half{(here[0] + mean[0]) / 2, (here[1] + mean[1]) / 2, (here[2] + mean[2]) / 2};
      if (try_move(v, star, half)) return true;
      bool moved = false;
      for (double step : {shortest / 5, shortest / 10, shortest / 20})
        for (int round = 0; round < 4; ++round) {
          bool any = false;
          for (int axis = 0; axis < 3; ++axis)
            for (double sign : {1.0, -1.0}) {
              Point to = m_.points[v];
              to[std::size_t(axis)] += sign * step;
              if (try_move(v, star, to)) any = moved = true;
            }
          if (!any) break;
        }
      if (moved) return true;
    }
    return false;
  }

  static double volume(const Point& a, const Point& b, const Point& c, const Point& d) {
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
            u[2] * (v[0] * w[1] - v[1] * w[0])) /
           6;
  }

  using Face = std::array<std::size_t, 3>;

  /// The face of t opposite t[i], ordered so that (face, t[i]) has t's orientation.
  static Face face_towards(const Tet& t, int i) {
    Face f{};
    for (int j = 0, n = 0; j < 4; ++j)
      if (j != i) f[std::size_t(n++)] = t[std::size_t(j)];
    if ((3 - i) % 2 == 1) std::swap(f[0], f[1]); // moving t[i] last took 3 - i transpositions
    return f;
  }

  static Face key(Face f) {
    std::sort(f.begin(), f.end());
    return f;
  }

  /// A search for a tetrahedralization of a cavity without its inner point: every cell joins an
  /// open face (its open side towards the cavity still to fill) to a cavity vertex.
  struct CavitySearch {
    const Repair& r;
    const std::vector<std::size_t>& vertices;
    Worst before, best_worst;
    std::vector<Tet> chosen, best;
    std::map<Face, Face> open; ///< key -> the face oriented with its open side positive
    std::size_t nodes = 0;

    void run() {
      if (open.empty()) {
        const Worst w = r.worst(chosen);
        if (r.better(before, w) && (best.empty() || w.radius_edge < best_worst.radius_edge ||
                                    (w.radius_edge == best_worst.radius_edge &&
                                     w.min_dihedral_deg > best_worst.min_dihedral_deg))) {
          best = chosen;
          best_worst = w;
        }
        return;
      }
      const Face f = open.begin()->second;
      for (std::size_t x : vertices) {
        if (++nodes > kMaxNodes) return;
        if (x == f[0] || x == f[1] || x == f[2]) continue;
        const Tet n{f[0], f[1], f[2], x};
        if (r.orientation(n) <= 0 || !acceptable(n)) continue;
        // The other three faces of n close an open face facing them or open up.
        std::vector<std::pair<Face, Face>> closed, opened;
        bool fits = true;
        for (int i = 0; i < 3 && fits; ++i) {
          Face g = face_towards(n, i);
          std::swap(g[0], g[1]); // its open side is outside n
          const auto it = open.find(key(g));
          if (it == open.end()) {
            opened.emplace_back(key(g), g);
          } else if (r.orientation({it->second[0], it->second[1], it->second[2], n[i]}) > 0) {
            closed.emplace_back(*it); // the open face looks into n: shared, both sides filled
          } else {
            fits = false; // two cells on the same side of a face
          }
        }
        if (!fits) continue;
        const auto first = *open.begin();
        open.erase(open.begin());
        for (const auto& c : closed) open.erase(c.first);
        for (const auto& o : opened) open.insert(o);
        chosen.push_back(n);
        run();
        chosen.pop_back();
        for (const auto& o : opened) open.erase(o.first);
        for (const auto& c : closed) open.insert(c);
        open.insert(first);
      }
    }

    bool acceptable(const Tet& n) const {
      const Worst w = r.worst({n});
      if (w.radius_edge > std::max(before.radius_edge, r.limit_.radius_edge)) return false;
      if (w.min_dihedral_deg < std::min(before.min_dihedral_deg, r.limit_.min_dihedral_deg))
        return false;
      if (!best.empty() && w.radius_edge >= best_worst.radius_edge) return false;
      const auto& p = r.m_.points;
      return volume(p[n[0]], p[n[1]], p[n[2]], p[n[3]]) <= r.b_.max_volume;
    }
  };
  static constexpr std::size_t kMaxNodes = 20000;

  /// Takes out a vertex of t that TetGen added inside the domain (in a domain thinner than the
  /// size, such a point is what makes the flat cells, and no move of it helps). Its star, a
  /// closed ball in one region, is tetrahedralized anew on its link vertices by a bounded
  /// search: positive cells whose faces pair up inside and give exactly the link's oriented
  /// triangles outside; for such a chain the link winds once around every point of the star,
  /// so positive cells cover it exactly once, a tiling that keeps the link as faces. The best
  /// replacement (smallest worst ratio, then largest smallest dihedral angle) wins if it is
  /// better; no cell may exceed the volume bound TetGen was given, so the size request holds.
  bool remove_a_vertex(std::size_t t) {
    const Tet c = m_.tetrahedra[t];
    for (std::size_t v : c) {
      if (v < fixed_) continue; // a surface point is never taken out
      const auto star = cells_with({v});
      std::vector<Tet> old;
      std::vector<std::size_t> link;
      bool one_region = true;
      for (std::size_t u : star) {
        one_region = one_region && m_.region[u] == m_.region[star[0]];
        old.push_back(m_.tetrahedra[u]);
        for (std::size_t w : m_.tetrahedra[u])
          if (w != v) link.push_back(w);
      }
      if (star.size() < 4 || !one_region) continue;
      std::sort(link.begin(), link.end());
      link.erase(std::unique(link.begin(), link.end()), link.end());
      CavitySearch s{*this, link, worst(old), {}, {}, {}, {}, 0};
      for (const Tet& o : old) {
        const int i = int(std::find(o.begin(), o.end(), v) - o.begin());
        const Face f = face_towards(o, i);
        s.open.emplace(key(f), f);
      }
      s.run();
      if (s.best.empty()) continue;
      for (std::size_t k = 0; k < std::max(star.size(), s.best.size()); ++k) {
        if (k < star.size() && k < s.best.size())
          replace(star[k], s.best[k]);
        else if (k < star.size())
          alive_[star[k]] = 0;
        else
          add(s.best[k], m_.region[star[0]]);
      }
      removed_[v] = 1;
      return true;
    }
    return false;
  }

  /// Drops dead cells and the points taken out (only added points: the surface points keep
  /// their ids, which the SVB refers to).
  void compact() {
    std::vector<std::size_t> id(m_.points.size());
    std::size_t kept = 0;
    for (std::size_t v = 0; v < m_.points.size(); ++v) {
      id[v] = kept;
      if (!removed_[v]) m_.points[kept++] = m_.points[v];
    }
    m_.points.resize(kept);
    std::size_t n = 0;
    for (std::size_t t = 0; t < m_.tetrahedra.size(); ++t) {
      if (!alive_[t]) continue;
      for (std::size_t& v : m_.tetrahedra[t]) v = id[v];
      m_.tetrahedra[n] = m_.tetrahedra[t];
      m_.region[n] = m_.region[t];
      ++n;
    }
    m_.tetrahedra.resize(n);
    m_.region.resize(n);
  }
};
} // namespace

OutlierRepairReport repair_outliers(const SurfaceInput& surface, TetrahedralMeshOutput& m,
                                    const OutlierBounds& b) {
  if (!(b.radius_edge >= 1) || !(b.min_dihedral_deg >= 0) || !(b.max_volume > 0))
    throw std::invalid_argument("outlier bounds: radius-edge below 1, negative dihedral angle or "
                                "volume bound not positive");
  if (m.region.size() != m.tetrahedra.size() || m.points.size() < surface.points.size())
    throw std::invalid_argument("outlier repair: not a mesh of this surface");
  return Repair(surface, m, b).run();
}

} // namespace symmesh::gen
