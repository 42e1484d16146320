/// Outputs of `symmesh bpp`: the boundary patch partition (Algorithm 4.1) with its relation
/// (Def 4.8) and regularity verdict (Def 4.9) as JSON, SVG (2D) and VTK XML (.vtu, 2D and 3D)
/// — spec/outputs.md#boundary-patches
///
/// Patch and class ids are indices into the partition's lists (0-based, as in the JSON);
/// templates are numbered from 1 as in the dissertation (X_1, X_2, ...). Coordinates are exact
/// strings in the JSON (core::exact_text) and rounded to double only for the pictures.
#pragma once
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/kernel.h"
#include "symmesh/core/structure_report.h"
#include "symmesh/core/templated_structure.h"
#include "symmesh/io/mesh_render.h"

#include <nlohmann/json.hpp>

#include <string>

namespace symmesh::io {

using number::Cyclotomic;
using Bpp2 = core::BoundaryPatchPartition<Exact, 2>;
using Bpp3 = core::BoundaryPatchPartition<Exact, 3>;
using CyclotomicBpp2 = core::BoundaryPatchPartition<Cyclotomic, 2>;
using CyclotomicBpp3 = core::BoundaryPatchPartition<Cyclotomic, 3>;

/// {"patch", "target", "f1": [mapping names], "f2": [...], "symmetry": {"matrix", "translation"}}
/// with exact strings; shared by `bpp` and `check --json`.
nlohmann::ordered_json irregularity_json(const core::IrregularitySummary& w);

/// The whole partition as one JSON object (keys in spec/outputs.md#bpp-json).
nlohmann::ordered_json bpp_json(const core::TemplatedStructure<Exact, 2>& x, const Bpp2& bpp);
nlohmann::ordered_json bpp_json(const core::TemplatedStructure<Exact, 3>& x, const Bpp3& bpp);
nlohmann::ordered_json bpp_json(const core::TemplatedStructure<Cyclotomic, 2>& x,
                                const CyclotomicBpp2& bpp);
nlohmann::ordered_json bpp_json(const core::TemplatedStructure<Cyclotomic, 3>& x,
                                const CyclotomicBpp3& bpp);

/// One panel per template (template coordinates, side by side): interior lightly filled, facet
/// patches as thick polylines coloured by relation class, lower-dimensional patches as dots,
/// "P<id> c<class>" labels, dashed curves between directly related patches, a class legend.
std::string bpp_svg(const core::TemplatedStructure<Exact, 2>& x, const Bpp2& bpp);
std::string bpp_svg(const core::TemplatedStructure<Cyclotomic, 2>& x, const CyclotomicBpp2& bpp);

/// The facet patches of every template as a picture overlay for `symmesh render --patches`
/// (io/mesh_render.h), coordinates rounded, colours as in bpp_svg.
PatchOverlay patch_overlay(const Bpp2& bpp);
PatchOverlay patch_overlay(const CyclotomicBpp2& bpp);

/// VTK XML UnstructuredGrid (ASCII): every face of the closed boundary subdivision as VTK_VERTEX,
/// VTK_LINE or VTK_TRIANGLE pieces, templates shifted apart along x; CellData "template"
/// (1-based), "patch", "class", "dimension" (of the patch).
std::string bpp_vtu(const Bpp2& bpp);
std::string bpp_vtu(const Bpp3& bpp);
std::string bpp_vtu(const CyclotomicBpp2& bpp);
std::string bpp_vtu(const CyclotomicBpp3& bpp);

} // namespace symmesh::io
