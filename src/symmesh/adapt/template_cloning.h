/// Section 5.2.1: template cloning, merging and splitting — spec/adaptation.md#cloning
///
/// Template management that leaves AT(Γ) unchanged cell for cell: cloning gives one instance
/// its own copy of a template (so that a later operation on it stays local, Figure 5.10),
/// merging is its inverse, splitting cuts a template along a set of its cells into two
/// templates that both carry every transformation (Figure 5.9). The exact core keeps no vertex
/// bookkeeping of its own (AT identifies exactly equal points), so nothing else has to follow.
#pragma once
#include "symmesh/adapt/template_cells.h"

#include <algorithm>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::adapt {

/// Template cloning: instance `id` moves to a new template (appended, named "<name>'") that is
/// a copy of template id.i; the other instances stay with the original.
/// \pre id names an instance, and template id.i has at least two instances (the original must
/// keep one); else std::invalid_argument
template <class FT, int D>
TemplatedStructure<FT, D> clone_template(const TemplatedStructure<FT, D>& x, InstanceId id) {
  if (id.i >= x.templates.size() || id.g >= x.instances[id.i].size())
    throw std::invalid_argument("clone_template: no instance " + core::to_string(id));
  if (x.instances[id.i].size() < 2)
    throw std::invalid_argument("clone_template: template " + std::to_string(id.i + 1) +
                                " has one instance; cloning would leave it with none");
  TemplatedStructure<FT, D> y = x;
  auto copy = x.templates[id.i];
  copy.name += "'";
  y.templates.push_back(std::move(copy));
  y.instances.push_back({x.instances[id.i][id.g]});
  y.instances[id.i].erase(y.instances[id.i].begin() + std::ptrdiff_t(id.g));
  return y;
}

/// Templates i and j are identical: the same points in the same order and the same elements.
template <class FT, int D>
bool identical_templates(const TemplatedStructure<FT, D>& x, std::size_t i, std::size_t j) {
  const auto &a = x.templates.at(i).mesh, &b = x.templates.at(j).mesh;
  return a.points == b.points && a.elements == b.elements;
}

/// Template merging, the inverse of cloning: template j's instances join template i, and
/// template j is removed (later templates move down by one).
/// \pre i != j and the two templates are identical (identical_templates); else
/// std::invalid_argument
template <class FT, int D>
TemplatedStructure<FT, D> merge_templates(const TemplatedStructure<FT, D>& x, std::size_t i,
                                          std::size_t j) {
  if (i == j || i >= x.templates.size() || j >= x.templates.size())
    throw std::invalid_argument("merge_templates: needs two distinct templates");
  if (!identical_templates(x, i, j))
    throw std::invalid_argument("merge_templates: templates " + std::to_string(i + 1) + " and " +
                                std::to_string(j + 1) + " are not identical");
  TemplatedStructure<FT, D> y = x;
  for (const auto& s : x.instances[j]) y.instances[i].push_back(s);
  y.templates.erase(y.templates.begin() + std::ptrdiff_t(j));
  y.instances.erase(y.instances.begin() + std::ptrdiff_t(j));
  return y;
}

namespace detail {
/// The mesh of some of m's cells over the points they use (renumbered in increasing old id).
template <class FT, int D>
ElementComplex<FT, D> sub_mesh(const ElementComplex<FT, D>& m, const std::vector<Simplex>& cells) {
  std::set<VertexId> used;
  for (const auto& c : cells) used.insert(c.begin(), c.end());
  std::map<VertexId, VertexId> renumber;
  std::vector<Point<FT, D>> points;
  for (VertexId v : used) {
    renumber[v] = VertexId(points.size());
    points.push_back(m.points[v]);
  }
  std::vector<Simplex> out;
  for (const auto& c : cells) {
    std::vector<VertexId> ids;
    for (VertexId v : c) ids.push_back(renumber.at(v));
    out.push_back(simplex_of(ids));
  }
  return complex_of_cells<FT, D>(std::move(points), out);
}
} // namespace detail

/// Template splitting: template i becomes the mesh of its cells with index in `part` (indices
/// into template i's cells in element order) and a new template (appended, "<name>/2") of the
/// others; both carry every transformation and region of template i.
/// \pre part is a non-empty proper subset of the cell indices; else std::invalid_argument
template <class FT, int D>
TemplatedStructure<FT, D> split_template(const TemplatedStructure<FT, D>& x, std::size_t i,
                                         const std::set<std::size_t>& part) {
  if (i >= x.templates.size()) throw std::invalid_argument("split_template: no such template");
  const auto cells = x.templates[i].mesh.cells();
  std::vector<Simplex> first, second;
  for (std::size_t c = 0; c < cells.size(); ++c)
    (part.count(c) ? first : second).push_back(cells[c]);
  if (first.empty() || second.empty() || *part.rbegin() >= cells.size())
    throw std::invalid_argument("split_template: the part must be a non-empty proper subset of "
                                "the template's " +
                                std::to_string(cells.size()) + " cells");
  TemplatedStructure<FT, D> y = x;
  auto other = x.templates[i];
  other.name += "/2";
  other.mesh = detail::sub_mesh(x.templates[i].mesh, second);
  y.templates[i].mesh = detail::sub_mesh(x.templates[i].mesh, first);
  y.templates.push_back(std::move(other));
  y.instances.push_back(x.instances[i]);
  return y;
}

} // namespace symmesh::adapt
