// In-process Graphviz rendering of the instance graph.
#include "symmesh/io/instance_graph_render.h"

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace symmesh::io {
namespace {

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

void build(Graph& gr, const core::StructureReport& r) {
  char gname[] = "instance_graph";
  gr.g = agopen(gname, Agundirected, nullptr);
  if (!gr.g) throw std::runtime_error("graphviz: cannot create a graph");
  std::vector<Agnode_t*> nodes;
  for (std::size_t i = 0; i < r.templates; ++i) {
    std::string id = "X" + std::to_string(i + 1);
    Agnode_t* n = agnode(gr.g, id.data(), 1);
    std::string label = node_name(r, i);
    agsafeset(n, const_cast<char*>("label"), label.data(), const_cast<char*>(""));
    agsafeset(n, const_cast<char*>("shape"), const_cast<char*>("box"), const_cast<char*>(""));
    nodes.push_back(n);
  }
  std::size_t k = 0;
  for (const auto& e : r.graph_edges) {
    std::string id = "e" + std::to_string(k++);
    Agedge_t* ge = agedge(gr.g, nodes.at(e.template_a), nodes.at(e.template_b), id.data(), 1);
    std::string label = e.edge.label();
    agsafeset(ge, const_cast<char*>("label"), label.data(), const_cast<char*>(""));
    if (e.edge.trivial)
      agsafeset(ge, const_cast<char*>("style"), const_cast<char*>("dashed"), const_cast<char*>(""));
  }
}

} // namespace

std::string instance_graph_dot(const core::StructureReport& r) {
  // Written directly (not through agwrite) so that the text is stable across Graphviz versions.
  std::ostringstream os;
  os << "graph instance_graph {\n  node [shape=box];\n";
  for (std::size_t i = 0; i < r.templates; ++i)
    os << "  X" << (i + 1) << " [label=\"" << escape(node_name(r, i)) << "\"];\n";
  for (const auto& e : r.graph_edges)
    os << "  X" << (e.template_a + 1) << " -- X" << (e.template_b + 1) << " [label=\""
       << escape(e.edge.label()) << "\"" << (e.edge.trivial ? ", style=dashed" : "") << "];\n";
  os << "}\n";
  return os.str();
}

void render_instance_graph(const core::StructureReport& r, const std::string& path) {
  namespace fs = std::filesystem;
  const std::string ext = fs::path(path).extension().string();
  if (ext != ".dot" && ext != ".svg" && ext != ".png")
    throw std::invalid_argument("-o " + path + ": unknown output format '" + ext +
                                "' (use .dot, .svg or .png)");
  const std::string tmp = path + ".tmp";
  if (ext == ".dot") {
    std::ofstream out(tmp);
    out << instance_graph_dot(r);
    if (!out) throw std::runtime_error(path + ": cannot write");
  } else {
    Graph gr;
    build(gr, r);
    if (gvLayout(gr.gvc, gr.g, "dot") != 0) throw std::runtime_error("graphviz: layout failed");
    gr.laid_out = true;
    if (gvRenderFilename(gr.gvc, gr.g, ext.substr(1).c_str(), tmp.c_str()) != 0) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw std::runtime_error("graphviz: rendering " + ext.substr(1) + " failed");
    }
  }
  fs::rename(tmp, path);
}

} // namespace symmesh::io
