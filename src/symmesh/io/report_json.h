/// The `symmesh check` report, as JSON (--json) and as text — spec/outputs.md#check-report
#pragma once
#include "symmesh/core/structure_report.h"

#include <string>

namespace symmesh::io {

/// One JSON object: templated_structure, templated_mesh, templated_geometry, dimension,
/// templates, instances, instance_graph_edges, lemma_4_2 {holds, failing_pair, condition, ...},
/// kernel, instance_graph {nodes, edges}, structure_instance {vertices, cells}, error, and for
/// templated structures regular, irregularity, patches_per_template (bpp_error when Algorithm 4.1
/// hit its composition guard).
std::string report_to_json(const core::StructureReport& r);

/// The human-readable report printed by `symmesh check`.
std::string report_to_text(const core::StructureReport& r, const std::string& source);

} // namespace symmesh::io
