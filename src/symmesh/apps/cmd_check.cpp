// symmesh check FILE [--json]
#include "symmesh/apps/commands.h"
#include "symmesh/apps/load.h"
#include "symmesh/io/report_json.h"

#include <iostream>

namespace symmesh::apps {

void print_error(const std::string& message) {
  std::string one_line = message;
  for (char& c : one_line)
    if (c == '\n') c = ' ';
  std::cerr << "symmesh: error: " << one_line << "\n";
}

namespace {
struct CheckOptions {
  std::string file;
  bool json = false;
};

int run_check(const CheckOptions& o) {
  core::StructureReport r;
  if (!load_well_formed(o.file, r)) return bad_input;
  if (o.json)
    std::cout << io::report_to_json(r);
  else
    std::cout << io::report_to_text(r, o.file);
  if (!r.templated_structure) {
    print_error(o.file + ": not a templated structure: " + r.error);
    return bad_input;
  }
  if (r.mesh_templates && !r.templated_mesh) {
    if (!o.json)
      std::cerr << "symmesh: " << o.file << " is a templated structure but not a templated mesh"
                << " (Lemma 4.2 fails for " << core::to_string(r.lemma42.a) << ", "
                << core::to_string(r.lemma42.b) << ")\n";
    return negative;
  }
  return ok;
}
} // namespace

void add_check(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CheckOptions>();
  auto* cmd = app.add_subcommand(
      "check", "Validate a templated structure: Eq. 4.2, templated mesh/geometry, the Lemma 4.2 "
               "verdict with the failing instance pair, instance graph. Exit 0: templated mesh or "
               "geometry; 1: templated structure only; 2: bad input.");
  cmd->add_option("file", o->file, "templated-structure JSON (spec/input-format.md)")->required();
  cmd->add_flag("--json", o->json, "print one JSON object instead of the text report");
  cmd->callback([o, &exit_code] { exit_code = run_check(*o); });
}

} // namespace symmesh::apps
