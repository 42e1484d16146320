/// Definition 4.3 (templated structure), Eq. 4.3 (apply-template AT), Definition 4.4 (templated
/// geometry / templated mesh), Definition 4.6 (instance interface, geometry instance interface)
/// and the neighbourhood of instances (Section 4.2) — spec/definitions.md#def-4-3 … #def-4-6
///
/// Templates are simplicial: a mesh template is a mesh; a geometry template is a linear geometry
/// given by a carrier triangulation, of which only the underlying space counts.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/multi_region_mesh.h"
#include "symmesh/core/rigid_transformation.h"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace symmesh::core {

enum class TemplateKind { mesh, geometry };

template <class FT, int D>
struct Template {
  std::string name;
  TemplateKind kind = TemplateKind::mesh;
  ElementComplex<FT, D> mesh; ///< the mesh template, or the carrier of a geometry template

  /// A D-dimensional mesh with pairwise distinct vertex coordinates.
  bool is_valid(std::ostream* why = nullptr) const {
    std::set<Point<FT, D>, PointLess<FT, D>> seen;
    for (const auto& p : mesh.points)
      if (!seen.insert(p).second) {
        if (why) *why << "two vertices have equal coordinates";
        return false;
      }
    if (!is_mesh(mesh, why)) return false;
    if (mesh.cell_dimension() != D) {
      if (why) *why << "cells have dimension " << mesh.cell_dimension() << ", expected " << D;
      return false;
    }
    return true;
  }
};

template <class FT, int D>
struct InstanceSpec {
  RigidTransformation<FT, D> transformation; ///< T_{i,g}
  int region = 1;                            ///< r_{i,g}
};

/// (i, g): the g-th instance of template i (0-based; the dissertation counts from 1).
struct InstanceId {
  std::size_t i = 0, g = 0;
  friend bool operator==(const InstanceId& a, const InstanceId& b) {
    return a.i == b.i && a.g == b.g;
  }
  friend bool operator<(const InstanceId& a, const InstanceId& b) {
    return a.i != b.i ? a.i < b.i : a.g < b.g;
  }
};

inline std::string to_string(const InstanceId& id) {
  return "T_{" + std::to_string(id.i + 1) + "," + std::to_string(id.g + 1) + "}";
}

template <class FT, int D>
struct TemplatedStructure {
  std::vector<Template<FT, D>> templates;
  std::vector<std::vector<InstanceSpec<FT, D>>> instances; ///< instances[i] = (T_{i,g}, r_{i,g})_g

  std::vector<InstanceId> instance_ids() const {
    std::vector<InstanceId> out;
    for (std::size_t i = 0; i < instances.size(); ++i)
      for (std::size_t g = 0; g < instances[i].size(); ++g) out.push_back({i, g});
    return out;
  }
  const RigidTransformation<FT, D>& tf(InstanceId id) const {
    return instances[id.i][id.g].transformation;
  }
  bool all_of_kind(TemplateKind k) const {
    for (const auto& t : templates)
      if (t.kind != k) return false;
    return true;
  }

  /// Shape checks: every template valid and instanced at least once, same count of lists.
  bool is_well_formed(std::ostream* why = nullptr) const {
    if (templates.empty()) {
      if (why) *why << "no templates";
      return false;
    }
    if (templates.size() != instances.size()) {
      if (why) *why << "templates and instance lists differ in number";
      return false;
    }
    for (std::size_t i = 0; i < templates.size(); ++i) {
      std::ostringstream w;
      if (!templates[i].is_valid(&w)) {
        if (why) *why << "template " << (i + 1) << " ('" << templates[i].name << "'): " << w.str();
        return false;
      }
      if (instances[i].empty()) {
        if (why) *why << "template " << (i + 1) << " has no instances";
        return false;
      }
    }
    if (!all_of_kind(TemplateKind::mesh) && !all_of_kind(TemplateKind::geometry)) {
      if (why) *why << "templates mix meshes and geometries (Definition 4.3)";
      return false;
    }
    return true;
  }
};

/// The same structure over another number type (coordinates and transformations mapped by `to`).
/// \pre `to` is an exact field embedding, e.g. FT -> CGAL::Lazy_exact_nt<FT>
template <class To, class FT, int D, class F>
TemplatedStructure<To, D> convert_numbers(const TemplatedStructure<FT, D>& x, F&& to) {
  TemplatedStructure<To, D> y;
  for (const auto& t : x.templates) {
    Template<To, D> u{t.name, t.kind, {}};
    for (const auto& p : t.mesh.points) {
      Point<To, D> q;
      for (int d = 0; d < D; ++d) q[d] = to(p[d]);
      u.mesh.points.push_back(q);
    }
    u.mesh.elements = t.mesh.elements;
    y.templates.push_back(std::move(u));
  }
  for (const auto& list : x.instances) {
    y.instances.emplace_back();
    for (const auto& s : list)
      y.instances.back().push_back({s.transformation.template convert_numbers<To>(to), s.region});
  }
  return y;
}

/// inst(X, i, g) = T_{i,g}(X_i), over its own transformed point array.
template <class FT, int D>
ElementComplex<FT, D> instance(const TemplatedStructure<FT, D>& x, InstanceId id) {
  ElementComplex<FT, D> out = x.templates[id.i].mesh;
  const auto& t = x.tf(id);
  for (auto& p : out.points) p = t(p);
  return out;
}

/// Two distinct instances whose interiors meet (Eq. 4.2 violated), with the cells that overlap.
struct OverlapWitness {
  InstanceId a, b;
};

/// The one-line message for an Eq. 4.2 violation (shared by check, graph and bpp).
inline std::string overlap_message(const OverlapWitness& o) {
  return "instances " + to_string(o.a) + " and " + to_string(o.b) +
         " overlap: their interiors intersect (Eq. 4.2)";
}

/// Eq. 4.2: int*(us(T_{i,g}(X_i))) ∩ int*(us(T_{j,h}(X_j))) = ∅ for distinct instances.
/// For pure D-dimensional meshes this holds iff no two D-cells of different instances have
/// meeting interiors (spec/definitions.md#eq-4-2-by-cells). `rotation_copies` = n > 0: only the
/// pairs of a copy 0 and a copy k <= n/2 are decided — R^-k maps the pair ((i,k), (j,l)) onto
/// ((i,0), (j,l-k)) and ((i,0), (j,l)) onto ((j,0), (i,n-l)), and keeps meeting interiors
/// (spec/lemmas.md#lemma-4-2-rotational).
/// \pre with rotation_copies = n > 0: every template has the n instances T_{i,k} = R^k ∘ T_{i,0}
/// for one rotation R of order n (checked by the caller). `wanted(a, b)`, when given, decides
/// only the pairs it accepts (the caller knows the others are images of accepted ones).
template <class FT, int D>
std::optional<OverlapWitness>
find_instance_overlap(const TemplatedStructure<FT, D>& x, std::size_t rotation_copies = 0,
                      const std::function<bool(InstanceId, InstanceId)>& wanted = {}) {
  const auto ids = x.instance_ids();
  std::vector<ElementComplex<FT, D>> inst;
  std::vector<Box<FT, D>> boxes;
  for (auto id : ids) {
    inst.push_back(instance(x, id));
    boxes.push_back(box_of<FT, D>(inst.back().points));
  }
  std::optional<OverlapWitness> out;
  for_each_overlapping_pair<FT, D>(boxes, [&](std::size_t a, std::size_t b) {
    // Up to the rotation: one side a copy 0, the other a copy k <= n/2 (R^{-k} turns
    // ((i,0), (j,k)) into ((j,0), (i,n-k)); spec/lemmas.md#lemma-4-2-rotational).
    if (rotation_copies > 0) {
      const auto half = [&](std::size_t c) { return 2 * ids[c].g <= rotation_copies; };
      if (!((ids[a].g == 0 && half(b)) || (ids[b].g == 0 && half(a)))) return true;
    }
    if (wanted && !wanted(ids[a], ids[b])) return true;
    const auto ca = inst[a].cells();
    const auto cb = inst[b].cells();
    for (const auto& s : ca) {
      const auto sp = inst[a].coords(s);
      const auto sb = box_of<FT, D>(sp);
      for (const auto& t : cb) {
        const auto tp = inst[b].coords(t);
        if (!sb.overlaps(box_of<FT, D>(tp))) continue;
        if (relative_interiors_meet<FT, D>(sp, tp)) {
          out = OverlapWitness{ids[a], ids[b]};
          return false;
        }
      }
    }
    return true;
  });
  return out;
}

/// AT(X) (Eq. 4.3) with its bookkeeping: the union of all instances over one point array in
/// which exactly-equal points are one vertex (no tolerance), the region indicator of each cell,
/// and every instance's element set and vertex map in global indices.
template <class FT, int D>
struct StructureInstance {
  MultiRegionMesh<FT, D> at;
  std::vector<InstanceId> ids;
  std::vector<std::vector<VertexId>> vertex_map;       ///< per instance: template vertex -> global
  std::vector<std::vector<Simplex>> instance_elements; ///< per instance, sorted, global ids
  std::vector<Box<FT, D>> instance_box;

  std::size_t index_of(InstanceId id) const {
    for (std::size_t k = 0; k < ids.size(); ++k)
      if (ids[k] == id) return k;
    throw std::out_of_range("no such instance");
  }
  ElementComplex<FT, D> instance_complex(std::size_t k) const {
    ElementComplex<FT, D> out;
    out.points = at.mesh.points;
    out.elements = instance_elements[k];
    return out;
  }
};

template <class FT, int D>
StructureInstance<FT, D> apply_template(const TemplatedStructure<FT, D>& x) {
  StructureInstance<FT, D> si;
  std::map<Point<FT, D>, VertexId, PointLess<FT, D>> index;
  auto& pts = si.at.mesh.points;
  si.ids = x.instance_ids();
  for (auto id : si.ids) {
    const auto& tmpl = x.templates[id.i].mesh;
    const auto& t = x.tf(id);
    std::vector<VertexId> map(tmpl.points.size());
    for (std::size_t v = 0; v < tmpl.points.size(); ++v) {
      const auto p = t(tmpl.points[v]);
      auto [it, inserted] = index.emplace(p, VertexId(pts.size()));
      if (inserted) pts.push_back(p);
      map[v] = it->second;
    }
    std::vector<Simplex> elems;
    const int cd = tmpl.cell_dimension();
    for (const auto& e : tmpl.elements) {
      std::array<VertexId, 4> g{};
      for (int k = 0; k < e.n; ++k) g[k] = map[e.v[k]];
      const Simplex s = Simplex::from_range(g.data(), g.data() + e.n);
      elems.push_back(s);
      si.at.mesh.elements.push_back(s);
      if (e.dim() == cd) si.at.cell_region[s] = x.instances[id.i][id.g].region;
    }
    std::sort(elems.begin(), elems.end());
    si.vertex_map.push_back(std::move(map));
    si.instance_elements.push_back(std::move(elems));
    std::vector<Point<FT, D>> ip;
    for (VertexId v : si.vertex_map.back()) ip.push_back(pts[v]);
    si.instance_box.push_back(box_of<FT, D>(ip));
  }
  si.at.mesh.normalize();
  return si;
}

/// interf(X, T_a, T_b) (Eq. 4.5) = inst_a ∩ inst_b as element sets.
template <class FT, int D>
ElementComplex<FT, D> instance_interface(const StructureInstance<FT, D>& si, std::size_t a,
                                         std::size_t b) {
  return intersection(si.instance_complex(a), si.instance_complex(b));
}

/// Whether two lists of global vertex ids have a common element.
inline bool share_a_vertex(std::vector<VertexId> a, std::vector<VertexId> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end();) {
    if (*i == *j) return true;
    *i < *j ? ++i : ++j;
  }
  return false;
}

/// interf_geo(X, T_a, T_b) ≠ ∅ (Eq. 4.6): the underlying spaces meet, i.e. some two cells meet.
template <class FT, int D>
bool geometry_interface_nonempty(const StructureInstance<FT, D>& si, std::size_t a, std::size_t b) {
  if (a == b) return true;
  if (!si.instance_box[a].overlaps(si.instance_box[b])) return false;
  // AT identifies equal points, so a shared vertex is a common point without any arithmetic:
  // in rotational structures every pair shares the centre, and the cell tests below would cost
  // a number-field evaluation each.
  if (share_a_vertex(si.vertex_map[a], si.vertex_map[b])) return true;
  const auto& m = si.at.mesh;
  // The closed top-dimensional elements cover a pure complex; templates may be boundary
  // complexes of dimension D - 1 (interface_conformity.h, boundary_structure).
  const auto top = [&](std::size_t k) {
    int d = 0;
    for (const auto& s : si.instance_elements[k]) d = std::max(d, s.dim());
    return d;
  };
  const int cd = top(a), cdb = top(b);
  for (const auto& s : si.instance_elements[a]) {
    if (s.dim() != cd) continue;
    const auto sp = m.coords(s);
    const auto sb = box_of<FT, D>(sp);
    if (!sb.overlaps(si.instance_box[b])) continue;
    for (const auto& t : si.instance_elements[b]) {
      if (t.dim() != cdb) continue;
      const auto tp = m.coords(t);
      if (!sb.overlaps(box_of<FT, D>(tp))) continue;
      if (closed_simplices_meet<FT, D>(sp, tp)) return true;
    }
  }
  return false;
}

/// All pairs (a, b), a < b, of distinct neighbouring instances (Section 4.2).
template <class FT, int D>
std::vector<std::pair<std::size_t, std::size_t>>
neighbouring_instances(const StructureInstance<FT, D>& si) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for_each_overlapping_pair<FT, D>(si.instance_box, [&](std::size_t a, std::size_t b) {
    if (geometry_interface_nonempty(si, a, b)) out.emplace_back(a, b);
    return true;
  });
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace symmesh::core
