// Shared checks of the Section 5.2 adaptation properties — spec/adaptation.md#properties
//
// "A templated mesh" is Definition 4.4 decided exactly: well-formed, instances with disjoint
// interiors (Eq. 4.2), the Lemma 4.2 checker's verdict on every neighbouring pair, and AT(Γ)
// conforming by the direct test. "AT equals" compares structure instances as multisets of cells
// given by their exact vertex coordinates (adapt::structure_instance_cells), so no vertex
// numbering enters.
#pragma once
#include "proofs-checks/generators.h"
#include "symmesh/adapt/template_cells.h"
#include "symmesh/adapt/vertex_insertion.h"
#include "symmesh/core/interface_conformity.h"

#include <utility>
#include <vector>

namespace symmesh::proofs::adaptation {

using gen::Structure;

template <int D>
bool is_templated_mesh(const Structure<D>& x) {
  if (!x.is_well_formed() || core::find_instance_overlap(x)) return false;
  const auto si = core::apply_template(x);
  return core::check_interface_conformity(x, si).holds && core::structure_instance_conforming(si);
}

/// A boundary facet of template i whose image under instance `own` is a face of a cell of
/// another instance: that cell's vertex off the facet, in AT's coordinates.
template <int D>
struct InterfaceFacet {
  std::size_t i;
  core::Simplex facet;
  core::InstanceId own;
  gen::Point<D> neighbour_apex;
};

/// Every template boundary facet that lies in an instance interface, once (its first instance
/// and neighbouring cell in AT's order).
template <int D>
std::vector<InterfaceFacet<D>> interface_neighbours(const Structure<D>& x) {
  const auto si = core::apply_template(x);
  std::vector<InterfaceFacet<D>> out;
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    for (const auto& f : adapt::boundary_facets(x.templates[i].mesh)) {
      bool found = false;
      for (std::size_t k = 0; k < si.ids.size() && !found; ++k) {
        if (si.ids[k].i != i) continue;
        std::vector<core::VertexId> g;
        for (core::VertexId v : f) g.push_back(si.vertex_map[k][v]);
        const auto image = adapt::simplex_of(g);
        for (std::size_t l = 0; l < si.ids.size() && !found; ++l) {
          if (l == k) continue;
          for (const auto& c : si.instance_elements[l])
            if (c.dim() == D && image.is_face_of(c)) {
              out.push_back(
                  {i, f, si.ids[k], si.at.mesh.points[adapt::opposite_vertices(c, image)[0]]});
              found = true;
              break;
            }
        }
      }
    }
  return out;
}

/// The boundary facets of templates that lie in an instance interface: (template, facet).
template <int D>
std::vector<std::pair<std::size_t, core::Simplex>> interface_facets(const Structure<D>& x) {
  std::vector<std::pair<std::size_t, core::Simplex>> out;
  for (const auto& n : interface_neighbours<D>(x)) out.push_back({n.i, n.facet});
  return out;
}

/// The exact centroid of template i's simplex s.
template <int D>
gen::Point<D> centroid(const Structure<D>& x, std::size_t i, const core::Simplex& s) {
  gen::Point<D> c;
  for (int d = 0; d < D; ++d) c[d] = Exact(0);
  for (core::VertexId v : s)
    for (int d = 0; d < D; ++d) c[d] += x.templates[i].mesh.points[v][d];
  for (int d = 0; d < D; ++d) c[d] /= Exact(int(s.n));
  return c;
}

/// A random point of the open simplex s of template i: barycentric weights 1..4 (not all equal
/// in general, so the point is not the centroid).
template <int D>
gen::Point<D> random_inner_point(const Structure<D>& x, std::size_t i, const core::Simplex& s) {
  gen::Point<D> c;
  for (int d = 0; d < D; ++d) c[d] = Exact(0);
  int total = 0;
  for (core::VertexId v : s) {
    const int w = *rc::gen::inRange<int>(1, 5);
    total += w;
    for (int d = 0; d < D; ++d) c[d] += Exact(w) * x.templates[i].mesh.points[v][d];
  }
  for (int d = 0; d < D; ++d) c[d] /= Exact(total);
  return c;
}

/// The input of an adaptation property after 1-3 random adaptation steps of Section 5.2.4: a
/// random inner point of a random cell inserted, and sometimes a random point of an instance
/// interface facet inserted at every related facet. The generators' meshes have few interior
/// vertices and are often Delaunay already; these steps give smoothing and Technique 5.8 work.
template <int D>
Structure<D> with_random_insertions(Structure<D> x) {
  const int steps = *rc::gen::inRange<int>(1, 4);
  for (int k = 0; k < steps; ++k) {
    const auto i = std::size_t(*rc::gen::inRange<int>(0, int(x.templates.size())));
    const auto cells = x.templates[i].mesh.cells();
    const auto c = cells[std::size_t(*rc::gen::inRange<int>(0, int(cells.size())))];
    adapt::insert_interior_vertex(x, i, random_inner_point<D>(x, i, c));
  }
  if (*rc::gen::arbitrary<bool>()) {
    const auto facets = interface_facets<D>(x);
    if (!facets.empty()) {
      const auto [i, f] = facets[std::size_t(*rc::gen::inRange<int>(0, int(facets.size())))];
      adapt::insert_boundary_vertex(x, i, random_inner_point<D>(x, i, f));
    }
  }
  return x;
}

/// AT(x)'s cells with, at every instance of template i, the images of `removed` replaced by the
/// images of `added` (template vertex ids of template i in `points`): the operation done on AT.
template <int D>
adapt::CellSet<Exact, D> at_with_replaced_cells(const Structure<D>& x, std::size_t i,
                                                const std::vector<gen::Point<D>>& points,
                                                const std::vector<core::Simplex>& removed,
                                                const std::vector<core::Simplex>& added) {
  auto cells = adapt::structure_instance_cells(x);
  for (const auto& s : x.instances[i]) {
    const auto image = [&](const core::Simplex& c) {
      std::vector<gen::Point<D>> p;
      for (core::VertexId v : c) p.push_back(s.transformation(points[v]));
      return adapt::sorted_points<Exact, D>(std::move(p));
    };
    for (const auto& c : removed) {
      const auto it = cells.find(image(c));
      if (it == cells.end()) return {}; // an empty set never equals a templated mesh's AT
      cells.erase(it);
    }
    for (const auto& c : added) cells.insert(image(c));
  }
  return cells;
}

} // namespace symmesh::proofs::adaptation
