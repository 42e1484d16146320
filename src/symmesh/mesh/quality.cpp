// Triangle quality statistics (spec/mesh-data-structures.md#quality).
#include "symmesh/mesh/quality.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace symmesh::mesh {

QualityStatistics triangle_quality(const Mesh& m, double bound_deg) {
  QualityStatistics q;
  q.bound_deg = bound_deg;
  q.min_angle_deg = 180;
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    if (m.cell_types[c] != ElementType::triangle)
      throw std::invalid_argument("triangle_quality: a cell is not a triangle");
    const auto* v = m.cell(c);
    double smallest = 180, shortest2 = 0, twice_area = 0, edge2[3];
    for (int k = 0; k < 3; ++k) {
      const double* a = m.vertex(std::size_t(v[k]));
      const double* b = m.vertex(std::size_t(v[(k + 1) % 3]));
      const double* p = m.vertex(std::size_t(v[(k + 2) % 3]));
      const double ux = b[0] - a[0], uy = b[1] - a[1], wx = p[0] - a[0], wy = p[1] - a[1];
      const double cross = std::fabs(ux * wy - uy * wx);
      smallest = std::min(smallest, std::atan2(cross, ux * wx + uy * wy) * 180.0 / M_PI);
      edge2[k] = ux * ux + uy * uy;
      twice_area = cross;
    }
    shortest2 = std::min({edge2[0], edge2[1], edge2[2]});
    // R = abc / (4 area) = abc / (2 · twice_area).
    const double r = std::sqrt(edge2[0] * edge2[1] * edge2[2]) / (2 * twice_area);
    q.max_radius_edge_ratio = std::max(q.max_radius_edge_ratio, r / std::sqrt(shortest2));
    q.min_angle_deg = std::min(q.min_angle_deg, smallest);
    q.histogram[std::min<std::size_t>(11, std::size_t(smallest / 5))]++;
    if (smallest < bound_deg) ++q.below_bound;
    ++q.triangles;
  }
  if (q.triangles == 0) q.min_angle_deg = 0;
  return q;
}

QualityStatistics triangle_quality(const TemplatedMesh& t, double bound_deg) {
  QualityStatistics q;
  q.bound_deg = bound_deg;
  q.min_angle_deg = 180;
  for (const auto& tm : t.templates) {
    const std::size_t copies = tm.instance_count();
    if (copies == 0 || tm.mesh.cell_count() == 0) continue;
    const auto one = triangle_quality(tm.mesh, bound_deg);
    q.triangles += one.triangles * copies;
    q.below_bound += one.below_bound * copies;
    for (std::size_t b = 0; b < q.histogram.size(); ++b)
      q.histogram[b] += one.histogram[b] * copies;
    q.min_angle_deg = std::min(q.min_angle_deg, one.min_angle_deg);
    q.max_radius_edge_ratio = std::max(q.max_radius_edge_ratio, one.max_radius_edge_ratio);
  }
  if (q.triangles == 0) q.min_angle_deg = 0;
  return q;
}

} // namespace symmesh::mesh
