/// The templated mesh file (.tmesh) — spec/outputs.md#tmesh
///
/// JSON, "symmesh": "templated-mesh/1": the compact-SVB templated mesh as symmesh holds it
/// (templates with double vertices and cells, per instance a transformation index and a region,
/// the transformations, the identification tables and the instance identifications). Doubles
/// are written so that they read back bit-identically; `read_tmesh(write_tmesh(t)) == t`.
#pragma once
#include "symmesh/mesh/templated_mesh.h"

#include <string>

namespace symmesh::io {

/// Writes atomically (path + ".part", then rename).
void write_tmesh(const mesh::TemplatedMeshCompactSvb& t, const std::string& path);
/// Throws io::InputError (templated_structure_json.h) naming the field for malformed files.
mesh::TemplatedMeshCompactSvb read_tmesh(const std::string& path);

} // namespace symmesh::io
