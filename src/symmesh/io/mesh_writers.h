/// Writers of a generated structure instance — spec/outputs.md#mesh-files
///
/// VTK XML unstructured grid (.vtu, ParaView; cell data region, template, instance), Gmsh MSH
/// 4.1 (.msh; one entity per region, physical tag = region) and Medit (.mesh; reference =
/// region). The structure instance is streamed from the templated mesh instance by instance
/// (mesh/structure_instance.h), so writing needs memory for one instance, not for AT. Binary by
/// default (.vtu: appended raw data, optionally zlib-compressed as VTK's vtkZLibDataCompressor;
/// .msh: MSH 4.1 binary); ASCII on request, with 17 significant digits. Every cell is positively
/// oriented. The same mesh and options give the same bytes. Each writer writes PATH.part and
/// renames it, so a failure leaves no partial output.
#pragma once
#include "symmesh/mesh/progress.h"
#include "symmesh/mesh/structure_instance.h"

#include <string>
#include <utility>
#include <vector>

namespace symmesh::io {

struct MeshFileOptions {
  bool ascii = false;    ///< text instead of binary (.vtu, .msh; .mesh is always text)
  bool compress = false; ///< .vtu only: zlib-compressed appended blocks
  mesh::Progress* progress = nullptr;
  /// .vtu only: named point-data arrays (one value per vertex of the structure instance, in the
  /// writer's vertex order), e.g. the solution of `symmesh solve`.
  std::vector<std::pair<std::string, const std::vector<double>*>> point_data;
};

void write_vtu(const mesh::StructureInstance& at, const std::string& path,
               const MeshFileOptions& options = {});
void write_msh41(const mesh::StructureInstance& at, const std::string& path,
                 const MeshFileOptions& options = {});
void write_medit(const mesh::StructureInstance& at, const std::string& path,
                 const MeshFileOptions& options = {});
/// By extension: .vtu, .msh or .mesh; throws std::invalid_argument for another extension and
/// for --compress with a format other than .vtu.
void write_mesh_file(const mesh::StructureInstance& at, const std::string& path,
                     const MeshFileOptions& options = {});

} // namespace symmesh::io
