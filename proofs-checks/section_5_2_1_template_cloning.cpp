// Section 5.2.1 (template cloning, merging and splitting) — spec/adaptation.md#cloning
//
// Claim: cloning a template for one of its instances, merging the clone back, and splitting a
// template along a set of its cells (every transformation copied to both parts) map templated
// meshes to templated meshes with the same structure instance, cell for cell.
// Dropped hypothesis: a split whose second part keeps only the first instance's transformation
// (not "the transformation functions of Γ_i are copied to all new mesh templates") loses the
// other instances' cells of that part.
// Claim (merging congruent templates): when a template's clone is replaced by a congruent copy
// (moved by a rigid motion M, vertices renumbered, its instance's transformation T ∘ M^{-1}),
// merge_congruent_templates finds the congruence and merges it back with the same AT; a copy
// scaled by 2 is refused. Dropped hypothesis (compose with the congruence): moving the copy's
// instances to the original template with their transformations unchanged moves their cells.
#include "proofs-checks/adaptation_support.h"
#include "proofs-checks/registry.h"
#include "symmesh/adapt/template_cloning.h"

namespace symmesh::proofs {
namespace {

using namespace gen;
using namespace adaptation;

constexpr const char* kClaim = "Section_5_2_1";

template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kClaim, s);
}
using gen::picture;

/// A random template of x with at least two instances (the valid tier instances every template
/// at least twice; the precondition discards anything else).
template <int D>
std::size_t pick_template(const Structure<D>& x) {
  const auto i = std::size_t(*rc::gen::inRange<int>(0, int(x.templates.size())));
  RC_PRE(x.instances[i].size() >= 2);
  return i;
}

/// A random non-empty proper subset of the n cell indices. \pre n >= 2
std::set<std::size_t> pick_part(std::size_t n) {
  std::set<std::size_t> part;
  const auto size = std::size_t(*rc::gen::inRange<int>(1, int(n)));
  while (part.size() < size) part.insert(std::size_t(*rc::gen::inRange<int>(0, int(n))));
  return part;
}

template <int D>
void same_structure_instance(const GeneratedStructure<D>& s, bool copy_transformations) {
  const auto& x = s.x;
  const auto at = adapt::structure_instance_cells(x);
  const std::size_t i = pick_template(x);
  const auto g = std::size_t(*rc::gen::inRange<int>(0, int(x.instances[i].size())));
  const auto cloned = adapt::clone_template(x, {i, g});
  SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(cloned), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(cloned) == at, record(s), picture(s));
  const auto merged = adapt::merge_templates(cloned, i, cloned.templates.size() - 1);
  SYMMESH_PROOF_ASSERT(merged.templates.size() == x.templates.size(), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(merged) == at, record(s), picture(s));
  const auto cells = x.templates[i].mesh.cells().size();
  RC_PRE(cells >= 2);
  auto split = adapt::split_template(x, i, pick_part(cells));
  if (!copy_transformations) split.instances.back().resize(1);
  SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(split), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(split) == at, record(s), picture(s));
}

/// x with template i's clone for instance g replaced by a congruent copy M(X_i) (M a random
/// signed permutation and a non-zero translation, so M != I), its vertices in reverse order and
/// the instance's transformation T ∘ M^{-1}: AT is unchanged. With `scale` the copy is 2 M(X_i)
/// instead (similar, not congruent).
template <int D>
Structure<D> congruent_clone(const Structure<D>& x, std::size_t i, std::size_t g, bool scale) {
  Structure<D> y = adapt::clone_template(x, {i, g});
  const std::size_t last = y.templates.size() - 1;
  std::array<int, D> perm, sign;
  for (int k = 0; k < D; ++k) perm[std::size_t(k)] = k;
  for (int k = D - 1; k > 0; --k)
    std::swap(perm[std::size_t(k)], perm[std::size_t(*rc::gen::inRange<int>(0, k + 1))]);
  for (int k = 0; k < D; ++k) sign[std::size_t(k)] = *rc::gen::element(-1, 1);
  gen::Point<D> b = core::zero_point<Exact, D>();
  for (int k = 0; k < D; ++k) b[k] = Exact(*rc::gen::inRange<int>(1, 4));
  const auto m = core::RigidTransformation<Exact, D>::signed_permutation(perm, sign, b);
  const auto& mesh = y.templates[last].mesh;
  const auto n = core::VertexId(mesh.points.size());
  std::vector<gen::Point<D>> points(mesh.points.size());
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    auto q = m(mesh.points[v]);
    if (scale)
      for (int k = 0; k < D; ++k) q[k] = Exact(2) * q[k];
    points[std::size_t(n) - 1 - v] = q;
  }
  std::vector<core::Simplex> cells;
  for (const auto& c : mesh.cells()) {
    std::vector<core::VertexId> ids;
    for (core::VertexId v : c) ids.push_back(n - 1 - v);
    cells.push_back(adapt::simplex_of(ids));
  }
  y.templates[last].mesh = adapt::complex_of_cells<Exact, D>(std::move(points), cells);
  auto& t = y.instances[last][0].transformation;
  t = t * m.inverse();
  return y;
}

template <int D>
void congruent_templates_merge(const GeneratedStructure<D>& s, bool compose) {
  const auto& x = s.x;
  const auto at = adapt::structure_instance_cells(x);
  const std::size_t i = pick_template(x);
  const auto g = std::size_t(*rc::gen::inRange<int>(0, int(x.instances[i].size())));
  const auto y = congruent_clone(x, i, g, false);
  const std::size_t last = y.templates.size() - 1;
  SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(y) == at, record(s), picture(s));
  Structure<D> merged;
  if (compose) {
    merged = adapt::merge_congruent_templates(y, i, last);
  } else { // the copy's instances join template i with their transformations unchanged
    merged = y;
    for (const auto& spec : y.instances[last]) merged.instances[i].push_back(spec);
    merged.templates.pop_back();
    merged.instances.pop_back();
  }
  SYMMESH_PROOF_ASSERT(merged.templates.size() == x.templates.size(), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(merged) == at, record(s), picture(s));
  SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(merged), record(s), picture(s));
  if (!compose) return;
  bool refused = false;
  try {
    adapt::merge_congruent_templates(congruent_clone(x, i, g, true), i, last);
  } catch (const std::invalid_argument&) {
    refused = true;
  }
  SYMMESH_PROOF_ASSERT(refused, record(s), picture(s));
}

template <int D>
void add(std::vector<Property>& p) {
  p.push_back({kClaim, "congruent_templates_merge" + dim_suffix(D), D, Kind::holds,
               "Section 5.2.1: a template's clone replaced by a congruent copy (moved by a "
               "random signed permutation and translation, renumbered) is merged back by "
               "merge_congruent_templates with the same AT, cell for cell; a scaled copy is "
               "refused",
               [] {
                 return rc::detail::toProperty(
                     [] { congruent_templates_merge<D>(*valid_templated_mesh<D>(), true); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { congruent_templates_merge<D>(*valid_templated_mesh<D>(), false); });
               }});
  p.push_back({kClaim, "clone_merge_split_keep_the_structure_instance" + dim_suffix(D), D,
               Kind::holds,
               "Section 5.2.1: cloning a template for one instance, merging the clone back and "
               "splitting a template by a random cell subset (transformations copied to both "
               "parts) give templated meshes whose AT equals the input's cell for cell",
               [] {
                 return rc::detail::toProperty(
                     [] { same_structure_instance<D>(*valid_templated_mesh<D>(), true); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { same_structure_instance<D>(*valid_templated_mesh<D>(), false); });
               }});
}

} // namespace

void register_section_5_2_1(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
