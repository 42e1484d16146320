/// Shared vertex bookkeeping (SVB) of Algorithms 5.6 and 5.7, for both dimensions —
/// spec/generation.md#svb, spec/mesh-data-structures.md#compact-svb
///
/// The boundary meshes (line meshes in 2D, surface meshes in 3D) are built so that every
/// template boundary mapping sends the boundary mesh of a face onto the boundary mesh of its
/// image, vertex for vertex. What a mapping identifies is therefore a list of (from-template
/// vertex, to-template vertex) pairs known combinatorially (the dimension-specific stage supplies
/// it as `pairs_of(letter)`); this stage turns those lists into the compact SVB without any
/// coordinate comparison. The mesher numbers the boundary vertices first, so only vertices below
/// a template's boundary count are ever identified. Internal to gen/.
#pragma once
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/templated_structure.h"
#include "symmesh/gen/generation_support.h"
#include "symmesh/mesh/templated_mesh.h"
#include "symmesh/mesh/union_find.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace symmesh::gen::support {

/// One candidate of the SVB: the instance pair (from, to) and its identified template vertices.
using SvbPairs = std::vector<std::pair<mesh::IndexType, mesh::IndexType>>;
/// The copies of one mapping share one pair list (a rotational mapping stands for n pairs).
struct SvbCandidate {
  core::InstanceId from, to;
  std::shared_ptr<const SvbPairs> pairs;
};

/// The pairs a template boundary mapping identifies on the vertex and edge faces of its domain,
/// from the automaton alone: each vertex with its image, and the k-th line-mesh point of an edge
/// face with the k-th or (N-k)-th of its image (depending on where the edge's first vertex goes).
/// `from_lines` / `to_lines`: the line meshes of the from- and to-template, per subdivision face.
template <class FT, int D>
void vertex_and_line_pairs(const core::BoundaryPatchPartition<FT, D>& bpp, std::size_t letter,
                           const std::vector<FaceLine>& from_lines,
                           const std::vector<FaceLine>& to_lines, SvbPairs& pairs) {
  const auto& m = bpp.mappings[letter];
  const auto& src = bpp.subdivisions[m.from_template()];
  const auto& dst = bpp.subdivisions[m.to_template()];
  // Vertex faces first in the list, so the image of an edge's first vertex is known.
  std::map<std::size_t, std::size_t> vertex_image;
  for (auto [f, g] : bpp.letter_action[letter])
    if (src.faces[f].dimension == 0) {
      vertex_image[src.faces[f].vertices[0]] = dst.faces[g].vertices[0];
      pairs.emplace_back(mesh::IndexType(src.faces[f].vertices[0]),
                         mesh::IndexType(dst.faces[g].vertices[0]));
    }
  for (auto [f, g] : bpp.letter_action[letter]) {
    const auto& face = src.faces[f];
    if (face.dimension != 1) continue;
    const auto& lf = from_lines[f];
    const auto& lg = to_lines[g];
    if (lf.n != lg.n) throw std::logic_error("SVB: a mapping joins faces of different line meshes");
    const auto it = vertex_image.find(face.vertices[0]);
    if (it == vertex_image.end())
      throw std::logic_error("SVB: a mapping applies to an edge but not to its end");
    const bool same_direction = it->second == dst.faces[g].vertices[0];
    for (std::size_t k = 1; k < lf.n; ++k)
      pairs.emplace_back(mesh::IndexType(lf.first + k - 1),
                         mesh::IndexType(lg.first + (same_direction ? k - 1 : lf.n - k - 1)));
  }
}

/// The BPP's mappings between distinct instances, one direction each (the inverse is a mapping
/// too). `rotations` > 0 (the rotational method): the BPP was computed on the first two rotated
/// copies only, and every mapping from copy a to copy b stands for all pairs (k, k + b - a mod n).
/// `copies` > 0 (reflective/combined): the BPP was computed on copy 0 only, and every mapping
/// from (i,0) to (j,0) stands for all pairs ((i,k), (j,k)).
template <class FT, int D>
std::vector<SvbCandidate> svb_candidates(const core::TemplatedStructure<FT, D>& x,
                                         const core::BoundaryPatchPartition<FT, D>& bpp,
                                         const std::function<SvbPairs(std::size_t)>& pairs_of,
                                         std::size_t rotations, std::size_t copies = 0) {
  std::vector<std::size_t> instance_offset;
  std::size_t instances = 0;
  for (const auto& list : x.instances) {
    instance_offset.push_back(instances);
    instances += list.size();
  }
  const auto global = [&](core::InstanceId id) { return instance_offset[id.i] + id.g; };
  std::vector<SvbCandidate> out;
  for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
    const auto& m = bpp.mappings[l];
    if (m.whole_boundary) continue;
    if (copies > 0) {
      const auto pairs = std::make_shared<const SvbPairs>(pairs_of(l));
      for (std::size_t k = 0; k < copies; ++k) {
        const core::InstanceId from{m.from.i, k}, to{m.to.i, k};
        if (global(from) < global(to)) out.push_back({from, to, pairs});
      }
      continue;
    }
    if (rotations == 0) {
      if (global(m.from) < global(m.to))
        out.push_back({m.from, m.to, std::make_shared<const SvbPairs>(pairs_of(l))});
      continue;
    }
    const auto pairs = std::make_shared<const SvbPairs>(pairs_of(l));
    const std::size_t n = rotations, shift = (m.to.g + n - m.from.g) % n;
    for (std::size_t k = 0; k < n; ++k) {
      const core::InstanceId from{m.from.i, k}, to{m.to.i, (k + shift) % n};
      if (global(from) < global(to)) out.push_back({from, to, pairs});
    }
  }
  return out;
}

/// Compact SVB: one table per distinct set of pairs, and a spanning set of instance pairs. The
/// union-find runs over the boundary vertices only (`boundary_vertices[i]` of template i), so
/// its size is the boundary size, not the cell count.
template <class FT, int D>
void shared_vertex_bookkeeping(const core::TemplatedStructure<FT, D>& x,
                               const std::vector<std::size_t>& boundary_vertices,
                               std::vector<SvbCandidate> candidates,
                               mesh::TemplatedMeshCompactSvb& out) {
  std::vector<std::size_t> instance_offset, vertex_offset;
  std::size_t instances = 0, vertices = 0;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    instance_offset.push_back(instances);
    vertex_offset.push_back(vertices);
    instances += x.instances[i].size();
    vertices += x.instances[i].size() * boundary_vertices[i];
  }
  const auto global_instance = [&](core::InstanceId id) { return instance_offset[id.i] + id.g; };
  const auto first_vertex = [&](core::InstanceId id) {
    return vertex_offset[id.i] + id.g * boundary_vertices[id.i];
  };
  // Interfaces with many identified vertices first, so point contacts implied by them drop out.
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const SvbCandidate& a, const SvbCandidate& b) {
                     return a.pairs->size() > b.pairs->size();
                   });
  mesh::UnionFind uf(vertices);
  // Tables are deduplicated by content; the copies of one mapping share their list, so the
  // content is compared once per list, not once per instance pair.
  std::map<std::tuple<std::size_t, std::size_t, SvbPairs>, std::size_t> table_of;
  std::map<std::tuple<std::size_t, std::size_t, const SvbPairs*>, std::size_t> table_of_list;
  for (const auto& c : candidates) {
    bool adds = false;
    for (auto [a, b] : *c.pairs) {
      if (std::size_t(a) >= boundary_vertices[c.from.i] ||
          std::size_t(b) >= boundary_vertices[c.to.i])
        throw std::logic_error("SVB: an identified vertex is not a boundary vertex");
      adds = uf.unite(first_vertex(c.from) + std::size_t(a), first_vertex(c.to) + std::size_t(b)) ||
             adds;
    }
    if (!adds) continue;
    auto [by_list, fresh] =
        table_of_list.emplace(std::make_tuple(c.from.i, c.to.i, c.pairs.get()), 0);
    if (fresh) {
      auto [it, inserted] =
          table_of.emplace(std::make_tuple(c.from.i, c.to.i, *c.pairs), out.tables.size());
      if (inserted)
        out.tables.push_back({mesh::IndexType(c.from.i), mesh::IndexType(c.to.i), *c.pairs});
      by_list->second = it->second;
    }
    out.identifications.push_back({mesh::IndexType(global_instance(c.from)),
                                   mesh::IndexType(global_instance(c.to)),
                                   mesh::IndexType(by_list->second)});
  }
}

/// A template's boundary points, found by exact equality among the few whose certified interval
/// boxes meet the query's: a grid over the boxes' midpoints (cells of 2^-20 of the points' extent)
/// prunes, the exact comparison decides. Equal exact values have intersecting intervals, so it
/// finds what an exact ordered map finds, without the map's exact comparisons of near points (or
/// its K_m evaluations of every probe's neighbours). A probe whose box spans more than four cells
/// per axis falls back to the exact map.
template <class FT, int D>
class BoundaryPointLocator {
public:
  explicit BoundaryPointLocator(const std::vector<core::Point<FT, D>>& pts) : pts_(pts) {
    double extent = 0;
    boxes_.reserve(pts.size());
    for (const auto& p : pts) {
      Box b;
      for (int d = 0; d < D; ++d) {
        b[std::size_t(d)] = CGAL::to_interval(p[d]);
        reach_ = std::max(reach_, b[std::size_t(d)].second - b[std::size_t(d)].first);
        extent = std::max(extent, std::abs(b[std::size_t(d)].first));
      }
      boxes_.push_back(b);
    }
    cell_ = std::max(extent, 1e-300) * 0x1p-20;
    for (std::size_t v = 0; v < pts.size(); ++v) grid_[key(boxes_[v])].push_back(v);
  }

  using Box = std::array<std::pair<double, double>, D>;

  /// The certified interval box of point v.
  const Box& box(std::size_t v) const { return boxes_[v]; }

  /// The index of the point equal to q, if any.
  std::optional<std::size_t> find(const core::Point<FT, D>& q) const {
    Box b;
    for (int d = 0; d < D; ++d) b[std::size_t(d)] = CGAL::to_interval(q[d]);
    return find(b, [&] { return q; });
  }

  /// The index of the point equal to the point `exact()` builds, whose value lies in box b:
  /// exact() is called only when some point's box meets b.
  template <class Exact>
  std::optional<std::size_t> find(const Box& b, Exact&& exact) const {
    std::array<std::int64_t, D> lo{}, hi{};
    std::optional<core::Point<FT, D>> q;
    const auto probe = [&]() -> const core::Point<FT, D>& {
      if (!q) q = exact();
      return *q;
    };
    for (int d = 0; d < D; ++d) {
      const double l = std::floor((b[std::size_t(d)].first - reach_) / cell_);
      const double h = std::floor((b[std::size_t(d)].second + reach_) / cell_);
      if (!(h - l <= 4) || !(std::abs(l) < 0x1p62) || !(std::abs(h) < 0x1p62))
        return exact_find(probe());
      lo[std::size_t(d)] = std::int64_t(l);
      hi[std::size_t(d)] = std::int64_t(h);
    }
    std::array<std::int64_t, D> k = lo;
    for (;;) {
      if (const auto it = grid_.find(k); it != grid_.end())
        for (std::size_t v : it->second)
          if (meets(boxes_[v], b) && pts_[v] == probe()) return v;
      int d = 0;
      while (d < D && k[std::size_t(d)] == hi[std::size_t(d)])
        k[std::size_t(d)] = lo[std::size_t(d)], ++d;
      if (d == D) return std::nullopt;
      ++k[std::size_t(d)];
    }
  }

private:
  static bool meets(const Box& a, const Box& b) {
    for (int d = 0; d < D; ++d)
      if (a[std::size_t(d)].second < b[std::size_t(d)].first ||
          b[std::size_t(d)].second < a[std::size_t(d)].first)
        return false;
    return true;
  }
  std::array<std::int64_t, D> key(const Box& b) const {
    std::array<std::int64_t, D> k{};
    for (int d = 0; d < D; ++d)
      k[std::size_t(d)] = std::int64_t(std::floor(
          (b[std::size_t(d)].first + (b[std::size_t(d)].second - b[std::size_t(d)].first) / 2) /
          cell_));
    return k;
  }
  std::optional<std::size_t> exact_find(const core::Point<FT, D>& q) const {
    if (exact_.empty())
      for (std::size_t v = 0; v < pts_.size(); ++v) exact_.emplace(pts_[v], v);
    const auto it = exact_.find(q);
    if (it == exact_.end()) return std::nullopt;
    return it->second;
  }

  const std::vector<core::Point<FT, D>>& pts_;
  std::vector<Box> boxes_;
  double reach_ = 0, cell_ = 1;
  std::map<std::array<std::int64_t, D>, std::vector<std::size_t>> grid_;
  mutable std::map<core::Point<FT, D>, std::size_t, core::PointLess<FT, D>> exact_;
};

/// The SVB candidates of the copies of one template (Algorithms 6.1/6.4/6.5): vertex p of copy k
/// is vertex q of copy l when T_{i,l}^-1 ∘ T_{i,k} sends p to q (exact, over the template's exact
/// boundary points `boundary_points[i]`, in local vertex ids). On a mirror the relative map is
/// the reflection that fixes the mirror pointwise (Lemma 6.1).
template <class FT, int D>
void copy_candidates(const core::TemplatedStructure<FT, D>& x,
                     const std::vector<std::vector<core::Point<FT, D>>>& boundary_points,
                     std::vector<SvbCandidate>& out) {
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    const auto& pts = boundary_points[i];
    const BoundaryPointLocator<FT, D> local(pts);
    const auto& list = x.instances[i];
    using I = CGAL::Interval_nt<false>;
    for (std::size_t k = 0; k < list.size(); ++k)
      for (std::size_t l = k + 1; l < list.size(); ++l) {
        const auto m = list[l].transformation.inverse() * list[k].transformation;
        // m's entries as intervals: the image box of each point costs a few interval operations,
        // and the exact image is built only for the points whose box meets a stored one.
        std::array<std::array<I, D + 1>, D> mi;
        for (int r = 0; r < D; ++r) {
          for (int c = 0; c < D; ++c)
            mi[std::size_t(r)][std::size_t(c)] = I(CGAL::to_interval(m.matrix()[r][c]));
          mi[std::size_t(r)][std::size_t(D)] = I(CGAL::to_interval(m.translation_part()[r]));
        }
        std::vector<typename BoundaryPointLocator<FT, D>::Box> image(pts.size());
        {
          // Upward rounding for the unprotected intervals, only around these interval operations
          // (the exact comparisons below expect the default rounding).
          CGAL::Protect_FPU_rounding<true> upward;
          for (std::size_t v = 0; v < pts.size(); ++v)
            for (int r = 0; r < D; ++r) {
              I s = mi[std::size_t(r)][std::size_t(D)];
              for (int c = 0; c < D; ++c)
                s += mi[std::size_t(r)][std::size_t(c)] * I(local.box(v)[std::size_t(c)]);
              image[v][std::size_t(r)] = {s.inf(), s.sup()};
            }
        }
        SvbPairs pairs;
        for (std::size_t v = 0; v < pts.size(); ++v)
          if (const auto w = local.find(image[v], [&] { return m(pts[v]); }))
            pairs.emplace_back(mesh::IndexType(v), mesh::IndexType(*w));
        if (!pairs.empty())
          out.push_back({{i, k}, {i, l}, std::make_shared<const SvbPairs>(std::move(pairs))});
      }
  }
}

} // namespace symmesh::gen::support
