// Triangle quality statistics (spec/mesh-data-structures.md#quality).
#include "symmesh/mesh/quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

namespace {
using Vec3 = std::array<double, 3>;
Vec3 sub(const double* a, const double* b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
} // namespace

TetrahedronShape tetrahedron_shape(const double* p0, const double* p1, const double* p2,
                                   const double* p3) {
  const double* p[4] = {p0, p1, p2, p3};
  // Outward normal of the face opposite vertex k: orthogonal to the face, pointing away from
  // p[k].
  Vec3 n[4];
  for (int k = 0; k < 4; ++k) {
    const double* a = p[(k + 1) % 4];
    const double* b = p[(k + 2) % 4];
    const double* d = p[(k + 3) % 4];
    n[k] = cross(sub(b, a), sub(d, a));
    if (dot(n[k], sub(p[k], a)) > 0) n[k] = {-n[k][0], -n[k][1], -n[k][2]};
  }
  // The dihedral angle at the edge shared by faces i and j is π minus the angle between their
  // outward normals, so it grows with the cosine between them: the smallest and largest angles
  // are those of the smallest and largest cosines.
  double low = 1, high = -1;
  bool undefined = false; // a face normal of length zero: no angle
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double cosine =
          std::clamp(dot(n[i], n[j]) / std::sqrt(dot(n[i], n[i]) * dot(n[j], n[j])), -1.0, 1.0);
      undefined = undefined || std::isnan(cosine);
      low = std::min(low, cosine);
      high = std::max(high, cosine);
    }
  TetrahedronShape s;
  s.min_dihedral_deg = undefined ? NAN : 180.0 - std::acos(low) * 180.0 / M_PI;
  s.max_dihedral_deg = undefined ? NAN : 180.0 - std::acos(high) * 180.0 / M_PI;
  const Vec3 u = sub(p[1], p[0]), w = sub(p[2], p[0]), t = sub(p[3], p[0]);
  const double six_volume = dot(u, cross(w, t));
  const Vec3 a = cross(w, t), b = cross(t, u), d = cross(u, w);
  Vec3 centre{};
  for (int k = 0; k < 3; ++k)
    centre[std::size_t(k)] = (dot(u, u) * a[std::size_t(k)] + dot(w, w) * b[std::size_t(k)] +
                              dot(t, t) * d[std::size_t(k)]) /
                             (2 * six_volume);
  double shortest2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Vec3 e = sub(p[j], p[i]);
      shortest2 = std::min(shortest2, dot(e, e));
    }
  s.radius_edge_ratio = six_volume == 0 ? std::numeric_limits<double>::infinity()
                                        : std::sqrt(dot(centre, centre) / shortest2);
  return s;
}

TetrahedronQualityStatistics tetrahedron_quality(const Mesh& m, double bound_deg) {
  if (m.point_dimension != 3)
    throw std::invalid_argument("tetrahedron_quality: the mesh is not 3D");
  TetrahedronQualityStatistics q;
  q.bound_deg = bound_deg;
  q.min_dihedral_deg = 180;
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    if (m.cell_types[c] != ElementType::tetrahedron)
      throw std::invalid_argument("tetrahedron_quality: a cell is not a tetrahedron");
    const auto* v = m.cell(c);
    const auto s = tetrahedron_shape(m.vertex(std::size_t(v[0])), m.vertex(std::size_t(v[1])),
                                     m.vertex(std::size_t(v[2])), m.vertex(std::size_t(v[3])));
    q.max_radius_edge_ratio = std::max(q.max_radius_edge_ratio, s.radius_edge_ratio);
    q.min_dihedral_deg = std::min(q.min_dihedral_deg, s.min_dihedral_deg);
    q.max_dihedral_deg = std::max(q.max_dihedral_deg, s.max_dihedral_deg);
    // A cell without angles (NaN) counts as the worst: bin 0 and below the bound.
    const double smallest = std::isnan(s.min_dihedral_deg) ? 0 : s.min_dihedral_deg;
    q.histogram[std::min<std::size_t>(17, std::size_t(smallest / 5))]++;
    if (smallest < bound_deg) ++q.below_bound;
    ++q.tetrahedra;
  }
  if (q.tetrahedra == 0) q.min_dihedral_deg = 0;
  return q;
}

TetrahedronQualityStatistics tetrahedron_quality(const TemplatedMesh& t, double bound_deg) {
  TetrahedronQualityStatistics q;
  q.bound_deg = bound_deg;
  q.min_dihedral_deg = 180;
  for (const auto& tm : t.templates) {
    const std::size_t copies = tm.instance_count();
    if (copies == 0 || tm.mesh.cell_count() == 0) continue;
    const auto one = tetrahedron_quality(tm.mesh, bound_deg);
    q.tetrahedra += one.tetrahedra * copies;
    q.below_bound += one.below_bound * copies;
    for (std::size_t b = 0; b < q.histogram.size(); ++b)
      q.histogram[b] += one.histogram[b] * copies;
    q.min_dihedral_deg = std::min(q.min_dihedral_deg, one.min_dihedral_deg);
    q.max_dihedral_deg = std::max(q.max_dihedral_deg, one.max_dihedral_deg);
    q.max_radius_edge_ratio = std::max(q.max_radius_edge_ratio, one.max_radius_edge_ratio);
  }
  if (q.tetrahedra == 0) q.min_dihedral_deg = 0;
  return q;
}

} // namespace symmesh::mesh
