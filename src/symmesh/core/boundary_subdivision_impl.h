// The closed boundary subdivision of every template — spec/boundary-patches.md#subdivision
//
// Part 2 of the definitions behind boundary_patch_partition.h (after
// template_boundary_mapping_impl.h); definitions only, see that file.
#pragma once
#include "symmesh/core/template_boundary_mapping_impl.h"

namespace symmesh::core {
namespace {

// ---------------------------------------------------------------------------------------------
// The closed subdivision.

template <class FT, int D>
struct MappingIndex {
  std::vector<std::vector<std::size_t>> from; ///< non-trivial mappings by from-template
  std::vector<Box<FT, D>> box;                ///< bounding box of each domain
};

template <class FT, int D>
MappingIndex<FT, D> index_mappings(const std::vector<TemplateBoundaryMapping<FT, D>>& ms,
                                   std::size_t templates) {
  MappingIndex<FT, D> ix;
  ix.from.resize(templates);
  for (std::size_t m = 0; m < ms.size(); ++m) {
    ix.box.push_back(ms[m].whole_boundary ? Box<FT, D>{} : piece_box<FT, D>(ms[m].domain));
    if (!ms[m].whole_boundary) ix.from[ms[m].from_template()].push_back(m);
  }
  return ix;
}

/// The image of x under mapping m, x in m's domain. The inverse's domain lists the same world
/// pieces vertex for vertex, so the image of a domain vertex is read off it (exact, and the
/// template's own point where the pull-back found one); the trivial mapping is the identity.
template <class FT, int D>
Point<FT, D> apply_mapping(const std::vector<TemplateBoundaryMapping<FT, D>>& ms, std::size_t m,
                           const Point<FT, D>& x) {
  const auto& mp = ms[m];
  if (mp.whole_boundary) return x;
  const auto& image = ms[mp.inverse].domain;
  for (std::size_t k = 0; k < mp.domain.size(); ++k)
    for (std::size_t j = 0; j < mp.domain[k].vertices.size(); ++j)
      if (mp.domain[k].vertices[j] == x) return image[k].vertices[j];
  return mp.map(x);
}

template <class FT, int D>
bool applies(const TemplateBoundaryMapping<FT, D>& m, const Box<FT, D>& box,
             const Point<FT, D>& x) {
  if (m.whole_boundary) return true;
  if (!box_contains<FT, D>(box, x)) return false;
  for (const auto& p : m.domain)
    if (piece_contains<FT, D>(p, x)) return true;
  return false;
}

/// Faces of a subdivision in which vertices are numbered in lexicographic point order.
template <class FT, int D>
void add_vertex_faces(BoundarySubdivision<FT, D>& s) {
  for (std::size_t v = 0; v < s.points.size(); ++v) {
    BoundaryFace f;
    f.dimension = 0;
    f.vertices = {VertexId(v)};
    f.pieces = {Simplex{VertexId(v)}};
    s.faces.push_back(f);
    s.rep.push_back(s.points[v]);
  }
}

template <class FT, int D>
VertexId vertex_id(const BoundarySubdivision<FT, D>& s, const Point<FT, D>& p) {
  auto it = std::lower_bound(s.points.begin(), s.points.end(), p, PointLess<FT, D>());
  if (it == s.points.end() || *it != p)
    throw std::logic_error("boundary subdivision: point is not a subdivision vertex");
  return VertexId(it - s.points.begin());
}

template <class FT, int D>
void add_edge_face(BoundarySubdivision<FT, D>& s, VertexId a, VertexId b) {
  BoundaryFace f;
  f.dimension = 1;
  f.vertices = {std::min(a, b), std::max(a, b)};
  f.pieces = {Simplex{a, b}};
  f.closure = {std::min(a, b), std::max(a, b)};
  s.faces.push_back(f);
  s.rep.push_back(midpoint<FT, D>(s.points[a], s.points[b]));
}

// 2D: boundary edges cut at breakpoints; breakpoints closed under all mappings by a worklist.

template <class FT>
std::vector<BoundarySubdivision<FT, 2>>
close_subdivisions_2d(const TemplatedStructure<FT, 2>& x,
                      const std::vector<TemplateBoundaryMapping<FT, 2>>& ms,
                      const MappingIndex<FT, 2>& ix, const BppOptions& o) {
  const std::size_t nt = x.templates.size();
  std::vector<std::vector<PointVec<FT, 2>>> edges(nt);
  std::vector<PointSet<FT, 2>> breaks(nt);
  std::deque<std::pair<std::size_t, Point<FT, 2>>> work;
  std::size_t created = 0;
  auto insert = [&](std::size_t t, const Point<FT, 2>& p, bool composed) {
    if (!breaks[t].insert(p).second) return;
    bool on = false;
    for (const auto& e : edges[t])
      if (point_on_segment<FT, 2>(e[0], e[1], p)) on = true;
    if (!on) throw std::logic_error("boundary subdivision: a mapped point left the boundary");
    if (composed && ++created > o.max_compositions) {
      std::ostringstream m;
      m << "boundary patch partition: closing the template boundaries under compositions of "
           "template boundary mappings needs more than "
        << o.max_compositions
        << " composed images (𝔗_X explodes, e.g. a glide reflection by a tiny offset); raise "
           "--max-compositions to go on";
      throw CompositionLimitExceeded(m.str());
    }
    work.emplace_back(t, p);
  };
  for (std::size_t t = 0; t < nt; ++t) edges[t] = boundary_facets(x.templates[t].mesh);
  for (std::size_t t = 0; t < nt; ++t)
    for (const auto& e : edges[t])
      for (const auto& p : e) insert(t, p, false);
  for (const auto& m : ms)
    for (const auto& piece : m.domain)
      for (const auto& p : piece.vertices) insert(m.from_template(), p, false);
  while (!work.empty()) {
    const auto [t, p] = work.front();
    work.pop_front();
    for (std::size_t mi : ix.from[t])
      if (applies<FT, 2>(ms[mi], ix.box[mi], p))
        insert(ms[mi].to_template(), apply_mapping<FT, 2>(ms, mi, p), true);
  }
  std::vector<BoundarySubdivision<FT, 2>> out(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    auto& s = out[t];
    s.points.assign(breaks[t].begin(), breaks[t].end());
    add_vertex_faces(s);
    for (const auto& e : edges[t]) {
      const auto d = e[1] - e[0];
      std::vector<std::pair<FT, VertexId>> on;
      for (std::size_t v = 0; v < s.points.size(); ++v)
        if (point_on_segment<FT, 2>(e[0], e[1], s.points[v]))
          on.emplace_back(dot<FT, 2>(s.points[v] - e[0], d), VertexId(v));
      std::sort(on.begin(), on.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t k = 0; k + 1 < on.size(); ++k)
        add_edge_face(s, on[k].second, on[k + 1].second);
    }
  }
  return out;
}

// 3D: each boundary triangle is triangulated with its cuts (constraints); cuts are closed under
// all mappings in rounds until every mapping sends vertices to vertices and edges to edges.

template <class FT>
struct Cuts {
  PointSet<FT, 3> points;
  std::set<std::pair<Point<FT, 3>, Point<FT, 3>>, std::less<>> segments;
};

template <class FT>
struct PlaneFrame {
  Point<FT, 3> normal;
  FT offset; ///< normal · x on the plane
  int drop = 2, u = 0, v = 1;
  explicit PlaneFrame(const PointVec<FT, 3>& tri) {
    normal = cross<FT>(tri[1] - tri[0], tri[2] - tri[0]);
    offset = dot<FT, 3>(normal, tri[0]);
    drop = 0;
    for (int a = 1; a < 3; ++a)
      if (CGAL::abs(normal[a]) > CGAL::abs(normal[drop])) drop = a;
    u = (drop + 1) % 3;
    v = (drop + 2) % 3;
  }
  Point<FT, 3> lift(const FT& a, const FT& b) const {
    Point<FT, 3> p;
    p[u] = a;
    p[v] = b;
    p[drop] = (offset - normal[u] * a - normal[v] * b) / normal[drop];
    return p;
  }
};

/// A flat region's triangulation: only its faces between constraints are used, so it need not be
/// Delaunay (the Delaunay one's flips were in-circle tests of cocircular corners, exact over K_m).
template <class FT>
using RegionTriangulation = CGAL::Constrained_triangulation_2<
    KernelOf<FT>,
    CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<KernelOf<FT>>,
                                         CGAL::Constrained_triangulation_face_base_2<KernelOf<FT>>>,
    CGAL::Exact_intersections_tag>;

/// The flat regions of a closed boundary: maximal sets of boundary triangles connected across
/// edges shared by two coplanar triangles, each sorted, in order of their first triangle. A
/// carrier's diagonals inside a flat face are not features of the geometry (Definition 4.4: only
/// the underlying space counts), so the subdivision must not cut along them; otherwise every
/// surface mesh would have to follow them and inherit their small angles.
template <class FT>
std::vector<std::vector<std::size_t>> flat_regions(const std::vector<PointVec<FT, 3>>& tris) {
  std::vector<std::size_t> parent(tris.size());
  for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = k;
  const auto find = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  std::map<std::pair<Point<FT, 3>, Point<FT, 3>>, std::vector<std::size_t>, std::less<>> by_edge;
  for (std::size_t k = 0; k < tris.size(); ++k)
    for (int e = 0; e < 3; ++e) {
      Point<FT, 3> a = tris[k][std::size_t(e)], b = tris[k][std::size_t((e + 1) % 3)];
      if (PointLess<FT, 3>()(b, a)) std::swap(a, b);
      by_edge[{a, b}].push_back(k);
    }
  for (const auto& [edge, ks] : by_edge) {
    if (ks.size() != 2) continue;
    const auto& x = tris[ks[0]];
    const auto& y = tris[ks[1]];
    const Point<FT, 3> n = cross<FT>(x[1] - x[0], x[2] - x[0]);
    bool coplanar = true;
    for (const auto& q : y) coplanar = coplanar && dot<FT, 3>(n, q - x[0]) == FT(0);
    if (coplanar) parent[find(ks[0])] = find(ks[1]);
  }
  std::map<std::size_t, std::size_t> index_of_root;
  std::vector<std::vector<std::size_t>> regions;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const auto [it, fresh] = index_of_root.emplace(find(k), regions.size());
    if (fresh) regions.emplace_back();
    regions[it->second].push_back(k);
  }
  return regions;
}

enum class CornerCut { edge, corner_only, undecided };

/// How a cut segment [a, b] meets a boundary triangle, where predicates decide it without a
/// construction: along an edge of the triangle (both ends are its corners: the edge), or only in
/// a corner (one end is a corner and the other lies off the triangle's plane). Anything else is
/// undecided (CGAL's segment–triangle intersection decides).
template <class FT>
CornerCut corner_cut(const PointVec<FT, 3>& tri, const Point<FT, 3>& a, const Point<FT, 3>& b) {
  using P3 = typename KernelOf<FT>::Point_3;
  const auto cg = [](const Point<FT, 3>& p) { return P3(p[0], p[1], p[2]); };
  const bool a_corner = std::find(tri.begin(), tri.end(), a) != tri.end();
  const bool b_corner = std::find(tri.begin(), tri.end(), b) != tri.end();
  if (a_corner && b_corner) return CornerCut::edge;
  if ((a_corner || b_corner) &&
      CGAL::orientation(cg(tri[0]), cg(tri[1]), cg(tri[2]), cg(a_corner ? b : a)) != CGAL::COPLANAR)
    return CornerCut::corner_only;
  return CornerCut::undecided;
}

template <class FT>
BoundarySubdivision<FT, 3> build_subdivision_3d(const std::vector<PointVec<FT, 3>>& tris,
                                                const Cuts<FT>& cuts) {
  using K = KernelOf<FT>;
  using P2 = typename K::Point_2;
  using P3 = typename K::Point_3;
  auto cg = [](const Point<FT, 3>& p) { return P3(p[0], p[1], p[2]); };
  auto pt = [](const P3& p) {
    Point<FT, 3> q;
    q[0] = p.x();
    q[1] = p.y();
    q[2] = p.z();
    return q;
  };
  using VertexHandle = typename RegionTriangulation<FT>::Vertex_handle;
  using FaceHandle = typename RegionTriangulation<FT>::Face_handle;
  // One constrained triangulation per flat region, in the region's plane: its outline (edges
  // in one of its triangles) and the cuts are constraints, the carrier's inner edges are not.
  const auto regions = flat_regions<FT>(tris);
  std::vector<RegionTriangulation<FT>> cdts(regions.size());
  // Each vertex's point on the boundary: the 3D point it was inserted as, or — for a crossing of
  // constraints that the triangulation made — the lift of its projection. Lifting every vertex
  // divided by the plane's normal over K_m, and comparing the quotients with the input points
  // evaluated those divisions exactly (most of the subdivision's time at K_128).
  std::vector<std::map<VertexHandle, Point<FT, 3>>> lifted(regions.size());
  std::vector<std::set<FaceHandle>> inside(regions.size());
  PointSet<FT, 3> all;
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const PlaneFrame<FT> fr(tris[regions[k].front()]);
    auto proj = [&](const Point<FT, 3>& p) { return P2(p[fr.u], p[fr.v]); };
    auto& cdt = cdts[k];
    std::map<std::pair<Point<FT, 3>, Point<FT, 3>>, int, std::less<>> uses;
    for (std::size_t t : regions[k])
      for (int e = 0; e < 3; ++e) {
        Point<FT, 3> a = tris[t][std::size_t(e)], b = tris[t][std::size_t((e + 1) % 3)];
        if (PointLess<FT, 3>()(b, a)) std::swap(a, b);
        ++uses[{a, b}];
      }
    auto& known = lifted[k];
    const auto insert = [&](const Point<FT, 3>& p) {
      const VertexHandle h = cdt.insert(proj(p));
      known.emplace(h, p);
      return h;
    };
    for (const auto& [edge, n] : uses) {
      const VertexHandle a = insert(edge.first), b = insert(edge.second);
      if (n == 1) cdt.insert_constraint(a, b);
    }
    for (std::size_t t : regions[k]) {
      const auto& tri = tris[t];
      const typename K::Triangle_3 t3(cg(tri[0]), cg(tri[1]), cg(tri[2]));
      const auto tb = box_of<FT, 3>(tri);
      // The interval filter of the interface pieces first: a cut that it proves apart from the
      // triangle is, and the exact tests (an exactly-zero orientation over K_m for a cut in the
      // triangle's plane) are left for the others.
      for (const auto& p : cuts.points)
        if (box_contains<FT, 3>(tb, p) && !certainly_apart<FT>(tri, {p, p, p}) &&
            point_in_simplex<FT, 3>(tri, p))
          insert(p);
      for (const auto& [a, b] : cuts.segments) {
        if (!tb.overlaps(box_of<FT, 3>({a, b})) || certainly_apart<FT>(tri, {a, b, b})) continue;
        const auto corner = corner_cut<FT>(tri, a, b);
        if (corner == CornerCut::edge) cdt.insert_constraint(insert(a), insert(b));
        if (corner != CornerCut::undecided) continue; // a corner only: already a vertex
        const auto r = CGAL::intersection(typename K::Segment_3(cg(a), cg(b)), t3);
        if (!r) continue;
        if (const P3* p = boost::get<P3>(&*r))
          insert(pt(*p));
        else if (const auto* sg = boost::get<typename K::Segment_3>(&*r))
          cdt.insert_constraint(insert(pt(sg->source())), insert(pt(sg->target())));
      }
    }
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
      const auto it = known.find(v);
      all.insert(it != known.end() ? it->second
                                   : (known[v] = fr.lift(v->point().x(), v->point().y())));
    }
    // The region may be non-convex: keep the faces whose centroid lies in one of its triangles,
    // decided in the projection (one-to-one on the region's plane, which holds the centroid and
    // every triangle of the region exactly): closed containment, no sign against the triangle's.
    std::vector<std::array<P2, 3>> projected;
    for (std::size_t t : regions[k])
      projected.push_back({proj(tris[t][0]), proj(tris[t][1]), proj(tris[t][2])});
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      const P2 c =
          CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      for (const auto& q : projected) {
        const auto turn = CGAL::orientation(q[0], q[1], q[2]);
        bool in = true;
        for (int e = 0; e < 3 && in; ++e)
          in = CGAL::orientation(q[std::size_t(e)], q[std::size_t((e + 1) % 3)], c) != -turn;
        if (in) {
          inside[k].insert(f);
          break;
        }
      }
    }
  }
  BoundarySubdivision<FT, 3> s;
  s.points.assign(all.begin(), all.end());
  add_vertex_faces(s);
  std::vector<std::map<VertexHandle, VertexId>> ids(regions.size());
  // In the triangulation's order, not the handles' (addresses): the exact comparisons of
  // vertex_id refine the lazy numbers' intervals, which later roundings read, so their order
  // must not depend on the heap layout (same input, same bytes).
  for (std::size_t k = 0; k < regions.size(); ++k)
    for (auto v = cdts[k].finite_vertices_begin(); v != cdts[k].finite_vertices_end(); ++v)
      ids[k][v] = vertex_id(s, lifted[k].at(v));
  // Edges and 2-faces are numbered in an order of their vertex ids, not in the triangulations'
  // iteration order, which differs between runs (heap layout): the face numbers decide the
  // order of the line-mesh points, and so the input order of the surface mesher.
  std::map<std::pair<VertexId, VertexId>, std::size_t> edge_of;
  for (std::size_t k = 0; k < regions.size(); ++k) {
    auto& cdt = cdts[k];
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
      if (!cdt.is_constrained(*e)) continue;
      const auto f = e->first;
      const int i = e->second;
      if (!inside[k].count(f) && !inside[k].count(f->neighbor(i))) continue;
      VertexId a = ids[k].at(f->vertex(cdt.cw(i))), b = ids[k].at(f->vertex(cdt.ccw(i)));
      if (a > b) std::swap(a, b);
      edge_of.emplace(std::make_pair(a, b), 0);
    }
  }
  for (auto& [ab, index] : edge_of) {
    index = s.faces.size();
    add_edge_face(s, ab.first, ab.second);
  }
  std::vector<BoundaryFace> facets;
  for (std::size_t k = 0; k < regions.size(); ++k) {
    auto& cdt = cdts[k];
    std::set<FaceHandle> seen;
    for (auto f0 = cdt.finite_faces_begin(); f0 != cdt.finite_faces_end(); ++f0) {
      FaceHandle h0 = f0;
      if (!inside[k].count(h0) || seen.count(h0)) continue;
      BoundaryFace face;
      face.dimension = 2;
      std::set<VertexId> verts;
      std::set<std::size_t> closure;
      std::vector<FaceHandle> stack{h0};
      seen.insert(h0);
      while (!stack.empty()) {
        auto h = stack.back();
        stack.pop_back();
        std::array<VertexId, 3> vids{};
        for (int i = 0; i < 3; ++i) vids[i] = ids[k].at(h->vertex(i));
        face.pieces.push_back(Simplex{vids[0], vids[1], vids[2]});
        for (int i = 0; i < 3; ++i) {
          verts.insert(vids[i]);
          closure.insert(vids[i]);
          const VertexId a = std::min(vids[(i + 1) % 3], vids[(i + 2) % 3]);
          const VertexId b = std::max(vids[(i + 1) % 3], vids[(i + 2) % 3]);
          if (cdt.is_constrained({h, i})) {
            closure.insert(edge_of.at({a, b}));
            continue;
          }
          auto n = h->neighbor(i);
          if (cdt.is_infinite(n) || seen.count(n) || !inside[k].count(n)) continue;
          seen.insert(n);
          stack.push_back(n);
        }
      }
      std::sort(face.pieces.begin(), face.pieces.end());
      face.vertices.assign(verts.begin(), verts.end());
      face.closure.assign(closure.begin(), closure.end());
      facets.push_back(std::move(face));
    }
  }
  // Distinct 2-faces have distinct vertex sets (they are separated by constrained edges).
  std::sort(facets.begin(), facets.end(),
            [](const BoundaryFace& x, const BoundaryFace& y) { return x.vertices < y.vertices; });
  for (auto& face : facets) {
    const auto& p0 = face.pieces.front();
    s.rep.push_back(centroid<FT, 3>({s.points[p0.v[0]], s.points[p0.v[1]], s.points[p0.v[2]]}));
    s.faces.push_back(std::move(face));
  }
  return s;
}

template <class FT>
std::vector<BoundarySubdivision<FT, 3>>
close_subdivisions_3d(const TemplatedStructure<FT, 3>& x,
                      const std::vector<TemplateBoundaryMapping<FT, 3>>& ms,
                      const MappingIndex<FT, 3>& ix, const BppOptions& o) {
  const std::size_t nt = x.templates.size();
  std::vector<std::vector<PointVec<FT, 3>>> tris(nt);
  std::vector<Cuts<FT>> cuts(nt);
  for (std::size_t t = 0; t < nt; ++t) tris[t] = boundary_facets(x.templates[t].mesh);
  auto add_segment = [&](std::size_t t, Point<FT, 3> a, Point<FT, 3> b) {
    if (PointLess<FT, 3>()(b, a)) std::swap(a, b);
    return cuts[t].segments.emplace(a, b).second;
  };
  // A domain is cut along the outline of its polygonal pieces: an edge two of them share lies
  // inside the domain (the pieces follow the carriers' triangles, whose inner edges are no
  // feature, see flat_regions). Segment and point pieces are cuts unless they are such an edge
  // or a polygon's vertex (facet pairs that only touch along a carrier edge give them).
  for (const auto& m : ms) {
    using Seg = std::pair<Point<FT, 3>, Point<FT, 3>>;
    const auto seg = [](Point<FT, 3> a, Point<FT, 3> b) {
      if (PointLess<FT, 3>()(b, a)) std::swap(a, b);
      return Seg{a, b};
    };
    std::map<Seg, int, std::less<>> outline;
    PointSet<FT, 3> corners;
    for (const auto& piece : m.domain) {
      const auto& v = piece.vertices;
      if (v.size() < 3) continue;
      for (std::size_t k = 0; k < v.size(); ++k) {
        ++outline[seg(v[k], v[(k + 1) % v.size()])];
        corners.insert(v[k]);
      }
    }
    for (const auto& piece : m.domain) {
      const auto& v = piece.vertices;
      if (v.size() == 1 && !corners.count(v[0])) cuts[m.from_template()].points.insert(v[0]);
      if (v.size() == 2 && !outline.count(seg(v[0], v[1])))
        add_segment(m.from_template(), v[0], v[1]);
    }
    for (const auto& [edge, n] : outline)
      if (n == 1) add_segment(m.from_template(), edge.first, edge.second);
  }
  std::vector<BoundarySubdivision<FT, 3>> sub(nt);
  std::vector<bool> dirty(nt, true);
  std::size_t created = 0;
  for (;;) {
    for (std::size_t t = 0; t < nt; ++t)
      if (dirty[t]) sub[t] = build_subdivision_3d<FT>(tris[t], cuts[t]);
    std::fill(dirty.begin(), dirty.end(), false);
    std::vector<std::set<std::pair<VertexId, VertexId>>> edges(nt);
    for (std::size_t t = 0; t < nt; ++t)
      for (const auto& g : sub[t].faces)
        if (g.dimension == 1) edges[t].emplace(g.vertices[0], g.vertices[1]);
    bool changed = false;
    auto note = [&](std::size_t t) {
      changed = true;
      dirty[t] = true;
      if (++created > o.max_compositions) {
        std::ostringstream m;
        m << "boundary patch partition: closing the template boundaries under compositions of "
             "template boundary mappings needs more than "
          << o.max_compositions
          << " composed images (𝔗_X explodes, e.g. an irrational in-plane rotation); raise "
             "--max-compositions to go on";
        throw CompositionLimitExceeded(m.str());
      }
    };
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t mi : ix.from[t]) {
        const auto& m = ms[mi];
        const auto& src = sub[t];
        const auto& dst = sub[m.to_template()];
        for (std::size_t f = 0; f < src.faces.size(); ++f) {
          const auto& face = src.faces[f];
          if (face.dimension > 1) break;
          if (!applies<FT, 3>(m, ix.box[mi], src.rep[f])) continue;
          if (face.dimension == 0) {
            const auto y = m.map(src.points[f]);
            if (!std::binary_search(dst.points.begin(), dst.points.end(), y, PointLess<FT, 3>()) &&
                cuts[m.to_template()].points.insert(y).second)
              note(m.to_template());
          } else {
            const auto a = m.map(src.points[face.vertices[0]]);
            const auto b = m.map(src.points[face.vertices[1]]);
            const bool both =
                std::binary_search(dst.points.begin(), dst.points.end(), a, PointLess<FT, 3>()) &&
                std::binary_search(dst.points.begin(), dst.points.end(), b, PointLess<FT, 3>());
            bool is_edge = false;
            if (both) {
              VertexId va = vertex_id(dst, a), vb = vertex_id(dst, b);
              if (va > vb) std::swap(va, vb);
              is_edge = edges[m.to_template()].count({va, vb}) > 0;
            }
            if (!is_edge && add_segment(m.to_template(), a, b)) note(m.to_template());
          }
        }
      }
    if (!changed) break;
  }
  return sub;
}

} // namespace
} // namespace symmesh::core
