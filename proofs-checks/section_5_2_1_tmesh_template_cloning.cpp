// Section 5.2.1 on generated templated meshes (.tmesh) — spec/adaptation.md#tmesh-cloning
//
// Claim (generated box grids, 2D and 3D, translated or with mirrored columns): cloning the
// template of a random instance (adapt::clone_template, the identification tables following the
// instance) gives a valid templated mesh, certified conforming with the same boundary measure,
// whose AT is the input's (the same cells with the same coordinates, the same number of
// vertices) and whose two templates are identical; merge_identical_templates merges them back
// with AT unchanged again. Splitting a random template along a random non-empty proper subset of
// its cells (adapt::split_template; box grids or a block on a base slab, whose two templates
// share a table) keeps AT the same way, and bisecting every template boundary
// edge of the new part afterwards keeps AT conforming. When the clone is first changed (a
// template-interior edge bisected), the templates are no longer identical and nothing is merged.
// Dropped hypothesis (the templates are identical): merging the changed clone into the original
// anyway gives its instance the original's cells, and AT changes; splitting without identifying
// the two parts along the cut gives AT more vertices and an open cut.
// Claim (congruent merging): when the clone is moved by a random signed permutation R (its
// coordinates replaced by their images, its vertices and cells renumbered at random, its
// instance's transformation composed with R^{-1}, the tables renumbered: AT is unchanged),
// template_congruence finds R exactly and merge_congruent_templates merges the clone back with AT
// unchanged, cell for cell; a moved clone whose interior was also changed is refused. Dropped
// hypothesis (the motion): merging the moved clone as if it were identical (its instance keeps
// the transformation made for the moved coordinates) changes AT.
// Claim (congruent up to rounding): when the clone is turned by a rotation R that is no signed
// permutation (1°–89°, in 3D about (1, 2, 3); its coordinates replaced by their rounded images,
// its instance's transformation by T R^T rounded: AT is unchanged up to rounding), the exact
// search refuses it, template_congruence(t, i, j, 1e-9) finds R, and
// merge_congruent_templates(t, 1e-9) merges it back: valid, certified with the same boundary
// measure, AT's vertex count and its cells (as point sets, to 1e-9) unchanged. Dropped hypothesis
// (the templates differ by rounding and no more): a turned clone with one vertex also moved by
// 1e-6 of the diameter, merged with a tolerance of 1e-4, is merged too, and AT's cells change.
#include "proofs-checks/box_inputs.h"
#include "proofs-checks/registry.h"
#include "symmesh/adapt/tmesh_template_cloning.h"
#include "symmesh/mesh/structure_instance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::proofs {
namespace {

constexpr const char* kClaim = "Section_5_2_1";

using Cells = std::multiset<std::vector<std::array<double, 3>>>;

/// AT's cells as point sets in AT's coordinates, independent of instance and vertex numbering.
Cells structure_instance_cells(const mesh::TemplatedMeshCompactSvb& t) {
  Cells out;
  const int d = t.templated.point_dimension;
  const mesh::StructureInstance at(t);
  at.for_each_cell([&](const mesh::StructureInstance::Instance& in, std::size_t c,
                       const std::array<mesh::IndexType, 4>&) {
    const auto& m = in.mesh_template->mesh;
    std::vector<std::array<double, 3>> cell;
    for (int q = 0; q <= d; ++q) {
      std::array<double, 3> image{0, 0, 0};
      in.transformation->apply(m.vertex(std::size_t(m.cell(c)[q])), image.data());
      cell.push_back(image);
    }
    std::sort(cell.begin(), cell.end());
    out.insert(std::move(cell));
  });
  return out;
}

/// What an operation that keeps AT must keep: the certificate's boundary measure, AT's cells as
/// point sets and its vertex count.
struct StructureInstanceRecord {
  double boundary = 0;
  Cells cells;
  std::size_t vertices = 0;
};

StructureInstanceRecord record_of(const mesh::TemplatedMeshCompactSvb& t) {
  return {adapt::certify_conformity(t).boundary_measure, structure_instance_cells(t),
          mesh::StructureInstance(t).vertex_count()};
}

/// t is a valid templated mesh, certified conforming with the recorded boundary measure, whose
/// AT has the recorded cells and vertex count.
bool keeps_structure_instance(const mesh::TemplatedMeshCompactSvb& t,
                              const StructureInstanceRecord& r) {
  return t.is_valid() && adapt::certify_conformity(t, r.boundary).holds &&
         structure_instance_cells(t) == r.cells &&
         mesh::StructureInstance(t).vertex_count() == r.vertices;
}

/// The first template-interior edge of template `ti` (not on a facet of exactly one cell).
std::optional<adapt::TemplateEdge> interior_edge(const mesh::TemplatedMeshCompactSvb& t,
                                                 std::size_t ti) {
  const int d = t.templated.point_dimension;
  const auto& m = t.templated.templates[ti].mesh;
  std::set<std::pair<mesh::IndexType, mesh::IndexType>> edges, boundary;
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    const auto* v = m.cell(c);
    for (int a = 0; a <= d; ++a)
      for (int b = a + 1; b <= d; ++b) edges.insert(std::minmax(v[a], v[b]));
  }
  for (const auto& f : boxes::one_cell_facets(m, d))
    for (std::size_t a = 0; a < f.size(); ++a)
      for (std::size_t b = a + 1; b < f.size(); ++b) boundary.insert({f[a], f[b]});
  for (const auto& e : edges)
    if (!boundary.count(e)) return adapt::TemplateEdge{ti, e.first, e.second};
  return std::nullopt;
}

/// Clones the template of a random instance (box grids have one, instanced at least twice);
/// returns that template and where the clone went.
std::pair<std::size_t, adapt::ClonedInstance>
clone_random_instance(mesh::TemplatedMeshCompactSvb& t) {
  const auto instance = std::size_t(*rc::gen::inRange<int>(0, int(t.templated.instance_count())));
  std::size_t original = 0;
  for (std::size_t k = instance; k >= t.templated.templates[original].instance_count();)
    k -= t.templated.templates[original++].instance_count();
  return {original, adapt::clone_template(t, instance)};
}

void clone_and_merge(const boxes::BoxInput& g, bool change_clone, bool identical_only) {
  const std::string text = g.description();
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  auto t = g.generate();
  const auto before = record_of(t);
  const auto templates = t.templated.templates.size();
  const auto n = t.templated.instance_count();
  const auto [original, clone] = clone_random_instance(t);
  RC_TAG(t.identifications.empty() ? "no identifications" : "identifications follow");
  SYMMESH_PROOF_ASSERT(clone.template_index == templates && clone.instance == n - 1, failure,
                       no_picture);
  SYMMESH_PROOF_ASSERT(keeps_structure_instance(t, before), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::identical_templates(t, original, clone.template_index), failure,
                       no_picture);

  if (!change_clone) {
    SYMMESH_PROOF_ASSERT(adapt::merge_identical_templates(t) == 1, failure, no_picture);
    SYMMESH_PROOF_ASSERT(t.templated.templates.size() == templates, failure, no_picture);
    SYMMESH_PROOF_ASSERT(keeps_structure_instance(t, before), failure, no_picture);
    return;
  }
  const auto edge = interior_edge(t, clone.template_index);
  RC_PRE(edge.has_value());
  adapt::bisect_edges(t, {*edge});
  const auto changed = structure_instance_cells(t);
  SYMMESH_PROOF_ASSERT(changed != before.cells, failure, no_picture);
  if (identical_only)
    SYMMESH_PROOF_ASSERT(adapt::merge_identical_templates(t) == 0, failure, no_picture);
  else
    adapt::detail::merge_templates_unchecked(t, original, clone.template_index);
  SYMMESH_PROOF_ASSERT(t.is_valid(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::certify_conformity(t, before.boundary).holds, failure, no_picture);
  SYMMESH_PROOF_ASSERT(structure_instance_cells(t) == changed, failure, no_picture);
}

/// Moves template `ti` (instanced once, its instance `instance`) by the signed permutation x ->
/// (sign_k x_perm(k)): coordinates replaced by their images (exact), vertices renumbered by a
/// random permutation, cells shuffled and, when R reverses orientation, two corners swapped; the
/// instance's transformation becomes T ∘ R^{-1} (exact: a signed permutation of T's columns), the
/// tables follow the new vertex numbers. AT is unchanged.
void move_template(mesh::TemplatedMeshCompactSvb& t, std::size_t ti) {
  const int d = t.templated.point_dimension;
  auto& mt = t.templated.templates[ti];
  auto& m = mt.mesh;
  std::vector<std::vector<int>> perms;
  std::vector<int> perm(static_cast<std::size_t>(d));
  std::iota(perm.begin(), perm.end(), 0);
  do perms.push_back(perm);
  while (std::next_permutation(perm.begin(), perm.end()));
  perm = *rc::gen::elementOf(perms);
  const auto signs =
      *rc::gen::container<std::vector<bool>>(std::size_t(d), rc::gen::arbitrary<bool>());
  // det R = sign of the permutation times the product of the signs.
  int det = 1;
  for (int a = 0; a < d; ++a)
    for (int b = a + 1; b < d; ++b)
      if (perm[std::size_t(a)] > perm[std::size_t(b)]) det = -det;
  for (bool negative : signs)
    if (negative) det = -det;
  RC_TAG(det < 0 ? "R reverses orientation" : "R keeps orientation");
  const std::size_t n = m.vertex_count();
  std::vector<mesh::IndexType> rho(n);
  for (std::size_t v = 0; v < n; ++v) rho[v] = mesh::IndexType(v);
  const auto keys = *rc::gen::container<std::vector<unsigned>>(n, rc::gen::arbitrary<unsigned>());
  std::stable_sort(rho.begin(), rho.end(), [&](mesh::IndexType a, mesh::IndexType b) {
    return keys[std::size_t(a)] < keys[std::size_t(b)];
  });                                      // rho[new] = old
  std::vector<mesh::IndexType> renamed(n); // old -> new
  for (std::size_t v = 0; v < n; ++v) renamed[std::size_t(rho[v])] = mesh::IndexType(v);
  mesh::Mesh moved;
  moved.point_dimension = d;
  for (std::size_t v = 0; v < n; ++v) {
    const double* x = m.vertex(std::size_t(rho[v]));
    double y[3];
    for (int k = 0; k < d; ++k)
      y[k] = signs[std::size_t(k)] ? -x[perm[std::size_t(k)]] : x[perm[std::size_t(k)]];
    moved.add_vertex(y);
  }
  std::vector<std::size_t> order(m.cell_count());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
  std::reverse(order.begin(), order.end());
  for (const auto c : order) {
    std::vector<mesh::IndexType> v(m.cell(c), m.cell(c) + d + 1);
    for (auto& x : v) x = renamed[std::size_t(x)];
    if (det < 0) std::swap(v[0], v[1]);
    moved.add_cell(m.cell_types[c], v.data());
  }
  m = std::move(moved);
  // T ∘ R^{-1}: R^{-1} y has coordinate perm(k) equal to sign_k y_k, so column k of the new
  // matrix is sign_k times column perm(k) of T's.
  const auto& old = t.templated.transformations[std::size_t(mt.transformation_indices[0])];
  mesh::Transformation composed = old;
  for (int r = 0; r < d; ++r)
    for (int k = 0; k < d; ++k) {
      const double e = old.matrix[std::size_t(r * d + perm[std::size_t(k)])];
      composed.matrix[std::size_t(r * d + k)] = signs[std::size_t(k)] ? -e : e;
    }
  mt.transformation_indices[0] = mesh::IndexType(t.templated.transformations.size());
  t.templated.transformations.push_back(composed);
  for (auto& table : t.tables) {
    if (std::size_t(table.from_template) == ti)
      for (auto& pair : table.pairs) pair.first = renamed[std::size_t(pair.first)];
    if (std::size_t(table.to_template) == ti)
      for (auto& pair : table.pairs) pair.second = renamed[std::size_t(pair.second)];
  }
}

void merge_moved_clone(const boxes::BoxInput& g, bool change_clone, bool by_congruence) {
  const std::string text = g.description();
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  auto t = g.generate();
  const auto before = record_of(t);
  const auto templates = t.templated.templates.size();
  const auto [original, clone] = clone_random_instance(t);
  move_template(t, clone.template_index);
  SYMMESH_PROOF_ASSERT(keeps_structure_instance(t, before), failure, no_picture);
  RC_TAG(adapt::identical_templates(t, original, clone.template_index) ? "R = identity"
                                                                       : "moved clone");
  if (change_clone) {
    adapt::expand_identifications(t);
    const auto edge = interior_edge(t, clone.template_index);
    RC_PRE(edge.has_value());
    adapt::bisect_edges(t, {*edge});
    SYMMESH_PROOF_ASSERT(!adapt::template_congruence(t, original, clone.template_index), failure,
                         no_picture);
    bool refused = false;
    try {
      adapt::merge_congruent_templates(t, original, clone.template_index);
    } catch (const std::invalid_argument&) {
      refused = true;
    }
    SYMMESH_PROOF_ASSERT(refused, failure, no_picture);
    return;
  }
  SYMMESH_PROOF_ASSERT(adapt::template_congruence(t, original, clone.template_index).has_value(),
                       failure, no_picture);
  if (by_congruence)
    SYMMESH_PROOF_ASSERT(adapt::merge_congruent_templates(t) == 1, failure, no_picture);
  else
    adapt::detail::merge_templates_unchecked(t, original, clone.template_index);
  SYMMESH_PROOF_ASSERT(t.templated.templates.size() == templates, failure, no_picture);
  SYMMESH_PROOF_ASSERT(keeps_structure_instance(t, before), failure, no_picture);
}

/// AT's cells as point sets with coordinates rounded to 1e-9: equal for meshes that differ by
/// the rounding of their coordinates.
Cells structure_instance_cells_to_1e9(const mesh::TemplatedMeshCompactSvb& t) {
  Cells out;
  for (auto cell : structure_instance_cells(t)) {
    for (auto& p : cell)
      for (auto& x : p) x = std::round(x * 1e9) / 1e9;
    std::sort(cell.begin(), cell.end());
    out.insert(std::move(cell));
  }
  return out;
}

/// Turns template `ti` (instanced once) by a rotation R by `degrees` (in 3D about (1, 2, 3)):
/// coordinates R x rounded, the instance's transformation T R^T rounded; with `nudge`, one vertex
/// moved by 1e-6 of the template's extent along x too.
void turn_template(mesh::TemplatedMeshCompactSvb& t, std::size_t ti, int degrees, bool nudge) {
  const int d = t.templated.point_dimension;
  const auto r = boxes::turning_rotation(d, degrees);
  auto& mt = t.templated.templates[ti];
  auto& m = mt.mesh;
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    double* p = &m.vertex_coords[v * std::size_t(d)];
    lo = std::min(lo, p[0]), hi = std::max(hi, p[0]);
    double q[3] = {0, 0, 0};
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) q[i] += r[std::size_t(i * d + j)] * p[j];
    std::copy(q, q + d, p);
  }
  if (nudge) m.vertex_coords[0] += 1e-6 * (hi - lo);
  const auto& old = t.templated.transformations[std::size_t(mt.transformation_indices[0])];
  mesh::Transformation composed = old;
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      double e = 0; // (T R^T)_ij = sum_l T_il R_jl
      for (int l = 0; l < d; ++l)
        e += old.matrix[std::size_t(i * d + l)] * r[std::size_t(j * d + l)];
      composed.matrix[std::size_t(i * d + j)] = e;
    }
  mt.transformation_indices[0] = mesh::IndexType(t.templated.transformations.size());
  t.templated.transformations.push_back(composed);
}

void merge_turned_clone(const boxes::BoxInput& g, int degrees, bool nudge, double tolerance) {
  const std::string text = g.description() + "\n(clone turned by " + std::to_string(degrees) +
                           " degrees" + (nudge ? ", one vertex nudged" : "") + ", tolerance " +
                           std::to_string(tolerance) + ")";
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  auto t = g.generate();
  const auto templates = t.templated.templates.size();
  const auto [original, clone] = clone_random_instance(t);
  turn_template(t, clone.template_index, degrees, nudge);
  const double boundary = adapt::certify_conformity(t).boundary_measure;
  const auto cells = structure_instance_cells_to_1e9(t);
  const auto vertices = mesh::StructureInstance(t).vertex_count();
  SYMMESH_PROOF_ASSERT(!adapt::template_congruence(t, original, clone.template_index), failure,
                       no_picture);
  SYMMESH_PROOF_ASSERT(
      adapt::template_congruence(t, original, clone.template_index, tolerance).has_value(), failure,
      no_picture);
  SYMMESH_PROOF_ASSERT(adapt::merge_congruent_templates(t, tolerance) == 1, failure, no_picture);
  SYMMESH_PROOF_ASSERT(t.templated.templates.size() == templates, failure, no_picture);
  SYMMESH_PROOF_ASSERT(t.is_valid(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::certify_conformity(t, boundary).holds, failure, no_picture);
  SYMMESH_PROOF_ASSERT(mesh::StructureInstance(t).vertex_count() == vertices, failure, no_picture);
  SYMMESH_PROOF_ASSERT(structure_instance_cells_to_1e9(t) == cells, failure, no_picture);
}

/// Splits a random template of g's mesh along a random non-empty proper subset of its cells;
/// without `identify_cut`, the two parts of each instance are not identified along the cut.
void split_random_part(const boxes::BoxInput& g, bool identify_cut) {
  const std::string text = g.description();
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  auto t = g.generate();
  adapt::expand_identifications(t); // as symmesh adapt does, for the bisection below
  const auto before = record_of(t);
  const auto templates = t.templated.templates.size();
  const auto n = t.templated.instance_count();
  const auto ti = std::size_t(*rc::gen::inRange<int>(0, int(templates)));
  const auto cells = t.templated.templates[ti].mesh.cell_count();
  RC_PRE(cells >= 2);
  const auto flags = *rc::gen::container<std::vector<bool>>(cells, rc::gen::arbitrary<bool>());
  std::vector<std::size_t> part;
  for (std::size_t c = 0; c < cells; ++c)
    if (flags[c]) part.push_back(c);
  if (part.empty()) part.push_back(0);
  if (part.size() == cells) part.pop_back();
  RC_TAG(part.size() == 1 ? "one cell split off" : "several cells split off");
  RC_TAG(templates == 1 ? "one template" : "two templates");

  const auto split = identify_cut ? adapt::split_template(t, ti, part)
                                  : adapt::detail::split_template(t, ti, part, false);
  SYMMESH_PROOF_ASSERT(split == templates, failure, no_picture);
  const auto& parts = t.templated.templates;
  SYMMESH_PROOF_ASSERT(parts[split].mesh.cell_count() == part.size() &&
                           parts[ti].mesh.cell_count() == cells - part.size(),
                       failure, no_picture);
  SYMMESH_PROOF_ASSERT(t.templated.instance_count() == n + parts[ti].instance_count(), failure,
                       no_picture);
  SYMMESH_PROOF_ASSERT(keeps_structure_instance(t, before), failure, no_picture);
  // The new part can be changed alone: bisecting every edge of its template boundary (with the
  // related edges, found through one table each) keeps AT conforming.
  const int d = t.templated.point_dimension;
  std::set<std::pair<mesh::IndexType, mesh::IndexType>> edges;
  for (const auto& f : boxes::one_cell_facets(parts[split].mesh, d))
    for (std::size_t a = 0; a < f.size(); ++a)
      for (std::size_t b = a + 1; b < f.size(); ++b) edges.insert(std::minmax(f[a], f[b]));
  std::vector<adapt::TemplateEdge> bisect;
  for (const auto& [a, b] : edges) bisect.push_back({split, a, b});
  adapt::bisect_edges(t, bisect);
  SYMMESH_PROOF_ASSERT(t.is_valid(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::certify_conformity(t, before.boundary).holds, failure, no_picture);
}

/// A box grid (one template instanced by translations or mirrors, tables from the template to
/// itself) or a block on a base slab (two templates instanced once, a table between them that a
/// split of either cuts into pieces).
rc::Gen<boxes::BoxInput> split_input(int d) {
  return rc::gen::oneOf(boxes::box_grid(d), boxes::block_on_base(d));
}

} // namespace

void register_section_5_2_1_tmesh(std::vector<Property>& p) {
  // Clone-then-merge claims on box grids: `check(g, changed, checked)` with a random changed flag
  // holds; merged unchecked (the dropped hypothesis), the clone changed or not as `dropped`
  // says, it must fail.
  const auto on_box_grids = [&p](const std::string& name, const std::string& text,
                                 void (*check)(const boxes::BoxInput&, bool, bool), bool dropped) {
    for (int d : {2, 3})
      p.push_back({kClaim, name + "_" + std::to_string(d) + "d", d, Kind::holds, text,
                   [d, check] {
                     return rc::detail::toProperty([d, check] {
                       check(*boxes::box_grid(d), *rc::gen::arbitrary<bool>(), true);
                     });
                   },
                   [d, check, dropped] {
                     return rc::detail::toProperty(
                         [d, check, dropped] { check(*boxes::box_grid(d), dropped, false); });
                   }});
  };
  on_box_grids("tmesh_clone_merge_keep_the_structure_instance",
               "Section 5.2.1 on generated box grids: cloning a random instance's template "
               "(tables following it) and merging identical templates back keep AT, cell for "
               "cell, certified; a clone changed inside is not merged",
               clone_and_merge, true);
  on_box_grids("tmesh_merge_congruent_keeps_the_structure_instance",
               "Section 5.2.1 on generated box grids: a clone moved by a random signed "
               "permutation (renumbered, its instance's transformation composed with the "
               "inverse) is found congruent exactly and merged back with AT unchanged, cell for "
               "cell, certified; a moved clone changed inside is refused",
               merge_moved_clone, false);
  for (int d : {2, 3})
    p.push_back({kClaim,
                 "tmesh_merge_congruent_to_rounding_keeps_the_structure_instance_" +
                     std::to_string(d) + "d",
                 d, Kind::holds,
                 "Section 5.2.1 on generated box grids: a clone turned by a rotation that is no "
                 "signed permutation (coordinates and transformation rounded) is refused by the "
                 "exact search, found congruent up to 1e-9 of its diameter and merged back with AT "
                 "unchanged to rounding, certified",
                 [d] {
                   return rc::detail::toProperty([d] {
                     merge_turned_clone(*boxes::box_grid(d), *rc::gen::inRange(1, 90), false, 1e-9);
                   });
                 },
                 [d] {
                   return rc::detail::toProperty([d] {
                     merge_turned_clone(*boxes::box_grid(d), *rc::gen::inRange(1, 90), true, 1e-4);
                   });
                 }});
  for (int d : {2, 3})
    p.push_back(
        {kClaim, "tmesh_split_keeps_the_structure_instance_" + std::to_string(d) + "d", d,
         Kind::holds,
         "Section 5.2.1 on generated box grids and a block on a base slab (two "
         "templates, a table between them): splitting a random template along a "
         "random cell subset (new template instanced like the old, parts identified "
         "along the cut, tables split by part) keeps AT, cell for cell and vertex for "
         "vertex, certified",
         [d] { return rc::detail::toProperty([d] { split_random_part(*split_input(d), true); }); },
         [d] {
           return rc::detail::toProperty([d] { split_random_part(*split_input(d), false); });
         }});
}

} // namespace symmesh::proofs
