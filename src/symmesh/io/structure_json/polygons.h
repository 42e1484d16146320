/// Reading templated-structure JSON, part 4 (internal): 2D geometry templates given as polygons
/// with holes — simple and disjoint rings, exact constrained Delaunay triangulation, nesting
/// parity — spec/input-format.md#polygons
#pragma once
#include "symmesh/io/structure_json/numbers.h"

#include "symmesh/core/element_complex.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace symmesh::io::structure_json {

// ---------------------------------------------------------------------------------------------
// Polygons (2D geometry templates): validation and exact constrained Delaunay triangulation

template <class FT>
struct Ring {
  std::string path;                    // e.g. templates[0].polygon or templates[0].holes[1]
  std::vector<core::Point<FT, 2>> pts; // implicitly closed
  std::size_t first = 0;               // global index of pts[0]
};

template <class FT>
using KernelOf = core::ExactKernelOf<FT>;
template <class FT>
using P2 = typename KernelOf<FT>::Point_2;

template <class FT>
P2<FT> to_cgal(const core::Point<FT, 2>& p) {
  using LFT = typename KernelOf<FT>::FT;
  return P2<FT>(LFT(p[0]), LFT(p[1]));
}

template <class FT>
struct Edge {
  std::size_t ring, k; // edge from ring.pts[k] to ring.pts[(k+1) % n]
  P2<FT> a, b;
  FT xmin, xmax;
};

template <class FT>
std::string edge_name(const std::vector<Ring<FT>>& rings, const Edge<FT>& e) {
  const Ring<FT>& r = rings[e.ring];
  const std::string base = r.path.substr(r.path.rfind('.') + 1);
  return base + "[" + std::to_string(e.k) + "]-" + base + "[" +
         std::to_string((e.k + 1) % r.pts.size()) + "]";
}

/// The rings have pairwise disjoint boundaries except for consecutive edges of one ring, which
/// share their common vertex only: each ring is a simple polygon and no two rings touch.
template <class FT>
void check_simple_and_disjoint(const std::vector<Ring<FT>>& rings) {
  using K = KernelOf<FT>;
  std::vector<Edge<FT>> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& pts = rings[r].pts;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const auto& p = pts[k];
      const auto& q = pts[(k + 1) % pts.size()];
      edges.push_back({r, k, to_cgal(p), to_cgal(q), std::min(p[0], q[0]), std::max(p[0], q[0])});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const Edge<FT>& x, const Edge<FT>& y) { return x.xmin < y.xmin; });
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size() && !(edges[i].xmax < edges[j].xmin); ++j) {
      const Edge<FT>& e = edges[i];
      const Edge<FT>& f = edges[j];
      const std::size_t n = rings[e.ring].pts.size();
      const bool same_ring = e.ring == f.ring;
      const bool e_then_f = same_ring && (e.k + 1) % n == f.k;
      const bool f_then_e = same_ring && (f.k + 1) % n == e.k;
      bool bad;
      if (e_then_f || f_then_e) {
        // Consecutive edges u-v, v-w: they overlap beyond v iff u, v, w are collinear and u, w
        // lie on the same side of v.
        const P2<FT>& u = e_then_f ? e.a : f.a;
        const P2<FT>& v = e_then_f ? e.b : f.b;
        const P2<FT>& w = e_then_f ? f.b : e.b;
        bad = CGAL::collinear(u, v, w) && CGAL::angle(u, v, w) == CGAL::ACUTE;
        if (n == 3 && !bad) bad = CGAL::collinear(u, v, w);
      } else {
        bad = CGAL::do_intersect(typename K::Segment_2(e.a, e.b), typename K::Segment_2(f.a, f.b));
      }
      if (bad) {
        const Edge<FT>& later = e.ring < f.ring ? f : e;
        const Edge<FT>& earlier = e.ring < f.ring ? e : f;
        const std::string what = same_ring ? "the polygon is self-intersecting: edge "
                                           : "the boundaries of the domain touch or cross: edge ";
        fail(rings[later.ring].path,
             what + edge_name(rings, later) + " meets edge " + edge_name(rings, earlier));
      }
    }
}

struct FaceInfo {
  int nesting = -1;
  bool in_domain() const { return nesting % 2 == 1; }
};
template <class K>
using CdtOf = CGAL::Constrained_Delaunay_triangulation_2<
    K,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>,
        CGAL::Constrained_triangulation_face_base_2<
            K, CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>>>,
    CGAL::No_constraint_intersection_tag>;

/// Nesting level of every face: the number of constraint crossings on a path from the infinite
/// face. Flood-fills each level without crossing constraints; crossings seed the next level.
template <class CDT>
void mark_nesting(CDT& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().nesting = -1;
  std::deque<std::pair<typename CDT::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    auto [start, level] = seeds.front();
    seeds.pop_front();
    if (start->info().nesting != -1) continue;
    std::vector<typename CDT::Face_handle> stack{start};
    start->info().nesting = level;
    while (!stack.empty()) {
      auto f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        auto n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(typename CDT::Edge(f, i))) {
          seeds.emplace_back(n, level + 1);
        } else {
          n->info().nesting = level;
          stack.push_back(n);
        }
      }
    }
  }
}

/// Validates rings (outer polygon first, then holes) and triangulates the domain they bound
/// exactly; the triangles index the rings' vertices in order (outer, then holes). `where` names
/// the outer polygon in messages.
template <class FT>
std::vector<std::array<std::size_t, 3>> triangulate_rings(std::vector<Ring<FT>>& rings,
                                                          const std::string& where) {
  using K = KernelOf<FT>;
  using CDT = CdtOf<K>;
  // Repeated vertices (within a ring, e.g. a closing copy of the first vertex, or across rings).
  std::map<core::Point<FT, 2>, std::string, core::PointLess<FT, 2>> seen;
  std::size_t count = 0;
  for (auto& r : rings) {
    r.first = count;
    count += r.pts.size();
    for (std::size_t k = 0; k < r.pts.size(); ++k) {
      auto [it, inserted] = seen.emplace(r.pts[k], at(r.path, k));
      if (!inserted)
        fail(at(r.path, k),
             "repeated vertex (same coordinates as " + it->second +
                 "; polygons are closed implicitly, do not repeat the first vertex)");
    }
  }
  check_simple_and_disjoint(rings);
  // With disjoint simple boundaries, nesting is decided by one vertex per ring.
  std::vector<std::vector<P2<FT>>> polys;
  for (const auto& r : rings) {
    std::vector<P2<FT>> p;
    for (const auto& q : r.pts) p.push_back(to_cgal(q));
    polys.push_back(std::move(p));
  }
  for (std::size_t h = 1; h < rings.size(); ++h) {
    const P2<FT>& v = polys[h][0];
    if (CGAL::bounded_side_2(polys[0].begin(), polys[0].end(), v, K()) != CGAL::ON_BOUNDED_SIDE)
      fail(rings[h].path, "the hole is not inside the polygon");
    for (std::size_t o = 1; o < rings.size(); ++o)
      if (o != h &&
          CGAL::bounded_side_2(polys[o].begin(), polys[o].end(), v, K()) == CGAL::ON_BOUNDED_SIDE)
        fail(rings[h].path, "the hole lies inside another hole (" +
                                rings[o].path.substr(rings[o].path.rfind('.') + 1) + ")");
  }

  CDT cdt;
  std::vector<typename CDT::Vertex_handle> vh(count);
  try {
    for (const auto& r : rings)
      for (std::size_t k = 0; k < r.pts.size(); ++k) {
        vh[r.first + k] = cdt.insert(polys[std::size_t(&r - rings.data())][k]);
        vh[r.first + k]->info() = r.first + k;
      }
    for (const auto& r : rings)
      for (std::size_t k = 0; k < r.pts.size(); ++k)
        cdt.insert_constraint(vh[r.first + k], vh[r.first + (k + 1) % r.pts.size()]);
  } catch (const typename CDT::Intersection_of_constraints_exception&) {
    fail(where, "the polygon boundaries intersect");
  }
  mark_nesting(cdt);
  std::vector<std::array<std::size_t, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info().in_domain())
      out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  if (out.empty()) fail(where, "the polygon bounds no area");
  return out;
}

/// Validates outer polygon + holes and triangulates the domain they bound.
template <class FT>
core::ElementComplex<FT, 2> triangulate_polygon(const json& tj, const std::string& tpath) {
  std::vector<Ring<FT>> rings;
  auto read_ring = [&](const json& j, const std::string& path) {
    expect_array(j, path, "an array of [x, y] vertices");
    if (j.size() < 3)
      fail(path, "a polygon needs at least 3 vertices, got " + std::to_string(j.size()));
    Ring<FT> r;
    r.path = path;
    for (std::size_t k = 0; k < j.size(); ++k) r.pts.push_back(get_point<FT, 2>(j[k], at(path, k)));
    rings.push_back(std::move(r));
  };
  read_ring(tj["polygon"], dot(tpath, "polygon"));
  if (tj.contains("holes")) {
    const std::string hp = dot(tpath, "holes");
    const json& h = tj["holes"];
    expect_array(h, hp, "an array of polygons");
    for (std::size_t k = 0; k < h.size(); ++k) read_ring(h[k], at(hp, k));
  }
  const auto triangles = triangulate_rings(rings, dot(tpath, "polygon"));
  core::ElementComplex<FT, 2> m;
  for (const auto& r : rings)
    for (const auto& p : r.pts) m.points.push_back(p);
  for (const auto& t : triangles)
    m.elements.push_back(
        core::Simplex{core::VertexId(t[0]), core::VertexId(t[1]), core::VertexId(t[2])});
  return m;
}

} // namespace symmesh::io::structure_json
