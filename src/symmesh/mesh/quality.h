/// Element quality of triangle meshes (Definitions 2.12–2.20: smallest angle, radius-edge ratio)
/// — spec/mesh-data-structures.md#quality
///
/// Statistics over all triangles: the smallest angle (its minimum and a histogram in 5° bins
/// from 0° to 60°), the radius-edge ratio R/l_min (its maximum; an equilateral triangle has
/// 1/√3), and how many triangles have a smallest angle below a requested bound.
#pragma once
#include "symmesh/mesh/mesh.h"
#include "symmesh/mesh/templated_mesh.h"

#include <array>
#include <cstddef>

namespace symmesh::mesh {

struct QualityStatistics {
  std::size_t triangles = 0;
  double min_angle_deg = 0;                ///< smallest angle of any triangle
  double max_radius_edge_ratio = 0;        ///< largest circumradius / shortest edge
  std::array<std::size_t, 12> histogram{}; ///< smallest angle per triangle, bins [5i, 5i+5)°
  std::size_t below_bound = 0;             ///< triangles whose smallest angle < bound
  double bound_deg = 0;
};

/// \pre every cell of m is a triangle
QualityStatistics triangle_quality(const Mesh& m, double bound_deg);

/// The statistics of the structure instance AT from the templates alone: a rigid map keeps
/// every angle and ratio, so each template's statistics count once per instance.
/// \pre every template cell is a triangle
QualityStatistics triangle_quality(const TemplatedMesh& t, double bound_deg);

/// Tetrahedron quality (Definitions 2.12–2.20 for tetrahedra; Table 7.1's measures): dihedral
/// angles (smallest and largest, a histogram of each tetrahedron's smallest in 5° bins from 0°
/// to 90°) and the radius-edge ratio R/l_min (largest; the regular tetrahedron has √6/4).
struct TetrahedronQualityStatistics {
  std::size_t tetrahedra = 0;
  double min_dihedral_deg = 0;             ///< smallest dihedral angle of any tetrahedron
  double max_dihedral_deg = 0;             ///< largest dihedral angle of any tetrahedron
  double max_radius_edge_ratio = 0;        ///< largest circumradius / shortest edge
  std::array<std::size_t, 18> histogram{}; ///< smallest dihedral per tetrahedron, [5i, 5i+5)°
  std::size_t below_bound = 0;             ///< tetrahedra whose smallest dihedral < bound
  double bound_deg = 0;
};

/// The measures of one tetrahedron (any orientation): its smallest and largest dihedral angle
/// and its radius-edge ratio; a flat one has an infinite ratio, and its angles are NaN when a
/// face has no normal in doubles (the statistics below leave NaN out of the extremes, as they
/// always did, and count such a cell in the lowest histogram bin and below the bound).
struct TetrahedronShape {
  double min_dihedral_deg = 0, max_dihedral_deg = 0, radius_edge_ratio = 0;
};
TetrahedronShape tetrahedron_shape(const double* p0, const double* p1, const double* p2,
                                   const double* p3);

/// The smallest dihedral angle the 3D report counts cells below (`dihedral_bound_deg`), and the
/// outlier repair's bound (gen/outlier_repair.h).
inline constexpr double kDihedralBoundDeg = 10;

/// \pre every cell of m is a tetrahedron, m.point_dimension == 3
TetrahedronQualityStatistics tetrahedron_quality(const Mesh& m, double bound_deg);
/// AT's statistics from the templates (rigid maps keep dihedral angles and ratios).
TetrahedronQualityStatistics tetrahedron_quality(const TemplatedMesh& t, double bound_deg);

} // namespace symmesh::mesh
