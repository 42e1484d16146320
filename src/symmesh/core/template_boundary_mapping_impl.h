// Definition 4.7 (template boundary mappings) with their exact domains, and the exact small
// geometry they need — spec/boundary-patches.md#def-4-7
//
// Part 1 of the definitions behind boundary_patch_partition.h (then boundary_subdivision_impl.h,
// then boundary_patch_partition_impl.h). CGAL is used here only: exact segment/triangle
// intersections for the mapping domains and, in 3D, constrained triangulations of each boundary
// triangle with its cuts. The public headers stay free of CGAL.
//
// Definitions only, included by the translation units that instantiate them for one number
// type each (boundary_patch_partition.cpp: rationals; cyclotomic_instantiations.cpp: K_m).
#pragma once
#include "symmesh/core/boundary_patch_partition.h"

#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/kernel.h"

#include <CGAL/Constrained_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_vertex_base_2.h>
#include <CGAL/intersections.h>
#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <array>
#include <deque>
#include <initializer_list>
#include <map>
#include <numeric>
#include <optional>
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
  const auto n = cross<FT>(p[1] - p[0], p[2] - p[0]);
  Point<FT, 3> nn = n;
  // p[0..2] might be collinear; find any non-degenerate normal.
  for (std::size_t k = 3; k < p.size() && nn[0] == 0 && nn[1] == 0 && nn[2] == 0; ++k)
    nn = cross<FT>(p[1] - p[0], p[k] - p[0]);
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

/// Where each corner of triangle a lies among b's corners (its index there, or −1), by exact
/// point equality: found once per facet pair for the shortcuts below.
struct SharedCorners {
  std::array<int, 3> in_b{-1, -1, -1};
  int count = 0;
};

// Certified interval filters for the triangle pairs of neighbouring copies. Their boxes overlap
// far beyond the interface, and most pairs are apart or meet only in a corner while lying in a
// common plane (top and bottom faces of adjacent slices) or with a far corner in the other's
// plane: there the exact tests start with an orientation that is exactly zero, which no filter
// decides, so it was evaluated over K_m (a millisecond per pair at K_128). A filter decides only
// what its enclosures prove and otherwise leaves the pair to the exact tests, so the pieces
// found are those of the exact tests alone. The enclosures are element_complex.h's
// (`detail::Enclosure`, `enclosures`), with Point's arithmetic.
using detail::Enclosure;
using detail::enclosures;
using EnclosedPoint = Point<Enclosure, 3>;

/// The sign of m · (q − o) when the enclosures prove it, else 0.
inline int certain_side(const EnclosedPoint& m, const EnclosedPoint& o, const EnclosedPoint& q) {
  const Enclosure s = dot<Enclosure, 3>(m, q - o);
  return s.inf() > 0 ? 1 : (s.sup() < 0 ? -1 : 0);
}

/// Whether the points `far` lie certainly strictly on one side of the plane through o with normal
/// m and the points `near` certainly strictly on the other.
inline bool certainly_splits(const EnclosedPoint& m, const EnclosedPoint& o,
                             std::initializer_list<const EnclosedPoint*> near,
                             std::initializer_list<const EnclosedPoint*> far) {
  int side = 0;
  for (const auto* q : far) {
    const int s = certain_side(m, o, *q);
    if (s == 0 || (side != 0 && s != side)) return false;
    side = s;
  }
  for (const auto* q : near)
    if (certain_side(m, o, *q) != -side) return false;
  return true;
}

/// Whether the enclosures prove two triangles disjoint: some plane has one triangle on its closed
/// side and every corner of the other strictly beyond it — the plane of either triangle, or the
/// plane through an edge of one that is orthogonal to its triangle (for coplanar triangles, a
/// separating line of their plane). A segment or a point may be given as a degenerate triangle
/// (a repeated corner): its own planes then prove nothing, the other's still do.
template <class FT>
bool certainly_apart(const PointVec<FT, 3>& a, const PointVec<FT, 3>& b) {
  const auto one_way = [](const std::vector<EnclosedPoint>& t,
                          const std::vector<EnclosedPoint>& u) {
    const EnclosedPoint n = cross<Enclosure>(t[1] - t[0], t[2] - t[0]);
    if (certainly_splits(n, t[0], {}, {&u[0], &u[1], &u[2]})) return true;
    for (std::size_t i = 0; i < 3; ++i) {
      const EnclosedPoint m = cross<Enclosure>(t[(i + 1) % 3] - t[i], n);
      if (certainly_splits(m, t[i], {&t[(i + 2) % 3]}, {&u[0], &u[1], &u[2]})) return true;
    }
    return false;
  };
  const auto ea = enclosures<FT, 3>(a), eb = enclosures<FT, 3>(b);
  return one_way(ea, eb) || one_way(eb, ea);
}

/// Whether the enclosures prove that two triangles with the common corner v = a[ia] = b[ib] meet
/// only in v: some plane through v has the other corners of one strictly on one side and those
/// of the other on the opposite closed side (in the plane of a triangle, or strictly across).
/// Candidates: the triangles' planes, the planes through an edge at v orthogonal to its
/// triangle, and the planes spanned by an edge at v of each triangle (those two edges in it meet
/// only in v, being not parallel; the other two corners strictly on opposite sides).
template <class FT>
bool certainly_meet_only_at(const PointVec<FT, 3>& a, const PointVec<FT, 3>& b, int ia, int ib) {
  const auto ea = enclosures<FT, 3>(a), eb = enclosures<FT, 3>(b);
  const EnclosedPoint& v = ea[std::size_t(ia)];
  const EnclosedPoint* a_far[2] = {&ea[std::size_t((ia + 1) % 3)], &ea[std::size_t((ia + 2) % 3)]};
  const EnclosedPoint* b_far[2] = {&eb[std::size_t((ib + 1) % 3)], &eb[std::size_t((ib + 2) % 3)]};
  const EnclosedPoint na = cross<Enclosure>(*a_far[0] - v, *a_far[1] - v);
  const EnclosedPoint nb = cross<Enclosure>(*b_far[0] - v, *b_far[1] - v);
  if (certainly_splits(na, v, {}, {b_far[0], b_far[1]}) ||
      certainly_splits(nb, v, {}, {a_far[0], a_far[1]}))
    return true;
  for (int k = 0; k < 2; ++k) {
    if (certainly_splits(cross<Enclosure>(*a_far[k] - v, na), v, {a_far[1 - k]},
                         {b_far[0], b_far[1]}) ||
        certainly_splits(cross<Enclosure>(*b_far[k] - v, nb), v, {b_far[1 - k]},
                         {a_far[0], a_far[1]}))
      return true;
    for (int l = 0; l < 2; ++l)
      if (certainly_splits(cross<Enclosure>(*a_far[k] - v, *b_far[l] - v), v, {a_far[1 - k]},
                           {b_far[1 - l]}))
        return true;
  }
  return false;
}

template <class FT>
SharedCorners shared_corners(const PointVec<FT, 3>& a, const PointVec<FT, 3>& b) {
  SharedCorners out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3 && out.in_b[std::size_t(i)] < 0; ++j)
      if (a[std::size_t(i)] == b[std::size_t(j)]) out.in_b[std::size_t(i)] = j, ++out.count;
  return out;
}

/// Two triangles that share exactly one edge meet in that edge when they are not coplanar, or
/// when they are and lie on opposite sides of it: decided by predicates and exact point
/// equality, without constructions. Neighbouring copies' boundary triangles meet like this
/// along their interfaces. nullopt when the triangles are otherwise placed (CGAL decides).
template <class FT>
std::optional<PointVec<FT, 3>> shared_edge_meet(const PointVec<FT, 3>& a, const PointVec<FT, 3>& b,
                                                const SharedCorners& shared) {
  using K = KernelOf<FT>;
  using P = typename K::Point_3;
  if (shared.count != 2) return std::nullopt;
  const auto& in_b = shared.in_b;
  const int a_apex = in_b[0] < 0 ? 0 : in_b[1] < 0 ? 1 : 2;
  const int b_apex = 3 - in_b[std::size_t((a_apex + 1) % 3)] - in_b[std::size_t((a_apex + 2) % 3)];
  const auto cg = [](const Point<FT, 3>& p) { return P(p[0], p[1], p[2]); };
  const P e0 = cg(a[std::size_t((a_apex + 1) % 3)]), e1 = cg(a[std::size_t((a_apex + 2) % 3)]);
  const P pa = cg(a[std::size_t(a_apex)]), pb = cg(b[std::size_t(b_apex)]);
  if (CGAL::collinear(e0, e1, pa) || CGAL::collinear(e0, e1, pb)) return std::nullopt;
  if (CGAL::orientation(e0, e1, pa, pb) == CGAL::COPLANAR &&
      CGAL::coplanar_orientation(e0, e1, pa, pb) != CGAL::NEGATIVE)
    return std::nullopt;
  return PointVec<FT, 3>{a[std::size_t((a_apex + 1) % 3)], a[std::size_t((a_apex + 2) % 3)]};
}

/// Two triangles that share exactly one vertex v meet only in v when (not coplanar) the far
/// vertices of one lie strictly on one side of the other's plane, or (coplanar) the line of an
/// edge at v has one triangle on its side and the other's far vertices strictly across it or on
/// the line's opposite ray (two convex wedges at v that meet only in v are separated so; their
/// triangles lie in them). Decided by predicates, without constructions: boundary triangles of
/// neighbouring copies around a shared vertex meet like this. nullopt when not decided (CGAL
/// decides).
template <class FT>
std::optional<Point<FT, 3>> shared_vertex_meet(const PointVec<FT, 3>& a, const PointVec<FT, 3>& b,
                                               const SharedCorners& shared) {
  using K = KernelOf<FT>;
  using P = typename K::Point_3;
  if (shared.count != 1) return std::nullopt;
  const int ia = shared.in_b[0] >= 0 ? 0 : shared.in_b[1] >= 0 ? 1 : 2;
  const int ib = shared.in_b[std::size_t(ia)];
  if (certainly_meet_only_at<FT>(a, b, ia, ib)) return a[std::size_t(ia)];
  const auto cg = [](const Point<FT, 3>& p) { return P(p[0], p[1], p[2]); };
  const P v = cg(a[std::size_t(ia)]);
  const P a1 = cg(a[std::size_t((ia + 1) % 3)]), a2 = cg(a[std::size_t((ia + 2) % 3)]);
  const P b1 = cg(b[std::size_t((ib + 1) % 3)]), b2 = cg(b[std::size_t((ib + 2) % 3)]);
  if (CGAL::collinear(v, a1, a2) || CGAL::collinear(v, b1, b2)) return std::nullopt;
  // Not coplanar: when one triangle's far vertices lie strictly on one side of the other's
  // plane, it meets that plane, and so the other triangle, only in v.
  const auto sb1 = CGAL::orientation(v, a1, a2, b1), sb2 = CGAL::orientation(v, a1, a2, b2);
  if (sb1 != CGAL::COPLANAR || sb2 != CGAL::COPLANAR) {
    if (sb1 == sb2) return a[std::size_t(ia)];
    const auto sa1 = CGAL::orientation(v, b1, b2, a1), sa2 = CGAL::orientation(v, b1, b2, a2);
    if (sa1 != CGAL::COPLANAR && sa1 == sa2) return a[std::size_t(ia)];
    return std::nullopt;
  }
  // The line through v and e, with the wedge's other end `own` on its positive side.
  const auto separates = [&](const P& e, const P& own, const P& y1, const P& y2) {
    for (const P* y : {&y1, &y2}) {
      const auto side = CGAL::coplanar_orientation(v, e, own, *y);
      if (side == CGAL::POSITIVE) return false;
      if (side == CGAL::COLLINEAR && CGAL::angle(e, v, *y) != CGAL::OBTUSE) return false;
    }
    return true;
  };
  if (separates(a1, a2, b1, b2) || separates(a2, a1, b1, b2) || separates(b1, b2, a1, a2) ||
      separates(b2, b1, a1, a2))
    return a[std::size_t(ia)];
  return std::nullopt;
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
    if (certainly_apart<FT>(a, b)) return;
    const auto shared = shared_corners<FT>(a, b);
    if (const auto edge = shared_edge_meet<FT>(a, b, shared)) {
      out.push_back({*edge});
      return;
    }
    // The same triangle on both sides (neighbouring copies meet like this across their shared
    // faces): it is the intersection, without CGAL's degenerate coplanar case analysis.
    if (shared.count == 3) {
      out.push_back({convex_cyclic_order<FT>(a)});
      return;
    }
    if (const auto vertex = shared_vertex_meet<FT>(a, b, shared)) {
      out.push_back({{*vertex}});
      return;
    }
    const typename K::Triangle_3 ta(cg(a[0]), cg(a[1]), cg(a[2]));
    const typename K::Triangle_3 tb(cg(b[0]), cg(b[1]), cg(b[2]));
    // Predicates first: CGAL's intersection constructs edge crossings (divisions, costly over
    // K_m) before it knows that there are none.
    if (!CGAL::do_intersect(ta, tb)) return;
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

/// The pieces in the coordinates of the instance whose facets are `seen` where the pieces were
/// found (`local` moved there, facet for facet): a piece vertex that is a facet end of that
/// instance becomes the template's own point (no arithmetic, and later comparisons with it are by
/// identity), any other is mapped by `back` (none: the pieces were found in `local` itself).
template <class FT, int D>
std::vector<DomainPiece<FT, D>>
pull_back(const std::vector<DomainPiece<FT, D>>& pieces, const std::vector<PointVec<FT, D>>& seen,
          const std::vector<PointVec<FT, D>>& local, const RigidTransformation<FT, D>* back) {
  auto out = pieces;
  for (auto& p : out)
    for (auto& v : p.vertices) {
      const Point<FT, D>* same = nullptr;
      for (std::size_t k = 0; k < seen.size() && !same; ++k)
        for (std::size_t j = 0; j < seen[k].size() && !same; ++j)
          if (seen[k][j] == v) same = &local[k][j];
      if (same)
        v = *same;
      else if (back)
        v = (*back)(v);
    }
  return out;
}

template <class FT, int D>
std::vector<EnclosingBox<FT, D>> facet_enclosures(const std::vector<PointVec<FT, D>>& facets) {
  std::vector<EnclosingBox<FT, D>> out;
  for (const auto& s : facets) out.push_back(enclosure<FT, D>(s));
  return out;
}

} // namespace

template <class FT, int D>
std::vector<TemplateBoundaryMapping<FT, D>>
template_boundary_mappings(const TemplatedStructure<FT, D>& x, bool check_well_formed,
                           const std::function<void(std::size_t, std::size_t)>& on_progress,
                           const std::function<bool(InstanceId, InstanceId)>& wanted) {
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
  std::vector<std::vector<PointVec<FT, D>>> template_facets;
  // Boxes are certified enclosures (intervals): filters that never decide a shared coordinate
  // exactly; the segment intersections decide.
  std::vector<EnclosingBox<FT, D>> instance_box;
  std::vector<std::vector<EnclosingBox<FT, D>>> template_boxes;
  for (const auto& t : x.templates) {
    template_facets.push_back(boundary_facets(t.mesh));
    template_boxes.push_back(facet_enclosures<FT, D>(template_facets.back()));
  }
  for (auto id : ids) {
    PointVec<FT, D> ends;
    for (const auto& s : template_facets[id.i])
      for (const auto& p : s) ends.push_back(x.tf(id)(p));
    instance_box.push_back(enclosure<FT, D>(ends));
  }
  // interf_geo = bnd ∩ bnd for non-overlapping instances, so two instances are neighbours iff
  // some two boundary facets meet; this avoids the cell-pair tests of neighbouring_instances.
  std::vector<std::pair<std::size_t, std::size_t>> candidates;
  for_each_overlapping_box_pair(instance_box, [&](std::size_t a, std::size_t b) {
    if (!wanted || wanted(ids[a], ids[b])) candidates.emplace_back(a, b);
    return true;
  });
  std::sort(candidates.begin(), candidates.end());
  std::size_t decided = 0;
  for (const auto& [a, b] : candidates) {
    if (on_progress) on_progress(decided++, candidates.size());
    const auto ia = ids[a], ib = ids[b];
    TemplateBoundaryMapping<FT, D> ab, ba;
    ab.to = ia;
    ab.from = ib;
    ab.map = x.tf(ia).inverse() * x.tf(ib);
    ba.to = ib;
    ba.from = ia;
    ba.map = ab.map.inverse(); // = T_b^{-1} ∘ T_a exactly; a transpose, not a product
    // interf_geo is found in b's own coordinates, with a's facets moved there by T_b^{-1} ∘ T_a:
    // where neighbouring copies meet on a face of b's template, that face keeps its exact
    // template coordinates (rational on a slice's starting half-plane, where world coordinates
    // are the rotation's cyclotomic images), and the predicates there, degenerate and so decided
    // exactly, are cheap. The pieces are the same points as in world coordinates.
    auto a_in_b = template_facets[ia.i];
    for (auto& f : a_in_b)
      for (auto& p : f) p = ba.map(p);
    const auto pieces = geometry_interface_pieces<FT, D>(
        a_in_b, facet_enclosures<FT, D>(a_in_b), template_facets[ib.i], template_boxes[ib.i]);
    if (pieces.empty()) continue;
    ab.domain = pull_back<FT, D>(pieces, template_facets[ib.i], template_facets[ib.i], nullptr);
    ba.domain = pull_back<FT, D>(pieces, a_in_b, template_facets[ia.i], &ab.map);
    ab.inverse = out.size() + 1;
    ba.inverse = out.size();
    out.push_back(std::move(ab));
    out.push_back(std::move(ba));
  }
  return out;
}

} // namespace symmesh::core
