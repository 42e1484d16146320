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
#include "symmesh/gen/symmetry_copies.h"
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

/// Boundary points first .. first+count-1 of a template that are affine combinations of
/// `spanning` (the interior points of a planar face, p0 + s u + t v): a map that fixes the
/// spanning points fixes all of them, decided by |spanning| exact tests instead of count.
template <class FT, int D>
struct AffinePointRange {
  std::size_t first = 0, count = 0;
  std::vector<core::Point<FT, D>> spanning;
};

/// The SVB candidates of the copies of one template (Algorithms 6.1/6.4/6.5): vertex p of copy k
/// is vertex q of copy l when T_{i,l}^-1 ∘ T_{i,k} sends p to q (exact, over the template's exact
/// boundary points `boundary_points[i]`, in local vertex ids). On a mirror the relative map is
/// the reflection that fixes the mirror pointwise (Lemma 6.1).
/// The copies S_k = T_{0,k} ∘ T_{0,0}^-1 form a group (symmetry_copies checked it), so
/// T_{i,l}^-1 ∘ T_{i,k} = T_{i,0}^-1 ∘ S_g ∘ T_{i,0} with S_g = S_l^-1 ∘ S_k: the pairs of each
/// group element g are found once (O(n) maps, not the n^2 pairs of copies; a map whose image of
/// the template's box misses the box finds none), then every pair (k, l) with S_k = S_l ∘ S_g
/// gets them — in the order of the pairs k < l, as the pairwise search gave them.
/// \pre T_{i,k} = S_k ∘ T_{i,0} for every template i, {S_k} closed under composition
/// `ranges[i]` (optional): template i's boundary points known to be affine combinations.
template <class FT, int D>
void copy_candidates(const core::TemplatedStructure<FT, D>& x,
                     const std::vector<std::vector<core::Point<FT, D>>>& boundary_points,
                     std::vector<SvbCandidate>& out,
                     const std::vector<std::vector<AffinePointRange<FT, D>>>& ranges = {}) {
  if (x.instances.empty()) return;
  const std::size_t n = x.instances[0].size();
  std::vector<core::RigidTransformation<FT, D>> copies;
  const auto s0_inv = x.instances[0][0].transformation.inverse();
  for (const auto& inst : x.instances[0]) copies.push_back(inst.transformation * s0_inv);
  using I = CGAL::Interval_nt<false>;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    const auto& pts = boundary_points[i];
    if (pts.empty()) continue;
    const BoundaryPointLocator<FT, D> local(pts);
    const auto& t0 = x.instances[i][0].transformation;
    const auto t0_inv = t0.inverse();
    std::array<std::pair<double, double>, D> whole{};
    for (int d = 0; d < D; ++d) whole[std::size_t(d)] = local.box(0)[std::size_t(d)];
    for (std::size_t v = 1; v < pts.size(); ++v)
      for (int d = 0; d < D; ++d) {
        auto& w = whole[std::size_t(d)];
        w.first = std::min(w.first, local.box(v)[std::size_t(d)].first);
        w.second = std::max(w.second, local.box(v)[std::size_t(d)].second);
      }
    // pairs_of[g]: the pairs (v, w) with T_{i,0}^-1 S_g T_{i,0} (p_v) = p_w.
    std::vector<std::shared_ptr<const SvbPairs>> pairs_of(n);
    for (std::size_t g = 1; g < n; ++g) {
      const auto m = t0_inv * copies[g] * t0;
      // m's entries as intervals: the image box of each point costs a few interval operations,
      // and the exact image is built only for the points whose box meets a stored one.
      std::array<std::array<I, D + 1>, D> mi;
      for (int r = 0; r < D; ++r) {
        for (int c = 0; c < D; ++c)
          mi[std::size_t(r)][std::size_t(c)] = I(CGAL::to_interval(m.matrix()[r][c]));
        mi[std::size_t(r)][std::size_t(D)] = I(CGAL::to_interval(m.translation_part()[r]));
      }
      std::vector<typename BoundaryPointLocator<FT, D>::Box> image(pts.size());
      bool may_meet = true;
      {
        // Upward rounding for the unprotected intervals, only around these interval operations
        // (the exact comparisons below expect the default rounding).
        CGAL::Protect_FPU_rounding<true> upward;
        const auto image_of = [&](const auto& box, auto& into) {
          for (int r = 0; r < D; ++r) {
            I s = mi[std::size_t(r)][std::size_t(D)];
            for (int c = 0; c < D; ++c)
              s += mi[std::size_t(r)][std::size_t(c)] * I(box[std::size_t(c)]);
            into[std::size_t(r)] = {s.inf(), s.sup()};
          }
        };
        typename BoundaryPointLocator<FT, D>::Box hull;
        image_of(whole, hull);
        for (int d = 0; d < D; ++d)
          may_meet = may_meet && !(hull[std::size_t(d)].second < whole[std::size_t(d)].first ||
                                   whole[std::size_t(d)].second < hull[std::size_t(d)].first);
        if (may_meet)
          for (std::size_t v = 0; v < pts.size(); ++v) image_of(local.box(v), image[v]);
      }
      if (!may_meet) continue;
      // A reflection fixes exactly its mirror plane, one linear equation (a nonzero row of
      // m - I): a point whose image box meets its own box is tested on it — 3 exact products
      // instead of the image's 9 (the mirror faces' points, nearly all the pairs here).
      // (A reflection: orientation-reversing, an involution, trace D - 2 — not the point
      // inversion of 3D, trace -3, which fixes one point only.)
      std::optional<int> mirror_row;
      FT trace(0);
      for (int d = 0; d < D; ++d) trace += m.matrix()[d][d];
      if (CGAL::sign(m.determinant_of_linear_part()) < 0 && trace == FT(D - 2) &&
          (m * m).is_identity())
        for (int r = 0; r < D && !mirror_row; ++r)
          for (int c = 0; c < D && !mirror_row; ++c)
            if (m.matrix()[r][c] != FT(r == c ? 1 : 0)) mirror_row = r;
      const auto on_mirror = [&](const core::Point<FT, D>& p) {
        const int r = *mirror_row;
        FT e = m.translation_part()[r] - p[r];
        for (int c = 0; c < D; ++c) e += m.matrix()[r][c] * p[c];
        return CGAL::is_zero(e);
      };
      const auto meets_own = [&](std::size_t v) {
        for (int d = 0; d < D; ++d)
          if (image[v][std::size_t(d)].second < local.box(v)[std::size_t(d)].first ||
              local.box(v)[std::size_t(d)].second < image[v][std::size_t(d)].first)
            return false;
        return true;
      };
      std::vector<bool> fixed(pts.size(), false); // in a range whose spanning points m fixes
      if (mirror_row && i < ranges.size())
        for (const auto& range : ranges[i]) {
          bool all = true;
          for (const auto& q : range.spanning) all = all && on_mirror(q);
          if (all)
            for (std::size_t v = range.first; v < range.first + range.count; ++v) fixed[v] = true;
        }
      SvbPairs pairs;
      for (std::size_t v = 0; v < pts.size(); ++v) {
        // (p_v is not evaluated exactly here. An exact evaluation narrows a lazy interval, and
        // rounded() takes a narrow interval's midpoint, so the written doubles of such points may
        // differ by an ulp from those of the pointwise test this replaces; deterministic still.)
        if (fixed[v] || (mirror_row && meets_own(v) && on_mirror(pts[v]))) {
          pairs.emplace_back(mesh::IndexType(v), mesh::IndexType(v));
          continue;
        }
        if (const auto w = local.find(image[v], [&] { return m(pts[v]); }))
          pairs.emplace_back(mesh::IndexType(v), mesh::IndexType(*w));
      }
      if (!pairs.empty()) pairs_of[g] = std::make_shared<const SvbPairs>(std::move(pairs));
    }
    std::vector<std::tuple<std::size_t, std::size_t, std::size_t>> found; // (k, l, g)
    for (std::size_t g = 1; g < n; ++g) {
      if (!pairs_of[g]) continue;
      for (std::size_t l = 0; l < n; ++l) {
        const auto k = copy_index(copies, copies[l] * copies[g], true);
        if (!k) throw std::logic_error("SVB: the copies are not closed under composition");
        if (*k < l) found.emplace_back(*k, l, g);
      }
    }
    std::sort(found.begin(), found.end());
    for (const auto& [k, l, g] : found) out.push_back({{i, k}, {i, l}, pairs_of[g]});
  }
}

} // namespace symmesh::gen::support
