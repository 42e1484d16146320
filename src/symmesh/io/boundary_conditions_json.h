/// The boundary-condition file of `symmesh solve` (JSON, "symmesh": "boundary-conditions/1") —
/// spec/fem.md#bc-file
#pragma once
#include "symmesh/fem/boundary_conditions.h"

#include <string>

namespace symmesh::io {

/// Throws io::InputError (templated_structure_json.h) with a one-line message naming the field
/// (malformed JSON, unknown key, non-finite number, empty box, …).
fem::BoundaryConditions parse_boundary_conditions(const std::string& text,
                                                  const std::string& source);
fem::BoundaryConditions read_boundary_conditions(const std::string& path);

} // namespace symmesh::io
