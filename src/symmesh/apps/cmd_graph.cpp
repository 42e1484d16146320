// symmesh graph FILE -o OUT.{dot,svg,png} [--view templates|instances]
#include "symmesh/apps/commands.h"
#include "symmesh/apps/load.h"
#include "symmesh/io/instance_graph_render.h"

#include <iostream>
#include <map>

namespace symmesh::apps {
namespace {
struct GraphOptions {
  std::string file, out;
  io::GraphView view = io::GraphView::templates;
  bool quiet = false;
};

/// Instances per template, isolated ones included (the report's edges name only neighbours).
std::vector<std::size_t> instances_per_template(const std::string& path) {
  return std::visit(
      [](const auto& x) {
        std::vector<std::size_t> n(x.templates.size(), 0);
        for (const auto& id : x.instance_ids()) ++n.at(id.i);
        return n;
      },
      io::read_templated_structure(path));
}

int run_graph(const GraphOptions& o) {
  core::StructureReport r;
  if (!load_well_formed(o.file, r)) return bad_input;
  if (!r.templated_structure) {
    print_error(o.file + ": " + r.error);
    return bad_input;
  }
  io::GraphRenderOptions ro;
  ro.view = o.view;
  try {
    if (o.view == io::GraphView::instances)
      ro.instances_per_template = instances_per_template(o.file);
    io::render_instance_graph(r, o.out, ro);
  } catch (const std::invalid_argument& e) {
    print_error(e.what());
    return bad_input;
  }
  if (!o.quiet)
    std::cerr << "symmesh: wrote " << o.out << " ("
              << (o.view == io::GraphView::templates ? "template view, " : "instance view, ")
              << r.templates << " templates, " << r.instances << " instances, "
              << r.graph_edges.size() << " edges)\n";
  return ok;
}
} // namespace

void add_graph(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<GraphOptions>();
  auto* cmd = app.add_subcommand(
      "graph", "Render the instance graph with Graphviz: by default one node per template and one "
               "edge per template pair labelled with its number of neighbouring instance pairs "
               "(the full list in the .dot); --view instances draws the instances.");
  cmd->add_option("file", o->file, "templated-structure JSON")->required();
  cmd->add_option("-o,--output", o->out, "output file: .dot, .svg or .png")->required();
  const std::map<std::string, io::GraphView> views{{"templates", io::GraphView::templates},
                                                   {"instances", io::GraphView::instances}};
  cmd->add_option("--view", o->view,
                  "templates (default) or instances (at most " +
                      std::to_string(io::kMaxInstanceViewInstances) + " instances)")
      ->transform(CLI::CheckedTransformer(views, CLI::ignore_case));
  cmd->add_flag("-q,--quiet", o->quiet, "no message on stderr");
  cmd->callback([o, &exit_code] { exit_code = run_graph(*o); });
}

} // namespace symmesh::apps
