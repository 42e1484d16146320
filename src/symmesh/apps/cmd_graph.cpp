// symmesh graph FILE -o OUT.{dot,svg,png}
#include "symmesh/apps/commands.h"
#include "symmesh/apps/load.h"
#include "symmesh/io/instance_graph_render.h"

#include <iostream>

namespace symmesh::apps {
namespace {
struct GraphOptions {
  std::string file, out;
  bool quiet = false;
};

int run_graph(const GraphOptions& o) {
  core::StructureReport r;
  if (!load_well_formed(o.file, r)) return bad_input;
  if (!r.templated_structure) {
    print_error(o.file + ": " + r.error);
    return bad_input;
  }
  try {
    io::render_instance_graph(r, o.out);
  } catch (const std::invalid_argument& e) {
    print_error(e.what());
    return bad_input;
  }
  if (!o.quiet)
    std::cerr << "symmesh: wrote " << o.out << " (" << r.templates << " nodes, "
              << r.graph_edges.size() << " edges)\n";
  return ok;
}
} // namespace

void add_graph(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<GraphOptions>();
  auto* cmd = app.add_subcommand(
      "graph", "Render the instance graph (a multigraph with one self-loop per template and one "
               "edge per neighbouring instance pair) with Graphviz.");
  cmd->add_option("file", o->file, "templated-structure JSON")->required();
  cmd->add_option("-o,--output", o->out, "output file: .dot, .svg or .png")->required();
  cmd->add_flag("-q,--quiet", o->quiet, "no message on stderr");
  cmd->callback([o, &exit_code] { exit_code = run_graph(*o); });
}

} // namespace symmesh::apps
