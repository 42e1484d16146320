// Algorithm 6.2 and the reflective boundary patches of Section 6.2 against Algorithm 4.1 —
// spec/boundary-patches.md#special-cases
//
// Two code paths compute the facet patches of the same structure: the general one composes
// template boundary mappings (boundary_patch_partition), the special ones only use the symmetry
// (traces of all regions on the mirror line / on the first slice ray, rotated onto the second).
// They must give the same partition of every template boundary into facet patches.
#include "proofs-checks/bpp_generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/symmetric_boundary_patches.h"

#include <set>

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kKey = "Algorithm_6_2";

auto record(const GeneratedStructure<2>& s) {
  return structure_failure_record<2>(kKey, s);
}
using gen::picture;

using EdgeSets = std::set<std::set<std::size_t>>;

/// Per template, the facet patches as sets of subdivision edges.
std::vector<EdgeSets> general_facet_patches(const core::BoundaryPatchPartition<Exact, 2>& b) {
  std::vector<EdgeSets> out(b.subdivisions.size());
  for (const auto& p : b.patches) {
    if (p.dimension != 1) continue;
    std::set<std::size_t> edges;
    for (std::size_t f : p.faces)
      if (b.subdivisions[p.template_index].faces[f].dimension == 1) edges.insert(f);
    out[p.template_index].insert(edges);
  }
  return out;
}

/// The special patches as sets of the same subdivision edges (an edge belongs to a patch when it
/// lies on one of the patch's segments); empty optional if some edge is in none or in two.
std::optional<std::vector<EdgeSets>>
special_facet_patches(const core::BoundaryPatchPartition<Exact, 2>& b,
                      const std::vector<core::SymmetryPatch<Exact>>& special) {
  std::vector<EdgeSets> out(b.subdivisions.size());
  std::vector<std::map<std::size_t, int>> owners(b.subdivisions.size());
  for (const auto& sp : special) {
    const auto& sub = b.subdivisions[sp.template_index];
    std::set<std::size_t> edges;
    for (std::size_t f = 0; f < sub.faces.size(); ++f) {
      if (sub.faces[f].dimension != 1) continue;
      const auto& u = sub.points[sub.faces[f].vertices[0]];
      const auto& v = sub.points[sub.faces[f].vertices[1]];
      for (const auto& s : sp.segments)
        if (core::detail::on_closed_segment<Exact>(s, u) &&
            core::detail::on_closed_segment<Exact>(s, v)) {
          edges.insert(f);
          ++owners[sp.template_index][f];
          break;
        }
    }
    out[sp.template_index].insert(edges);
  }
  for (std::size_t t = 0; t < b.subdivisions.size(); ++t)
    for (std::size_t f = 0; f < b.subdivisions[t].faces.size(); ++f)
      if (b.subdivisions[t].faces[f].dimension == 1 && owners[t][f] != 1) return std::nullopt;
  return out;
}

bool agree(const GeneratedStructure<2>& s, const std::vector<core::SymmetryPatch<Exact>>& special) {
  const auto b = core::boundary_patch_partition(s.x);
  const auto sp = special_facet_patches(b, special);
  return sp && *sp == general_facet_patches(b);
}

/// Facet patches from direct-neighbour labels: connected (through the closure relation) unions of
/// faces with equal labels, as sets of (D-1)-faces per template.
template <int D>
bool direct_labels_agree(const GeneratedStructure<D>& s) {
  const auto b = core::boundary_patch_partition(s.x);
  const auto labels = core::direct_neighbour_labels<Exact, D>(s.x, b.subdivisions);
  for (std::size_t t = 0; t < b.subdivisions.size(); ++t) {
    const auto& sub = b.subdivisions[t];
    std::vector<std::size_t> comp(sub.faces.size());
    for (std::size_t f = 0; f < comp.size(); ++f) comp[f] = f;
    auto find = [&](std::size_t k) {
      while (comp[k] != k) k = comp[k] = comp[comp[k]];
      return k;
    };
    for (std::size_t f = 0; f < comp.size(); ++f)
      for (std::size_t g : sub.faces[f].closure)
        if (labels[t][f] == labels[t][g]) comp[find(f)] = find(g);
    std::map<std::size_t, std::set<std::size_t>> special;
    for (std::size_t f = 0; f < comp.size(); ++f)
      if (sub.faces[f].dimension == D - 1) special[find(f)].insert(f);
    std::set<std::set<std::size_t>> a, g;
    for (auto& [root, faces] : special) a.insert(faces);
    for (const auto& p : b.patches)
      if (p.template_index == t && p.dimension == D - 1) {
        std::set<std::size_t> faces;
        for (std::size_t f : p.faces)
          if (sub.faces[f].dimension == D - 1) faces.insert(f);
        g.insert(faces);
      }
    if (a != g) return false;
  }
  return true;
}

template <int D>
void add_direct(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kKey,
               "direct_neighbours_agree_with_algorithm_4_1" + d,
               D,
               Kind::holds,
               "Sections 6.2-6.3: on reflective, orthogonal-reflective and rotational structures "
               "(one symmetry group for all templates) the facet patches are the connected "
               "regions of equal direct-neighbour sets, as Algorithm 4.1 finds with compositions",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s =
                       *rc::gen::oneOf(reflective_structure<D>(), rotational_slice_structure<D>(),
                                       valid_templated_mesh<D>());
                   if (!core::instanced_by_symmetry_group<Exact, D>(s.x))
                     RC_DISCARD("templates not instanced by one symmetry group");
                   RC_TAG(s.x.instances[0].size() == 2 ? "reflection" : "group");
                   SYMMESH_PROOF_ASSERT(direct_labels_agree<D>(s),
                                        structure_failure_record<D>(kKey, s), gen::picture<D>(s));
                 });
               },
               {}});
}

void add(std::vector<Property>& p) {
  p.push_back({kKey,
               "rotational_slice_agrees_with_algorithm_4_1_2d",
               2,
               Kind::holds,
               "Algorithm 6.2 (traces of all regions on the first slice ray, rotated onto the "
               "second; rest cut at intra-slice region interfaces) gives the same facet patches "
               "as Algorithm 4.1 on one- and two-region order-4 rotational slices",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *rotational_slice_structure<2>();
                   const auto special = core::rotational_boundary_patches<Exact>(
                       s.x, Point<2>{{Exact(1), Exact(-1)}});
                   SYMMESH_PROOF_ASSERT(agree(s, special), record(s), picture(s));
                 });
               },
               {}});
  p.push_back({kKey,
               "reflective_agrees_with_algorithm_4_1_2d",
               2,
               Kind::holds,
               "Section 6.2: the mirror line cut at the traces of all copies, plus the rest of "
               "each template boundary (cut at intra-side region interfaces), gives the same "
               "facet patches as Algorithm 4.1 on reflective structures (also split into several "
               "templates and moved by a global rigid motion)",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s =
                       *rc::gen::oneOf(reflective_structure<2>(), valid_templated_mesh<2>());
                   std::vector<core::SymmetryPatch<Exact>> special;
                   try {
                     special = core::reflective_boundary_patches<Exact>(s.x);
                   } catch (const std::invalid_argument&) {
                     RC_DISCARD("not a reflective structure");
                   }
                   SYMMESH_PROOF_ASSERT(agree(s, special), record(s), picture(s));
                 });
               },
               {}});
}

} // namespace

void register_algorithm_6_2(std::vector<Property>& p) {
  add(p);
  add_direct<2>(p);
  add_direct<3>(p);
}

} // namespace symmesh::proofs
