/// The 3D mesher adapter of Algorithm 5.7, Line "tetrahedralize each template with its boundary
/// kept" — spec/generation.md#mesher-3
///
/// TetGen 1.5 (libtet, through `tetgenio`) on a closed triangulated surface: the surface meshes
/// of a template's boundary patches, already refined to the size. Switches: -p (the input is a
/// PLC), -Y (no Steiner point on the boundary), -q (radius-edge bound, then after a slash the
/// smallest dihedral angle TetGen refines towards), -a (volume bound from
/// the size), -A with region seeds, -z (zero-based), -Q (quiet). TetGen's -Y is best effort, so
/// the result is checked combinatorially afterwards: the input points come first and unchanged,
/// and the boundary of the tetrahedral mesh (faces in one tetrahedron, or between two regions)
/// is exactly the input triangles. Anything else is a MeshingError naming the input triangle;
/// such a mesh is never returned. Tetrahedra are returned positively oriented (exact orientation
/// predicate on the double coordinates).
#pragma once
#include "symmesh/gen/triangle_mesher.h"
#include "symmesh/mesh/mesh.h"
#include "symmesh/mesh/quality.h"

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace symmesh::gen {

struct SurfaceInput {
  std::vector<std::array<double, 3>> points;
  /// Closed surface(s), any orientation; interfaces between regions appear once.
  std::vector<std::array<std::size_t, 3>> triangles;
  /// Optional region seeds: a point strictly inside a region and its id (TetGen -A). Without
  /// seeds every tetrahedron gets region 0.
  struct Seed {
    std::array<double, 3> point{};
    int region = 0;
  };
  std::vector<Seed> seeds;
};

struct TetrahedralMeshingParameters {
  double size = 0; ///< target edge length; the volume bound is that of a regular tetrahedron
  double radius_edge = 2.0; ///< TetGen -q bound (its default; 1.414 for better shape, slower)
  /// TetGen -q/D: the report's dihedral bound (mesh::kDihedralBoundDeg). Without it TetGen bounds
  /// no dihedral angle, and on thin rotational half-slices it leaves slivers between the two cut
  /// faces that no flip or move of the outlier repair can mend (spec/generation.md#mesher-3);
  /// 0 leaves it out.
  double min_dihedral_deg = mesh::kDihedralBoundDeg;
};

struct TetrahedralMeshOutput {
  std::vector<std::array<double, 3>> points;          ///< input points first, in input order
  std::vector<std::array<std::size_t, 4>> tetrahedra; ///< positively oriented
  std::vector<int> region;                            ///< one per tetrahedron
};

/// TetGen changed the boundary it was told to keep: `triangle` is the input triangle that is no
/// face of its mesh, or past the input's triangles when a mesh boundary face is no input triangle.
struct BoundaryChanged : MeshingError {
  std::size_t triangle;
  BoundaryChanged(const std::string& what, std::size_t t) : MeshingError(what), triangle(t) {}
};

/// Regular tetrahedron volume for edge `size`: size³ / (6√2), TetGen's -a bound.
double volume_bound(double size);

/// The TetGen switches used for `p` and whether seeds are given ("pYq2/10a0.0001AzQ").
std::string tetgen_switches(const TetrahedralMeshingParameters& p, bool with_regions);

/// \pre p.size > 0, p.radius_edge >= 1 (TetGen's termination needs > ~1.1 with -q),
/// 0 <= p.min_dihedral_deg < 70.5 (a regular tetrahedron's dihedral angle); the
/// surface is closed, its points pairwise distinct and finite
TetrahedralMeshOutput mesh_domain_3(const SurfaceInput& surface,
                                    const TetrahedralMeshingParameters& p);

/// TetGen -pY without refinement: a tetrahedralization of the solid the closed surface bounds
/// (cavities included), no point added on the surface, checked like mesh_domain_3. For carriers.
TetrahedralMeshOutput tetrahedralize_surface(const SurfaceInput& surface);

/// TetGen -pY -O0 on the surface and every given point (points on no triangle are inserted as
/// well): its constrained Delaunay tetrahedralization, with no optimisation flips afterwards, no
/// point added on the surface, checked like mesh_domain_3. For Technique 5.8 in 3D
/// (adapt/templated_mesh_adaptation.h), where the surface triangles are Delaunay already.
TetrahedralMeshOutput constrained_delaunay_tetrahedralization(const SurfaceInput& surface);

/// The first input triangle that is not a boundary face of `m` exactly (by vertex ids), or the
/// first boundary face of `m` that is no input triangle (reported as an index past the input's
/// triangles), or nothing when the boundary is the input surface. A boundary face is a face of
/// one tetrahedron, or a face between tetrahedra of two regions.
std::optional<std::size_t> boundary_mismatch(const SurfaceInput& surface,
                                             const TetrahedralMeshOutput& m);

/// Puts every tetrahedron of m in positive order (exact orient_3d on its double coordinates).
/// Throws MeshingError for a flat tetrahedron.
void orient_tetrahedra_positively(mesh::Mesh& m);

} // namespace symmesh::gen
