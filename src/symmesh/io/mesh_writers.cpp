// .vtu, .msh 4.1 and .mesh writers (spec/outputs.md#mesh-files).
#include "symmesh/io/mesh_writers.h"

#include "symmesh/io/atomic_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace symmesh::io {
namespace {

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

double coordinate(const mesh::Mesh& m, std::size_t v, int d) {
  return d < m.point_dimension ? m.vertex(v)[d] : 0.0;
}

} // namespace

void write_vtu(const mesh::StructureInstanceMesh& s, const std::string& path) {
  const auto& m = s.mesh.mesh;
  write_atomically(path, [&](std::ostream& os) {
    os << "<?xml version=\"1.0\"?>\n"
          "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
          "header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\""
       << m.vertex_count() << "\" NumberOfCells=\"" << m.cell_count() << "\">\n";
    os << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::size_t v = 0; v < m.vertex_count(); ++v)
      os << number(coordinate(m, v, 0)) << ' ' << number(coordinate(m, v, 1)) << ' '
         << number(coordinate(m, v, 2)) << '\n';
    os << "</DataArray>\n</Points>\n<Cells>\n"
          "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
      const int n = mesh::vertex_count(m.cell_types[c]);
      for (int k = 0; k < n; ++k) os << m.cell(c)[k] << (k + 1 < n ? ' ' : '\n');
    }
    os << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t c = 1; c < m.cell_vertex_index_offsets.size(); ++c)
      os << m.cell_vertex_index_offsets[c] << '\n';
    os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (auto t : m.cell_types) os << int(t) << '\n';
    os << "</DataArray>\n</Cells>\n<CellData Scalars=\"region\">\n";
    const auto array = [&](const char* name, auto get) {
      os << "<DataArray type=\"Int32\" Name=\"" << name << "\" format=\"ascii\">\n";
      for (std::size_t c = 0; c < m.cell_count(); ++c) os << get(c) << '\n';
      os << "</DataArray>\n";
    };
    array("region", [&](std::size_t c) { return int(s.mesh.cell_region[c]); });
    array("template", [&](std::size_t c) { return s.cell_template[c] + 1; });
    array("instance", [&](std::size_t c) { return s.cell_instance[c] + 1; });
    os << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  });
}

void write_msh41(const mesh::StructureInstanceMesh& s, const std::string& path) {
  const auto& m = s.mesh.mesh;
  const int dim = m.point_dimension;
  std::map<int, std::vector<std::size_t>> cells_of_region;
  for (std::size_t c = 0; c < m.cell_count(); ++c)
    cells_of_region[s.mesh.cell_region[c]].push_back(c);
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    for (int d = 0; d < 3; ++d) {
      const double x = coordinate(m, v, d);
      if (v == 0 || x < lo[d]) lo[d] = x;
      if (v == 0 || x > hi[d]) hi[d] = x;
    }
  const int gmsh_type = dim == 2 ? 2 : 4; // 3-node triangle, 4-node tetrahedron
  write_atomically(path, [&](std::ostream& os) {
    os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    os << "$PhysicalNames\n" << cells_of_region.size() << '\n';
    for (const auto& [region, cells] : cells_of_region)
      os << dim << ' ' << region << " \"region_" << region << "\"\n";
    os << "$EndPhysicalNames\n$Entities\n";
    os << "0 0 " << (dim == 2 ? cells_of_region.size() : 0) << ' '
       << (dim == 3 ? cells_of_region.size() : 0) << '\n';
    for (const auto& [region, cells] : cells_of_region) {
      os << region;
      for (int d = 0; d < 3; ++d) os << ' ' << number(lo[d]);
      for (int d = 0; d < 3; ++d) os << ' ' << number(hi[d]);
      os << " 1 " << region << " 0\n";
    }
    os << "$EndEntities\n$Nodes\n";
    const std::size_t nv = m.vertex_count(), nc = m.cell_count();
    const int first_entity = cells_of_region.empty() ? 1 : cells_of_region.begin()->first;
    os << "1 " << nv << " 1 " << nv << '\n' << dim << ' ' << first_entity << " 0 " << nv << '\n';
    for (std::size_t v = 0; v < nv; ++v) os << v + 1 << '\n';
    for (std::size_t v = 0; v < nv; ++v)
      os << number(coordinate(m, v, 0)) << ' ' << number(coordinate(m, v, 1)) << ' '
         << number(coordinate(m, v, 2)) << '\n';
    os << "$EndNodes\n$Elements\n";
    os << cells_of_region.size() << ' ' << nc << " 1 " << nc << '\n';
    std::size_t tag = 1;
    for (const auto& [region, cells] : cells_of_region) {
      os << dim << ' ' << region << ' ' << gmsh_type << ' ' << cells.size() << '\n';
      for (std::size_t c : cells) {
        os << tag++;
        for (int k = 0; k < mesh::vertex_count(m.cell_types[c]); ++k) os << ' ' << m.cell(c)[k] + 1;
        os << '\n';
      }
    }
    os << "$EndElements\n";
  });
}

void write_medit(const mesh::StructureInstanceMesh& s, const std::string& path) {
  const auto& m = s.mesh.mesh;
  const int dim = m.point_dimension;
  write_atomically(path, [&](std::ostream& os) {
    os << "MeshVersionFormatted 2\nDimension " << dim << "\nVertices\n" << m.vertex_count() << '\n';
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
      for (int d = 0; d < dim; ++d) os << number(m.vertex(v)[d]) << ' ';
      os << "0\n";
    }
    os << (dim == 2 ? "Triangles\n" : "Tetrahedra\n") << m.cell_count() << '\n';
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
      for (int k = 0; k < mesh::vertex_count(m.cell_types[c]); ++k) os << m.cell(c)[k] + 1 << ' ';
      os << s.mesh.cell_region[c] << '\n';
    }
    os << "End\n";
  });
}

void write_mesh_file(const mesh::StructureInstanceMesh& m, const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".vtu") return write_vtu(m, path);
  if (ext == ".msh") return write_msh41(m, path);
  if (ext == ".mesh") return write_medit(m, path);
  throw std::invalid_argument(path + ": unknown mesh file extension '" + ext +
                              "' (use .vtu, .msh or .mesh)");
}

} // namespace symmesh::io
