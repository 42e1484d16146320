/// Definition 2.24 (Edge-protected) — spec/definitions.md#def-2-24
///
/// An element space E is edge-protected if every line L ∈ elem_1(E) (Def A.7) is strongly
/// Delaunay (Def 2.21). For a mesh, "strongly Delaunay" is meant in the mesh; for a PLC P (the
/// use in Lemma 2.7, as in Shewchuk's CDT theorem) it is meant with respect to the vertices of P:
/// some closed circumball of the segment contains no vertex of P but its two end points.
/// A 1-cell of P is a path of collinear carrier edges; the line is the segment between its ends.
#pragma once
#include "symmesh/core/delaunay.h"
#include "symmesh/core/plc.h"

#include <map>
#include <ostream>

namespace symmesh::core {

/// The segment [a, b] is strongly Delaunay among `vertices` (a and b among them or not).
template <class FT, int D>
bool strongly_delaunay_among(const Point<FT, D>& a, const Point<FT, D>& b,
                             const std::vector<Point<FT, D>>& vertices) {
  std::vector<Point<FT, D>> others;
  for (const auto& v : vertices)
    if (v != a && v != b) others.push_back(v);
  return circumball_avoiding<FT, D>({a, b}, others).strictly_feasible;
}

/// The two ends of a 1-cell (the carrier vertices of degree one).
/// \pre p.cells[c] is a 1-cell of a valid PLC
template <class FT, int D>
std::pair<VertexId, VertexId> segment_ends(const Plc<FT, D>& p, std::size_t c) {
  std::map<VertexId, int> degree;
  for (const auto& s : p.cells.at(c).pieces)
    for (VertexId v : s) ++degree[v];
  std::vector<VertexId> ends;
  for (const auto& [v, k] : degree)
    if (k == 1) ends.push_back(v);
  if (ends.size() != 2) throw std::invalid_argument("segment_ends: not a path with two ends");
  return {ends[0], ends[1]};
}

/// Def 2.24 for a PLC: every 1-cell is strongly Delaunay with respect to the vertices of P.
/// `why` names the first segment that is not.
template <class FT, int D>
bool is_edge_protected(const Plc<FT, D>& p, std::ostream* why = nullptr) {
  const auto verts = p.vertex_points();
  for (std::size_t c : p.cells_of_dimension(1)) {
    const auto [a, b] = segment_ends(p, c);
    if (!strongly_delaunay_among<FT, D>(p.carrier.points[a], p.carrier.points[b], verts)) {
      if (why)
        *why << "segment " << c << " (vertices " << a << ", " << b << ") is not strongly Delaunay";
      return false;
    }
  }
  return true;
}

/// Def 2.24 for an element space stored as a complex: every edge is strongly Delaunay in it.
template <class FT, int D>
bool is_edge_protected(const ElementComplex<FT, D>& m) {
  for (const auto& e : m.elements_of_dimension(1))
    if (!is_strongly_delaunay_in(m, e)) return false;
  return true;
}

} // namespace symmesh::core
