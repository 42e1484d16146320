/// The carrier tetrahedralization of a 3D geometry template given as a piecewise linear complex
/// (Definition 2.3 PLC, Definition 4.4 geometry template) — spec/input-format.md#plc
///
/// A 3D geometry template is read as polygonal faces; the reader triangulates each face in its
/// own plane (no new vertex) and hands the triangulated surface here. Two steps, both exact:
///  1. `find_surface_defect`: the surface bounds a solid — every edge lies in exactly two
///     triangles (closed and edge-manifold) and triangles of different faces meet only in
///     common vertices or edges (no self-intersection, no overlap).
///  2. `carrier_tetrahedralization`: TetGen (-pY) tetrahedralizes the rounded surface without a
///     point on it; the result is then certified on the exact coordinates — every input triangle
///     is the face of exactly one kept tetrahedron, every other face of exactly two that lie on
///     opposite sides of it, and no tetrahedron is flat — so the carrier's underlying space is
///     exactly the solid the faces bound. Cavities (a closed shell inside another) are left out
///     by the parity of the shells crossed. Interior Steiner points are exact (dyadic) values.
/// The carrier is only the template's geometry (Definition 4.4): generation re-meshes it.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/point.h"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace symmesh::gen {

template <class FT>
struct TriangulatedSurface {
  std::vector<core::Point<FT, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::size_t> face; ///< the polygonal face each triangle comes from
};

/// A reason the surface bounds no solid, and the face it is found at.
struct SurfaceDefect {
  std::size_t face = 0;
  std::string what;
};

/// The first defect of `s`, or nothing when it is closed, edge-manifold and embedded.
/// \pre every triangle is non-degenerate and the triangles of one face do not overlap
template <class FT>
std::optional<SurfaceDefect> find_surface_defect(const TriangulatedSurface<FT>& s);

/// The carrier of the solid bounded by `s`: input points first, in order, then interior points.
/// \pre !find_surface_defect(s)
/// Throws MeshingError when TetGen's result cannot be certified exactly.
template <class FT>
core::ElementComplex<FT, 3> carrier_tetrahedralization(const TriangulatedSurface<FT>& s);

} // namespace symmesh::gen
