// Lemma 4.1 (Instance interface properties) over K_m — spec/lemmas.md#lemma-4-1,
// spec/number-type.md
//
// The properties of lemma_4_1_instance_interface.cpp re-run on ROTATIONAL structures, whose
// coordinates and instance transformations lie in the real cyclotomic field K_m (symmesh::number::
// Cyclotomic; rotations of order n ∉ {1, 2, 4} are not rational): a slice template in the wedge of
// angle 2π/n (radii on both bounding rays, a zipper triangulation of the strip, the centre
// triangle, rational interior points), instanced by rot(2πi/n), i = 0..n-1, n ∈ {3, 4, 5, 6, 8,
// 10, 12, 16}, in K_m with m = lcm(4, n) (sometimes 2 or 3 times that).
// X a templated structure with mesh templates, (a, b) distinct neighbouring instances:
//  (i)   every element of interf(X, T_a, T_b) respects interf_geo(X, T_a, T_b) = us(inst_a) ∩
//        us(inst_b) (also when the radii of the two rays differ);
//  (ii)  if X is a templated mesh (equal radii), us(interf) = interf_geo;
//  (iii) if X is a templated mesh, interf = T_a(bnd(X_i) restricted to T_a^{-1}(interf_geo))
//        (Eq. 4.7), from either side.
// Counterexample: different radii on the two rays ("templated mesh" dropped: consecutive slices
// meet along differently subdivided segments): (ii) and (iii) fail on some neighbouring pair.
// The checks are those of lemma_4_1_instance_interface.cpp written generically in the number type
// (core::common_point runs CGAL's exact LP over Cyclotomic).
#include "proofs-checks/cyclotomic_generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/exact_lp.h"
#include "symmesh/core/interface_conformity.h"

#include <algorithm>

namespace symmesh::proofs {
namespace {

using namespace cyclo;
using core::Simplex;

constexpr const char* kLemma = "Lemma_4_1";

auto record(const RotationalStructure& s) {
  return rotational_failure_record(kLemma, s);
}
auto picture(const RotationalStructure& s) {
  return rotational_failure_picture(s);
}

/// The complex of one simplex given by its vertices (all faces included).
template <class FT, int D>
core::ElementComplex<FT, D> simplex_complex(const std::vector<core::Point<FT, D>>& vertices) {
  core::ElementComplex<FT, D> c;
  c.points = vertices;
  std::vector<core::VertexId> ids(vertices.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = core::VertexId(i);
  c.elements.push_back(Simplex::from_range(ids.data(), ids.data() + ids.size()));
  return core::face_completion(c);
}

/// E respects X = us(A) ∩ us(B) for face-complete conforming A, B: every face f of E has
/// f ⊆ X (covered by both) or relint(f) ∩ X = ∅ (no g ∈ A, h ∈ B with relint(f) ∩ g ∩ h ≠ ∅).
template <class FT, int D>
bool respects_intersection_of(const std::vector<core::Point<FT, D>>& e,
                              const core::ElementComplex<FT, D>& a,
                              const core::ElementComplex<FT, D>& b) {
  const auto es = simplex_complex<FT, D>(e);
  for (const auto& f : es.elements) {
    const auto fp = es.coords(f);
    if (core::simplex_covered_by<FT, D>(fp, a) && core::simplex_covered_by<FT, D>(fp, b)) continue;
    const auto fb = core::box_of<FT, D>(fp);
    for (const auto& g : a.elements) {
      const auto gp = a.coords(g);
      if (!fb.overlaps(core::box_of<FT, D>(gp))) continue;
      for (const auto& h : b.elements) {
        const auto hp = b.coords(h);
        if (!fb.overlaps(core::box_of<FT, D>(hp))) continue;
        if (core::common_point<FT, D>({{fp, true}, {gp, false}, {hp, false}}).strict_meet)
          return false;
      }
    }
  }
  return true;
}

/// (ii): us(inst_a) ∩ us(inst_b) ⊆ us(interf) by witnesses (a point of relint(E_a) ∩ relint(E_b)
/// is in us(interf) iff E_a = E_b is a common element); ⊇ is trivial.
template <class FT, int D>
bool interface_covers_geometry_interface(const core::ElementComplex<FT, D>& a,
                                         const core::ElementComplex<FT, D>& b,
                                         const core::ElementComplex<FT, D>& interf) {
  for (const auto& ea : a.elements) {
    const auto pa = a.coords(ea);
    const auto ba = core::box_of<FT, D>(pa);
    for (const auto& eb : b.elements) {
      if (ea.is_face_of(eb) || eb.is_face_of(ea)) continue;
      const auto pb = b.coords(eb);
      if (!ba.overlaps(core::box_of<FT, D>(pb))) continue;
      // the exact LP only where the relative interiors meet (separating planes decide the rest)
      if (!core::relative_interiors_meet<FT, D>(pa, pb)) continue;
      const auto cp = core::common_point<FT, D>({{pa, true}, {pb, true}});
      if (cp.strict_meet && !core::point_in_underlying_space(interf, cp.witness)) return false;
    }
  }
  return true;
}

/// The instances inst(X, id) on their own point arrays (transformed separately, not through
/// AT's vertex identification), their boxes, and the template boundaries, computed once.
template <class FT, int D>
struct SeparateInstances {
  std::vector<core::ElementComplex<FT, D>> inst;
  std::vector<core::Box<FT, D>> box;
  std::vector<core::ElementComplex<FT, D>> boundary; ///< per template
  SeparateInstances(const core::TemplatedStructure<FT, D>& x,
                    const core::StructureInstance<FT, D>& si) {
    for (const auto& t : x.templates) boundary.push_back(core::mesh_boundary(t.mesh));
    for (auto id : si.ids) {
      inst.push_back(core::instance(x, id));
      box.push_back(core::box_of<FT, D>(inst.back().points));
    }
  }
};

/// (iii)'s right-hand side: boundary elements of the template of instance a whose image under
/// T_a lies in us(inst_b) (inst_b transformed on its own point array), in AT's vertex ids.
template <class FT, int D>
std::vector<Simplex> transformed_boundary_part(const core::TemplatedStructure<FT, D>& x,
                                               const core::StructureInstance<FT, D>& si,
                                               const SeparateInstances<FT, D>& sep, std::size_t a,
                                               std::size_t b) {
  const auto id = si.ids[a];
  const auto& t = x.tf(id);
  const auto& bnd = sep.boundary[id.i];
  std::vector<Simplex> out;
  for (const auto& e : bnd.elements) {
    std::vector<core::Point<FT, D>> img;
    for (core::VertexId v : e) img.push_back(t(bnd.points[v]));
    if (!core::box_of<FT, D>(img).overlaps(sep.box[b])) continue; // cannot lie in inst_b
    if (!core::simplex_covered_by<FT, D>(img, sep.inst[b])) continue;
    std::vector<core::VertexId> g;
    for (core::VertexId v : e) g.push_back(si.vertex_map[a][v]);
    out.push_back(Simplex::from_range(g.data(), g.data() + g.size()));
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Lemma 4.1's hypothesis, asserted on every generated input (holds and counterexample alike:
/// the counterexample drops 'templated mesh', not 'templated structure'): well-formed (templates
/// are meshes) and no two instances overlap (Eq. 4.2).
void well_formed(const RotationalStructure& s) {
  SYMMESH_PROOF_ASSERT(s.x.is_well_formed(), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(!core::find_instance_overlap(s.x).has_value(), record(s), picture(s));
}

/// (i) on every neighbouring pair.
void interface_respects(const RotationalStructure& s) {
  well_formed(s);
  const auto si = core::apply_template(s.x);
  const auto pairs = core::neighbouring_instances(si);
  RC_TAG("n = " + std::to_string(s.n), s.same_radii ? "equal radii" : "different radii");
  // every two slices meet at the centre
  SYMMESH_PROOF_ASSERT(pairs.size() == std::size_t(s.n * (s.n - 1) / 2), record(s), picture(s));
  for (auto [a, b] : pairs) {
    const auto ca = si.instance_complex(a), cb = si.instance_complex(b);
    const auto interf = core::instance_interface(si, a, b);
    for (const auto& e : interf.elements)
      SYMMESH_PROOF_ASSERT((respects_intersection_of<Cyclotomic, 2>(interf.coords(e), ca, cb)),
                           record(s), picture(s));
  }
}

/// (ii) and (iii) on every neighbouring pair; asserts each if `assert_each`.
std::pair<bool, bool> templated_mesh_interfaces(const RotationalStructure& s, bool assert_each) {
  well_formed(s);
  const auto si = core::apply_template(s.x);
  const SeparateInstances<Cyclotomic, 2> sep(s.x, si);
  bool ii = true, iii = true;
  for (auto [a, b] : core::neighbouring_instances(si)) {
    const auto interf = core::instance_interface(si, a, b);
    const bool cover = interface_covers_geometry_interface<Cyclotomic, 2>(
        si.instance_complex(a), si.instance_complex(b), interf);
    const bool eq47 =
        interf.elements == transformed_boundary_part<Cyclotomic, 2>(s.x, si, sep, a, b) &&
        interf.elements == transformed_boundary_part<Cyclotomic, 2>(s.x, si, sep, b, a);
    if (assert_each) {
      SYMMESH_PROOF_ASSERT(cover, record(s), picture(s));
      SYMMESH_PROOF_ASSERT(eq47, record(s), picture(s));
    }
    ii = ii && cover;
    iii = iii && eq47;
  }
  return {ii, iii};
}

rc::Gen<RotationalStructure> any_rotational() {
  return rc::gen::exec([] { return *rotational_structure(chance(50)); });
}

} // namespace

void register_lemma_4_1_cyclotomic(std::vector<Property>& p) {
  p.push_back({kLemma,
               "cyclotomic_rotational_interface_respects_2d",
               2,
               Kind::holds,
               "Lemma 4.1 (i) over K_m: on rotational structures (a slice of angle 2π/n "
               "instanced by rot(2πi/n), equal or different radii on its two rays), every "
               "element of an instance interface respects us(inst_a) ∩ us(inst_b)",
               [] { return rc::detail::toProperty([] { interface_respects(*any_rotational()); }); },
               {}});
  p.push_back({kLemma, "cyclotomic_rotational_templated_mesh_interfaces_2d", 2, Kind::holds,
               "Lemma 4.1 (ii), (iii) over K_m: on rotational templated meshes (equal radii on "
               "both rays), us(interf) = interf_geo for every neighbouring pair, and interf "
               "equals the transformed template boundary elements lying in the geometry "
               "instance interface (Eq. 4.7), from either side",
               [] {
                 return rc::detail::toProperty(
                     [] { templated_mesh_interfaces(*rotational_structure(true), true); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { templated_mesh_interfaces(*rotational_structure(false), true); });
               }});
  p.push_back({kLemma,
               "cyclotomic_different_radii_counterexample_2d",
               2,
               Kind::counterexample,
               "Lemma 4.1 (ii), (iii) over K_m without 'templated mesh' (the two rays of the "
               "slice carry different interior radii): us(interf) != interf_geo and Eq. 4.7 "
               "fails on some neighbouring pair",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *rotational_structure(false);
                   const auto [ii, iii] = templated_mesh_interfaces(s, false);
                   SYMMESH_PROOF_ASSERT(!ii && !iii, record(s), picture(s));
                 });
               },
               {}});
}

} // namespace symmesh::proofs
