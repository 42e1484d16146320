/// Algorithm 5.5 (initialise a templated mesh) and Algorithm 5.6 (templated triangle mesh
/// generation using the boundary patch partition) — spec/generation.md#alg-5-6
///
/// From a 2D templated geometry: the boundary patch partition (Algorithm 4.1) cuts every template
/// boundary into faces on which all template boundary mappings act face to face. Every edge face
/// is split into N equal parts, N = the smallest integer with N·size >= its length, decided
/// exactly; congruent faces get the same N, so a mapping sends the line mesh of a face onto the
/// line mesh of its image (Lines 11–20), and each line mesh is symmetric under the reflection
/// that swaps its ends (what Line 15 asks for irregular instance graphs). Each template is then
/// meshed without touching its boundary (Line 24, triangle_mesher.h). Interface vertices are
/// identified combinatorially: a mapping sends face f to face g and the k-th point of f to the
/// k-th or (N-k)-th point of g, which gives the compact SVB tables (templated_mesh.h).
/// Afterwards the Lemma 4.2 checker certifies the result in exact arithmetic on the templates'
/// boundary complexes (spec/lemmas.md#lemma-4-2-boundary).
#pragma once
#include "symmesh/core/kernel.h"
#include "symmesh/core/templated_structure.h"
#include "symmesh/mesh/progress.h"
#include "symmesh/mesh/quality.h"
#include "symmesh/mesh/templated_mesh.h"
#include "symmesh/number/cyclotomic.h"

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>

namespace symmesh::gen {

struct GenerationOptions {
  double size = 0;
  double min_angle_deg = 20;
  /// Progress lines (stage, counts, elapsed seconds); nullptr = quiet.
  mesh::Progress* progress = nullptr;
  /// Fault injection for tests (3D): after the surface meshes are carried to every face of their
  /// class, move one interior vertex of one interface face a little within its plane (exactly),
  /// so that its instances no longer conform and the Lemma 4.2 certificate must fail.
  bool perturb_one_surface_mesh = false;
  /// Fault injection for tests (3D): the frame of one face carried in face coordinates moves
  /// within its plane, its points with it, as a defect in carrying the copies would (the
  /// certificate's frame check must fail).
  bool perturb_one_face_frame = false;
  /// 3D: certify with the general Lemma 4.2 checker on the exact boundary complexes (every pair
  /// of neighbouring instances, condition (i) by a sweep) instead of mapping by mapping; slower,
  /// the independent check the tests compare with (spec/lemmas.md#lemma-4-2-surface-meshes).
  bool direct_certificate = false;
  /// 3D: the outlier repair after TetGen (spec/generation.md#outlier-repair: flips, point removals
  /// and moves of TetGen's interior points on the tetrahedra beyond radius-edge √2 or below a 10°
  /// dihedral angle; the boundary is not touched).
  bool repair_outliers = true;
  /// 3D: TetGen's -q/D, the smallest dihedral angle it refines towards, in every TetGen call of
  /// the 3D methods (templates and the whole geometry alike; 0: none) — spec/generation.md#mesher-3
  double tetgen_min_dihedral_deg = mesh::kDihedralBoundDeg;
};

struct GenerationTimings {
  double boundary_patch_partition = 0, line_meshes = 0, template_meshing = 0, svb = 0,
         certificate = 0;
  /// 3D: the part of template_meshing that the outlier repair after TetGen took.
  double outlier_repair = 0;
  double total() const {
    return boundary_patch_partition + line_meshes + template_meshing + svb + certificate;
  }
  /// Minor page faults per step (getrusage): a step that first touches fresh memory pays for it
  /// (about 10 µs per page on the benchmark VM), so a step that frees memory another step reuses
  /// moves time between the two; the counts make that visible.
  struct PageFaults {
    long boundary_patch_partition = 0, line_meshes = 0, template_meshing = 0, svb = 0,
         certificate = 0;
  } page_faults;
};

struct GenerationResult {
  mesh::TemplatedMeshCompactSvb templated;
  std::string method; ///< the method that ran ("bpp", "rotational", "conventional", "gmsh")
  GenerationTimings timings;
  bool lemma_4_2_holds = false;
  std::string lemma_4_2_failure; ///< the failing instance pair, when it does not hold
  /// --method merge (spec/generation.md#merge): interface points Algorithm 5.3 inserted, its
  /// rounds, close pairs Algorithm 5.2 merged and the points it moved.
  std::size_t merge_insertions = 0, merge_rounds = 0, merge_merged = 0, merge_moves = 0;
  /// 3D outlier repair (spec/generation.md#outlier-repair), summed over the TetGen calls: cells
  /// beyond its bounds before and after it, and its flips and vertex moves.
  std::size_t outliers_before = 0, outliers_after = 0, repair_flips = 0, repair_moves = 0,
              repair_removals = 0;
  /// --method gmsh in 3D: Gmsh's error when its optimizer failed and the mesh is the retry
  /// without it (gmsh_mesher.h); empty otherwise.
  std::string gmsh_optimizer_failure;
};

/// The generation methods of `symmesh generate --method` (spec/generation.md):
///  automatic    the first of rotational, combined, reflective whose exact check passes, else
///               bpp;
///  bpp          Algorithm 5.6 over the boundary patch partition;
///  rotational   Section 6.3 with Algorithm 6.2: every template instanced by the n rotations
///               T_{i,k} = R^k ∘ T_{i,0} (checked exactly); the BPP of the first two copies,
///               its mappings replicated to all n consecutive pairs for the SVB; otherwise as bpp;
///  reflective   Algorithms 6.1/6.4 on templated input: the copies S_k (T_{i,k} = S_k ∘ T_{i,0})
///               are I and one reflection, or the compositions of two orthogonal reflections
///               (checked exactly); the BPP of copy 0 only (region interfaces), mirrors need
///               nothing (Lemma 6.1); SVB: copy-0 mappings for every copy, plus the points each
///               relative map T_{i,l}^-1 ∘ T_{i,k} sends onto template points;
///  combined     Algorithm 6.5 likewise, the copies a dihedral group (reflection + rotation of
///               order >= 3);
///  conventional the baseline of Section 7.1: per region, AT of that region's instances as one
///               template with one instance, through the same line meshing and mesher with the
///               same parameters (region boundaries stay mesh edges);
///  sao          Section 6.3.2: a rotational slice structure (one template) is cut into a centre
///               n-gon, instanced once, and the ring slice, instanced by the rotations (other
///               structures are taken as cut already); then Algorithm 5.6 with line meshes
///               refined until the full Delaunay refinement splits no boundary segment, so that
///               every triangle meets --min-angle (spec/generation.md#sao);
///  gmsh         the peer: the whole geometry, per region, meshed by Gmsh's 2D Delaunay at the
///               same size (Gmsh has no smallest-angle parameter).
/// --method merge could not sew the interfaces within its bounds (the CLI's exit 1; names the
/// instances): spec/generation.md#merge.
struct MergeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Method {
  automatic,
  bpp,
  rotational,
  reflective,
  combined,
  conventional,
  gmsh,
  sao,
  merge
};

/// \pre x is a templated geometry (geometry templates, Eq. 4.2); options.size > 0. Throws
/// std::invalid_argument for other input (and for `rotational` on a structure that is not
/// rotational) and MeshingError when the mesher cannot respect a boundary.
GenerationResult generate_triangle_mesh(const core::TemplatedStructure<Exact, 2>& x, Method method,
                                        const GenerationOptions& options);
GenerationResult generate_triangle_mesh(const core::TemplatedStructure<number::Cyclotomic, 2>& x,
                                        Method method, const GenerationOptions& options);

/// The area of AT(X) (exact: the sum over instances of the template carriers' areas, rounded
/// once) and the number of triangles Mesh_2 makes of it at `size`: about area / (0.2 size²),
/// measured on the n-gon slices (961 408 triangles of the 128-gon at size 0.003963, where the
/// formula gives 999 800) — spec/generation.md#cell-estimate. Used to refuse an infeasible
/// --size before any work.
/// In 3D (templated_tetrahedral_mesh.h) the measure is the volume and the cells are tetrahedra.
struct CellEstimate {
  int dimension = 2;
  double measure = 0; ///< area (2D) or volume (3D) of AT(X)
  double cells = 0;   ///< triangles (2D) or tetrahedra (3D)
};
CellEstimate estimate_cells(const core::TemplatedStructure<Exact, 2>& x, double size);
CellEstimate estimate_cells(const core::TemplatedStructure<number::Cyclotomic, 2>& x, double size);

} // namespace symmesh::gen
