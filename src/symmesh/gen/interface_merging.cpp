// Section 5.1.1 in the plane: independent template meshing, Algorithm 5.3 —
// spec/generation.md#merge
#include "symmesh/gen/interface_merging.h"
#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/line_mesh_conformity.h"
#include "symmesh/gen/generation_support.h"
#include "symmesh/gen/pipeline_stages.h"
#include "symmesh/gen/triangle_mesher.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Lazy_exact_nt.h>

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

namespace symmesh::gen {
namespace {
using support::Clock;
using support::exact_from_double;
using support::minor_faults;
using support::parts_for;
using support::rounded;
using support::seconds_since;

template <class FT>
using P2 = core::Point<FT, 2>;

/// A boundary edge of a template's carrier with the exact points on it (its line mesh and the
/// points Algorithm 5.3 inserts), each with its mesh vertex (-1 until it is inserted).
template <class FT>
struct CarrierEdge {
  P2<FT> a, b;
  std::map<P2<FT>, mesh::IndexType, core::PointLess<FT, 2>> points;

  FT along(const P2<FT>& q) const { return core::dot<FT, 2>(q - a, b - a); }
  /// q in the relative interior of [a, b], exactly.
  bool holds_inside(const P2<FT>& q) const {
    if (core::detail::orientation_sign<FT>(a, b, q) != 0) return false;
    const FT s = along(q);
    return s > FT(0) && s < core::dot<FT, 2>(b - a, b - a);
  }
  /// The points in order from a to b.
  std::vector<std::pair<P2<FT>, mesh::IndexType>> in_order() const {
    std::vector<std::pair<P2<FT>, mesh::IndexType>> out(points.begin(), points.end());
    std::sort(out.begin(), out.end(),
              [&](const auto& p, const auto& q) { return along(p.first) < along(q.first); });
    return out;
  }
};

/// Edge e of template i, seen from instance b's template j through R = T_b^-1 ∘ T_a, overlaps
/// edge f of template j in a segment of positive length.
template <class FT>
struct Overlap {
  std::size_t a = 0, b = 0; ///< global instance numbers (template-major)
  std::size_t i = 0, e = 0, j = 0, f = 0;
  core::RigidTransformation<FT, 2> r;
};

/// Segments [fa, fb] and [p, q] are collinear and share a part of positive length (exact).
template <class FT>
bool overlaps(const P2<FT>& fa, const P2<FT>& fb, const P2<FT>& p, const P2<FT>& q) {
  using core::detail::orientation_sign;
  const auto d = fb - fa;
  // Intervals first for both ends: an exact zero test (a shared end, e.g. an n-gon's centre,
  // is collinear with every ray) costs an exact evaluation, so it comes only when needed.
  const auto surely_off = [&](const P2<FT>& r) {
    const auto [lo, hi] = CGAL::to_interval(d[0] * (r[1] - fa[1]) - d[1] * (r[0] - fa[0]));
    return lo > 0 || hi < 0;
  };
  if (surely_off(p) || surely_off(q)) return false;
  if (orientation_sign<FT>(fa, fb, p) != 0 || orientation_sign<FT>(fa, fb, q) != 0) return false;
  const FT s = core::dot<FT, 2>(p - fa, d), t = core::dot<FT, 2>(q - fa, d),
           l = core::dot<FT, 2>(d, d);
  return std::max(std::min(s, t), FT(0)) < std::min(std::max(s, t), l);
}

struct Named {
  std::vector<std::string> names;
  std::vector<std::size_t> template_of, local_of;
  std::string instance(std::size_t a) const {
    return "instance " + std::to_string(local_of[a]) + " of template '" + names[template_of[a]] +
           "'";
  }
};

/// Splits the cell on boundary segment {u, w} of m into the fan over u, q_1 … q_k, w (the new
/// vertices in order from u to w): each fan cell is the cell with u, w replaced by consecutive
/// fan vertices, so orientation is kept.
void split_boundary_cell(mesh::Mesh& m, std::size_t cell, mesh::IndexType u, mesh::IndexType w,
                         const std::vector<mesh::IndexType>& run) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::array<mesh::IndexType, 3> original{};
  std::copy(m.cell(cell), m.cell(cell) + 3, original.begin());
  std::vector<mesh::IndexType> fan{u};
  fan.insert(fan.end(), run.begin(), run.end());
  fan.push_back(w);
  for (std::size_t k = 0; k + 1 < fan.size(); ++k) {
    auto c = original;
    for (auto& v : c) v = v == u ? fan[k] : v == w ? fan[k + 1] : v;
    const auto p = [&](int n) {
      const double* x = &m.vertex_coords[std::size_t(c[std::size_t(n)]) * 2];
      return K::Point_2(x[0], x[1]);
    };
    if (CGAL::orientation(p(0), p(1), p(2)) != CGAL::POSITIVE)
      throw MeshingError("merge: splitting a boundary triangle at an inserted interface point "
                         "gives a triangle that is not positively oriented");
    if (k == 0)
      std::copy(c.begin(), c.end(),
                m.cell_vertex_indices.begin() + m.cell_vertex_index_offsets[cell]);
    else
      m.add_cell(mesh::ElementType::triangle, c.data());
  }
}

/// A template boundary point to move: template, carrier edge, old and new exact position.
template <class FT>
struct Move {
  std::size_t t = 0, e = 0;
  P2<FT> from, to;
};

/// Algorithm 5.1: the pairs (p on e, w on f) of an overlap whose points are close (|R(p) − w| at
/// most d_max, exactly), not yet related (R(p) is no point of f, R^-1(w) no point of e), and not
/// carrier corners; sorted by distance (then by position, for determinism).
template <class FT>
struct ClosePair {
  FT d2;
  std::size_t overlap = 0;
  P2<FT> p, w;
};

template <class FT>
std::vector<ClosePair<FT>>
close_vertex_pairs(const std::vector<std::vector<CarrierEdge<FT>>>& edges,
                   const std::vector<Overlap<FT>>& pairs, const FT& dmax2) {
  std::vector<ClosePair<FT>> out;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto& ov = pairs[k];
    const auto& e = edges[ov.i][ov.e];
    const auto& f = edges[ov.j][ov.f];
    const auto back = ov.r.inverse();
    // R(e) lies on f's line, so |R(p) − w|² = (s_p − s_w)² / L with s the parameter along f
    // (s = (x − f.a)·(f.b − f.a), L = |f.b − f.a|²): a sorted sweep finds the close w.
    const auto d = f.b - f.a;
    const FT l = core::dot<FT, 2>(d, d);
    const FT reach = dmax2 * l;
    std::vector<std::pair<FT, P2<FT>>> along;
    for (const auto& [w, u] : f.points)
      if (w != f.a && w != f.b && !e.points.count(back(w)))
        along.push_back({core::dot<FT, 2>(w - f.a, d), w});
    std::sort(along.begin(), along.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& entry : e.points) {
      // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
      const P2<FT>& p = entry.first;
      if (p == e.a || p == e.b) continue;
      const auto q = ov.r(p);
      if (f.points.count(q)) continue;
      const FT sq = core::dot<FT, 2>(q - f.a, d);
      const auto at = std::lower_bound(along.begin(), along.end(), sq,
                                       [](const auto& x, const FT& t) { return x.first < t; });
      const auto take = [&](const std::pair<FT, P2<FT>>& x) {
        const FT gap = x.first - sq;
        if (gap * gap > reach) return false;
        out.push_back({gap * gap / l, k, p, x.second});
        return true;
      };
      for (auto it = at; it != along.end() && take(*it); ++it) {
      }
      for (auto it = at; it != along.begin() && take(*(it - 1)); --it) {
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const ClosePair<FT>& a, const ClosePair<FT>& b) {
    if (a.d2 != b.d2) return a.d2 < b.d2;
    if (a.overlap != b.overlap) return a.overlap < b.overlap;
    if (a.p != b.p) return core::PointLess<FT, 2>()(a.p, b.p);
    return core::PointLess<FT, 2>()(a.w, b.w);
  });
  return out;
}

/// Algorithm 5.2, Lines 14–29 for one pair: p and w move to their centre z (p to R^-1(z)), and
/// every point related to a moved one through an overlap (R(point) is a point there) moves
/// along. Returns the moves, or nothing when they contradict each other or one would leave the
/// relative interior of its carrier edge or land on another point of it.
template <class FT>
std::optional<std::vector<Move<FT>>>
merge_moves(const std::vector<std::vector<CarrierEdge<FT>>>& edges,
            const std::vector<Overlap<FT>>& pairs, const ClosePair<FT>& c) {
  const auto& ov = pairs[c.overlap];
  P2<FT> z;
  const auto q = ov.r(c.p);
  for (int d = 0; d < 2; ++d) z[d] = (q[d] + c.w[d]) / FT(2);
  std::vector<Move<FT>> moves{{ov.i, ov.e, c.p, ov.r.inverse()(z)}, {ov.j, ov.f, c.w, z}};
  for (std::size_t next = 0; next < moves.size(); ++next) {
    const auto m = moves[next];
    for (const auto& o : pairs) {
      if (o.i != m.t || o.e != m.e) continue;
      const auto image = o.r(m.from);
      if (!edges[o.j][o.f].points.count(image)) continue;
      const Move<FT> related{o.j, o.f, image, o.r(m.to)};
      bool seen = false;
      for (const auto& other : moves)
        if (other.t == related.t && other.e == related.e && other.from == related.from) {
          if (other.to != related.to) return std::nullopt;
          seen = true;
        }
      if (!seen) moves.push_back(related);
    }
  }
  for (const auto& m : moves) {
    const auto& e = edges[m.t][m.e];
    if (m.from == e.a || m.from == e.b || !e.holds_inside(m.to)) return std::nullopt;
    for (const auto& [point, v] : e.points)
      if (point == m.to && point != m.from) return std::nullopt;
  }
  return moves;
}

/// The moves keep every triangle around a moved vertex positively oriented (exact on the
/// rounded new coordinates): the validity of Section 5.2.2.
template <class FT>
bool moves_valid(const std::vector<Move<FT>>& moves,
                 const std::vector<std::vector<CarrierEdge<FT>>>& edges,
                 const mesh::TemplatedMesh& tm) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::map<std::size_t, std::map<mesh::IndexType, std::array<double, 2>>> moved;
  for (const auto& m : moves)
    moved[m.t][edges[m.t][m.e].points.at(m.from)] = {rounded(m.to[0]), rounded(m.to[1])};
  for (const auto& entry : moved) {
    const auto& at = entry.second; // captured below: no structured binding (clang 14)
    const auto& mesh = tm.templates[entry.first].mesh;
    for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
      const auto* v = mesh.cell(c);
      if (!at.count(v[0]) && !at.count(v[1]) && !at.count(v[2])) continue;
      const auto p = [&](int k) {
        const auto it = at.find(v[k]);
        if (it != at.end()) return K::Point_2(it->second[0], it->second[1]);
        const double* x = &mesh.vertex_coords[std::size_t(v[k]) * 2];
        return K::Point_2(x[0], x[1]);
      };
      if (CGAL::orientation(p(0), p(1), p(2)) != CGAL::POSITIVE) return false;
    }
  }
  return true;
}

template <class FT>
GenerationResult merge(const core::TemplatedStructure<FT, 2>& x, const GenerationOptions& o) {
  support::input_stage(x, o, "--method merge");
  const auto say = [&](const std::string& s) {
    if (o.progress) o.progress->message(s);
  };
  const auto stage = [&](const std::string& name, std::size_t total, const std::string& unit) {
    if (o.progress) o.progress->stage(name, total, unit);
  };
  stage("instance overlap (Eq. 4.2)", 0, "");
  if (const auto overlap = core::find_instance_overlap(x))
    throw std::invalid_argument(core::overlap_message(*overlap));
  GenerationResult r;
  Named named;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    named.names.push_back(x.templates[i].name);
    for (std::size_t g = 0; g < x.instances[i].size(); ++g) {
      named.template_of.push_back(i);
      named.local_of.push_back(g);
    }
  }
  const std::size_t n_instances = named.template_of.size();

  // Line meshes of every carrier edge, template by template (no boundary patch partition).
  stage("line meshes", 0, "");
  auto t0 = Clock::now();
  long f0 = minor_faults();
  const FT h = exact_from_double<FT>(o.size);
  const FT h2 = h * h;
  std::vector<std::vector<CarrierEdge<FT>>> edges(x.templates.size());
  std::vector<BoundaryInput> inputs(x.templates.size());
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    const auto bnd = core::mesh_boundary(x.templates[i].mesh);
    std::map<P2<FT>, std::size_t, core::PointLess<FT, 2>> id;
    const auto point_id = [&](const P2<FT>& p) {
      auto [it, added] = id.emplace(p, inputs[i].points.size());
      if (added) inputs[i].points.push_back({rounded(p[0]), rounded(p[1])});
      return it->second;
    };
    for (const auto& el : bnd.elements) {
      if (el.dim() != 1) continue;
      CarrierEdge<FT> e{bnd.points[el.v[0]], bnd.points[el.v[1]], {}};
      const std::size_t n = parts_for<FT, 2>(e.a, e.b, h2, o.size);
      std::size_t prev = 0;
      for (std::size_t k = 0; k <= n; ++k) {
        const auto p = core::line_mesh_point<FT>(e.a, e.b, k, n);
        const std::size_t v = point_id(p);
        e.points.emplace(p, mesh::IndexType(v));
        if (k > 0) inputs[i].segments.push_back({prev, v});
        prev = v;
      }
      edges[i].push_back(std::move(e));
    }
  }
  r.timings.line_meshes = seconds_since(t0);
  r.timings.page_faults.line_meshes = minor_faults() - f0;

  // Each template meshed on its own.
  t0 = Clock::now();
  f0 = minor_faults();
  stage("template meshing", x.templates.size(), "templates");
  auto& tm = r.templated.templated;
  tm.point_dimension = 2;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    MeshingParameters p;
    p.size = o.size;
    p.min_angle_deg = o.min_angle_deg;
    mesh::MeshTemplate t;
    t.mesh = triangle_mesh_of(mesh_domain_2(inputs[i], p));
    support::add_instances<2>(t, x.instances[i], tm);
    say("template " + std::to_string(i + 1) + "/" + std::to_string(x.templates.size()) + " ('" +
        x.templates[i].name + "'): " + std::to_string(t.mesh.cell_count()) +
        " triangles, meshed on its own");
    tm.templates.push_back(std::move(t));
    if (o.progress) o.progress->set_done(i + 1);
  }
  r.timings.template_meshing = seconds_since(t0);
  r.timings.page_faults.template_meshing = minor_faults() - f0;

  // Algorithm 5.3: the overlapping carrier edges of every ordered instance pair, then the
  // hanging points carried across them until none is left.
  stage("interface merging (Algorithm 5.3)", 0, "");
  t0 = Clock::now();
  f0 = minor_faults();
  // World edges first: the relative transformation is composed only for pairs that overlap
  // (all slices of an n-gon meet at its centre, so boxes alone would pass every pair).
  std::vector<std::vector<std::pair<P2<FT>, P2<FT>>>> world(n_instances);
  std::vector<core::EnclosingBox<FT, 2>> box;
  for (std::size_t a = 0; a < n_instances; ++a) {
    const auto& s = x.instances[named.template_of[a]][named.local_of[a]].transformation;
    std::vector<P2<FT>> points;
    for (const auto& e : edges[named.template_of[a]]) {
      world[a].push_back({s(e.a), s(e.b)});
      points.push_back(world[a].back().first);
      points.push_back(world[a].back().second);
    }
    std::vector<core::VertexId> all(points.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = core::VertexId(k);
    box.push_back(core::EnclosingBox<FT, 2>::of(points, all));
  }
  std::vector<Overlap<FT>> pairs;
  for (std::size_t a = 0; a < n_instances; ++a)
    for (std::size_t b = 0; b < n_instances; ++b) {
      if (a == b || !box[a].overlaps(box[b])) continue;
      const std::size_t i = named.template_of[a], j = named.template_of[b];
      std::optional<core::RigidTransformation<FT, 2>> rel;
      for (std::size_t e = 0; e < world[a].size(); ++e)
        for (std::size_t f = 0; f < world[b].size(); ++f) {
          if (!overlaps(world[b][f].first, world[b][f].second, world[a][e].first,
                        world[a][e].second))
            continue;
          const auto& tb = x.instances[j][named.local_of[b]].transformation;
          const auto& ta = x.instances[i][named.local_of[a]].transformation;
          if (!rel) rel = tb.inverse() * ta;
          pairs.push_back({a, b, i, e, j, f, *rel});
        }
    }
  // Algorithms 5.1 and 5.2: close pairs moved to their centre, nearest first, with every
  // related point; a pair whose moves contradict or invert a triangle is left to Algorithm 5.3.
  const FT dmax = exact_from_double<FT>(o.size) / FT(3);
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& c : close_vertex_pairs(edges, pairs, dmax * dmax)) {
      const auto moves = merge_moves(edges, pairs, c);
      if (!moves || !moves_valid(*moves, edges, tm)) continue;
      for (const auto& m : *moves) {
        auto& points = edges[m.t][m.e].points;
        const auto v = points.at(m.from);
        points.erase(m.from);
        points.emplace(m.to, v);
        const double q[2] = {rounded(m.to[0]), rounded(m.to[1])};
        std::copy(q, q + 2, &tm.templates[m.t].mesh.vertex_coords[std::size_t(v) * 2]);
      }
      r.merge_moves += moves->size();
      ++r.merge_merged;
      changed = true;
      break; // Line 44: W is recomputed after every merge
    }
  }
  constexpr std::size_t kMaxRounds = 64, kMaxInserted = 1000000;
  for (;;) {
    std::size_t added = 0;
    const Overlap<FT>* last = nullptr;
    for (const auto& ov : pairs) {
      std::vector<P2<FT>> from;
      for (const auto& [p, v] : edges[ov.i][ov.e].points) from.push_back(p);
      auto& f = edges[ov.j][ov.f];
      for (const auto& p : from) {
        const auto q = ov.r(p);
        if (f.holds_inside(q) && f.points.emplace(q, -1).second) {
          ++added;
          last = &ov;
        }
      }
    }
    if (added == 0) break;
    ++r.merge_rounds;
    r.merge_insertions += added;
    if (r.merge_rounds == kMaxRounds || r.merge_insertions > kMaxInserted)
      throw MergeError("--method merge: the interface of " + named.instance(last->a) + " and " +
                       named.instance(last->b) + " still has hanging vertices after " +
                       std::to_string(r.merge_rounds) + " rounds of Algorithm 5.3 (" +
                       std::to_string(r.merge_insertions) +
                       " points inserted): its transformations carry points to ever new places");
  }
  // The inserted points into the double meshes: each run of new points between two old
  // neighbours splits the one cell on that boundary segment.
  for (std::size_t j = 0; j < edges.size(); ++j) {
    auto& m = tm.templates[j].mesh;
    std::map<std::pair<mesh::IndexType, mesh::IndexType>, std::vector<std::size_t>> on_edge;
    for (std::size_t c = 0; c < m.cell_count(); ++c)
      for (int k = 0; k < 3; ++k) {
        const auto u = m.cell(c)[k], w = m.cell(c)[(k + 1) % 3];
        on_edge[std::minmax(u, w)].push_back(c);
      }
    for (auto& f : edges[j]) {
      const auto ordered = f.in_order();
      mesh::IndexType u = ordered.front().second;
      std::vector<mesh::IndexType> run;
      for (std::size_t k = 1; k < ordered.size(); ++k) {
        const auto& [p, v] = ordered[k];
        if (v < 0) {
          const double q[2] = {rounded(p[0]), rounded(p[1])};
          const auto id = m.add_vertex(q);
          f.points[p] = id;
          run.push_back(id);
          continue;
        }
        if (!run.empty()) {
          const auto& cells = on_edge[std::minmax(u, v)];
          if (cells.size() != 1)
            throw MeshingError("merge: template '" + x.templates[j].name +
                               "': a boundary segment is not the edge of one triangle");
          split_boundary_cell(m, cells[0], u, v, run);
          run.clear();
        }
        u = v;
      }
    }
  }
  say("interface merging: " + std::to_string(r.merge_merged) + " close pairs merged (" +
      std::to_string(r.merge_moves) + " points moved, Algorithm 5.2), " +
      std::to_string(r.merge_insertions) + " interface points inserted in " +
      std::to_string(r.merge_rounds) + " rounds (" + std::to_string(pairs.size()) +
      " overlapping edge pairs)");

  // The exact boundary complexes: the SVB is read off their structure instance, and Lemma 4.2
  // is certified on them.
  core::TemplatedStructure<FT, 2> boundary;
  boundary.instances = x.instances;
  std::vector<std::vector<mesh::IndexType>> mesh_vertex(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    core::Template<FT, 2> b{x.templates[i].name, core::TemplateKind::mesh, {}};
    std::map<mesh::IndexType, core::VertexId> local;
    const auto id = [&](const P2<FT>& p, mesh::IndexType v) {
      auto [it, added] = local.emplace(v, core::VertexId(b.mesh.points.size()));
      if (added) {
        b.mesh.points.push_back(p);
        mesh_vertex[i].push_back(v);
        b.mesh.elements.push_back(core::Simplex{it->second});
      }
      return it->second;
    };
    for (const auto& f : edges[i]) {
      const auto ordered = f.in_order();
      for (std::size_t k = 0; k + 1 < ordered.size(); ++k)
        b.mesh.elements.push_back(core::Simplex{id(ordered[k].first, ordered[k].second),
                                                id(ordered[k + 1].first, ordered[k + 1].second)});
    }
    b.mesh.normalize();
    boundary.templates.push_back(std::move(b));
  }
  const auto si = core::apply_template(boundary);
  std::vector<std::size_t> first(x.templates.size() + 1, 0);
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    first[i + 1] = first[i] + x.instances[i].size();
  std::vector<std::vector<std::pair<std::size_t, mesh::IndexType>>> members(
      si.at.mesh.points.size());
  for (std::size_t k = 0; k < si.ids.size(); ++k) {
    const std::size_t a = first[si.ids[k].i] + si.ids[k].g;
    for (std::size_t v = 0; v < si.vertex_map[k].size(); ++v)
      members[si.vertex_map[k][v]].push_back({a, mesh_vertex[si.ids[k].i][v]});
  }
  // Consecutive members of each identified class, so that the pairs span the classes.
  std::map<std::pair<std::size_t, std::size_t>,
           std::vector<std::pair<mesh::IndexType, mesh::IndexType>>>
      pair_lists;
  for (auto& list : members) {
    std::sort(list.begin(), list.end());
    for (std::size_t k = 0; k + 1 < list.size(); ++k)
      pair_lists[{list[k].first, list[k + 1].first}].push_back(
          {list[k].second, list[k + 1].second});
  }
  std::map<std::tuple<std::size_t, std::size_t,
                      std::vector<std::pair<mesh::IndexType, mesh::IndexType>>>,
           mesh::IndexType>
      table_of;
  for (auto& [instances, list] : pair_lists) {
    std::sort(list.begin(), list.end());
    const auto i = named.template_of[instances.first], j = named.template_of[instances.second];
    auto [it, added] =
        table_of.emplace(std::make_tuple(i, j, list), mesh::IndexType(r.templated.tables.size()));
    if (added) r.templated.tables.push_back({mesh::IndexType(i), mesh::IndexType(j), list});
    r.templated.identifications.push_back(
        {mesh::IndexType(instances.first), mesh::IndexType(instances.second), it->second});
  }
  r.timings.svb = seconds_since(t0);
  r.timings.page_faults.svb = minor_faults() - f0;

  support::certificate_stage(o, r, [&] { return core::check_interface_conformity(boundary, si); });
  return r;
}
} // namespace

GenerationResult generate_merge(const core::TemplatedStructure<Exact, 2>& x,
                                const GenerationOptions& o) {
  return merge(x, o);
}
GenerationResult generate_merge(const core::TemplatedStructure<support::LazyCyclotomic, 2>& x,
                                const GenerationOptions& o) {
  return merge(x, o);
}

} // namespace symmesh::gen
