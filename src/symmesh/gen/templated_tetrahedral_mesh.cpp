// Algorithm 5.7 (spec/generation.md#alg-5-7). Instantiated for the rationals (Epeck's FT) and for
// K_m through Lazy_exact_nt<Cyclotomic>, like the 2D path. The stages it shares with
// Algorithm 5.6 (the BPP, uniform line meshes, the SVB, the conventional input, rounding) come
// from the same headers; only the surface meshes and the mesher are 3D.
#include "symmesh/gen/templated_tetrahedral_mesh.h"

#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/interface_conformity.h"
#include "symmesh/gen/generation_support.h"
#include "symmesh/gen/gmsh_mesher.h"
#include "symmesh/gen/pipeline_stages.h"
#include "symmesh/gen/rotation_order.h"
#include "symmesh/gen/shared_vertex_bookkeeping.h"
#include "symmesh/gen/symmetric_surface_mesh.h"
#include "symmesh/gen/symmetry_copies.h"
#include "symmesh/gen/tetrahedral_mesher.h"
#include "symmesh/gen/triangle_mesher.h"
#include "symmesh/mesh/union_find.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace symmesh::gen {
namespace {
using support::Clock;
using support::exact_from_double;
using support::FaceLine;
using support::LazyCyclotomic;
using support::minor_faults;
using support::rounded;
using support::seconds_since;
using support::SvbPairs;
using support::Symmetry;

template <class FT>
using P3 = core::Point<FT, 3>;

using symmetric::cross; // the exact cross product (gen/symmetric_surface_mesh.h)

/// The k-th of the n + 1 points of the uniform line mesh of [a, b], exactly: the value of
/// core::line_mesh_point, written as one product so that its interval enclosure, which rounded()
/// reads, is the one the 3D outputs were made with (another expression of the same value may
/// round to a neighbouring double and change the mesh).
template <class FT>
P3<FT> line_point(const P3<FT>& a, const P3<FT>& b, std::size_t k, std::size_t n) {
  if (k == 0) return a;
  if (k == n) return b;
  return a + core::scaled<FT, 3>(b - a, FT(int(k)) / FT(int(n)));
}

/// Tetrahedra TetGen makes per volume bound (-a) of volume, at the default radius-edge bound:
/// measured on the rotational slices of data/rotational_slice_3d.json
/// (spec/generation.md#cell-estimate).
constexpr double kTetrahedraPerVolumeBound = 2.0;

/// Template t's boundary mesh: every boundary point exactly in local ids (subdivision points,
/// then the interior points of each line mesh, then those of each surface mesh), the line mesh
/// of every edge face and the triangles of the surface meshes of the 2-faces. TetGen gets the
/// points rounded once from their exact values; conformity never depends on the rounding, the
/// SVB identifies points by index.
template <class FT>
struct SurfaceBoundary {
  std::vector<P3<FT>> exact;
  std::vector<FaceLine> lines;                       ///< per subdivision face (n = 0: not an edge)
  std::vector<std::size_t> facet_first, facet_count; ///< per subdivision face: interior points
  /// per subdivision face: meshed symmetrically, so a mapping may permute its interior points
  std::vector<bool> facet_symmetric;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::size_t> triangle_face;                      ///< the 2-face each triangle lies in
  std::map<P3<FT>, std::size_t, core::PointLess<FT, 3>> id_of; ///< vertices and line points
};

template <class FT>
SurfaceBoundary<FT> line_meshes_3(const core::BoundarySubdivision<FT, 3>& sd, const FT& h2,
                                  double h, const std::set<FT>& even_lengths) {
  SurfaceBoundary<FT> tb;
  tb.exact = sd.points;
  for (std::size_t v = 0; v < tb.exact.size(); ++v) tb.id_of.emplace(tb.exact[v], v);
  tb.lines.resize(sd.faces.size());
  tb.facet_first.assign(sd.faces.size(), 0);
  tb.facet_count.assign(sd.faces.size(), 0);
  tb.facet_symmetric.assign(sd.faces.size(), false);
  for (std::size_t f = 0; f < sd.faces.size(); ++f) {
    const auto& face = sd.faces[f];
    if (face.dimension != 1) continue;
    FaceLine& line = tb.lines[f];
    line.a = face.vertices[0];
    line.b = face.vertices[1];
    line.n = support::parts_for<FT, 3>(sd.points[line.a], sd.points[line.b], h2, h);
    if (line.n % 2 == 1 && !even_lengths.empty() &&
        even_lengths.count(core::dot<FT, 3>(sd.points[line.b] - sd.points[line.a],
                                            sd.points[line.b] - sd.points[line.a])))
      ++line.n;
    line.first = tb.exact.size();
    for (std::size_t k = 1; k < line.n; ++k) {
      tb.exact.push_back(line_point<FT>(sd.points[line.a], sd.points[line.b], k, line.n));
      tb.id_of.emplace(tb.exact.back(), tb.exact.size() - 1);
    }
  }
  return tb;
}

/// The local ids of the line-mesh points of edge face e, from a to b.
std::vector<std::size_t> line_ids(const FaceLine& line) {
  std::vector<std::size_t> out{line.a};
  for (std::size_t k = 1; k < line.n; ++k) out.push_back(line.first + k - 1);
  out.push_back(line.b);
  return out;
}

/// The triangulation of one 2-face in its own plane, conforming to the line meshes of its
/// closure: boundary points as local ids of the face's template, interior points exactly (they
/// lie in the face's plane exactly: p0 + s·u + t·v with rational s, t), triangles over
/// (boundary ids, then interior points).
template <class FT>
struct FacetMesh {
  std::vector<std::size_t> boundary_ids;
  std::vector<P3<FT>> interior;
  std::vector<std::array<std::size_t, 3>> triangles; ///< < boundary_ids.size(): boundary
};

/// An exact orthogonal frame of a face's plane, from its vertices (not its pieces, whose
/// triangulation need not be canonical): p0 its first vertex, u towards its second, v = n × u in
/// the plane with n from the first vertex off the line. The mesher works in (x·u/|u|, x·v/|v|),
/// whose orientation is that of n.
template <class FT>
struct FacetFrame {
  P3<FT> p0, u, v, n;
  double lu = 0, lv = 0;

  std::array<double, 2> to_plane(const P3<FT>& x) const {
    const P3<FT> d = x - p0;
    return {rounded(core::dot<FT, 3>(d, u)) / lu, rounded(core::dot<FT, 3>(d, v)) / lv};
  }
  P3<FT> from_plane(const std::array<double, 2>& q) const {
    const FT s = exact_from_double<FT>(q[0] / lu);
    const FT t = exact_from_double<FT>(q[1] / lv);
    return p0 + core::scaled<FT, 3>(u, s) + core::scaled<FT, 3>(v, t);
  }
};

template <class FT>
FacetFrame<FT> facet_frame(const core::BoundarySubdivision<FT, 3>& sd, std::size_t f) {
  const auto& vs = sd.faces[f].vertices;
  FacetFrame<FT> fr;
  fr.p0 = sd.points[vs.at(0)];
  fr.u = sd.points[vs.at(1)] - fr.p0;
  fr.n = cross<FT>(fr.u, sd.points[vs.at(2)] - fr.p0);
  for (std::size_t k = 3; k < vs.size() && fr.n == core::zero_point<FT, 3>(); ++k)
    fr.n = cross<FT>(fr.u, sd.points[vs[k]] - fr.p0);
  fr.v = cross<FT>(fr.n, fr.u);
  fr.lu = std::sqrt(rounded(core::dot<FT, 3>(fr.u, fr.u)));
  fr.lv = std::sqrt(rounded(core::dot<FT, 3>(fr.v, fr.v)));
  return fr;
}

/// The boundary of face f for the 2D mesher: its vertices and line-mesh points (local ids of the
/// template, in first-seen order) and the line-mesh segments over them.
template <class FT>
std::vector<std::array<std::size_t, 2>> facet_boundary(const core::BoundarySubdivision<FT, 3>& sd,
                                                       const SurfaceBoundary<FT>& tb, std::size_t f,
                                                       std::vector<std::size_t>& boundary_ids) {
  std::vector<std::array<std::size_t, 2>> segments;
  std::map<std::size_t, std::size_t> local; // template boundary id -> input point
  const auto point = [&](std::size_t id) {
    auto [it, fresh] = local.emplace(id, boundary_ids.size());
    if (fresh) boundary_ids.push_back(id);
    return it->second;
  };
  for (std::size_t c : sd.faces[f].closure) {
    const auto& cf = sd.faces[c];
    if (cf.dimension == 0) point(cf.vertices[0]);
    if (cf.dimension != 1) continue;
    const auto ids = line_ids(tb.lines[c]);
    for (std::size_t k = 0; k + 1 < ids.size(); ++k)
      segments.push_back({point(ids[k]), point(ids[k + 1])});
  }
  return segments;
}

template <class FT>
FacetMesh<FT> mesh_facet(const core::BoundarySubdivision<FT, 3>& sd, const SurfaceBoundary<FT>& tb,
                         std::size_t f, double size, double min_angle_deg) {
  FacetMesh<FT> out;
  BoundaryInput in;
  in.segments = facet_boundary(sd, tb, f, out.boundary_ids);
  const auto frame = facet_frame(sd, f);
  for (std::size_t id : out.boundary_ids) in.points.push_back(frame.to_plane(tb.exact[id]));
  MeshingParameters p;
  p.size = size;
  p.min_angle_deg = min_angle_deg;
  const auto m = mesh_domain_2(in, p);
  for (std::size_t k = in.points.size(); k < m.points.size(); ++k)
    out.interior.push_back(frame.from_plane(m.points[k]));
  out.triangles = m.triangles;
  return out;
}

/// A class of 2-faces under the face-to-face action of the mappings (spec/generation.md#
/// surface-meshes): its first face, its members with the composition of mappings from the first
/// face to each along a BFS tree, and the differences between other chains and the tree's
/// (maps of the first face onto itself that do not fix it: the generators of its group).
template <class FT>
struct FaceClass {
  core::FaceRef first;
  std::vector<core::FaceRef> members;
  std::map<core::FaceRef, core::RigidTransformation<FT, 3>> comp;
  std::vector<core::RigidTransformation<FT, 3>> generators;
};

template <class FT>
std::vector<FaceClass<FT>> face_classes(const core::BoundaryPatchPartition<FT, 3>& bpp) {
  using Map = core::RigidTransformation<FT, 3>;
  const auto& sds = bpp.subdivisions;
  std::vector<std::vector<std::vector<std::pair<std::size_t, core::FaceRef>>>> arrows(sds.size());
  for (std::size_t t = 0; t < sds.size(); ++t) arrows[t].resize(sds[t].faces.size());
  for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
    const auto& m = bpp.mappings[l];
    if (m.whole_boundary) continue;
    for (auto [f, g] : bpp.letter_action[l])
      if (sds[m.from_template()].faces[f].dimension == 2)
        arrows[m.from_template()][f].push_back({l, core::FaceRef{m.to_template(), g}});
  }
  std::vector<FaceClass<FT>> classes;
  std::vector<std::vector<bool>> done(sds.size());
  for (std::size_t t = 0; t < sds.size(); ++t) done[t].assign(sds[t].faces.size(), false);
  for (std::size_t t = 0; t < sds.size(); ++t)
    for (std::size_t f = 0; f < sds[t].faces.size(); ++f) {
      if (sds[t].faces[f].dimension != 2 || done[t][f]) continue;
      FaceClass<FT> c;
      c.first = {t, f};
      c.members.push_back(c.first);
      c.comp.emplace(c.first, Map());
      done[t][f] = true;
      for (std::size_t k = 0; k < c.members.size(); ++k) {
        const auto cur = c.members[k];
        for (const auto& [l, next] : arrows[cur.t][cur.f]) {
          if (c.comp.count(next)) continue;
          c.comp.emplace(next, bpp.mappings[l].map * c.comp.at(cur));
          done[next.t][next.f] = true;
          c.members.push_back(next);
        }
      }
      const auto& vs = sds[t].faces[f].vertices;
      for (const auto& cur : c.members)
        for (const auto& [l, next] : arrows[cur.t][cur.f]) {
          const Map d = c.comp.at(next).inverse() * bpp.mappings[l].map * c.comp.at(cur);
          bool fixes = true;
          for (std::size_t k = 0; k < vs.size() && fixes; ++k)
            fixes = d(sds[t].points[vs[k]]) == sds[t].points[vs[k]];
          if (!fixes) c.generators.push_back(d);
        }
      classes.push_back(std::move(c));
    }
  return classes;
}

/// The group of every class's first face (trivial when the class has no generators).
template <class FT>
std::vector<symmetric::FaceGroup<FT>> face_groups(const core::BoundaryPatchPartition<FT, 3>& bpp,
                                                  const std::vector<FaceClass<FT>>& classes) {
  std::vector<symmetric::FaceGroup<FT>> groups;
  for (const auto& c : classes) {
    if (c.generators.empty()) {
      groups.push_back({{core::RigidTransformation<FT, 3>()}, {false}});
      continue;
    }
    const auto& sd = bpp.subdivisions[c.first.t];
    std::vector<P3<FT>> vertices;
    for (auto v : sd.faces[c.first.f].vertices) vertices.push_back(sd.points[v]);
    groups.push_back(symmetric::face_group<FT>(vertices, c.generators));
  }
  return groups;
}

/// Squared lengths of the edges that a reflection of a face group reverses: their line meshes get
/// an even number of parts, so that the mirror meets the boundary in a line-mesh point (the
/// edge's midpoint). Equal lengths are equal exactly, so the edges' whole classes agree.
template <class FT>
std::set<FT> mirrored_edge_lengths(const core::BoundaryPatchPartition<FT, 3>& bpp,
                                   const std::vector<FaceClass<FT>>& classes,
                                   const std::vector<symmetric::FaceGroup<FT>>& groups) {
  std::set<FT> lengths;
  for (std::size_t k = 0; k < classes.size(); ++k) {
    if (!groups[k].has_reflections()) continue;
    const auto& sd = bpp.subdivisions[classes[k].first.t];
    for (std::size_t c : sd.faces[classes[k].first.f].closure) {
      if (sd.faces[c].dimension != 1) continue;
      const P3<FT>& a = sd.points[sd.faces[c].vertices[0]];
      const P3<FT>& b = sd.points[sd.faces[c].vertices[1]];
      for (std::size_t e = 0; e < groups[k].order(); ++e)
        if (groups[k].reflection[e] && groups[k].elements[e](a) == b)
          lengths.insert(core::dot<FT, 3>(b - a, b - a));
    }
  }
  return lengths;
}

/// The symmetric mesh of a class's first face (spec/generation.md#symmetric-surface-meshes).
template <class FT>
FacetMesh<FT> mesh_symmetric_facet(const core::TemplatedStructure<FT, 3>& x,
                                   const core::BoundarySubdivision<FT, 3>& sd,
                                   const SurfaceBoundary<FT>& tb, core::FaceRef face,
                                   const symmetric::FaceGroup<FT>& group, const FT& h2, double size,
                                   double min_angle_deg) {
  FacetMesh<FT> out;
  const auto segments = facet_boundary(sd, tb, face.f, out.boundary_ids);
  std::vector<P3<FT>> boundary;
  for (std::size_t id : out.boundary_ids) boundary.push_back(tb.exact[id]);
  const auto frame = facet_frame(sd, face.f);
  MeshingParameters p;
  p.size = size;
  p.min_angle_deg = min_angle_deg;
  const std::string where = "template '" + x.templates[face.t].name + "', boundary face " +
                            std::to_string(face.f) + " (symmetric under " +
                            std::to_string(group.order()) + " mappings)";
  auto m = symmetric::symmetric_facet_mesh<FT>(
      group, frame.n, boundary, segments, [&](const P3<FT>& q) { return frame.to_plane(q); },
      [&](const std::array<double, 2>& q) { return frame.from_plane(q); },
      [&](const P3<FT>& a, const P3<FT>& b) { return support::parts_for<FT, 3>(a, b, h2, size); },
      p, where);
  out.interior = std::move(m.interior);
  out.triangles = std::move(m.triangles);
  return out;
}

/// Surface meshes of all 2-faces (spec/generation.md#surface-meshes): each class is meshed once
/// at its first face — symmetrically under the face's group when other chains of mappings reach
/// a member than the BFS tree's (spec/generation.md#symmetric-surface-meshes) — and carried to
/// the other members by the tree's compositions.
template <class FT>
void surface_meshes(const core::TemplatedStructure<FT, 3>& x,
                    const core::BoundaryPatchPartition<FT, 3>& bpp,
                    const std::vector<FaceClass<FT>>& classes,
                    const std::vector<symmetric::FaceGroup<FT>>& groups,
                    std::vector<SurfaceBoundary<FT>>& boundaries, const FT& h2, double size,
                    double min_angle_deg) {
  const auto& sds = bpp.subdivisions;
  for (std::size_t k = 0; k < classes.size(); ++k) {
    const auto [t, f] = classes[k].first;
    const auto rep = groups[k].is_trivial()
                         ? mesh_facet(sds[t], boundaries[t], f, size, min_angle_deg)
                         : mesh_symmetric_facet(x, sds[t], boundaries[t], classes[k].first,
                                                groups[k], h2, size, min_angle_deg);
    for (const auto& g : classes[k].members) {
      auto& tb = boundaries[g.t];
      const auto& map = classes[k].comp.at(g);
      std::vector<std::size_t> ids;
      for (std::size_t id : rep.boundary_ids) {
        const auto it = tb.id_of.find(map(boundaries[t].exact[id]));
        if (it == tb.id_of.end())
          throw std::logic_error("Algorithm 5.7: a mapped surface-mesh boundary point is not a "
                                 "line-mesh point of the image face");
        ids.push_back(it->second);
      }
      tb.facet_first[g.f] = tb.exact.size();
      tb.facet_count[g.f] = rep.interior.size();
      tb.facet_symmetric[g.f] = !groups[k].is_trivial();
      for (const auto& q : rep.interior) {
        ids.push_back(tb.exact.size());
        tb.exact.push_back(map(q));
      }
      for (const auto& c : rep.triangles) {
        tb.triangles.push_back({ids[c[0]], ids[c[1]], ids[c[2]]});
        tb.triangle_face.push_back(g.f);
      }
    }
  }
}

/// GenerationOptions::perturb_one_surface_mesh: the first interior surface-mesh vertex of the first
/// 2-face that some non-trivial mapping sends onto another face moves 1/16 of the way to a
/// neighbour (exactly, so it stays in the face's plane and the surface stays a valid
/// triangulation); its images on the related faces stay where they were.
template <class FT>
void perturb_one_surface_mesh(const core::BoundaryPatchPartition<FT, 3>& bpp,
                              std::vector<SurfaceBoundary<FT>>& boundaries) {
  for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
    const auto& m = bpp.mappings[l];
    if (m.whole_boundary) continue;
    auto& tb = boundaries[m.from_template()];
    for (auto [f, g] : bpp.letter_action[l]) {
      // A face the mapping sends onto itself (a mirror) carries the moved vertex along.
      if (tb.facet_count[f] == 0 || (m.from_template() == m.to_template() && f == g)) continue;
      const std::size_t p = tb.facet_first[f];
      for (const auto& c : tb.triangles) {
        const auto* at = std::find(c.begin(), c.end(), p);
        if (at == c.end()) continue;
        const std::size_t q = c[std::size_t(at - c.begin() + 1) % 3];
        tb.exact[p] = tb.exact[p] + core::scaled<FT, 3>(tb.exact[q] - tb.exact[p], FT(1) / FT(16));
        return;
      }
    }
  }
  throw std::invalid_argument(
      "perturb_one_surface_mesh: no face mapped onto another face has interior vertices");
}

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
    std::map<std::size_t, std::size_t> image;
    for (auto [a, b] : pairs) {
      image.emplace(std::size_t(a), std::size_t(b));
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
  for (const auto& m : core::template_boundary_mappings(x, false)) {
    if (m.whole_boundary || m.from.g != 0 || m.to.g == 0) continue;
    ++v.pairs_checked;
    const auto& from = x.tf(m.from);
    for (const auto& piece : m.domain)
      for (const auto& p : piece.vertices) {
        const auto w = from(p);
        if (copies[m.to.g](w) != w) return certify_3(x, boundaries);
      }
  }
  return v;
}

/// Section 6.3 in 3D: the BPP of the first two rotated copies shows every interface of
/// consecutive copies (k, k+1) (rotations of (0, 1)); the method also needs that no two
/// non-consecutive copies touch (e.g. slices meeting only on the axis), because their interfaces
/// would be neither partitioned nor certified. Up to the rotation it suffices to decide the
/// pairs (copy 0, copy j), 2 <= j <= n/2, exactly (geometry_interface_nonempty on the carriers).
/// Returns the first touching pair as text, or nothing.
template <class FT>
std::optional<std::string> non_consecutive_contact(const core::TemplatedStructure<FT, 3>& x,
                                                   std::size_t n) {
  if (n < 4) return std::nullopt;
  // Certified interval boxes of the carriers' cells of copy k of every template filter the
  // candidates; only copies whose boxes meet copy 0's are decided exactly.
  const auto cell_boxes = [&](std::size_t k) {
    std::vector<core::EnclosingBox<FT, 3>> out;
    for (std::size_t i = 0; i < x.templates.size(); ++i) {
      const auto& c = x.templates[i].mesh;
      std::vector<P3<FT>> pts;
      for (const auto& p : c.points) pts.push_back(x.instances[i][k].transformation(p));
      for (const auto& e : c.elements)
        if (e.dim() == 3) out.push_back(core::EnclosingBox<FT, 3>::of(pts, e));
    }
    return out;
  };
  const auto first = cell_boxes(0);
  core::TemplatedStructure<FT, 3> y;
  y.templates = x.templates;
  y.instances.resize(x.templates.size());
  for (std::size_t i = 0; i < x.templates.size(); ++i) y.instances[i].push_back(x.instances[i][0]);
  std::vector<std::size_t> copies;
  for (std::size_t j = 2; j <= n / 2; ++j) {
    bool meet = false;
    for (const auto& b : cell_boxes(j))
      for (const auto& a : first) meet = meet || a.overlaps(b);
    if (!meet) continue;
    copies.push_back(j);
    for (std::size_t i = 0; i < x.templates.size(); ++i)
      y.instances[i].push_back(x.instances[i][j]);
  }
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

template <class FT>
FT carrier_volume(const core::ElementComplex<FT, 3>& c) {
  FT six(0);
  for (const auto& e : c.elements) {
    if (e.dim() != 3) continue;
    const auto& a = c.points[e.v[0]];
    const P3<FT> u = c.points[e.v[1]] - a, v = c.points[e.v[2]] - a, w = c.points[e.v[3]] - a;
    const FT d = core::dot<FT, 3>(u, cross<FT>(v, w));
    six += CGAL::is_negative(d) ? -d : d;
  }
  return six / FT(6);
}

/// The boundaries of AT's regions as one surface (spec/generation.md#conventional-3d, #gmsh-3d):
/// the templates' surface meshes placed by the instances (each point rounded once from its exact
/// image) and identified through the SVB; a triangle between two instances of one region is left
/// out (a whole-geometry mesher does not see the slices), one between two regions kept once.
/// `sides` gives, per kept triangle, the region(s) it bounds. The seeds are a point strictly
/// inside each instance (for TetGen -A).
struct WholeSurface {
  SurfaceInput surface;
  struct Sides {
    int region = 0, other = 0;
    bool interface = false; ///< between `region` and `other`; else on the outer boundary
  };
  std::vector<Sides> sides;
};

template <class FT>
WholeSurface whole_surface(const core::TemplatedStructure<FT, 3>& x,
                           const std::vector<SurfaceBoundary<FT>>& boundaries,
                           const GenerationResult& r) {
  // Global surface vertices: union-find over (instance, boundary vertex) with the SVB.
  std::vector<std::size_t> first;
  std::vector<core::InstanceId> ids;
  std::size_t total = 0;
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    for (std::size_t g = 0; g < x.instances[i].size(); ++g) {
      first.push_back(total);
      ids.push_back({i, g});
      total += boundaries[i].exact.size();
    }
  mesh::UnionFind uf(total);
  for (const auto& id : r.templated.identifications)
    for (auto [a, b] : r.templated.tables[std::size_t(id.table)].pairs)
      uf.unite(first[std::size_t(id.from_instance)] + std::size_t(a),
               first[std::size_t(id.to_instance)] + std::size_t(b));
  // Surface triangles by their classes' roots; an interface triangle of two instances of one
  // region is no boundary of the whole geometry (the conventional mesher does not see the
  // slices), so only triangles met once, or by instances of two regions, are kept.
  struct Face {
    std::array<std::size_t, 3> roots;
    int region = 0, other = 0, count = 0;
    bool two_regions = false;
  };
  std::map<std::array<std::size_t, 3>, Face> faces;
  std::vector<std::array<std::size_t, 3>> order;
  for (std::size_t a = 0; a < ids.size(); ++a) {
    const int region = int(x.instances[ids[a].i][ids[a].g].region);
    for (const auto& c : boundaries[ids[a].i].triangles) {
      std::array<std::size_t, 3> g{};
      for (int k = 0; k < 3; ++k) g[std::size_t(k)] = uf.find(first[a] + c[std::size_t(k)]);
      auto key = g;
      std::sort(key.begin(), key.end());
      auto [it, fresh] = faces.emplace(key, Face{g, region, region, 0, false});
      if (fresh) order.push_back(key);
      ++it->second.count;
      if (it->second.region != region) {
        it->second.two_regions = true;
        it->second.other = region;
      }
    }
  }
  WholeSurface w;
  SurfaceInput& s = w.surface;
  std::map<std::size_t, std::size_t> global; // class root -> surface point
  std::map<std::size_t, std::size_t> owner;  // class root -> (instance, vertex) position
  for (std::size_t a = 0; a < ids.size(); ++a)
    for (std::size_t v = 0; v < boundaries[ids[a].i].exact.size(); ++v)
      owner.emplace(uf.find(first[a] + v), first[a] + v);
  const auto point_of = [&](std::size_t root) {
    auto [it, fresh] = global.emplace(root, s.points.size());
    if (fresh) {
      const std::size_t flat = owner.at(root);
      const std::size_t a =
          std::size_t(std::upper_bound(first.begin(), first.end(), flat) - first.begin()) - 1;
      const auto q = x.tf(ids[a])(boundaries[ids[a].i].exact[flat - first[a]]);
      s.points.push_back({rounded(q[0]), rounded(q[1]), rounded(q[2])});
    }
    return it->second;
  };
  for (const auto& key : order) {
    const auto& f = faces.at(key);
    if (f.count > 1 && !f.two_regions) continue;
    s.triangles.push_back({point_of(f.roots[0]), point_of(f.roots[1]), point_of(f.roots[2])});
    w.sides.push_back({f.region, f.other, f.two_regions});
  }
  for (std::size_t a = 0; a < ids.size(); ++a) {
    const auto& t = x.tf(ids[a]);
    // A seed strictly inside the instance: the centroid of its carrier's first cell.
    const auto& carrier = x.templates[ids[a].i].mesh;
    for (const auto& e : carrier.elements) {
      if (e.dim() != 3) continue;
      P3<FT> c = carrier.points[e.v[0]];
      for (int k = 1; k < 4; ++k) c = c + carrier.points[e.v[k]];
      const auto q = t(core::scaled<FT, 3>(c, FT(1) / FT(4)));
      s.seeds.push_back({{rounded(q[0]), rounded(q[1]), rounded(q[2])},
                         int(x.instances[ids[a].i][ids[a].g].region)});
      break;
    }
  }
  return w;
}

/// Stores a tetrahedralization of the whole geometry (spec/generation.md#conventional-3d,
/// #gmsh-3d) as one template per region (vertices numbered per region in global order),
/// instanced once by the identity, and the vertices two regions share as the SVB tables.
/// Returns the number of regions.
std::size_t store_by_region(const TetrahedralMeshOutput& out, GenerationResult& r) {
  std::map<int, std::vector<std::size_t>> by_region;
  for (std::size_t c = 0; c < out.tetrahedra.size(); ++c) by_region[out.region[c]].push_back(c);
  auto& tm = r.templated.templated;
  tm = mesh::TemplatedMesh{};
  tm.point_dimension = 3;
  r.templated.tables.clear();
  r.templated.identifications.clear();
  std::vector<std::map<std::size_t, mesh::IndexType>> local;
  for (const auto& [region, cells] : by_region) {
    mesh::MeshTemplate t;
    t.mesh.point_dimension = 3;
    std::map<std::size_t, mesh::IndexType> ids_here;
    for (std::size_t c : cells)
      for (std::size_t v : out.tetrahedra[c]) ids_here.emplace(v, 0);
    for (auto& [v, l] : ids_here) l = t.mesh.add_vertex(out.points[v].data());
    for (std::size_t c : cells) {
      mesh::IndexType v[4];
      for (int k = 0; k < 4; ++k) v[k] = ids_here.at(out.tetrahedra[c][std::size_t(k)]);
      t.mesh.add_cell(mesh::ElementType::tetrahedron, v);
    }
    t.transformation_indices.push_back(mesh::IndexType(tm.transformations.size()));
    t.region_ids.push_back(mesh::RegionIdType(region));
    tm.transformations.push_back({{1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}});
    tm.templates.push_back(std::move(t));
    local.push_back(std::move(ids_here));
  }
  for (std::size_t a = 0; a < local.size(); ++a)
    for (std::size_t b = a + 1; b < local.size(); ++b) {
      mesh::VertexIdentificationTable table{mesh::IndexType(a), mesh::IndexType(b), {}};
      for (const auto& [v, la] : local[a])
        if (const auto it = local[b].find(v); it != local[b].end())
          table.pairs.emplace_back(la, it->second);
      if (table.pairs.empty()) continue;
      r.templated.identifications.push_back(
          {mesh::IndexType(a), mesh::IndexType(b), mesh::IndexType(r.templated.tables.size())});
      r.templated.tables.push_back(std::move(table));
    }
  return by_region.size();
}

/// The conventional baseline of Section 7.1 in 3D (spec/generation.md#conventional-3d): the same
/// mesher with the same switches on the whole geometry. The boundaries of AT's regions
/// (whole_surface) are meshed by one TetGen call with a region seed inside each instance (-A);
/// its boundary is checked to be that surface exactly (the adapter). The result is stored as one
/// template per region, instanced once by the identity, whose shared TetGen vertices are the SVB
/// tables; it is conforming by construction (one tetrahedralization), so the certificate is the
/// adapter's boundary check.
template <class FT>
void mesh_whole(const core::TemplatedStructure<FT, 3>& x,
                const std::vector<SurfaceBoundary<FT>>& boundaries, const GenerationOptions& o,
                GenerationResult& r) {
  const auto t0 = Clock::now();
  const long f0 = minor_faults();
  if (o.progress) o.progress->stage("whole-geometry meshing (TetGen)", 0, "");
  const auto s = whole_surface(x, boundaries, r).surface;
  TetrahedralMeshingParameters p;
  p.size = o.size;
  const auto out = mesh_domain_3(s, p);
  const std::size_t regions = store_by_region(out, r);
  r.timings.template_meshing = seconds_since(t0);
  r.timings.page_faults.template_meshing = minor_faults() - f0;
  r.lemma_4_2_holds = true; // one tetrahedralization whose boundary was checked by the adapter
  if (o.progress)
    o.progress->message("whole geometry: " + std::to_string(out.tetrahedra.size()) +
                        " tetrahedra in " + std::to_string(regions) + " regions");
}

/// The Gmsh peer in 3D (spec/generation.md#gmsh-3d): the region surfaces of the conventional
/// baseline (whole_surface: the same boundary meshes), each region's closed surface handed to
/// Gmsh's 3D Delaunay as a discrete volume whose surface mesh is kept. Stored as mesh_whole
/// stores TetGen's result. Not certified in exact arithmetic: Gmsh's boundary is checked
/// combinatorially to be the input surface (every input triangle a face, every boundary or
/// region-interface face an input triangle; otherwise MeshingError, exit 2), and
/// `lemma_4_2_holds` is that check plus no triangle in more than two tetrahedra (the regions
/// share their interface triangles by node ids, so AT is conforming).
template <class FT>
void mesh_whole_by_gmsh(const core::TemplatedStructure<FT, 3>& x,
                        const std::vector<SurfaceBoundary<FT>>& boundaries,
                        const GenerationOptions& o, GenerationResult& r) {
  if (o.progress) o.progress->stage("whole-geometry meshing (Gmsh)", 0, "");
  const auto w = whole_surface(x, boundaries, r);
  ClosedSurfaces in;
  in.points = w.surface.points;
  std::map<int, std::size_t> slot; // region id -> position in in.regions (ascending ids)
  for (const auto& s : w.sides) {
    slot.emplace(s.region, 0);
    slot.emplace(s.other, 0);
  }
  for (auto& [id, k] : slot) {
    k = in.regions.size();
    in.regions.push_back({id, {}});
  }
  for (std::size_t k = 0; k < w.sides.size(); ++k) {
    in.regions[slot.at(w.sides[k].region)].triangles.push_back(w.surface.triangles[k]);
    if (w.sides[k].interface)
      in.regions[slot.at(w.sides[k].other)].triangles.push_back(w.surface.triangles[k]);
  }
  long f0 = minor_faults();
  const auto g = mesh_with_gmsh_3d(in, o.size);
  r.timings.template_meshing = g.seconds; // the module's own span: model build and generate(3)
  r.timings.page_faults.template_meshing = minor_faults() - f0;
  const auto t0 = Clock::now();
  f0 = minor_faults();
  TetrahedralMeshOutput out;
  out.points = g.nodes;
  for (std::size_t k = 0; k < in.regions.size(); ++k)
    for (const auto& c : g.tetrahedra[k]) {
      out.tetrahedra.push_back(c);
      out.region.push_back(in.regions[k].id);
    }
  if (const auto f = boundary_mismatch(w.surface, out)) {
    std::ostringstream why;
    if (*f < w.surface.triangles.size())
      why << "Gmsh changed the boundary: surface triangle " << *f << " ("
          << w.surface.triangles[*f][0] << ", " << w.surface.triangles[*f][1] << ", "
          << w.surface.triangles[*f][2] << ") is not a face of its mesh (split or lost)";
    else
      why << "Gmsh changed the boundary: its mesh has a boundary or region-interface face that "
             "is no surface triangle (a Steiner point on the boundary)";
    throw MeshingError(why.str());
  }
  // Triangles in more than two tetrahedra: runs of three equal faces in the sorted face list.
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(4 * out.tetrahedra.size());
  for (const auto& c : out.tetrahedra)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<std::size_t, 3> f{};
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != skip) f[std::size_t(j++)] = c[std::size_t(k)];
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  std::size_t crowded = 0;
  for (std::size_t k = 2; k < faces.size(); ++k)
    if (faces[k] == faces[k - 2] && (k < 3 || faces[k] != faces[k - 3])) ++crowded;
  const std::size_t regions = store_by_region(out, r);
  for (auto& t : r.templated.templated.templates) orient_tetrahedra_positively(t.mesh);
  r.timings.certificate = seconds_since(t0);
  r.timings.page_faults.certificate = minor_faults() - f0;
  r.lemma_4_2_holds = crowded == 0;
  if (!r.lemma_4_2_holds)
    r.lemma_4_2_failure = std::to_string(crowded) + " triangles of Gmsh's mesh lie in more than "
                                                    "two tetrahedra (its region meshes overlap)";
  if (o.progress)
    o.progress->message("gmsh: " + std::to_string(out.tetrahedra.size()) + " tetrahedra in " +
                        std::to_string(regions) + " regions");
}

/// Which mesher makes the volume mesh: one TetGen call per template (Algorithm 5.7), or the
/// whole geometry at once by TetGen (#conventional-3d) or by Gmsh (#gmsh-3d).
enum class Whole { no, tetgen, gmsh };

/// `rotational`: Section 6.3 with Algorithm 6.2 in 3D (spec/generation.md#rotational-3d).
/// `whole`: the baselines (#conventional-3d, #gmsh-3d): the same boundary meshes, then one
/// mesher call on the whole geometry instead of one per template.
template <class FT>
GenerationResult generate_3(const core::TemplatedStructure<FT, 3>& x, const GenerationOptions& o,
                            Symmetry symmetry = Symmetry::none, Whole whole = Whole::no) {
  const bool rotational = symmetry == Symmetry::rotational;
  const bool group = symmetry == Symmetry::reflective || symmetry == Symmetry::combined;
  if (!(o.size > 0) || !std::isfinite(o.size))
    throw std::invalid_argument("--size must be a positive number");
  if (o.progress) o.progress->stage("templates well-formed", 0, "");
  std::ostringstream why;
  if (!x.is_well_formed(&why)) throw std::invalid_argument(why.str());
  if (!x.all_of_kind(core::TemplateKind::geometry))
    throw std::invalid_argument("Algorithm 5.7 needs geometry templates (\"kind\": \"geometry\")");
  const auto say = [&](const std::string& s) {
    if (o.progress) o.progress->message(s);
  };
  const auto stage = [&](const std::string& name, std::size_t total, const std::string& unit) {
    if (o.progress) o.progress->stage(name, total, unit);
  };
  GenerationResult r;
  auto& faults = r.timings.page_faults;
  // The rotational checks come first (timed with the BPP, whose shortcut they license): they let
  // Eq. 4.2 be checked up to the rotation too.
  auto t0 = Clock::now();
  long f0 = minor_faults();
  std::size_t rotations = 0;
  core::TemplatedStructure<FT, 3> two_copies;
  if (rotational) {
    std::string reason;
    rotations = support::rotation_order(x, reason);
    if (rotations == 0)
      throw std::invalid_argument("--method rotational: not a rotational slice structure: " +
                                  reason);
    if (const auto contact = non_consecutive_contact(x, rotations))
      throw std::invalid_argument("--method rotational: " + *contact +
                                  " (3D slices may meet only their neighbours; use bpp)");
    two_copies.templates = x.templates;
    for (const auto& list : x.instances) two_copies.instances.push_back({list[0], list[1]});
  }
  std::size_t copies = 0;
  if (group) {
    // Algorithms 6.1/6.4/6.5 in 3D: copy 0 of every template is the positive part; its BPP makes
    // the interfaces inside it conform, and the mirror planes need nothing (Lemma 6.1: each
    // reflection fixes its mirror pointwise, so any surface mesh of a mirror face conforms).
    copies = support::symmetry_copies(x, symmetry).size();
    two_copies.templates = x.templates;
    for (const auto& list : x.instances) two_copies.instances.push_back({list[0]});
  }
  const double symmetry_seconds = seconds_since(t0);
  const long symmetry_faults = minor_faults() - f0;
  stage("instance overlap (Eq. 4.2)", 0, "");
  if (const auto overlap = core::find_instance_overlap(x, rotations))
    throw std::invalid_argument(core::overlap_message(*overlap));
  const auto bpp = support::boundary_patch_stage(rotational || group ? two_copies : x, o,
                                                 symmetry_seconds, symmetry_faults, r);

  stage("line and surface meshes", 0, "");
  t0 = Clock::now();
  f0 = minor_faults();
  const FT h = exact_from_double<FT>(o.size);
  const FT h2 = h * h;
  const auto classes = face_classes(bpp);
  const auto groups = face_groups(bpp, classes);
  const auto even = mirrored_edge_lengths(bpp, classes, groups);
  std::vector<SurfaceBoundary<FT>> boundaries;
  for (const auto& sd : bpp.subdivisions)
    boundaries.push_back(line_meshes_3<FT>(sd, h2, o.size, even));
  surface_meshes(x, bpp, classes, groups, boundaries, h2, o.size, o.min_angle_deg);
  if (o.perturb_one_surface_mesh) perturb_one_surface_mesh(bpp, boundaries);
  r.timings.line_meshes = seconds_since(t0);
  faults.line_meshes = minor_faults() - f0;

  stage("shared vertex bookkeeping", 0, "");
  t0 = Clock::now();
  f0 = minor_faults();
  auto candidates = support::svb_candidates<FT, 3>(
      x, bpp, [&](std::size_t l) { return mapping_pairs_3(bpp, l, boundaries); }, rotations,
      copies);
  std::vector<std::size_t> boundary_vertices;
  for (const auto& b : boundaries) boundary_vertices.push_back(b.exact.size());
  if (group) {
    std::vector<std::vector<P3<FT>>> points;
    for (const auto& b : boundaries) points.push_back(b.exact);
    support::copy_candidates<FT, 3>(x, points, candidates);
  }
  support::shared_vertex_bookkeeping<FT, 3>(x, boundary_vertices, std::move(candidates),
                                            r.templated);
  r.timings.svb = seconds_since(t0);
  faults.svb = minor_faults() - f0;

  if (whole == Whole::tetgen) {
    mesh_whole(x, boundaries, o, r);
    return r;
  }
  if (whole == Whole::gmsh) {
    mesh_whole_by_gmsh(x, boundaries, o, r);
    return r;
  }

  t0 = Clock::now();
  f0 = minor_faults();
  stage("template meshing (TetGen)", x.templates.size(), "templates");
  auto& tm = r.templated.templated;
  tm.point_dimension = 3;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    SurfaceInput s;
    for (const auto& p : boundaries[i].exact)
      s.points.push_back({rounded(p[0]), rounded(p[1]), rounded(p[2])});
    s.triangles = boundaries[i].triangles;
    TetrahedralMeshingParameters p;
    p.size = o.size;
    TetrahedralMeshOutput out;
    try {
      out = mesh_domain_3(s, p);
    } catch (const BoundaryChanged& e) {
      throw MeshingError("template '" + x.templates[i].name + "'" +
                         boundary_place(bpp, boundaries[i], i, e.triangle) + ": " + e.what() +
                         "; nothing written");
    } catch (const MeshingError& e) {
      throw MeshingError("template '" + x.templates[i].name + "': " + e.what());
    }
    mesh::MeshTemplate t;
    t.mesh.point_dimension = 3;
    for (const auto& q : out.points) t.mesh.add_vertex(q.data());
    for (const auto& c : out.tetrahedra) {
      const mesh::IndexType v[4] = {mesh::IndexType(c[0]), mesh::IndexType(c[1]),
                                    mesh::IndexType(c[2]), mesh::IndexType(c[3])};
      t.mesh.add_cell(mesh::ElementType::tetrahedron, v);
    }
    for (const auto& inst : x.instances[i]) {
      t.transformation_indices.push_back(mesh::IndexType(tm.transformations.size()));
      t.region_ids.push_back(mesh::RegionIdType(inst.region));
      tm.transformations.push_back(support::to_double_transformation<3>(inst.transformation));
    }
    say("template " + std::to_string(i + 1) + "/" + std::to_string(x.templates.size()) + " ('" +
        x.templates[i].name + "'): " + std::to_string(t.mesh.cell_count()) + " tetrahedra, " +
        std::to_string(boundaries[i].triangles.size()) + " boundary triangles");
    tm.templates.push_back(std::move(t));
    if (o.progress) o.progress->set_done(i + 1);
  }
  r.timings.template_meshing = seconds_since(t0);
  faults.template_meshing = minor_faults() - f0;

  support::certificate_stage(o, r, [&] {
    if (o.direct_certificate) return certify_3(x, boundaries);
    if (group) return certify_copies(x, support::symmetry_copies(x, symmetry), bpp, boundaries);
    return certify_by_mappings(bpp, boundaries);
  });
  return r;
}

template <class FT>
GenerationResult generate_by_3(const core::TemplatedStructure<FT, 3>& x, Method method,
                               const GenerationOptions& options) {
  std::string unused;
  const auto rotational_applies = [&] {
    const std::size_t n = support::rotation_order(x, unused);
    return n > 0 && !non_consecutive_contact(x, n);
  };
  const auto is_group = [&](Symmetry kind) {
    try {
      support::symmetry_copies(x, kind);
      return true;
    } catch (const std::invalid_argument&) {
      return false;
    }
  };
  if (method == Method::automatic)
    // The most specialised method whose exact checks pass; bpp needs no symmetry.
    method = x.instances.empty()              ? Method::bpp
             : rotational_applies()           ? Method::rotational
             : is_group(Symmetry::combined)   ? Method::combined
             : is_group(Symmetry::reflective) ? Method::reflective
                                              : Method::bpp;
  GenerationResult r;
  switch (method) {
  case Method::bpp:
    r = generate_3(x, options);
    r.method = "bpp";
    break;
  case Method::rotational:
    r = generate_3(x, options, Symmetry::rotational);
    r.method = "rotational";
    break;
  case Method::reflective:
    r = generate_3(x, options, Symmetry::reflective);
    r.method = "reflective";
    break;
  case Method::combined:
    r = generate_3(x, options, Symmetry::combined);
    r.method = "combined";
    break;
  case Method::conventional:
    // The boundary meshes as the templated method makes them (rotational when it applies).
    r = generate_3(x, options, rotational_applies() ? Symmetry::rotational : Symmetry::none,
                   Whole::tetgen);
    r.method = "conventional";
    break;
  case Method::gmsh:
    // The peer on the very surfaces the conventional baseline hands TetGen.
    r = generate_3(x, options, rotational_applies() ? Symmetry::rotational : Symmetry::none,
                   Whole::gmsh);
    r.method = "gmsh";
    break;
  default:
    throw std::invalid_argument(
        "--method: only auto, bpp, rotational, reflective, combined, conventional and gmsh "
        "generate 3D meshes so far (spec/generation.md#alg-5-7)");
  }
  return r;
}

using support::lazily;

template <class FT>
CellEstimate estimate_3(const core::TemplatedStructure<FT, 3>& x, double size) {
  FT volume(0);
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    volume += carrier_volume(x.templates[i].mesh) * FT(int(x.instances[i].size()));
  CellEstimate e;
  e.dimension = 3;
  e.measure = rounded(volume);
  e.cells = e.measure / volume_bound(size) * kTetrahedraPerVolumeBound;
  return e;
}
} // namespace

CellEstimate estimate_cells(const core::TemplatedStructure<Exact, 3>& x, double size) {
  return estimate_3(x, size);
}
CellEstimate estimate_cells(const core::TemplatedStructure<number::Cyclotomic, 3>& x, double size) {
  return estimate_3(lazily(x), size);
}

GenerationResult generate_tetrahedral_mesh(const core::TemplatedStructure<Exact, 3>& x,
                                           Method method, const GenerationOptions& options) {
  return generate_by_3(x, method, options);
}
GenerationResult generate_tetrahedral_mesh(const core::TemplatedStructure<number::Cyclotomic, 3>& x,
                                           Method method, const GenerationOptions& options) {
  return generate_by_3(lazily(x), method, options);
}

} // namespace symmesh::gen
