/// Listing 2.1 (MESH) and Listing 2.2 (MRMESH), Eq. 2.11 and 2.12 —
/// spec/mesh-data-structures.md#listing-2-1, #listing-2-2, #eq-2-11
///
/// The compressed-row layout of Section 2.4 with the dissertation's type sizes: NUMERIC_TYPE =
/// double, ELEMENT_TYPE = 8-bit, INDEX_TYPE = 32-bit, REGION_ID_TYPE = 16-bit. Byte counts are
/// taken from the arrays (their sizes times their element sizes), so they can be compared with
/// the formulas. Coordinates are doubles: a generated mesh is not exact; conformity between
/// template instances comes from shared vertex bookkeeping (templated_mesh_svb.h).
#pragma once
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <vector>

namespace symmesh::mesh {

using NumericType = double;
using IndexType = std::int32_t;
using RegionIdType = std::uint16_t;

/// ELEMENT_TYPE: the VTK cell type numbers, so that writers need no table.
enum class ElementType : std::uint8_t { vertex = 1, line = 3, triangle = 5, tetrahedron = 10 };

/// Number of vertices of a simplex element type.
inline int vertex_count(ElementType t) {
  switch (t) {
  case ElementType::vertex:
    return 1;
  case ElementType::line:
    return 2;
  case ElementType::triangle:
    return 3;
  case ElementType::tetrahedron:
    return 4;
  }
  return 0;
}

/// Listing 2.1.
struct Mesh {
  int point_dimension = 2;
  std::vector<NumericType> vertex_coords;              ///< point_dimension per vertex
  std::vector<ElementType> cell_types;                 ///< one per cell
  std::vector<IndexType> cell_vertex_indices;          ///< concatenated vertex tuples
  std::vector<IndexType> cell_vertex_index_offsets{0}; ///< cell_count + 1 entries

  std::size_t vertex_count() const { return vertex_coords.size() / std::size_t(point_dimension); }
  std::size_t cell_count() const { return cell_types.size(); }

  IndexType add_vertex(const NumericType* x) {
    vertex_coords.insert(vertex_coords.end(), x, x + point_dimension);
    return IndexType(vertex_count() - 1);
  }
  /// \pre the vertex ids exist and their number matches the type
  void add_cell(ElementType t, const IndexType* v) {
    cell_types.push_back(t);
    cell_vertex_indices.insert(cell_vertex_indices.end(), v, v + mesh::vertex_count(t));
    cell_vertex_index_offsets.push_back(IndexType(cell_vertex_indices.size()));
  }
  const IndexType* cell(std::size_t c) const {
    return cell_vertex_indices.data() + cell_vertex_index_offsets[c];
  }
  const NumericType* vertex(std::size_t v) const {
    return vertex_coords.data() + v * std::size_t(point_dimension);
  }

  /// Bytes of the four arrays (Section 2.4 leaves out the counts as negligible).
  std::size_t bytes() const {
    return vertex_coords.size() * sizeof(NumericType) + cell_types.size() * sizeof(ElementType) +
           cell_vertex_indices.size() * sizeof(IndexType) +
           cell_vertex_index_offsets.size() * sizeof(IndexType);
  }

  /// Offsets consistent, every cell's vertex count matches its type, every index in range.
  bool is_valid(std::ostream* why = nullptr) const;
};

/// Listing 2.2.
struct MrMesh {
  Mesh mesh;
  std::vector<RegionIdType> cell_region; ///< one per cell

  std::size_t bytes() const { return mesh.bytes() + cell_region.size() * sizeof(RegionIdType); }
  bool is_valid(std::ostream* why = nullptr) const;
};

/// Eq. 2.11 as printed: |V|·8n + |C|·(7 + 4·max faces_0(C)).
std::size_t eq_2_11_bound(std::size_t vertices, std::size_t cells, int n, int max_cell_vertices);
/// Eq. 2.12 as printed: |V|·8n + |C|·(5 + 4·max faces_0(C)). The constants 7 and 5 are swapped
/// in the dissertation: a cell costs 1 type byte, 4 offset bytes and 4 per vertex index (5 + 4k)
/// in MESH, and 2 region bytes more (7 + 4k) in MRMESH (spec/mesh-data-structures.md#eq-2-11).
std::size_t eq_2_12_bound(std::size_t vertices, std::size_t cells, int n, int max_cell_vertices);

} // namespace symmesh::mesh
