/// The editable form of a templated mesh that the operations of `symmesh adapt` share
/// (Section 5.2, spec/adaptation.md#tmesh-adaptation): each template as coordinates, cells and
/// vertex-to-cell incidence (Work), all of them with the instances' transformations (Session),
/// and the geometric helpers the 2D and 3D operations both use. Internal to adapt/: the 2D
/// operations and the public entry points live in templated_mesh_adaptation.cpp, Technique 5.8
/// in 3D in technique_5_8_3d.cpp.
#pragma once
#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/mesh/progress.h"
#include "symmesh/mesh/templated_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace symmesh::adapt::work {
using mesh::IndexType;
using Cell = std::array<IndexType, 4>;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = Kernel::Point_2;
using P3 = Kernel::Point_3;

/// One template, editable: coordinates, cells (d + 1 vertices each) and vertex-to-cell incidence.
struct Work {
  int d = 2;
  std::vector<double> x;
  std::vector<Cell> cells;
  std::vector<std::vector<IndexType>> inc;

  std::size_t vertex_count() const { return x.size() / std::size_t(d); }
  const double* p(IndexType v) const { return &x[std::size_t(v) * std::size_t(d)]; }
  int arity() const { return d + 1; }
  bool has(const Cell& c, IndexType v) const {
    for (int k = 0; k < arity(); ++k)
      if (c[std::size_t(k)] == v) return true;
    return false;
  }
  /// The cells that contain every vertex of `verts`.
  std::vector<IndexType> cells_with(std::initializer_list<IndexType> verts) const {
    std::vector<IndexType> out;
    for (IndexType ci : inc[std::size_t(*verts.begin())]) {
      bool all = true;
      for (IndexType v : verts) all = all && has(cells[std::size_t(ci)], v);
      if (all) out.push_back(ci);
    }
    return out;
  }
  void set_cell(IndexType ci, const Cell& c) {
    auto& old = cells[std::size_t(ci)];
    for (int k = 0; k < arity(); ++k) {
      auto& list = inc[std::size_t(old[std::size_t(k)])];
      list.erase(std::find(list.begin(), list.end(), ci));
    }
    old = c;
    for (int k = 0; k < arity(); ++k) inc[std::size_t(c[std::size_t(k)])].push_back(ci);
  }
  IndexType add_cell(const Cell& c) {
    cells.push_back(c);
    const auto ci = IndexType(cells.size() - 1);
    for (int k = 0; k < arity(); ++k) inc[std::size_t(c[std::size_t(k)])].push_back(ci);
    return ci;
  }
  IndexType add_vertex(const double* q) {
    x.insert(x.end(), q, q + d);
    inc.emplace_back();
    return IndexType(vertex_count() - 1);
  }
};

/// The templates of a templated mesh, editable, and where each global instance comes from.
struct Session {
  mesh::TemplatedMeshCompactSvb& t;
  std::vector<Work> w;
  std::vector<std::size_t> template_of, local_of;

  explicit Session(mesh::TemplatedMeshCompactSvb& tm) : t(tm) {
    const int d = t.templated.point_dimension;
    if (d != 2 && d != 3) throw std::invalid_argument("adaptation needs a 2D or 3D mesh");
    const auto want = d == 2 ? mesh::ElementType::triangle : mesh::ElementType::tetrahedron;
    for (std::size_t i = 0; i < t.templated.templates.size(); ++i) {
      const auto& m = t.templated.templates[i].mesh;
      Work wk;
      wk.d = d;
      wk.x = m.vertex_coords;
      wk.inc.resize(wk.vertex_count());
      for (std::size_t c = 0; c < m.cell_count(); ++c) {
        if (m.cell_types[c] != want)
          throw std::invalid_argument("templates[" + std::to_string(i) + "].cells[" +
                                      std::to_string(c) + "]: not a " +
                                      (d == 2 ? "triangle" : "tetrahedron"));
        Cell cell{0, 0, 0, 0};
        std::copy(m.cell(c), m.cell(c) + d + 1, cell.begin());
        wk.add_cell(cell);
      }
      w.push_back(std::move(wk));
      for (std::size_t k = 0; k < t.templated.templates[i].instance_count(); ++k) {
        template_of.push_back(i);
        local_of.push_back(k);
      }
    }
  }
  const mesh::Transformation& transformation(std::size_t instance) const {
    const auto& mt = t.templated.templates[template_of[instance]];
    return t.templated.transformations[std::size_t(mt.transformation_indices[local_of[instance]])];
  }
  void store() {
    for (std::size_t i = 0; i < w.size(); ++i) {
      auto& m = t.templated.templates[i].mesh;
      const auto type = w[i].d == 2 ? mesh::ElementType::triangle : mesh::ElementType::tetrahedron;
      m.vertex_coords = w[i].x;
      m.cell_types.clear();
      m.cell_vertex_indices.clear();
      m.cell_vertex_index_offsets.assign(1, 0);
      for (const auto& c : w[i].cells) m.add_cell(type, c.data());
    }
  }
};

/// An identification table as maps both ways (template vertex -> related template vertex).
struct TableIndex {
  std::unordered_map<IndexType, IndexType> fwd, bwd;
};
std::vector<TableIndex> index_tables(const mesh::TemplatedMeshCompactSvb& t);

/// One table read from template `from`'s side: `map` sends its vertices to template `to`'s.
struct TableView {
  const std::unordered_map<IndexType, IndexType>* map = nullptr;
  std::size_t to = 0;
};
/// Every table, either way, that starts at template t: the steps of a closure under the tables.
std::vector<TableView> tables_from(const Session& s, const std::vector<TableIndex>& index,
                                   std::size_t t);

/// A condition on a new cell (sliver removal: positive in every instance).
using CellTest = std::function<bool(const Cell&)>;

/// Vertices at the apex of an acute template corner, per template: Technique 5.8's protection
/// balls (Section 5.2.5, Figure 5.17). Protection is a property of the point of AT, so it is
/// closed under the identification tables (a corner of one template protects its copies).
using Protected = std::vector<std::vector<char>>;
/// The protected vertices of every template: 2D, boundary vertices where the template's cells
/// meet with an angle sum below 90°; 3D, the ends of template boundary edges where they meet
/// with a dihedral angle sum below 60° (acute creases). Closed under the identification tables.
Protected acute_corners(const Session& s);
/// 3D: the dihedral angle sum (degrees) at every edge of w, over the cells around it.
std::map<std::pair<IndexType, IndexType>, double> dihedral_angle_sums(const Work& w);

std::array<double, 3> sub3(const double* a, const double* b);
std::array<double, 3> cross3(const std::array<double, 3>& u, const std::array<double, 3>& v);
double dot3(const std::array<double, 3>& u, const std::array<double, 3>& v);
P2 p2(const double* q);
P3 p3(const double* q);

/// The orientation sign of cell c (exact predicate on the doubles), with vertex `moved` at `at`.
int orientation(const Work& w, const Cell& c, IndexType moved = -1, const double* at = nullptr);
/// Angle between two vectors, in degrees.
double angle_between(const double* u, const double* v, int d);
/// Smallest angle (triangle) or dihedral angle (tetrahedron) in degrees; 0 for a flat cell.
double cell_quality(const Work& w, const Cell& c, IndexType moved = -1, const double* at = nullptr);
/// Positive and not flat to rounding (d!·|cell| / L^d > 1e-9): smoothing moves and the 3D
/// sliver removal keep every cell so.
bool robustly_positive(const Work& w, const Cell& c, IndexType moved = -1,
                       const double* at = nullptr);
/// The smallest quality of the given cells.
double min_quality(const Work& w, std::initializer_list<Cell> cells);
/// The facets (d vertices, sorted) of a cell.
std::vector<std::vector<IndexType>> facets_of(const Work& w, const Cell& c);
std::size_t facet_cell_count(const Work& w, const std::vector<IndexType>& f);
/// Whether edge {a, b} lies on the template boundary (on a facet of exactly one cell).
bool is_boundary_edge(const Work& w, IndexType a, IndexType b);
/// The vertices on some boundary facet.
std::vector<char> boundary_vertices(const Work& w);
TemplateEdge edge_of(std::size_t t, IndexType a, IndexType b);
/// Splits every cell on edge {a, b} of w at new vertex m (in place: a -> m, then b -> m).
void split_edge(Work& w, IndexType a, IndexType b, IndexType m);
/// Splits the given template edges and every related one (closed under the tables) at one
/// point each (the midpoint, or a protection-ball shell point next to a protected corner), and
/// records the new vertex pairs in the tables; returns the number of template edges split.
std::size_t bisect(Session& s, const std::vector<TemplateEdge>& edges,
                   const Protected* protect = nullptr);
/// Removes a cell; the last cell takes its index.
void remove_cell(Work& w, IndexType ci);
bool quality_flip_2_3(Work& w, IndexType ci, int skip, const CellTest* also = nullptr);
bool quality_flip_3_2(Work& w, IndexType ci, int p, int q, const CellTest* also = nullptr);
bool remove_edge(Work& w, IndexType ci, int p, int q, const CellTest& ok, std::size_t largest_ring,
                 bool improve);
/// The vertex of a cell that is not on its facet f (an edge in 2D, a triangle in 3D).
IndexType apex(const Cell& c, std::initializer_list<IndexType> f);
IndexType apex(const Cell& c, const std::array<IndexType, 3>& f);
double longest_edge(const Work& w, const IndexType* c, int n, IndexType& a, IndexType& b);

/// 3D: the template boundary triangles (sorted vertices).
std::vector<std::array<IndexType, 3>> surface_of(const Work& w);
/// 3D: replaces the cells of w by TetGen's constrained Delaunay tetrahedralization of its
/// vertices and the given boundary triangles.
void retetrahedralize_template(Work& w, const std::vector<std::array<IndexType, 3>>& surface);

/// Technique 5.8 in 3D (technique_5_8_3d.cpp; spec/adaptation.md#tmesh-adaptation).
DelaunayReport make_delaunay_3d(Session& s, std::size_t max_rounds, mesh::Progress* progress,
                                bool crease_mirrors);

} // namespace symmesh::adapt::work
