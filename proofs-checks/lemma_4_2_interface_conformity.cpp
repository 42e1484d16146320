// Lemma 4.2 (Interface conformity) — spec/lemmas.md#lemma-4-2
//
// Γ a templated structure with mesh templates. If for all neighbouring instances
//  (i)  us(interf(Γ, T_a, T_b)) = interf_geo(Γ, T_a, T_b) and
//  (ii) T_a(IP_{a,b}) = T_b(IP_{b,a}),
// then AT(Γ) is conforming (Γ is a templated mesh).
//
// The core implements (i)–(ii) as a checker (core::check_interface_conformity); the conclusion
// is decided independently by the direct conformity test of AT (core::find_nonconformity over
// all elements of the structure instance). Both must agree: the lemma gives "checker ⇒ direct",
// its converse (AT conforming ⇒ (i), (ii) for structures obeying Eq. 4.2) gives the other way.
#include "proofs-checks/generators.h"
#include "proofs-checks/line_mesh_cases.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/interface_conformity.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_4_2";

/// Failure records of this lemma's generated structures (see generators.h).
template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kLemma, s);
}
using gen::picture;

/// The conclusion: AT(Γ) is conforming (that this makes it a multi-region mesh is checked in
/// at_multi_region_equivalence.cpp).
template <int D>
void conclusion(const GeneratedStructure<D>& s, const core::StructureInstance<Exact, D>& si) {
  SYMMESH_PROOF_ASSERT(core::structure_instance_conforming(si), record(s), picture(s));
}

/// holds: the valid tier satisfies (i) and (ii) on every neighbouring pair by construction
/// (Lemma 6.1 / 6.2, identical opposite sides, splitting a conforming mesh); the conclusion must
/// follow.
template <int D>
void sufficiency(const GeneratedStructure<D>& s) {
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  RC_TAG(v.pairs_checked > 0 ? "has neighbouring instances" : "no neighbours");
  SYMMESH_PROOF_ASSERT(v.holds, record(s), picture(s)); // the generator's promise
  conclusion<D>(s, si);
}

template <int D>
void conclusion_only(const GeneratedStructure<D>& s) {
  conclusion<D>(s, core::apply_template(s.x));
}

/// The checker and the direct test agree on templated structures (Eq. 4.2 holds); a negative
/// verdict names a genuinely neighbouring pair and condition 1 or 2.
template <int D>
void checker_agrees(const GeneratedStructure<D>& s) {
  SYMMESH_PROOF_ASSERT(!core::find_instance_overlap(s.x).has_value(), record(s), picture(s));
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  const bool direct = core::structure_instance_conforming(si);
  RC_TAG(direct ? "AT conforming" : "AT not conforming");
  SYMMESH_PROOF_ASSERT(v.holds == direct, record(s), picture(s));
  if (!v.holds) {
    const auto a = si.index_of(v.a), b = si.index_of(v.b);
    // Spec note: with exact vertex identification (i) alone decides a pair's conformity, so
    // (ii) never fails where (i) holds; the first failing condition is always (i).
    SYMMESH_PROOF_ASSERT(v.condition == 1, record(s), picture(s));
    SYMMESH_PROOF_ASSERT(a != b && core::geometry_interface_nonempty(si, a, b), record(s),
                         picture(s));
  }
}

/// On every input (Eq. 4.2 possibly violated) the checker is sound: it never certifies a
/// non-conforming AT. Where Eq. 4.2 holds it also agrees with the direct test.
template <int D>
void checker_sound(const GeneratedStructure<D>& s) {
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  const bool direct = core::structure_instance_conforming(si);
  const bool structure = !core::find_instance_overlap(s.x).has_value();
  RC_TAG(structure ? "templated structure" : "instances overlap");
  SYMMESH_PROOF_ASSERT(!v.holds || direct, record(s), picture(s));
  if (structure) SYMMESH_PROOF_ASSERT(v.holds == direct, record(s), picture(s));
}

/// Figure 4.4: the interface side (face) is split differently in the two instances: (i) fails
/// on that pair and AT is not conforming.
template <int D>
void figure_4_4(const GeneratedStructure<D>& s) {
  const auto si = core::apply_template(s.x);
  const auto v = core::check_interface_conformity(s.x, si);
  SYMMESH_PROOF_ASSERT(!v.holds && v.condition == 1, record(s), picture(s));
  SYMMESH_PROOF_ASSERT(!core::structure_instance_conforming(si), record(s), picture(s));
}

/// spec/lemmas.md#lemma-4-2-boundary: with Eq. 4.2, Lemma 4.2 on the boundary complexes
/// (what `symmesh generate` certifies with) gives the verdict of the direct check of AT(Γ).
template <int D>
void reduction_equals_direct(const GeneratedStructure<D>& s) {
  const auto v = core::check_interface_conformity_on_boundaries(s.x);
  const bool direct = core::structure_instance_conforming(core::apply_template(s.x));
  RC_TAG(direct ? "AT conforming" : "AT not conforming");
  SYMMESH_PROOF_ASSERT(v.holds == direct, record(s), picture(s));
}

template <int D>
void boundary_reduction_agrees(const GeneratedStructure<D>& s) {
  SYMMESH_PROOF_ASSERT(!core::find_instance_overlap(s.x).has_value(), record(s), picture(s));
  reduction_equals_direct<D>(s);
}

/// Eq. 4.2 dropped: a triangulation and a small simplex strictly inside one of its cells (both
/// instanced by the identity). The boundaries do not meet, so the reduction certifies, while
/// AT(Γ) is not conforming.
template <int D>
rc::Gen<GeneratedStructure<D>> simplex_inside_a_cell() {
  return rc::gen::exec([] {
    const auto c = *rc::gen::suchThat(triangulation<D>(), [](const Described<Complex<D>>& t) {
      return t.value.cell_dimension() == D;
    });
    const auto& m = c.value;
    core::Simplex cell{};
    for (const auto& e : m.elements)
      if (e.dim() == D) {
        cell = e;
        break;
      }
    const auto corners = m.coords(cell);
    Point<D> centroid;
    for (int d = 0; d < D; ++d) {
      Exact sum = 0;
      for (const auto& q : corners) sum += q[d];
      centroid[d] = sum / Exact(D + 1);
    }
    PointSet<D> inner;
    for (const auto& q : corners) {
      Point<D> r;
      for (int d = 0; d < D; ++d) r[d] = centroid[d] + (q[d] - centroid[d]) / Exact(4);
      inner.push_back(r);
    }
    GeneratedStructure<D> s;
    s.x.templates.push_back({"mesh", core::TemplateKind::mesh, m});
    s.x.templates.push_back({"inner simplex", core::TemplateKind::mesh, simplex_complex<D>(inner)});
    s.x.instances = {{core::InstanceSpec<Exact, D>{}}, {core::InstanceSpec<Exact, D>{}}};
    s.recipe = "a simplex shrunk by 1/4 inside a cell of " + c.recipe;
    return s;
  });
}

template <int D>
void boundary_reduction_without_eq_4_2(const GeneratedStructure<D>& s) {
  SYMMESH_PROOF_ASSERT(core::check_interface_conformity_on_boundaries(s.x).holds, record(s),
                       picture(s));
  SYMMESH_PROOF_ASSERT(!core::structure_instance_conforming(core::apply_template(s.x)), record(s),
                       picture(s));
}

/// spec/lemmas.md#lemma-4-2-condition-ii: the interface part of a pair in both directions, by
/// membership (what the checker computes) and by exact containment (the definition).
template <int D>
struct InterfaceParts {
  std::vector<core::Simplex> members, contained;
};

template <int D>
std::vector<InterfaceParts<D>> interface_parts(const GeneratedStructure<D>& s,
                                               const core::StructureInstance<Exact, D>& si,
                                               std::size_t a, std::size_t b) {
  const auto view = [&](std::size_t k) {
    return core::instance_view(si, k, core::mesh_boundary(s.x.templates[si.ids[k].i].mesh));
  };
  const auto va = view(a), vb = view(b);
  return {{core::detail::interface_part_of_members(va, vb),
           core::transformed_interface_part(s.x, si, a, b)},
          {core::detail::interface_part_of_members(vb, va),
           core::transformed_interface_part(s.x, si, b, a)}};
}

/// Where condition (i) holds for a neighbouring pair, the transformed boundary elements that are
/// elements of the other instance are exactly those contained in it (both directions). With
/// `hypothesis` false the pairs where (i) fails are compared too (the dropped hypothesis).
template <int D>
void interface_part_members_equal_containment(const GeneratedStructure<D>& s,
                                              bool hypothesis = true) {
  const auto si = core::apply_template(s.x);
  const auto failures_i = core::condition_i_failures(si);
  std::size_t compared = 0;
  for (auto [a, b] : core::neighbouring_instances(si)) {
    if (hypothesis && failures_i.count({a, b})) continue;
    for (const auto& part : interface_parts<D>(s, si, a, b)) {
      SYMMESH_PROOF_ASSERT(part.members == part.contained, record(s), picture(s));
      compared += part.contained.size();
    }
  }
  RC_TAG(compared > 0 ? "interface parts compared" : "all interface parts empty");
}

/// (i) dropped (Figure 4.4): on a pair where (i) fails, some transformed boundary element lies in
/// the other instance without being one of its elements, so membership is not containment.
template <int D>
void interface_part_without_condition_i(const GeneratedStructure<D>& s) {
  const auto si = core::apply_template(s.x);
  const auto failures_i = core::condition_i_failures(si);
  SYMMESH_PROOF_ASSERT(!failures_i.empty(), record(s), picture(s));
  bool differs = false;
  for (const auto& [pair, why] : failures_i)
    for (const auto& part : interface_parts<D>(s, si, pair.first, pair.second))
      differs = differs || part.members != part.contained;
  SYMMESH_PROOF_ASSERT(differs, record(s), picture(s));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma, "sufficiency" + d, D, Kind::holds,
       "Lemma 4.2: on valid templated meshes (reflections, orthogonal reflections, "
       "translation grids with identical opposite sides, multi-template splits, global "
       "motions) (i) and (ii) hold for all neighbouring instances and AT is conforming "
       "and a valid multi-region mesh",
       [] { return rc::detail::toProperty([] { sufficiency<D>(*valid_templated_mesh<D>()); }); },
       [] {
         return rc::detail::toProperty([] { conclusion_only<D>(*figure_4_4_structure<D>()); });
       }});
  p.push_back(
      {kLemma,
       "checker_agrees_with_direct" + d,
       D,
       Kind::holds,
       "Lemma 4.2 and its converse: on templated structures (valid and Figure 4.4-like) "
       "the interface-conformity checker's verdict equals the direct conformity check of "
       "AT, and a failure names a neighbouring pair and condition (i) (spec note: (i) "
       "implies (ii) under exact vertex identification)",
       [] { return rc::detail::toProperty([] { checker_agrees<D>(*templated_structure<D>()); }); },
       {}});
  p.push_back(
      {kLemma,
       "checker_sound_on_any_input" + d,
       D,
       Kind::holds,
       "Lemma 4.2 checker on any structure (overlapping instances included): it never "
       "certifies a non-conforming AT, and agrees with the direct check where Eq. 4.2 holds",
       [] { return rc::detail::toProperty([] { checker_sound<D>(*any_structure<D>()); }); },
       {}});
  p.push_back(
      {kLemma,
       "figure_4_4_counterexample" + d,
       D,
       Kind::counterexample,
       "Lemma 4.2 without (i) (Figure 4.4): a translated template whose interface side is "
       "subdivided differently; the checker reports condition (i) and AT is not conforming",
       [] { return rc::detail::toProperty([] { figure_4_4<D>(*figure_4_4_structure<D>()); }); },
       {}});
  p.push_back(
      {kLemma, "interface_part_members_equal_containment" + d, D, Kind::holds,
       "Lemma 4.2 (ii) as the checker computes it (spec/lemmas.md#lemma-4-2-condition-ii): "
       "on every neighbouring pair where (i) holds, the transformed boundary elements that are "
       "elements of the other instance are exactly those contained in it (exact containment), "
       "in both directions",
       [] {
         return rc::detail::toProperty(
             [] { interface_part_members_equal_containment<D>(*templated_structure<D>()); });
       },
       [] {
         return rc::detail::toProperty([] {
           interface_part_members_equal_containment<D>(*figure_4_4_structure<D>(), false);
         });
       }});
  p.push_back(
      {kLemma,
       "interface_part_needs_condition_i" + d,
       D,
       Kind::counterexample,
       "Without (i) (Figure 4.4) membership is not containment: on a pair where (i) fails some "
       "transformed boundary element lies in the other instance without being one of its "
       "elements",
       [] {
         return rc::detail::toProperty(
             [] { interface_part_without_condition_i<D>(*figure_4_4_structure<D>()); });
       },
       {}});
  p.push_back(
      {kLemma, "boundary_reduction_agrees" + d, D, Kind::holds,
       "Lemma 4.2 on the templates' boundary complexes (the generator's certificate): on "
       "templated structures (Eq. 4.2) its verdict equals the direct conformity check of AT",
       [] {
         return rc::detail::toProperty(
             [] { boundary_reduction_agrees<D>(*templated_structure<D>()); });
       },
       [] {
         return rc::detail::toProperty(
             [] { reduction_equals_direct<D>(*simplex_inside_a_cell<D>()); });
       }});
  p.push_back(
      {kLemma,
       "boundary_reduction_needs_eq_4_2" + d,
       D,
       Kind::counterexample,
       "Without Eq. 4.2 the boundary reduction is unsound: a simplex strictly inside a cell "
       "of another instance has disjoint boundaries (certified) but AT is not conforming",
       [] {
         return rc::detail::toProperty(
             [] { boundary_reduction_without_eq_4_2<D>(*simplex_inside_a_cell<D>()); });
       },
       {}});
}

// ----- spec/lemmas.md#lemma-4-2-line-meshes ---------------------------------------------------

struct LineCase {
  LineMeshCase<Exact> c;
  std::string recipe;
};
std::ostream& operator<<(std::ostream& os, const LineCase& l) {
  return os << l.recipe;
}

GeneratedStructure<2> as_generated(const LineCase& l) {
  GeneratedStructure<2> s;
  s.x = l.c.actual;
  s.recipe = l.recipe;
  return s;
}

/// A templated structure of the generator (Eq. 4.2 holds) with its boundary complexes split
/// uniformly for a random size h.
rc::Gen<LineCase> uniform_line_case() {
  return rc::gen::exec([] {
    const auto s = *templated_structure<2>();
    const int num = *rc::gen::inRange(1, 4), den = *rc::gen::inRange(1, 5);
    LineCase l;
    l.c = uniform_case<Exact>(s.x, Exact(num) / Exact(den));
    l.recipe = "uniform line meshes (h = " + std::to_string(num) + "/" + std::to_string(den) +
               ") of " + s.recipe;
    return l;
  });
}

/// The uniform hypothesis dropped: two squares of side s side by side (identity and translation
/// by (s, 0), after one random global motion), the shared side split into n parts on both, but
/// the square's right side at the parameters k/n + 1/(3n) instead of k/n. Same ends, same N.
rc::Gen<LineCase> non_uniform_shared_side() {
  return rc::gen::exec([] {
    const int side = *rc::gen::inRange(1, 5), n = *rc::gen::inRange(2, 6);
    const int motion = *rc::gen::inRange(0, 3);
    const Exact s(side);
    const auto pt = [](const Exact& x, const Exact& y) {
      Point<2> p;
      p[0] = x;
      p[1] = y;
      return p;
    };
    core::UniformLineMesh<Exact> u;
    u.points = {pt(0, 0), pt(s, 0), pt(s, s), pt(0, s)};
    u.faces = {{0, 1, 1}, {1, 2, std::size_t(n)}, {2, 3, 1}, {3, 0, std::size_t(n)}};
    using Motion = core::RigidTransformation<Exact, 2>;
    const Motion g = motion == 0   ? Motion()
                     : motion == 1 ? Motion::rotation_2d(Exact(3) / 5, Exact(4) / 5, pt(1, 2))
                                   : Motion::translation(pt(Exact(7) / 3, Exact(-1) / 2));
    LineCase l;
    l.c.lines.templates = {u};
    l.c.lines.instances = {{{g, 1}, {g * Motion::translation(pt(s, 0)), 1}}};
    // The line meshes actually written: the right side (face 1) non-uniform.
    core::Template<Exact, 2> t{"square", core::TemplateKind::mesh, {}};
    t.mesh.points = u.points;
    for (std::size_t f = 0; f < u.faces.size(); ++f) {
      const auto& face = u.faces[f];
      core::VertexId prev = face.a;
      t.mesh.elements.push_back(core::Simplex{face.a});
      for (std::size_t k = 1; k < face.parts; ++k) {
        Exact param = Exact(int(k)) / Exact(n);
        if (f == 1) param += Exact(1) / Exact(3 * n);
        Point<2> q;
        for (int d = 0; d < 2; ++d)
          q[d] = u.points[face.a][d] + (u.points[face.b][d] - u.points[face.a][d]) * param;
        t.mesh.points.push_back(q);
        const auto v = core::VertexId(t.mesh.points.size() - 1);
        t.mesh.elements.push_back(core::Simplex{v});
        t.mesh.elements.push_back(core::Simplex{std::min(prev, v), std::max(prev, v)});
        prev = v;
      }
      t.mesh.elements.push_back(core::Simplex{std::min(prev, face.b), std::max(prev, face.b)});
    }
    t.mesh.normalize();
    l.c.actual.templates = {t};
    l.c.actual.instances = l.c.lines.instances;
    l.recipe = "two squares of side " + std::to_string(side) + " side by side (motion " +
               std::to_string(motion) + "), shared side split into " + std::to_string(n) +
               " parts, non-uniformly on one square";
    return l;
  });
}

void line_mesh_reduction_equals_direct(const LineCase& l) {
  const auto v = line_mesh_verdicts(l.c);
  RC_TAG(v.direct ? "AT conforming" : "AT not conforming");
  SYMMESH_PROOF_ASSERT(v.face_by_face == v.direct, record(as_generated(l)),
                       picture(as_generated(l)));
}

void line_mesh_reduction_without_uniform_split(const LineCase& l) {
  const auto v = line_mesh_verdicts(l.c);
  SYMMESH_PROOF_ASSERT(v.face_by_face && !v.direct, record(as_generated(l)),
                       picture(as_generated(l)));
}

void add_line_meshes(std::vector<Property>& p) {
  p.push_back({kLemma, "line_mesh_reduction_agrees_2d", 2, Kind::holds,
               "Lemma 4.2 face by face on uniform line meshes (spec/lemmas.md#lemma-4-2-line-"
               "meshes; the generator's certificate): on the boundary complexes of templated "
               "structures split for a random size, the verdict equals the direct conformity "
               "check of AT of the written-out line meshes",
               [] {
                 return rc::detail::toProperty(
                     [] { line_mesh_reduction_equals_direct(*uniform_line_case()); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { line_mesh_reduction_equals_direct(*non_uniform_shared_side()); });
               }});
  p.push_back({kLemma,
               "line_mesh_reduction_needs_uniform_split_2d",
               2,
               Kind::counterexample,
               "Without the uniform split the face-by-face decision is unsound: two squares "
               "whose shared side has the same ends and N on both, split non-uniformly on one, "
               "are certified while AT is not conforming",
               [] {
                 return rc::detail::toProperty(
                     [] { line_mesh_reduction_without_uniform_split(*non_uniform_shared_side()); });
               },
               {}});
}

} // namespace

void register_lemma_4_2(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
  add_line_meshes(p);
}

} // namespace symmesh::proofs
