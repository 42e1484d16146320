/// Definition 2.21 (Delaunay, strongly Delaunay, locally Delaunay), Lemma 2.5 and
/// Definition 4.10 (template-aware locally Delaunay) — spec/definitions.md#def-2-21, #def-4-10
///
/// The circumballs of a k-simplex S are the balls centred on the (D-k)-flat of points equidistant
/// from S's vertices. "Some circumball of S avoids the vertex set V" is therefore a linear
/// feasibility problem in the centre c: |v-c|^2 >= |a_0-c|^2 is 2(a_0-v)·c >= |a_0|^2-|v|^2.
/// Open balls give >=, closed balls give > (strict feasibility); both are decided exactly.
#pragma once
#include "symmesh/core/element_complex.h"

#include <set>

namespace symmesh::core {

template <class FT, int D>
FeasibilityResult circumball_avoiding(const std::vector<Point<FT, D>>& s,
                                      const std::vector<Point<FT, D>>& avoid) {
  std::vector<LinearRow<FT>> rows;
  const auto& a0 = s[0];
  const FT n0 = dot<FT, D>(a0, a0);
  for (std::size_t i = 1; i < s.size(); ++i) { // equidistant from every vertex of S
    LinearRow<FT> r;
    r.a.resize(D);
    for (int d = 0; d < D; ++d) r.a[d] = FT(2) * (a0[d] - s[i][d]);
    r.b = n0 - dot<FT, D>(s[i], s[i]);
    r.equal = true;
    rows.push_back(r);
  }
  for (const auto& v : avoid) {
    LinearRow<FT> r;
    r.a.resize(D);
    for (int d = 0; d < D; ++d) r.a[d] = FT(2) * (a0[d] - v[d]);
    r.b = n0 - dot<FT, D>(v, v);
    rows.push_back(r);
  }
  return feasibility<FT>(rows, D);
}

/// All vertices of m that are not vertices of s.
template <class FT, int D>
std::vector<Point<FT, D>> other_vertices(const ElementComplex<FT, D>& m, const Simplex& s,
                                         const std::set<VertexId>& among) {
  std::vector<Point<FT, D>> out;
  for (VertexId v : among)
    if (!s.has_vertex(v)) out.push_back(m.points[v]);
  return out;
}

template <class FT, int D>
std::set<VertexId> used_vertices(const ElementComplex<FT, D>& m) {
  std::set<VertexId> out;
  for (const auto& e : m.elements)
    for (VertexId v : e) out.insert(v);
  return out;
}

/// S is Delaunay in M: some open circumball of S contains no vertex of M.
template <class FT, int D>
bool is_delaunay_in(const ElementComplex<FT, D>& m, const Simplex& s) {
  return circumball_avoiding<FT, D>(m.coords(s), other_vertices(m, s, used_vertices(m))).feasible;
}

/// S is strongly Delaunay in M: some closed circumball of S contains no vertex of M but S's own.
template <class FT, int D>
bool is_strongly_delaunay_in(const ElementComplex<FT, D>& m, const Simplex& s) {
  auto others = other_vertices(m, s, used_vertices(m));
  return circumball_avoiding<FT, D>(m.coords(s), others).strictly_feasible;
}

/// Facet F is locally Delaunay in M: some open circumball of F contains no vertex of F's
/// co-face cells.
template <class FT, int D>
bool is_locally_delaunay_in(const ElementComplex<FT, D>& m, const Simplex& f) {
  std::set<VertexId> around;
  for (const auto& c : coface_cells(m, f))
    for (VertexId v : c) around.insert(v);
  return circumball_avoiding<FT, D>(m.coords(f), other_vertices(m, f, around)).feasible;
}

/// M is Delaunay: all cells are Delaunay in M (Def 2.21).
template <class FT, int D>
bool is_delaunay_mesh(const ElementComplex<FT, D>& m) {
  for (const auto& c : m.cells())
    if (!is_delaunay_in(m, c)) return false;
  return true;
}

template <class FT, int D>
bool all_facets_delaunay(const ElementComplex<FT, D>& m) {
  for (const auto& f : m.elements_of_dimension(m.cell_dimension() - 1))
    if (!is_delaunay_in(m, f)) return false;
  return true;
}

template <class FT, int D>
bool all_facets_locally_delaunay(const ElementComplex<FT, D>& m) {
  for (const auto& f : m.elements_of_dimension(m.cell_dimension() - 1))
    if (!is_locally_delaunay_in(m, f)) return false;
  return true;
}

} // namespace symmesh::core
