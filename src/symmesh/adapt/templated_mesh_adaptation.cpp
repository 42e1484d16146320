// Section 5.2 and Technique 5.8 on a generated templated mesh — spec/adaptation.md#tmesh-adaptation
#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/adapt/adaptation_work.h"
#include "symmesh/adapt/tmesh_template_cloning.h"
#include "symmesh/gen/tetrahedral_mesher.h"
#include "symmesh/mesh/structure_instance.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <tuple>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numbers>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

namespace symmesh::adapt::work {

std::array<double, 3> sub3(const double* a, const double* b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
std::array<double, 3> cross3(const std::array<double, 3>& u, const std::array<double, 3>& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
double dot3(const std::array<double, 3>& u, const std::array<double, 3>& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

P2 p2(const double* q) {
  return P2(q[0], q[1]);
}
P3 p3(const double* q) {
  return P3(q[0], q[1], q[2]);
}

/// Orientation sign of a cell (exact on the doubles), with vertex `moved` read at `at` if given.
int orientation(const Work& w, const Cell& c, IndexType moved, const double* at) {
  const auto q = [&](int k) {
    const IndexType v = c[std::size_t(k)];
    return v == moved ? at : w.p(v);
  };
  if (w.d == 2) return int(CGAL::orientation(p2(q(0)), p2(q(1)), p2(q(2))));
  return int(CGAL::orientation(p3(q(0)), p3(q(1)), p3(q(2)), p3(q(3))));
}

/// Positive (exact) and not flat to rounding: d!·|cell| / L^d > 1e-9, L the longest edge, with
/// vertex `moved` read at `at` if given. AT's writers use one coordinate per shared vertex, taken
/// from one of its instances, so a cell is written with coordinates that differ from its own
/// image by rounding; and a later bisection puts its midpoint at a rounded place. Only a cell this
/// far from flat stays positive in every written copy and in its children (a smoothing that kept
/// cells merely positive let fuzz_adapt invert a child after --refine-where on the 8-TSV).
bool robustly_positive(const Work& w, const Cell& c, IndexType moved, const double* at) {
  if (orientation(w, c, moved, at) <= 0) return false;
  const auto q = [&](int k) {
    const IndexType v = c[std::size_t(k)];
    return v == moved ? at : w.p(v);
  };
  double longest = 0;
  for (int i = 0; i <= w.d; ++i)
    for (int j = i + 1; j <= w.d; ++j) {
      double l = 0;
      for (int k = 0; k < w.d; ++k) l += (q(i)[k] - q(j)[k]) * (q(i)[k] - q(j)[k]);
      longest = std::max(longest, l);
    }
  longest = std::sqrt(longest);
  if (w.d == 2) {
    const double cross =
        (q(1)[0] - q(0)[0]) * (q(2)[1] - q(0)[1]) - (q(1)[1] - q(0)[1]) * (q(2)[0] - q(0)[0]);
    return cross > 1e-9 * longest * longest;
  }
  const auto u = sub3(q(1), q(0)), v = sub3(q(2), q(0)), x = sub3(q(3), q(0));
  return dot3(cross3(u, v), x) > 1e-9 * longest * longest * longest;
}

double angle_between(const double* u, const double* v, int d) {
  double dot = 0, uu = 0, vv = 0;
  for (int i = 0; i < d; ++i) dot += u[i] * v[i], uu += u[i] * u[i], vv += v[i] * v[i];
  const double c = std::clamp(dot / std::sqrt(uu * vv), -1.0, 1.0);
  return std::acos(c) * 180 / std::numbers::pi;
}

/// Smallest angle (triangle) or dihedral angle (tetrahedron) in degrees; 0 for a flat cell.
double cell_quality(const Work& w, const Cell& c, IndexType moved, const double* at) {
  const auto q = [&](int k) {
    const IndexType v = c[std::size_t(k)];
    return v == moved ? at : w.p(v);
  };
  double best = 180;
  if (w.d == 2) {
    for (int k = 0; k < 3; ++k) {
      const double *o = q(k), *a = q((k + 1) % 3), *b = q((k + 2) % 3);
      const double u[2] = {a[0] - o[0], a[1] - o[1]}, v[2] = {b[0] - o[0], b[1] - o[1]};
      best = std::min(best, angle_between(u, v, 2));
    }
    return best;
  }
  static constexpr int pairs[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                      {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for (const auto& e : pairs) {
    const double *pi = q(e[0]), *pj = q(e[1]), *pk = q(e[2]), *pl = q(e[3]);
    double t[3], u[3], v[3];
    double tt = 0;
    for (int i = 0; i < 3; ++i) t[i] = pj[i] - pi[i], tt += t[i] * t[i];
    double uk = 0, vl = 0;
    for (int i = 0; i < 3; ++i) uk += (pk[i] - pi[i]) * t[i], vl += (pl[i] - pi[i]) * t[i];
    for (int i = 0; i < 3; ++i) {
      u[i] = pk[i] - pi[i] - uk / tt * t[i];
      v[i] = pl[i] - pi[i] - vl / tt * t[i];
    }
    best = std::min(best, angle_between(u, v, 3));
  }
  return best;
}

/// The facets (d vertices) of a cell.
std::vector<std::vector<IndexType>> facets_of(const Work& w, const Cell& c) {
  std::vector<std::vector<IndexType>> out;
  for (int skip = 0; skip < w.arity(); ++skip) {
    std::vector<IndexType> f;
    for (int k = 0; k < w.arity(); ++k)
      if (k != skip) f.push_back(c[std::size_t(k)]);
    std::sort(f.begin(), f.end());
    out.push_back(f);
  }
  return out;
}

std::size_t facet_cell_count(const Work& w, const std::vector<IndexType>& f) {
  std::size_t n = 0;
  for (IndexType ci : w.inc[std::size_t(f[0])]) {
    bool all = true;
    for (IndexType v : f) all = all && w.has(w.cells[std::size_t(ci)], v);
    n += all;
  }
  return n;
}

/// Whether edge {a, b} lies on the template boundary (on a facet of exactly one cell).
bool is_boundary_edge(const Work& w, IndexType a, IndexType b) {
  const auto around = w.cells_with({a, b});
  if (w.d == 2) return around.size() == 1;
  for (IndexType ci : around)
    for (IndexType v : w.cells[std::size_t(ci)])
      if (v != a && v != b && facet_cell_count(w, {a, b, v}) == 1) return true;
  return false;
}

/// The vertices on some boundary facet.
std::vector<char> boundary_vertices(const Work& w) {
  std::vector<char> on(w.vertex_count(), 0);
  for (const auto& c : w.cells)
    for (const auto& f : facets_of(w, c))
      if (facet_cell_count(w, f) == 1)
        for (IndexType v : f) on[std::size_t(v)] = 1;
  return on;
}

std::vector<TableIndex> index_tables(const mesh::TemplatedMeshCompactSvb& t) {
  std::vector<TableIndex> out(t.tables.size());
  for (std::size_t k = 0; k < t.tables.size(); ++k)
    for (auto [a, b] : t.tables[k].pairs) {
      out[k].fwd.emplace(a, b);
      out[k].bwd.emplace(b, a);
    }
  return out;
}

std::vector<TableView> tables_from(const Session& s, const std::vector<TableIndex>& index,
                                   std::size_t t) {
  std::vector<TableView> out;
  for (std::size_t k = 0; k < s.t.tables.size(); ++k)
    for (bool forward : {true, false}) {
      const auto& table = s.t.tables[k];
      if (std::size_t(forward ? table.from_template : table.to_template) != t) continue;
      out.push_back({forward ? &index[k].fwd : &index[k].bwd,
                     std::size_t(forward ? table.to_template : table.from_template)});
    }
  return out;
}

TemplateEdge edge_of(std::size_t t, IndexType a, IndexType b) {
  return {t, std::min(a, b), std::max(a, b)};
}

/// The related edge of e across table k in direction `forward`, if it is a boundary edge there.
bool related_edge(const Session& s, const std::vector<TableIndex>& index, std::size_t k,
                  bool forward, const TemplateEdge& e, TemplateEdge& out) {
  const auto& table = s.t.tables[k];
  if (std::size_t(forward ? table.from_template : table.to_template) != e.t) return false;
  const auto& map = forward ? index[k].fwd : index[k].bwd;
  const auto ia = map.find(e.a), ib = map.find(e.b);
  if (ia == map.end() || ib == map.end()) return false;
  const auto other = std::size_t(forward ? table.to_template : table.from_template);
  if (!is_boundary_edge(s.w[other], ia->second, ib->second)) return false;
  out = edge_of(other, ia->second, ib->second);
  return true;
}

/// Splits every cell on edge {a, b} of w at new vertex m (in place: a -> m, then b -> m).
void split_edge(Work& w, IndexType a, IndexType b, IndexType m) {
  for (IndexType ci : w.cells_with({a, b})) {
    Cell first = w.cells[std::size_t(ci)], second = first;
    std::replace(first.begin(), first.begin() + w.arity(), a, m);
    std::replace(second.begin(), second.begin() + w.arity(), b, m);
    w.set_cell(ci, first);
    w.add_cell(second);
  }
}

/// 2D: the boundary vertices at which the template's cells meet with an angle sum below 90°.
std::vector<char> acute_corners_2d(const Work& w) {
  std::vector<double> angle(w.vertex_count(), 0);
  for (const auto& c : w.cells)
    for (int k = 0; k < 3; ++k) {
      const double *o = w.p(c[std::size_t(k)]), *a = w.p(c[std::size_t((k + 1) % 3)]),
                   *b = w.p(c[std::size_t((k + 2) % 3)]);
      const double u[2] = {a[0] - o[0], a[1] - o[1]}, v[2] = {b[0] - o[0], b[1] - o[1]};
      angle[std::size_t(c[std::size_t(k)])] += angle_between(u, v, 2);
    }
  const auto on = boundary_vertices(w);
  std::vector<char> acute(w.vertex_count(), 0);
  for (std::size_t v = 0; v < acute.size(); ++v) acute[v] = on[v] && angle[v] < 90;
  return acute;
}

std::map<std::pair<IndexType, IndexType>, double> dihedral_angle_sums(const Work& w) {
  std::map<std::pair<IndexType, IndexType>, double> dihedral;
  for (const auto& c : w.cells)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        int k = 0;
        while (k == i || k == j) ++k;
        const int l = 6 - i - j - k;
        const IndexType a = c[std::size_t(i)], b = c[std::size_t(j)];
        // The angle between the normals of faces (a, b, c_k) and (a, b, c_l) is the cell's
        // dihedral angle at edge ab.
        const auto ab = sub3(w.p(b), w.p(a));
        const auto n1 = cross3(ab, sub3(w.p(c[std::size_t(k)]), w.p(a)));
        const auto n2 = cross3(ab, sub3(w.p(c[std::size_t(l)]), w.p(a)));
        dihedral[{std::min(a, b), std::max(a, b)}] += angle_between(n1.data(), n2.data(), 3);
      }
  return dihedral;
}

/// 3D: the ends of the template boundary edges at which the template's cells meet with a
/// dihedral angle sum below 60° — the acute creases. In a cross-section through a crease the
/// crease is an acute corner; a point put on the crease is protected like its ends. Ping-pong
/// encroachment needs angles of at most 45° (Section 5.2.5). With 90° as in 2D, the slices of
/// the 16-, 32- and 128-TSV had protected creases (between 60° and 90°) whose shell points made
/// slivers that no flip or vertex move removed.
std::vector<char> acute_creases_3d(const Work& w) {
  const auto dihedral = dihedral_angle_sums(w);
  std::vector<char> acute(w.vertex_count(), 0);
  for (const auto& [e, angle] : dihedral)
    if (angle < 60 && is_boundary_edge(w, e.first, e.second))
      acute[std::size_t(e.first)] = acute[std::size_t(e.second)] = 1;
  return acute;
}

/// The protected vertices: acute template corners (2D) or crease ends (3D), closed under the
/// identification tables.
Protected acute_corners(const Session& s) {
  Protected out;
  for (const auto& w : s.w) out.push_back(w.d == 2 ? acute_corners_2d(w) : acute_creases_3d(w));
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& table : s.t.tables)
      for (const auto& [a, b] : table.pairs) {
        auto& pa = out[std::size_t(table.from_template)][std::size_t(a)];
        auto& pb = out[std::size_t(table.to_template)][std::size_t(b)];
        if (pa != pb) pa = pb = 1, changed = true;
      }
  }
  return out;
}

/// Whether exactly one end of {a, b} is protected, and which: the end the split is measured from.
bool protected_end(IndexType a, IndexType b, const std::vector<char>* protect, IndexType& from,
                   IndexType& to) {
  const auto is = [&](IndexType v) {
    return protect && std::size_t(v) < protect->size() && (*protect)[std::size_t(v)];
  };
  from = is(b) ? b : a;
  to = from == a ? b : a;
  return is(a) != is(b);
}

/// Where edge {a, b} is split, as a fraction of its length from its protected end: 1/2, or —
/// when exactly one end is a protected corner — the power of two nearest to half the length
/// (concentric shells: the pieces next to a corner then have power-of-two lengths, so the two
/// sides of an acute corner end with equal pieces and stop encroaching on each other).
double split_fraction(const Work& w, IndexType a, IndexType b, const std::vector<char>* protect) {
  IndexType from = a, to = b;
  if (!protected_end(a, b, protect, from, to)) return 0.5;
  double ll = 0;
  for (int i = 0; i < w.d; ++i) ll += std::pow(w.p(to)[i] - w.p(from)[i], 2);
  const double length = std::sqrt(ll);
  return std::exp2(std::round(std::log2(length / 2))) / length; // in [0.35, 0.71]
}

/// The point at fraction f of edge {a, b} from its protected end (from a when none is).
void split_point(const Work& w, IndexType a, IndexType b, const std::vector<char>* protect,
                 double f, double* q) {
  IndexType from = a, to = b;
  protected_end(a, b, protect, from, to);
  for (int i = 0; i < w.d; ++i) q[i] = w.p(from)[i] + f * (w.p(to)[i] - w.p(from)[i]);
}

/// Calls visit(r) for every edge r related to e through one table (either way), and keeps going
/// from every r for which visit returns true.
template <class Visit>
void walk_related(const Session& s, const std::vector<TableIndex>& index, const TemplateEdge& e,
                  Visit&& visit) {
  std::vector<TemplateEdge> stack{e};
  while (!stack.empty()) {
    const auto x = stack.back();
    stack.pop_back();
    for (std::size_t k = 0; k < s.t.tables.size(); ++k)
      for (bool forward : {true, false}) {
        TemplateEdge r;
        if (related_edge(s, index, k, forward, x, r) && visit(r)) stack.push_back(r);
      }
  }
}

std::size_t bisect(Session& s, const std::vector<TemplateEdge>& edges, const Protected* protect) {
  const auto index = index_tables(s.t);
  std::set<TemplateEdge> closure;
  for (const auto& e : edges) {
    const auto n = edge_of(e.t, e.a, e.b);
    if (e.t >= s.w.size() || s.w[e.t].cells_with({n.a, n.b}).empty())
      throw std::invalid_argument("bisect: {" + std::to_string(e.a) + ", " + std::to_string(e.b) +
                                  "} is no edge of template " + std::to_string(e.t));
    if (closure.insert(n).second)
      walk_related(s, index, n, [&](const TemplateEdge& r) { return closure.insert(r).second; });
  }
  // One split fraction per class of related edges, taken from its first edge: the copies'
  // lengths differ by the rounding of their templates' coordinates, and two copies of one edge
  // of AT must not round to different shells (related ends share protection, so the fraction
  // is measured from the same end of AT's edge).
  const auto protect_of = [&](std::size_t t) { return protect ? &(*protect)[t] : nullptr; };
  std::map<TemplateEdge, double> fraction;
  for (const auto& root : closure) {
    if (fraction.count(root)) continue;
    const double f = split_fraction(s.w[root.t], root.a, root.b, protect_of(root.t));
    fraction.emplace(root, f);
    walk_related(s, index, root,
                 [&](const TemplateEdge& r) { return fraction.emplace(r, f).second; });
  }
  std::map<TemplateEdge, IndexType> mid;
  for (const auto& e : closure) {
    auto& w = s.w[e.t];
    double q[3];
    split_point(w, e.a, e.b, protect_of(e.t), fraction.at(e), q);
    const IndexType m = w.add_vertex(q);
    split_edge(w, e.a, e.b, m);
    mid[e] = m;
  }
  for (std::size_t k = 0; k < s.t.tables.size(); ++k) {
    auto& table = s.t.tables[k];
    for (const auto& e : closure) {
      if (std::size_t(table.from_template) != e.t) continue;
      const auto ia = index[k].fwd.find(e.a), ib = index[k].fwd.find(e.b);
      if (ia == index[k].fwd.end() || ib == index[k].fwd.end()) continue;
      const auto to = mid.find(edge_of(std::size_t(table.to_template), ia->second, ib->second));
      if (to != mid.end()) table.pairs.emplace_back(mid[e], to->second);
    }
  }
  return closure.size();
}

/// Lawson flips in a triangle template; returns the flips.
std::size_t lawson(Work& w) {
  std::vector<std::pair<IndexType, IndexType>> stack;
  for (const auto& c : w.cells)
    for (int k = 0; k < 3; ++k) stack.emplace_back(c[std::size_t(k)], c[std::size_t((k + 1) % 3)]);
  std::size_t flips = 0;
  const std::size_t cap = 64 * (w.cells.size() + 16) * (w.cells.size() + 16);
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    const auto around = w.cells_with({a, b});
    if (around.size() != 2) continue;
    const Cell c0 = w.cells[std::size_t(around[0])], c1 = w.cells[std::size_t(around[1])];
    IndexType c = -1, d = -1;
    for (int k = 0; k < 3; ++k) {
      if (c0[std::size_t(k)] != a && c0[std::size_t(k)] != b) c = c0[std::size_t(k)];
      if (c1[std::size_t(k)] != a && c1[std::size_t(k)] != b) d = c1[std::size_t(k)];
    }
    if (CGAL::side_of_oriented_circle(p2(w.p(c0[0])), p2(w.p(c0[1])), p2(w.p(c0[2])), p2(w.p(d))) !=
        CGAL::ON_POSITIVE_SIDE)
      continue;
    Cell n0{c, a, d, 0}, n1{c, d, b, 0};
    if (orientation(w, n0) < 0) std::swap(n0[1], n0[2]);
    if (orientation(w, n1) < 0) std::swap(n1[1], n1[2]);
    if (orientation(w, n0) <= 0 || orientation(w, n1) <= 0) continue; // not strictly convex
    w.set_cell(around[0], n0);
    w.set_cell(around[1], n1);
    if (++flips > cap) throw std::logic_error("Lawson flips did not terminate (a defect)");
    stack.insert(stack.end(), {{a, c}, {c, b}, {b, d}, {d, a}});
  }
  return flips;
}

/// The smallest quality of the given cells.
double min_quality(const Work& w, std::initializer_list<Cell> cells) {
  double q = 180;
  for (const auto& c : cells) q = std::min(q, cell_quality(w, c));
  return q;
}

/// Removes a cell; the last cell takes its index.
void remove_cell(Work& w, IndexType ci) {
  const auto last = IndexType(w.cells.size() - 1);
  for (int k = 0; k < w.arity(); ++k) {
    auto& list = w.inc[std::size_t(w.cells[std::size_t(ci)][std::size_t(k)])];
    list.erase(std::find(list.begin(), list.end(), ci));
  }
  if (ci != last) {
    for (int k = 0; k < w.arity(); ++k)
      std::replace(w.inc[std::size_t(w.cells[std::size_t(last)][std::size_t(k)])].begin(),
                   w.inc[std::size_t(w.cells[std::size_t(last)][std::size_t(k)])].end(), last, ci);
    w.cells[std::size_t(ci)] = w.cells[std::size_t(last)];
  }
  w.cells.pop_back();
}

/// 2-3 flip of the facet of cell ci opposite its vertex `skip`, shared with one more cell, when
/// the new edge crosses the facet (the three new cells are then positive) and the smallest
/// dihedral angle grows.
bool quality_flip_2_3(Work& w, IndexType ci, int skip, const CellTest* also) {
  const Cell c0 = w.cells[std::size_t(ci)];
  const IndexType d = c0[std::size_t(skip)];
  std::vector<IndexType> f;
  for (int k = 0; k < 4; ++k)
    if (k != skip) f.push_back(c0[std::size_t(k)]);
  const auto two = w.cells_with({f[0], f[1], f[2]});
  if (two.size() != 2) return false; // a template boundary facet: never flipped
  const IndexType cj = two[0] == ci ? two[1] : two[0];
  const Cell c1 = w.cells[std::size_t(cj)];
  IndexType e = -1;
  for (int k = 0; k < 4; ++k)
    if (std::find(f.begin(), f.end(), c1[std::size_t(k)]) == f.end()) e = c1[std::size_t(k)];
  if (e < 0 || !w.cells_with({d, e}).empty()) return false;
  // c0 is positive; replacing one facet vertex by e gives a positive cell for each of the three
  // exactly when the segment de crosses the facet's interior.
  std::array<Cell, 3> n;
  for (int k = 0, m = 0; k < 4; ++k) {
    if (k == skip) continue;
    n[std::size_t(m)] = c0;
    n[std::size_t(m)][std::size_t(k)] = e;
    if (orientation(w, n[std::size_t(m)]) <= 0) return false;
    ++m;
  }
  // With `also` (sliver removal) the count of cells failing it falls instead.
  if (!also && !(min_quality(w, {n[0], n[1], n[2]}) > min_quality(w, {c0, c1}))) return false;
  if (also && !((*also)(n[0]) && (*also)(n[1]) && (*also)(n[2]))) return false;
  w.set_cell(ci, n[0]);
  w.set_cell(cj, n[1]);
  w.add_cell(n[2]);
  return true;
}

/// 3-2 flip of edge {d, e} of cell ci when exactly three cells close around it (so it is no
/// template boundary edge), the new facet does not exist yet, the edge crosses it, and the
/// smallest dihedral angle grows.
bool quality_flip_3_2(Work& w, IndexType ci, int p, int q, const CellTest* also) {
  const Cell c0 = w.cells[std::size_t(ci)];
  const IndexType d = c0[std::size_t(p)], e = c0[std::size_t(q)];
  const auto three = w.cells_with({d, e});
  if (three.size() != 3) return false;
  std::map<IndexType, int> ring;
  for (IndexType cj : three)
    for (IndexType v : w.cells[std::size_t(cj)])
      if (v != d && v != e) ++ring[v];
  if (ring.size() != 3) return false;
  for (const auto& r : ring)
    if (r.second != 2) return false; // the cells do not close around the edge
  auto it = ring.begin();
  const IndexType a = (it++)->first, b = (it++)->first, c = it->first;
  if (!w.cells_with({a, b, c}).empty()) return false;
  Cell n0{a, b, c, d};
  const int od = orientation(w, n0);
  if (od == 0) return false;
  if (od < 0) std::swap(n0[0], n0[1]);
  Cell n1 = n0;
  n1[3] = e;
  // The ring surrounds the edge's line, so the edge crosses triangle abc iff d and e lie on
  // opposite sides of its plane.
  if (orientation(w, n1) >= 0) return false;
  std::swap(n1[0], n1[1]);
  const Cell o0 = w.cells[std::size_t(three[0])], o1 = w.cells[std::size_t(three[1])],
             o2 = w.cells[std::size_t(three[2])];
  if (!(min_quality(w, {n0, n1}) > min_quality(w, {o0, o1, o2}))) return false;
  if (also && !((*also)(n0) && (*also)(n1))) return false;
  w.set_cell(three[0], n0);
  w.set_cell(three[1], n1);
  remove_cell(w, three[2]);
  return true;
}

/// Section 5.2.6 in 3D: 2-3, 3-2 and 4-4 flips inside a tetrahedral template, each made only
/// when it raises the smallest dihedral angle of the cells it replaces. Facets on the template
/// boundary are never flipped (Section 5.2.3; a 4-4 flip needs a closed ring of four cells, so
/// its edge is template-interior), so every instance changes alike. Each flip raises the sorted
/// vector of cell qualities, so the sweeps end. Returns the flip count.
std::size_t quality_flips_3d(Work& w) {
  static const CellTest any = [](const Cell&) { return true; };
  std::size_t flips = 0;
  const std::size_t cap = 64 * (w.cells.size() + 16);
  for (bool again = true; again;) {
    again = false;
    for (IndexType ci = 0; ci < IndexType(w.cells.size()); ++ci) {
      bool flipped = false;
      for (int skip = 0; skip < 4 && !flipped; ++skip) flipped = quality_flip_2_3(w, ci, skip);
      for (int p = 0; p < 4 && !flipped; ++p)
        for (int q = p + 1; q < 4 && !flipped; ++q) flipped = quality_flip_3_2(w, ci, p, q);
      for (int p = 0; p < 4 && !flipped; ++p)
        for (int q = p + 1; q < 4 && !flipped; ++q)
          flipped = remove_edge(w, ci, p, q, any, 4, true);
      if (!flipped) continue;
      again = true;
      if (++flips > cap) throw std::logic_error("quality flips did not end (a defect)");
    }
  }
  return flips;
}

/// The vertex of a cell (d + 1 vertices) that is not on its facet f (d vertices): the apex
/// across f, in 2D (f an edge) and 3D (f a triangle) alike.
IndexType apex(const Cell& c, std::initializer_list<IndexType> f) {
  for (std::size_t k = 0; k <= f.size(); ++k)
    if (std::find(f.begin(), f.end(), c[k]) == f.end()) return c[k];
  return -1;
}
IndexType apex(const Cell& c, const std::array<IndexType, 3>& f) {
  return apex(c, {f[0], f[1], f[2]});
}

P2 image(const Session& s, std::size_t instance, IndexType v) {
  double q[2];
  s.transformation(instance).apply(s.w[s.template_of[instance]].p(v), q);
  return P2(q[0], q[1]);
}

/// Whether the cell of instance i on edge {a, b} has instance j's apex strictly inside its
/// circumcircle, in AT's coordinates.
bool encroached(const Session& s, std::size_t i, IndexType a, IndexType b, std::size_t j,
                IndexType ja, IndexType jb) {
  const auto& wi = s.w[s.template_of[i]];
  const auto& wj = s.w[s.template_of[j]];
  const auto ci = wi.cells_with({a, b}), cj = wj.cells_with({ja, jb});
  if (ci.size() != 1 || cj.size() != 1) return false;
  const IndexType c = apex(wi.cells[std::size_t(ci[0])], {a, b});
  const IndexType cc = apex(wj.cells[std::size_t(cj[0])], {ja, jb});
  return CGAL::side_of_bounded_circle(image(s, i, a), image(s, i, b), image(s, i, c),
                                      image(s, j, cc)) == CGAL::ON_BOUNDED_SIDE;
}

std::vector<TemplateEdge> non_tald(const Session& s) {
  const auto index = index_tables(s.t);
  std::set<TemplateEdge> bad;
  for (const auto& id : s.t.identifications) {
    const auto i = std::size_t(id.from_instance), j = std::size_t(id.to_instance);
    const auto& fwd = index[std::size_t(id.table)].fwd;
    const auto& wi = s.w[s.template_of[i]];
    for (const auto& c : wi.cells)
      for (int k = 0; k < 3; ++k) {
        const IndexType a = c[std::size_t(k)], b = c[std::size_t((k + 1) % 3)];
        const auto ia = fwd.find(a), ib = fwd.find(b);
        if (ia == fwd.end() || ib == fwd.end()) continue;
        if (!is_boundary_edge(wi, a, b) ||
            !is_boundary_edge(s.w[s.template_of[j]], ia->second, ib->second))
          continue;
        if (encroached(s, i, a, b, j, ia->second, ib->second) ||
            encroached(s, j, ia->second, ib->second, i, a, b))
          bad.insert(edge_of(s.template_of[i], a, b));
      }
  }
  return {bad.begin(), bad.end()};
}

/// The template-boundary facets through each vertex (d vertices each, sorted).
std::vector<std::vector<std::vector<IndexType>>> boundary_facets_by_vertex(const Work& w) {
  std::vector<std::vector<std::vector<IndexType>>> out(w.vertex_count());
  for (const auto& c : w.cells)
    for (const auto& f : facets_of(w, c))
      if (facet_cell_count(w, f) == 1)
        for (IndexType v : f) out[std::size_t(v)].push_back(f);
  return out;
}

/// Within how much of L (the farthest link vertex from v) rounded points count as lying in one
/// plane or on one line, and unit normals as equal (1 - dot). A generated patch on a slanted plane
/// (an n-gon slice's sides and cut planes) holds no exactly coplanar doubles, but its points are
/// off the plane by rounding, about 1e-15 L; a real crease of angle θ puts its link θ L off it.
/// The same margin as the flat patches of Technique 5.8's boundary flips.
constexpr double kFlatToRounding = 1e-9;

/// Where v may slide: its link (sorted), and whether deciding it needed kFlatToRounding (the
/// exact predicates found the points not exactly in one plane / on one line).
struct SlidingLink {
  std::vector<IndexType> link;
  bool rounded = false;
};

/// Unit outward normal of a 3D template-boundary facet: its cell's fourth vertex lies behind it.
/// NaN for a facet flat to zero area (the tests below then fail on it).
std::array<double, 3> outward_normal(const Work& w, const std::vector<IndexType>& f) {
  auto n = cross3(sub3(w.p(f[1]), w.p(f[0])), sub3(w.p(f[2]), w.p(f[0])));
  const auto cells = w.cells_with({f[0], f[1], f[2]});
  const IndexType q = apex(w.cells[std::size_t(cells.front())], {f[0], f[1], f[2]});
  const double s = dot3(n, sub3(w.p(q), w.p(f[0]))) > 0 ? -1 : 1;
  const double len = std::sqrt(dot3(n, n));
  for (auto& x : n) x *= s / len;
  return n;
}

/// The farthest of the points from o.
double reach(const Work& w, IndexType o, const std::vector<IndexType>& points) {
  double r = 0;
  for (IndexType u : points) {
    double l = 0;
    for (int i = 0; i < w.d; ++i) l += (w.p(u)[i] - w.p(o)[i]) * (w.p(u)[i] - w.p(o)[i]);
    r = std::max(r, l);
  }
  return std::sqrt(r);
}

/// o strictly between a and b on their line, up to `tol` times |ab| off it (tol = 0: exactly, by
/// exact predicates).
bool strictly_between(const Work& w, IndexType a, IndexType o, IndexType b, double tol) {
  if (tol == 0) {
    if (w.d == 2) {
      const P2 pa = p2(w.p(a)), po = p2(w.p(o)), pb = p2(w.p(b));
      return CGAL::collinear(pa, po, pb) &&
             CGAL::collinear_are_strictly_ordered_along_line(pa, po, pb);
    }
    const P3 pa = p3(w.p(a)), po = p3(w.p(o)), pb = p3(w.p(b));
    // (CGAL's ordering test presupposes collinearity.)
    return CGAL::collinear(pa, po, pb) &&
           CGAL::collinear_are_strictly_ordered_along_line(pa, po, pb);
  }
  double ab[3] = {0, 0, 0}, ao[3] = {0, 0, 0}, ll = 0, t = 0;
  for (int i = 0; i < w.d; ++i) {
    ab[i] = w.p(b)[i] - w.p(a)[i];
    ao[i] = w.p(o)[i] - w.p(a)[i];
    ll += ab[i] * ab[i];
    t += ab[i] * ao[i];
  }
  if (!(ll > 0)) return false;
  t /= ll;
  double off = 0;
  for (int i = 0; i < w.d; ++i) off += (ao[i] - t * ab[i]) * (ao[i] - t * ab[i]);
  return t > 0 && t < 1 && std::sqrt(off) <= tol * std::sqrt(ll);
}

/// The facets through v that lie in the plane through v with unit normal n, up to `tol` L, with
/// their outward normals within `tol` of n (a fold is not flat). Written so that a NaN normal
/// (a facet of zero area) fails.
bool in_plane_to_rounding(const Work& w, const std::vector<IndexType>& f, IndexType v,
                          const std::array<double, 3>& n, double tol, double l) {
  if (!(1 - dot3(outward_normal(w, f), n) <= tol)) return false;
  for (IndexType u : f)
    if (!(std::abs(dot3(sub3(w.p(u), w.p(v)), n)) <= tol * l)) return false;
  return true;
}

/// The two ends of a straight crease through 3D boundary vertex v, sorted: its boundary facets
/// (a closed fan) lie in two planes that meet in a line through v, and exactly two link vertices
/// lie in both, on that line on either side of v. Then v lies inside one edge of its template's
/// boundary subdivision and may slide along it (Section 5.2.2: within its patch, here a patch
/// edge). Otherwise empty. tol = 0: exact predicates decide; else the planes and the line hold
/// the points up to tol L (kFlatToRounding: a slanted crease of a generated mesh).
std::vector<IndexType> crease_ends(const Work& w, const std::vector<std::vector<IndexType>>& facets,
                                   IndexType v, double tol) {
  const P3 o = p3(w.p(v));
  std::set<IndexType> around;
  for (const auto& f : facets) around.insert(f.begin(), f.end());
  around.erase(v);
  const double l = reach(w, v, {around.begin(), around.end()});
  // The plane of a facet through v, as its two other vertices (exact) or its normal (rounded).
  const auto other = [&](const std::vector<IndexType>& f) {
    std::array<P3, 2> q;
    std::size_t n = 0;
    for (IndexType u : f)
      if (u != v && n < 2) q[n++] = p3(w.p(u));
    return q;
  };
  struct Plane {
    std::array<P3, 2> points;
    std::array<double, 3> normal;
  };
  const auto plane_of = [&](const std::vector<IndexType>& f) {
    return Plane{other(f), tol == 0 ? std::array<double, 3>{} : outward_normal(w, f)};
  };
  const auto in_plane = [&](const Plane& plane, const std::vector<IndexType>& f) {
    if (tol != 0) return in_plane_to_rounding(w, f, v, plane.normal, tol, l);
    for (IndexType u : f)
      if (CGAL::orientation(o, plane.points[0], plane.points[1], p3(w.p(u))) != CGAL::COPLANAR)
        return false;
    return true;
  };
  const auto degenerate = [&](const Plane& plane) {
    return tol == 0 && CGAL::collinear(o, plane.points[0], plane.points[1]);
  };
  const auto first = plane_of(facets[0]);
  if (degenerate(first)) return {};
  std::optional<Plane> second;
  std::set<IndexType> on_first, on_second;
  for (const auto& f : facets) {
    auto& side = in_plane(first, f) ? on_first : on_second;
    if (&side == &on_second) {
      if (!second) second = plane_of(f);
      if (degenerate(*second) || !in_plane(*second, f)) return {};
    }
    for (IndexType u : f)
      if (u != v) side.insert(u);
  }
  if (!second) return {};
  std::vector<IndexType> ends;
  std::set_intersection(on_first.begin(), on_first.end(), on_second.begin(), on_second.end(),
                        std::back_inserter(ends));
  if (ends.size() != 2) return {};
  return strictly_between(w, ends[0], v, ends[1], tol) ? ends : std::vector<IndexType>{};
}

/// Whether the closed fan of 3D boundary facets through v is one flat disk up to tol L: every
/// link vertex within tol L of the plane through v with the outward normal of its largest facet,
/// and every outward normal within tol of that one.
bool flat_disk_to_rounding(const Work& w, const std::vector<std::vector<IndexType>>& facets,
                           IndexType v, const std::vector<IndexType>& link, double tol) {
  std::size_t largest = 0;
  double area = -1;
  for (std::size_t k = 0; k < facets.size(); ++k) {
    const auto& f = facets[k];
    const auto n = cross3(sub3(w.p(f[1]), w.p(f[0])), sub3(w.p(f[2]), w.p(f[0])));
    if (dot3(n, n) > area) area = dot3(n, n), largest = k;
  }
  if (!(area > 0)) return false;
  const auto n = outward_normal(w, facets[largest]);
  const double l = reach(w, v, link);
  for (const auto& f : facets)
    if (!in_plane_to_rounding(w, f, v, n, tol, l)) return false;
  return true;
}

/// Where boundary vertex v may slide (Section 5.2.2): its boundary facets form one flat disk —
/// two collinear edges with v strictly between them (2D), or as many coplanar triangles as link
/// vertices, each link vertex on two of them (3D) — then its link; or, in 3D, two flat
/// half-disks meeting in a straight crease through v — then the crease's two ends
/// (crease_ends). A vertex where the boundary bends otherwise lies in more than one patch and
/// may not move: empty. Exact predicates decide first; what they find not exactly flat or
/// straight is decided again up to `tol` (kFlatToRounding), and marked `rounded`.
SlidingLink sliding_link(const Work& w, const std::vector<std::vector<IndexType>>& facets,
                         IndexType v, double tol) {
  std::map<IndexType, int> degree;
  for (const auto& f : facets)
    for (IndexType u : f)
      if (u != v) ++degree[u];
  std::vector<IndexType> link;
  for (const auto& [u, n] : degree) {
    if (n != w.d - 1) return {};
    link.push_back(u);
  }
  if (w.d == 2) {
    if (facets.size() != 2 || link.size() != 2) return {};
    if (strictly_between(w, link[0], v, link[1], 0)) return {link, false};
    if (tol != 0 && strictly_between(w, link[0], v, link[1], tol)) return {link, true};
    return {};
  }
  if (facets.size() < 3 || link.size() != facets.size()) return {};
  const P3 o = p3(w.p(v)), a = p3(w.p(link[0]));
  std::size_t k = 1;
  while (k < link.size() && CGAL::collinear(o, a, p3(w.p(link[k])))) ++k;
  if (k == link.size()) return {};
  const P3 b = p3(w.p(link[k]));
  bool flat = true;
  for (IndexType u : link) flat = flat && CGAL::orientation(o, a, b, p3(w.p(u))) == CGAL::COPLANAR;
  if (flat) return {link, false};
  if (auto ends = crease_ends(w, facets, v, 0); !ends.empty()) return {ends, false};
  if (tol == 0) return {};
  if (flat_disk_to_rounding(w, facets, v, link, tol)) return {link, true};
  if (auto ends = crease_ends(w, facets, v, tol); !ends.empty()) return {ends, true};
  return {};
}

/// A vertex of one template moved to the centroid of its boundary link.
struct SlidingMove {
  std::size_t t = 0;
  IndexType v = 0;
  std::vector<IndexType> link; ///< sorted
  bool rounded = false;        ///< flat / straight only up to kFlatToRounding
};

/// Equation 5.1: the moves of boundary vertex v of template t and of every vertex related to it
/// through the identification tables (closed under them), each to the centroid of its own link.
/// The link is carried across each table, so a related vertex moves to the image of v's new
/// place. False when some related vertex may not slide, its link is not the image of v's, or it
/// is reached with two different links (the irregular instance graph of Figure 4.11). Without
/// `link_copies` (the dropped hypothesis of Equation 5.1) v's move alone.
bool plan_sliding_move(const Session& s, const std::vector<TableIndex>& index,
                       const std::vector<std::vector<std::vector<std::vector<IndexType>>>>& bfacets,
                       std::size_t t, IndexType v, std::vector<SlidingMove>& out, double tol,
                       bool link_copies = true) {
  out.clear();
  const auto link = sliding_link(s.w[t], bfacets[t][std::size_t(v)], v, tol);
  if (link.link.empty()) return false;
  std::map<std::pair<std::size_t, IndexType>, std::size_t> seen;
  out.push_back({t, v, link.link, link.rounded});
  if (!link_copies) return true;
  seen[{t, v}] = 0;
  for (std::size_t next = 0; next < out.size(); ++next) {
    for (const auto& [map_of, other] : tables_from(s, index, out[next].t)) {
      const SlidingMove m = out[next];
      const auto& map = *map_of;
      const auto iv = map.find(m.v);
      if (iv == map.end()) continue;
      std::vector<IndexType> mapped;
      for (IndexType u : m.link) {
        const auto iu = map.find(u);
        if (iu == map.end()) return false;
        mapped.push_back(iu->second);
      }
      std::sort(mapped.begin(), mapped.end());
      const auto found = seen.find({other, iv->second});
      if (found != seen.end()) {
        if (out[found->second].link != mapped) return false;
        continue;
      }
      const auto there =
          sliding_link(s.w[other], bfacets[other][std::size_t(iv->second)], iv->second, tol);
      if (there.link != mapped) return false;
      seen[{other, iv->second}] = out.size();
      out.push_back({other, iv->second, mapped, there.rounded});
    }
  }
  return true;
}

/// Applies the moves if every cell around a moved vertex stays positively oriented (and, with
/// `improve_only`, their smallest quality grows); otherwise leaves the templates unchanged.
bool apply_moves(Session& s, const std::vector<SlidingMove>& moves, bool improve_only) {
  std::vector<std::array<double, 3>> old(moves.size()), at(moves.size());
  bool changed = false;
  for (std::size_t m = 0; m < moves.size(); ++m) {
    const auto& w = s.w[moves[m].t];
    // The sum, then one division; a coordinate that every link vertex shares (the plane of a
    // flat patch parallel to an axis) is copied, not recomputed: a mean of equal doubles that
    // are not dyadic (0.1 + 0.1 + 0.1 = 0.30000000000000004) may round off them, and the vertex
    // would leave its face.
    at[m] = {0, 0, 0};
    for (IndexType u : moves[m].link)
      for (int i = 0; i < w.d; ++i) at[m][std::size_t(i)] += w.p(u)[i];
    for (int i = 0; i < w.d; ++i) {
      const double shared = w.p(moves[m].link.front())[i];
      bool all = true;
      for (IndexType u : moves[m].link) all = all && w.p(u)[i] == shared;
      at[m][std::size_t(i)] = all ? shared : at[m][std::size_t(i)] / double(moves[m].link.size());
    }
    for (int i = 0; i < w.d; ++i) {
      old[m][std::size_t(i)] = w.p(moves[m].v)[i];
      changed = changed || at[m][std::size_t(i)] != old[m][std::size_t(i)];
    }
    // A crease vertex (two link vertices in 3D) on an exact crease must land on it exactly: the
    // midpoint of a slanted crease's ends may round off it, and the boundary would change. On a
    // crease straight only to rounding the midpoint is as far off as the crease's own points.
    if (w.d == 3 && moves[m].link.size() == 2 && !moves[m].rounded) {
      const P3 a = p3(w.p(moves[m].link[0])), b = p3(w.p(moves[m].link[1]));
      const P3 q = p3(at[m].data());
      if (!CGAL::collinear(a, q, b) || !CGAL::collinear_are_strictly_ordered_along_line(a, q, b))
        return false;
    }
  }
  if (!changed) return false;
  const auto around_quality = [&] {
    double q = 180;
    for (const auto& m : moves)
      for (IndexType ci : s.w[m.t].inc[std::size_t(m.v)])
        q = std::min(q, cell_quality(s.w[m.t], s.w[m.t].cells[std::size_t(ci)]));
    return q;
  };
  const double before = improve_only ? around_quality() : 0;
  const auto place = [&](const std::vector<std::array<double, 3>>& where) {
    for (std::size_t m = 0; m < moves.size(); ++m) {
      auto& w = s.w[moves[m].t];
      std::copy(where[m].begin(), where[m].begin() + w.d,
                &w.x[std::size_t(moves[m].v) * std::size_t(w.d)]);
    }
  };
  place(at);
  bool valid = true;
  for (const auto& m : moves)
    for (IndexType ci : s.w[m.t].inc[std::size_t(m.v)])
      valid = valid && robustly_positive(s.w[m.t], s.w[m.t].cells[std::size_t(ci)]);
  if (valid && improve_only) valid = around_quality() > before;
  if (!valid) place(old);
  return valid;
}

SmoothReport smooth(Session& s, std::size_t iterations, bool improve_only, bool link_copies = true,
                    double tol = kFlatToRounding) {
  SmoothReport r;
  const auto index = index_tables(s.t);
  std::vector<std::vector<std::vector<std::vector<IndexType>>>> bfacets;
  for (const auto& w : s.w) bfacets.push_back(boundary_facets_by_vertex(w));
  std::vector<SlidingMove> moves;
  for (std::size_t it = 0; it < iterations; ++it)
    for (std::size_t t = 0; t < s.w.size(); ++t) {
      auto& w = s.w[t];
      for (IndexType v = 0; v < IndexType(w.vertex_count()); ++v) {
        if (w.inc[std::size_t(v)].empty()) continue;
        if (!bfacets[t][std::size_t(v)].empty()) {
          if (plan_sliding_move(s, index, bfacets, t, v, moves, tol, link_copies) &&
              apply_moves(s, moves, improve_only))
            r.boundary_moves += moves.size();
          continue;
        }
        std::set<IndexType> around;
        for (IndexType ci : w.inc[std::size_t(v)])
          for (int k = 0; k < w.arity(); ++k)
            around.insert(w.cells[std::size_t(ci)][std::size_t(k)]);
        around.erase(v);
        double q[3] = {0, 0, 0};
        for (IndexType u : around)
          for (int i = 0; i < w.d; ++i) q[i] += w.p(u)[i];
        for (int i = 0; i < w.d; ++i) q[i] /= double(around.size());
        bool valid = true;
        double before = 180, after = 180;
        for (IndexType ci : w.inc[std::size_t(v)]) {
          const auto& c = w.cells[std::size_t(ci)];
          valid = valid && robustly_positive(w, c, v, q);
          if (improve_only) {
            before = std::min(before, cell_quality(w, c));
            after = std::min(after, cell_quality(w, c, v, q));
          }
        }
        if (!valid || (improve_only && !(after > before))) continue;
        bool same = true;
        for (int i = 0; i < w.d; ++i) same = same && q[i] == w.p(v)[i];
        if (same) continue;
        std::copy(q, q + w.d, &w.x[std::size_t(v) * std::size_t(w.d)]);
        ++r.interior_moves;
      }
    }
  return r;
}

/// The longest edge {a, b} (a < b) among the n vertices c — a cell or a facet — and its length;
/// ties go to the smaller vertex pair, for cells and facets alike.
double longest_edge(const Work& w, const IndexType* c, int n, IndexType& a, IndexType& b) {
  double best = -1;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const IndexType u = std::min(c[i], c[j]);
      const IndexType v = std::max(c[i], c[j]);
      double l = 0;
      for (int k = 0; k < w.d; ++k) l += (w.p(u)[k] - w.p(v)[k]) * (w.p(u)[k] - w.p(v)[k]);
      if (l > best || (l == best && std::make_pair(u, v) < std::make_pair(a, b))) {
        best = l;
        a = u;
        b = v;
      }
    }
  return std::sqrt(best);
}

// --- the --refine-where expression ---
struct Term {
  std::string name, op;
  double value = 0;
};

double field(const CellView& c, const std::string& name) {
  if (name == "x") return c.centroid[0];
  if (name == "y") return c.centroid[1];
  if (name == "z") return c.centroid[2];
  if (name == "size") return c.size;
  if (name == "quality") return c.quality;
  if (name == "region") return double(c.region);
  if (name == "template") return double(c.template_index);
  return double(c.instance);
}

bool compare(double l, const std::string& op, double r) {
  if (op == "<") return l < r;
  if (op == "<=") return l <= r;
  if (op == ">") return l > r;
  if (op == ">=") return l >= r;
  if (op == "==") return l == r;
  return l != r;
}

/// Edge removal (generalising the 3-2 flip; k = 4 is the 4-4 flip): the k cells around edge
/// {d, e} of cell ci (3 <= k <= largest_ring), whose far vertices close a ring, become the
/// 2(k - 2) cells of a fan of the ring joined to d and to e — the fan from the first ring vertex
/// for which every fan triangle separates d from e with one orientation, the new facets are new,
/// every new cell passes `ok` and, with `improve`, the smallest dihedral angle grows. Only
/// template-interior edges qualify (a closed ring).
bool remove_edge(Work& w, IndexType ci, int p, int q, const CellTest& ok, std::size_t largest_ring,
                 bool improve) {
  const Cell c0 = w.cells[std::size_t(ci)];
  const IndexType d = c0[std::size_t(p)], e = c0[std::size_t(q)];
  const auto around = w.cells_with({d, e});
  if (around.size() < 3 || around.size() > largest_ring) return false;
  // Ring order: consecutive cells share a facet {d, e, r}.
  std::map<IndexType, std::vector<IndexType>> next;
  for (IndexType cj : around) {
    std::vector<IndexType> far;
    for (IndexType v : w.cells[std::size_t(cj)])
      if (v != d && v != e) far.push_back(v);
    next[far[0]].push_back(far[1]);
    next[far[1]].push_back(far[0]);
  }
  for (const auto& [v, n] : next)
    if (n.size() != 2) return false; // not closed: a boundary edge
  std::vector<IndexType> ring{next.begin()->first};
  IndexType prev = -1;
  while (ring.size() < around.size()) {
    const auto& n = next[ring.back()];
    const IndexType nx = n[0] != prev ? n[0] : n[1];
    prev = ring.back();
    ring.push_back(nx);
  }
  if (next[ring.back()][0] != ring.front() && next[ring.back()][1] != ring.front()) return false;
  double before = 180;
  for (IndexType cj : around) before = std::min(before, cell_quality(w, w.cells[std::size_t(cj)]));
  const std::size_t k = ring.size();
  for (std::size_t r0 = 0; r0 < k; ++r0) {
    std::vector<Cell> fresh;
    int side = 0;
    bool valid = true;
    for (std::size_t i = 1; i + 1 < k && valid; ++i) {
      const IndexType x = ring[r0], y = ring[(r0 + i) % k], z = ring[(r0 + i + 1) % k];
      if (!w.cells_with({x, y, z}).empty()) valid = false;
      Cell nd{x, y, z, d}, ne{x, y, z, e};
      const int od = orientation(w, nd), oe = orientation(w, ne);
      if (od == 0 || oe == 0 || od == oe || (side != 0 && od != side)) valid = false;
      side = od;
      if (od < 0) std::swap(nd[0], nd[1]);
      if (oe < 0) std::swap(ne[0], ne[1]);
      fresh.push_back(nd);
      fresh.push_back(ne);
    }
    if (!valid) continue;
    double after = 180;
    for (const auto& c : fresh) {
      valid = valid && ok(c);
      after = std::min(after, cell_quality(w, c));
    }
    // Sliver removal: the count of cells failing `ok` falls by at least one (c0), so the
    // removals end. Quality pass: the smallest dihedral angle of the cells replaced grows.
    if (!valid || (improve && !(after > before))) continue;
    std::vector<IndexType> slots(around.begin(), around.end());
    std::sort(slots.begin(), slots.end());
    std::size_t used = 0;
    for (; used < fresh.size() && used < slots.size(); ++used) w.set_cell(slots[used], fresh[used]);
    for (std::size_t f = used; f < fresh.size(); ++f) w.add_cell(fresh[f]);
    for (std::size_t r = slots.size(); r-- > used;) remove_cell(w, slots[r]);
    return true;
  }
  return false;
}

/// The Delaunay tetrahedralization of points that lie on common spheres (the rings of a
/// symmetric object) contains slivers of four nearly cocircular points, positive in template
/// coordinates by a rounding margin and flat or negative in some rotated instance. Each is
/// removed by the 2-3 or 3-2 flip (inside the template; boundary facets are never flipped) that
/// raises the smallest dihedral angle and leaves cells positive in every instance; the points
/// of such a flip are cospherical up to rounding, so the cells stay Delaunay. Returns the flips.

} // namespace symmesh::adapt::work

namespace symmesh::adapt {
using namespace work;

std::size_t expand_identifications(mesh::TemplatedMeshCompactSvb& t) {
  Session s(t);
  std::vector<std::vector<TemplateEdge>> edges(s.w.size());
  std::vector<std::vector<char>> on(s.w.size());
  for (std::size_t i = 0; i < s.w.size(); ++i) {
    on[i] = boundary_vertices(s.w[i]);
    std::set<TemplateEdge> e;
    for (const auto& c : s.w[i].cells)
      for (int p = 0; p < s.w[i].arity(); ++p)
        for (int q = p + 1; q < s.w[i].arity(); ++q) {
          const auto a = c[std::size_t(p)], b = c[std::size_t(q)];
          if (on[i][std::size_t(a)] && on[i][std::size_t(b)] && is_boundary_edge(s.w[i], a, b))
            e.insert(edge_of(i, a, b));
        }
    edges[i].assign(e.begin(), e.end());
  }
  std::map<std::pair<IndexType, IndexType>, std::vector<std::size_t>> sharing;
  std::vector<std::unordered_map<IndexType, IndexType>> at_to_vertex(s.template_of.size());
  const mesh::StructureInstance at(t);
  at.for_each_instance([&](const mesh::StructureInstance::Instance& inst) {
    const auto& g = *inst.global;
    for (const auto& e : edges[inst.template_index])
      sharing[{std::min(g[std::size_t(e.a)], g[std::size_t(e.b)]),
               std::max(g[std::size_t(e.a)], g[std::size_t(e.b)])}]
          .push_back(inst.index);
    for (std::size_t v = 0; v < g.size(); ++v)
      if (on[inst.template_index][v]) at_to_vertex[inst.index].emplace(g[v], IndexType(v));
  });
  std::set<std::pair<std::size_t, std::size_t>> direct;
  for (const auto& id : t.identifications)
    direct.insert(std::minmax(std::size_t(id.from_instance), std::size_t(id.to_instance)));
  using Key = std::tuple<IndexType, IndexType, std::vector<std::pair<IndexType, IndexType>>>;
  std::map<Key, IndexType> tables;
  for (std::size_t k = 0; k < t.tables.size(); ++k)
    tables.emplace(Key{t.tables[k].from_template, t.tables[k].to_template, t.tables[k].pairs},
                   IndexType(k));
  std::size_t added = 0;
  for (const auto& [edge, list] : sharing)
    for (std::size_t p = 0; p < list.size(); ++p)
      for (std::size_t q = p + 1; q < list.size(); ++q) {
        const auto [i, j] = std::minmax(list[p], list[q]);
        if (i == j || !direct.insert({i, j}).second) continue;
        std::vector<std::pair<IndexType, IndexType>> pairs;
        for (const auto& [g, v] : at_to_vertex[i]) {
          const auto it = at_to_vertex[j].find(g);
          if (it != at_to_vertex[j].end()) pairs.emplace_back(v, it->second);
        }
        std::sort(pairs.begin(), pairs.end());
        Key key{IndexType(s.template_of[i]), IndexType(s.template_of[j]), pairs};
        auto found = tables.find(key);
        if (found == tables.end()) {
          t.tables.push_back({IndexType(s.template_of[i]), IndexType(s.template_of[j]), pairs});
          found = tables.emplace(key, IndexType(t.tables.size() - 1)).first;
        }
        t.identifications.push_back({IndexType(i), IndexType(j), found->second});
        ++added;
      }
  return added;
}

std::size_t bisect_edges(mesh::TemplatedMeshCompactSvb& t, const std::vector<TemplateEdge>& edges) {
  Session s(t);
  const auto n = bisect(s, edges);
  s.store();
  return n;
}

std::size_t make_templates_delaunay(mesh::TemplatedMeshCompactSvb& t) {
  Session s(t);
  if (s.w.empty() || s.w[0].d != 2) throw std::invalid_argument("Delaunay flips are planar only");
  std::size_t flips = 0;
  for (auto& w : s.w) flips += lawson(w);
  s.store();
  return flips;
}

std::vector<TemplateEdge> non_tald_edges(const mesh::TemplatedMeshCompactSvb& t) {
  auto copy = t;
  Session s(copy);
  return non_tald(s);
}

DelaunayReport make_delaunay(mesh::TemplatedMeshCompactSvb& t, std::size_t max_rounds,
                             mesh::Progress* progress, bool crease_mirrors) {
  Session s(t);
  if (progress) progress->stage("Technique 5.8", max_rounds, "rounds");
  if (!s.w.empty() && s.w[0].d == 3) {
    const auto r = make_delaunay_3d(s, max_rounds, progress, crease_mirrors);
    s.store();
    return r;
  }
  DelaunayReport r;
  const auto corners = acute_corners(s); // the input's corners; split points never are one
  for (;;) {
    for (auto& w : s.w) r.flips += lawson(w);
    const auto bad = non_tald(s);
    if (bad.empty()) break;
    if (r.rounds == max_rounds) {
      s.store(); // the tables already name the vertices of the rounds made: keep t consistent
      const auto& e = bad.front();
      throw AdaptationLimit("Technique 5.8: after " + std::to_string(max_rounds) +
                            " rounds of boundary insertions, template " + std::to_string(e.t) +
                            " edge {" + std::to_string(e.a) + ", " + std::to_string(e.b) +
                            "} (and " + std::to_string(bad.size() - 1) +
                            " more) is still not template-aware locally Delaunay (ping-pong "
                            "encroachment, Figure 5.17; raise --max-rounds)");
    }
    r.bisections += bisect(s, bad, &corners);
    ++r.rounds;
    if (progress) progress->set_done(r.rounds);
  }
  s.store();
  return r;
}

SmoothReport smooth_vertices(mesh::TemplatedMeshCompactSvb& t, std::size_t iterations,
                             bool improve_only) {
  Session s(t);
  const auto r = smooth(s, iterations, improve_only);
  s.store();
  return r;
}

namespace detail {
SmoothReport smooth_vertices_unlinked(mesh::TemplatedMeshCompactSvb& t, std::size_t iterations) {
  Session s(t);
  const auto r = smooth(s, iterations, false, false);
  s.store();
  return r;
}

SmoothReport smooth_vertices_with_flatness(mesh::TemplatedMeshCompactSvb& t, std::size_t iterations,
                                           double tolerance) {
  Session s(t);
  const auto r = smooth(s, iterations, false, true, tolerance);
  s.store();
  return r;
}
} // namespace detail

namespace {
/// What a cell predicate sees of cell `cell` of template `ti`, in the template's coordinates
/// (instance and region are left unset); (a, b) is its longest edge.
CellView template_cell_view(const Work& w, const Cell& cell, std::size_t ti, IndexType& a,
                            IndexType& b) {
  CellView view;
  view.size = longest_edge(w, cell.data(), w.arity(), a, b);
  view.quality = cell_quality(w, cell);
  view.template_index = ti;
  for (int k = 0; k < w.arity(); ++k)
    for (int d = 0; d < w.d; ++d) view.centroid[d] += w.p(cell[std::size_t(k)])[d] / w.arity();
  return view;
}

/// Parses a cell predicate for `option`, whose names are `names` (listed in errors as `list`).
CellPredicate parse_predicate(const std::string& expression, const std::string& option,
                              const std::set<std::string>& names, const std::string& list) {
  std::vector<Term> terms;
  std::size_t i = 0;
  const auto skip = [&] {
    while (i < expression.size() && std::isspace(static_cast<unsigned char>(expression[i]))) ++i;
  };
  const auto fail = [&](const std::string& what) {
    throw std::invalid_argument(option + " \"" + expression + "\": " + what + " at column " +
                                std::to_string(i + 1));
  };
  for (;;) {
    skip();
    Term term;
    while (i < expression.size() &&
           (std::isalpha(static_cast<unsigned char>(expression[i])) || expression[i] == '_'))
      term.name += expression[i++];
    if (!names.count(term.name))
      fail(term.name.empty() ? "expected a name (" + list + ")"
                             : "unknown name '" + term.name + "' (" + list + ")");
    skip();
    for (const char* op : {"<=", ">=", "==", "!=", "<", ">"})
      if (expression.compare(i, std::strlen(op), op) == 0) {
        term.op = op;
        i += term.op.size();
        break;
      }
    if (term.op.empty()) fail("expected one of < <= > >= == !=");
    skip();
    const char* start = expression.c_str() + i;
    char* end = nullptr;
    term.value = std::strtod(start, &end);
    if (end == start || !std::isfinite(term.value)) fail("expected a finite number");
    i += std::size_t(end - start);
    terms.push_back(term);
    skip();
    if (i == expression.size()) break;
    if (expression.compare(i, 3, "and") == 0)
      i += 3;
    else if (expression.compare(i, 2, "&&") == 0)
      i += 2;
    else
      fail("expected 'and' or the end");
  }
  return [terms](const CellView& c) {
    for (const auto& term : terms)
      if (!compare(field(c, term.name), term.op, term.value)) return false;
    return true;
  };
}
} // namespace

CellPredicate parse_cell_predicate(const std::string& expression) {
  return parse_predicate(expression, "--refine-where",
                         {"x", "y", "z", "size", "quality", "region", "template", "instance"},
                         "x y z size quality region template instance");
}

CellPredicate parse_template_cell_predicate(const std::string& expression) {
  return parse_predicate(expression, "--split-where",
                         {"x", "y", "z", "size", "quality", "template"},
                         "x y z size quality template; a split acts on every instance, so "
                         "region and instance are not names here");
}

std::vector<TemplateSplit> split_where(mesh::TemplatedMeshCompactSvb& t,
                                       const CellPredicate& where) {
  // The Session reads cells unchecked, so an invalid mesh is refused before it is built.
  std::ostringstream why;
  if (!t.is_valid(&why))
    throw std::invalid_argument("split_where: the templated mesh is not valid: " + why.str());
  std::vector<std::vector<std::size_t>> parts;
  {
    auto copy = t;
    const Session s(copy);
    for (std::size_t ti = 0; ti < s.w.size(); ++ti) {
      const auto& w = s.w[ti];
      parts.emplace_back();
      for (std::size_t c = 0; c < w.cells.size(); ++c) {
        IndexType a = -1, b = -1;
        if (where(template_cell_view(w, w.cells[c], ti, a, b))) parts.back().push_back(c);
      }
    }
  }
  std::vector<TemplateSplit> out;
  for (std::size_t ti = 0; ti < parts.size(); ++ti) {
    if (parts[ti].empty() || parts[ti].size() == t.templated.templates[ti].mesh.cell_count())
      continue;
    out.push_back({ti, split_template(t, ti, parts[ti]), parts[ti].size()});
  }
  return out;
}

std::size_t refine_where(mesh::TemplatedMeshCompactSvb& t, const CellPredicate& where) {
  Session s(t);
  std::set<TemplateEdge> marked;
  std::size_t first = 0;
  for (std::size_t ti = 0; ti < s.w.size(); ++ti) {
    const auto& w = s.w[ti];
    const auto& mt = t.templated.templates[ti];
    for (const auto& c : w.cells) {
      IndexType a = -1, b = -1;
      auto view = template_cell_view(w, c, ti, a, b);
      double centroid[3];
      std::copy(view.centroid, view.centroid + 3, centroid);
      for (std::size_t k = 0; k < mt.instance_count(); ++k) {
        view.instance = first + k;
        view.region = mt.region_ids[k];
        s.transformation(first + k).apply(centroid, view.centroid);
        if (where(view)) {
          marked.insert({ti, a, b});
          break;
        }
      }
    }
    first += mt.instance_count();
  }
  const auto n = marked.empty() ? 0 : bisect(s, {marked.begin(), marked.end()});
  s.store();
  return n;
}

ImproveReport improve_quality(mesh::TemplatedMeshCompactSvb& t, std::size_t max_rounds) {
  Session s(t);
  ImproveReport r;
  while (r.rounds < max_rounds) {
    const auto smoothed = smooth(s, 1, true);
    const auto moves = smoothed.interior_moves + smoothed.boundary_moves;
    std::size_t flips = 0;
    for (auto& w : s.w) flips += w.d == 2 ? lawson(w) : quality_flips_3d(w);
    ++r.rounds;
    r.moves += moves;
    r.flips += flips;
    if (moves + flips == 0) break;
  }
  s.store();
  return r;
}

double smallest_quality(const mesh::TemplatedMeshCompactSvb& t) {
  auto copy = t;
  Session s(copy);
  double best = 180;
  for (const auto& w : s.w)
    for (const auto& c : w.cells) best = std::min(best, cell_quality(w, c));
  return best;
}

ConformityCertificate certify_conformity(const mesh::TemplatedMeshCompactSvb& t,
                                         double expected_boundary) {
  auto copy = t;
  Session s(copy);
  ConformityCertificate r;
  const auto fail = [&](const std::string& why) {
    r.holds = false;
    if (r.why.empty()) r.why = why;
  };
  // Facets as fixed-size sorted keys (-1 padded in 2D), counted by sorting: this runs after
  // every operation of the fuzz harness, so it avoids node-based maps.
  using Key = std::array<IndexType, 3>;
  const auto key_of = [](const std::vector<IndexType>& f) {
    Key k{-1, -1, -1};
    std::copy(f.begin(), f.end(), k.begin());
    std::sort(k.begin(), k.begin() + std::ptrdiff_t(f.size()));
    return k;
  };
  std::vector<std::vector<Key>> bnd(s.w.size());
  for (std::size_t i = 0; i < s.w.size(); ++i) {
    std::vector<Key> all;
    for (std::size_t c = 0; c < s.w[i].cells.size(); ++c) {
      if (orientation(s.w[i], s.w[i].cells[c]) <= 0)
        fail("templates[" + std::to_string(i) + "].cells[" + std::to_string(c) +
             "] is not positively oriented");
      for (const auto& f : facets_of(s.w[i], s.w[i].cells[c])) all.push_back(key_of(f));
    }
    std::sort(all.begin(), all.end());
    for (std::size_t k = 0; k < all.size();) {
      std::size_t run = k;
      while (run < all.size() && all[run] == all[k]) ++run;
      if (run - k > 2)
        fail("a facet of template " + std::to_string(i) + " lies in " + std::to_string(run - k) +
             " cells");
      if (run - k == 1) bnd[i].push_back(all[k]);
      k = run;
    }
  }
  const int facet_size = s.w.empty() ? 0 : s.w[0].d;
  struct Seen {
    Key at;
    std::size_t instance = 0;
    Key facet;
  };
  std::vector<Seen> seen;
  const mesh::StructureInstance at(t);
  at.for_each_instance([&](const mesh::StructureInstance::Instance& inst) {
    r.cells += s.w[inst.template_index].cells.size();
    for (const auto& f : bnd[inst.template_index]) {
      Key key{-1, -1, -1};
      for (int k = 0; k < facet_size; ++k)
        key[std::size_t(k)] = (*inst.global)[std::size_t(f[std::size_t(k)])];
      std::sort(key.begin(), key.begin() + facet_size);
      seen.push_back({key, inst.index, f});
    }
  });
  std::sort(seen.begin(), seen.end(), [](const Seen& a, const Seen& b) {
    return a.at != b.at ? a.at < b.at : a.instance < b.instance;
  });
  for (std::size_t k = 0; k < seen.size();) {
    std::size_t run = k;
    while (run < seen.size() && seen[run].at == seen[k].at) ++run;
    const std::size_t count = run - k;
    const auto& first = seen[k];
    k = run;
    if (count > 2) fail("a facet of AT lies in " + std::to_string(count) + " instances");
    if (count != 1) continue;
    ++r.boundary_facets;
    const auto& w = s.w[s.template_of[first.instance]];
    double q[3][3] = {};
    for (std::size_t v = 0; v < std::size_t(facet_size); ++v)
      s.transformation(first.instance).apply(w.p(first.facet[v]), q[v]);
    if (w.d == 2) {
      r.boundary_measure += std::hypot(q[1][0] - q[0][0], q[1][1] - q[0][1]);
    } else {
      double u[3], v[3];
      for (int i = 0; i < 3; ++i) u[i] = q[1][i] - q[0][i], v[i] = q[2][i] - q[0][i];
      r.boundary_measure += 0.5 * std::sqrt(std::pow(u[1] * v[2] - u[2] * v[1], 2) +
                                            std::pow(u[2] * v[0] - u[0] * v[2], 2) +
                                            std::pow(u[0] * v[1] - u[1] * v[0], 2));
    }
  }
  // The identification is combinatorial; the coordinates must agree with it, or the writers
  // (one coordinate per AT vertex) would distort the cells of every instance but one. Agreement
  // is up to the rounding of the two transformations, like the boundary measure below.
  for (const auto& id : t.identifications) {
    const auto i = std::size_t(id.from_instance), j = std::size_t(id.to_instance);
    for (const auto& [a, b] : t.tables[std::size_t(id.table)].pairs) {
      double x[3] = {}, y[3] = {};
      s.transformation(i).apply(s.w[s.template_of[i]].p(a), x);
      s.transformation(j).apply(s.w[s.template_of[j]].p(b), y);
      for (int k = 0; k < s.w[s.template_of[i]].d; ++k)
        if (std::abs(x[k] - y[k]) > 1e-9 * (1 + std::abs(x[k]))) {
          fail("instance " + std::to_string(i) + " vertex " + std::to_string(a) + " and instance " +
               std::to_string(j) + " vertex " + std::to_string(b) +
               " are identified but lie apart by more than rounding");
          break;
        }
    }
  }
  // The measure is a sum of rounded terms; a hanging vertex doubles a whole interface's share.
  if (expected_boundary >= 0 &&
      std::abs(r.boundary_measure - expected_boundary) > 1e-9 * std::max(1.0, expected_boundary))
    fail("AT's boundary measures " + std::to_string(r.boundary_measure) + ", not " +
         std::to_string(expected_boundary) + " (an interface does not conform)");
  return r;
}

} // namespace symmesh::adapt
