// Loading and analysing an input file, shared by check and graph.
#pragma once
#include "symmesh/core/structure_report.h"
#include "symmesh/io/templated_structure_json.h"

#include <string>
#include <variant>

namespace symmesh::apps {

inline core::StructureReport analyse_file(const std::string& path) {
  const auto x = io::read_templated_structure(path);
  return std::visit([](const auto& s) { return core::analyse(s); }, x);
}

} // namespace symmesh::apps
