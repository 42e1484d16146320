/// Listing 4.1 (TEMPLATED_MESH), Listing 4.2 (TEMPLATED_MESH_SVB) and the compact shared vertex
/// bookkeeping — spec/mesh-data-structures.md#listing-4-1, #listing-4-2, #compact-svb
///
/// A templated mesh stores each mesh template once (MESH, Listing 2.1), the rigid
/// transformations once, and per instance a transformation index and a region id. Which
/// template vertices of two instances are the same vertex of the structure instance is not
/// recomputed from coordinates: the generator knows it combinatorially and records it.
///  - Listing 4.2 (the dissertation's SVB): per instance, the (local, global) pairs of all its
///    vertices that lie on an instance interface, and the global vertices' coordinates.
///  - The compact SVB (ours): the identifications of a template boundary mapping are stored
///    once, as (from-template vertex, to-template vertex) pairs, and each identifying instance
///    pair refers to one such table. Congruent interfaces (every slice of an n-gon meets the
///    next one by the same mapping) share one table, so the cost no longer grows with the number
///    of instances times the interface size.
#pragma once
#include "symmesh/mesh/mesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <utility>
#include <vector>

namespace symmesh::mesh {

/// TRANSFORMATION: x -> A x + b, A row-major n×n.
struct Transformation {
  std::vector<NumericType> matrix;
  std::vector<NumericType> translation;

  std::size_t bytes() const { return (matrix.size() + translation.size()) * sizeof(NumericType); }
  void apply(const NumericType* x, NumericType* out) const;
};

/// MESH_TEMPLATE of Listing 4.1.
struct MeshTemplate {
  Mesh mesh;
  std::vector<IndexType> transformation_indices; ///< one per instance
  std::vector<RegionIdType> region_ids;          ///< one per instance

  std::size_t instance_count() const { return transformation_indices.size(); }
  std::size_t bytes() const {
    return mesh.bytes() + transformation_indices.size() * sizeof(IndexType) +
           region_ids.size() * sizeof(RegionIdType);
  }
};

/// TEMPLATED_MESH of Listing 4.1.
struct TemplatedMesh {
  int point_dimension = 2;
  std::vector<MeshTemplate> templates;
  std::vector<Transformation> transformations;

  std::size_t instance_count() const;
  std::size_t bytes() const;
  bool is_valid(std::ostream* why = nullptr) const;
};

/// Listing 4.2: per instance, its transformation, region and local-to-global vertex pairs.
struct MeshInstanceSvb {
  IndexType transformation_index = 0;
  RegionIdType region_id = 0;
  std::vector<std::pair<IndexType, IndexType>> local_to_global_vertex_mapping;

  std::size_t bytes() const {
    return sizeof(IndexType) + sizeof(RegionIdType) +
           local_to_global_vertex_mapping.size() * 2 * sizeof(IndexType);
  }
};

struct MeshTemplateSvb {
  Mesh mesh;
  std::vector<MeshInstanceSvb> instances;
};

/// TEMPLATED_MESH_SVB of Listing 4.2.
struct TemplatedMeshSvb {
  int point_dimension = 2;
  std::vector<MeshTemplateSvb> templates;
  std::vector<Transformation> transformations;
  std::vector<NumericType> global_vertices; ///< point_dimension per global (interface) vertex

  std::size_t global_vertex_count() const {
    return global_vertices.size() / std::size_t(point_dimension);
  }
  std::size_t bytes() const;
  bool is_valid(std::ostream* why = nullptr) const;
};

/// One table of the compact SVB: template vertex `from` of template `from_template` is template
/// vertex `to` of template `to_template` across a template boundary mapping.
struct VertexIdentificationTable {
  IndexType from_template = 0, to_template = 0;
  std::vector<std::pair<IndexType, IndexType>> pairs;

  std::size_t bytes() const { return 2 * sizeof(IndexType) + pairs.size() * 2 * sizeof(IndexType); }
};

/// The instance pair (from, to), global instance numbers in template-major order, identified
/// by table `table`.
struct InstanceIdentification {
  IndexType from_instance = 0, to_instance = 0, table = 0;
};

/// Compact SVB: a templated mesh (Listing 4.1) plus identification tables and the instance
/// pairs that use them. Only pairs that add an identification not implied by earlier pairs are
/// kept (a spanning set), so an n-gon keeps its n slice-to-slice pairs and drops the n(n-1)
/// pairs that meet only at the centre.
struct TemplatedMeshCompactSvb {
  TemplatedMesh templated;
  std::vector<VertexIdentificationTable> tables;
  std::vector<InstanceIdentification> identifications;

  std::size_t bytes() const;
  bool is_valid(std::ostream* why = nullptr) const;
};

/// A vertex of the structure instance named by an instance and a template vertex.
struct InstanceVertex {
  std::size_t instance = 0; ///< global instance number (template-major)
  IndexType vertex = 0;     ///< vertex of that instance's template
};

/// The structure instance AT(X) as a multi-region mesh, assembled from the compact SVB without
/// any coordinate comparison: identified vertices are one vertex (union-find over the
/// identifications); each instance's coordinates are its transformation applied to the template.
/// Cell data: region, template, instance (for the writers).
struct StructureInstanceMesh {
  MrMesh mesh;
  std::vector<IndexType> cell_template, cell_instance;
};
StructureInstanceMesh assemble_structure_instance(const TemplatedMeshCompactSvb& t);

/// Listing 4.2 derived from the compact SVB: global vertices are the identified classes with more
/// than one member; every instance lists its vertices in such a class.
TemplatedMeshSvb to_listing_4_2(const TemplatedMeshCompactSvb& t);

} // namespace symmesh::mesh
