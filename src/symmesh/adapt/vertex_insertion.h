/// Section 5.2.4: vertex insertion into mesh templates — spec/adaptation.md#insertion
///
/// A point strictly inside a template is inserted by splitting the cell (or the two or more cells
/// around the face) whose relative interior holds it: no boundary facet changes, so the
/// insertion is safe at every instance. A point on a template boundary facet lies in an instance
/// interface wherever another instance has that facet too: it must then be inserted into every
/// related facet, through the instances' transformations, and again from those templates'
/// other instances, until the set closes (the boundary patch relation of the inserted point).
/// Splitting a boundary facet adds no edge inside it other than those to the new point, so in 3D
/// the new edge configuration is the same on both sides of every interface (the unique one of
/// Section 5.2.4 for a single vertex). A cap on the number of insertions ends irregular cases in
/// an error instead of a loop.
#pragma once
#include "symmesh/adapt/template_cells.h"

#include <deque>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace symmesh::adapt {

/// The smallest element of m whose relative interior holds p (exact barycentric coordinates),
/// if p lies in us(m).
template <class FT, int D>
std::optional<Simplex> carrier_element(const ElementComplex<FT, D>& m, const Point<FT, D>& p) {
  for (int k = 0; k <= D; ++k)
    for (const auto& e : m.elements) {
      if (e.dim() != k) continue;
      const auto mu = core::barycentric<FT, D>(m.coords(e), p);
      if (!mu) continue;
      bool interior = true;
      for (const auto& c : *mu) interior = interior && c > 0;
      if (interior) return e;
    }
  return std::nullopt;
}

/// Inserts p into template i by splitting every cell around the element whose relative interior
/// holds p (each such cell c becomes the cells with one vertex of that element replaced by p).
/// Returns the new vertex id, or the existing id if p is a vertex already.
/// \pre p ∈ us(X_i) (else std::invalid_argument)
template <class FT, int D>
VertexId split_at(TemplatedStructure<FT, D>& x, std::size_t i, const Point<FT, D>& p) {
  auto& m = x.templates.at(i).mesh;
  const auto e = carrier_element(m, p);
  if (!e) throw std::invalid_argument("insert: the point is not in the template");
  if (e->dim() == 0) return e->v[0];
  const VertexId v = VertexId(m.points.size());
  m.points.push_back(p);
  const auto around = co_cells(m, *e);
  std::vector<Simplex> added;
  for (const auto& c : around)
    for (VertexId q : *e) {
      std::vector<VertexId> ids;
      for (VertexId r : c) ids.push_back(r == q ? v : r);
      added.push_back(simplex_of(ids));
    }
  replace_cells(x, i, around, added);
  return v;
}

/// Inserts a point strictly inside template i (not on its boundary).
/// \pre p lies in the interior of us(X_i) (else std::invalid_argument)
template <class FT, int D>
VertexId insert_interior_vertex(TemplatedStructure<FT, D>& x, std::size_t i,
                                const Point<FT, D>& p) {
  const auto& m = x.templates.at(i).mesh;
  const auto e = carrier_element(m, p);
  if (!e) throw std::invalid_argument("insert: the point is not in the template");
  if (on_boundary(m, *e))
    throw std::invalid_argument("insert: the point is on the template boundary; use "
                                "insert_boundary_vertex");
  return split_at(x, i, p);
}

/// The template-frame points that inserting template i's point p into its boundary needs, with
/// their templates: (i, p) and, closed under the relation, every T_{k,l}^{-1}(T_{j,h}(q)) that
/// lies on a boundary facet of X_k for an inserted (j, q) and any two instances (j, h), (k, l).
/// \pre at most `cap` points (else std::runtime_error naming the cap)
template <class FT, int D>
std::vector<std::pair<std::size_t, Point<FT, D>>>
related_boundary_points(const TemplatedStructure<FT, D>& x, std::size_t i, const Point<FT, D>& p,
                        std::size_t cap = 4096) {
  std::vector<ElementComplex<FT, D>> boundary;
  for (const auto& t : x.templates) {
    const auto facets = boundary_facets(t.mesh);
    boundary.push_back(complex_of_cells<FT, D>(t.mesh.points, facets));
  }
  // A point on a boundary facet of X_k: the (D-1)-complex of its boundary facets holds it.
  const auto on_template_boundary = [&](std::size_t k, const Point<FT, D>& q) {
    for (const auto& f : boundary[k].elements)
      if (f.dim() == D - 1 && core::point_in_simplex<FT, D>(boundary[k].coords(f), q)) return true;
    return false;
  };
  using Placed = std::pair<std::size_t, Point<FT, D>>;
  struct Less {
    bool operator()(const Placed& a, const Placed& b) const {
      if (a.first != b.first) return a.first < b.first;
      return core::PointLess<FT, D>()(a.second, b.second);
    }
  };
  std::vector<Placed> out{{i, p}};
  std::set<Placed, Less> seen;
  seen.insert(out[0]);
  for (std::size_t next = 0; next < out.size(); ++next) {
    const auto [j, q] = out[next];
    for (const auto& sj : x.instances[j]) {
      const auto world = sj.transformation(q);
      for (std::size_t k = 0; k < x.templates.size(); ++k)
        for (const auto& sk : x.instances[k]) {
          const auto r = sk.transformation.inverse()(world);
          if (!on_template_boundary(k, r) || !seen.insert({k, r}).second) continue;
          out.push_back({k, r});
          if (out.size() > cap)
            throw std::runtime_error("insert: more than " + std::to_string(cap) +
                                     " related boundary points (an irregular instance graph "
                                     "maps the point to ever new places)");
        }
    }
  }
  return out;
}

/// Section 5.2.4 on the boundary: inserts p (on a boundary facet of template i) into every
/// related boundary facet of every template, so that every instance interface stays conforming.
/// Returns the number of points inserted.
/// \pre p lies on the boundary of us(X_i) (else std::invalid_argument)
template <class FT, int D>
std::size_t insert_boundary_vertex(TemplatedStructure<FT, D>& x, std::size_t i,
                                   const Point<FT, D>& p) {
  const auto& m = x.templates.at(i).mesh;
  const auto e = carrier_element(m, p);
  if (!e || !on_boundary(m, *e))
    throw std::invalid_argument("insert: the point is not on the template boundary");
  std::size_t inserted = 0;
  for (const auto& [k, q] : related_boundary_points(x, i, p)) {
    const auto before = x.templates[k].mesh.points.size();
    split_at(x, k, q);
    inserted += x.templates[k].mesh.points.size() - before;
  }
  return inserted;
}

} // namespace symmesh::adapt
