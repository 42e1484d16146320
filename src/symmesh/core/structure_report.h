/// What `symmesh check` decides about a templated structure — spec/definitions.md#check-verdicts
///
/// Classification along Definitions 4.3 and 4.4: well-formed input, templated structure (Eq. 4.2),
/// templated mesh (AT conforming, decided directly) or templated geometry, the Lemma 4.2
/// checker's verdict (which must agree with the direct decision), and the instance graph.
#pragma once
#include "symmesh/core/instance_graph.h"
#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/kernel.h"

#include <optional>
#include <string>
#include <vector>

namespace symmesh::core {

using symmesh::Exact;

struct GraphEdgeSummary {
  std::size_t template_a, template_b;
  InterfaceEdge edge;
};

struct StructureReport {
  int dimension = 0;
  std::size_t templates = 0, instances = 0;
  bool mesh_templates = true;
  bool well_formed = false;
  std::string error; ///< why it is not well-formed or not a templated structure
  bool templated_structure = false;
  std::optional<OverlapWitness> overlap;
  bool at_conforming = false;
  bool templated_mesh = false;
  bool templated_geometry = false;
  Lemma42Verdict lemma42;
  bool lemma42_agrees = true;
  std::vector<std::string> template_names;
  std::vector<GraphEdgeSummary> graph_edges;
  std::size_t structure_instance_vertices = 0, structure_instance_cells = 0;
};

template <class FT, int D>
StructureReport analyse(const TemplatedStructure<FT, D>& x) {
  StructureReport r;
  r.dimension = D;
  r.templates = x.templates.size();
  for (const auto& t : x.templates) r.template_names.push_back(t.name);
  r.instances = x.instance_ids().size();
  r.mesh_templates = x.all_of_kind(TemplateKind::mesh);
  std::ostringstream why;
  r.well_formed = x.is_well_formed(&why);
  if (!r.well_formed) {
    r.error = why.str();
    return r;
  }
  r.overlap = find_instance_overlap(x);
  r.templated_structure = !r.overlap.has_value();
  if (!r.templated_structure) {
    r.error = "instances " + to_string(r.overlap->a) + " and " + to_string(r.overlap->b) +
              " overlap: their interiors intersect (Eq. 4.2)";
    return r;
  }
  const auto si = apply_template(x);
  r.structure_instance_vertices = si.at.mesh.points.size();
  r.structure_instance_cells = si.at.cell_region.size();
  const auto g = instance_graph(x, si);
  for (auto [e, end] = boost::edges(g); e != end; ++e)
    r.graph_edges.push_back({boost::source(*e, g), boost::target(*e, g), g[*e]});
  if (r.mesh_templates) {
    r.at_conforming = structure_instance_conforming(si);
    r.lemma42 = check_interface_conformity(x, si);
    r.lemma42_agrees = r.lemma42.holds == r.at_conforming;
    r.templated_mesh = r.at_conforming;
  } else {
    r.templated_geometry = true; // Definition 4.4: AT of geometry templates is a geometry
    r.at_conforming = true;
  }
  return r;
}

// Instantiated once, in instantiate.cpp, for the default exact kernel.
extern template StructureReport analyse<Exact, 2>(const TemplatedStructure<Exact, 2>&);
extern template StructureReport analyse<Exact, 3>(const TemplatedStructure<Exact, 3>&);

} // namespace symmesh::core
