/// Definition 2.23 (Constrained Delaunay) and the three statements of Lemma 2.6 (Constrained
/// Delaunay Lemma) — spec/definitions.md#def-2-23, spec/lemmas.md#lemma-2-6
///
/// Let P be a PLC and M a simplex mesh that respects and geometry-conforms to P. A simplex S of M
/// is constrained Delaunay if all its vertices are vertices of P and some open circumball of S
/// contains only vertices of M that are not visible (Def 2.22) from any point of relint S. M is
/// constrained Delaunay if every cell is.
///
/// Computable form: the vertices of M visible from relint S are found by
/// `visible_from_relative_interior` (exact, see visibility.h); then "some open circumball avoids
/// them" is the exact LP of `circumball_avoiding` (delaunay.h). A simplex that is Delaunay in M
/// (its circumball avoids all vertices) is constrained Delaunay without any visibility test.
/// Visibility from relint S is computed for cells and for facets not included in a facet of P
/// (the only simplices Def 2.23 and Lemma 2.6 ask about); for those, relint S lies inside one
/// D-cell and meets no lower-dimensional element of P because M respects P.
#pragma once
#include "symmesh/core/geometry_conforming.h"
#include "symmesh/core/multi_region_geometry.h"
#include "symmesh/core/visibility.h"

#include <array>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

namespace symmesh::core {

/// M respects P (Def 2.9): every element of M respects every element of P.
/// Two reductions, both exact:
///  - checked on the cells: a face f of a cell E has f ∩ p = f ∩ (E ∩ p), an intersection of
///    faces of E, so it respects p when E does;
///  - an element p of P whose carrier pieces are all elements of M (as point tuples) is respected
///    by every element E of the conforming M: E ∩ p = ⋃ (E ∩ g) over the pieces g, and each
///    E ∩ g is a common face of E and g in M. Only the other elements are tested geometrically;
///  - the D-cells need no test once us(M) ⊆ us(P) and M respects the lower-dimensional
///    elements: then int E meets no element of dimension < D (E ∩ q would contain an interior
///    point of E, so E ⊆ q), hence, as the D-cells' boundaries are covered by (D-1)-cells
///    (Def 2.3 iii), the connected int E lies inside one D-cell p, so E ∩ p = E, and for every
///    other D-cell p', E ∩ p' ⊆ p ∩ p', a union of lower-dimensional elements q (Def 2.3 iv), so
///    E ∩ p' = ⋃ (E ∩ q) is a union of faces of E.
/// \pre M is conforming (is_mesh) and us(M) ⊆ us(P) (checked by the callers through
/// geometry_conforms before this)
template <class FT, int D>
bool mesh_respects_plc(const ElementComplex<FT, D>& m, const Plc<FT, D>& p) {
  std::map<Point<FT, D>, VertexId, PointLess<FT, D>> index;
  for (VertexId v = 0; v < m.points.size(); ++v) index.emplace(m.points[v], v);
  auto in_mesh = [&](const Simplex& s) { // s over P's carrier points is an element of M
    std::array<VertexId, 4> ids{};
    for (int i = 0; i < s.n; ++i) {
      const auto it = index.find(p.carrier.points[s.v[i]]);
      if (it == index.end()) return false;
      ids[i] = it->second;
    }
    return m.contains(Simplex::from_range(ids.data(), ids.data() + s.n));
  };
  std::vector<ElementComplex<FT, D>> others;
  for (VertexId v : p.vertices)
    if (!in_mesh(Simplex{v})) {
      ElementComplex<FT, D> vertex;
      vertex.points = p.carrier.points;
      vertex.elements = {Simplex{v}};
      others.push_back(vertex);
    }
  for (std::size_t c = 0; c < p.cells.size(); ++c) {
    if (p.cells[c].dimension == D) continue;
    bool all = true;
    for (const auto& s : p.cells[c].pieces) all = all && in_mesh(s);
    if (!all) others.push_back(p.cell_complex(c));
  }
  for (const auto& c : m.cells())
    for (const auto& k : others)
      if (!respects_plc_element<FT, D>(m.coords(c), k)) return false;
  return true;
}

/// Def 2.10 for a multi-region mesh and a multi-region geometry: the same region ids and
/// us(region((M, ξ), i)) = region((G, ξ̃), i) for each.
template <class FT, int D>
bool geometry_conforms(const MultiRegionMesh<FT, D>& m, const MultiRegionGeometry<FT, D>& g) {
  if (m.region_ids() != g.region_ids()) return false;
  for (int i : m.region_ids())
    if (!geometry_conforms(m.region(i), g.region(i))) return false;
  return true;
}

/// The vertices of M (used by some element) and the vertices of P are the same point sets.
template <class FT, int D>
bool same_vertices(const ElementComplex<FT, D>& m, const Plc<FT, D>& p) {
  std::set<Point<FT, D>, PointLess<FT, D>> a, b;
  for (VertexId v : used_vertices(m)) a.insert(m.points[v]);
  for (const auto& x : p.vertex_points()) b.insert(x);
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}

/// M is a triangulation of the PLC P (Shewchuk's sense, the hypothesis Lemma 2.6 needs,
/// spec/lemmas.md#lemma-2-6): a mesh with DIM_cell = D, vertices(M) = vertices(P), M respects P
/// and us(M) = us(P).
template <class FT, int D>
bool is_triangulation_of(const ElementComplex<FT, D>& m, const Plc<FT, D>& p,
                         std::ostream* why = nullptr) {
  if (!is_mesh(m, why)) return false;
  if (m.cell_dimension() != D) {
    if (why) *why << "DIM_cell(M) != " << D;
    return false;
  }
  if (!same_vertices(m, p)) {
    if (why) *why << "vertices(M) != vertices(P)";
    return false;
  }
  if (!geometry_conforms(m, p.domain())) {
    if (why) *why << "us(M) != us(P)";
    return false;
  }
  if (!mesh_respects_plc(m, p)) {
    if (why) *why << "M does not respect P";
    return false;
  }
  return true;
}

/// Def 2.23 and the statements of Lemma 2.6 for one PLC P and one mesh M.
template <class FT, int D>
class ConstrainedDelaunay {
public:
  using PointT = Point<FT, D>;

  /// \pre P is a multi-region PLC (Plc::is_multi_region), M a mesh with DIM_cell(M) = D that
  /// respects P and geometry-conforms to it (us(M) = us(P)); checked, std::invalid_argument.
  ConstrainedDelaunay(const Plc<FT, D>& p, const ElementComplex<FT, D>& m) : m_(m) {
    std::ostringstream why;
    if (!p.is_multi_region(&why))
      throw std::invalid_argument("ConstrainedDelaunay: P is not a multi-region PLC: " + why.str());
    if (!is_mesh(m, &why) || m.cell_dimension() != D)
      throw std::invalid_argument("ConstrainedDelaunay: M is no D-dimensional mesh " + why.str());
    if (!geometry_conforms(m, p.domain()))
      throw std::invalid_argument("ConstrainedDelaunay: M does not geometry-conform to P");
    if (!mesh_respects_plc(m, p))
      throw std::invalid_argument("ConstrainedDelaunay: M does not respect P");
    for (const auto& x : p.vertex_points()) plc_vertices_.insert(x);
    blockers_ = visibility_blockers(p);
    for (const auto& f : p.cells_of_dimension(D - 1)) plc_facets_.push_back(p.cell_complex(f));
  }

  /// F is included in some facet ((D-1)-cell) of P.
  bool in_plc_facet(const Simplex& f) const {
    const auto fp = m_.coords(f);
    for (const auto& k : plc_facets_)
      if (simplex_covered_by<FT, D>(fp, k)) return true;
    return false;
  }

  /// The vertices of M other than S's own that are visible from some point of relint S.
  /// \pre S is a cell of M, or a facet of M not included in a facet of P
  std::vector<PointT> visible_vertices(const Simplex& s) const {
    check_asked(s);
    std::vector<PointT> out;
    const auto sp = m_.coords(s);
    for (const auto& v : other_vertices(m_, s, used_vertices(m_)))
      if (visible_from_relative_interior<FT, D>(sp, v, blockers_)) out.push_back(v);
    return out;
  }

  /// Def 2.23 for a cell of M or a facet of M not included in a facet of P.
  bool is_constrained_delaunay(const Simplex& s) const {
    check_asked(s);
    for (VertexId v : s)
      if (!plc_vertices_.count(m_.points[v])) return false;
    const auto sp = m_.coords(s);
    auto others = other_vertices(m_, s, used_vertices(m_));
    if (circumball_avoiding<FT, D>(sp, others).feasible) return true; // Delaunay in M
    std::vector<PointT> candidates = others;
    if (s.dim() == D) { // the circumball is unique: only the vertices inside it matter
      candidates.clear();
      for (const auto& v : others)
        if (!circumball_avoiding<FT, D>(sp, {v}).feasible) candidates.push_back(v);
    }
    std::vector<PointT> seen;
    for (const auto& v : candidates)
      if (visible_from_relative_interior<FT, D>(sp, v, blockers_)) seen.push_back(v);
    return circumball_avoiding<FT, D>(sp, seen).feasible;
  }

  /// Lemma 2.6 (first statement): every cell of M is constrained Delaunay.
  bool mesh_is_constrained_delaunay() const {
    for (const auto& c : m_.cells())
      if (!is_constrained_delaunay(c)) return false;
    return true;
  }

  /// The facets of M not included in any facet of P.
  std::vector<Simplex> free_facets() const {
    std::vector<Simplex> out;
    for (const auto& f : m_.elements_of_dimension(D - 1))
      if (!in_plc_facet(f)) out.push_back(f);
    return out;
  }

  /// Lemma 2.6 (second statement).
  bool free_facets_constrained_delaunay() const {
    for (const auto& f : free_facets())
      if (!is_constrained_delaunay(f)) return false;
    return true;
  }

  /// Lemma 2.6 (third statement).
  bool free_facets_locally_delaunay() const {
    for (const auto& f : free_facets())
      if (!is_locally_delaunay_in(m_, f)) return false;
    return true;
  }

private:
  void check_asked(const Simplex& s) const {
    if (!m_.contains(s)) throw std::invalid_argument("ConstrainedDelaunay: not a simplex of M");
    if (s.dim() == D) return;
    if (s.dim() == D - 1 && !in_plc_facet(s)) return;
    throw std::invalid_argument(
        "ConstrainedDelaunay: visibility from relint S is computed for cells and for facets not "
        "included in a facet of P only");
  }

  ElementComplex<FT, D> m_;
  std::set<PointT, PointLess<FT, D>> plc_vertices_;
  std::vector<std::vector<PointT>> blockers_;
  std::vector<ElementComplex<FT, D>> plc_facets_;
};

/// Lemma 2.7's conclusion for a multi-region mesh (M, ξ): (M, ξ) is a triangulation of the
/// vertices of (P, ξ̃) (a mesh with vertices(M) = vertices(P)), it respects P, geometry-conforms
/// to (P, ξ̃) region by region, and is constrained Delaunay. `why` names the first failure.
template <class FT, int D>
bool is_constrained_delaunay_triangulation(const MultiRegionMesh<FT, D>& m, const Plc<FT, D>& p,
                                           std::ostream* why = nullptr) {
  if (!m.is_valid(why)) return false;
  if (!same_vertices(m.mesh, p)) {
    if (why) *why << "vertices(M) != vertices(P)";
    return false;
  }
  std::optional<ConstrainedDelaunay<FT, D>> cd;
  try { // checks: P multi-region, M a D-mesh that respects P and has us(M) = us(P)
    cd.emplace(p, m.mesh);
  } catch (const std::invalid_argument& e) {
    if (why) *why << e.what();
    return false;
  }
  if (!geometry_conforms(m, p.geometry())) {
    if (why) *why << "(M, xi) does not geometry-conform to (P, xi~) region by region";
    return false;
  }
  for (const auto& c : m.mesh.cells())
    if (!cd->is_constrained_delaunay(c)) {
      if (why) *why << "a cell is not constrained Delaunay";
      return false;
    }
  return true;
}

} // namespace symmesh::core
