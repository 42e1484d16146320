/// Lemma 4.2 (interface conformity) as a checker, and the direct check "AT(X) is conforming" —
/// spec/lemmas.md#lemma-4-2
///
/// For every pair of distinct neighbouring instances (a, b):
///  (i)  us(interf(Γ, T_a, T_b)) = interf_geo(Γ, T_a, T_b). With inst_a, inst_b conforming,
///       this fails exactly when some element of inst_a and a different element of inst_b have
///       meeting relative interiors (spec/lemmas.md#lemma-4-2-condition-i);
///  (ii) T_a(IP_{a,b}) = T_b(IP_{b,a}), IP_{a,b} = bnd(X_i) restricted to T_a^{-1}(interf_geo):
///       the transformed template boundary elements contained in us(inst_b), found with the
///       exact containment test simplex_covered_by (boundary elements have dimension <= 2).
/// Pairs (a, a) are trivial. When all pairs pass, AT(Γ) is conforming (the lemma); the
/// converse also holds, so the verdict must equal the direct check.
#pragma once
#include "symmesh/core/templated_structure.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <optional>
#include <string>

namespace symmesh::core {

struct Lemma42Verdict {
  bool holds = true;
  std::size_t pairs_checked = 0;
  InstanceId a, b;   ///< the failing neighbouring pair (when !holds)
  int condition = 0; ///< 1 for (i), 2 for (ii)
  std::string detail;
};

/// What the checker needs of one instance, computed once rather than per pair: its elements in
/// global ids with their coordinates and boxes, its complex over its own points, and T_a applied
/// to the boundary elements of its template (also in global ids).
template <class FT, int D>
struct InstanceView {
  std::vector<Simplex> elements; ///< global ids (si.instance_elements)
  std::vector<std::vector<Point<FT, D>>> coords;
  std::vector<Box<FT, D>> boxes;
  std::vector<std::size_t> order_by_x;    ///< element indices by increasing box lo[0]
  ElementComplex<FT, D> local;            ///< the instance over its own points only
  std::vector<Box<FT, D>> local_boxes;    ///< per element of `local`
  std::vector<Simplex> boundary_elements; ///< T_a(bnd(X_i)) in global ids
};

template <class FT, int D>
InstanceView<FT, D> instance_view(const StructureInstance<FT, D>& si, std::size_t a,
                                  const ElementComplex<FT, D>& template_boundary) {
  InstanceView<FT, D> v;
  const auto& m = si.at.mesh;
  v.elements = si.instance_elements[a];
  for (const auto& s : v.elements) {
    v.coords.push_back(m.coords(s));
    v.boxes.push_back(box_of<FT, D>(v.coords.back()));
  }
  v.order_by_x.resize(v.boxes.size());
  for (std::size_t k = 0; k < v.boxes.size(); ++k) v.order_by_x[k] = k;
  std::stable_sort(v.order_by_x.begin(), v.order_by_x.end(), [&](std::size_t p, std::size_t q) {
    return v.boxes[p].lo[0] < v.boxes[q].lo[0];
  });
  std::map<VertexId, VertexId> local_id;
  for (VertexId g : si.vertex_map[a])
    if (local_id.emplace(g, VertexId(v.local.points.size())).second)
      v.local.points.push_back(m.points[g]);
  for (const auto& s : v.elements) {
    std::array<VertexId, 4> l{};
    for (int k = 0; k < s.n; ++k) l[k] = local_id.at(s.v[k]);
    v.local.elements.push_back(Simplex::from_range(l.data(), l.data() + s.n));
  }
  v.local.normalize();
  for (const auto& e : v.local.elements) v.local_boxes.push_back(box_of<FT, D>(v.local.coords(e)));
  for (const auto& e : template_boundary.elements) {
    std::array<VertexId, 4> g{};
    for (int k = 0; k < e.n; ++k) g[k] = si.vertex_map[a][e.v[k]];
    v.boundary_elements.push_back(Simplex::from_range(g.data(), g.data() + e.n));
  }
  return v;
}

/// Condition (i): no element of a and a different element of b with meeting relative interiors.
/// Candidate pairs come from a sweep along x over the elements inside the other instance's box,
/// so a pair costs about the number of box overlaps rather than the product of element counts.
template <class FT, int D>
bool condition_i_holds(const StructureInstance<FT, D>& si, const InstanceView<FT, D>& va,
                       const InstanceView<FT, D>& vb, std::size_t a, std::size_t b,
                       std::string* detail) {
  struct Item {
    const InstanceView<FT, D>* view;
    std::size_t k;
  };
  std::vector<Item> items;
  for (std::size_t k : va.order_by_x)
    if (va.boxes[k].overlaps(si.instance_box[b])) items.push_back({&va, k});
  std::vector<Item> from_b;
  for (std::size_t k : vb.order_by_x)
    if (vb.boxes[k].overlaps(si.instance_box[a])) from_b.push_back({&vb, k});
  const auto lo_x = [](const Item& it) -> const FT& { return it.view->boxes[it.k].lo[0]; };
  std::vector<Item> merged;
  std::merge(items.begin(), items.end(), from_b.begin(), from_b.end(), std::back_inserter(merged),
             [&](const Item& p, const Item& q) { return lo_x(p) < lo_x(q); });
  for (std::size_t x = 0; x < merged.size(); ++x) {
    const auto& bx = merged[x].view->boxes[merged[x].k];
    for (std::size_t y = x + 1; y < merged.size(); ++y) {
      if (bx.hi[0] < lo_x(merged[y])) break;
      if (merged[y].view == merged[x].view) continue;
      const Item& p = merged[x].view == &va ? merged[x] : merged[y];
      const Item& q = merged[x].view == &va ? merged[y] : merged[x];
      if (va.elements[p.k] == vb.elements[q.k] || !va.boxes[p.k].overlaps(vb.boxes[q.k])) continue;
      if (relative_interiors_meet<FT, D>(va.coords[p.k], vb.coords[q.k])) {
        if (detail)
          *detail = "a " + std::to_string(va.elements[p.k].dim()) +
                    "-element of one instance and a different " +
                    std::to_string(vb.elements[q.k].dim()) + "-element of the other overlap";
        return false;
      }
    }
  }
  return true;
}

/// T_a(IP_{a,b}) in global element ids: the transformed template boundary elements of a that lie
/// in us(inst_b). Only the elements of b inside a's box can contain them.
template <class FT, int D>
std::vector<Simplex>
transformed_interface_part(const StructureInstance<FT, D>& si, const InstanceView<FT, D>& va,
                           const InstanceView<FT, D>& vb, std::size_t a, std::size_t b) {
  ElementComplex<FT, D> near;
  for (std::size_t k = 0; k < vb.local.elements.size(); ++k)
    if (vb.local_boxes[k].overlaps(si.instance_box[a]))
      near.elements.push_back(vb.local.elements[k]);
  std::vector<Simplex> out;
  if (near.elements.empty()) return out;
  near.points = vb.local.points;
  for (const auto& s : va.boundary_elements) {
    const auto sp = si.at.mesh.coords(s);
    if (!box_of<FT, D>(sp).overlaps(si.instance_box[b])) continue;
    if (simplex_covered_by<FT, D>(sp, near)) out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Condition (ii): T_a(IP_{a,b}) = T_b(IP_{b,a}).
template <class FT, int D>
bool condition_ii_holds(const StructureInstance<FT, D>& si, const InstanceView<FT, D>& va,
                        const InstanceView<FT, D>& vb, std::size_t a, std::size_t b,
                        std::string* detail) {
  const auto ip_a = transformed_interface_part(si, va, vb, a, b);
  const auto ip_b = transformed_interface_part(si, vb, va, b, a);
  if (ip_a == ip_b) return true;
  if (detail)
    *detail = "the interface boundary elements differ: " + std::to_string(ip_a.size()) +
              " from one template, " + std::to_string(ip_b.size()) + " from the other";
  return false;
}

/// \pre x is a templated structure (Eq. 4.2) with mesh templates
template <class FT, int D>
Lemma42Verdict check_interface_conformity(const TemplatedStructure<FT, D>& x,
                                          const StructureInstance<FT, D>& si) {
  Lemma42Verdict v;
  std::vector<std::optional<ElementComplex<FT, D>>> boundary(x.templates.size());
  std::vector<std::optional<InstanceView<FT, D>>> views(si.ids.size());
  const auto view = [&](std::size_t a) -> const InstanceView<FT, D>& {
    if (!views[a]) {
      const std::size_t i = si.ids[a].i;
      if (!boundary[i]) boundary[i] = mesh_boundary(x.templates[i].mesh);
      views[a] = instance_view(si, a, *boundary[i]);
    }
    return *views[a];
  };
  for (auto [a, b] : neighbouring_instances(si)) {
    ++v.pairs_checked;
    std::string detail;
    int failed = 0;
    const auto& va = view(a);
    const auto& vb = view(b);
    if (!condition_i_holds(si, va, vb, a, b, &detail))
      failed = 1;
    else if (!condition_ii_holds(si, va, vb, a, b, &detail))
      failed = 2;
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

/// Definition 4.4 directly: AT(X) is conforming.
template <class FT, int D>
bool structure_instance_conforming(const StructureInstance<FT, D>& si) {
  return !find_nonconformity(si.at.mesh).has_value();
}

} // namespace symmesh::core
