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
/// are capped and the cap ends in an error naming it, never in a hang. Protection balls are not
/// implemented. Planar only: 3D templates would need 2-3/3-2 flip sequences that can get stuck
/// (spec/adaptation.md#not-yet).
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

struct MakeDelaunayReport {
  std::size_t rounds = 0, flips = 0, inserted = 0;
};

/// Technique 5.8 in the plane. Throws std::runtime_error when `max_rounds` rounds of boundary
/// insertions leave a facet that is not template-aware locally Delaunay.
/// \pre x is a templated mesh (Definition 4.4) of triangle templates
template <class FT>
MakeDelaunayReport make_delaunay(TemplatedStructure<FT, 2>& x, std::size_t max_rounds = 64) {
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
          const auto& a = m.points[f.v[0]];
          const auto& b = m.points[f.v[1]];
          Point<FT, 2> c;
          for (int d = 0; d < 2; ++d) c[d] = (a[d] + b[d]) / FT(2);
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
