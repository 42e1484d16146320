/// The 2D mesher adapter of Algorithm 5.6, Line 24 — spec/generation.md#mesher-2
///
/// CGAL's Delaunay refinement (Mesh_2) in the mode that never alters the boundary
/// (Delaunay_mesher_no_edge_refinement_2): the caller gives the boundary already split into short
/// segments (the line meshes); the mesher inserts interior vertices only. On request the full
/// mesher (Delaunay_mesher_2) runs instead and reports the segments it had to split. The domain is
/// the set of points enclosed an odd number of times by the boundary segments (nesting parity), so
/// holes need no seeds. The output keeps the input vertices first, in input order, which is what
/// lets the generator name boundary vertices combinatorially.
#pragma once
#include "symmesh/mesh/mesh.h"

#include <array>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::gen {

struct MeshingParameters {
  double size = 0;          ///< target edge length (Delaunay_mesh_size_criteria_2 size bound)
  double min_angle_deg = 0; ///< shape bound B = sin²(angle); 0 = no shape criterion
  /// Run Delaunay_mesher_2, which may split boundary segments, and report which it split
  /// (TriangleMeshOutput::split_segments) instead of failing: the generator then refines the
  /// line meshes and meshes again (spec/generation.md#sao). The output is a valid mesh of the
  /// given boundary only when no segment was split.
  bool report_boundary_splits = false;
  /// Called now and then during refinement with the number of triangles so far (all faces of
  /// the triangulation, inside the domain or not), for progress lines.
  std::function<void(std::size_t)> on_progress;
};

struct BoundaryInput {
  std::vector<std::array<double, 2>> points;
  std::vector<std::array<std::size_t, 2>> segments; ///< closed boundary curves, any orientation
  /// Constrained segments inside the domain that do not bound it (they leave the nesting parity
  /// alone): the cuts of a symmetric surface mesh (spec/generation.md#symmetric-surface-meshes).
  std::vector<std::array<std::size_t, 2>> cuts;
};

struct TriangleMeshOutput {
  std::vector<std::array<double, 2>> points; ///< input points first, in input order
  std::vector<std::array<std::size_t, 3>> triangles;
  /// With report_boundary_splits: the input segments the mesher split (indices, increasing).
  std::vector<std::size_t> split_segments;
};

/// Raised when the mesher cannot respect the boundary (crossing segments, a Steiner point on the
/// boundary): the generator must fail, never ship such a mesh.
struct MeshingError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Puts every triangle of m in counter-clockwise order (exact orientation predicate on its double
/// coordinates), so that templates are positively oriented whatever mesher made them. Throws
/// MeshingError for a degenerate (zero-area) triangle.
void orient_triangles_positively(mesh::Mesh& m);

/// The mesher's output as a MESH (Listing 2.1) of positively oriented triangles.
mesh::Mesh triangle_mesh_of(const TriangleMeshOutput& out);

/// \pre parameters.size > 0; 0 <= min_angle_deg <= 33.8 (Mesh_2's termination bound)
TriangleMeshOutput mesh_domain_2(const BoundaryInput& boundary,
                                 const MeshingParameters& parameters);

} // namespace symmesh::gen
