/// Section 5.2.3: flips inside mesh templates — spec/adaptation.md#flips
///
/// A flip replaces the cells around an interior face of a template by another triangulation of
/// their union: 2-2 across an edge in 2D, 2-3 across a triangle, 3-2 and 4-4 around an edge in 3D.
/// Inside a template no boundary facet changes, so the template boundaries — and with them every
/// instance interface (Lemma 4.2) — stay as they were, and AT(Γ) changes by the same flip at
/// every instance of the template. A face on the template boundary has cells of another
/// instance on its other side (or none); flipping it would need cells of two instances
/// (Figure 5.13), so such flips are refused. Every test is exact (orientation signs).
#pragma once
#include "symmesh/adapt/template_cells.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace symmesh::adapt {

/// What a flip did: the cells it removed and added (template vertex ids), or why it refused.
struct FlipResult {
  std::vector<Simplex> removed, added;
  std::string refused; ///< empty: the flip was made
  explicit operator bool() const { return refused.empty(); }
};

namespace detail {
template <class FT, int D>
std::vector<Point<FT, D>> points_of(const ElementComplex<FT, D>& m,
                                    const std::vector<VertexId>& ids) {
  std::vector<Point<FT, D>> p;
  for (VertexId v : ids) p.push_back(m.points[v]);
  return p;
}

template <class FT, int D>
FlipResult refuse(const std::string& why) {
  FlipResult r;
  r.refused = why;
  return r;
}
} // namespace detail

/// The 2-2 flip of interior edge e = (u, w) of a triangle template: the triangles (u, w, a) and
/// (u, w, b) become (a, b, u) and (a, b, w).
/// Refused (FlipResult::refused says why): e is no edge of the template, e is on the template
/// boundary, or the quadrilateral u a w b is not strictly convex (the new diagonal would leave it
/// or make a flat triangle). \pre D == 2
template <class FT>
FlipResult flip_2_2(TemplatedStructure<FT, 2>& x, std::size_t i, const Simplex& e) {
  const auto& m = x.templates.at(i).mesh;
  if (e.dim() != 1 || !m.contains(e)) return detail::refuse<FT, 2>("not an edge of the template");
  const auto around = co_cells(m, e);
  if (around.size() != 2)
    return detail::refuse<FT, 2>("the edge is on the template boundary (Figure 5.13)");
  const VertexId u = e.v[0], w = e.v[1];
  const VertexId a = opposite_vertices(around[0], e)[0], b = opposite_vertices(around[1], e)[0];
  const int su = orientation<FT, 2>(detail::points_of(m, {a, b, u}));
  const int sw = orientation<FT, 2>(detail::points_of(m, {a, b, w}));
  if (su == 0 || sw == 0 || su == sw)
    return detail::refuse<FT, 2>("the quadrilateral is not strictly convex");
  FlipResult r;
  r.removed = around;
  r.added = {simplex_of({a, b, u}), simplex_of({a, b, w})};
  replace_cells(x, i, r.removed, r.added);
  return r;
}

namespace detail {
/// The line through a and b crosses the open triangle uvw (all three tetrahedra (u,v,a,b),
/// (v,w,a,b), (w,u,a,b) have one non-zero orientation); with a and b on either side of the
/// triangle's plane, the segment does.
template <class FT>
bool segment_crosses_triangle(const ElementComplex<FT, 3>& m, VertexId a, VertexId b, VertexId u,
                              VertexId v, VertexId w) {
  const int s1 = orientation<FT, 3>(points_of(m, {u, v, a, b}));
  const int s2 = orientation<FT, 3>(points_of(m, {v, w, a, b}));
  const int s3 = orientation<FT, 3>(points_of(m, {w, u, a, b}));
  return s1 != 0 && s1 == s2 && s2 == s3;
}
} // namespace detail

/// The 2-3 flip of interior triangle f = (u, v, w) of a tetrahedral template: the tetrahedra
/// (f, a) and (f, b) become (u, v, a, b), (v, w, a, b), (w, u, a, b).
/// Refused: f is no triangle of the template, f is on the template boundary, or segment ab does
/// not cross f's interior (the union of the two tetrahedra is not convex there; a and b are on
/// either side of f, so the line test decides it).
template <class FT>
FlipResult flip_2_3(TemplatedStructure<FT, 3>& x, std::size_t i, const Simplex& f) {
  const auto& m = x.templates.at(i).mesh;
  if (f.dim() != 2 || !m.contains(f))
    return detail::refuse<FT, 3>("not a triangle of the template");
  const auto around = co_cells(m, f);
  if (around.size() != 2)
    return detail::refuse<FT, 3>("the triangle is on the template boundary (Figure 5.13)");
  const VertexId u = f.v[0], v = f.v[1], w = f.v[2];
  const VertexId a = opposite_vertices(around[0], f)[0], b = opposite_vertices(around[1], f)[0];
  if (!detail::segment_crosses_triangle(m, a, b, u, v, w))
    return detail::refuse<FT, 3>("the segment between the apices does not cross the triangle");
  FlipResult r;
  r.removed = around;
  r.added = {simplex_of({u, v, a, b}), simplex_of({v, w, a, b}), simplex_of({w, u, a, b})};
  replace_cells(x, i, r.removed, r.added);
  return r;
}

/// The 3-2 flip of interior edge e = (a, b) of a tetrahedral template with exactly three
/// tetrahedra around it, (a, b, u, v), (a, b, v, w), (a, b, w, u): they become (u, v, w, a) and
/// (u, v, w, b).
/// Refused: e is no edge, e lies on the template boundary, e has not exactly three tetrahedra
/// around it, or e does not cross the triangle u v w.
template <class FT>
FlipResult flip_3_2(TemplatedStructure<FT, 3>& x, std::size_t i, const Simplex& e) {
  const auto& m = x.templates.at(i).mesh;
  if (e.dim() != 1 || !m.contains(e)) return detail::refuse<FT, 3>("not an edge of the template");
  if (on_boundary(m, e))
    return detail::refuse<FT, 3>("the edge is on the template boundary (Figure 5.13)");
  const auto around = co_cells(m, e);
  if (around.size() != 3)
    return detail::refuse<FT, 3>("the edge has " + std::to_string(around.size()) +
                                 " tetrahedra around it, not 3");
  std::set<VertexId> ring;
  for (const auto& c : around)
    for (VertexId q : opposite_vertices(c, e)) ring.insert(q);
  if (ring.size() != 3) return detail::refuse<FT, 3>("the edge's link is not a triangle");
  const std::vector<VertexId> uvw(ring.begin(), ring.end());
  // The line through the edge must cross the open triangle, and the edge's ends must lie on
  // either side of it (an edge from a corner to an inner point has its line through the
  // opposite face but both ends on one side: the 3-2 flip would duplicate a cell).
  const int sa = orientation<FT, 3>(detail::points_of(m, {uvw[0], uvw[1], uvw[2], e.v[0]}));
  const int sb = orientation<FT, 3>(detail::points_of(m, {uvw[0], uvw[1], uvw[2], e.v[1]}));
  if (sa == 0 || sa == sb ||
      !detail::segment_crosses_triangle(m, e.v[0], e.v[1], uvw[0], uvw[1], uvw[2]))
    return detail::refuse<FT, 3>("the edge does not cross the triangle of its link");
  FlipResult r;
  r.removed = around;
  r.added = {simplex_of({uvw[0], uvw[1], uvw[2], e.v[0]}),
             simplex_of({uvw[0], uvw[1], uvw[2], e.v[1]})};
  replace_cells(x, i, r.removed, r.added);
  return r;
}

/// The 4-4 flip of interior edge e = (a, b) of a tetrahedral template with exactly four
/// tetrahedra around it, whose far edges close the ring c0 c1 c2 c3: the octahedron they fill
/// is cut along the ring's diagonal c_k c_{k+2} instead (`diagonal` k = 0 or 1), into
/// (a, c_k, c_{k+1}, c_{k+2}), (a, c_k, c_{k+2}, c_{k+3}), (b, ...) likewise.
/// With the four old cells oriented alike around e (sign s of (a, b, c_j, c_{j+1})), the chain
/// of the new cells (a, c_k, c_{k+1}, c_{k+2}) + (a, c_k, c_{k+2}, c_{k+3}) + (b, c_k, c_{k+2},
/// c_{k+1}) + (b, c_k, c_{k+3}, c_{k+2}) has the same boundary; when each of them has sign s
/// too, they fill the same octahedron once, so the flip is made exactly then.
/// Refused: e is no edge, e lies on the template boundary, e has not exactly four tetrahedra
/// around it, their far edges do not close a ring, or a new cell would be flat or inverted.
template <class FT>
FlipResult flip_4_4(TemplatedStructure<FT, 3>& x, std::size_t i, const Simplex& e, int diagonal) {
  const auto& m = x.templates.at(i).mesh;
  if (e.dim() != 1 || !m.contains(e)) return detail::refuse<FT, 3>("not an edge of the template");
  if (on_boundary(m, e))
    return detail::refuse<FT, 3>("the edge is on the template boundary (Figure 5.13)");
  const auto around = co_cells(m, e);
  if (around.size() != 4)
    return detail::refuse<FT, 3>("the edge has " + std::to_string(around.size()) +
                                 " tetrahedra around it, not 4");
  std::map<VertexId, std::vector<VertexId>> next;
  for (const auto& c : around) {
    const auto far = opposite_vertices(c, e);
    next[far[0]].push_back(far[1]);
    next[far[1]].push_back(far[0]);
  }
  if (next.size() != 4) return detail::refuse<FT, 3>("the edge's link is not a ring of four");
  for (const auto& link : next)
    if (link.second.size() != 2) return detail::refuse<FT, 3>("the edge's link is not a ring");
  std::vector<VertexId> ring{next.begin()->first, next.begin()->second[0]};
  while (ring.size() < 4) {
    const auto& n = next[ring.back()];
    ring.push_back(n[0] != ring[ring.size() - 2] ? n[0] : n[1]);
  }
  const VertexId a = e.v[0], b = e.v[1];
  const auto sign = [&](std::vector<VertexId> ids) {
    return orientation<FT, 3>(detail::points_of(m, ids));
  };
  const int s = sign({a, b, ring[0], ring[1]});
  for (std::size_t j = 1; j < 4; ++j)
    if (sign({a, b, ring[j], ring[(j + 1) % 4]}) != s)
      return detail::refuse<FT, 3>("the tetrahedra around the edge are not oriented alike");
  const auto c = [&](int j) { return ring[std::size_t((diagonal + j) % 4)]; };
  const std::vector<std::vector<VertexId>> fresh{
      {a, c(0), c(1), c(2)}, {a, c(0), c(2), c(3)}, {b, c(0), c(2), c(1)}, {b, c(0), c(3), c(2)}};
  for (const auto& ids : fresh)
    if (sign(ids) != s)
      return detail::refuse<FT, 3>("the diagonal leaves the octahedron (a new cell is flat or "
                                   "inverted)");
  FlipResult r;
  r.removed = around;
  for (const auto& ids : fresh) r.added.push_back(simplex_of(ids));
  replace_cells(x, i, r.removed, r.added);
  return r;
}

} // namespace symmesh::adapt
