/// Section 5.2.2: vertex smoothing of template-interior vertices — spec/adaptation.md#smoothing
///
/// A vertex off the template boundary belongs to its template alone: moving it changes no
/// instance interface, so AT(Γ) changes by the same move at every instance (T_{i,g}(v) goes to
/// T_{i,g}(p)). A move is valid when every cell around the vertex keeps its exact, non-zero
/// orientation sign: the cells then still tile the vertex's star (no inversion, no flat cell).
/// Boundary vertices are not moved here: they may move only inside the intersection of their
/// boundary patches and together with every related vertex (Eq. 5.1), which needs the boundary
/// patch partition of the templated mesh (spec/adaptation.md#not-yet).
#pragma once
#include "symmesh/adapt/template_cells.h"

#include <string>
#include <vector>

namespace symmesh::adapt {

namespace detail {
/// Why moving vertex v of m to p would invert or flatten a cell around it, or "".
template <class FT, int D>
std::string orientation_refusal(const ElementComplex<FT, D>& m, VertexId v, const Point<FT, D>& p) {
  for (const auto& c : co_cells(m, simplex_of({v}))) {
    std::vector<Point<FT, D>> before, after;
    for (VertexId q : c) {
      before.push_back(m.points[q]);
      after.push_back(q == v ? p : m.points[q]);
    }
    const int a = orientation<FT, D>(before), b = orientation<FT, D>(after);
    if (b == 0 || a != b) return "the move would invert or flatten a cell around the vertex";
  }
  return "";
}
} // namespace detail

/// Why moving template i's vertex v to p is not valid, or "" when it is.
template <class FT, int D>
std::string vertex_move_refusal(const TemplatedStructure<FT, D>& x, std::size_t i, VertexId v,
                                const Point<FT, D>& p) {
  const auto& m = x.templates.at(i).mesh;
  if (v >= m.points.size()) return "no such vertex";
  const Simplex s = simplex_of({v});
  if (!m.contains(s)) return "the vertex is in no element";
  if (on_boundary(m, s)) return "the vertex is on the template boundary";
  return detail::orientation_refusal(m, v, p);
}

/// Moves template i's interior vertex v to p. \pre vertex_move_refusal(x, i, v, p) is empty
/// (else std::invalid_argument with the reason)
template <class FT, int D>
void move_vertex(TemplatedStructure<FT, D>& x, std::size_t i, VertexId v, const Point<FT, D>& p) {
  const auto why = vertex_move_refusal(x, i, v, p);
  if (!why.empty()) throw std::invalid_argument("move_vertex: " + why);
  x.templates[i].mesh.points[v] = p;
}

/// The centroid of v's neighbours (vertices sharing an edge with v), exactly.
template <class FT, int D>
Point<FT, D> neighbour_centroid(const ElementComplex<FT, D>& m, VertexId v) {
  Point<FT, D> sum;
  for (int d = 0; d < D; ++d) sum[d] = FT(0);
  int n = 0;
  for (const auto& e : m.elements)
    if (e.dim() == 1 && e.has_vertex(v)) {
      const VertexId w = e.v[0] == v ? e.v[1] : e.v[0];
      for (int d = 0; d < D; ++d) sum[d] += m.points[w][d];
      ++n;
    }
  if (n > 0)
    for (int d = 0; d < D; ++d) sum[d] /= FT(n);
  return sum;
}

/// `sweeps` passes of Laplacian smoothing over every template-interior vertex of every
/// template: each vertex goes to its neighbours' centroid when that move is valid, else stays.
/// Returns the number of moves made.
template <class FT, int D>
std::size_t smooth_interior_vertices(TemplatedStructure<FT, D>& x, int sweeps) {
  std::size_t moves = 0;
  for (int s = 0; s < sweeps; ++s)
    for (std::size_t i = 0; i < x.templates.size(); ++i) {
      const auto boundary = boundary_facets(x.templates[i].mesh);
      std::set<VertexId> fixed;
      for (const auto& f : boundary) fixed.insert(f.begin(), f.end());
      auto& m = x.templates[i].mesh;
      for (VertexId v = 0; v < m.points.size(); ++v) {
        if (fixed.count(v) || !m.contains(simplex_of({v}))) continue;
        const auto p = neighbour_centroid(m, v);
        if (p == m.points[v] || !detail::orientation_refusal(m, v, p).empty()) continue;
        m.points[v] = p;
        ++moves;
      }
    }
  return moves;
}

} // namespace symmesh::adapt
