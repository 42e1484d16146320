// Serialisation of the check report.
#include "symmesh/io/report_json.h"

#include "symmesh/io/bpp_output.h"
#include "symmesh/io/templated_structure_json.h"

#include <nlohmann/json.hpp>

#include <sstream>

namespace symmesh::io {

namespace {
const char* kKernel = "rational (CGAL Epeck, exact)";

std::string condition_name(int c) {
  return c == 1 ? "(i)" : c == 2 ? "(ii)" : "";
}

/// "regular", "irregularity", "patches_per_template" (and "bpp_error" when the guard stopped
/// Algorithm 4.1): null / empty when the partition was not computed.
void add_boundary_patches(nlohmann::ordered_json& j, const core::StructureReport& r) {
  j["regular"] = r.bpp_computed ? nlohmann::ordered_json(r.regular) : nlohmann::ordered_json();
  j["irregularity"] =
      r.irregularity ? irregularity_json(*r.irregularity) : nlohmann::ordered_json(nullptr);
  j["patches_per_template"] = nlohmann::ordered_json::array();
  for (std::size_t t = 0; t < r.patches_per_template.size(); ++t)
    j["patches_per_template"].push_back(
        {{"template", t + 1},
         {"name", r.template_names.at(t)},
         {"facet_patches", r.patches_per_template[t].facet_patches},
         {"lower_dimensional_patches", r.patches_per_template[t].lower_dimensional_patches}});
  if (!r.bpp_error.empty()) j["bpp_error"] = r.bpp_error;
}

/// A composition in the dissertation's notation, last applied leftmost; I when empty.
std::string composition_text(const std::vector<std::string>& letters) {
  if (letters.empty()) return "I";
  std::string out;
  for (auto it = letters.rbegin(); it != letters.rend(); ++it)
    out += (out.empty() ? "" : " ∘ ") + *it;
  return out;
}

/// x -> [[a, b], [c, d]] x + [e, f] with exact entries.
std::string symmetry_text(const core::IrregularitySummary& w) {
  std::string m = "[";
  for (std::size_t i = 0; i < w.symmetry_matrix.size(); ++i) {
    m += i ? ", [" : "[";
    for (std::size_t k = 0; k < w.symmetry_matrix[i].size(); ++k)
      m += (k ? ", " : "") + w.symmetry_matrix[i][k];
    m += "]";
  }
  m += "] x + [";
  for (std::size_t i = 0; i < w.symmetry_translation.size(); ++i)
    m += (i ? ", " : "") + w.symmetry_translation[i];
  return "x -> " + m + "]";
}

void boundary_patches_text(std::ostringstream& os, const core::StructureReport& r) {
  os << "  instance graph regularity (Def 4.9): ";
  if (!r.bpp_computed) {
    os << "not decided: " << r.bpp_error << " (check stops at " << core::kCheckMaxCompositions
       << "; use symmesh bpp --max-compositions N)\n";
    return;
  }
  os << (r.regular ? "regular" : "IRREGULAR") << "\n";
  if (const auto& w = r.irregularity) {
    os << "    F1 = " << composition_text(w->f1) << " and F2 = " << composition_text(w->f2)
       << " both map boundary patch P" << w->patch << " onto P" << w->target
       << " but differ on it\n";
    os << "    forced symmetry F1^-1 ∘ F2 of P" << w->patch << ": " << symmetry_text(*w) << "\n";
  }
  for (std::size_t t = 0; t < r.patches_per_template.size(); ++t)
    os << "  boundary patches of " << r.template_names.at(t) << " (template " << t + 1
       << ", Algorithm 4.1): " << r.patches_per_template[t].facet_patches << " facet, "
       << r.patches_per_template[t].lower_dimensional_patches << " lower-dimensional\n";
}
} // namespace

std::string report_to_json(const core::StructureReport& r) {
  nlohmann::ordered_json j;
  j["dimension"] = r.dimension;
  j["templates"] = r.templates;
  j["instances"] = r.instances;
  j["kind"] = r.mesh_templates ? "mesh" : "geometry";
  j["kernel"] = r.kernel.empty() ? kKernel : r.kernel;
  j["field_m"] = r.field_m;
  j["well_formed"] = r.well_formed;
  j["templated_structure"] = r.templated_structure;
  j["templated_mesh"] = r.templated_mesh;
  j["templated_geometry"] = r.templated_geometry;
  if (!r.error.empty()) j["error"] = r.error;
  if (r.overlap)
    j["overlapping_instances"] = {core::to_string(r.overlap->a), core::to_string(r.overlap->b)};
  j["instance_graph_edges"] = r.graph_edges.size();
  nlohmann::ordered_json l;
  if (r.templated_structure && r.mesh_templates) {
    l["holds"] = r.lemma42.holds;
    l["neighbouring_pairs_checked"] = r.lemma42.pairs_checked;
    if (!r.lemma42.holds) {
      l["failing_pair"] = {core::to_string(r.lemma42.a), core::to_string(r.lemma42.b)};
      l["condition"] = condition_name(r.lemma42.condition);
      l["detail"] = r.lemma42.detail;
    }
    l["agrees_with_direct_check"] = r.lemma42_agrees;
  } else {
    l["holds"] = nullptr;
    l["reason"] = r.mesh_templates ? "not a templated structure" : "geometry templates";
  }
  j["lemma_4_2"] = l;
  j["structure_instance_conforming"] = r.templated_structure
                                           ? nlohmann::ordered_json(r.at_conforming)
                                           : nlohmann::ordered_json(nullptr);
  nlohmann::ordered_json g;
  g["nodes"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.templates; ++i)
    g["nodes"].push_back({{"template", i + 1}, {"name", r.template_names.at(i)}});
  g["edges"] = nlohmann::ordered_json::array();
  for (const auto& e : r.graph_edges)
    g["edges"].push_back(
        {{"templates", {e.template_a + 1, e.template_b + 1}},
         {"instances", e.edge.trivial ? nlohmann::ordered_json(nullptr)
                                      : nlohmann::ordered_json{core::to_string(e.edge.a),
                                                               core::to_string(e.edge.b)}},
         {"trivial", e.edge.trivial},
         {"label", e.edge.label()}});
  j["instance_graph"] = g;
  j["structure_instance"] = {{"vertices", r.structure_instance_vertices},
                             {"cells", r.structure_instance_cells}};
  add_boundary_patches(j, r);
  return j.dump(2) + "\n";
}

std::string report_to_text(const core::StructureReport& r, const std::string& source) {
  std::ostringstream os;
  os << source << ": " << r.dimension << "D, " << r.templates << " template(s) ("
     << (r.mesh_templates ? "meshes" : "geometries") << "), " << r.instances
     << " instance(s), kernel " << (r.kernel.empty() ? kKernel : r.kernel) << "\n";
  if (!r.well_formed) {
    os << "  not a valid input: " << r.error << "\n";
    return os.str();
  }
  os << "  templated structure (Def 4.3, Eq. 4.2): " << (r.templated_structure ? "yes" : "NO")
     << "\n";
  if (!r.templated_structure) {
    os << "  " << r.error << "\n";
    return os.str();
  }
  if (r.mesh_templates) {
    os << "  templated mesh (Def 4.4, AT conforming): " << (r.templated_mesh ? "yes" : "NO")
       << "\n";
    os << "  Lemma 4.2 (interface conformity): " << (r.lemma42.holds ? "holds" : "FAILS") << " on "
       << r.lemma42.pairs_checked << " neighbouring instance pair(s)\n";
    if (!r.lemma42.holds)
      os << "    failing pair " << core::to_string(r.lemma42.a) << ", "
         << core::to_string(r.lemma42.b) << ": condition " << condition_name(r.lemma42.condition)
         << " - " << r.lemma42.detail << "\n";
    if (!r.lemma42_agrees)
      os << "    INTERNAL: the Lemma 4.2 checker disagrees with the direct conformity check\n";
  } else {
    os << "  templated geometry (Def 4.4): yes\n";
  }
  std::size_t loops = 0;
  for (const auto& e : r.graph_edges) loops += e.template_a == e.template_b;
  os << "  instance graph: " << r.templates << " node(s), " << r.graph_edges.size() << " edge(s) ("
     << loops << " self-loop(s))\n";
  os << "  structure instance: " << r.structure_instance_vertices << " vertices, "
     << r.structure_instance_cells << " cells\n";
  boundary_patches_text(os, r);
  return os.str();
}

} // namespace symmesh::io
