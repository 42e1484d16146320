/// Instance graph output: DOT text, and SVG/PNG rendered in-process with the Graphviz library
/// (gvc/cgraph) — spec/outputs.md#instance-graph
#pragma once
#include "symmesh/core/structure_report.h"

#include <string>

namespace symmesh::io {

/// The instance graph as an undirected multigraph in DOT: one node per template, one edge per
/// neighbouring instance pair (labelled "T_{i,g} / T_{j,h}") and the trivial self-loops ("I").
std::string instance_graph_dot(const core::StructureReport& r);

/// Writes the graph to `path`; the format comes from the extension: .dot, .svg or .png.
/// Writes to a temporary file and renames it, so a failure leaves no partial output.
/// Throws std::invalid_argument for another extension, std::runtime_error if Graphviz fails.
void render_instance_graph(const core::StructureReport& r, const std::string& path);

} // namespace symmesh::io
