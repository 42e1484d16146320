// In-process Graphviz rendering of the instance graph: the DOT text is the single description,
// parsed back by cgraph for SVG/PNG, so what the .dot file says is what the picture shows.
#include "symmesh/io/instance_graph_render.h"

#include "symmesh/io/atomic_file.h"
#include "symmesh/io/colour.h"
#include "symmesh/io/svg.h"

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace symmesh::io {
namespace {

/// Graphviz sizes are in points (SVG keeps them); its PNG renderer draws at 96 dpi, and pictures
/// are measured in pixels at that resolution.
constexpr double kDpi = 96;
constexpr double kNodeFontPt = 12;
/// Above this many instances neato's stress majorisation gets slow; sfdp is made for it.
constexpr std::size_t kNeatoInstances = 150;

std::string node_name(const core::StructureReport& r, std::size_t i) {
  const std::string n = i < r.template_names.size() ? r.template_names[i] : "";
  return "X" + std::to_string(i + 1) +
         (n.empty() || n == "X" + std::to_string(i + 1) ? "" : " (" + n + ")");
}

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

/// Graph-wide attributes: the page limit lets Graphviz only shrink (never enlarge) a layout; the
/// readability check after layout refuses shrinking that would make labels unreadable.
void graph_header(std::ostringstream& os, const std::string& extra) {
  const double inches = kMaxPicturePixels / kDpi;
  char size[64];
  std::snprintf(size, sizeof size, "%.4f,%.4f", inches, inches);
  os << "graph instance_graph {\n  graph [fontname=\"Helvetica\", fontsize=" << kNodeFontPt
     << ", size=\"" << size << "\", pad=0.2" << extra << "];\n";
}

using PairKey = std::pair<std::size_t, std::size_t>;

/// Non-trivial edges grouped by unordered template pair, in the report's order within a group.
std::map<PairKey, std::vector<std::string>> pairs_by_templates(const core::StructureReport& r) {
  std::map<PairKey, std::vector<std::string>> groups;
  for (const auto& e : r.graph_edges) {
    if (e.edge.trivial) continue;
    const PairKey key{std::min(e.template_a, e.template_b), std::max(e.template_a, e.template_b)};
    groups[key].push_back(e.edge.label());
  }
  return groups;
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (std::size_t k = 0; k < v.size(); ++k) out += (k ? sep : "") + v[k];
  return out;
}

std::string template_view_dot(const core::StructureReport& r) {
  std::ostringstream os;
  const auto groups = pairs_by_templates(r);
  std::size_t pairs = 0;
  for (const auto& [key, labels] : groups) pairs += labels.size();
  graph_header(os, ", label=\"" + std::to_string(r.templates) + " templates, " +
                       std::to_string(r.instances) + " instances, " + std::to_string(pairs) +
                       " neighbouring instance pairs (symmesh graph --view instances)\"");
  os << "  node [shape=box, fontname=\"Helvetica\", fontsize=" << kNodeFontPt << "];\n"
     << "  edge [fontname=\"Helvetica\", fontsize=" << kNodeFontPt << "];\n";
  for (std::size_t i = 0; i < r.templates; ++i)
    os << "  X" << (i + 1) << " [label=\"" << escape(node_name(r, i)) << "\"];\n";
  for (const auto& e : r.graph_edges)
    if (e.edge.trivial)
      os << "  X" << (e.template_a + 1) << " -- X" << (e.template_b + 1)
         << " [label=\"I\", style=dashed];\n";
  for (const auto& [key, labels] : groups) {
    const std::string n = std::to_string(labels.size());
    os << "  X" << (key.first + 1) << " -- X" << (key.second + 1) << " [label=\"" << n
       << (labels.size() == 1 ? " pair" : " pairs") << "\", multiplicity=" << n
       << ", penwidth=2, tooltip=\"" << escape(join(labels, ", ")) << "\"];\n";
    for (const auto& l : labels)
      os << "  // X" << (key.first + 1) << " -- X" << (key.second + 1) << ": " << l << "\n";
  }
  os << "}\n";
  return os.str();
}

std::vector<std::size_t> instance_counts(const core::StructureReport& r,
                                         const GraphRenderOptions& o) {
  if (!o.instances_per_template.empty()) return o.instances_per_template;
  std::vector<std::size_t> n(r.templates, 0);
  for (const auto& e : r.graph_edges)
    for (const auto& id : {e.edge.a, e.edge.b}) n.at(id.i) = std::max(n.at(id.i), id.g + 1);
  return n;
}

std::string instance_node(const core::InstanceId& id) {
  return "T" + std::to_string(id.i + 1) + "_" + std::to_string(id.g + 1);
}

/// The legend of the instance view (an HTML-like graph label): one colour swatch per template.
std::string legend(const core::StructureReport& r, const std::vector<std::size_t>& counts) {
  std::ostringstream os;
  os << "<<table border=\"0\" cellspacing=\"4\">";
  for (std::size_t i = 0; i < counts.size(); ++i)
    os << "<tr><td bgcolor=\"" << fill_colour(i) << "\" width=\"18\"> </td><td align=\"left\">"
       << xml_escape(node_name(r, i)) << ": " << counts[i] << " instances</td></tr>";
  os << "</table>>";
  return os.str();
}

std::string instance_view_dot(const core::StructureReport& r, const GraphRenderOptions& o) {
  const auto counts = instance_counts(r, o);
  std::size_t total = 0;
  for (auto c : counts) total += c;
  std::ostringstream os;
  // start=1 seeds neato's initial placement, so the same graph gives the same picture.
  graph_header(os, std::string(", layout=") + (total <= kNeatoInstances ? "neato" : "sfdp") +
                       ", overlap=false, sep=\"+6\", start=1, outputorder=edgesfirst, "
                       "labelloc=b, label=" +
                       legend(r, counts));
  os << "  node [shape=ellipse, style=filled, fontname=\"Helvetica\", fontsize=" << kNodeFontPt
     << ", margin=\"0.03,0.02\"];\n  edge [color=\"#555555\"];\n";
  for (std::size_t i = 0; i < counts.size(); ++i)
    for (std::size_t g = 0; g < counts[i]; ++g) {
      const core::InstanceId id{i, g};
      os << "  " << instance_node(id) << " [label=\"" << core::to_string(id) << "\", fillcolor=\""
         << fill_colour(i) << "\"];\n";
    }
  for (const auto& e : r.graph_edges)
    if (!e.edge.trivial)
      os << "  " << instance_node(e.edge.a) << " -- " << instance_node(e.edge.b) << ";\n";
  os << "}\n";
  return os.str();
}

std::size_t instance_total(const core::StructureReport& r, const GraphRenderOptions& o) {
  std::size_t total = 0;
  for (auto c : instance_counts(r, o)) total += c;
  return total;
}

/// Owns a Graphviz graph with its context.
struct Graph {
  GVC_t* gvc = gvContext();
  Agraph_t* g = nullptr;
  bool laid_out = false;
  ~Graph() {
    if (g && laid_out) gvFreeLayout(gvc, g);
    if (g) agclose(g);
    gvFreeContext(gvc);
  }
};

/// Pixel size of the laid-out graph at kDpi before Graphviz's shrinking to `size`.
std::pair<double, double> layout_pixels(Agraph_t* g) {
  double llx = 0, lly = 0, urx = 0, ury = 0;
  const char* bb = agget(g, const_cast<char*>("bb"));
  std::string text = bb ? bb : "";
  std::replace(text.begin(), text.end(), ',', ' '); // gvLayout writes spaces, the DOT writer commas
  if (std::sscanf(text.c_str(), "%lf %lf %lf %lf", &llx, &lly, &urx, &ury) != 4)
    throw std::runtime_error("graphviz: no bounding box after layout");
  return {(urx - llx) * kDpi / 72, (ury - lly) * kDpi / 72};
}

/// Labels are drawn at kNodeFontPt, shrunk by Graphviz to fit the page: their size in pixels.
double label_pixels(const std::pair<double, double>& size) {
  const double scale =
      std::min({1.0, kMaxPicturePixels / size.first, kMaxPicturePixels / size.second});
  return kNodeFontPt * kDpi / 72 * scale;
}

/// A layout engine with the graph attributes it is tried with.
struct Engine {
  const char* name;
  std::vector<std::pair<const char*, const char*>> attributes;
};

/// The template view is tried top-down and left-right with dot (the rank direction whose
/// aspect fits the page better wins) and, for dense template graphs, spread out by neato.
std::vector<Engine> engines(GraphView view, std::size_t instances) {
  if (view == GraphView::instances) return {{instances <= kNeatoInstances ? "neato" : "sfdp", {}}};
  return {{"dot", {{"rankdir", "TB"}}},
          {"dot", {{"rankdir", "LR"}}},
          {"neato", {{"overlap", "false"}, {"sep", "+30"}, {"start", "1"}}}};
}

std::unique_ptr<Graph> laid_out(const std::string& dot, const Engine& e) {
  auto gr = std::make_unique<Graph>();
  gr->g = agmemread(dot.c_str());
  if (!gr->g) throw std::runtime_error("graphviz: cannot read the generated DOT");
  for (const auto& [name, value] : e.attributes)
    agsafeset(gr->g, const_cast<char*>(name), const_cast<char*>(value), const_cast<char*>(""));
  if (gvLayout(gr->gvc, gr->g, e.name) != 0) throw std::runtime_error("graphviz: layout failed");
  gr->laid_out = true;
  return gr;
}

/// The candidate layout with the largest labels (the first that needs no shrinking).
std::unique_ptr<Graph> readable_layout(const std::string& dot, const std::vector<Engine>& es) {
  std::unique_ptr<Graph> best;
  double best_px = 0;
  std::pair<double, double> best_size;
  for (const auto& e : es) {
    auto gr = laid_out(dot, e);
    const auto size = layout_pixels(gr->g);
    if (label_pixels(size) > best_px)
      best = std::move(gr), best_px = label_pixels(size), best_size = size;
    if (best_px >= kNodeFontPt * kDpi / 72) break;
  }
  if (best_px >= kMinLabelPixels) return best;
  char msg[256];
  std::snprintf(msg, sizeof msg,
                "the layout needs %.0f x %.0f pixels; shrunk to %.0f pixels its labels would be "
                "%.1f px (< %.0f): use --view templates, or -o .dot",
                best_size.first, best_size.second, kMaxPicturePixels, best_px, kMinLabelPixels);
  throw std::invalid_argument(msg);
}

std::string render_with_graphviz(const std::string& dot, const std::vector<Engine>& es,
                                 const std::string& format) {
  const auto gr = readable_layout(dot, es);
  char* data = nullptr;
  unsigned int length = 0;
  if (gvRenderData(gr->gvc, gr->g, format.c_str(), &data, &length) != 0 || !data)
    throw std::runtime_error("graphviz: rendering " + format + " failed");
  std::string bytes(data, length);
  gvFreeRenderData(data);
  return bytes;
}

} // namespace

std::string instance_graph_dot(const core::StructureReport& r, const GraphRenderOptions& o) {
  for (const auto& e : r.graph_edges)
    if (e.template_a >= r.templates || e.template_b >= r.templates)
      throw std::invalid_argument("instance graph: an edge names a template out of range");
  return o.view == GraphView::templates ? template_view_dot(r) : instance_view_dot(r, o);
}

void render_instance_graph(const core::StructureReport& r, const std::string& path,
                           const GraphRenderOptions& o) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".dot" && ext != ".svg" && ext != ".png")
    throw std::invalid_argument("-o " + path + ": unknown output format '" + ext +
                                "' (use .dot, .svg or .png)");
  if (o.view == GraphView::instances && instance_total(r, o) > kMaxInstanceViewInstances)
    throw std::invalid_argument("--view instances draws at most " +
                                std::to_string(kMaxInstanceViewInstances) +
                                " instances, this "
                                "structure has " +
                                std::to_string(instance_total(r, o)) + " (use --view templates)");
  const std::string dot = instance_graph_dot(r, o);
  if (ext == ".dot") return write_file_atomically(path, dot);
  write_file_atomically(
      path, render_with_graphviz(dot, engines(o.view, instance_total(r, o)), ext.substr(1)));
}

} // namespace symmesh::io
