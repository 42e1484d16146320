/// The closed boundary subdivision: a common refinement of every template boundary on which all
/// template boundary mappings (Def 4.7) act face to face — spec/boundary-patches.md#subdivision
///
/// Each template boundary bnd*(X_i) is cut into relatively open faces (vertices, edges and, in
/// 3D, polygonal 2-faces) such that (a) every mapping domain is a union of closed faces and
/// (b) every mapping sends each face of its domain onto a face of the target template. (b) is
/// reached by closing the cut points (2D) or cut points and segments (3D) under all mappings
/// until nothing new appears. Then every composition of mappings (𝔗_X) also acts face to face,
/// so Algorithm 4.1 becomes a finite partition refinement on faces (boundary_patch_partition.h).
#pragma once
#include "symmesh/core/point.h"
#include "symmesh/core/simplex.h"

#include <cstddef>
#include <vector>

namespace symmesh::core {

/// A relatively open face of the subdivision of one template boundary.
struct BoundaryFace {
  int dimension = 0;                ///< 0 .. D-1
  std::vector<VertexId> vertices;   ///< subdivision vertices in the closure (sorted)
  std::vector<Simplex> pieces;      ///< the closure as simplices over the subdivision points
  std::vector<std::size_t> closure; ///< lower-dimensional faces in the closure (sorted)
};

template <class FT, int D>
struct BoundarySubdivision {
  std::vector<Point<FT, D>> points; ///< subdivision vertices
  std::vector<BoundaryFace> faces;  ///< faces 0..points.size()-1 are the vertices, in order
  std::vector<Point<FT, D>> rep;    ///< a point in the relative interior of each face

  std::size_t vertex_count() const { return points.size(); }

  bool is_valid(std::ostream* why = nullptr) const;
};

} // namespace symmesh::core
