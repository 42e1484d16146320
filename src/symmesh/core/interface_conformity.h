/// Lemma 4.2 (interface conformity) as a checker, and the direct check "AT(X) is conforming" —
/// spec/lemmas.md#lemma-4-2
///
/// For every pair of distinct neighbouring instances (a, b):
///  (i)  us(interf(Γ, T_a, T_b)) = interf_geo(Γ, T_a, T_b). With inst_a, inst_b conforming,
///       this fails exactly when some element of inst_a and a different element of inst_b have
///       meeting relative interiors (spec/lemmas.md#lemma-4-2-condition-i);
///  (ii) T_a(IP_{a,b}) = T_b(IP_{b,a}), IP_{a,b} = bnd(X_i) restricted to T_a^{-1}(interf_geo):
///       the transformed template boundary elements contained in us(inst_b). It is evaluated
///       only where (i) holds, and there these are the ones that are elements of inst_b
///       (spec/lemmas.md#lemma-4-2-condition-ii); transformed_interface_part keeps the
///       definition (exact containment) as the reference for the properties.
/// Pairs (a, a) are trivial. When all pairs pass, AT(Γ) is conforming (the lemma); the
/// converse also holds, so the verdict must equal the direct check.
#pragma once
#include "symmesh/core/templated_structure.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace symmesh::core {

struct Lemma42Verdict {
  bool holds = true;
  std::size_t pairs_checked = 0;
  InstanceId a, b;   ///< the failing neighbouring pair (when !holds)
  int condition = 0; ///< 1 for (i), 2 for (ii)
  std::string detail;
};

/// What condition (ii) needs of one instance, computed once rather than per pair: its elements
/// and T_a applied to the boundary elements of its template, both in global ids and sorted.
struct InstanceView {
  std::vector<Simplex> elements;          ///< si.instance_elements[a]
  std::vector<Simplex> boundary_elements; ///< T_a(bnd(X_i))
};

template <class FT, int D>
InstanceView instance_view(const StructureInstance<FT, D>& si, std::size_t a,
                           const ElementComplex<FT, D>& template_boundary) {
  InstanceView v;
  v.elements = si.instance_elements[a];
  for (const auto& e : template_boundary.elements) {
    std::array<VertexId, 4> g{};
    for (int k = 0; k < e.n; ++k) g[k] = si.vertex_map[a][e.v[k]];
    v.boundary_elements.push_back(Simplex::from_range(g.data(), g.data() + e.n));
  }
  std::sort(v.boundary_elements.begin(), v.boundary_elements.end());
  return v;
}

/// When two distinct elements share vertices, some cases need no geometry: a proper face has its
/// relative interior on the other's relative boundary, and two plane segments with one common
/// end meet in their relative interiors iff they are collinear and leave that end on the same side
/// (one orientation sign and one dot product).
template <class FT, int D>
std::optional<bool> shared_vertices_decide(const ElementComplex<FT, D>& m, const Simplex& p,
                                           const Simplex& q) {
  if (p.is_face_of(q) || q.is_face_of(p)) return false;
  if constexpr (D == 2) {
    if (p.n != 2 || q.n != 2) return std::nullopt;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        if (p.v[i] == q.v[j]) {
          const auto& o = m.points[p.v[i]];
          const auto& a = m.points[p.v[1 - i]];
          const auto& b = m.points[q.v[1 - j]];
          if (detail::orientation_sign<FT>(o, a, b) != 0) return false;
          return dot<FT, 2>(a - o, b - o) > 0;
        }
  }
  return std::nullopt;
}

/// A certified enclosure of the box of some points (from CGAL::to_interval of each coordinate):
/// a filter only — boxes that do not meet certainly hold points that do not meet; every
/// decision stays exact.
template <class FT, int D>
struct EnclosingBox {
  using Bound = decltype(CGAL::to_interval(std::declval<const FT&>()).first);
  std::array<Bound, D> lo{}, hi{};

  template <class Ids>
  static EnclosingBox of(const std::vector<Point<FT, D>>& points, const Ids& ids) {
    EnclosingBox b;
    bool first = true;
    for (VertexId v : ids) {
      for (int d = 0; d < D; ++d) {
        const auto [l, h] = CGAL::to_interval(points[v][d]);
        b.lo[d] = first ? l : std::min(b.lo[d], l);
        b.hi[d] = first ? h : std::max(b.hi[d], h);
      }
      first = false;
    }
    return b;
  }
  bool overlaps(const EnclosingBox& o) const { return may_meet(o); }
  /// The boxes may meet in dimensions from..D-1.
  bool may_meet(const EnclosingBox& o, int from = 0) const {
    for (int d = from; d < D; ++d)
      if (hi[d] < o.lo[d] || o.hi[d] < lo[d]) return false;
    return true;
  }
};

/// Condition (i) for every pair of instances at once: all elements of all instances in one sweep
/// along x over certified enclosures of their boxes (the enclosures only filter; every decision
/// is exact), so the cost is the number of nearby element pairs, not pairs of instances times
/// their sizes. Returns the failing pairs (a < b) with a description of the first conflict.
template <class FT, int D>
std::map<std::pair<std::size_t, std::size_t>, std::string>
condition_i_failures(const StructureInstance<FT, D>& si) {
  struct Item {
    std::size_t instance;
    Simplex s;
    EnclosingBox<FT, D> box;
  };
  const auto& m = si.at.mesh;
  std::vector<Item> items;
  for (std::size_t a = 0; a < si.instance_elements.size(); ++a)
    for (const auto& s : si.instance_elements[a])
      items.push_back({a, s, EnclosingBox<FT, D>::of(m.points, s)});
  std::stable_sort(items.begin(), items.end(),
                   [](const Item& p, const Item& q) { return p.box.lo[0] < q.box.lo[0]; });
  std::map<std::pair<std::size_t, std::size_t>, std::string> failed;
  for (std::size_t x = 0; x < items.size(); ++x) {
    const Item& p = items[x];
    for (std::size_t y = x + 1; y < items.size() && !(p.box.hi[0] < items[y].box.lo[0]); ++y) {
      const Item& q = items[y];
      if (p.instance == q.instance || p.s == q.s || !p.box.may_meet(q.box, 1)) continue;
      const std::pair<std::size_t, std::size_t> key = std::minmax(p.instance, q.instance);
      if (failed.count(key)) continue;
      const auto shared = shared_vertices_decide<FT, D>(m, p.s, q.s);
      if (shared ? *shared : relative_interiors_meet<FT, D>(m.coords(p.s), m.coords(q.s)))
        failed[key] = "a " + std::to_string(p.s.dim()) +
                      "-element of one instance and a different " + std::to_string(q.s.dim()) +
                      "-element of the other overlap";
    }
  }
  return failed;
}

namespace detail {
/// T_a(IP_{a,b}) in global element ids where condition (i) holds for (a, b): the transformed
/// template boundary elements of a that are elements of inst_b. Under (i) these are exactly the
/// ones contained in us(inst_b) (spec/lemmas.md#lemma-4-2-condition-ii), so (ii) costs a set
/// intersection instead of exact containment tests.
/// \pre condition (i) holds for (a, b): check_interface_conformity, the only caller, evaluates
/// (ii) only on such pairs
inline std::vector<Simplex> interface_part_of_members(const InstanceView& va,
                                                      const InstanceView& vb) {
  std::vector<Simplex> out;
  std::set_intersection(va.boundary_elements.begin(), va.boundary_elements.end(),
                        vb.elements.begin(), vb.elements.end(), std::back_inserter(out));
  return out;
}

/// Condition (ii): T_a(IP_{a,b}) = T_b(IP_{b,a}). \pre condition (i) holds for (a, b)
inline bool condition_ii_holds(const InstanceView& va, const InstanceView& vb,
                               std::string* detail) {
  const auto ip_a = interface_part_of_members(va, vb);
  const auto ip_b = interface_part_of_members(vb, va);
  if (ip_a == ip_b) return true;
  if (detail)
    *detail = "the interface boundary elements differ: " + std::to_string(ip_a.size()) +
              " from one template, " + std::to_string(ip_b.size()) + " from the other";
  return false;
}
} // namespace detail

/// T_a(IP_{a,b}) in global element ids by its definition: the transformed template boundary
/// elements of a contained in us(inst_b), decided by exact containment (simplex_covered_by;
/// boundary elements have dimension <= 2). The checker does not use it: it is the reference the
/// Lemma 4.2 properties compare detail::interface_part_of_members with.
/// \pre x is a templated structure with mesh templates and si = apply_template(x)
template <class FT, int D>
std::vector<Simplex> transformed_interface_part(const TemplatedStructure<FT, D>& x,
                                                const StructureInstance<FT, D>& si, std::size_t a,
                                                std::size_t b) {
  const auto inst_b = si.instance_complex(b);
  std::vector<Simplex> out;
  const auto va = instance_view(si, a, mesh_boundary(x.templates[si.ids[a].i].mesh));
  for (const auto& s : va.boundary_elements)
    if (simplex_covered_by<FT, D>(si.at.mesh.coords(s), inst_b)) out.push_back(s);
  return out;
}

/// \pre x is a templated structure (Eq. 4.2) with mesh templates
template <class FT, int D>
Lemma42Verdict check_interface_conformity(const TemplatedStructure<FT, D>& x,
                                          const StructureInstance<FT, D>& si) {
  Lemma42Verdict v;
  std::vector<std::optional<ElementComplex<FT, D>>> boundary(x.templates.size());
  std::vector<std::optional<InstanceView>> views(si.ids.size());
  const auto view = [&](std::size_t a) -> const InstanceView& {
    if (!views[a]) {
      const std::size_t i = si.ids[a].i;
      if (!boundary[i]) boundary[i] = mesh_boundary(x.templates[i].mesh);
      views[a] = instance_view(si, a, *boundary[i]);
    }
    return *views[a];
  };
  const auto failures_i = condition_i_failures(si);
  for (auto [a, b] : neighbouring_instances(si)) {
    ++v.pairs_checked;
    std::string detail;
    int failed = 0;
    const std::size_t i = si.ids[a].i, j = si.ids[b].i;
    for (std::size_t t : {i, j})
      if (!boundary[t]) boundary[t] = mesh_boundary(x.templates[t].mesh);
    if (const auto it = failures_i.find(std::pair<std::size_t, std::size_t>(std::minmax(a, b)));
        it != failures_i.end()) {
      failed = 1;
      detail = it->second;
    } else if ((!boundary[i]->elements.empty() || !boundary[j]->elements.empty()) &&
               !detail::condition_ii_holds(view(a), view(b), &detail)) {
      failed = 2;
    }
    if (failed && v.holds) {
      v.holds = false;
      v.a = si.ids[a];
      v.b = si.ids[b];
      v.condition = failed;
      v.detail = detail;
    }
  }
  return v;
}

/// The structure Γ_∂ with the same instances and, as templates, the boundary complexes bnd(X_i)
/// over their own points (spec/lemmas.md#lemma-4-2-boundary).
template <class FT, int D>
TemplatedStructure<FT, D> boundary_structure(const TemplatedStructure<FT, D>& x) {
  TemplatedStructure<FT, D> out;
  out.instances = x.instances;
  for (const auto& t : x.templates) {
    const auto bnd = mesh_boundary(t.mesh);
    Template<FT, D> b{t.name, TemplateKind::mesh, {}};
    std::map<VertexId, VertexId> compact;
    for (const auto& e : bnd.elements) {
      std::array<VertexId, 4> v{};
      for (int k = 0; k < e.n; ++k) {
        auto [it, inserted] = compact.emplace(e.v[k], VertexId(b.mesh.points.size()));
        if (inserted) b.mesh.points.push_back(bnd.points[e.v[k]]);
        v[k] = it->second;
      }
      b.mesh.elements.push_back(Simplex::from_range(v.data(), v.data() + e.n));
    }
    b.mesh.normalize();
    out.templates.push_back(std::move(b));
  }
  return out;
}

/// Lemma 4.2 decided on the boundary complexes only (spec/lemmas.md#lemma-4-2-boundary): when
/// the instances' interiors are disjoint, an element of inst_a that is not a transformed boundary
/// element lies in the interior of us(inst_a) and meets no other instance, so AT(Γ) is conforming
/// iff AT(Γ_∂) is, and the checker runs on Γ_∂. This is what makes certifying a generated mesh
/// cost its boundary size rather than its cell count.
/// \pre x obeys Eq. 4.2 (no two instances' interiors meet; find_instance_overlap is empty) and
/// every template is a conforming pure mesh
template <class FT, int D>
Lemma42Verdict check_interface_conformity_on_boundaries(const TemplatedStructure<FT, D>& x) {
  const auto b = boundary_structure(x);
  return check_interface_conformity(b, apply_template(b));
}

/// Lemma 4.2 on a rotationally invariant structure, up to the rotation
/// (spec/lemmas.md#lemma-4-2-rotational): when every template's instances are
/// T_{i,k} = R^k ∘ T_{i,0}, k = 0..n-1, the rotation R^-k maps the pair ((i,k), (j,l)) onto
/// ((i,0), (j,l-k)), and isometries keep meeting relative interiors, so condition (i) only has to
/// be decided for the pairs with a copy 0. Copy 0 is applied in full; of the other copies only
/// the elements whose certified box meets the copies 0 are applied (with exact identification of
/// their points), which is what makes the check cost one slice's neighbourhood rather than n
/// slices. (ii) is not evaluated: it is implied by (i) (spec/lemmas.md#lemma-4-2), and vacuous on
/// the boundary complexes this is used with.
/// \pre every template has n >= 1 instances T_{i,k} = R^k ∘ T_{i,0} for one rotation R of order n
/// (checked by the caller, e.g. gen's rotation_order)
template <class FT, int D>
Lemma42Verdict check_interface_conformity_up_to_rotation(const TemplatedStructure<FT, D>& x) {
  using IBox = EnclosingBox<FT, D>;
  StructureInstance<FT, D> si;
  si.ids = x.instance_ids();
  std::vector<std::vector<Point<FT, D>>> moved(si.ids.size());
  std::vector<IBox> copy0_boxes;
  for (std::size_t a = 0; a < si.ids.size(); ++a) {
    const auto& t = x.tf(si.ids[a]);
    for (const auto& p : x.templates[si.ids[a].i].mesh.points) moved[a].push_back(t(p));
    if (si.ids[a].g == 0) {
      std::vector<VertexId> all(moved[a].size());
      for (std::size_t v = 0; v < all.size(); ++v) all[v] = VertexId(v);
      copy0_boxes.push_back(IBox::of(moved[a], all));
    }
  }
  std::map<Point<FT, D>, VertexId, PointLess<FT, D>> index;
  auto& pts = si.at.mesh.points;
  si.instance_elements.resize(si.ids.size());
  for (std::size_t a = 0; a < si.ids.size(); ++a)
    for (const auto& e : x.templates[si.ids[a].i].mesh.elements) {
      if (si.ids[a].g != 0) {
        const auto b = IBox::of(moved[a], e);
        if (std::none_of(copy0_boxes.begin(), copy0_boxes.end(),
                         [&](const IBox& c) { return b.may_meet(c); }))
          continue;
      }
      std::array<VertexId, 4> g{};
      for (int k = 0; k < e.n; ++k) {
        auto [it, inserted] = index.emplace(moved[a][e.v[k]], VertexId(pts.size()));
        if (inserted) pts.push_back(moved[a][e.v[k]]);
        g[std::size_t(k)] = it->second;
      }
      si.instance_elements[a].push_back(Simplex::from_range(g.data(), g.data() + e.n));
    }
  Lemma42Verdict v;
  for (std::size_t a = 0; a < si.ids.size(); ++a)
    if (si.ids[a].g != 0 && !si.instance_elements[a].empty()) ++v.pairs_checked;
  const auto failures = condition_i_failures(si);
  if (!failures.empty()) {
    const auto& [pair, detail] = *failures.begin();
    v.holds = false;
    v.a = si.ids[pair.first];
    v.b = si.ids[pair.second];
    v.condition = 1;
    v.detail = detail;
  }
  return v;
}

/// Definition 4.4 directly: AT(X) is conforming.
template <class FT, int D>
bool structure_instance_conforming(const StructureInstance<FT, D>& si) {
  return !find_nonconformity(si.at.mesh).has_value();
}

} // namespace symmesh::core
