// Algorithm 4.1 / Definitions 4.8, 4.9: independent checks of the boundary patch partition —
// spec/boundary-patches.md#checks
//
// - The fast regularity verdict (BFS potentials per relation class) equals Definition 4.9 decided
//   by brute force over an explicit enumeration of 𝔗_X (every pair of compositions that send a
//   patch onto the same patch is compared on it).
// - Metamorphic: renumbering the templates, moving every template into its own frame
//   (X_i -> H_i(X_i), T_{i,g} -> T_{i,g} ∘ H_i^{-1}, same structure instance) or one global rigid
//   motion (T -> G ∘ T) leaves the patch counts per template, the class sizes and regularity
//   unchanged.
#include "proofs-checks/bpp_generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/boundary_patch_partition.h"

#include <map>

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kKey = "BPP_invariance";

template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kKey, s);
}
using gen::picture;

template <int D>
using Bpp = core::BoundaryPatchPartition<Exact, D>;

/// What must not change: per template the patch counts by dimension, the sorted class sizes and
/// regularity.
struct Summary {
  std::vector<std::vector<std::size_t>> counts;
  std::vector<std::size_t> class_sizes;
  bool regular = true;
  friend bool operator==(const Summary&, const Summary&) = default;
};

template <int D>
Summary summary(const Bpp<D>& b, std::size_t templates) {
  Summary s;
  for (std::size_t t = 0; t < templates; ++t) {
    std::vector<std::size_t> c;
    for (int dim = 0; dim < D; ++dim) c.push_back(b.patch_count(t, dim));
    s.counts.push_back(c);
  }
  for (const auto& c : b.classes) s.class_sizes.push_back(c.size());
  std::sort(s.class_sizes.begin(), s.class_sizes.end());
  s.regular = b.regular();
  return s;
}

template <int D>
Summary summary_of(const Structure<D>& x) {
  return summary<D>(core::boundary_patch_partition(x), x.templates.size());
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kKey,
       "regularity_agrees_with_enumeration" + d,
       D,
       Kind::holds,
       "Definition 4.9: the regularity verdict of the relation's BFS potentials equals the "
       "brute-force verdict over all of 𝔗_X (compositions deduplicated as restricted functions)",
       [] {
         return rc::detail::toProperty([] {
           const auto s = *bpp_structure<D>();
           const auto b = core::boundary_patch_partition(s.x);
           std::vector<core::RestrictedComposition<Exact, D>> all;
           try {
             all = core::enumerate_compositions(b, 4000);
           } catch (const core::CompositionLimitExceeded&) {
             RC_DISCARD("𝔗_X larger than 4000 compositions");
           }
           RC_TAG(b.regular() ? "regular" : "irregular");
           SYMMESH_PROOF_ASSERT(b.regular() == core::regular_by_enumeration(b, all), record(s),
                                picture(s));
         });
       },
       {}});
  p.push_back({kKey,
               "renumbered_templates" + d,
               D,
               Kind::holds,
               "Metamorphic: listing the templates in reverse order permutes the per-template "
               "patch counts accordingly and keeps class sizes and regularity",
               [] {
                 return rc::detail::toProperty([] {
                   auto s = *bpp_structure<D>();
                   const auto before = summary_of<D>(s.x);
                   std::reverse(s.x.templates.begin(), s.x.templates.end());
                   std::reverse(s.x.instances.begin(), s.x.instances.end());
                   auto after = summary_of<D>(s.x);
                   std::reverse(after.counts.begin(), after.counts.end());
                   SYMMESH_PROOF_ASSERT(before == after, record(s), picture(s));
                 });
               },
               {}});
  p.push_back({kKey,
               "moved_template_frames" + d,
               D,
               Kind::holds,
               "Metamorphic: X_i -> H_i(X_i) and T_{i,g} -> T_{i,g} ∘ H_i^{-1} with a random "
               "rigid H_i per template (same structure instance) keeps patch counts, class sizes "
               "and regularity",
               [] {
                 return rc::detail::toProperty([] {
                   auto s = *bpp_structure<D>();
                   const auto before = summary_of<D>(s.x);
                   for (std::size_t i = 0; i < s.x.templates.size(); ++i) {
                     const auto h = *bpp_motion<D>();
                     s.recipe += "; template " + std::to_string(i + 1) + " moved by " + h.recipe;
                     for (auto& q : s.x.templates[i].mesh.points) q = h.value(q);
                     const auto hi = h.value.inverse();
                     for (auto& inst : s.x.instances[i])
                       inst.transformation = inst.transformation * hi;
                   }
                   SYMMESH_PROOF_ASSERT(before == summary_of<D>(s.x), record(s), picture(s));
                 });
               },
               {}});
  p.push_back({kKey,
               "global_rigid_motion" + d,
               D,
               Kind::holds,
               "Metamorphic: one global rigid motion T -> G ∘ T of every instance keeps patch "
               "counts, class sizes and regularity",
               [] {
                 return rc::detail::toProperty([] {
                   auto s = *bpp_structure<D>();
                   const auto before = summary_of<D>(s.x);
                   const auto g = *bpp_motion<D>();
                   s.recipe += "; all instances moved by " + g.recipe;
                   for (auto& list : s.x.instances)
                     for (auto& inst : list) inst.transformation = g.value * inst.transformation;
                   SYMMESH_PROOF_ASSERT(before == summary_of<D>(s.x), record(s), picture(s));
                 });
               },
               {}});
}

} // namespace

void register_bpp_invariance(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
