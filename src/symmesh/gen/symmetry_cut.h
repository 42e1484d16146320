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

// ----- 3D ----------------------------------------------------------------------------------

using CutPoint3 = std::array<number::Cyclotomic, 3>;

/// The symmetry to cut a 3D object by: a rotation about the z axis and mirror planes through
/// the origin.
struct SymmetrySpec3 {
  int rotation_order = 0;         ///< n >= 2 about the z axis, or 0 for no rotation
  std::vector<CutPoint3> mirrors; ///< normals of mirror planes through the origin (0 to 3)
  /// Rotation only: the direction (x, y) of the slice's first half-plane; none = the x axis
  /// (Algorithm 6.3's choice of the starting angle is 2D only).
  std::optional<CutPoint> start;
};

/// One piece of the 3D cut: one instance of the object clipped to the fundamental cone, as a
/// carrier tetrahedralization (conforming, positively oriented), instanced by the whole group.
struct CutPiece3 {
  int region = 1;
  std::string name; ///< the instance's template name (and instance number)
  std::vector<CutPoint3> points;
  std::vector<std::array<std::size_t, 4>> tetrahedra;
};

struct CutResult3 {
  std::vector<CutPiece3> pieces;
  std::vector<GroupElement> group; ///< the instances of every piece, in this order
  number::CyclotomicFieldPtr field;
  int rotation_order = 0;
  std::vector<CutPoint3> mirrors;
  CutPoint3 start_direction; ///< rotation only: the first half-plane's direction (z = 0)
};

/// The cut of a whole 3D object (spec/generation.md#cut-3d): Algorithm 6.2 about the z axis
/// (slice between the half-planes at σ and σ + 2π/n), 6.1/6.4 (positive part of one to three
/// orthogonal mirror planes) and 6.5 (half-slice between a mirror plane through the z axis and
/// that plane turned by π/n). Exact in K_m. The symmetry is verified on volumes: every generator
/// g maps each region R into itself, vol(g(R) ∩ R) = vol(R), computed tetrahedron by tetrahedron.
/// \pre x is a 3D templated geometry obeying Eq. 4.2 (the caller checks it). Throws CutError
/// when the object does not have the symmetry (naming the element and region) or the spec is bad.
CutResult3 cut_to_fundamental_piece(const core::TemplatedStructure<number::Cyclotomic, 3>& x,
                                    const SymmetrySpec3& spec);

} // namespace symmesh::gen
