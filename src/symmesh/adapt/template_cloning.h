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
#include <map>
#include <optional>
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
/// The affine map sending p[0..D] onto q[0..D], if p is affinely independent and the map is
/// rigid (A^T A = I exactly): A = Q P^{-1} with P, Q the edge vectors from p[0], q[0].
template <class FT, int D>
std::optional<core::RigidTransformation<FT, D>> rigid_map(const std::vector<Point<FT, D>>& p,
                                                          const std::vector<Point<FT, D>>& q) {
  using Mat = typename core::RigidTransformation<FT, D>::Mat;
  Mat P, Q;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) {
      P[r][c] = p[std::size_t(c + 1)][r] - p[0][r];
      Q[r][c] = q[std::size_t(c + 1)][r] - q[0][r];
    }
  // P^{-1} = adj(P) / det(P), by cofactors (D <= 3).
  const auto minor = [&](int r, int c) {
    if constexpr (D == 2) {
      return P[1 - r][1 - c];
    } else {
      int rr[2], cc[2];
      for (int k = 0, n = 0; k < 3; ++k)
        if (k != r) rr[n++] = k;
      for (int k = 0, n = 0; k < 3; ++k)
        if (k != c) cc[n++] = k;
      return P[rr[0]][cc[0]] * P[rr[1]][cc[1]] - P[rr[0]][cc[1]] * P[rr[1]][cc[0]];
    }
  };
  FT det(0);
  for (int c = 0; c < D; ++c) det += ((c % 2) ? FT(-1) : FT(1)) * P[0][c] * minor(0, c);
  if (det == 0) return std::nullopt;
  Mat inv, a;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) inv[r][c] = (((r + c) % 2) ? FT(-1) : FT(1)) * minor(c, r) / det;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) {
      a[r][c] = FT(0);
      for (int k = 0; k < D; ++k) a[r][c] += Q[r][k] * inv[k][c];
    }
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) {
      FT dot(0);
      for (int k = 0; k < D; ++k) dot += a[k][r] * a[k][c];
      if (dot != FT(r == c ? 1 : 0)) return std::nullopt;
    }
  Point<FT, D> b = q[0];
  for (int r = 0; r < D; ++r)
    for (int k = 0; k < D; ++k) b[r] -= a[r][k] * p[0][k];
  return core::RigidTransformation<FT, D>::from_matrix(a, b);
}

/// Whether r maps mesh `from` onto mesh `to`: every point onto a point, bijectively, and the
/// cells onto the cells.
template <class FT, int D>
bool maps_onto(const core::RigidTransformation<FT, D>& r, const ElementComplex<FT, D>& from,
               const ElementComplex<FT, D>& to) {
  if (from.points.size() != to.points.size()) return false;
  std::map<Point<FT, D>, VertexId, core::PointLess<FT, D>> where;
  for (std::size_t v = 0; v < to.points.size(); ++v) where.emplace(to.points[v], VertexId(v));
  std::vector<VertexId> image(from.points.size());
  std::set<VertexId> hit;
  for (std::size_t v = 0; v < from.points.size(); ++v) {
    const auto it = where.find(r(from.points[v]));
    if (it == where.end() || !hit.insert(it->second).second) return false;
    image[v] = it->second;
  }
  std::set<Simplex> cells;
  for (const auto& c : from.cells()) {
    std::vector<VertexId> ids;
    for (VertexId v : c) ids.push_back(image[v]);
    cells.insert(simplex_of(ids));
  }
  const auto target = to.cells();
  return cells == std::set<Simplex>(target.begin(), target.end());
}
} // namespace detail

/// Templates i and j are congruent (Section 5.2.1): a rigid motion R (rotation, reflection or
/// both, and a translation) maps template j's mesh onto template i's — points bijectively, cells
/// onto cells; returns it. R is fixed by one cell of j and the cell of i it goes to, so every
/// cell of i and every order of its vertices is tried for j's first cell (exactly: a candidate
/// must be rigid and map all of j onto i).
template <class FT, int D>
std::optional<core::RigidTransformation<FT, D>> congruence(const TemplatedStructure<FT, D>& x,
                                                           std::size_t i, std::size_t j) {
  const auto &to = x.templates.at(i).mesh, &from = x.templates.at(j).mesh;
  const auto from_cells = from.cells(), to_cells = to.cells();
  if (from_cells.empty() || from_cells.size() != to_cells.size() ||
      from.points.size() != to.points.size())
    return std::nullopt;
  std::vector<Point<FT, D>> p;
  for (VertexId v : from_cells[0]) p.push_back(from.points[v]);
  for (const auto& c : to_cells) {
    std::vector<VertexId> ids(c.begin(), c.end());
    std::sort(ids.begin(), ids.end());
    do {
      std::vector<Point<FT, D>> q;
      for (VertexId v : ids) q.push_back(to.points[v]);
      const auto r = detail::rigid_map<FT, D>(p, q);
      if (r && detail::maps_onto(*r, from, to)) return r;
    } while (std::next_permutation(ids.begin(), ids.end()));
  }
  return std::nullopt;
}

/// Merging congruent templates (Section 5.2.1): template j's instances join template i with
/// the transformation T_{j,g} ∘ R^{-1}, R the congruence that maps template j onto template i
/// (so T_{j,g}(X_j) = T_{j,g} R^{-1}(X_i) and AT is unchanged cell for cell); template j is
/// removed (later templates move down by one). Identical templates are the case R = I.
/// \pre i != j and the templates are congruent; else std::invalid_argument
template <class FT, int D>
TemplatedStructure<FT, D> merge_congruent_templates(const TemplatedStructure<FT, D>& x,
                                                    std::size_t i, std::size_t j) {
  if (i == j || i >= x.templates.size() || j >= x.templates.size())
    throw std::invalid_argument("merge_congruent_templates: needs two distinct templates");
  const auto r = congruence(x, i, j);
  if (!r)
    throw std::invalid_argument("merge_congruent_templates: no rigid motion maps template " +
                                std::to_string(j + 1) + " onto template " + std::to_string(i + 1));
  const auto back = r->inverse();
  TemplatedStructure<FT, D> y = x;
  for (auto spec : x.instances[j]) {
    spec.transformation = spec.transformation * back;
    y.instances[i].push_back(spec);
  }
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
