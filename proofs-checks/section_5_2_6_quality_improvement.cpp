// Section 5.2.6 (quality improvement) — spec/adaptation.md#properties
//
// Claim (on generated templated meshes of boxes, 2D and 3D: grids translated or mirrored and a
// block on a base slab, half of them first refined where x < c so that they hold poor cells):
// the combined pass of smoothing and flips with the section's restrictions (adapt::improve_quality:
// template-boundary vertices move only inside their patch and together with every related
// vertex, template boundary facets are never flipped, a move or flip is made only when it raises
// the smallest quality around it) maps a templated mesh to a templated mesh — valid, certified
// by the conformity certificate with the same boundary measure, every identified pair one
// point — and AT after is AT before with the same vertices (none inserted or deleted), the same
// template boundary facets, the same area or volume (exact), and a smallest angle (2D) or
// dihedral angle (3D) that is not lower.
// Dropped restriction (a template-boundary vertex moves together with its related vertices):
// moving one identified vertex in its own template only puts the two copies of a point of AT
// apart, and the certificate fails.
#include "proofs-checks/box_inputs.h"
#include "proofs-checks/registry.h"
#include "symmesh/mesh/structure_instance.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace symmesh::proofs {
namespace {

constexpr const char* kClaim = "Section_5_2_6";

using boxes::BoxInput;
using Facets = std::vector<std::set<std::vector<mesh::IndexType>>>;

/// The template boundary facets of every template (sorted vertex numbers): facets of exactly one
/// cell of their template.
Facets boundary_facets(const mesh::TemplatedMeshCompactSvb& t) {
  Facets out;
  for (const auto& mt : t.templated.templates)
    out.push_back(boxes::one_cell_facets(mt.mesh, t.templated.point_dimension));
  return out;
}

/// A generated box mesh, refined where x < c in half of the cases (c from the bytes).
struct Case {
  BoxInput input;
  int refine_below = 0; ///< 0: no refinement; else refine where x < refine_below / 4
};

rc::Gen<Case> cases(int dimension) {
  return rc::gen::apply(
      [](BoxInput in, int refine) {
        return Case{std::move(in), refine};
      },
      rc::gen::oneOf(boxes::box_grid(dimension), boxes::block_on_base(dimension)),
      rc::gen::inRange(0, 9));
}

void quality_pass_keeps_the_templated_mesh(const Case& k, bool with_related) {
  const std::string text =
      k.input.description() + "\n(refined where x < " + std::to_string(k.refine_below) + "/4)";
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  auto t = k.input.generate();
  if (k.refine_below > 0)
    adapt::refine_where(t,
                        adapt::parse_cell_predicate("x < " + std::to_string(k.refine_below / 4.0)));
  const double boundary = adapt::certify_conformity(t).boundary_measure;
  const double q0 = adapt::smallest_quality(t);
  const std::size_t v0 = mesh::StructureInstance(t).vertex_count();
  const auto facets0 = boundary_facets(t);

  const auto report = adapt::improve_quality(t, 8);
  RC_TAG(report.moves + report.flips > 0 ? "changed" : "unchanged");
  RC_TAG(k.refine_below > 0 ? "refined first" : "as generated");
  if (!with_related) {
    // The dropped restriction: the first identified vertex moves a third of the way to the
    // centroid of one of its cells, in its own template only (no related vertex follows).
    RC_PRE(!t.tables.empty() && !t.tables[0].pairs.empty());
    const auto tmpl = std::size_t(t.tables[0].from_template);
    const auto v = t.tables[0].pairs[0].first;
    auto& m = t.templated.templates[tmpl].mesh;
    const int d = t.templated.point_dimension;
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
      const auto* cell = m.cell(c);
      if (std::find(cell, cell + d + 1, v) == cell + d + 1) continue;
      for (int i = 0; i < d; ++i) {
        double centroid = 0;
        for (int q = 0; q <= d; ++q) centroid += m.vertex(std::size_t(cell[q]))[i] / (d + 1);
        auto& x = m.vertex_coords[std::size_t(v) * std::size_t(d) + std::size_t(i)];
        x += (centroid - x) / 3;
      }
      break;
    }
  }
  SYMMESH_PROOF_ASSERT(t.is_valid(), failure, no_picture);
  const auto certificate = adapt::certify_conformity(t, boundary);
  SYMMESH_PROOF_ASSERT(
      certificate.holds, [&] { return text + "\n" + certificate.why; }, no_picture);
  SYMMESH_PROOF_ASSERT(mesh::StructureInstance(t).vertex_count() == v0, failure, no_picture);
  SYMMESH_PROOF_ASSERT(boundary_facets(t) == facets0, failure, no_picture);
  SYMMESH_PROOF_ASSERT(boxes::exact_measure(t) == k.input.measure(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::smallest_quality(t) >= q0, failure, no_picture);
}

} // namespace

void register_section_5_2_6(std::vector<Property>& p) {
  for (int d : {2, 3})
    p.push_back({kClaim, "quality_pass_keeps_the_templated_mesh_" + std::to_string(d) + "d", d,
                 Kind::holds,
                 "Section 5.2.6: the smoothing + flipping pass with the section's restrictions "
                 "maps a templated mesh to a templated mesh (certified) with the same AT "
                 "vertices, template boundary facets and measure (exact), and a smallest "
                 "quality that is not lower",
                 [d] {
                   return rc::detail::toProperty(
                       [d] { quality_pass_keeps_the_templated_mesh(*cases(d), true); });
                 },
                 [d] {
                   return rc::detail::toProperty(
                       [d] { quality_pass_keeps_the_templated_mesh(*cases(d), false); });
                 }});
}

} // namespace symmesh::proofs
