// MESH/MRMESH and the templated mesh structures (spec/mesh-data-structures.md).
#include "symmesh/mesh/templated_mesh.h"
#include "symmesh/mesh/structure_instance.h"

#include <map>
#include <numeric>

namespace symmesh::mesh {

bool Mesh::is_valid(std::ostream* why) const {
  const auto fail = [&](const char* what) {
    if (why) *why << what;
    return false;
  };
  if (point_dimension < 1 || point_dimension > 3) return fail("point_dimension not in 1..3");
  if (vertex_coords.size() % std::size_t(point_dimension) != 0)
    return fail("vertex_coords is not a multiple of point_dimension");
  if (cell_vertex_index_offsets.size() != cell_types.size() + 1)
    return fail("cell_vertex_index_offsets must have cell_count + 1 entries");
  if (cell_vertex_index_offsets.front() != 0 ||
      std::size_t(cell_vertex_index_offsets.back()) != cell_vertex_indices.size())
    return fail("cell_vertex_index_offsets must start at 0 and end at the index count");
  for (std::size_t c = 0; c < cell_types.size(); ++c)
    if (cell_vertex_index_offsets[c + 1] - cell_vertex_index_offsets[c] !=
        mesh::vertex_count(cell_types[c]))
      return fail("a cell's vertex count does not match its type");
  for (IndexType v : cell_vertex_indices)
    if (v < 0 || std::size_t(v) >= vertex_count())
      return fail("a cell vertex index is out of range");
  return true;
}

bool MrMesh::is_valid(std::ostream* why) const {
  if (!mesh.is_valid(why)) return false;
  if (cell_region.size() != mesh.cell_count()) {
    if (why) *why << "cell_region must have one entry per cell";
    return false;
  }
  return true;
}

std::size_t eq_2_11_bound(std::size_t vertices, std::size_t cells, int n, int max_cell_vertices) {
  return vertices * 8 * std::size_t(n) + cells * std::size_t(7 + 4 * max_cell_vertices);
}

std::size_t eq_2_12_bound(std::size_t vertices, std::size_t cells, int n, int max_cell_vertices) {
  return vertices * 8 * std::size_t(n) + cells * std::size_t(5 + 4 * max_cell_vertices);
}

void Transformation::apply(const NumericType* x, NumericType* out) const {
  const std::size_t n = translation.size();
  for (std::size_t i = 0; i < n; ++i) {
    NumericType s = translation[i];
    for (std::size_t j = 0; j < n; ++j) s += matrix[i * n + j] * x[j];
    out[i] = s;
  }
}

std::size_t TemplatedMesh::instance_count() const {
  std::size_t n = 0;
  for (const auto& t : templates) n += t.instance_count();
  return n;
}

std::size_t TemplatedMesh::bytes() const {
  std::size_t b = 0;
  for (const auto& t : templates) b += t.bytes();
  for (const auto& f : transformations) b += f.bytes();
  return b;
}

bool TemplatedMesh::is_valid(std::ostream* why) const {
  const std::size_t n = std::size_t(point_dimension);
  for (const auto& f : transformations)
    if (f.matrix.size() != n * n || f.translation.size() != n) {
      if (why) *why << "a transformation does not have point_dimension";
      return false;
    }
  for (std::size_t i = 0; i < templates.size(); ++i) {
    const auto& t = templates[i];
    if (!t.mesh.is_valid(why)) return false;
    if (t.mesh.point_dimension != point_dimension || t.region_ids.size() != t.instance_count()) {
      if (why) *why << "template " << i << ": dimension or region ids do not match";
      return false;
    }
    for (IndexType k : t.transformation_indices)
      if (k < 0 || std::size_t(k) >= transformations.size()) {
        if (why) *why << "template " << i << ": transformation index out of range";
        return false;
      }
  }
  return true;
}

std::size_t TemplatedMeshSvb::bytes() const {
  std::size_t b = global_vertices.size() * sizeof(NumericType);
  for (const auto& t : templates) {
    b += t.mesh.bytes();
    for (const auto& i : t.instances) b += i.bytes();
  }
  for (const auto& f : transformations) b += f.bytes();
  return b;
}

bool TemplatedMeshSvb::is_valid(std::ostream* why) const {
  for (const auto& t : templates) {
    if (!t.mesh.is_valid(why)) return false;
    for (const auto& i : t.instances)
      for (auto [local, global] : i.local_to_global_vertex_mapping)
        if (local < 0 || std::size_t(local) >= t.mesh.vertex_count() || global < 0 ||
            std::size_t(global) >= global_vertex_count()) {
          if (why) *why << "a local-to-global pair is out of range";
          return false;
        }
  }
  return true;
}

std::size_t TemplatedMeshCompactSvb::bytes() const {
  std::size_t b = templated.bytes() + identifications.size() * sizeof(InstanceIdentification);
  for (const auto& t : tables) b += t.bytes();
  return b;
}

namespace {
/// Template of each global instance number and its first vertex in a flat numbering.
struct InstanceIndex {
  std::vector<std::size_t> template_of, first_vertex;
  std::size_t total_vertices = 0;

  explicit InstanceIndex(const TemplatedMesh& t) {
    for (std::size_t i = 0; i < t.templates.size(); ++i)
      for (std::size_t g = 0; g < t.templates[i].instance_count(); ++g) {
        template_of.push_back(i);
        first_vertex.push_back(total_vertices);
        total_vertices += t.templates[i].mesh.vertex_count();
      }
  }
};

} // namespace

bool TemplatedMeshCompactSvb::is_valid(std::ostream* why) const {
  if (!templated.is_valid(why)) return false;
  const InstanceIndex index(templated);
  for (const auto& table : tables) {
    const auto nt = templated.templates.size();
    if (table.from_template < 0 || std::size_t(table.from_template) >= nt ||
        table.to_template < 0 || std::size_t(table.to_template) >= nt) {
      if (why) *why << "an identification table names a template out of range";
      return false;
    }
    const auto nf = templated.templates[std::size_t(table.from_template)].mesh.vertex_count();
    const auto nto = templated.templates[std::size_t(table.to_template)].mesh.vertex_count();
    for (auto [a, b] : table.pairs)
      if (a < 0 || std::size_t(a) >= nf || b < 0 || std::size_t(b) >= nto) {
        if (why) *why << "an identification pair is out of range";
        return false;
      }
  }
  for (const auto& id : identifications) {
    const auto n = index.template_of.size();
    if (id.from_instance < 0 || std::size_t(id.from_instance) >= n || id.to_instance < 0 ||
        std::size_t(id.to_instance) >= n || id.table < 0 ||
        std::size_t(id.table) >= tables.size()) {
      if (why) *why << "an instance identification is out of range";
      return false;
    }
    const auto& table = tables[std::size_t(id.table)];
    if (index.template_of[std::size_t(id.from_instance)] != std::size_t(table.from_template) ||
        index.template_of[std::size_t(id.to_instance)] != std::size_t(table.to_template)) {
      if (why) *why << "an instance identification uses a table of other templates";
      return false;
    }
  }
  return true;
}

StructureInstanceMesh assemble_structure_instance(const TemplatedMeshCompactSvb& t) {
  const StructureInstance at(t);
  StructureInstanceMesh out;
  out.mesh.mesh.point_dimension = at.dimension();
  out.mesh.mesh.vertex_coords.reserve(at.vertex_count() * std::size_t(at.dimension()));
  at.for_each_vertex([&](const NumericType* x) { out.mesh.mesh.add_vertex(x); });
  at.for_each_cell(
      [&](const StructureInstance::Instance& in, std::size_t c, const std::array<IndexType, 4>& v) {
        out.mesh.mesh.add_cell(in.mesh_template->mesh.cell_types[c], v.data());
        out.mesh.cell_region.push_back(in.region);
        out.cell_template.push_back(IndexType(in.template_index));
        out.cell_instance.push_back(IndexType(in.index));
      });
  return out;
}

TemplatedMeshSvb to_listing_4_2(const TemplatedMeshCompactSvb& t) {
  const StructureInstance at(t);
  const auto& class_size = at.class_sizes();
  TemplatedMeshSvb out;
  out.point_dimension = t.templated.point_dimension;
  out.transformations = t.templated.transformations;
  // Global vertices: the identified classes, numbered as they first appear.
  std::vector<IndexType> global_of_class(class_size.size(), -1);
  std::vector<NumericType> x(std::size_t(out.point_dimension), 0.0);
  for (const auto& tm : t.templated.templates) {
    MeshTemplateSvb ts;
    ts.mesh = tm.mesh;
    out.templates.push_back(std::move(ts));
  }
  at.for_each_instance([&](const StructureInstance::Instance& in) {
    MeshInstanceSvb inst;
    const auto& tm = *in.mesh_template;
    inst.transformation_index = in.transformation_index;
    inst.region_id = in.region;
    for (std::size_t v = 0; v < tm.mesh.vertex_count(); ++v) {
      const IndexType c = at.class_of(in.index, IndexType(v));
      if (c < 0 || class_size[std::size_t(c)] < 2) continue;
      auto& g = global_of_class[std::size_t(c)];
      if (g < 0) {
        g = IndexType(out.global_vertex_count());
        in.transformation->apply(tm.mesh.vertex(v), x.data());
        out.global_vertices.insert(out.global_vertices.end(), x.begin(), x.end());
      }
      inst.local_to_global_vertex_mapping.emplace_back(IndexType(v), g);
    }
    out.templates[in.template_index].instances.push_back(std::move(inst));
  });
  return out;
}

} // namespace symmesh::mesh
