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

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
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
    std::map<core::Point<FT, D>, std::size_t, core::PointLess<FT, D>> local;
    for (std::size_t v = 0; v < pts.size(); ++v) local.emplace(pts[v], v);
    const auto& list = x.instances[i];
    for (std::size_t k = 0; k < list.size(); ++k)
      for (std::size_t l = k + 1; l < list.size(); ++l) {
        const auto m = list[l].transformation.inverse() * list[k].transformation;
        SvbPairs pairs;
        for (std::size_t v = 0; v < pts.size(); ++v)
          if (const auto it = local.find(m(pts[v])); it != local.end())
            pairs.emplace_back(mesh::IndexType(v), mesh::IndexType(it->second));
        if (!pairs.empty())
          out.push_back({{i, k}, {i, l}, std::make_shared<const SvbPairs>(std::move(pairs))});
      }
  }
}

} // namespace symmesh::gen::support
