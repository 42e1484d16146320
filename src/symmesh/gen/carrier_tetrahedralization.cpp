// Exact surface checks and the certified carrier tetrahedralization of a 3D PLC template
// (spec/input-format.md#plc).
#include "symmesh/gen/carrier_tetrahedralization.h"
#include "symmesh/gen/generation_support.h"
#include "symmesh/gen/tetrahedral_mesher.h"

#include "symmesh/core/exact_kernel_of.h"
#include "symmesh/core/kernel.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <map>
#include <type_traits>

namespace symmesh::gen {
namespace {

template <class FT>
using KernelOf = core::ExactKernelOf<FT>;

template <class FT>
struct Geometry {
  using K = KernelOf<FT>;
  using P = typename K::Point_3;
  std::vector<P> p;
  explicit Geometry(const std::vector<core::Point<FT, 3>>& points) {
    using LFT = typename K::FT;
    for (const auto& q : points) p.emplace_back(LFT(q[0]), LFT(q[1]), LFT(q[2]));
  }
  typename K::Triangle_3 triangle(const std::array<std::size_t, 3>& t) const {
    return {p[t[0]], p[t[1]], p[t[2]]};
  }
};

using Edge = std::pair<std::size_t, std::size_t>;
Edge edge(std::size_t a, std::size_t b) {
  return a < b ? Edge{a, b} : Edge{b, a};
}

/// Direction v -> a points into triangle (v, b1, b2) (closed sector, in its plane).
template <class G>
bool into_triangle(const G& g, std::size_t v, std::size_t a, std::size_t b1, std::size_t b2) {
  const auto& P = g.p;
  if (!CGAL::coplanar(P[v], P[b1], P[b2], P[a])) return false;
  const auto s1 = CGAL::coplanar_orientation(P[v], P[b1], P[b2], P[a]);
  const auto s2 = CGAL::coplanar_orientation(P[v], P[b2], P[b1], P[a]);
  if (s1 == CGAL::NEGATIVE || s2 == CGAL::NEGATIVE) return false;
  // On a side line of the sector: the ray, not the line behind v.
  if (s1 == CGAL::COLLINEAR) return CGAL::angle(P[b1], P[v], P[a]) == CGAL::ACUTE;
  if (s2 == CGAL::COLLINEAR) return CGAL::angle(P[b2], P[v], P[a]) == CGAL::ACUTE;
  return true;
}

/// Triangles x, y (of different faces) meet in more than their common vertices and edge.
template <class G>
bool improper_contact(const G& g, const std::array<std::size_t, 3>& x,
                      const std::array<std::size_t, 3>& y) {
  std::vector<std::size_t> common, only_x, only_y;
  for (std::size_t v : x) (std::count(y.begin(), y.end(), v) ? common : only_x).push_back(v);
  for (std::size_t v : y)
    if (!std::count(x.begin(), x.end(), v)) only_y.push_back(v);
  const auto& P = g.p;
  switch (common.size()) {
  case 0:
    return CGAL::do_intersect(g.triangle(x), g.triangle(y));
  case 1: {
    // A∩B is convex and holds v; it holds more iff its boundary leaves v along an edge of one
    // triangle into the other, or the edge opposite v of one meets the other.
    const std::size_t v = common[0];
    using Segment = typename G::K::Segment_3;
    return CGAL::do_intersect(Segment(P[only_x[0]], P[only_x[1]]), g.triangle(y)) ||
           CGAL::do_intersect(Segment(P[only_y[0]], P[only_y[1]]), g.triangle(x)) ||
           into_triangle(g, v, only_x[0], only_y[0], only_y[1]) ||
           into_triangle(g, v, only_x[1], only_y[0], only_y[1]) ||
           into_triangle(g, v, only_y[0], only_x[0], only_x[1]) ||
           into_triangle(g, v, only_y[1], only_x[0], only_x[1]);
  }
  case 2: // a common edge: they overlap iff coplanar and on the same side of it
    return CGAL::coplanar(P[common[0]], P[common[1]], P[only_x[0]], P[only_y[0]]) &&
           CGAL::coplanar_orientation(P[common[0]], P[common[1]], P[only_x[0]], P[only_y[0]]) ==
               CGAL::POSITIVE;
  default:
    return true;
  }
}

std::string vertex_pair(const Edge& e) {
  return "vertices " + std::to_string(e.first) + " and " + std::to_string(e.second);
}

template <class FT>
std::optional<SurfaceDefect> closedness_defect(const TriangulatedSurface<FT>& s) {
  std::map<Edge, std::vector<std::size_t>> uses;
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      uses[edge(s.triangles[t][std::size_t(k)], s.triangles[t][std::size_t((k + 1) % 3)])]
          .push_back(t);
  for (const auto& [e, ts] : uses) {
    if (ts.size() == 1)
      return SurfaceDefect{s.face[ts[0]],
                           "the surface is not closed: the edge between " + vertex_pair(e) +
                               " belongs to no other face (a gap, or a vertex on that edge that "
                               "this face does not list)"};
    if (ts.size() > 2) {
      std::string faces;
      for (std::size_t t : ts) faces += (faces.empty() ? "" : ", ") + std::to_string(s.face[t]);
      return SurfaceDefect{s.face[ts[2]], "the surface is not manifold: the edge between " +
                                              vertex_pair(e) + " is shared by faces " + faces};
    }
  }
  return std::nullopt;
}

template <class FT>
std::optional<SurfaceDefect> intersection_defect(const TriangulatedSurface<FT>& s) {
  const Geometry<FT> g(s.points);
  std::vector<CGAL::Bbox_3> box;
  for (const auto& t : s.triangles) box.push_back(g.triangle(t).bbox());
  std::vector<std::size_t> order(s.triangles.size());
  for (std::size_t t = 0; t < order.size(); ++t) order[t] = t;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return box[a].xmin() < box[b].xmin(); });
  std::optional<std::pair<std::size_t, std::size_t>> first; // smallest (later face, earlier face)
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size() && box[order[j]].xmin() <= box[order[i]].xmax();
         ++j) {
      const std::size_t a = order[i], b = order[j];
      if (s.face[a] == s.face[b] || !CGAL::do_overlap(box[a], box[b])) continue;
      if (!improper_contact(g, s.triangles[a], s.triangles[b])) continue;
      const auto pair = std::minmax(s.face[a], s.face[b]);
      const std::pair<std::size_t, std::size_t> key{pair.second, pair.first};
      if (!first || key < *first) first = key;
    }
  if (!first) return std::nullopt;
  return SurfaceDefect{first->first, "faces " + std::to_string(first->second) + " and " +
                                         std::to_string(first->first) +
                                         " intersect (the surface must not cross or touch itself "
                                         "other than in common edges and vertices)"};
}

using Face = std::array<std::size_t, 3>;
Face sorted_face(const std::array<std::size_t, 4>& t, int skip) {
  Face f{};
  for (int k = 0, j = 0; k < 4; ++k)
    if (k != skip) f[std::size_t(j++)] = t[std::size_t(k)];
  std::sort(f.begin(), f.end());
  return f;
}

/// Keeps the tetrahedra an odd number of surface triangles away from outside (cavities out).
std::vector<bool> inside_by_parity(const std::vector<std::array<std::size_t, 4>>& tets,
                                   const std::map<Face, std::vector<std::size_t>>& face_tets,
                                   const std::map<Face, bool>& on_surface) {
  std::vector<int> level(tets.size(), -1);
  std::vector<std::size_t> stack;
  for (const auto& [f, ts] : face_tets)
    if (ts.size() == 1 && level[ts[0]] < 0) {
      level[ts[0]] = on_surface.count(f) ? 1 : 0;
      stack.push_back(ts[0]);
    }
  while (!stack.empty()) {
    const std::size_t t = stack.back();
    stack.pop_back();
    for (int k = 0; k < 4; ++k) {
      const Face f = sorted_face(tets[t], k);
      const auto& ts = face_tets.at(f);
      if (ts.size() != 2) continue;
      const std::size_t n = ts[0] == t ? ts[1] : ts[0];
      const int want = level[t] + (on_surface.count(f) ? 1 : 0);
      if (level[n] < 0) {
        level[n] = want;
        stack.push_back(n);
      } else if ((level[n] - want) % 2 != 0) {
        throw MeshingError("the carrier tetrahedralization has an inconsistent inside");
      }
    }
  }
  std::vector<bool> inside(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t) {
    if (level[t] < 0) throw MeshingError("the carrier tetrahedralization is not connected");
    inside[t] = level[t] % 2 == 1;
  }
  return inside;
}

template <class FT>
double rounded_value(const FT& v) {
  if constexpr (std::is_same_v<FT, Exact>)
    return support::rounded(v);
  else
    return support::rounded(support::LazyCyclotomic(v));
}

} // namespace

template <class FT>
std::optional<SurfaceDefect> find_surface_defect(const TriangulatedSurface<FT>& s) {
  if (auto d = closedness_defect(s)) return d;
  return intersection_defect(s);
}

template <class FT>
core::ElementComplex<FT, 3> carrier_tetrahedralization(const TriangulatedSurface<FT>& s) {
  SurfaceInput in;
  for (const auto& q : s.points)
    in.points.push_back({rounded_value(q[0]), rounded_value(q[1]), rounded_value(q[2])});
  in.triangles = s.triangles;
  const TetrahedralMeshOutput t = tetrahedralize_surface(in);

  std::map<Face, std::vector<std::size_t>> face_tets;
  for (std::size_t c = 0; c < t.tetrahedra.size(); ++c)
    for (int k = 0; k < 4; ++k) face_tets[sorted_face(t.tetrahedra[c], k)].push_back(c);
  std::map<Face, bool> on_surface;
  for (auto f : s.triangles) {
    std::sort(f.begin(), f.end());
    on_surface[f] = true;
  }
  const std::vector<bool> inside = inside_by_parity(t.tetrahedra, face_tets, on_surface);

  // Exact coordinates: the input's, and the (dyadic, hence exact) interior points of TetGen.
  core::ElementComplex<FT, 3> carrier;
  std::vector<std::size_t> index(t.points.size(), std::size_t(-1));
  for (std::size_t v = 0; v < s.points.size(); ++v) {
    index[v] = v;
    carrier.points.push_back(s.points[v]);
  }
  for (std::size_t c = 0; c < t.tetrahedra.size(); ++c)
    if (inside[c])
      for (std::size_t v : t.tetrahedra[c])
        if (index[v] == std::size_t(-1)) {
          index[v] = carrier.points.size();
          core::Point<FT, 3> q;
          for (int d = 0; d < 3; ++d)
            q[d] = support::exact_from_double<FT>(t.points[v][std::size_t(d)]);
          carrier.points.push_back(q);
        }
  const Geometry<FT> g(carrier.points);

  // Certificate: the kept tetrahedra have exactly the surface as boundary, and neighbours lie on
  // opposite sides of their common face, with no flat tetrahedron (exact predicates).
  std::map<Face, std::vector<std::pair<std::size_t, std::size_t>>> kept; // face -> (tet, apex)
  for (std::size_t c = 0; c < t.tetrahedra.size(); ++c) {
    if (!inside[c]) continue;
    std::array<std::size_t, 4> v{};
    for (int k = 0; k < 4; ++k) v[std::size_t(k)] = index[t.tetrahedra[c][std::size_t(k)]];
    if (CGAL::orientation(g.p[v[0]], g.p[v[1]], g.p[v[2]], g.p[v[3]]) == CGAL::COPLANAR)
      throw MeshingError("a carrier tetrahedron is flat in exact arithmetic");
    for (int k = 0; k < 4; ++k) kept[sorted_face(v, k)].push_back({c, v[std::size_t(k)]});
    carrier.elements.push_back(core::Simplex{core::VertexId(v[0]), core::VertexId(v[1]),
                                             core::VertexId(v[2]), core::VertexId(v[3])});
  }
  for (const auto& [f, uses] : kept) {
    const bool surface = on_surface.count(f) > 0;
    if (uses.size() != (surface ? 1u : 2u))
      throw MeshingError("the carrier tetrahedralization does not have the surface as boundary");
    if (!surface && CGAL::orientation(g.p[f[0]], g.p[f[1]], g.p[f[2]], g.p[uses[0].second]) ==
                        CGAL::orientation(g.p[f[0]], g.p[f[1]], g.p[f[2]], g.p[uses[1].second]))
      throw MeshingError("two carrier tetrahedra overlap in exact arithmetic");
  }
  for (const auto& [f, yes] : on_surface)
    if (!kept.count(f))
      throw MeshingError("the carrier tetrahedralization misses a surface triangle");
  carrier.normalize();
  return carrier;
}

template std::optional<SurfaceDefect> find_surface_defect(const TriangulatedSurface<Exact>&);
template std::optional<SurfaceDefect>
find_surface_defect(const TriangulatedSurface<number::Cyclotomic>&);
template core::ElementComplex<Exact, 3>
carrier_tetrahedralization(const TriangulatedSurface<Exact>&);
template core::ElementComplex<number::Cyclotomic, 3>
carrier_tetrahedralization(const TriangulatedSurface<number::Cyclotomic>&);

} // namespace symmesh::gen
