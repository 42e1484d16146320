// Section 5.2.1 (template cloning, merging and splitting) — spec/adaptation.md#cloning
//
// Claim: cloning a template for one of its instances, merging the clone back, and splitting a
// template along a set of its cells (every transformation copied to both parts) map templated
// meshes to templated meshes with the same structure instance, cell for cell.
// Dropped hypothesis: a split whose second part keeps only the first instance's transformation
// (not "the transformation functions of Γ_i are copied to all new mesh templates") loses the
// other instances' cells of that part.
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

template <int D>
void add(std::vector<Property>& p) {
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
