/// Definition 4.1 (geometry decomposition, geometry block, geometry template, geometry instance)
/// — spec/definitions.md#def-4-1
///
/// Geometries are linear multi-region geometries stored by carriers (Def 2.2,
/// `MultiRegionGeometry`); the blocks' carriers need not match G's. Decided exactly, as point
/// sets:
///  (i) a manifold partition of G into D-dimensional blocks: every block cell lies in G
///      (`cell_covered_by`), cells of different blocks have disjoint interiors, and the block
///      volumes add up to G's. Then ∪ G_i ⊆ G with equal volume, and a non-empty relatively open
///      rest of the pure D-dimensional G would have positive volume, so ∪ G_i = G.
///  (ii) ξ̃_i = ξ̃ on int*(G_i): every block cell of region r lies in G's region r, and for every
///      r the block regions r add up to G's region r in volume. Then G's region r is the union of
///      the blocks' regions r (as in (i)), so a point of int(G_i) lies in G's region r iff it lies
///      in G_i's region r.
/// A geometry template (𝒯, ζ̃) of a block with rigid T: T(𝒯)'s region r geometry-conforms to the
/// block's region r for every r (Def 2.10, exact), and both have the same regions.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/geometry_conforming.h"
#include "symmesh/core/multi_region_geometry.h"
#include "symmesh/core/refined_mesh.h"
#include "symmesh/core/rigid_transformation.h"

#include <map>
#include <ostream>
#include <vector>

namespace symmesh::core {

namespace detail {
/// D! · volume of the cells of g with region r (all cells when r is empty).
template <class FT, int D>
FT region_volume(const MultiRegionGeometry<FT, D>& g, std::optional<int> r = std::nullopt) {
  FT v = 0;
  for (const auto& [c, id] : g.cell_region)
    if (!r || id == *r) v += simplex_volume_times_factorial<FT, D>(g.carrier.coords(c));
  return v;
}

template <class FT, int D>
bool block_interiors_disjoint(const std::vector<MultiRegionGeometry<FT, D>>& blocks,
                              std::ostream* why) {
  std::vector<std::vector<Point<FT, D>>> cells;
  std::vector<std::size_t> owner;
  std::vector<Box<FT, D>> boxes;
  for (std::size_t i = 0; i < blocks.size(); ++i)
    for (const auto& [c, r] : blocks[i].cell_region) {
      cells.push_back(blocks[i].carrier.coords(c));
      owner.push_back(i);
      boxes.push_back(box_of<FT, D>(cells.back()));
    }
  bool ok = true;
  for_each_overlapping_pair<FT, D>(boxes, [&](std::size_t a, std::size_t b) {
    if (owner[a] != owner[b] && relative_interiors_meet<FT, D>(cells[a], cells[b])) {
      if (why) *why << "blocks " << owner[a] << " and " << owner[b] << " overlap";
      ok = false;
    }
    return ok;
  });
  return ok;
}
} // namespace detail

/// Def 4.1 (i), (ii). \pre g and every block are valid multi-region geometries (checked; a
/// violation returns false with the reason)
template <class FT, int D>
bool is_geometry_decomposition(const MultiRegionGeometry<FT, D>& g,
                               const std::vector<MultiRegionGeometry<FT, D>>& blocks,
                               std::ostream* why = nullptr) {
  if (!g.is_valid(why)) return false;
  FT total = 0;
  std::map<int, FT> by_region;
  std::map<int, ElementComplex<FT, D>> g_regions;
  for (int r : g.region_ids()) g_regions.emplace(r, g.region(r));
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (!blocks[i].is_valid(why)) return false;
    for (const auto& [c, r] : blocks[i].cell_region) {
      const auto coords = blocks[i].carrier.coords(c);
      const auto gr = g_regions.find(r);
      if (gr == g_regions.end() || !cell_covered_by<FT, D>(coords, gr->second)) {
        if (why) *why << "block " << i << ": a cell of region " << r << " leaves G's region " << r;
        return false;
      }
      const FT v = simplex_volume_times_factorial<FT, D>(coords);
      total += v;
      by_region[r] += v;
    }
  }
  if (!detail::block_interiors_disjoint(blocks, why)) return false;
  if (total != detail::region_volume(g)) {
    if (why) *why << "the blocks do not cover G";
    return false;
  }
  for (const auto& [r, complex] : g_regions)
    if (by_region[r] != detail::region_volume(g, r)) {
      if (why) *why << "the blocks' region " << r << " is not G's region " << r;
      return false;
    }
  return true;
}

/// Def 4.1: (templ, ζ̃) is a geometry template of `block` with rigid transformation t.
template <class FT, int D>
bool is_geometry_instance(const MultiRegionGeometry<FT, D>& templ,
                          const MultiRegionGeometry<FT, D>& block,
                          const RigidTransformation<FT, D>& t, std::ostream* why = nullptr) {
  if (templ.region_ids() != block.region_ids()) {
    if (why) *why << "T(template) and the block have different regions";
    return false;
  }
  for (int r : templ.region_ids()) {
    auto image = templ.region(r);
    for (auto& p : image.points) p = t(p);
    if (!geometry_conforms(image, block.region(r))) {
      if (why) *why << "region " << r << " of T(template) is not the block's region " << r;
      return false;
    }
  }
  return true;
}

} // namespace symmesh::core
