// AT(X) of a templated mesh, numbered from the compact SVB and visited instance by instance
// (spec/outputs.md#structure-instance).
#include "symmesh/mesh/structure_instance.h"
#include "symmesh/mesh/union_find.h"

#include <set>
#include <sstream>
#include <stdexcept>

namespace symmesh::mesh {

bool reverses_orientation(const Transformation& f) {
  const auto& a = f.matrix;
  double det = 0;
  if (a.size() == 4)
    det = a[0] * a[3] - a[1] * a[2];
  else if (a.size() == 9)
    det = a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
          a[2] * (a[3] * a[7] - a[4] * a[6]);
  else
    throw std::invalid_argument("reverses_orientation: the matrix is not 2x2 or 3x3");
  // A rigid map has det = ±1 exactly; its double rounding cannot move it near 0.
  return det < 0;
}

StructureInstance::StructureInstance(const TemplatedMeshCompactSvb& t) : t_(t) {
  std::ostringstream why;
  if (!t.is_valid(&why))
    throw std::invalid_argument("StructureInstance: invalid templated mesh: " + why.str());
  const auto& templates = t.templated.templates;
  // Slots: the vertices of each template that some identification table names.
  slot_.resize(templates.size());
  for (std::size_t i = 0; i < templates.size(); ++i)
    slot_[i].assign(templates[i].mesh.vertex_count(), -1);
  for (const auto& table : t.tables)
    for (auto [a, b] : table.pairs) {
      slot_[std::size_t(table.from_template)][std::size_t(a)] = 0;
      slot_[std::size_t(table.to_template)][std::size_t(b)] = 0;
    }
  std::vector<std::size_t> slots_of_template(templates.size(), 0);
  for (std::size_t i = 0; i < templates.size(); ++i)
    for (auto& s : slot_[i])
      if (s == 0) s = IndexType(slots_of_template[i]++);
  std::size_t slots = 0;
  std::set<int> cell_sizes;
  for (std::size_t i = 0; i < templates.size(); ++i) {
    const auto& tm = templates[i];
    for (std::size_t g = 0; g < tm.instance_count(); ++g) {
      template_of_.push_back(i);
      first_slot_.push_back(slots);
      slots += slots_of_template[i];
      reverses_.push_back(
          reverses_orientation(
              t.templated.transformations[std::size_t(tm.transformation_indices[g])])
              ? 1
              : 0);
      cell_count_ += tm.mesh.cell_count();
    }
    for (auto type : tm.mesh.cell_types) cell_sizes.insert(mesh::vertex_count(type));
  }
  uniform_cell_vertices_ = cell_sizes.size() == 1 ? *cell_sizes.begin() : 0;
  UnionFind uf(slots);
  for (const auto& id : t.identifications) {
    const auto& table = t.tables[std::size_t(id.table)];
    const auto& from = slot_[std::size_t(table.from_template)];
    const auto& to = slot_[std::size_t(table.to_template)];
    for (auto [a, b] : table.pairs)
      uf.unite(first_slot_[std::size_t(id.from_instance)] + std::size_t(from[std::size_t(a)]),
               first_slot_[std::size_t(id.to_instance)] + std::size_t(to[std::size_t(b)]));
  }
  // Representatives are the smallest members, so one increasing sweep names every class.
  class_of_slot_.resize(slots);
  std::size_t classes = 0;
  for (std::size_t s = 0; s < slots; ++s) {
    const std::size_t root = uf.find(s);
    class_of_slot_[s] = root == s ? IndexType(classes++) : class_of_slot_[root];
  }
  class_size_.assign(classes, 0);
  for (IndexType c : class_of_slot_) ++class_size_[std::size_t(c)];
  class_global_.assign(classes, -1);
  std::size_t next = 0;
  for (std::size_t k = 0; k < template_of_.size(); ++k) {
    const auto& s = slot_[template_of_[k]];
    for (IndexType slot : s) {
      if (slot < 0) {
        ++next;
        continue;
      }
      auto& g = class_global_[std::size_t(class_of_slot_[first_slot_[k] + std::size_t(slot)])];
      if (g < 0) g = IndexType(next++);
    }
  }
  vertex_count_ = next;
}

IndexType StructureInstance::class_of(std::size_t instance, IndexType vertex) const {
  const IndexType s = slot_[template_of_[instance]][std::size_t(vertex)];
  return s < 0 ? -1 : class_of_slot_[first_slot_[instance] + std::size_t(s)];
}

void StructureInstance::number_instance(std::size_t k, std::size_t i, std::size_t& next,
                                        std::vector<IndexType>& global,
                                        std::vector<char>& first_seen) const {
  const auto& s = slot_[i];
  global.resize(s.size());
  first_seen.assign(s.size(), 0);
  for (std::size_t v = 0; v < s.size(); ++v) {
    if (s[v] < 0) {
      global[v] = IndexType(next++);
      first_seen[v] = 1;
      continue;
    }
    // Class vertices were numbered in this same order, so a class is new exactly when its id
    // is the next one.
    const IndexType g =
        class_global_[std::size_t(class_of_slot_[first_slot_[k] + std::size_t(s[v])])];
    if (std::size_t(g) == next) {
      first_seen[v] = 1;
      ++next;
    }
    global[v] = g;
  }
}

std::size_t StructureInstance::bytes() const {
  std::size_t b = (class_of_slot_.size() + class_global_.size()) * sizeof(IndexType) +
                  class_size_.size() * sizeof(IndexType) +
                  (template_of_.size() + first_slot_.size()) * sizeof(std::size_t) +
                  reverses_.size();
  for (const auto& s : slot_) b += s.size() * sizeof(IndexType);
  return b;
}

} // namespace symmesh::mesh
