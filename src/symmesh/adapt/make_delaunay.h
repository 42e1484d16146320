/// Technique 5.8: make a templated mesh Delaunay (Section 5.2.5) — spec/adaptation.md#technique-5-8
///
/// Line 4: every template is made Delaunay by Lawson flips of its interior edges (a flip never
/// touches the template boundary, Section 5.2.3). Lines 6-18: while some template boundary facet
/// is not template-aware locally Delaunay (Definition 4.10, decided exactly on AT), its centroid
/// is inserted into it and, through the instances' transformations, into every related facet
/// (Section 5.2.4), and the templates are made Delaunay again. With every template Delaunay and
/// every template facet template-aware locally Delaunay, AT(Γ) is Delaunay when us(AT(Γ)) is
/// convex (Lemma 4.5 with the correction of spec/lemmas.md#lemma-4-5).
///
/// The section gives no termination guarantee: inputs with angles of 45° or less can make
/// midpoints encroach on each other for ever (ping-pong encroachment, Figure 5.17). The rounds
/// are capped and the cap ends in an error naming it, never in a hang. Protection balls (Line 9):
/// a facet with one end at an acute template corner gets its point not at the midpoint but on a
/// concentric shell around that corner (protected_split_point), so that the two legs of the
/// corner end with pieces of equal length that do not encroach on each other. Planar only: 3D
/// templates would need 2-3/3-2 flip sequences that can get stuck (spec/adaptation.md#not-yet).
#pragma once
#include "symmesh/adapt/flips.h"
#include "symmesh/adapt/vertex_insertion.h"
#include "symmesh/core/delaunay.h"
#include "symmesh/core/template_aware_delaunay.h"

#include <stdexcept>
#include <string>

namespace symmesh::adapt {

/// Lawson flips in template i until every interior edge is locally Delaunay in the template;
/// returns the number of flips. A non-locally-Delaunay interior edge always bounds a strictly
/// convex quadrilateral, so its flip is never refused; `cap` guards against a defect only.
template <class FT>
std::size_t make_template_delaunay(TemplatedStructure<FT, 2>& x, std::size_t i,
                                   std::size_t cap = 100000) {
  std::size_t flips = 0;
  for (bool changed = true; changed;) {
    changed = false;
    const auto edges = x.templates[i].mesh.elements_of_dimension(1);
    for (const auto& e : edges) {
      const auto& m = x.templates[i].mesh;
      if (!m.contains(e) || co_cells(m, e).size() != 2 || core::is_locally_delaunay_in(m, e))
        continue;
      const auto r = flip_2_2(x, i, e);
      if (!r) throw std::logic_error("Lawson flip refused: " + r.refused);
      changed = true;
      if (++flips > cap) throw std::runtime_error("Lawson flips exceeded their cap");
    }
  }
  return flips;
}

/// Whether template vertex v is an acute corner of its template: its two template boundary edges
/// (v, p), (v, q) span an angle below 90° (dot product > 0) and the template's cells at v lie in
/// that convex cone (so the template's angle at v is that one, not the reflex one). Exact.
template <class FT>
bool acute_corner(const ElementComplex<FT, 2>& m, VertexId v) {
  std::vector<VertexId> ends;
  for (const auto& f : boundary_facets(m))
    if (f.v[0] == v || f.v[1] == v) ends.push_back(f.v[0] == v ? f.v[1] : f.v[0]);
  if (ends.size() != 2) return false;
  const auto& o = m.points[v];
  const auto u = m.points[ends[0]] - o, w = m.points[ends[1]] - o;
  if (!(core::dot<FT, 2>(u, w) > FT(0))) return false;
  const auto cross = [](const Point<FT, 2>& a, const Point<FT, 2>& b) {
    return CGAL::sign(a[0] * b[1] - a[1] * b[0]);
  };
  const auto turn = cross(u, w);
  for (const auto& c : co_cells(m, simplex_of({v})))
    for (VertexId r : c) {
      if (r == v) continue;
      const auto d = m.points[r] - o;
      if (cross(u, d) == -turn || cross(d, w) == -turn) return false;
    }
  return true;
}

/// The point Technique 5.8 inserts into boundary facet (a, b) of template i: its midpoint, or —
/// when exactly one end is an acute corner — the point at distance about 2^k from that end, 2^k
/// the power of two in [L/(2√2), L/√2) for the length L (concentric shells; Ruppert's remedy for
/// small input angles). The parameter is the dyadic t = n/2^20 with t^2 <= 4^k/L^2 < (t + 2^-20)^2,
/// found by exact comparisons, so the point is exact and the pieces next to a corner have
/// power-of-two lengths up to a relative 2^-19 on every leg.
template <class FT>
Point<FT, 2> protected_split_point(const ElementComplex<FT, 2>& m, VertexId a, VertexId b) {
  const bool ca = acute_corner(m, a), cb = acute_corner(m, b);
  Point<FT, 2> from = m.points[a], to = m.points[b];
  if (ca == cb) {
    Point<FT, 2> c;
    for (int d = 0; d < 2; ++d) c[d] = (from[d] + to[d]) / FT(2);
    return c;
  }
  if (cb) std::swap(from, to);
  const auto edge = to - from;
  const FT ll = core::dot<FT, 2>(edge, edge);
  FT shell(1); // 4^k with ll/8 <= 4^k < ll/2
  while (!(shell < ll / FT(2))) shell /= FT(4);
  while (shell < ll / FT(8)) shell *= FT(4);
  const FT target = shell / ll; // t^2, in [1/8, 1/2)
  long lo = 0, hi = 1L << 20;   // t in [lo, hi) / 2^20
  while (hi - lo > 1) {
    const long mid = (lo + hi) / 2;
    const FT t = FT(mid) / FT(1L << 20);
    (t * t <= target ? lo : hi) = mid;
  }
  const FT t = FT(lo) / FT(1L << 20);
  Point<FT, 2> c;
  for (int d = 0; d < 2; ++d) c[d] = from[d] + t * edge[d];
  return c;
}

struct MakeDelaunayReport {
  std::size_t rounds = 0, flips = 0, inserted = 0;
};

/// Technique 5.8 in the plane, with protection balls unless `protection_balls` is false. Throws
/// std::runtime_error when `max_rounds` rounds of boundary insertions leave a facet that is not
/// template-aware locally Delaunay.
/// \pre x is a templated mesh (Definition 4.4) of triangle templates
template <class FT>
MakeDelaunayReport make_delaunay(TemplatedStructure<FT, 2>& x, std::size_t max_rounds = 64,
                                 bool protection_balls = true) {
  MakeDelaunayReport report;
  for (;; ++report.rounds) {
    for (std::size_t i = 0; i < x.templates.size(); ++i)
      report.flips += make_template_delaunay(x, i);
    const auto si = core::apply_template(x);
    std::vector<std::pair<std::size_t, Point<FT, 2>>> centroids;
    for (std::size_t i = 0; i < x.templates.size(); ++i) {
      const auto& m = x.templates[i].mesh;
      for (const auto& f : boundary_facets(m))
        if (!core::is_template_aware_locally_delaunay(si, i, f)) {
          Point<FT, 2> c;
          if (protection_balls) {
            c = protected_split_point(m, f.v[0], f.v[1]);
          } else {
            for (int d = 0; d < 2; ++d) c[d] = (m.points[f.v[0]][d] + m.points[f.v[1]][d]) / FT(2);
          }
          centroids.push_back({i, c});
        }
    }
    if (centroids.empty()) return report;
    if (report.rounds == max_rounds)
      throw std::runtime_error("Technique 5.8: " + std::to_string(centroids.size()) +
                               " boundary facets are still not template-aware locally Delaunay "
                               "after " +
                               std::to_string(max_rounds) +
                               " rounds (ping-pong encroachment, Figure 5.17)");
    for (const auto& [i, c] : centroids) {
      // An earlier insertion of this round may have put c in already (a related facet).
      const auto e = carrier_element(x.templates[i].mesh, c);
      if (e && e->dim() > 0) report.inserted += insert_boundary_vertex(x, i, c);
    }
  }
}

} // namespace symmesh::adapt
