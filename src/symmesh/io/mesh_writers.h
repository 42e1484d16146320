/// Writers of a generated structure instance — spec/outputs.md#mesh-files
///
/// VTK XML unstructured grid (.vtu, ParaView; cell data region, template, instance), Gmsh MSH
/// 4.1 ASCII (.msh; one surface entity per region, physical tag = region) and Medit (.mesh;
/// reference = region). Numbers are printed with 17 significant digits, so the same mesh gives
/// the same bytes. Each writer writes a temporary file next to the target and renames it, so a
/// failure leaves no partial output.
#pragma once
#include "symmesh/mesh/templated_mesh.h"

#include <string>

namespace symmesh::io {

void write_vtu(const mesh::StructureInstanceMesh& m, const std::string& path);
void write_msh41(const mesh::StructureInstanceMesh& m, const std::string& path);
void write_medit(const mesh::StructureInstanceMesh& m, const std::string& path);
/// By extension: .vtu, .msh or .mesh; throws std::invalid_argument for another extension.
void write_mesh_file(const mesh::StructureInstanceMesh& m, const std::string& path);

} // namespace symmesh::io
