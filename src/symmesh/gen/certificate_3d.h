// Algorithm 5.7, certificate stage (internal to templated_tetrahedral_mesh.cpp): the SVB pairs
// of every template boundary mapping and the Lemma 4.2 certificate of the surface meshes, mapping
// by mapping (or copy by copy for the symmetric methods), with the place of a failure named —
// spec/generation.md#alg-5-7, spec/lemmas.md#lemma-4-2-surface-meshes
#pragma once
#include "symmesh/gen/surface_meshes_3d.h"

#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/slice_of_copies.h"
#include "symmesh/gen/rotation_order.h"
#include "symmesh/mesh/union_find.h"

#include <sstream>

namespace symmesh::gen::surface3 {

/// The (from, to) vertex pairs of one template boundary mapping, from its face-to-face action:
/// vertices by the automaton, line-mesh points in or against the edge's direction, surface-mesh
/// points index for index (the surface meshes were carried so, see surface_meshes).
template <class FT>
SvbPairs mapping_pairs_3(const core::BoundaryPatchPartition<FT, 3>& bpp, std::size_t letter,
                         const std::vector<SurfaceBoundary<FT>>& boundaries) {
  const auto& m = bpp.mappings[letter];
  const std::size_t j = m.from_template(), i = m.to_template();
  SvbPairs pairs;
  support::vertex_and_line_pairs<FT, 3>(bpp, letter, boundaries[j].lines, boundaries[i].lines,
                                        pairs);
  for (auto [f, g] : bpp.letter_action[letter]) {
    if (bpp.subdivisions[j].faces[f].dimension != 2) continue;
    const std::size_t n = boundaries[j].facet_count[f];
    if (n != boundaries[i].facet_count[g])
      throw std::logic_error("Algorithm 5.7: a mapping joins faces of different surface meshes");
    if (!boundaries[i].facet_symmetric[g]) {
      for (std::size_t k = 0; k < n; ++k)
        pairs.emplace_back(mesh::IndexType(boundaries[j].facet_first[f] + k),
                           mesh::IndexType(boundaries[i].facet_first[g] + k));
      continue;
    }
    // A symmetric face class: the mapping may differ from the carrying composition by a
    // symmetry of the face, which permutes the interior points; pair them by their exact
    // images (a point without one stays unpaired, and the certificate then fails).
    std::map<P3<FT>, std::size_t, core::PointLess<FT, 3>> at;
    for (std::size_t k = 0; k < n; ++k)
      at.emplace(boundaries[i].exact[boundaries[i].facet_first[g] + k],
                 boundaries[i].facet_first[g] + k);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t a = boundaries[j].facet_first[f] + k;
      if (const auto it = at.find(m.map(boundaries[j].exact[a])); it != at.end())
        pairs.emplace_back(mesh::IndexType(a), mesh::IndexType(it->second));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

/// Where surface triangle k of template t lies, for an error message: its boundary patch (the
/// ids of `symmesh bpp` in the whole structure's partition; the symmetric methods partition only
/// some copies), its subdivision face and a point of it.
template <class FT>
std::string boundary_place(const core::BoundaryPatchPartition<FT, 3>& bpp,
                           const SurfaceBoundary<FT>& tb, std::size_t t, std::size_t k) {
  if (k >= tb.triangles.size()) return "";
  const std::size_t f = tb.triangle_face[k];
  std::string patch = "?";
  for (std::size_t p = 0; p < bpp.patches.size(); ++p)
    if (bpp.patches[p].template_index == t &&
        std::binary_search(bpp.patches[p].faces.begin(), bpp.patches[p].faces.end(), f))
      patch = std::to_string(p); // the "id" of symmesh bpp
  std::ostringstream at;
  at.precision(6);
  at << ", boundary patch " << patch << ", subdivision face " << f << ", near (";
  for (int d = 0; d < 3; ++d) {
    double c = 0;
    for (std::size_t v : tb.triangles[k]) c += rounded(tb.exact[v][d]) / 3;
    at << (d ? ", " : "") << c;
  }
  return at.str() + ")";
}

/// Lemma 4.2, exactly, on the templates' boundary complexes (spec/lemmas.md#lemma-4-2-boundary):
/// the instances' interiors are disjoint (checked before meshing) and TetGen kept every template
/// boundary as its surface mesh (checked by the adapter), so AT is conforming iff the structure
/// of the exact surface meshes is (the general checker, condition (i) over all instance pairs).
template <class FT>
core::Lemma42Verdict certify_3(const core::TemplatedStructure<FT, 3>& x,
                               const std::vector<SurfaceBoundary<FT>>& boundaries) {
  core::TemplatedStructure<FT, 3> b;
  b.instances = x.instances;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    core::Template<FT, 3> t{x.templates[i].name, core::TemplateKind::mesh, {}};
    t.mesh.points = boundaries[i].exact;
    for (const auto& c : boundaries[i].triangles)
      for (const auto& e : core::faces(
               core::Simplex{core::VertexId(c[0]), core::VertexId(c[1]), core::VertexId(c[2])}))
        t.mesh.elements.push_back(e);
    t.mesh.normalize();
    b.templates.push_back(std::move(t));
  }
  return core::check_interface_conformity(b, core::apply_template(b));
}

/// The boundary points of mapping `letter`'s domain whose images follow from other checks, with
/// the image each must be paired with (npos: check the point itself).
/// - Interior points of a non-symmetric face f stored in face coordinates (exact = P_f(s, t) =
///   p0 + s·u + t·v) whose image face g is too: the map is affine, so it sends P_f(s, t) to
///   P_{map(f)}(s, t); when it sends p0, p0 + u, p0 + v of f's frame onto those of g's (three
///   exact point comparisons, done here) and the (s, t) lists agree, point k of f goes to point
///   k of g. This relies on exact = FacePlane::at(s, t) (SurfaceBoundary::facet_plane).
/// - Line-mesh points of an edge face whose ends the SVB pairs with the ends of the image edge
///   (exact = a + (b − a)·k/n): point k goes to point k of the image line, or n − k when the
///   ends are swapped, once the end pairs themselves are checked (they are, point by point).
/// A frame or (s, t) mismatch is written to v.
template <class FT>
std::vector<std::size_t> implied_images(const core::BoundaryPatchPartition<FT, 3>& bpp,
                                        std::size_t letter,
                                        const std::vector<SurfaceBoundary<FT>>& boundaries,
                                        const SvbPairs& pairs, core::Lemma42Verdict& v) {
  constexpr std::size_t none = std::size_t(-1);
  const auto& m = bpp.mappings[letter];
  const auto& sd = bpp.subdivisions[m.from_template()];
  const auto& from = boundaries[m.from_template()];
  const auto& to = boundaries[m.to_template()];
  std::vector<std::size_t> expected(from.exact.size(), none);
  std::vector<std::size_t> vertex_image(sd.points.size(), none);
  for (auto [a, b] : pairs)
    if (std::size_t(a) < vertex_image.size()) vertex_image[std::size_t(a)] = std::size_t(b);
  for (auto [f, g] : bpp.letter_action[letter]) {
    const int dim = sd.faces[f].dimension;
    if (dim == 1) {
      const auto& lf = from.lines[f];
      const auto& lg = to.lines[g];
      if (lf.n != lg.n) continue;
      const bool forward = vertex_image[lf.a] == lg.a && vertex_image[lf.b] == lg.b;
      const bool backward = vertex_image[lf.a] == lg.b && vertex_image[lf.b] == lg.a;
      if (forward == backward) continue; // unpaired ends (or a degenerate edge): point by point
      for (std::size_t k = 1; k < lf.n; ++k)
        expected[lf.first + k - 1] = lg.first + (forward ? k - 1 : lf.n - k - 1);
      continue;
    }
    if (dim != 2 || from.facet_symmetric[f] || to.facet_symmetric[g] || !from.facet_plane[f] ||
        !to.facet_plane[g])
      continue;
    // The frame's three points mapped by m itself (not by image_plane, which carried the copies):
    // m sends p0, p0 + u, p0 + v onto the target's, hence p0 + s·u + t·v onto its point (s, t).
    const auto& source = *from.facet_plane[f];
    const auto& target = *to.facet_plane[g];
    const bool same_frame = m.map(source.p0) == target.p0 &&
                            m.map(source.p0 + source.u) == target.p0 + target.u &&
                            m.map(source.p0 + source.v) == target.p0 + target.v;
    const bool same_st = from.facet_st[f] == to.facet_st[g] || *from.facet_st[f] == *to.facet_st[g];
    if (!same_frame || !same_st) {
      v.holds = false;
      v.detail = "the mapping " + m.name() + " does not send the surface-mesh points of face " +
                 std::to_string(f) + " onto those of face " + std::to_string(g) +
                 (same_st ? " (their frames differ)" : " (their face coordinates differ)");
      return expected;
    }
    for (std::size_t k = 0; k < from.facet_count[f]; ++k)
      expected[from.facet_first[f] + k] = to.facet_first[g] + k;
  }
  return expected;
}

/// Lemma 4.2 mapping by mapping (spec/lemmas.md#lemma-4-2-surface-meshes): every non-trivial
/// template boundary mapping sends the boundary mesh of each face of its domain onto the boundary
/// mesh of the image face, exactly — each vertex, line-mesh point and surface-mesh point onto the
/// point the SVB identifies it with (exact arithmetic), and each surface triangle onto a surface
/// triangle (vertex ids). The domain of 𝕋_{a,b} is T_b^-1 of the geometric interface (Def 4.7),
/// the instances' interiors are disjoint (Eq. 4.2, checked before meshing) and TetGen kept each
/// template boundary as its surface mesh (checked by the adapter), so this is T_a(IP_{a,b}) =
/// T_b(IP_{b,a}) for every neighbouring pair, and no element of one instance meets a different
/// element of the other in its relative interior: AT is conforming. The cost is the boundary
/// size times the mappings, never instance pairs times their elements.
template <class FT>
core::Lemma42Verdict certify_by_mappings(const core::BoundaryPatchPartition<FT, 3>& bpp,
                                         const std::vector<SurfaceBoundary<FT>>& boundaries) {
  core::Lemma42Verdict v;
  std::vector<std::map<std::size_t, std::vector<std::array<std::size_t, 3>>>> face_triangles(
      boundaries.size());
  for (std::size_t t = 0; t < boundaries.size(); ++t)
    for (std::size_t k = 0; k < boundaries[t].triangles.size(); ++k) {
      auto c = boundaries[t].triangles[k];
      std::sort(c.begin(), c.end());
      face_triangles[t][boundaries[t].triangle_face[k]].push_back(c);
    }
  for (auto& per_template : face_triangles)
    for (auto& [f, list] : per_template) std::sort(list.begin(), list.end());
  for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
    const auto& m = bpp.mappings[l];
    if (m.whole_boundary) continue;
    ++v.pairs_checked;
    const std::size_t j = m.from_template(), i = m.to_template();
    const auto pairs = mapping_pairs_3(bpp, l, boundaries);
    const auto implied = implied_images(bpp, l, boundaries, pairs, v);
    std::map<std::size_t, std::size_t> image;
    for (auto [a, b] : pairs) {
      image.emplace(std::size_t(a), std::size_t(b));
      if (!v.holds) break;
      if (const std::size_t e = implied[std::size_t(a)]; e != std::size_t(-1)) {
        if (e == std::size_t(b)) continue;
        v.holds = false;
        v.detail = "the SVB pairs boundary point " + std::to_string(a) + " with " +
                   std::to_string(b) + " across the mapping " + m.name() +
                   ", but its line or face coordinates make its image " + std::to_string(e);
        break;
      }
      if (m.map(boundaries[j].exact[std::size_t(a)]) != boundaries[i].exact[std::size_t(b)]) {
        v.holds = false;
        v.detail = "the mapping " + m.name() + " does not send boundary vertex " +
                   std::to_string(a) + " onto the vertex " + std::to_string(b) +
                   " it is identified with";
        break;
      }
    }
    for (auto [f, g] : bpp.letter_action[l]) {
      if (!v.holds || bpp.subdivisions[j].faces[f].dimension != 2) continue;
      std::vector<std::array<std::size_t, 3>> mapped;
      for (const auto& c : face_triangles[j][f]) {
        std::array<std::size_t, 3> d{};
        for (int k = 0; k < 3; ++k) {
          const auto it = image.find(c[std::size_t(k)]);
          d[std::size_t(k)] = it == image.end() ? std::size_t(-1) : it->second;
        }
        std::sort(d.begin(), d.end());
        mapped.push_back(d);
      }
      std::sort(mapped.begin(), mapped.end());
      if (mapped != face_triangles[i][g]) {
        v.holds = false;
        v.detail = "the mapping " + m.name() + " does not send the surface mesh of face " +
                   std::to_string(f) + " onto that of face " + std::to_string(g);
      }
    }
    if (!v.holds) {
      v.a = m.to;
      v.b = m.from;
      v.condition = 2;
      return v;
    }
  }
  return v;
}

/// Lemma 4.2 for the reflective methods (spec/generation.md#reflective-3d), exactly: copy 0's
/// interfaces by its mappings (certify_by_mappings on copy 0's BPP), and every interface of a
/// copy-0 instance with a copy-m instance (m != 0) shown to be fixed pointwise by S_m (each vertex
/// of each domain piece, exactly). Then such an interface also lies in the copy-0 instances of
/// both templates (x = S_m^-1 x), so both sides carry the same surface mesh there (the relative
/// map is the identity on it); every other pair (k, l) is S_k of the pair (0, S_k^-1 S_l). When a
/// piece is not fixed (copy 0 is not a strict fundamental domain), the general checker decides.
template <class FT>
core::Lemma42Verdict certify_copies(const core::TemplatedStructure<FT, 3>& x,
                                    const std::vector<core::RigidTransformation<FT, 3>>& copies,
                                    const core::BoundaryPatchPartition<FT, 3>& bpp,
                                    const std::vector<SurfaceBoundary<FT>>& boundaries) {
  auto v = certify_by_mappings(bpp, boundaries);
  if (!v.holds) return v;
  // The interfaces of copy 0 are those with the copies near it (the group moves the rest there).
  const auto near = support::copies_near_copy_zero(x);
  const auto& y = near.structure;
  // Only pairs with one side in copy 0 are asked for: the others' interfaces are never read.
  const auto one_in_copy_zero = [](core::InstanceId a, core::InstanceId b) {
    return (a.g == 0) != (b.g == 0);
  };
  for (const auto& m : core::template_boundary_mappings(y, false, {}, one_in_copy_zero)) {
    if (m.whole_boundary || m.from.g != 0 || m.to.g == 0) continue;
    ++v.pairs_checked;
    const auto& from = y.tf(m.from);
    for (const auto& piece : m.domain)
      for (const auto& p : piece.vertices) {
        const auto w = from(p);
        if (copies[near.near[m.to.g]](w) != w) return certify_3(x, boundaries);
      }
  }
  return v;
}

/// Section 6.3 in 3D: the BPP of the first two rotated copies shows every interface of
/// consecutive copies (k, k+1) (rotations of (0, 1)); the method also needs that no two
/// non-consecutive copies touch (e.g. slices meeting only on the axis), because their interfaces
/// would be neither partitioned nor certified. Up to the rotation it suffices to decide the
/// pairs (copy 0, copy j), 2 <= j <= n/2, exactly (geometry_interface_nonempty on the carriers).
/// Returns the first touching pair as text, or nothing. When copy 0 lies in a slice of angle
/// 2π/n off the axis (`copy_zero_in_slice`: core::slice_of_copy_zero(x, n) holds, decided once
/// by the caller), no pair needs deciding (spec/lemmas.md#slice-separation).
template <class FT>
std::optional<std::string> non_consecutive_contact(const core::TemplatedStructure<FT, 3>& x,
                                                   std::size_t n, bool copy_zero_in_slice) {
  if (n < 4 || copy_zero_in_slice) return std::nullopt;
  // Only the copies 2 .. n/2 whose carrier boxes meet copy 0's are decided exactly.
  const auto near = support::copies_near_copy_zero(x, 2, n / 2 + 1);
  const auto& y = near.structure;
  const std::vector<std::size_t> copies(near.near.begin() + 1, near.near.end());
  if (copies.empty()) return std::nullopt;
  const auto si = core::apply_template(y);
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    for (std::size_t i2 = 0; i2 < x.templates.size(); ++i2)
      for (std::size_t k = 0; k < copies.size(); ++k)
        if (core::geometry_interface_nonempty(si, si.index_of({i, 0}), si.index_of({i2, k + 1})))
          return "T_{" + std::to_string(i + 1) + ",1} and T_{" + std::to_string(i2 + 1) + "," +
                 std::to_string(copies[k] + 1) + "} touch but are not consecutive rotated copies";
  return std::nullopt;
}

/// As above, deciding core::slice_of_copy_zero(x, n) itself.
template <class FT>
std::optional<std::string> non_consecutive_contact(const core::TemplatedStructure<FT, 3>& x,
                                                   std::size_t n) {
  return non_consecutive_contact(x, n, n >= 4 && core::slice_of_copy_zero(x, n).has_value());
}

} // namespace symmesh::gen::surface3
