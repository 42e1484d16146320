/// Pictures of templated meshes (`symmesh render`): the 2D structure instance as SVG/PNG, the
/// boundary surface of a 3D one as SVG/PNG, and a ParaView multiblock (.vtm) with one block per
/// template — spec/outputs.md#render
///
/// The structure instance is visited through mesh::StructureInstance, so interfaces are the
/// compact SVB's identifications (combinatorial), never found by comparing coordinates. Every
/// picture is a pure function of the mesh and the options: the same input gives the same bytes.
#pragma once
#include "symmesh/mesh/templated_mesh.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace symmesh::io {

enum class CellColour { instance, template_, region, quality };

/// A facet-patch segment of a template boundary (Algorithm 4.1), in template coordinates, with
/// its relation class (Def 4.8) and that class's colour in `symmesh bpp` pictures.
struct PatchSegment {
  std::array<double, 2> a{}, b{};
  std::size_t relation_class = 0;
  std::string colour;
};

/// The boundary patches drawn over a 2D picture (`symmesh render --patches STRUCTURE.json`):
/// per template of the mesh, its facet patches' segments (io/bpp_output.h, `patch_overlay`).
struct PatchOverlay {
  std::vector<std::vector<PatchSegment>> per_template;
  std::size_t classes = 0;
};

struct MeshRenderOptions {
  CellColour colour = CellColour::template_;
  double width = 900; ///< pixels of the longer side of the drawing (the legend comes below)
  const PatchOverlay* patches = nullptr; ///< 2D: drawn in every instance over the cells
};

/// 2D: every cell of AT a polygon (`<g class="cells">`, one `<polygon>` per cell and nothing
/// else drawn as a polygon), filled by `o.colour` (quality: the smallest angle, 0° to 60°, with a
/// colour bar); instance interfaces (AT edges whose two cells lie in different instances) and
/// the boundary of AT drawn over them as thicker paths; with `o.patches`, every template's
/// boundary patches carried into each of its instances by the instance's transformation and
/// drawn over those, one path per relation class (`<path class="patches" data-class=…>`); a
/// legend below.
/// 3D: the boundary triangles of AT in a fixed orthographic view (azimuth 35°, elevation 25°),
/// painter's order, shaded by a fixed light; `quality` is 2D-only.
/// \pre t.is_valid(); o.width in [100, 4000]; not CellColour::quality in 3D; o.patches only in
/// 2D and with one entry per template of t (all std::invalid_argument)
std::string mesh_svg(const mesh::TemplatedMeshCompactSvb& t, const MeshRenderOptions& o);

/// Rasterises `svg` to PNG at its own pixel size with rsvg-convert (librsvg2-bin) and writes it
/// to `path` atomically. Throws std::runtime_error when rsvg-convert is missing or fails.
void write_png_from_svg(const std::string& svg, const std::string& path);

/// Writes `path` (.vtm, VTK XML vtkMultiBlockDataSet) and one .vtu per template in the directory
/// next to it named after its stem (`OUT.vtm` + `OUT/OUT_<k>.vtu`): block k holds every instance
/// of template k+1 in structure coordinates (cell data region, template = k+1, instance = g of
/// T_{i,g}). The .vtm is written last, so it never names a block that is missing.
/// \pre t.is_valid()
/// \return the number of blocks
std::size_t write_vtm(const mesh::TemplatedMeshCompactSvb& t, const std::string& path);

} // namespace symmesh::io
