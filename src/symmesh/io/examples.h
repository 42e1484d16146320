/// Built-in 2D and 3D templated geometries (`symmesh example NAME`) — spec/examples.md
///
/// Each is a templated-structure document (spec/input-format.md) with exact coordinates: the
/// regular n-gon as n slices and in the small-angle-optimised form (Section 6.3.2), a MOSFET-like
/// multi-region device and an aircraft-like outline with one mirror axis, a Warren-truss bridge of
/// beams and connectors instanced by translations and 60°/120°/180° rotations (Section 7.4), and
/// the five-pointed star without symmetry, with its rotations, and with reflections and rotations
/// (Algorithm 6.5); in 3D the open TSV as n slices about the z axis (Section 6.3). Our own
/// coordinates; the dissertation gives none.
#pragma once
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace symmesh::io {

struct ExampleInfo {
  std::string name, summary;
  int dimension = 2; ///< 3 for the 3D objects (the open TSVs)
};

/// Every built-in name with a one-line summary, in a fixed order.
std::vector<ExampleInfo> example_list();

/// The document of `name`. Throws std::invalid_argument naming the known examples otherwise.
nlohmann::ordered_json example_document(const std::string& name);

} // namespace symmesh::io
