/// Section 5.1.1: independent template meshing and interface merging (Algorithms 5.1–5.3 in the
/// plane) — spec/generation.md#merge
///
/// Every template is meshed on its own — its carrier's boundary edges split into N equal parts
/// each (N from the size, decided exactly), Mesh_2 inside — with no boundary patch partition,
/// so where two instances meet, their boundary points need not match. The interfaces are then
/// sewn. Algorithms 5.1/5.2: close pairs of boundary points across an interface move to their
/// centre, with every point related to them, when the movement is valid. Algorithm 5.3: every
/// boundary point of an instance that still lies in the relative interior of a boundary edge of
/// another instance is a vertex-in-facet non-conformity; its preimage is inserted into that
/// template (every instance of it), and the cell on that edge is split by connecting the new
/// vertices to its apex, until nothing hangs. Every decision is exact: the boundary points are
/// exact (a + k/N (b − a), their images and centres), collinearity and order along an edge are
/// exact signs. The vertex identification (compact SVB) is read off the exact structure instance
/// of the boundary complexes, and Lemma 4.2 is certified on them (check_interface_conformity).
#pragma once
#include "symmesh/gen/generation_support.h"
#include "symmesh/gen/templated_triangle_mesh.h"

#include <stdexcept>

namespace symmesh::gen {

/// \pre x is a templated geometry in the plane (geometry templates, Eq. 4.2); o.size > 0.
/// Throws std::invalid_argument for other input, MeshingError when Mesh_2 cannot keep a
/// boundary, MergeError when the sewing does not close within its bounds.
GenerationResult generate_merge(const core::TemplatedStructure<Exact, 2>& x,
                                const GenerationOptions& o);
GenerationResult generate_merge(const core::TemplatedStructure<support::LazyCyclotomic, 2>& x,
                                const GenerationOptions& o);

/// Section 5.1.1 in 3D (interface_merging_3d.cpp, spec/generation.md#merge-3d): every 2-face of
/// every template surface-meshed on its own, the interfaces merged exactly (Algorithm 5.2, then
/// the overlay of Algorithms 5.3/5.4), TetGen inside each template.
/// `copies`: the copies of a group symmetry (support::symmetry_copies), when x is one: then only
/// the interfaces inside copy 0 are merged, as Algorithms 6.1/6.4/6.5 mesh only copy 0's (every
/// other interface lies on a mirror, which each face's own mesh matches, Lemma 6.1), and overlap,
/// bookkeeping and certificate go over the copies near copy 0 instead of every instance pair.
/// \pre x is a templated geometry in space; o.size > 0. Throws std::invalid_argument for other
/// input, MeshingError when TetGen fails or changes a boundary, MergeError when the overlay does
/// not settle within its rounds (naming the interface).
GenerationResult
generate_merge(const core::TemplatedStructure<Exact, 3>& x, const GenerationOptions& o,
               const std::vector<core::RigidTransformation<Exact, 3>>& copies = {});
GenerationResult generate_merge(
    const core::TemplatedStructure<support::LazyCyclotomic, 3>& x, const GenerationOptions& o,
    const std::vector<core::RigidTransformation<support::LazyCyclotomic, 3>>& copies = {});

} // namespace symmesh::gen
