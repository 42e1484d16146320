/// Definition 4.8 for a templated mesh: the boundary patch relation on template boundary elements
/// (Lemma 4.4) — spec/boundary-patches.md#element-relation
///
/// For a templated mesh Γ, E1 ~ E2 when some template boundary mapping sends the boundary element
/// E1 of X_j (inside its domain) onto the boundary element E2 of X_i; ~ is the transitive closure.
/// Lemma 4.4 (ii) says the image of such an element is an element again; where it is not (Γ is
/// then not a templated mesh), `maps_onto_elements` is false and the first offender is named.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/template_boundary_mapping.h"
#include "symmesh/core/templated_structure.h"

#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace symmesh::core {

struct BoundaryElementRelation {
  std::vector<std::vector<Simplex>> elements;          ///< per template: bnd(X_i), sorted
  std::vector<std::vector<std::size_t>> element_class; ///< class of each element
  std::size_t class_count = 0;
  bool maps_onto_elements = true; ///< Lemma 4.4 (ii) held for every mapping and element
  std::string offender;           ///< first element whose image is not an element
};

/// \pre the mappings are template_boundary_mappings(x). On a templated mesh every domain is a
/// union of boundary elements (Lemma 4.1 (iii)), so E lies in a domain iff its centroid does.
template <class FT, int D>
BoundaryElementRelation
boundary_element_relation(const TemplatedStructure<FT, D>& x,
                          const std::vector<TemplateBoundaryMapping<FT, D>>& mappings) {
  BoundaryElementRelation r;
  std::vector<std::size_t> offset{0};
  std::vector<std::map<Point<FT, D>, VertexId, PointLess<FT, D>>> index(x.templates.size());
  for (std::size_t t = 0; t < x.templates.size(); ++t) {
    r.elements.push_back(mesh_boundary(x.templates[t].mesh).elements);
    offset.push_back(offset.back() + r.elements.back().size());
    const auto& pts = x.templates[t].mesh.points;
    for (std::size_t v = 0; v < pts.size(); ++v) index[t].emplace(pts[v], VertexId(v));
  }
  std::vector<std::size_t> parent(offset.back());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  for (const auto& m : mappings) {
    if (m.whole_boundary) continue;
    const std::size_t j = m.from_template(), i = m.to_template();
    const auto& pj = x.templates[j].mesh.points;
    for (std::size_t e = 0; e < r.elements[j].size(); ++e) {
      const auto& el = r.elements[j][e];
      Point<FT, D> c = zero_point<FT, D>();
      for (VertexId v : el) c = c + pj[v];
      if (!m.in_domain(scaled<FT, D>(c, FT(1) / FT(int(el.n))))) continue;
      std::vector<VertexId> img;
      for (VertexId v : el) {
        const auto it = index[i].find(m.map(pj[v]));
        if (it != index[i].end()) img.push_back(it->second);
      }
      const auto& target = r.elements[i];
      const auto hit =
          img.size() == el.n
              ? std::lower_bound(target.begin(), target.end(),
                                 Simplex::from_range(img.data(), img.data() + img.size()))
              : target.end();
      if (hit == target.end() || *hit != Simplex::from_range(img.data(), img.data() + img.size())) {
        if (r.maps_onto_elements)
          r.offender = "a " + std::to_string(el.dim()) + "-element of template " +
                       std::to_string(j + 1) + " is not mapped onto an element by " + m.name();
        r.maps_onto_elements = false;
        continue;
      }
      parent[find(offset[j] + e)] = find(offset[i] + std::size_t(hit - target.begin()));
    }
  }
  std::map<std::size_t, std::size_t> dense;
  for (std::size_t t = 0; t < r.elements.size(); ++t) {
    r.element_class.emplace_back();
    for (std::size_t e = 0; e < r.elements[t].size(); ++e)
      r.element_class[t].push_back(dense.emplace(find(offset[t] + e), dense.size()).first->second);
  }
  r.class_count = dense.size();
  return r;
}

} // namespace symmesh::core
