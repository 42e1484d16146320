// Lemma 4.1 (Instance interface properties) — spec/lemmas.md#lemma-4-1
//
// X a templated structure with mesh templates, (a, b) distinct neighbouring instances:
//  (i)   every element of interf(X, T_a, T_b) respects interf_geo(X, T_a, T_b) = us(inst_a) ∩
//  us(inst_b); (ii)  if X is a templated mesh, us(interf(X, T_a, T_b)) = interf_geo(X, T_a, T_b);
//  (iii) if X is a templated mesh, interf(X, T_a, ...) = T_a(bnd(X_i) restricted to
//        T_a^{-1}(interf_geo)) (Eq. 4.7).
// interf is the element-set intersection in AT (exact vertex identification); the right-hand
// sides are computed here from the template boundary and separately transformed instances.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/interface_conformity.h"

namespace symmesh::proofs {
namespace {

using namespace gen;
using core::Simplex;

constexpr const char* kLemma = "Lemma_4_1";

/// Failure records of this lemma's generated structures (see generators.h).
template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kLemma, s);
}
using gen::picture;

/// E respects X = us(A) ∩ us(B) for face-complete conforming A, B: every face f of E has
/// f ⊆ X (covered by both) or relint(f) ∩ X = ∅ (no g ∈ A, h ∈ B with relint(f) ∩ g ∩ h ≠ ∅).
template <int D>
bool respects_intersection_of(const PointSet<D>& e, const Complex<D>& a, const Complex<D>& b) {
  const auto es = simplex_complex<D>(e);
  for (const auto& f : es.elements) {
    const auto fp = es.coords(f);
    if (core::simplex_covered_by<Exact, D>(fp, a) && core::simplex_covered_by<Exact, D>(fp, b))
      continue;
    const auto fb = core::box_of<Exact, D>(fp);
    for (const auto& g : a.elements) {
      const auto gp = a.coords(g);
      if (!fb.overlaps(core::box_of<Exact, D>(gp))) continue;
      for (const auto& h : b.elements) {
        const auto hp = b.coords(h);
        if (!fb.overlaps(core::box_of<Exact, D>(hp))) continue;
        if (core::common_point<Exact, D>({{fp, true}, {gp, false}, {hp, false}}).strict_meet)
          return false;
      }
    }
  }
  return true;
}

/// (ii): us(inst_a) ∩ us(inst_b) ⊆ us(interf) by witnesses (see Lemma 2.1 iv: a point of
/// relint(E_a) ∩ relint(E_b) is in us(interf) iff E_a = E_b is a common element); ⊇ is trivial.
template <int D>
bool interface_covers_geometry_interface(const Complex<D>& a, const Complex<D>& b,
                                         const Complex<D>& interf) {
  for (const auto& ea : a.elements) {
    const auto pa = a.coords(ea);
    const auto ba = core::box_of<Exact, D>(pa);
    for (const auto& eb : b.elements) {
      // equal elements are common ones; a proper face lies in the other's relative boundary
      if (ea.is_face_of(eb) || eb.is_face_of(ea)) continue;
      const auto pb = b.coords(eb);
      if (!ba.overlaps(core::box_of<Exact, D>(pb))) continue;
      const auto cp = core::common_point<Exact, D>({{pa, true}, {pb, true}});
      if (cp.strict_meet && !core::point_in_underlying_space(interf, cp.witness)) return false;
    }
  }
  return true;
}

/// (iii)'s right-hand side: boundary elements of the template of instance a whose image under
/// T_a lies in us(inst_b) (inst_b transformed on its own point array), in AT's vertex ids.
template <int D>
std::vector<Simplex> transformed_boundary_part(const Structure<D>& x,
                                               const core::StructureInstance<Exact, D>& si,
                                               std::size_t a, std::size_t b) {
  const auto id = si.ids[a];
  const auto& t = x.tf(id);
  const auto bnd = core::mesh_boundary(x.templates[id.i].mesh);
  const auto other = core::instance(x, si.ids[b]);
  std::vector<Simplex> out;
  for (const auto& e : bnd.elements) {
    PointSet<D> img;
    for (core::VertexId v : e) img.push_back(t(bnd.points[v]));
    if (!core::simplex_covered_by<Exact, D>(img, other)) continue;
    std::vector<core::VertexId> g;
    for (core::VertexId v : e) g.push_back(si.vertex_map[a][v]);
    out.push_back(Simplex::from_range(g.data(), g.data() + g.size()));
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <int D>
void interface_respects(const GeneratedStructure<D>& s) {
  const auto si = core::apply_template(s.x);
  const auto pairs = core::neighbouring_instances(si);
  RC_TAG(pairs.empty() ? "no neighbours" : "neighbours");
  for (auto [a, b] : pairs) {
    const auto ca = si.instance_complex(a), cb = si.instance_complex(b);
    const auto interf = core::instance_interface(si, a, b);
    for (const auto& e : interf.elements)
      SYMMESH_PROOF_ASSERT(respects_intersection_of<D>(interf.coords(e), ca, cb), record(s),
                           picture(s));
  }
}

/// (ii) and (iii) on every neighbouring pair; returns false at the first failure if `check`.
template <int D>
std::pair<bool, bool> templated_mesh_interfaces(const GeneratedStructure<D>& s, bool assert_each) {
  const auto si = core::apply_template(s.x);
  bool ii = true, iii = true;
  for (auto [a, b] : core::neighbouring_instances(si)) {
    const auto interf = core::instance_interface(si, a, b);
    const bool cover = interface_covers_geometry_interface<D>(si.instance_complex(a),
                                                              si.instance_complex(b), interf);
    const bool eq47 = interf.elements == transformed_boundary_part<D>(s.x, si, a, b) &&
                      interf.elements == transformed_boundary_part<D>(s.x, si, b, a);
    if (assert_each) {
      SYMMESH_PROOF_ASSERT(cover, record(s), picture(s));
      SYMMESH_PROOF_ASSERT(eq47, record(s), picture(s));
    }
    ii = ii && cover;
    iii = iii && eq47;
  }
  return {ii, iii};
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma,
       "interface_respects_geometry_interface" + d,
       D,
       Kind::holds,
       "Lemma 4.1 (i): on templated structures (conforming or not), every element of an "
       "instance interface respects the geometry instance interface us(inst_a) ∩ us(inst_b)",
       [] {
         return rc::detail::toProperty([] { interface_respects<D>(*templated_structure<D>()); });
       },
       {}});
  p.push_back({kLemma, "templated_mesh_interfaces" + d, D, Kind::holds,
               "Lemma 4.1 (ii), (iii): on templated meshes, us(interf) = interf_geo for every "
               "neighbouring pair, and interf equals the transformed template boundary elements "
               "lying in the geometry instance interface (Eq. 4.7), from either side",
               [] {
                 return rc::detail::toProperty(
                     [] { templated_mesh_interfaces<D>(*valid_templated_mesh<D>(), true); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { templated_mesh_interfaces<D>(*figure_4_4_structure<D>(), true); });
               }});
  p.push_back({kLemma,
               "figure_4_4_counterexample" + d,
               D,
               Kind::counterexample,
               "Lemma 4.1 (ii), (iii) without 'templated mesh' (Figure 4.4: interface side split "
               "differently): us(interf) != interf_geo and Eq. 4.7 fails on some neighbouring pair",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *figure_4_4_structure<D>();
                   const auto [ii, iii] = templated_mesh_interfaces<D>(s, false);
                   SYMMESH_PROOF_ASSERT(!ii && !iii, record<D>(s), picture<D>(s));
                 });
               },
               {}});
}

} // namespace

void register_lemma_4_1(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
