/// The templated mesh file (.tmesh) — spec/outputs.md#tmesh
///
/// JSON, "symmesh": "templated-mesh/1": the compact-SVB templated mesh as symmesh holds it
/// (templates with double vertices and cells, per instance a transformation index and a region,
/// the transformations, the identification tables and the instance identifications). Doubles
/// are written so that they read back bit-identically; `read_tmesh(write_tmesh(t)) == t`.
#pragma once
#include "symmesh/mesh/templated_mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace symmesh::io {

/// Optional point data per instance, over its template's vertices: (name, values[global instance]
/// [template vertex]) — e.g. the solution of `symmesh solve --templated`.
using InstancePointData = std::vector<std::pair<std::string, std::vector<std::vector<double>>>>;

/// Writes atomically (path + ".part", then rename); each instance gets "point_data" when given.
void write_tmesh(const mesh::TemplatedMeshCompactSvb& t, const std::string& path,
                 const InstancePointData& point_data = {});
/// Throws io::InputError (templated_structure_json.h) naming the field for malformed files.
mesh::TemplatedMeshCompactSvb read_tmesh(const std::string& path);

} // namespace symmesh::io
