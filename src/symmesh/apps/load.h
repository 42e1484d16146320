// Loading and analysing an input file, shared by check and graph.
#pragma once
#include "symmesh/core/structure_report.h"
#include "symmesh/io/templated_structure_json.h"

#include <string>
#include <variant>

namespace symmesh::apps {

inline core::StructureReport analyse_file(const std::string& path) {
  const auto x = io::read_templated_structure(path);
  core::StructureReport r = std::visit([](const auto& s) { return core::analyse(s); }, x);
  r.kernel = io::kernel_name(x);
  r.field_m = io::field_order(x);
  return r;
}

void print_error(const std::string& message);

/// Loads and analyses `path` into `r`. Returns false after printing the one-line error when the
/// input is not usable at all (unreadable, malformed, or not well-formed).
inline bool load_well_formed(const std::string& path, core::StructureReport& r) {
  try {
    r = analyse_file(path);
  } catch (const io::InputError& e) {
    print_error(e.what());
    return false;
  }
  if (!r.well_formed) {
    print_error(path + ": " + r.error);
    return false;
  }
  return true;
}

} // namespace symmesh::apps
