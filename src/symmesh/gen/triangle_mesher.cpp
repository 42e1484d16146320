// Mesh_2 without edge refinement on a pre-split boundary (spec/generation.md#mesher-2).
#include "symmesh/gen/triangle_mesher.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <set>
#include <utility>

namespace symmesh::gen {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
constexpr std::size_t kNoIndex = std::numeric_limits<std::size_t>::max();
/// Output index of a vertex; mesher-inserted vertices start without one.
struct VertexIndex {
  std::size_t i = kNoIndex;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexIndex, K,
                                                       CGAL::Delaunay_mesh_vertex_base_2<K>>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Segments meet only at shared endpoints; a crossing is an input error, not something to repair.
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

/// in_domain = odd number of boundary crossings from the infinite face (holes are even); a cut
/// (an input vertex pair in `cuts`) is crossed without counting.
void mark_by_nesting_parity(Cdt& cdt, const std::set<std::pair<std::size_t, std::size_t>>& cuts) {
  const auto is_cut = [&](Cdt::Face_handle f, int i) {
    if (cuts.empty()) return false;
    std::size_t a = f->vertex(Cdt::cw(i))->info().i, b = f->vertex(Cdt::ccw(i))->info().i;
    if (a > b) std::swap(a, b);
    return cuts.count({a, b}) > 0;
  };
  std::map<Cdt::Face_handle, int> level;
  std::deque<std::pair<Cdt::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    auto [start, l] = seeds.front();
    seeds.pop_front();
    if (level.count(start)) continue;
    std::vector<Cdt::Face_handle> stack{start};
    level[start] = l;
    while (!stack.empty()) {
      auto f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        auto n = f->neighbor(i);
        if (level.count(n)) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i)) && !is_cut(f, i)) {
          seeds.emplace_back(n, l + 1);
        } else {
          level[n] = l;
          stack.push_back(n);
        }
      }
    }
  }
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->set_in_domain(!cdt.is_infinite(f) && level[f] % 2 == 1);
}
/// refine_mesh() one inserted point at a time: Mesher_level's step-by-step refinement takes the
/// same elements in the same order, so the mesh is the same; it lets progress be reported.
template <class Mesher>
void refine_with_progress(Mesher& mesher, const Cdt& cdt, const MeshingParameters& p) {
  if (!p.on_progress) {
    mesher.refine_mesh();
    return;
  }
  std::size_t steps = 0;
  while (mesher.step_by_step_refine_mesh())
    if ((++steps & 0xfff) == 0) p.on_progress(cdt.number_of_faces());
}
} // namespace

mesh::Mesh triangle_mesh_of(const TriangleMeshOutput& out) {
  mesh::Mesh m;
  m.point_dimension = 2;
  for (const auto& p : out.points) m.add_vertex(p.data());
  for (const auto& c : out.triangles) {
    const mesh::IndexType v[3] = {mesh::IndexType(c[0]), mesh::IndexType(c[1]),
                                  mesh::IndexType(c[2])};
    m.add_cell(mesh::ElementType::triangle, v);
  }
  orient_triangles_positively(m);
  return m;
}

void orient_triangles_positively(mesh::Mesh& m) {
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    if (m.cell_types[c] != mesh::ElementType::triangle) continue;
    auto* v = m.cell_vertex_indices.data() + m.cell_vertex_index_offsets[c];
    const auto point = [&](int k) {
      const double* x = m.vertex(std::size_t(v[k]));
      return K::Point_2(x[0], x[1]);
    };
    switch (CGAL::orientation(point(0), point(1), point(2))) {
    case CGAL::COUNTERCLOCKWISE:
      break;
    case CGAL::CLOCKWISE:
      std::swap(v[1], v[2]);
      break;
    default:
      throw MeshingError("a triangle of the mesh has zero area");
    }
  }
}

TriangleMeshOutput mesh_domain_2(const BoundaryInput& boundary, const MeshingParameters& p) {
  if (!(p.size > 0) || !std::isfinite(p.size))
    throw std::invalid_argument("mesh size must be a positive number");
  if (!(p.min_angle_deg >= 0 && p.min_angle_deg <= 33.8))
    throw std::invalid_argument("minimum angle must be in [0, 33.8] degrees");
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> vh;
  for (std::size_t k = 0; k < boundary.points.size(); ++k) {
    const auto& q = boundary.points[k];
    if (!std::isfinite(q[0]) || !std::isfinite(q[1]))
      throw MeshingError("a boundary point is not finite");
    auto v = cdt.insert(K::Point_2(q[0], q[1]));
    if (v->info().i != kNoIndex)
      throw MeshingError("two boundary points coincide in double precision");
    v->info().i = k;
    vh.push_back(v);
  }
  try {
    for (const auto& s : boundary.segments) cdt.insert_constraint(vh[s[0]], vh[s[1]]);
    for (const auto& s : boundary.cuts) cdt.insert_constraint(vh[s[0]], vh[s[1]]);
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    throw MeshingError("boundary segments cross or pass through a boundary point");
  }
  if (cdt.number_of_vertices() != boundary.points.size())
    throw MeshingError("the mesher inserted points while building the boundary");
  if (cdt.dimension() < 2) throw MeshingError("the boundary encloses no area");
  std::set<std::pair<std::size_t, std::size_t>> cuts;
  for (const auto& s : boundary.cuts) cuts.insert({std::min(s[0], s[1]), std::max(s[0], s[1])});
  mark_by_nesting_parity(cdt, cuts);
  const double b = std::pow(std::sin(p.min_angle_deg * M_PI / 180.0), 2);
  TriangleMeshOutput out;
  if (p.report_boundary_splits) {
    CGAL::Delaunay_mesher_2<Cdt, Criteria> mesher(cdt, Criteria(b, p.size));
    mesher.init(true);
    refine_with_progress(mesher, cdt, p);
    // A split segment is no longer a constrained edge between its two input vertices
    // (combinatorial). The edge itself may survive unconstrained: the split point, rounded off
    // the segment, can leave a flat triangle on it.
    for (std::size_t k = 0; k < boundary.segments.size(); ++k) {
      const auto& s = boundary.segments[k];
      Cdt::Face_handle f;
      int i = 0;
      if (!cdt.is_edge(vh[s[0]], vh[s[1]], f, i) || !cdt.is_constrained({f, i}))
        out.split_segments.push_back(k);
    }
    if (!out.split_segments.empty()) return out;
  } else {
    CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, Criteria> mesher(cdt, Criteria(b, p.size));
    mesher.init(true);
    refine_with_progress(mesher, cdt, p);
  }
  out.points = boundary.points;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info().i != kNoIndex) continue;
    // Any vertex on a constrained edge that is not an input point would alter the boundary.
    if (cdt.are_there_incident_constraints(v))
      throw MeshingError("the mesher put a vertex on the boundary");
    v->info().i = out.points.size();
    out.points.push_back({v->point().x(), v->point().y()});
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_in_domain())
      out.triangles.push_back(
          {f->vertex(0)->info().i, f->vertex(1)->info().i, f->vertex(2)->info().i});
  if (out.triangles.empty()) throw MeshingError("the boundary encloses no area");
  return out;
}

} // namespace symmesh::gen
