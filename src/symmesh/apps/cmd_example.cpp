// symmesh example NAME -o GEOMETRY.json | symmesh example --list
#include "symmesh/apps/commands.h"
#include "symmesh/io/atomic_file.h"
#include "symmesh/io/examples.h"

#include <filesystem>
#include <fstream>
#include <iostream>

namespace symmesh::apps {
namespace {
struct ExampleOptions {
  std::string name, out;
  bool list = false;
};

int run_example(const ExampleOptions& o) {
  if (o.list) {
    for (const auto& e : io::example_list()) std::cout << e.name << "\t" << e.summary << "\n";
    return ok;
  }
  if (o.name.empty() || o.out.empty()) {
    print_error("example: give NAME and -o FILE.json, or --list");
    return bad_input;
  }
  nlohmann::ordered_json doc;
  try {
    doc = io::example_document(o.name);
  } catch (const std::invalid_argument& e) {
    print_error(std::string("example: ") + e.what());
    return bad_input;
  }
  try {
    io::write_file_atomically(o.out, doc.dump(2) + "\n");
  } catch (const std::runtime_error& e) {
    print_error(std::string("example: ") + e.what());
    return bad_input;
  }
  return ok;
}
} // namespace

void add_example(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ExampleOptions>();
  auto* cmd = app.add_subcommand("example", "Write a built-in templated geometry (2D: n-gons, "
                                            "MOSFET, aircraft, bridge, star; 3D: open TSVs) "
                                            "as JSON (spec/examples.md).");
  cmd->add_option("name", o->name, "example name (see --list)");
  cmd->add_option("-o,--output", o->out, "templated-geometry JSON to write");
  cmd->add_flag("--list", o->list, "list the built-in examples");
  cmd->callback([o, &exit_code] { exit_code = run_example(*o); });
}

} // namespace symmesh::apps
