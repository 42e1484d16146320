/// Instance graph output: DOT text, and SVG/PNG rendered in-process with the Graphviz library
/// (gvc/cgraph), in a template-level and an instance-level view —
/// spec/outputs.md#instance-graph
///
/// The instance graph (definitions.md#instance-graph) is a multigraph on the templates with one
/// edge per neighbouring instance pair: a real structure (the bridge: 2 templates, 62 pairs) drawn
/// edge by edge is a strip of overlapping labels. The template view therefore collapses the
/// parallel edges of a template pair into one edge labelled with their multiplicity (the full
/// list stays in the DOT text as comments and in the SVG tooltips); the instance view draws the
/// instances themselves, coloured by template. Pictures are kept within kMaxPicturePixels at
/// readable labels, or refused.
#pragma once
#include "symmesh/core/structure_report.h"

#include <cstddef>
#include <string>
#include <vector>

namespace symmesh::io {

enum class GraphView { templates, instances };

/// Largest width and height of a rendered picture, in pixels (96 dpi).
inline constexpr double kMaxPicturePixels = 2000;
/// Smallest label size, in pixels at the output size, that still counts as readable.
inline constexpr double kMinLabelPixels = 10;
/// Largest structure the instance view draws: beyond, no layout keeps labels readable.
inline constexpr std::size_t kMaxInstanceViewInstances = 400;

struct GraphRenderOptions {
  GraphView view = GraphView::templates;
  /// Instances of each template (the instance view's nodes, isolated instances included). Empty:
  /// only the instances named by some edge are drawn.
  std::vector<std::size_t> instances_per_template;
};

/// The graph in DOT. Template view: one node per template, the trivial self-loop "I" (dashed),
/// and one edge per template pair with neighbouring instances, labelled "N pairs" (attribute
/// multiplicity=N), followed by its pairs as comments. Instance view: one node per instance
/// T_{i,g}, filled in its template's colour, one edge per neighbouring instance pair, a legend
/// of templates as the graph label.
/// \pre every edge's templates are < r.templates
std::string instance_graph_dot(const core::StructureReport& r, const GraphRenderOptions& o = {});

/// Writes the graph to `path`; the format comes from the extension: .dot, .svg or .png.
/// Writes PATH.part and renames it, so a failure leaves no partial output.
/// Throws std::invalid_argument for another extension, for an instance view of more than
/// kMaxInstanceViewInstances instances, and for a layout that would not fit kMaxPicturePixels
/// with labels of kMinLabelPixels; std::runtime_error if Graphviz fails.
void render_instance_graph(const core::StructureReport& r, const std::string& path,
                           const GraphRenderOptions& o = {});

} // namespace symmesh::io
