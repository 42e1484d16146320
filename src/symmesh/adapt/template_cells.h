/// Cell-level access to a mesh template for the adaptation operations of Section 5.2 —
/// spec/adaptation.md#template-cells
///
/// The exact core stores a mesh as a face-complete set of unoriented simplices. Adaptation
/// changes cells; these helpers read a template's cells and facets, decide orientation signs
/// exactly, and rebuild the face-complete complex from a changed cell list, so that no operation
/// has to keep lower-dimensional faces in step by hand.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/templated_structure.h"

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::adapt {

using core::ElementComplex;
using core::InstanceId;
using core::Point;
using core::Simplex;
using core::TemplatedStructure;
using core::VertexId;

/// The mesh over `points` whose cells are `cells`: every face of every cell is an element.
template <class FT, int D>
ElementComplex<FT, D> complex_of_cells(std::vector<Point<FT, D>> points,
                                       const std::vector<Simplex>& cells) {
  ElementComplex<FT, D> m;
  m.points = std::move(points);
  for (const auto& c : cells)
    for (const auto& f : core::faces(c)) m.elements.push_back(f);
  m.normalize();
  return m;
}

/// The cells (D-simplices) of m that have s as a face.
template <class FT, int D>
std::vector<Simplex> co_cells(const ElementComplex<FT, D>& m, const Simplex& s) {
  std::vector<Simplex> out;
  for (const auto& e : m.elements)
    if (e.dim() == D && s.is_face_of(e)) out.push_back(e);
  return out;
}

/// Facets of m in exactly one cell: bnd(m) for a pure D-mesh.
template <class FT, int D>
std::vector<Simplex> boundary_facets(const ElementComplex<FT, D>& m) {
  std::map<Simplex, int> count;
  for (const auto& e : m.elements)
    if (e.dim() == D)
      for (const auto& f : core::facets(e)) ++count[f];
  std::vector<Simplex> out;
  for (const auto& [f, n] : count)
    if (n == 1) out.push_back(f);
  return out;
}

/// Whether s (any dimension) is a face of some boundary facet of m.
template <class FT, int D>
bool on_boundary(const ElementComplex<FT, D>& m, const Simplex& s) {
  for (const auto& f : boundary_facets(m))
    if (s.is_face_of(f)) return true;
  return false;
}

/// Sign of det(p_1 − p_0, …, p_D − p_0), exactly: +1, −1, or 0 for a flat simplex.
/// \pre p.size() == D + 1
template <class FT, int D>
int orientation(const std::vector<Point<FT, D>>& p) {
  if (p.size() != std::size_t(D + 1)) throw std::invalid_argument("orientation needs D + 1 points");
  const FT v = core::signed_volume_times_factorial<FT, D>(p);
  return v > 0 ? 1 : v < 0 ? -1 : 0;
}

/// The simplex on the given vertex ids (any order).
inline Simplex simplex_of(const std::vector<VertexId>& ids) {
  return Simplex::from_range(ids.data(), ids.data() + ids.size());
}

/// The vertices of cell c other than those of its face f, in c's order.
inline std::vector<VertexId> opposite_vertices(const Simplex& c, const Simplex& f) {
  std::vector<VertexId> out;
  for (VertexId v : c)
    if (!f.has_vertex(v)) out.push_back(v);
  return out;
}

/// Template i's cells with `removed` taken out and `added` put in; the template keeps its
/// points (ids stay valid) and its complex is rebuilt from the cells.
/// \pre every removed simplex is a cell of template i
template <class FT, int D>
void replace_cells(TemplatedStructure<FT, D>& x, std::size_t i, const std::vector<Simplex>& removed,
                   const std::vector<Simplex>& added) {
  auto& m = x.templates.at(i).mesh;
  std::set<Simplex> cells;
  for (const auto& e : m.elements)
    if (e.dim() == D) cells.insert(e);
  for (const auto& r : removed)
    if (!cells.erase(r)) throw std::invalid_argument("replace_cells: not a cell of the template");
  for (const auto& a : added) cells.insert(a);
  m = complex_of_cells<FT, D>(std::move(m.points), {cells.begin(), cells.end()});
}

/// The cells of a structure instance as point sets, independent of vertex numbering: the
/// "AT equals" comparisons of the adaptation properties.
template <class FT, int D>
using CellSet = std::multiset<std::vector<Point<FT, D>>>;

template <class FT, int D>
std::vector<Point<FT, D>> sorted_points(std::vector<Point<FT, D>> p) {
  std::sort(p.begin(), p.end(), core::PointLess<FT, D>());
  return p;
}

/// Every instance's image of every cell (cells met by two instances appear twice: a multiset
/// sees overlapping instances).
template <class FT, int D>
CellSet<FT, D> structure_instance_cells(const TemplatedStructure<FT, D>& x) {
  CellSet<FT, D> out;
  for (const auto id : x.instance_ids()) {
    const auto& m = x.templates[id.i].mesh;
    const auto& t = x.tf(id);
    for (const auto& e : m.elements)
      if (e.dim() == D) {
        std::vector<Point<FT, D>> p;
        for (VertexId v : e) p.push_back(t(m.points[v]));
        out.insert(sorted_points<FT, D>(std::move(p)));
      }
  }
  return out;
}

} // namespace symmesh::adapt
