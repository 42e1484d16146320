/// The structure instance AT(X) of a templated mesh, visited instance by instance (Definition
/// 4.3, apply-template on a templated mesh) — spec/outputs.md#structure-instance
///
/// Writers and reports need AT as a plain mesh, but materialising it costs memory for the whole
/// structure instance, which is what a templated mesh saves. This view numbers AT's vertices
/// from the compact SVB alone (identified template vertices are one vertex; no coordinate is
/// compared) and hands out one instance at a time: its template, its transformation, the global
/// id of each template vertex and which of them appear for the first time. Its own memory is
/// O(interface vertices) plus one instance.
///
/// Orientation: a transformation with determinant -1 (a reflection) reverses every cell of its
/// instance, so the view gives such cells with their last two vertices swapped. Template cells
/// are positive (the generators make them so); then every cell of AT is positive: triangles
/// counter-clockwise, tetrahedra of positive volume (spec/outputs.md#orientation).
#pragma once
#include "symmesh/mesh/templated_mesh.h"

#include <array>
#include <cstddef>
#include <vector>

namespace symmesh::mesh {

/// Sign of det(A) of a rigid transformation's linear part: true for -1 (a reflection).
/// \pre the matrix is 2×2 or 3×3
bool reverses_orientation(const Transformation& f);

/// The cell's vertices in the order that is positive after the transformation.
inline std::array<IndexType, 4> oriented_cell(const Mesh& m, std::size_t c, bool reverse) {
  std::array<IndexType, 4> v{};
  const int n = mesh::vertex_count(m.cell_types[c]);
  for (int k = 0; k < n; ++k) v[std::size_t(k)] = m.cell(c)[k];
  if (reverse && n >= 3) std::swap(v[std::size_t(n - 2)], v[std::size_t(n - 1)]);
  return v;
}

class StructureInstance {
public:
  /// \pre t.is_valid()
  explicit StructureInstance(const TemplatedMeshCompactSvb& t);

  int dimension() const { return t_.templated.point_dimension; }
  std::size_t vertex_count() const { return vertex_count_; }
  std::size_t cell_count() const { return cell_count_; }
  std::size_t instance_count() const { return template_of_.size(); }
  /// Vertices per cell when all cells have one type (triangles or tetrahedra), else 0.
  int uniform_cell_vertices() const { return uniform_cell_vertices_; }
  const TemplatedMeshCompactSvb& templated() const { return t_; }

  /// One instance as the visitor sees it.
  struct Instance {
    std::size_t index = 0; ///< global instance number (template-major)
    std::size_t template_index = 0;
    const MeshTemplate* mesh_template = nullptr;
    const Transformation* transformation = nullptr;
    IndexType transformation_index = 0;
    RegionIdType region = 0;
    bool reverses = false; ///< det = -1: cells are given with two vertices swapped
    const std::vector<IndexType>* global = nullptr; ///< AT vertex id of each template vertex
    const std::vector<char>* first_seen = nullptr;  ///< 1 where that vertex is new in AT
  };

  /// Calls f(const Instance&) for every instance in order. The first-seen vertices of the
  /// instances, in order, are AT's vertices 0, 1, 2, …
  template <class F>
  void for_each_instance(F&& f) const {
    std::vector<IndexType> global;
    std::vector<char> first_seen;
    std::size_t next = 0, k = 0;
    for (std::size_t i = 0; i < t_.templated.templates.size(); ++i) {
      const auto& tm = t_.templated.templates[i];
      for (std::size_t g = 0; g < tm.instance_count(); ++g, ++k) {
        number_instance(k, i, next, global, first_seen);
        Instance in;
        in.index = k;
        in.template_index = i;
        in.mesh_template = &tm;
        in.transformation_index = tm.transformation_indices[g];
        in.transformation = &t_.templated.transformations[std::size_t(in.transformation_index)];
        in.region = tm.region_ids[g];
        in.reverses = reverses_[k] != 0;
        in.global = &global;
        in.first_seen = &first_seen;
        f(in);
      }
    }
  }

  /// Calls f(const NumericType* x) with the coordinates of AT's vertices 0, 1, 2, … in order.
  template <class F>
  void for_each_vertex(F&& f) const {
    std::vector<NumericType> x(std::size_t(dimension()), 0.0);
    for_each_instance([&](const Instance& in) {
      const Mesh& m = in.mesh_template->mesh;
      for (std::size_t v = 0; v < m.vertex_count(); ++v)
        if ((*in.first_seen)[v]) {
          in.transformation->apply(m.vertex(v), x.data());
          f(static_cast<const NumericType*>(x.data()));
        }
    });
  }

  /// Calls f(const Instance&, std::size_t template cell, const std::array<IndexType, 4>& AT
  /// vertex ids, positively oriented) for every cell of AT in order.
  template <class F>
  void for_each_cell(F&& f) const {
    for_each_instance([&](const Instance& in) {
      const Mesh& m = in.mesh_template->mesh;
      for (std::size_t c = 0; c < m.cell_count(); ++c) {
        auto v = oriented_cell(m, c, in.reverses);
        for (int q = 0; q < mesh::vertex_count(m.cell_types[c]); ++q)
          v[std::size_t(q)] = (*in.global)[std::size_t(v[std::size_t(q)])];
        f(in, c, static_cast<const std::array<IndexType, 4>&>(v));
      }
    });
  }

  /// Bytes the view holds (the interface numbering), for the memory accounting.
  std::size_t bytes() const;
  /// Number of identified vertex classes (AT vertices shared by two or more instance vertices).
  std::size_t shared_vertex_count() const { return class_global_.size(); }
  /// The identified class of vertex `vertex` of instance `instance`, or -1 when no
  /// identification table names it; classes are numbered 0, 1, … by their smallest member.
  IndexType class_of(std::size_t instance, IndexType vertex) const;
  /// Number of instance vertices in each class (>= 2 when an identification uses the class).
  const std::vector<IndexType>& class_sizes() const { return class_size_; }

private:
  void number_instance(std::size_t k, std::size_t i, std::size_t& next,
                       std::vector<IndexType>& global, std::vector<char>& first_seen) const;

  const TemplatedMeshCompactSvb& t_;
  /// Per template: each vertex's slot among the template's identified vertices, or -1.
  std::vector<std::vector<IndexType>> slot_;
  std::vector<std::size_t> template_of_, first_slot_; ///< per instance
  std::vector<char> reverses_;                        ///< per instance
  std::vector<IndexType> class_of_slot_;              ///< identified class of each instance slot
  std::vector<IndexType> class_global_;               ///< AT vertex id of each class
  std::vector<IndexType> class_size_;
  std::size_t vertex_count_ = 0, cell_count_ = 0;
  int uniform_cell_vertices_ = 0;
};

} // namespace symmesh::mesh
