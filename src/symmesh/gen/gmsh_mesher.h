/// The Gmsh peer baseline (Section 7.1: the whole geometry meshed by the tool a user would
/// otherwise pick) — spec/generation.md#gmsh
///
/// Planar regions given by their boundary edges over one shared point array are handed to Gmsh's
/// built-in CAD kernel (one line per distinct edge, so neighbouring regions share their lines and
/// therefore their mesh nodes; one plane surface per outer loop with its holes) and meshed with
/// Gmsh's 2D Delaunay algorithm (`Mesh.Algorithm = 5`, `-algo del2d`) at `Mesh.MeshSizeMax =
/// size`, on one thread. Gmsh has no smallest-angle parameter; quality is measured afterwards.
///
/// In 3D (spec/generation.md#gmsh-3d) the regions come as closed triangulated surfaces, which
/// become a discrete Gmsh model — the triangles are the surfaces' mesh, kept as they are — and
/// each region is tetrahedralized by Gmsh's 3D Delaunay algorithm (`Mesh.Algorithm3D = 1`).
///
/// Gmsh is loaded only when this baseline runs: it lives in the module libsymmesh_gmsh.so,
/// opened with dlopen(RTLD_LOCAL). Linking libgmsh into symmesh cost every command ~50 ms of
/// symbol binding at start-up (its dependency tree), and libgmsh carries its own copy of
/// TetGen's classes, which interposed on libtet's when both were linked (libtet's calls bound
/// into Gmsh's copy and corrupted the heap); a module opened locally stays out of the global
/// scope. The module is looked for next to the running executable, then at the path it was
/// built at.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace symmesh::gen {

struct PlanarRegions {
  std::vector<std::array<double, 2>> points;
  struct Region {
    int id = 1;
    std::vector<std::array<std::size_t, 2>> edges; ///< closed boundary curves, any orientation
  };
  std::vector<Region> regions;
};

struct GmshTriangles {
  std::vector<std::array<double, 2>> nodes;
  /// Per region (same order as the input): triangles in node indices.
  std::vector<std::vector<std::array<std::size_t, 3>>> triangles;
};

/// Regions of a 3D geometry by their closed boundary surfaces over one shared point array. A
/// triangle between two regions appears in both regions' lists.
struct ClosedSurfaces {
  std::vector<std::array<double, 3>> points; ///< pairwise distinct, all used by some triangle
  struct Region {
    int id = 1;
    std::vector<std::array<std::size_t, 3>> triangles; ///< any orientation
  };
  std::vector<Region> regions;
};

struct GmshTetrahedra {
  /// The input points first, in input order and with the same coordinates; then Gmsh's points.
  std::vector<std::array<double, 3>> nodes;
  /// Per region (same order as the input): tetrahedra in node indices, Gmsh's orientation.
  std::vector<std::vector<std::array<std::size_t, 4>>> tetrahedra;
  /// Building the Gmsh model and generate(3), measured in the module: the mesher's own time,
  /// without loading the module (libgmsh's start-up) or reading the mesh back. After a failed
  /// optimizer (below), the time of the run that succeeded.
  double seconds = 0;
  /// Gmsh's own error when its tetrahedral optimizer (Mesh.Optimize, on by default) failed and
  /// the mesh is the retry without it; empty when the optimized mesh is the result.
  std::string optimizer_failure;
};

/// \pre every region's edges form vertex-disjoint simple closed curves; size > 0. Throws
/// MeshingError (triangle_mesher.h) otherwise, when Gmsh fails, or when the module cannot be
/// loaded.
GmshTriangles mesh_with_gmsh(const PlanarRegions& regions, double size);

/// The implementation inside the module (gmsh_mesher.cpp); callers use mesh_with_gmsh.
GmshTriangles mesh_with_gmsh_in_module(const PlanarRegions& regions, double size);

/// Gmsh's 3D Delaunay on the regions' closed surfaces, the surface triangles kept as Gmsh's
/// boundary mesh (spec/generation.md#gmsh-3d). Gmsh may still change the boundary (its boundary
/// recovery can add Steiner points), so the caller checks the result against the surfaces.
/// Gmsh 4.8's optimizer (sliver removal after the Delaunay step) can stop on an internal error
/// ("a deleted triangle is a neighbor of a non deleted triangle", seen on tsv-128 at size
/// 0.046773); then the regions are meshed again with Mesh.Optimize = 0 and the failure is kept in
/// optimizer_failure, so that the peer still has a mesh and the report says which one.
/// \pre each triangle lies in one or two regions' lists; size > 0. Throws MeshingError otherwise,
/// when Gmsh fails, or when the module cannot be loaded.
GmshTetrahedra mesh_with_gmsh_3d(const ClosedSurfaces& regions, double size);

/// The implementation inside the module (gmsh_mesher.cpp); callers use mesh_with_gmsh_3d.
GmshTetrahedra mesh_with_gmsh_3d_in_module(const ClosedSurfaces& regions, double size);

} // namespace symmesh::gen
