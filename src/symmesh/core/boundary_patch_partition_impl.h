// Definition 4.7 mappings, the closed boundary subdivision, Algorithm 4.1, Definitions 4.8 and
// 4.9 and the valid vertex movement of Section 5.2.2 — spec/boundary-patches.md
//
// CGAL is used here only: exact segment/triangle intersections for the mapping domains and, in
// 3D, constrained triangulations of each boundary triangle with its cuts. The public headers
// stay free of CGAL.
//
// Definitions only, included by the translation units that instantiate them for one number
// type each (boundary_patch_partition.cpp: rationals; cyclotomic_instantiations.cpp: K_m).
#pragma once
#include "symmesh/core/boundary_patch_partition.h"

#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/kernel.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_vertex_base_2.h>
#include <CGAL/intersections.h>
#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <deque>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <type_traits>

namespace symmesh::core {
namespace {

template <class FT>
using KernelOf = std::conditional_t<std::is_same_v<FT, CGAL::Epeck::FT>, CGAL::Epeck,
                                    CGAL::Simple_cartesian<FT>>;

template <class FT, int D>
using PointSet = std::set<Point<FT, D>, PointLess<FT, D>>;

template <class FT, int D>
using PointVec = std::vector<Point<FT, D>>;

// ---------------------------------------------------------------------------------------------
// Exact small geometry.

template <class FT>
FT cross2(const Point<FT, 2>& a, const Point<FT, 2>& b) {
  return a[0] * b[1] - a[1] * b[0];
}

template <class FT>
Point<FT, 3> cross3(const Point<FT, 3>& a, const Point<FT, 3>& b) {
  Point<FT, 3> r;
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
  return r;
}

template <class FT, int D>
Point<FT, D> midpoint(const Point<FT, D>& a, const Point<FT, D>& b) {
  return scaled<FT, D>(a + b, FT(1) / FT(2));
}

template <class FT, int D>
Point<FT, D> centroid(const PointVec<FT, D>& p) {
  Point<FT, D> s = zero_point<FT, D>();
  for (const auto& q : p) s = s + q;
  return scaled<FT, D>(s, FT(1) / FT(int(p.size())));
}

template <class FT, int D>
Box<FT, D> piece_box(const std::vector<DomainPiece<FT, D>>& pieces) {
  PointVec<FT, D> all;
  for (const auto& p : pieces) all.insert(all.end(), p.vertices.begin(), p.vertices.end());
  return box_of<FT, D>(all);
}

template <class FT, int D>
bool box_contains(const Box<FT, D>& b, const Point<FT, D>& x) {
  return b.overlaps(box_of<FT, D>({x}));
}

/// Orders the vertices of a convex polygon in 3D cyclically (exact: orientation comparisons in
/// the projection that drops the dominant normal axis).
template <class FT>
PointVec<FT, 3> convex_cyclic_order(PointVec<FT, 3> p) {
  std::sort(p.begin(), p.end(), PointLess<FT, 3>());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  const auto n = cross3<FT>(p[1] - p[0], p[2] - p[0]);
  Point<FT, 3> nn = n;
  // p[0..2] might be collinear; find any non-degenerate normal.
  for (std::size_t k = 3; k < p.size() && nn[0] == 0 && nn[1] == 0 && nn[2] == 0; ++k)
    nn = cross3<FT>(p[1] - p[0], p[k] - p[0]);
  int drop = 0;
  for (int a = 1; a < 3; ++a)
    if (CGAL::abs(nn[a]) > CGAL::abs(nn[drop])) drop = a;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const auto o = p[0];
  std::sort(p.begin() + 1, p.end(), [&](const Point<FT, 3>& a, const Point<FT, 3>& b) {
    const FT c = (a[u] - o[u]) * (b[v] - o[v]) - (a[v] - o[v]) * (b[u] - o[u]);
    if (c != 0) return c > 0;
    return dot<FT, 3>(a - o, a - o) < dot<FT, 3>(b - o, b - o);
  });
  return p;
}

// ---------------------------------------------------------------------------------------------
// Definition 4.7: the mappings and their exact domains.

template <class FT, int D>
std::vector<PointVec<FT, D>> boundary_facets(const ElementComplex<FT, D>& m) {
  std::vector<PointVec<FT, D>> out;
  const auto b = mesh_boundary(m);
  for (const auto& e : b.elements)
    if (e.dim() == D - 1) out.push_back(b.coords(e));
  return out;
}

template <class FT, int D>
void add_intersection(const PointVec<FT, D>& a, const PointVec<FT, D>& b,
                      std::vector<DomainPiece<FT, D>>& out) {
  using K = KernelOf<FT>;
  if constexpr (D == 2) {
    using P = typename K::Point_2;
    const typename K::Segment_2 sa(P(a[0][0], a[0][1]), P(a[1][0], a[1][1]));
    const typename K::Segment_2 sb(P(b[0][0], b[0][1]), P(b[1][0], b[1][1]));
    const auto r = CGAL::intersection(sa, sb);
    if (!r) return;
    auto pt = [](const P& p) {
      Point<FT, 2> q;
      q[0] = p.x();
      q[1] = p.y();
      return q;
    };
    if (const P* p = boost::get<P>(&*r))
      out.push_back({{pt(*p)}});
    else if (const auto* s = boost::get<typename K::Segment_2>(&*r))
      out.push_back({{pt(s->source()), pt(s->target())}});
  } else {
    using P = typename K::Point_3;
    auto cg = [](const Point<FT, 3>& p) { return P(p[0], p[1], p[2]); };
    auto pt = [](const P& p) {
      Point<FT, 3> q;
      q[0] = p.x();
      q[1] = p.y();
      q[2] = p.z();
      return q;
    };
    const typename K::Triangle_3 ta(cg(a[0]), cg(a[1]), cg(a[2]));
    const typename K::Triangle_3 tb(cg(b[0]), cg(b[1]), cg(b[2]));
    const auto r = CGAL::intersection(ta, tb);
    if (!r) return;
    if (const P* p = boost::get<P>(&*r))
      out.push_back({{pt(*p)}});
    else if (const auto* s = boost::get<typename K::Segment_3>(&*r))
      out.push_back({{pt(s->source()), pt(s->target())}});
    else if (const auto* t = boost::get<typename K::Triangle_3>(&*r))
      out.push_back(
          {convex_cyclic_order<FT>({pt(t->vertex(0)), pt(t->vertex(1)), pt(t->vertex(2))})});
    else if (const auto* v = boost::get<std::vector<P>>(&*r)) {
      PointVec<FT, 3> q;
      for (const auto& p : *v) q.push_back(pt(p));
      out.push_back({convex_cyclic_order<FT>(q)});
    }
  }
}

template <class FT, int D>
EnclosingBox<FT, D> enclosure(const PointVec<FT, D>& p) {
  std::vector<VertexId> all(p.size());
  std::iota(all.begin(), all.end(), VertexId(0));
  return EnclosingBox<FT, D>::of(p, all);
}

/// interf_geo(a, b) = bnd(inst a) ∩ bnd(inst b) for non-overlapping pure instances, as convex
/// pieces in world coordinates, deduplicated (sorted vertex sets).
template <class FT, int D>
std::vector<DomainPiece<FT, D>> geometry_interface_pieces(
    const std::vector<PointVec<FT, D>>& fa, const std::vector<EnclosingBox<FT, D>>& ba,
    const std::vector<PointVec<FT, D>>& fb, const std::vector<EnclosingBox<FT, D>>& bb) {
  std::vector<DomainPiece<FT, D>> raw;
  for (std::size_t j = 0; j < fa.size(); ++j)
    for (std::size_t k = 0; k < fb.size(); ++k)
      if (ba[j].may_meet(bb[k])) add_intersection<FT, D>(fa[j], fb[k], raw);
  std::vector<DomainPiece<FT, D>> out;
  for (auto& p : raw) {
    auto key = p.vertices;
    std::sort(key.begin(), key.end(), PointLess<FT, D>());
    bool dup = false;
    for (const auto& q : out) {
      auto k2 = q.vertices;
      std::sort(k2.begin(), k2.end(), PointLess<FT, D>());
      if (k2 == key) {
        dup = true;
        break;
      }
    }
    if (!dup) out.push_back(std::move(p));
  }
  return out;
}

/// The pieces in the coordinates of the instance with world facets `world` (the instance's
/// transformation applied to `local`, facet for facet): a piece vertex that is a facet end of
/// that instance becomes the template's own point (no arithmetic, and later comparisons with it
/// are by identity), any other is mapped by `t_inverse`.
template <class FT, int D>
std::vector<DomainPiece<FT, D>>
pull_back(const std::vector<DomainPiece<FT, D>>& pieces, const std::vector<PointVec<FT, D>>& world,
          const std::vector<PointVec<FT, D>>& local, const RigidTransformation<FT, D>& t_inverse) {
  auto out = pieces;
  for (auto& p : out)
    for (auto& v : p.vertices) {
      const Point<FT, D>* same = nullptr;
      for (std::size_t k = 0; k < world.size() && !same; ++k)
        for (std::size_t j = 0; j < world[k].size() && !same; ++j)
          if (world[k][j] == v) same = &local[k][j];
      v = same ? *same : t_inverse(v);
    }
  return out;
}

} // namespace

template <class FT, int D>
std::vector<TemplateBoundaryMapping<FT, D>>
template_boundary_mappings(const TemplatedStructure<FT, D>& x, bool check_well_formed,
                           const std::function<void(std::size_t, std::size_t)>& on_progress) {
  std::ostringstream why;
  if (check_well_formed && !x.is_well_formed(&why)) throw std::invalid_argument(why.str());
  std::vector<TemplateBoundaryMapping<FT, D>> out;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    TemplateBoundaryMapping<FT, D> id;
    id.to = id.from = InstanceId{i, 0};
    id.whole_boundary = true;
    id.inverse = out.size();
    out.push_back(id);
  }
  // Instances and their world boundary facets only: identifying equal world points as AT
  // (apply_template) does would decide every shared coordinate exactly, for nothing here.
  const auto ids = x.instance_ids();
  std::vector<std::vector<PointVec<FT, D>>> facets; // per instance, world coordinates
  std::vector<std::vector<PointVec<FT, D>>> template_facets;
  // Boxes are certified enclosures (intervals): filters that never decide a shared coordinate
  // exactly; the segment intersections decide.
  std::vector<EnclosingBox<FT, D>> instance_box;
  std::vector<std::vector<EnclosingBox<FT, D>>> facet_boxes;
  std::vector<RigidTransformation<FT, D>> inverse; // T^{-1} per instance, once
  for (const auto& t : x.templates) template_facets.push_back(boundary_facets(t.mesh));
  for (auto id : ids) {
    inverse.push_back(x.tf(id).inverse());
    auto f = template_facets[id.i];
    PointVec<FT, D> ends;
    for (auto& s : f)
      for (auto& p : s) {
        p = x.tf(id)(p);
        ends.push_back(p);
      }
    instance_box.push_back(enclosure<FT, D>(ends));
    facet_boxes.emplace_back();
    for (const auto& s : f) facet_boxes.back().push_back(enclosure<FT, D>(s));
    facets.push_back(std::move(f));
  }
  // interf_geo = bnd ∩ bnd for non-overlapping instances, so two instances are neighbours iff
  // some two boundary facets meet; this avoids the cell-pair tests of neighbouring_instances.
  std::vector<std::pair<std::size_t, std::size_t>> candidates;
  for_each_overlapping_box_pair(instance_box, [&](std::size_t a, std::size_t b) {
    candidates.emplace_back(a, b);
    return true;
  });
  std::sort(candidates.begin(), candidates.end());
  std::size_t decided = 0;
  for (const auto& [a, b] : candidates) {
    if (on_progress) on_progress(decided++, candidates.size());
    const auto pieces =
        geometry_interface_pieces<FT, D>(facets[a], facet_boxes[a], facets[b], facet_boxes[b]);
    if (pieces.empty()) continue;
    const auto ia = ids[a], ib = ids[b];
    TemplateBoundaryMapping<FT, D> ab, ba;
    ab.to = ia;
    ab.from = ib;
    ab.map = x.tf(ia).inverse() * x.tf(ib);
    ab.domain = pull_back<FT, D>(pieces, facets[b], template_facets[ib.i], inverse[b]);
    ba.to = ib;
    ba.from = ia;
    ba.map = ab.map.inverse(); // = T_b^{-1} ∘ T_a exactly; a transpose, not a product
    ba.domain = pull_back<FT, D>(pieces, facets[a], template_facets[ia.i], inverse[a]);
    ab.inverse = out.size() + 1;
    ba.inverse = out.size();
    out.push_back(std::move(ab));
    out.push_back(std::move(ba));
  }
  return out;
}

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
    normal = cross3<FT>(tri[1] - tri[0], tri[2] - tri[0]);
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

template <class FT>
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
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
    const Point<FT, 3> n = cross3<FT>(x[1] - x[0], x[2] - x[0]);
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
  using VertexHandle = typename Cdt<FT>::Vertex_handle;
  using FaceHandle = typename Cdt<FT>::Face_handle;
  // One constrained triangulation per flat region, in the region's plane: its outline (edges
  // in one of its triangles) and the cuts are constraints, the carrier's inner edges are not.
  const auto regions = flat_regions<FT>(tris);
  std::vector<Cdt<FT>> cdts(regions.size());
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
    for (const auto& [edge, n] : uses) {
      cdt.insert(proj(edge.first));
      cdt.insert(proj(edge.second));
      if (n == 1) cdt.insert_constraint(proj(edge.first), proj(edge.second));
    }
    for (std::size_t t : regions[k]) {
      const auto& tri = tris[t];
      const typename K::Triangle_3 t3(cg(tri[0]), cg(tri[1]), cg(tri[2]));
      const auto tb = box_of<FT, 3>(tri);
      for (const auto& p : cuts.points)
        if (box_contains<FT, 3>(tb, p) && point_in_simplex<FT, 3>(tri, p)) cdt.insert(proj(p));
      for (const auto& [a, b] : cuts.segments) {
        if (!tb.overlaps(box_of<FT, 3>({a, b}))) continue;
        const auto r = CGAL::intersection(typename K::Segment_3(cg(a), cg(b)), t3);
        if (!r) continue;
        if (const P3* p = boost::get<P3>(&*r))
          cdt.insert(proj(pt(*p)));
        else if (const auto* sg = boost::get<typename K::Segment_3>(&*r))
          cdt.insert_constraint(proj(pt(sg->source())), proj(pt(sg->target())));
      }
    }
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      all.insert(lifted[k][v] = fr.lift(v->point().x(), v->point().y()));
    // The region may be non-convex: keep the faces whose centroid lies in one of its triangles.
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      const P2 c =
          CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      const Point<FT, 3> q = fr.lift(c.x(), c.y());
      for (std::size_t t : regions[k])
        if (box_contains<FT, 3>(box_of<FT, 3>(tris[t]), q) && point_in_simplex<FT, 3>(tris[t], q)) {
          inside[k].insert(f);
          break;
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

// ---------------------------------------------------------------------------------------------
// Face automaton, Moore refinement, patches, relation, regularity.

template <class FT, int D>
using FaceKey = std::pair<int, std::vector<VertexId>>;

template <class FT, int D>
std::vector<std::map<FaceKey<FT, D>, std::size_t>>
face_keys(const std::vector<BoundarySubdivision<FT, D>>& sub) {
  std::vector<std::map<FaceKey<FT, D>, std::size_t>> out(sub.size());
  for (std::size_t t = 0; t < sub.size(); ++t)
    for (std::size_t f = 0; f < sub[t].faces.size(); ++f) {
      const auto& face = sub[t].faces[f];
      if (!out[t].emplace(FaceKey<FT, D>{face.dimension, face.vertices}, f).second)
        throw std::logic_error("boundary subdivision: two faces with the same vertices");
    }
  return out;
}

} // namespace

template <class FT, int D>
BoundaryPatchPartition<FT, D> boundary_patch_partition(const TemplatedStructure<FT, D>& x,
                                                       const BppOptions& options) {
  BoundaryPatchPartition<FT, D> r;
  r.mappings = template_boundary_mappings(x, !options.well_formed_checked, options.on_progress);
  const std::size_t nt = x.templates.size();
  const auto ix = index_mappings<FT, D>(r.mappings, nt);
  if constexpr (D == 2)
    r.subdivisions = close_subdivisions_2d<FT>(x, r.mappings, ix, options);
  else
    r.subdivisions = close_subdivisions_3d<FT>(x, r.mappings, ix, options);
  const auto keys = face_keys<FT, D>(r.subdivisions);

  // Global state numbering and transitions δ(s, letter).
  std::vector<std::size_t> offset(nt + 1, 0);
  for (std::size_t t = 0; t < nt; ++t) offset[t + 1] = offset[t] + r.subdivisions[t].faces.size();
  const std::size_t ns = offset[nt];
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> delta(ns);
  r.letter_action.resize(r.mappings.size());
  for (std::size_t m = 0; m < r.mappings.size(); ++m) {
    const auto& mp = r.mappings[m];
    const std::size_t s = mp.from_template(), d = mp.to_template();
    const auto& src = r.subdivisions[s];
    const auto& dst = r.subdivisions[d];
    for (std::size_t f = 0; f < src.faces.size(); ++f) {
      if (!applies<FT, D>(mp, ix.box[m], src.rep[f])) continue;
      std::size_t g = f;
      if (!mp.whole_boundary) {
        std::vector<VertexId> img;
        for (VertexId v : src.faces[f].vertices)
          img.push_back(vertex_id(dst, apply_mapping<FT, D>(r.mappings, m, src.points[v])));
        std::sort(img.begin(), img.end());
        auto it = keys[d].find({src.faces[f].dimension, img});
        if (it == keys[d].end())
          throw std::logic_error(
              "boundary subdivision: a mapping does not send a face onto a face");
        g = it->second;
      }
      delta[offset[s] + f].emplace_back(m, offset[d] + g);
      r.letter_action[m].emplace_back(f, g);
    }
  }

  // Partition refinement to classes of equal languages (= equal Algorithm 4.1 signatures):
  // Moore's algorithm, but each round re-examines only states whose successors changed block, so
  // a long chain of faces (one split per round) costs O(n) rather than O(n^2).
  std::vector<std::size_t> block(ns);
  {
    std::vector<std::vector<std::size_t>> pred(ns);
    for (std::size_t s = 0; s < ns; ++s)
      for (const auto& [m, g] : delta[s]) pred[g].push_back(s);
    std::map<std::vector<std::size_t>, std::size_t> ids;
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t s = offset[t]; s < offset[t + 1]; ++s) {
        std::vector<std::size_t> key{t};
        for (const auto& [m, g] : delta[s]) key.push_back(m);
        block[s] = ids.emplace(key, ids.size()).first->second;
      }
    // Rounds use the block ids of the round's start (moves are applied at its end). In a block,
    // members not marked dirty share their successor blocks (nothing they point to moved since
    // the block was last checked), so the dirty members with another key split off; if all are
    // dirty, the largest group keeps the id. A block with one key is never renamed, so every
    // round splits a block or ends the loop.
    std::vector<std::vector<std::size_t>> members(ids.size());
    std::vector<std::size_t> pos(ns);
    for (std::size_t s = 0; s < ns; ++s) {
      pos[s] = members[block[s]].size();
      members[block[s]].push_back(s);
    }
    auto key_of = [&](std::size_t s) {
      std::vector<std::size_t> k;
      for (const auto& [m, g] : delta[s]) k.push_back(block[g]);
      return k;
    };
    std::vector<std::size_t> dirty(ns);
    for (std::size_t s = 0; s < ns; ++s) dirty[s] = s;
    std::vector<char> is_dirty(ns, 1);
    while (!dirty.empty()) {
      std::map<std::size_t, std::vector<std::size_t>> by_block;
      for (std::size_t s : dirty) by_block[block[s]].push_back(s);
      std::vector<std::pair<std::size_t, std::size_t>> moves;
      for (auto& [b, ds] : by_block) {
        std::optional<std::vector<std::size_t>> stay;
        if (ds.size() < members[b].size())
          for (std::size_t m : members[b])
            if (!is_dirty[m]) {
              stay = key_of(m);
              break;
            }
        std::map<std::vector<std::size_t>, std::vector<std::size_t>> groups;
        for (std::size_t s : ds) groups[key_of(s)].push_back(s);
        if (!stay) {
          stay = groups.begin()->first;
          for (const auto& [k, g] : groups)
            if (g.size() > groups[*stay].size()) stay = k;
        }
        for (const auto& [k, g] : groups) {
          if (k == *stay) continue;
          const std::size_t nb = members.size();
          members.emplace_back();
          for (std::size_t s : g) moves.emplace_back(s, nb);
        }
      }
      for (std::size_t s : dirty) is_dirty[s] = 0;
      dirty.clear();
      for (const auto& [s, nb] : moves) {
        auto& from = members[block[s]];
        pos[from.back()] = pos[s];
        from[pos[s]] = from.back();
        from.pop_back();
        pos[s] = members[nb].size();
        members[nb].push_back(s);
        block[s] = nb;
      }
      for (const auto& [s, nb] : moves)
        for (std::size_t q : pred[s])
          if (!is_dirty[q]) {
            is_dirty[q] = 1;
            dirty.push_back(q);
          }
    }
    // Dense, deterministic class numbers (first occurrence order).
    std::map<std::size_t, std::size_t> dense;
    for (std::size_t s = 0; s < ns; ++s)
      block[s] = dense.emplace(block[s], dense.size()).first->second;
  }

  // Patches: connected unions of faces of one class (incidence through closures).
  r.face_class.resize(nt);
  r.face_patch.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& sub = r.subdivisions[t];
    const std::size_t n = sub.faces.size();
    std::vector<std::size_t> rank(n), parent(n);
    boost::disjoint_sets<std::size_t*, std::size_t*> ds(rank.data(), parent.data());
    for (std::size_t f = 0; f < n; ++f) ds.make_set(f);
    r.face_class[t].resize(n);
    for (std::size_t f = 0; f < n; ++f) {
      r.face_class[t][f] = block[offset[t] + f];
      for (std::size_t g : sub.faces[f].closure)
        if (block[offset[t] + g] == block[offset[t] + f]) ds.union_set(f, g);
    }
    std::map<std::size_t, std::size_t> patch_of_root;
    r.face_patch[t].resize(n);
    for (std::size_t f = 0; f < n; ++f) {
      const std::size_t root = ds.find_set(f);
      auto [it, fresh] = patch_of_root.emplace(root, r.patches.size());
      if (fresh) {
        BoundaryPatch p;
        p.template_index = t;
        p.dimension = -1;
        r.patches.push_back(p);
      }
      auto& p = r.patches[it->second];
      p.faces.push_back(f);
      if (sub.faces[f].dimension > p.dimension) {
        p.dimension = sub.faces[f].dimension;
        p.representative = f;
      }
      r.face_patch[t][f] = it->second;
    }
  }

  // Patch graph and the relation (Def 4.8) by union-find.
  const std::size_t np = r.patches.size();
  std::vector<std::size_t> prank(np), pparent(np);
  boost::disjoint_sets<std::size_t*, std::size_t*> pds(prank.data(), pparent.data());
  for (std::size_t p = 0; p < np; ++p) pds.make_set(p);
  std::vector<std::vector<std::size_t>> out_arrows(np);
  for (std::size_t p = 0; p < np; ++p) {
    const auto& patch = r.patches[p];
    for (const auto& [m, g] : delta[offset[patch.template_index] + patch.representative]) {
      std::size_t gt = 0;
      while (offset[gt + 1] <= g) ++gt;
      const std::size_t q = r.face_patch[gt][g - offset[gt]];
      out_arrows[p].push_back(r.arrows.size());
      r.arrows.push_back({p, q, m});
      pds.union_set(p, q);
    }
  }
  {
    std::map<std::size_t, std::size_t> class_of_root;
    for (std::size_t p = 0; p < np; ++p) {
      auto [it, fresh] = class_of_root.emplace(pds.find_set(p), r.classes.size());
      if (fresh) r.classes.emplace_back();
      r.classes[it->second].push_back(p);
      r.patches[p].relation_class = it->second;
    }
  }

  // BFS per class with composition potentials; an inconsistent arrow witnesses irregularity
  // (Eq. 4.13). Two rigid maps agree on a patch iff they agree on an affine basis of its vertices,
  // and every mapping sends subdivision vertices to subdivision vertices, so a potential is kept
  // as the vertex ids of the basis images, read off the automaton on vertex faces: no products
  // of exact maps (the words are read off the BFS tree when needed).
  auto vertex_step = [&](std::size_t t, VertexId v, std::size_t letter) {
    const auto& out = delta[offset[t] + v];
    const auto it =
        std::lower_bound(out.begin(), out.end(), std::make_pair(letter, std::size_t(0)));
    if (it == out.end() || it->first != letter)
      throw std::logic_error("boundary subdivision: a mapping applies to a patch but not to a "
                             "vertex of its closure");
    return VertexId(it->second - offset[r.mappings[letter].to_template()]);
  };
  r.tree_parent.assign(np, std::nullopt);
  std::vector<std::optional<std::vector<VertexId>>> pot(np);
  for (const auto& cls : r.classes) {
    const std::size_t root = cls.front();
    const auto& rs = r.subdivisions[r.patches[root].template_index];
    std::vector<VertexId> ids; // in lexicographic point order, as the subdivision numbers them
    for (std::size_t f : r.patches[root].faces)
      for (VertexId v : rs.faces[f].vertices) ids.push_back(v);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<VertexId> basis;
    PointVec<FT, D> basis_points;
    for (VertexId v : ids) {
      if (int(basis.size()) == D + 1) break;
      basis_points.push_back(rs.points[v]);
      if (affinely_independent<FT, D>(basis_points))
        basis.push_back(v);
      else
        basis_points.pop_back();
    }
    pot[root] = basis;
    std::deque<std::size_t> queue{root};
    while (!queue.empty()) {
      const std::size_t p = queue.front();
      queue.pop_front();
      for (std::size_t ai : out_arrows[p]) {
        const auto& a = r.arrows[ai];
        std::vector<VertexId> c;
        for (VertexId v : *pot[p])
          c.push_back(vertex_step(r.patches[p].template_index, v, a.letter));
        if (!pot[a.to]) {
          pot[a.to] = std::move(c);
          r.tree_parent[a.to] = a;
          queue.push_back(a.to);
        } else if (!r.irregularity && *pot[a.to] != c) {
          IrregularityWitness<FT, D> w;
          w.patch = root;
          w.target = a.to;
          w.f1 = r.composition_between(root, a.to);
          auto f2 = r.composition_between(root, p).letters;
          f2.push_back(a.letter);
          w.f2 = compose<FT, D>(r.mappings, f2);
          w.symmetry = w.f1.map.inverse() * w.f2.map;
          r.irregularity = w;
        }
      }
    }
  }
  return r;
}

template <class FT, int D>
std::vector<std::size_t> BoundaryPatchPartition<FT, D>::bndpart(std::size_t t) const {
  std::vector<std::size_t> out;
  for (std::size_t p = 0; p < patches.size(); ++p)
    if (patches[p].template_index == t) out.push_back(p);
  return out;
}

template <class FT, int D>
std::size_t BoundaryPatchPartition<FT, D>::patch_count(std::size_t t, int dim) const {
  std::size_t n = 0;
  for (const auto& p : patches)
    if (p.template_index == t && p.dimension == dim) ++n;
  return n;
}

template <class FT, int D>
Composition<FT, D> BoundaryPatchPartition<FT, D>::composition_between(std::size_t a,
                                                                      std::size_t b) const {
  if (patches.at(a).relation_class != patches.at(b).relation_class)
    throw std::invalid_argument("composition_between: patches are not related");
  auto path = [&](std::size_t p) {
    std::vector<std::size_t> letters;
    while (tree_parent[p]) {
      letters.push_back(tree_parent[p]->letter);
      p = tree_parent[p]->from;
    }
    std::reverse(letters.begin(), letters.end());
    return letters;
  };
  const auto pa = path(a), pb = path(b);
  std::vector<std::size_t> letters;
  for (auto it = pa.rbegin(); it != pa.rend(); ++it) letters.push_back(mappings[*it].inverse);
  letters.insert(letters.end(), pb.begin(), pb.end());
  return compose<FT, D>(mappings, letters);
}

template <class FT, int D>
std::optional<FaceRef> BoundaryPatchPartition<FT, D>::step(FaceRef face, std::size_t letter) const {
  const auto& m = mappings.at(letter);
  if (m.from_template() != face.t) return std::nullopt;
  const auto& src = subdivisions[face.t];
  if (!m.in_domain(src.rep.at(face.f))) return std::nullopt;
  if (m.whole_boundary) return face;
  const auto& dst = subdivisions[m.to_template()];
  std::vector<VertexId> img;
  for (VertexId v : src.faces[face.f].vertices) img.push_back(vertex_id(dst, m.map(src.points[v])));
  std::sort(img.begin(), img.end());
  for (std::size_t g = 0; g < dst.faces.size(); ++g)
    if (dst.faces[g].dimension == src.faces[face.f].dimension && dst.faces[g].vertices == img)
      return FaceRef{m.to_template(), g};
  throw std::logic_error("boundary subdivision: a mapping does not send a face onto a face");
}

template <class FT, int D>
std::optional<std::size_t> BoundaryPatchPartition<FT, D>::locate(std::size_t t,
                                                                 const Point<FT, D>& x) const {
  const auto& s = subdivisions.at(t);
  auto it = std::lower_bound(s.points.begin(), s.points.end(), x, PointLess<FT, D>());
  if (it != s.points.end() && *it == x) return std::size_t(it - s.points.begin());
  for (int dim = 1; dim < D; ++dim)
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      if (s.faces[f].dimension != dim) continue;
      for (const auto& piece : s.faces[f].pieces) {
        PointVec<FT, D> c;
        for (VertexId v : piece) c.push_back(s.points[v]);
        if (dim == 1 ? point_on_segment<FT, D>(c[0], c[1], x) : point_in_simplex<FT, D>(c, x))
          return f;
      }
    }
  return std::nullopt;
}

template <class FT, int D>
std::vector<std::vector<Point<FT, D>>>
BoundaryPatchPartition<FT, D>::patch_simplices(std::size_t p) const {
  const auto& patch = patches.at(p);
  const auto& s = subdivisions[patch.template_index];
  std::vector<std::vector<Point<FT, D>>> out;
  for (std::size_t f : patch.faces)
    for (const auto& piece : s.faces[f].pieces) {
      std::vector<Point<FT, D>> c;
      for (VertexId v : piece) c.push_back(s.points[v]);
      out.push_back(std::move(c));
    }
  return out;
}

template <class FT, int D>
bool BoundarySubdivision<FT, D>::is_valid(std::ostream* why) const {
  auto fail = [&](const std::string& m) {
    if (why) *why << m;
    return false;
  };
  if (!std::is_sorted(points.begin(), points.end(), PointLess<FT, D>()))
    return fail("subdivision vertices are not in lexicographic order");
  if (faces.size() != rep.size()) return fail("a face has no representative point");
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    if (f < points.size() &&
        (face.dimension != 0 || face.vertices != std::vector<VertexId>{VertexId(f)}))
      return fail("face " + std::to_string(f) + " should be vertex " + std::to_string(f));
    if (face.dimension < 0 || face.dimension >= D) return fail("face dimension out of range");
    for (std::size_t g : face.closure)
      if (g >= faces.size() || faces[g].dimension >= face.dimension)
        return fail("face " + std::to_string(f) + " has an invalid closure face");
    for (VertexId v : face.vertices)
      if (v >= points.size()) return fail("face vertex out of range");
  }
  return true;
}

template <class FT, int D>
bool BoundaryPatchPartition<FT, D>::is_valid(std::ostream* why) const {
  auto fail = [&](const std::string& m) {
    if (why) *why << m;
    return false;
  };
  for (const auto& s : subdivisions)
    if (!s.is_valid(why)) return false;
  std::vector<std::set<std::size_t>> covered(subdivisions.size());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const auto& patch = patches[p];
    if (patch.faces.empty()) return fail("empty patch " + std::to_string(p));
    for (std::size_t f : patch.faces) {
      if (!covered[patch.template_index].insert(f).second)
        return fail("a face lies in two patches");
      if (face_patch[patch.template_index][f] != p) return fail("face_patch disagrees");
    }
    if (std::find(classes.at(patch.relation_class).begin(), classes[patch.relation_class].end(),
                  p) == classes[patch.relation_class].end())
      return fail("patch missing from its relation class");
  }
  for (std::size_t t = 0; t < subdivisions.size(); ++t)
    if (covered[t].size() != subdivisions[t].faces.size())
      return fail("template " + std::to_string(t + 1) + ": patches do not cover the boundary");
  for (const auto& a : arrows)
    if (patches.at(a.from).relation_class != patches.at(a.to).relation_class)
      return fail("an arrow joins two relation classes");
  return true;
}

// ---------------------------------------------------------------------------------------------
// 𝔗_X enumeration and the brute-force regularity verdict.

template <class FT, int D>
std::vector<RestrictedComposition<FT, D>>
enumerate_compositions(const BoundaryPatchPartition<FT, D>& bpp, std::size_t limit) {
  struct State {
    RestrictedComposition<FT, D> rc;
    std::vector<FaceRef> image; ///< image face of each domain face
  };
  std::vector<State> all;
  std::set<std::tuple<std::size_t, std::size_t, std::vector<std::size_t>, std::vector<VertexId>>>
      seen;
  auto admit = [&](State st) {
    if (st.rc.domain.empty()) return;
    std::vector<VertexId> imgs;
    const auto& src = bpp.subdivisions[st.rc.from_template];
    const auto& dst = bpp.subdivisions[st.rc.to_template];
    std::set<VertexId> dv;
    for (std::size_t f : st.rc.domain)
      for (VertexId v : src.faces[f].vertices) dv.insert(v);
    for (VertexId v : dv) imgs.push_back(vertex_id(dst, st.rc.composition.map(src.points[v])));
    if (!seen.emplace(st.rc.from_template, st.rc.to_template, st.rc.domain, imgs).second) return;
    if (all.size() >= limit) {
      std::ostringstream m;
      m << "𝔗_X has more than " << limit << " distinct compositions; raise the limit to go on";
      throw CompositionLimitExceeded(m.str());
    }
    all.push_back(std::move(st));
  };
  for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
    const auto& m = bpp.mappings[l];
    State st;
    st.rc.composition = compose<FT, D>(bpp.mappings, {l});
    st.rc.from_template = m.from_template();
    st.rc.to_template = m.to_template();
    for (std::size_t f = 0; f < bpp.subdivisions[m.from_template()].faces.size(); ++f)
      if (auto g = bpp.step({m.from_template(), f}, l)) {
        st.rc.domain.push_back(f);
        st.image.push_back(*g);
      }
    admit(std::move(st));
  }
  for (std::size_t k = 0; k < all.size(); ++k)
    for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
      if (bpp.mappings[l].from_template() != all[k].rc.to_template) continue;
      State st;
      st.rc.composition = all[k].rc.composition;
      st.rc.composition.letters.push_back(l);
      st.rc.composition.map = bpp.mappings[l].map * st.rc.composition.map;
      st.rc.from_template = all[k].rc.from_template;
      st.rc.to_template = bpp.mappings[l].to_template();
      for (std::size_t q = 0; q < all[k].rc.domain.size(); ++q)
        if (auto g = bpp.step(all[k].image[q], l)) {
          st.rc.domain.push_back(all[k].rc.domain[q]);
          st.image.push_back(*g);
        }
      admit(std::move(st));
    }
  std::vector<RestrictedComposition<FT, D>> out;
  for (auto& s : all) out.push_back(std::move(s.rc));
  return out;
}

template <class FT, int D>
bool regular_by_enumeration(const BoundaryPatchPartition<FT, D>& bpp,
                            const std::vector<RestrictedComposition<FT, D>>& all) {
  for (std::size_t p = 0; p < bpp.patches.size(); ++p) {
    const auto& patch = bpp.patches[p];
    const auto& src = bpp.subdivisions[patch.template_index];
    PointVec<FT, D> verts;
    for (std::size_t f : patch.faces)
      for (VertexId v : src.faces[f].vertices) verts.push_back(src.points[v]);
    std::map<std::size_t, const RigidTransformation<FT, D>*> by_target;
    for (const auto& c : all) {
      if (c.from_template != patch.template_index) continue;
      if (!std::binary_search(c.domain.begin(), c.domain.end(), patch.representative)) continue;
      // Image patch of the representative face under c.
      FaceRef f{patch.template_index, patch.representative};
      for (std::size_t l : c.composition.letters) f = *bpp.step(f, l);
      const std::size_t target = bpp.face_patch[f.t][f.f];
      auto [it, fresh] = by_target.emplace(target, &c.composition.map);
      if (fresh) continue;
      for (const auto& v : verts)
        if ((*it->second)(v) != c.composition.map(v)) return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// Section 5.2.2.

template <class FT, int D>
VertexMovement<FT, D> valid_vertex_movement(const BoundaryPatchPartition<FT, D>& bpp, std::size_t t,
                                            const Point<FT, D>& x) {
  const auto face = bpp.locate(t, x);
  if (!face)
    throw std::invalid_argument("valid_vertex_movement: the point is not on the boundary of "
                                "template " +
                                std::to_string(t + 1));
  const auto& s = bpp.subdivisions[t];
  auto closed = [&](std::size_t p) {
    std::set<std::size_t> c;
    for (std::size_t f : bpp.patches[p].faces) {
      c.insert(f);
      c.insert(s.faces[f].closure.begin(), s.faces[f].closure.end());
    }
    return c;
  };
  VertexMovement<FT, D> mv;
  std::optional<std::set<std::size_t>> meet;
  for (std::size_t p : bpp.bndpart(t)) {
    const auto c = closed(p);
    if (!c.count(*face)) continue;
    mv.patches.push_back(p);
    if (!meet) {
      meet = c;
      continue;
    }
    std::set<std::size_t> both;
    std::set_intersection(meet->begin(), meet->end(), c.begin(), c.end(),
                          std::inserter(both, both.end()));
    meet = std::move(both);
  }
  mv.dimension = 0;
  for (std::size_t f : *meet) {
    mv.dimension = std::max(mv.dimension, s.faces[f].dimension);
    for (const auto& piece : s.faces[f].pieces) {
      std::vector<Point<FT, D>> c;
      for (VertexId v : piece) c.push_back(s.points[v]);
      mv.allowed.push_back(std::move(c));
    }
  }
  mv.can_move = bpp.regular() && mv.dimension > 0;
  return mv;
}

#define SYMMESH_BPP_INSTANTIATE(FT, D)                                                             \
  template std::vector<TemplateBoundaryMapping<FT, D>> template_boundary_mappings<FT, D>(          \
      const TemplatedStructure<FT, D>&, bool,                                                      \
      const std::function<void(std::size_t, std::size_t)>&);                                       \
  template BoundaryPatchPartition<FT, D> boundary_patch_partition<FT, D>(                          \
      const TemplatedStructure<FT, D>&, const BppOptions&);                                        \
  template struct BoundaryPatchPartition<FT, D>;                                                   \
  template struct BoundarySubdivision<FT, D>;                                                      \
  template std::vector<RestrictedComposition<FT, D>> enumerate_compositions<FT, D>(                \
      const BoundaryPatchPartition<FT, D>&, std::size_t);                                          \
  template bool regular_by_enumeration<FT, D>(const BoundaryPatchPartition<FT, D>&,                \
                                              const std::vector<RestrictedComposition<FT, D>>&);   \
  template VertexMovement<FT, D> valid_vertex_movement<FT, D>(                                     \
      const BoundaryPatchPartition<FT, D>&, std::size_t, const Point<FT, D>&);

} // namespace symmesh::core
