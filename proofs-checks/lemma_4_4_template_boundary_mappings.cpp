// Lemma 4.4 (Template boundary mapping properties) — spec/lemmas.md#lemma-4-4
//
// (i) For A ~ B there is a composition of mappings with B = T(A): the witness composition of the
//     relation's BFS tree is applied face by face and must land exactly on B's faces.
// (ii) For a templated mesh, 𝕋_{a,b} maps the boundary elements of X_j inside its domain onto the
//     boundary elements of X_i inside its image. Decided without the subdivision: E ⊆ dom iff
//     T_b(E) is covered by us(inst a) (exact coverage), element sets compared exactly.
// (iii) For a templated mesh, every boundary element respects every closed boundary patch of its
//     template (E ∩ P a union of faces of E; exact coverage / relative-interior tests).
// Dropping "Γ is a templated mesh": a box and its translate shifted by part of a side meet in
// part of a boundary element, and (ii) and (iii) fail.
#include "proofs-checks/bpp_generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/boundary_element_relation.h"
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/respect.h"

#include <set>

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_4_4";

template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kLemma, s);
}
using gen::picture;

template <int D>
using Bpp = core::BoundaryPatchPartition<Exact, D>;

/// (i) for every patch and its class root (and the root back to it).
template <int D>
bool related_patches_are_mapped(const Bpp<D>& b) {
  for (const auto& cls : b.classes)
    for (std::size_t p : cls)
      for (auto [from, to] : {std::pair{cls.front(), p}, std::pair{p, cls.front()}}) {
        const auto c = b.composition_between(from, to);
        std::set<std::size_t> image;
        for (std::size_t f : b.patches[from].faces) {
          core::FaceRef r{b.patches[from].template_index, f};
          for (std::size_t l : c.letters) {
            const auto next = b.step(r, l);
            if (!next) return false;
            r = *next;
          }
          if (r.t != b.patches[to].template_index) return false;
          image.insert(r.f);
        }
        if (image != std::set<std::size_t>(b.patches[to].faces.begin(), b.patches[to].faces.end()))
          return false;
      }
  return true;
}

template <int D>
using Tuple = std::vector<Point<D>>;

template <int D>
Tuple<D> sorted(Tuple<D> t) {
  std::sort(t.begin(), t.end(), core::PointLess<Exact, D>());
  return t;
}

/// bnd(X_j)|_{dom 𝕋_{a,b}} as sorted coordinate tuples in template j's frame.
template <int D>
std::set<Tuple<D>> boundary_elements_in_interface(const Structure<D>& x, core::InstanceId own,
                                                  core::InstanceId other) {
  const auto bnd = core::mesh_boundary(x.templates[own.i].mesh);
  const auto other_instance = core::instance(x, other);
  const auto other_box = core::box_of<Exact, D>(other_instance.points);
  std::set<Tuple<D>> out;
  for (const auto& e : bnd.elements) {
    auto c = bnd.coords(e);
    Tuple<D> world;
    for (const auto& p : c) world.push_back(x.tf(own)(p));
    if (!core::box_of<Exact, D>(world).overlaps(other_box)) continue;
    // Cheap necessary condition first: every vertex lies in the other instance.
    bool vertices_inside = true;
    for (const auto& p : world)
      if (!core::point_in_underlying_space(other_instance, p)) vertices_inside = false;
    if (vertices_inside && core::simplex_covered_by<Exact, D>(world, other_instance))
      out.insert(sorted<D>(c));
  }
  return out;
}

/// (ii) for every non-trivial mapping.
template <int D>
bool mappings_map_boundary_elements(const Structure<D>& x, const Bpp<D>& b) {
  for (const auto& m : b.mappings) {
    if (m.whole_boundary) continue;
    std::set<Tuple<D>> mapped;
    for (const auto& t : boundary_elements_in_interface<D>(x, m.from, m.to)) {
      Tuple<D> img;
      for (const auto& p : t) img.push_back(m.map(p));
      mapped.insert(sorted<D>(img));
    }
    if (mapped != boundary_elements_in_interface<D>(x, m.to, m.from)) return false;
  }
  return true;
}

template <int D>
Complex<D> closed_patch(const Bpp<D>& b, std::size_t p) {
  Complex<D> c;
  std::map<Point<D>, core::VertexId, core::PointLess<Exact, D>> index;
  for (const auto& s : b.patch_simplices(p)) {
    std::vector<core::VertexId> ids;
    for (const auto& q : s) {
      auto [it, fresh] = index.emplace(q, core::VertexId(c.points.size()));
      if (fresh) c.points.push_back(q);
      ids.push_back(it->second);
    }
    c.elements.push_back(core::Simplex::from_range(ids.data(), ids.data() + ids.size()));
  }
  return core::face_completion(c);
}

/// (iii) every boundary element of every template respects every closed patch of it.
template <int D>
bool boundaries_respect_patches(const Structure<D>& x, const Bpp<D>& b) {
  for (std::size_t p = 0; p < b.patches.size(); ++p) {
    const auto patch = closed_patch<D>(b, p);
    std::vector<Tuple<D>> pieces;
    for (const auto& e : patch.elements) pieces.push_back(patch.coords(e));
    const auto box = core::box_of<Exact, D>(patch.points);
    const auto bnd = core::mesh_boundary(x.templates[b.patches[p].template_index].mesh);
    for (const auto& e : bnd.elements) {
      const auto c = bnd.coords(e);
      if (!core::box_of<Exact, D>(c).overlaps(box)) continue;
      // Exact tests only against pieces whose boxes meet the face (the others cannot meet it).
      auto near = [&](const Tuple<D>& f) {
        const auto fb = core::box_of<Exact, D>(f);
        std::vector<const Tuple<D>*> out;
        for (const auto& q : pieces)
          if (fb.overlaps(core::box_of<Exact, D>(q))) out.push_back(&q);
        return out;
      };
      const bool ok = core::respects_by_faces<Exact, D>(
          c,
          [&](const auto& f) {
            for (const auto& v : f)
              if (!core::point_in_underlying_space(patch, v)) return false;
            return core::simplex_covered_by<Exact, D>(f, patch);
          },
          [&](const auto& f) {
            for (const auto* q : near(f))
              if (!core::strictly_separated<Exact, D>(f, *q) &&
                  core::relint_meets_convex<Exact, D>(f, {*q}))
                return true;
            return false;
          });
      if (!ok) return false;
    }
  }
  return true;
}

template <int D>
void mesh_conclusion(const GeneratedStructure<D>& s) {
  const auto b = core::boundary_patch_partition(s.x);
  SYMMESH_PROOF_ASSERT(mappings_map_boundary_elements<D>(s.x, b), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(core::boundary_element_relation(s.x, b.mappings).maps_onto_elements,
                       record(s), picture(s));
  SYMMESH_PROOF_ASSERT(boundaries_respect_patches<D>(s.x, b), record(s), picture(s));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma,
               "related_patches_are_mapped" + d,
               D,
               Kind::holds,
               "Lemma 4.4 (i): for every two related patches A ~ B the witness composition of "
               "mappings sends every face of A onto a face of B, and onto all of B",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *bpp_structure<D>();
                   const auto b = core::boundary_patch_partition(s.x);
                   SYMMESH_PROOF_ASSERT(related_patches_are_mapped<D>(b), record(s), picture(s));
                 });
               },
               {}});
  p.push_back(
      {kLemma, "mesh_boundaries_follow_mappings_and_patches" + d, D, Kind::holds,
       "Lemma 4.4 (ii), (iii): on templated meshes (reflections, grids, split templates, "
       "rotational slices) every mapping sends the boundary elements in its domain onto "
       "those in its image, and every template boundary respects every boundary patch",
       [] { return rc::detail::toProperty([] { mesh_conclusion<D>(*bpp_templated_mesh<D>()); }); },
       [] {
         return rc::detail::toProperty(
             [] { mesh_conclusion<D>(*shifted_translation_structure<D>()); });
       }});
  p.push_back(
      {kLemma,
       "not_a_templated_mesh" + d,
       D,
       Kind::counterexample,
       "Lemma 4.4 (ii), (iii) without 'Γ is a templated mesh': a box and its translate "
       "shifted along a side meet in part of a boundary element; the mapping does not "
       "send elements onto elements and the boundary does not respect the patches",
       [] {
         return rc::detail::toProperty([] {
           const auto s = *shifted_translation_structure<D>();
           const auto b = core::boundary_patch_partition(s.x);
           SYMMESH_PROOF_ASSERT(!mappings_map_boundary_elements<D>(s.x, b), record(s), picture(s));
           SYMMESH_PROOF_ASSERT(!boundaries_respect_patches<D>(s.x, b), record(s), picture(s));
         });
       },
       {}});
}

} // namespace

void register_lemma_4_4(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
