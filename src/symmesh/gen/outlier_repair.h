/// Section 5.2.6 (quality improvement by smoothing and flips), applied to the few tetrahedra
/// TetGen leaves with a radius-edge ratio above √2 or a dihedral angle below 10° —
/// spec/generation.md#outlier-repair
///
/// TetGen with -Y skips a refinement whose Steiner point would encroach the kept surface, so a
/// few tetrahedra near it keep a high radius-edge ratio, and -q bounds no dihedral angle. In a
/// templated mesh every such outlier of a template is repeated in each of its instances. This
/// pass works on those outliers only (radius-edge ratio above `radius_edge` or smallest dihedral
/// angle below `min_dihedral_deg`): 2-3 flips of their facets, 3-2 flips of their edges, moves
/// of their vertices that TetGen added inside the domain, and removals of such vertices (their
/// star re-tetrahedralized from one link vertex). It never touches the boundary: a facet that is
/// an input triangle is never flipped, an input point never moves nor goes, and no point is
/// added, so the surface, the region of every tetrahedron and the surface points' ids are those
/// TetGen returned, and a templated mesh's shared vertex bookkeeping and Lemma 4.2 certificate
/// are unaffected. A change is made only when every new tetrahedron is positively oriented (exact
/// orientation on the doubles) and it makes the replaced cells' worst measure better while
/// neither measure ends worse than both its old value and its limit: the bound, or the mesh's
/// worst value as TetGen left it where that is within the bound. So the mesh's largest ratio and
/// smallest dihedral angle never get worse. Deterministic.
#pragma once
#include "symmesh/gen/tetrahedral_mesher.h"
#include "symmesh/mesh/quality.h"

#include <cstddef>
#include <limits>

namespace symmesh::gen {

struct OutlierBounds {
  /// √2: what Delaunay refinement reaches away from small input angles (TetGen's manual suggests
  /// -q1.414); symmesh runs TetGen with -q2 (tetgen_switches), so these cells are within
  /// TetGen's own bound but beyond this one
  double radius_edge = 1.414;
  double min_dihedral_deg = mesh::kDihedralBoundDeg; ///< the report's dihedral bound
  std::size_t max_passes = 6;                        ///< sweeps over the remaining outliers
  /// no cell a removal makes may be larger: TetGen's -a bound (volume_bound of the size)
  double max_volume = std::numeric_limits<double>::infinity();
};

struct OutlierRepairReport {
  std::size_t outliers_before = 0, outliers_after = 0, flips = 0, moves = 0, removals = 0;
};

/// Repairs the outliers of `m`, TetGen's mesh of `surface` (mesh_domain_3's output: the surface
/// points first, every boundary facet an input triangle, every tetrahedron positive).
/// \pre m is mesh_domain_3(surface, ...)'s result; b.radius_edge >= 1, b.min_dihedral_deg >= 0,
///      b.max_volume > 0
OutlierRepairReport repair_outliers(const SurfaceInput& surface, TetrahedralMeshOutput& m,
                                    const OutlierBounds& b);

} // namespace symmesh::gen
