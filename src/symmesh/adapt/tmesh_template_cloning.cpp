// Section 5.2.1 on a generated templated mesh — spec/adaptation.md#tmesh-cloning
#include "symmesh/adapt/tmesh_template_cloning.h"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace symmesh::adapt {
namespace {

using mesh::IndexType;
using mesh::TemplatedMeshCompactSvb;

void require_valid(const TemplatedMeshCompactSvb& t, const char* what) {
  std::ostringstream why;
  if (!t.is_valid(&why))
    throw std::invalid_argument(std::string(what) +
                                ": the templated mesh is not valid: " + why.str());
}

/// Renumbers the instances of every identification by `global` (old -> new global number).
void renumber_instances(TemplatedMeshCompactSvb& t, const std::vector<std::size_t>& global) {
  for (auto& id : t.identifications) {
    id.from_instance = IndexType(global[std::size_t(id.from_instance)]);
    id.to_instance = IndexType(global[std::size_t(id.to_instance)]);
  }
}

/// Keeps each table once (equal templates and pairs) and each identification once, in the order
/// they first appear, and drops the tables in `droppable` that no identification uses any more
/// (a table left unused by an edit; other unused tables are the input's and stay).
void compact_tables(TemplatedMeshCompactSvb& t, const std::vector<char>& droppable) {
  std::vector<char> used(t.tables.size(), 0);
  for (const auto& id : t.identifications) used[std::size_t(id.table)] = 1;
  using Key = std::tuple<IndexType, IndexType, std::vector<std::pair<IndexType, IndexType>>>;
  std::map<Key, IndexType> first;
  std::vector<IndexType> renamed(t.tables.size(), -1);
  std::vector<mesh::VertexIdentificationTable> kept;
  for (std::size_t k = 0; k < t.tables.size(); ++k) {
    if (!used[k] && droppable[k]) continue;
    auto& table = t.tables[k];
    const auto [it, fresh] = first.emplace(Key{table.from_template, table.to_template, table.pairs},
                                           IndexType(kept.size()));
    if (fresh) kept.push_back(std::move(table));
    renamed[k] = it->second;
  }
  t.tables = std::move(kept);
  std::vector<mesh::InstanceIdentification> ids;
  std::set<std::tuple<IndexType, IndexType, IndexType>> seen;
  for (auto id : t.identifications) {
    id.table = renamed[std::size_t(id.table)];
    if (seen.insert({id.from_instance, id.to_instance, id.table}).second) ids.push_back(id);
  }
  t.identifications = std::move(ids);
}

} // namespace

ClonedInstance clone_template(TemplatedMeshCompactSvb& t, std::size_t instance) {
  require_valid(t, "clone_template");
  auto& templates = t.templated.templates;
  const std::size_t n = t.templated.instance_count();
  if (instance >= n)
    throw std::invalid_argument("clone_template: no instance " + std::to_string(instance) +
                                " (the mesh has " + std::to_string(n) + ")");
  std::size_t i = 0, k = instance;
  while (k >= templates[i].instance_count()) k -= templates[i++].instance_count();
  if (templates[i].instance_count() < 2)
    throw std::invalid_argument("clone_template: instance " + std::to_string(instance) +
                                " is the only instance of template " + std::to_string(i) +
                                "; cloning would leave the template with none");
  mesh::MeshTemplate copy;
  copy.mesh = templates[i].mesh;
  copy.transformation_indices = {templates[i].transformation_indices[k]};
  copy.region_ids = {templates[i].region_ids[k]};
  templates[i].transformation_indices.erase(templates[i].transformation_indices.begin() +
                                            std::ptrdiff_t(k));
  templates[i].region_ids.erase(templates[i].region_ids.begin() + std::ptrdiff_t(k));
  templates.push_back(std::move(copy));
  const auto clone = IndexType(templates.size() - 1);

  // Template-major numbering: the cloned instance is now the last one, the ones after it move
  // down by one.
  std::vector<std::size_t> global(n);
  for (std::size_t g = 0; g < n; ++g) global[g] = g < instance ? g : g == instance ? n - 1 : g - 1;
  // A pair that involves the cloned instance needs its table with the clone's template on that
  // side; the clone has the original's vertex numbers, so the pairs are the same.
  std::vector<char> droppable(t.tables.size(), 0);
  std::map<std::tuple<IndexType, bool, bool>, IndexType> copies;
  for (auto& id : t.identifications) {
    const bool from = std::size_t(id.from_instance) == instance;
    const bool to = std::size_t(id.to_instance) == instance;
    if (!from && !to) continue;
    droppable[std::size_t(id.table)] = 1;
    const auto [it, fresh] = copies.emplace(std::tuple{id.table, from, to}, IndexType(0));
    if (fresh) {
      auto table = t.tables[std::size_t(id.table)];
      if (from) table.from_template = clone;
      if (to) table.to_template = clone;
      t.tables.push_back(std::move(table));
      it->second = IndexType(t.tables.size() - 1);
    }
    id.table = it->second;
  }
  droppable.resize(t.tables.size(), 0);
  renumber_instances(t, global);
  compact_tables(t, droppable);
  return {std::size_t(clone), n - 1};
}

bool identical_templates(const TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j) {
  const auto &a = t.templated.templates.at(i).mesh, &b = t.templated.templates.at(j).mesh;
  return a.point_dimension == b.point_dimension && a.vertex_coords == b.vertex_coords &&
         a.cell_types == b.cell_types && a.cell_vertex_indices == b.cell_vertex_indices &&
         a.cell_vertex_index_offsets == b.cell_vertex_index_offsets;
}

namespace detail {
void merge_templates_unchecked(TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j) {
  auto& templates = t.templated.templates;
  const std::size_t n = t.templated.instance_count();
  std::vector<std::size_t> start(templates.size() + 1, 0);
  for (std::size_t p = 0; p < templates.size(); ++p)
    start[p + 1] = start[p] + templates[p].instance_count();
  // New template-major order: every template but j in turn, j's instances right after i's.
  std::vector<std::size_t> global(n);
  std::size_t next = 0;
  for (std::size_t p = 0; p < templates.size(); ++p) {
    if (p == j) continue;
    for (std::size_t g = start[p]; g < start[p + 1]; ++g) global[g] = next++;
    if (p == i)
      for (std::size_t g = start[j]; g < start[j + 1]; ++g) global[g] = next++;
  }
  auto& into = templates[i];
  const auto& from = templates[j];
  into.transformation_indices.insert(into.transformation_indices.end(),
                                     from.transformation_indices.begin(),
                                     from.transformation_indices.end());
  into.region_ids.insert(into.region_ids.end(), from.region_ids.begin(), from.region_ids.end());
  templates.erase(templates.begin() + std::ptrdiff_t(j));
  const auto rename = [&](IndexType x) {
    const auto y = std::size_t(x) == j ? i : std::size_t(x);
    return IndexType(y > j ? y - 1 : y);
  };
  for (auto& table : t.tables) {
    table.from_template = rename(table.from_template);
    table.to_template = rename(table.to_template);
  }
  renumber_instances(t, global);
  // Tables of j that equal tables of i now are kept once; nothing becomes unused.
  compact_tables(t, std::vector<char>(t.tables.size(), 0));
}
} // namespace detail

void merge_templates(TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j) {
  require_valid(t, "merge_templates");
  const auto nt = t.templated.templates.size();
  if (i == j || i >= nt || j >= nt)
    throw std::invalid_argument("merge_templates: needs two distinct templates below " +
                                std::to_string(nt) + ", got " + std::to_string(i) + " and " +
                                std::to_string(j));
  if (!identical_templates(t, i, j))
    throw std::invalid_argument("merge_templates: templates " + std::to_string(i) + " and " +
                                std::to_string(j) + " are not identical");
  detail::merge_templates_unchecked(t, i, j);
}

namespace {

/// The two parts of a template to split: the mesh of the cells that stay and of those in the
/// part, and each old vertex's number in either (-1 where the part's cells do not use it).
/// Vertices no cell uses stay.
struct SplitParts {
  mesh::Mesh stay_mesh, leave_mesh;
  std::vector<IndexType> stay, leave;
};

SplitParts split_parts(const mesh::Mesh& m, const std::vector<char>& in_part) {
  const std::size_t nv = m.vertex_count();
  std::vector<char> in_stay(nv, 0), in_leave(nv, 0);
  for (std::size_t c = 0; c < m.cell_count(); ++c)
    for (std::size_t q = 0; q < std::size_t(mesh::vertex_count(m.cell_types[c])); ++q)
      (in_part[c] ? in_leave : in_stay)[std::size_t(m.cell(c)[q])] = 1;
  SplitParts p;
  p.stay_mesh.point_dimension = p.leave_mesh.point_dimension = m.point_dimension;
  p.stay.assign(nv, -1);
  p.leave.assign(nv, -1);
  for (std::size_t v = 0; v < nv; ++v) {
    if (in_stay[v] || !in_leave[v]) p.stay[v] = p.stay_mesh.add_vertex(m.vertex(v));
    if (in_leave[v]) p.leave[v] = p.leave_mesh.add_vertex(m.vertex(v));
  }
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    const auto& to = in_part[c] ? p.leave : p.stay;
    std::vector<IndexType> cell;
    for (std::size_t q = 0; q < std::size_t(mesh::vertex_count(m.cell_types[c])); ++q)
      cell.push_back(to[std::size_t(m.cell(c)[q])]);
    (in_part[c] ? p.leave_mesh : p.stay_mesh).add_cell(m.cell_types[c], cell.data());
  }
  return p;
}

/// The cells of template i in `part`, as flags; \pre as split_template.
std::vector<char> part_flags(const TemplatedMeshCompactSvb& t, std::size_t i,
                             const std::vector<std::size_t>& part) {
  const auto nt = t.templated.templates.size();
  if (i >= nt)
    throw std::invalid_argument("split_template: no template " + std::to_string(i) +
                                " (the mesh has " + std::to_string(nt) + ")");
  const auto cells = t.templated.templates[i].mesh.cell_count();
  std::vector<char> in_part(cells, 0);
  for (const auto c : part) {
    if (c >= cells)
      throw std::invalid_argument("split_template: template " + std::to_string(i) +
                                  " has no cell " + std::to_string(c) + " (it has " +
                                  std::to_string(cells) + ")");
    in_part[c] = 1;
  }
  const auto taken = std::size_t(std::count(in_part.begin(), in_part.end(), char(1)));
  if (taken == 0 || taken == cells)
    throw std::invalid_argument("split_template: the part must be a non-empty proper subset of "
                                "template " +
                                std::to_string(i) + "'s " + std::to_string(cells) + " cells, got " +
                                std::to_string(taken));
  return in_part;
}

} // namespace

namespace detail {
std::size_t split_template(TemplatedMeshCompactSvb& t, std::size_t i,
                           const std::vector<std::size_t>& part, bool identify_cut) {
  require_valid(t, "split_template");
  const auto in_part = part_flags(t, i, part);
  auto& templates = t.templated.templates;
  auto parts = split_parts(templates[i].mesh, in_part);
  const std::size_t n = t.templated.instance_count(), count = templates[i].instance_count();
  std::size_t first = 0; // global number of template i's first instance
  for (std::size_t p = 0; p < i; ++p) first += templates[p].instance_count();
  mesh::MeshTemplate split;
  split.mesh = std::move(parts.leave_mesh);
  split.transformation_indices = templates[i].transformation_indices;
  split.region_ids = templates[i].region_ids;
  templates[i].mesh = std::move(parts.stay_mesh);
  templates.push_back(std::move(split));
  const auto ti = IndexType(i), tn = IndexType(templates.size() - 1);
  // Template-major numbering: the new part of instance g of template i is instance n + (g -
  // first), after every other instance; no other instance moves.
  const auto moved = [&](IndexType g) { return IndexType(n + (std::size_t(g) - first)); };
  // Where template vertex v is now: in both parts if it is on the cut. A pair is put into the
  // table piece of every combination of parts that holds its two vertices, so that a facet of
  // either part finds its related facets through one table, as bisection and smoothing do.
  const auto places = [&](IndexType tmpl, IndexType v) {
    std::vector<std::pair<IndexType, IndexType>> out;
    if (tmpl != ti) {
      out.emplace_back(tmpl, v);
    } else {
      if (parts.stay[std::size_t(v)] >= 0) out.emplace_back(ti, parts.stay[std::size_t(v)]);
      if (parts.leave[std::size_t(v)] >= 0) out.emplace_back(tn, parts.leave[std::size_t(v)]);
    }
    return out;
  };
  // Every table naming template i splits into pieces by the parts its pairs' vertices are in.
  const std::size_t old_tables = t.tables.size();
  std::vector<char> droppable(old_tables, 0);
  std::map<std::tuple<std::size_t, IndexType, IndexType>, IndexType> pieces;
  for (std::size_t k = 0; k < old_tables; ++k) {
    if (t.tables[k].from_template != ti && t.tables[k].to_template != ti) continue;
    droppable[k] = 1;
    const auto old = t.tables[k];
    for (const auto& [a, b] : old.pairs)
      for (const auto& [fa, va] : places(old.from_template, a))
        for (const auto& [fb, vb] : places(old.to_template, b)) {
          const auto [it, fresh] = pieces.emplace(std::tuple{k, fa, fb}, IndexType(0));
          if (fresh) {
            t.tables.push_back({fa, fb, {}});
            it->second = IndexType(t.tables.size() - 1);
          }
          t.tables[std::size_t(it->second)].pairs.emplace_back(va, vb);
        }
  }
  std::vector<mesh::InstanceIdentification> ids;
  for (const auto& id : t.identifications) {
    if (!droppable[std::size_t(id.table)]) {
      ids.push_back(id);
      continue;
    }
    for (auto it = pieces.lower_bound({std::size_t(id.table), IndexType(0), IndexType(0)});
         it != pieces.end() && std::get<0>(it->first) == std::size_t(id.table); ++it)
      ids.push_back({std::get<1>(it->first) == tn ? moved(id.from_instance) : id.from_instance,
                     std::get<2>(it->first) == tn ? moved(id.to_instance) : id.to_instance,
                     it->second});
  }
  // The cut: the vertices both parts use, the new part's number first.
  mesh::VertexIdentificationTable cut{tn, ti, {}};
  for (std::size_t v = 0; v < parts.stay.size(); ++v)
    if (parts.stay[v] >= 0 && parts.leave[v] >= 0)
      cut.pairs.emplace_back(parts.leave[v], parts.stay[v]);
  if (identify_cut && !cut.pairs.empty() && count > 0) { // no instance, nothing to identify
    t.tables.push_back(std::move(cut));
    for (std::size_t k = 0; k < count; ++k)
      ids.push_back({IndexType(n + k), IndexType(first + k), IndexType(t.tables.size() - 1)});
  }
  t.identifications = std::move(ids);
  droppable.resize(t.tables.size(), 0);
  compact_tables(t, droppable);
  return std::size_t(tn);
}
} // namespace detail

std::size_t split_template(TemplatedMeshCompactSvb& t, std::size_t i,
                           const std::vector<std::size_t>& part) {
  return detail::split_template(t, i, part, true);
}

std::size_t merge_identical_templates(TemplatedMeshCompactSvb& t) {
  require_valid(t, "merge_identical_templates");
  std::size_t merged = 0;
  for (std::size_t j = 1; j < t.templated.templates.size();) {
    std::size_t i = 0;
    while (i < j && !identical_templates(t, i, j)) ++i;
    if (i == j) {
      ++j;
      continue;
    }
    detail::merge_templates_unchecked(t, i, j);
    ++merged;
  }
  return merged;
}

} // namespace symmesh::adapt
