/// Algorithm 5.7 (templated tetrahedral mesh generation using the boundary patch partition) —
/// spec/generation.md#alg-5-7
///
/// The 3D path of the one generation pipeline (spec/generation.md#pipeline): the boundary patch
/// partition (Algorithm 4.1, core) cuts every template boundary into faces on which all template
/// boundary mappings act face to face; the boundary meshes are the line meshes of the edge faces
/// (uniform, N decided exactly, as in 2D) and the surface meshes of the 2-faces: every class of
/// 2-faces related by the mappings is triangulated once, in the plane of its first face and
/// conforming to the line meshes of its edges, and carried to every other face of the class by
/// the exact composition of mappings, so that a mapping sends the surface mesh of a face onto the
/// surface mesh of its image vertex for vertex (Lemma 4.2 by construction). Each template is then
/// tetrahedralized by TetGen with its boundary kept (tetrahedral_mesher.h, -pY), the SVB is
/// read off the face-to-face action (shared_vertex_bookkeeping.h), and the Lemma 4.2 certificate
/// runs exactly on the templates' boundary complexes.
#pragma once
#include "symmesh/core/kernel.h"
#include "symmesh/core/templated_structure.h"
#include "symmesh/gen/templated_triangle_mesh.h"
#include "symmesh/number/cyclotomic.h"

namespace symmesh::gen {

/// The 3D methods of `symmesh generate --method` (spec/generation.md#alg-5-7): automatic (= bpp
/// for now), bpp and conventional (the regions of AT as templates instanced once, meshed by the
/// same pipeline and TetGen with the same switches). Others throw std::invalid_argument.
///
/// \pre x is a 3D templated geometry (geometry templates, Eq. 4.2); options.size > 0. Throws
/// std::invalid_argument for other input and for a face class whose symmetric surface mesh
/// cannot be built (spec/generation.md#symmetric-surface-meshes: e.g. a rotation centre on the
/// face's boundary), and MeshingError when TetGen changes a template boundary.
GenerationResult generate_tetrahedral_mesh(const core::TemplatedStructure<Exact, 3>& x,
                                           Method method, const GenerationOptions& options);
GenerationResult generate_tetrahedral_mesh(const core::TemplatedStructure<number::Cyclotomic, 3>& x,
                                           Method method, const GenerationOptions& options);

/// The volume of AT(X) (exact, rounded once) and the number of tetrahedra TetGen makes of it at
/// `size` (spec/generation.md#cell-estimate).
CellEstimate estimate_cells(const core::TemplatedStructure<Exact, 3>& x, double size);
CellEstimate estimate_cells(const core::TemplatedStructure<number::Cyclotomic, 3>& x, double size);

} // namespace symmesh::gen
