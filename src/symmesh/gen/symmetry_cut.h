/// The cut of a whole symmetric object into the piece its symmetric methods mesh —
/// spec/generation.md#cut
///
/// Algorithm 6.1 (positive side of one mirror), Algorithm 6.4 (of two orthogonal mirrors),
/// Algorithm 6.2 (the slice of a rotational symmetry of order n, between the rays at σ and
/// σ + 2π/n), Algorithm 6.3 (the starting angle σ that maximises the smallest angle the cut
/// introduces with the object's edges) and Algorithm 6.5 (the half-slice between a mirror and the
/// mirror turned by π/n), in 2D, about the origin.
///
/// The cut is exact (K_m): the object's symmetry is verified on the maximal boundary segments of
/// every region, every carrier triangle of the object is clipped by the (convex) fundamental
/// cone, and the clipped pieces' boundary is traced into rings (outer polygons and holes). The
/// pieces are returned as polygons, instanced by the symmetry group, for the templated-geometry
/// reader to triangulate and validate. Only the choice of σ (Algorithm 6.3) is computed in
/// double: it ranks candidate rays, each of which is an exact direction (an object vertex, the
/// foot of the perpendicular from the origin onto an edge, or a rational direction where two
/// edges' angles balance).
#pragma once
#include "symmesh/core/templated_structure.h"
#include "symmesh/number/cyclotomic.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace symmesh::gen {

using CutPoint = std::array<number::Cyclotomic, 2>;

/// The symmetry to cut by, about the origin.
struct SymmetrySpec {
  int rotation_order = 0;        ///< n >= 2, or 0 for no rotation
  std::vector<CutPoint> mirrors; ///< normals of mirror lines through the origin (0, 1 or 2)
  std::optional<CutPoint> start; ///< rotation only: the slice's first ray; none = Algorithm 6.3
};

/// One piece of the cut: a polygon with holes of one region, instanced by the whole group.
struct CutPiece {
  int region = 1;
  std::vector<CutPoint> outer;              ///< counter-clockwise
  std::vector<std::vector<CutPoint>> holes; ///< clockwise
};

/// One element of the symmetry group: rot(2πk/n) ∘ (the mirrors selected by `mirror_bits`).
struct GroupElement {
  int k = 0;
  unsigned mirror_bits = 0; ///< bit j: compose with the reflection in mirrors[j]
};

struct CutResult {
  std::vector<CutPiece> pieces;
  std::vector<GroupElement> group;  ///< the instances of every piece, in this order
  number::CyclotomicFieldPtr field; ///< the numbers' field (null: rationals)
  int rotation_order = 0;
  std::vector<CutPoint> mirrors;
  /// Rotation only: the first ray's exact direction, its angle in [0, 2π/n) in degrees, how it
  /// was chosen ("given", "vertex", "foot", "balance"), and the smallest angle the cut introduces
  /// with the object's edges at that ray and at the ray along the x-axis (Algorithm 6.3's
  /// objective, degrees; 90 when the ray meets no edge).
  CutPoint start_direction;
  double start_angle_deg = 0;
  std::string start_kind;
  double smallest_new_angle_deg = 90, smallest_new_angle_at_x_axis_deg = 90;
};

/// Bad input to the cut (not symmetric, unsupported group, a piece that touches itself, ...):
/// exit 2 in the CLI.
struct CutError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// \pre x is a 2D templated geometry obeying Eq. 4.2 (the caller checks it with
/// core::find_instance_overlap; overlaps along an edge are also caught here); `spec` is one
/// of: rotation n >= 2; one mirror; two orthogonal mirrors; one mirror and rotation n >= 2
/// (Algorithm 6.5). Throws CutError when the object does not have the symmetry (naming the
/// region and a boundary segment without image) or a piece cannot be represented as polygons.
CutResult cut_to_fundamental_piece(const core::TemplatedStructure<number::Cyclotomic, 2>& x,
                                   const SymmetrySpec& spec);

/// Algorithm 6.3's objective in 2D: the smallest angle (degrees, capped at 90) that the ray
/// from the origin in direction (cos σ, sin σ) makes inside the object with the boundary
/// segments it meets: min(θ, 180° − θ) where it crosses a segment's inside (both angles occur,
/// one at each ray of the slice), and the parts of the object's angle where it runs through a
/// vertex. `segments` (ax, ay, bx, by) have the object on their left and lie on no line through
/// the origin (such segments introduce no angle).
double smallest_new_angle_deg(const std::vector<std::array<double, 4>>& segments, double sigma);

} // namespace symmesh::gen
