/// Definition 2.3 (Piecewise linear complex, PLC) and the multi-region PLC (P, ξ̃) of Lemma 2.7
/// — spec/definitions.md#def-2-3
///
/// Representation (combinatorics apart from geometry): one carrier, a face-complete conforming
/// simplicial complex over a point array, and the PLC's elements on it —
///  - the 0-cells (vertices of P), carrier vertices listed in `vertices`;
///  - the k-cells, 1 <= k <= D, each the union of some k-simplices of the carrier (its `pieces`);
///    a D-cell carries the region id ξ̃ of the multi-region PLC.
/// The carrier may have points that are no vertex of P (Steiner points a polyhedron like
/// Schönhardt's needs to be triangulated at all); they are part of the representation only.
/// Because the carrier is conforming, intersections of elements are computed on it exactly and
/// combinatorially: us(K_1) ∩ us(K_2) = us(K_1 ∩ K_2) for subcomplexes of one complex.
///
/// Conditions of Def 2.3, computable form (checked by `is_valid`):
///  (i)   every k-cell is a linear k-cell: its pieces are k-simplices of the carrier spanning one
///        k-flat;
///  (ii)  the 0- and 1-cells form a face-complete element complex: a 1-cell is a path of
///        collinear carrier edges from one vertex of P to another with no vertex of P inside, and
///        two 1-cells meet at most in common end points;
///  (iii) the relative boundary of every k-cell (k >= 1) is a union of (k-1)-cells of P: the
///        carrier (k-1)-simplices with exactly one co-face piece are covered by (k-1)-cells whose
///        pieces all lie on that boundary (for k = 1: both ends are vertices of P);
///  (iv)  the intersection of two different cells is a union of elements of P of dimension
///        <= the smaller dimension; two different cells of one dimension k share no k-piece.
/// `is_multi_region` adds what (P, ξ̃) needs: at least one D-cell, and every vertex and every
/// lower-dimensional cell lies in the union of the D-cells (so us(P) is a D-dimensional
/// multi-region geometry, Def 2.2, whose regions are the D-cells with equal ids).
#pragma once
#include "symmesh/core/multi_region_geometry.h"
#include "symmesh/core/multi_region_mesh.h"

#include <algorithm>
#include <map>
#include <ostream>
#include <set>
#include <vector>

namespace symmesh::core {

/// One k-cell of a PLC, 1 <= k <= D.
struct PlcCell {
  int dimension = 1;
  std::vector<Simplex> pieces; ///< carrier k-simplices whose union is the cell
  int region = 0;              ///< ξ̃ of a D-cell (>= 1); 0 for lower-dimensional cells
};

template <class FT, int D>
struct Plc {
  using PointT = Point<FT, D>;
  ElementComplex<FT, D> carrier;  ///< face-complete and conforming
  std::vector<VertexId> vertices; ///< the 0-cells, sorted
  std::vector<PlcCell> cells;     ///< the k-cells, k >= 1

  bool is_vertex(VertexId v) const {
    return std::binary_search(vertices.begin(), vertices.end(), v);
  }
  std::vector<PointT> vertex_points() const {
    std::vector<PointT> out;
    for (VertexId v : vertices) out.push_back(carrier.points.at(v));
    return out;
  }
  /// The carrier subcomplex of cell c: its pieces and all their faces.
  ElementComplex<FT, D> cell_complex(std::size_t c) const {
    ElementComplex<FT, D> out;
    out.points = carrier.points;
    for (const auto& s : cells.at(c).pieces)
      for (const auto& f : faces(s)) out.elements.push_back(f);
    out.normalize();
    return out;
  }
  std::vector<std::size_t> cells_of_dimension(int k) const {
    std::vector<std::size_t> out;
    for (std::size_t c = 0; c < cells.size(); ++c)
      if (cells[c].dimension == k) out.push_back(c);
    return out;
  }
  std::set<int> region_ids() const {
    std::set<int> out;
    for (const auto& c : cells)
      if (c.dimension == D) out.insert(c.region);
    return out;
  }
  /// The multi-region geometry (Def 2.2) that (P, ξ̃) represents: the D-cells by region.
  MultiRegionGeometry<FT, D> geometry() const {
    MultiRegionGeometry<FT, D> g;
    g.carrier.points = carrier.points;
    for (const auto& c : cells)
      if (c.dimension == D)
        for (const auto& s : c.pieces) {
          g.cell_region[s] = c.region;
          for (const auto& f : faces(s)) g.carrier.elements.push_back(f);
        }
    g.carrier.normalize();
    return g;
  }
  /// us(P) restricted to the D-cells, as one complex.
  ElementComplex<FT, D> domain() const { return geometry().carrier; }

  bool is_valid(std::ostream* why = nullptr) const;
  bool is_multi_region(std::ostream* why = nullptr) const;
};

namespace detail {

/// The maximal simplices of a complex (those that are a face of no other element).
template <class FT, int D>
std::vector<Simplex> maximal_simplices(const ElementComplex<FT, D>& k) {
  std::vector<Simplex> out;
  for (const auto& e : k.elements) {
    bool maximal = true;
    for (const auto& g : k.elements)
      if (g.n > e.n && e.is_face_of(g)) {
        maximal = false;
        break;
      }
    if (maximal) out.push_back(e);
  }
  return out;
}

/// The (k-1)-simplices of a pure k-dimensional set of pieces with exactly one co-face piece.
inline std::vector<Simplex> relative_boundary_facets(const std::vector<Simplex>& pieces) {
  std::map<Simplex, int> count;
  for (const auto& s : pieces)
    for (const auto& f : facets(s)) ++count[f];
  std::vector<Simplex> out;
  for (const auto& [f, n] : count)
    if (n == 1) out.push_back(f);
  return out;
}

} // namespace detail

template <class FT, int D>
bool Plc<FT, D>::is_valid(std::ostream* why) const {
  auto fail = [&](const auto&... parts) {
    if (why) (*why << ... << parts);
    return false;
  };
  if (!is_face_complete(carrier, why) || !is_conforming(carrier, why)) return false;
  if (!std::is_sorted(vertices.begin(), vertices.end()) ||
      std::adjacent_find(vertices.begin(), vertices.end()) != vertices.end())
    return fail("the vertex list is not sorted and unique");
  for (VertexId v : vertices)
    if (!carrier.contains(Simplex{v})) return fail("vertex ", v, " is not a carrier vertex");
  // (i) linear k-cells
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const auto& cell = cells[c];
    if (cell.dimension < 1 || cell.dimension > D || cell.pieces.empty())
      return fail("cell ", c, " has dimension ", cell.dimension, " or no pieces (i)");
    if ((cell.dimension == D) != (cell.region >= 1))
      return fail("cell ", c, ": exactly the D-cells carry a region id >= 1");
    std::set<VertexId> used;
    for (const auto& s : cell.pieces) {
      if (s.dim() != cell.dimension || !carrier.contains(s))
        return fail("cell ", c, " has a piece that is no ", cell.dimension,
                    "-simplex of the carrier (i)");
      used.insert(s.begin(), s.end());
    }
    std::vector<PointT> pts;
    for (VertexId v : used) pts.push_back(carrier.points[v]);
    Matrix<FT> m;
    for (std::size_t i = 1; i < pts.size(); ++i) {
      std::vector<FT> row(D);
      for (int d = 0; d < D; ++d) row[d] = pts[i][d] - pts[0][d];
      m.push_back(row);
    }
    if (int(rank(m)) != cell.dimension)
      return fail("cell ", c, " does not lie in one ", cell.dimension, "-flat (i)");
  }
  // (ii) 1-cells: paths between vertices of P, no vertex of P inside, meeting only in ends
  std::vector<std::set<VertexId>> ends(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (cells[c].dimension != 1) continue;
    std::map<VertexId, int> degree;
    for (const auto& s : cells[c].pieces)
      for (VertexId v : s) ++degree[v];
    for (const auto& [v, k] : degree) {
      if (k > 2) return fail("1-cell ", c, " branches at a carrier vertex (ii)");
      if (k == 1) ends[c].insert(v);
      if (k == 2 && is_vertex(v))
        return fail("1-cell ", c, " has a vertex of P in its relative interior (ii)");
    }
    if (ends[c].size() != 2) return fail("1-cell ", c, " is not one path with two ends (ii)");
  }
  // (iii) boundaries are unions of (k-1)-cells
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const int k = cells[c].dimension;
    if (k == 1) {
      for (VertexId v : ends[c])
        if (!is_vertex(v)) return fail("an end of 1-cell ", c, " is no vertex of P (iii)");
      continue;
    }
    const auto bnd = detail::relative_boundary_facets(cells[c].pieces);
    const std::set<Simplex> bset(bnd.begin(), bnd.end());
    std::set<Simplex> covered;
    for (std::size_t q = 0; q < cells.size(); ++q) {
      if (cells[q].dimension != k - 1) continue;
      bool inside = true;
      for (const auto& s : cells[q].pieces) inside = inside && bset.count(s);
      if (inside) covered.insert(cells[q].pieces.begin(), cells[q].pieces.end());
    }
    if (covered.size() != bset.size())
      return fail("the relative boundary of ", k, "-cell ", c, " is not a union of ", k - 1,
                  "-cells of P (iii)");
  }
  // (iv) intersections are unions of lower-or-equal-dimensional elements
  std::vector<ElementComplex<FT, D>> complexes;
  for (std::size_t c = 0; c < cells.size(); ++c) complexes.push_back(cell_complex(c));
  for (std::size_t a = 0; a < cells.size(); ++a)
    for (std::size_t b = a + 1; b < cells.size(); ++b) {
      const auto common = intersection(complexes[a], complexes[b]);
      if (common.elements.empty()) continue;
      const int kmin = std::min(cells[a].dimension, cells[b].dimension);
      if (cells[a].dimension == cells[b].dimension && common.cell_dimension() == kmin)
        return fail(kmin, "-cells ", a, " and ", b, " share a ", kmin, "-piece (iv)");
      const std::set<Simplex> cset(common.elements.begin(), common.elements.end());
      for (const auto& s : detail::maximal_simplices(common)) {
        bool ok = s.n == 1 && is_vertex(s.v[0]);
        for (std::size_t q = 0; q < cells.size() && !ok; ++q) {
          if (cells[q].dimension > kmin) continue;
          if (!complexes[q].contains(s)) continue;
          bool inside = true;
          for (const auto& e : complexes[q].elements) inside = inside && cset.count(e);
          ok = inside;
        }
        if (!ok)
          return fail("cells ", a, " and ", b, " meet in a set that is no union of elements of P",
                      " (iv)");
      }
    }
  return true;
}

template <class FT, int D>
bool Plc<FT, D>::is_multi_region(std::ostream* why) const {
  if (!is_valid(why)) return false;
  const auto g = geometry();
  if (g.cell_region.empty()) {
    if (why) *why << "a multi-region PLC needs D-cells";
    return false;
  }
  // g's carrier is a subcomplex of the (conforming, face-complete) carrier and pure by
  // construction, every D-piece has its region: Def 2.2 (i), (ii) hold (multi_region_geometry.h)
  // On the conforming carrier the relative interiors of its elements are disjoint and us(g) is
  // the union of the relative interiors of g's elements, so a carrier simplex lies in us(g) iff
  // it is an element of g: the test is combinatorial and exact.
  for (VertexId v : vertices)
    if (!g.carrier.contains(Simplex{v})) {
      if (why) *why << "vertex " << v << " lies outside the D-cells";
      return false;
    }
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (cells[c].dimension == D) continue;
    for (const auto& s : cells[c].pieces)
      if (!g.carrier.contains(s)) {
        if (why) *why << "cell " << c << " leaves the union of the D-cells";
        return false;
      }
  }
  return true;
}

/// The PLC of a multi-region mesh (M, ξ): its vertices, a D-cell per region, the boundary and
/// interface facets as (D-1)-cells (in 3D, coplanar neighbours with the same co-face regions
/// merged into one polygonal facet when `merge_coplanar`), and in 3D the edges on the relative
/// boundaries of those facets as 1-cells. M is then a triangulation of this PLC.
/// \pre m.is_valid() and DIM_cell(M) = D
template <class FT, int D>
Plc<FT, D> plc_of_multi_region_mesh(const MultiRegionMesh<FT, D>& m, bool merge_coplanar = true) {
  Plc<FT, D> p;
  p.carrier = m.mesh;
  for (const auto& e : m.mesh.elements)
    if (e.n == 1) p.vertices.push_back(e.v[0]);
  std::sort(p.vertices.begin(), p.vertices.end());
  for (int r : m.region_ids()) {
    PlcCell c;
    c.dimension = D;
    c.region = r;
    for (const auto& [s, id] : m.cell_region)
      if (id == r) c.pieces.push_back(s);
    p.cells.push_back(c);
  }
  // facets on the boundary or between regions, keyed by the regions of their co-face cells
  std::map<Simplex, std::vector<int>> around;
  for (const auto& [s, id] : m.cell_region)
    for (const auto& f : facets(s)) around[f].push_back(id);
  std::vector<Simplex> constrained;
  std::vector<std::vector<int>> key;
  for (auto& [f, ids] : around) {
    std::sort(ids.begin(), ids.end());
    if (ids.size() == 1 || ids.front() != ids.back()) {
      constrained.push_back(f);
      key.push_back(ids);
    }
  }
  // group facets: union-find over shared (D-2)-faces, same key, coplanar (3D only)
  std::vector<std::size_t> parent(constrained.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  if (D == 3 && merge_coplanar) {
    std::map<Simplex, std::vector<std::size_t>> by_edge;
    for (std::size_t i = 0; i < constrained.size(); ++i)
      for (const auto& e : facets(constrained[i])) by_edge[e].push_back(i);
    for (const auto& [e, list] : by_edge) {
      if (list.size() != 2) continue; // a facet edge met by three or more facets stays a segment
      const std::size_t a = list[0], b = list[1];
      if (key[a] != key[b]) continue;
      std::set<VertexId> four(constrained[a].begin(), constrained[a].end());
      four.insert(constrained[b].begin(), constrained[b].end());
      std::vector<Point<FT, D>> pts;
      for (VertexId v : four) pts.push_back(m.mesh.points[v]);
      if (affinely_independent<FT, D>(pts)) continue; // not coplanar
      parent[find(a)] = find(b);
    }
  }
  std::map<std::size_t, PlcCell> groups;
  for (std::size_t i = 0; i < constrained.size(); ++i) {
    auto& g = groups[find(i)];
    g.dimension = D - 1;
    g.pieces.push_back(constrained[i]);
  }
  std::set<Simplex> segments;
  for (auto& [root, g] : groups) {
    std::sort(g.pieces.begin(), g.pieces.end());
    if (D == 3)
      for (const auto& e : detail::relative_boundary_facets(g.pieces)) segments.insert(e);
    p.cells.push_back(g);
  }
  for (const auto& e : segments) {
    PlcCell c;
    c.dimension = 1;
    c.pieces = {e};
    p.cells.push_back(c);
  }
  return p;
}

} // namespace symmesh::core
