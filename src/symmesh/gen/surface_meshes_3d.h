// Algorithm 5.7, surface stage (internal to templated_tetrahedral_mesh.cpp): uniform line meshes
// on the boundary subdivision's edges, every face class meshed once in its own plane (conforming
// to the line meshes; symmetric where a mapping sends the face onto itself) and carried to every
// related face by the exact template boundary mappings — spec/generation.md#alg-5-7,
// #symmetric-surface-meshes
#pragma once
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/gen/generation_support.h"
#include "symmesh/gen/pipeline_stages.h"
#include "symmesh/gen/shared_vertex_bookkeeping.h"
#include "symmesh/gen/symmetric_surface_mesh.h"
#include "symmesh/gen/symmetry_copies.h"
#include "symmesh/gen/triangle_mesher.h"
#include "symmesh/number/error_free.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::gen::surface3 {

using support::Clock;
using support::exact_from_double;
using support::FaceLine;
using support::LazyCyclotomic;
using support::minor_faults;
using support::narrow_midpoint;
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

/// A face's plane in exact coordinates: its points are p0 + s·u + t·v. A surface mesh carried by
/// a rigid map keeps its (s, t) and takes the image frame (map(p0), A·u, A·v), so that a mapping
/// between two carried faces is checked on the frames once and on the (s, t) lists, not point by
/// point (spec/lemmas.md#lemma-4-2-surface-meshes).
template <class FT>
struct FacePlane {
  P3<FT> p0, u, v;
  P3<FT> at(const std::array<FT, 2>& st) const {
    return p0 + core::scaled<FT, 3>(u, st[0]) + core::scaled<FT, 3>(v, st[1]);
  }
};

template <class FT>
FacePlane<FT> image_plane(const core::RigidTransformation<FT, 3>& m, const FacePlane<FT>& f) {
  return {m(f.p0), m.linear(f.u), m.linear(f.v)};
}

/// Template t's boundary mesh: every boundary point exactly in local ids (subdivision points,
/// then the interior points of each line mesh, then those of each surface mesh), the line mesh
/// of every edge face and the triangles of the surface meshes of the 2-faces. TetGen gets the
/// points rounded once from their exact values; conformity never depends on the rounding, the
/// SVB identifies points by index.
template <class FT>
struct SurfaceBoundary {
  std::vector<P3<FT>> exact;
  /// per subdivision face (n = 0: not an edge); its points are exact[first + k − 1] =
  /// line_point(a, b, k, n), written by line_meshes_3 only (the certificate relies on it)
  std::vector<FaceLine> lines;
  std::vector<std::size_t> facet_first, facet_count; ///< per subdivision face: interior points
  /// per subdivision face: meshed symmetrically, so a mapping may permute its interior points
  std::vector<bool> facet_symmetric;
  /// per subdivision face: set when its interior points are exact[facet_first + k] =
  /// facet_plane->at((*facet_st)[k]) — an invariant the certificate relies on and does not
  /// re-check: surface_meshes writes all three, perturb_one_surface_mesh changes one (s, t) and
  /// its point together, perturb_one_face_frame one frame and its points, and nothing else
  /// writes them (the merge method leaves facet_plane unset)
  std::vector<std::optional<FacePlane<FT>>> facet_plane;
  std::vector<std::shared_ptr<const std::vector<std::array<FT, 2>>>> facet_st;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<std::size_t> triangle_face; ///< the 2-face each triangle lies in
  /// vertices and line points, when line_meshes_3 is asked for it (the merge method looks points
  /// up; generation carries ids along the face action instead)
  std::map<P3<FT>, std::size_t, core::PointLess<FT, 3>> id_of;
};

template <class FT>
SurfaceBoundary<FT> line_meshes_3(const core::BoundarySubdivision<FT, 3>& sd, const FT& h2,
                                  double h, const std::set<FT>& even_lengths,
                                  bool point_index = true) {
  SurfaceBoundary<FT> tb;
  tb.exact = sd.points;
  if (point_index)
    for (std::size_t v = 0; v < tb.exact.size(); ++v) tb.id_of.emplace(tb.exact[v], v);
  tb.lines.resize(sd.faces.size());
  tb.facet_first.assign(sd.faces.size(), 0);
  tb.facet_count.assign(sd.faces.size(), 0);
  tb.facet_symmetric.assign(sd.faces.size(), false);
  tb.facet_plane.assign(sd.faces.size(), std::nullopt);
  tb.facet_st.assign(sd.faces.size(), nullptr);
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
      if (point_index) tb.id_of.emplace(tb.exact.back(), tb.exact.size() - 1);
    }
  }
  return tb;
}

/// The local ids of the line-mesh points of edge face e, from a to b.
inline std::vector<std::size_t> line_ids(const FaceLine& line) {
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
  /// when set, interior[k] = plane->at(st[k]) (mesh_facet; not the symmetric meshes)
  std::optional<FacePlane<FT>> plane;
  std::vector<std::array<FT, 2>> st;
};

/// An exact orthogonal frame of a face's plane, from its vertices (not its pieces, whose
/// triangulation need not be canonical): p0 its first vertex, u towards its second, v = n × u in
/// the plane with n from the first vertex off the line. The mesher works in (x·u/|u|, x·v/|v|),
/// whose orientation is that of n.
template <class FT>
struct FacetFrame {
  P3<FT> p0, u, v, n;
  double lu = 0, lv = 0;

  /// x in the plane's doubles by rounded(): the same exact point gives the same doubles however it
  /// was reached, which the merge method relies on (it overlays the meshes of two faces).
  std::array<double, 2> to_plane(const P3<FT>& x) const {
    const P3<FT> d = x - p0;
    return {rounded(core::dot<FT, 3>(d, u)) / lu, rounded(core::dot<FT, 3>(d, v)) / lv};
  }
  /// x in the plane's doubles for a mesh that is the only one made of its face class (generation
  /// carries it to the other faces by index): conformity and the exact interior points
  /// (plane_coordinates) never depend on these doubles, and the mesher keeps its points ~size
  /// apart, so a dot product is taken from its interval once that is within 1e-12·|d|·|u|
  /// (~1e-12 of the face's extent in the plane) — rounded() asks for 4 ulp of the product itself,
  /// and over K_512 the intervals of the line points are wider than that, so it evaluated most of
  /// them exactly (at n = 128, half of the surface meshes' time).
  std::array<double, 2> to_plane_once(const P3<FT>& x) const {
    const P3<FT> d = x - p0;
    double dd = 0;
    for (int c = 0; c < 3; ++c) {
      const auto [lo, hi] = CGAL::to_interval(d[c]);
      dd += std::max(std::abs(lo), std::abs(hi)) * std::max(std::abs(lo), std::abs(hi));
    }
    return {coordinate(core::dot<FT, 3>(d, u), std::sqrt(dd) * lu) / lu,
            coordinate(core::dot<FT, 3>(d, v), std::sqrt(dd) * lv) / lv};
  }
  static double coordinate(const FT& dot, double scale) {
    if (const auto m = narrow_midpoint(dot, 1e-12 * scale)) return *m;
    return rounded(dot);
  }
  std::array<FT, 2> plane_coordinates(const std::array<double, 2>& q) const {
    return {exact_from_double<FT>(q[0] / lu), exact_from_double<FT>(q[1] / lv)};
  }
  P3<FT> from_plane(const std::array<double, 2>& q) const {
    return FacePlane<FT>{p0, u, v}.at(plane_coordinates(q));
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

/// Two triangles (a, b, c), (b, a, d) of a face mesh are a tie — their four points on one circle
/// to the doubles the mesher worked in (its Delaunay choice was made in them), so either
/// diagonal is Delaunay — and the other diagonal makes two triangles of the same orientation.
inline bool tied_diagonals(const std::array<std::array<double, 2>, 4>& q) {
  double m[3][3], scale = 0;
  for (int i = 0; i < 3; ++i) {
    const double ds = q[std::size_t(i)][0] - q[3][0], dt = q[std::size_t(i)][1] - q[3][1];
    m[i][0] = ds;
    m[i][1] = dt;
    m[i][2] = ds * ds + dt * dt;
    scale = std::max({scale, std::abs(ds), std::abs(dt)});
  }
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  const double s2 = scale * scale;
  if (!(std::abs(det) <= 1e-8 * s2 * s2)) return false;
  const auto orient = [&](int i, int j, int k) {
    const auto &p = q[std::size_t(i)], &r = q[std::size_t(j)], &t = q[std::size_t(k)];
    return (r[0] - p[0]) * (t[1] - p[1]) - (r[1] - p[1]) * (t[0] - p[0]);
  };
  // Strictly convex: c and d clearly on either side of ab, and a, b on either side of cd.
  const double o = orient(0, 1, 2), tol = 1e-6 * s2;
  const double o1 = orient(2, 0, 3), o2 = orient(3, 1, 2);
  return std::abs(o) > tol && o * o1 > 0 && o * o2 > 0 && std::abs(o1) > tol && std::abs(o2) > tol;
}

/// Gives every tie of a face mesh (tied_diagonals) the diagonal through the smallest of its four
/// points in one order of the template's points: lexicographic on their coordinates, two
/// coordinates within 1e-7 of the quad's extent counting as equal (exactly equal ones differ by
/// their rounding only). A thin face is a strip of rectangles, all ties, where the mesher's choice
/// follows its frame; two faces of a thin column meshed apart (the two cut faces of a
/// half-slice) could then wind the column's side diagonals around it like a Schönhardt prism,
/// which no tetrahedralization without an interior point fills — TetGen adds one, and its cells
/// are flat. Diagonals through the smallest point follow one order of the column's edges, which
/// never winds (spec/generation.md#surface-meshes). Any diagonal of a tie keeps the mesh valid
/// and conforming; this only chooses.
template <class FT>
void canonical_ties(FacetMesh<FT>& m, const std::vector<P3<FT>>& template_exact,
                    const std::vector<std::array<double, 2>>& q) {
  const std::size_t nb = m.boundary_ids.size();
  std::vector<std::array<double, 3>> x(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    const P3<FT>& p = i < nb ? template_exact[m.boundary_ids[i]] : m.interior[i - nb];
    for (std::size_t c = 0; c < 3; ++c) {
      const auto [lo, hi] = CGAL::to_interval(p[c]);
      x[i][c] = lo / 2 + hi / 2;
    }
  }
  auto& tris = m.triangles;
  // Directed edge -> (triangle, position of the edge's first point).
  std::map<std::array<std::size_t, 2>, std::pair<std::size_t, int>> half;
  const auto index = [&](std::size_t t) {
    for (int i = 0; i < 3; ++i)
      half[{tris[t][std::size_t(i)], tris[t][std::size_t((i + 1) % 3)]}] = {t, i};
  };
  for (std::size_t t = 0; t < tris.size(); ++t) index(t);
  for (int pass = 0; pass < 4; ++pass) {
    bool changed = false;
    for (std::size_t t = 0; t < tris.size(); ++t) {
      for (int i = 0; i < 3; ++i) {
        const std::size_t a = tris[t][std::size_t(i)], b = tris[t][std::size_t((i + 1) % 3)];
        const std::size_t c = tris[t][std::size_t((i + 2) % 3)];
        const auto it = half.find({b, a});
        if (it == half.end()) continue; // a boundary segment
        const auto [u, j] = it->second;
        const std::size_t d = tris[u][std::size_t((j + 2) % 3)];
        if (!tied_diagonals({q[a], q[b], q[c], q[d]})) continue;
        double extent = 0;
        for (std::size_t v : {b, c, d})
          for (std::size_t k = 0; k < 3; ++k)
            extent = std::max(extent, std::abs(x[v][k] - x[a][k]));
        const auto less = [&](std::size_t v, std::size_t w) {
          for (std::size_t k = 0; k < 3; ++k)
            if (std::abs(x[v][k] - x[w][k]) > 1e-7 * extent) return x[v][k] < x[w][k];
          return v < w;
        };
        const std::size_t lo = std::min({a, b, c, d}, less);
        if (lo == a || lo == b) continue;
        // (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c), of the same orientation.
        half.erase({a, b});
        half.erase({b, a});
        tris[t] = {c, a, d};
        tris[u] = {d, b, c};
        index(t);
        index(u);
        changed = true;
        break;
      }
    }
    if (!changed) break;
  }
}

/// \p once: the mesh is the only one made of face f's class (to_plane_once), not one of several
/// meshes of congruent faces that are compared later (the merge method: to_plane).
template <class FT>
FacetMesh<FT> mesh_facet(const core::BoundarySubdivision<FT, 3>& sd, const SurfaceBoundary<FT>& tb,
                         std::size_t f, double size, double min_angle_deg, bool once = false) {
  FacetMesh<FT> out;
  BoundaryInput in;
  in.segments = facet_boundary(sd, tb, f, out.boundary_ids);
  const auto frame = facet_frame(sd, f);
  for (std::size_t id : out.boundary_ids)
    in.points.push_back(once ? frame.to_plane_once(tb.exact[id]) : frame.to_plane(tb.exact[id]));
  MeshingParameters p;
  p.size = size;
  p.min_angle_deg = min_angle_deg;
  const auto m = mesh_domain_2(in, p);
  out.plane = FacePlane<FT>{frame.p0, frame.u, frame.v};
  for (std::size_t k = in.points.size(); k < m.points.size(); ++k) {
    out.st.push_back(frame.plane_coordinates(m.points[k]));
    out.interior.push_back(out.plane->at(out.st.back()));
  }
  out.triangles = m.triangles;
  if (once) canonical_ties(out, tb.exact, m.points);
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
  /// Per member, the faces that comp sends the first face's closure faces onto (in the order of
  /// its `closure`): the letters' face actions composed along the same BFS tree, so that the
  /// line-mesh points of a member's boundary are found by index, without evaluating comp.
  std::map<core::FaceRef, std::vector<std::size_t>> closure_image;
  std::vector<core::RigidTransformation<FT, 3>> generators;
};

/// δ(f, l): the face that letter l sends face f onto (letter_action is ordered by f).
inline std::size_t face_image(const std::vector<std::pair<std::size_t, std::size_t>>& action,
                              std::size_t f) {
  const auto it = std::lower_bound(action.begin(), action.end(), std::make_pair(f, std::size_t(0)));
  if (it == action.end() || it->first != f)
    throw std::logic_error("Algorithm 5.7: a face in the closure of a mapped 2-face is not in "
                           "the mapping's domain");
  return it->second;
}

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
      c.closure_image.emplace(c.first, sds[t].faces[f].closure);
      done[t][f] = true;
      for (std::size_t k = 0; k < c.members.size(); ++k) {
        const auto cur = c.members[k];
        for (const auto& [l, next] : arrows[cur.t][cur.f]) {
          if (c.comp.count(next)) continue;
          c.comp.emplace(next, bpp.mappings[l].map * c.comp.at(cur));
          std::vector<std::size_t> image;
          for (std::size_t g : c.closure_image.at(cur))
            image.push_back(face_image(bpp.letter_action[l], g));
          c.closure_image.emplace(next, std::move(image));
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

/// The ids, in the member's template, of the line-mesh points on the closure of face f (vertices
/// and the points of its edge faces) — the images under the class composition, found from the
/// faces it sends the closure onto (`image`, in closure order): a vertex goes to the image
/// vertex; the k-th point of an edge from a to b goes to the k-th point of the image edge from
/// the image of a (line_point is affine in its ends and congruent edges get the same number of
/// parts, so it is the same exact point as the mapped one).
template <class FT>
std::map<std::size_t, std::size_t>
boundary_point_images(const core::BoundarySubdivision<FT, 3>& from_sd,
                      const SurfaceBoundary<FT>& from,
                      const core::BoundarySubdivision<FT, 3>& to_sd, const SurfaceBoundary<FT>& to,
                      std::size_t f, const std::vector<std::size_t>& image) {
  const auto& closure = from_sd.faces[f].closure;
  std::map<std::size_t, std::size_t> vertex; // closure vertex -> image vertex
  for (std::size_t k = 0; k < closure.size(); ++k)
    if (from_sd.faces[closure[k]].dimension == 0)
      vertex[from_sd.faces[closure[k]].vertices[0]] = to_sd.faces[image[k]].vertices[0];
  std::map<std::size_t, std::size_t> out(vertex.begin(), vertex.end());
  for (std::size_t k = 0; k < closure.size(); ++k) {
    if (from_sd.faces[closure[k]].dimension != 1) continue;
    const FaceLine &a = from.lines[closure[k]], &b = to.lines[image[k]];
    if (to_sd.faces[image[k]].dimension != 1 || a.n != b.n || !vertex.count(a.a))
      throw std::logic_error("Algorithm 5.7: a mapping does not send an edge face's line mesh "
                             "onto an edge face's line mesh");
    const auto ia = line_ids(a), ib = line_ids(b);
    const bool same = vertex.at(a.a) == b.a;
    for (std::size_t q = 0; q < ia.size(); ++q) out[ia[q]] = ib[same ? q : ia.size() - 1 - q];
  }
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
                         ? mesh_facet(sds[t], boundaries[t], f, size, min_angle_deg, true)
                         : mesh_symmetric_facet(x, sds[t], boundaries[t], classes[k].first,
                                                groups[k], h2, size, min_angle_deg);
    const auto st = std::make_shared<const std::vector<std::array<FT, 2>>>(rep.st);
    for (const auto& g : classes[k].members) {
      auto& tb = boundaries[g.t];
      const auto& map = classes[k].comp.at(g);
      const auto image = boundary_point_images(sds[t], boundaries[t], sds[g.t], tb, f,
                                               classes[k].closure_image.at(g));
      std::vector<std::size_t> ids;
      for (std::size_t id : rep.boundary_ids) {
        const auto it = image.find(id);
        if (it == image.end())
          throw std::logic_error("Algorithm 5.7: a surface-mesh boundary point of a 2-face is "
                                 "not on its closure's line meshes");
        ids.push_back(it->second);
      }
      tb.facet_first[g.f] = tb.exact.size();
      tb.facet_count[g.f] = rep.interior.size();
      tb.facet_symmetric[g.f] = !groups[k].is_trivial();
      if (rep.plane) {
        // Carried in face coordinates: the image frame once, then each point from its (s, t) —
        // the same exact value as map(q), and cheaper to evaluate (rational times K_m).
        const auto& plane = tb.facet_plane[g.f].emplace(
            map.is_identity() ? *rep.plane : image_plane(map, *rep.plane));
        tb.facet_st[g.f] = st;
        for (const auto& c : *st) {
          ids.push_back(tb.exact.size());
          tb.exact.push_back(plane.at(c));
        }
      } else {
        for (const auto& q : rep.interior) {
          ids.push_back(tb.exact.size());
          tb.exact.push_back(map(q));
        }
      }
      for (const auto& c : rep.triangles) {
        tb.triangles.push_back({ids[c[0]], ids[c[1]], ids[c[2]]});
        tb.triangle_face.push_back(g.f);
      }
    }
  }
}

/// The double-double enclosures of a face frame's nine exact coordinates (nearest_on_plane).
struct PlaneEnclosure {
  std::array<std::array<double, 3>, 3> hi{}, lo{}, bound{}; ///< [p0, u, v][coordinate]
  bool usable = false;
};

template <class FT>
PlaneEnclosure plane_enclosure(const FacePlane<FT>& plane) {
  PlaneEnclosure e;
  if constexpr (std::is_same_v<FT, LazyCyclotomic>) {
    const P3<FT>* parts[3] = {&plane.p0, &plane.u, &plane.v};
    e.usable = true;
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) {
        CGAL::exact((*parts[k])[d]).double_double_enclosure(e.hi[k][d], e.lo[k][d], e.bound[k][d]);
        // Far from underflow and overflow, so that the products below stay normal.
        const double a = std::fabs(e.hi[k][d]);
        if (a != 0 && !(a > 0x1p-900 && a < 0x1p900)) e.usable = false;
      }
  }
  return e;
}

/// The double nearest to x = p0 + s·u + t·v (one coordinate; s, t doubles) from the frame's
/// double-double enclosures, or nullopt where that cannot be decided (x within the error bound of
/// a midpoint between two doubles, or outside the normal range). s·hi is split exactly (fma) and
/// the big parts summed exactly (TwoSum); the rest, a floating sum of seven small terms, and the
/// enclosures' bounds give |x − (h + l)| <= B, and h is the nearest double when x lies strictly
/// between the midpoints to h's neighbours. The same double as to_double of the exact value
/// (correct rounding), at the cost of a few dozen flops instead of exact K_m arithmetic. The
/// error-free steps need every product and sum rounded on its own: symmesh_gen and the unit tests
/// are compiled with -ffp-contract=off (CMakeLists.txt), so no fma is fused into them.
inline std::optional<double> nearest_on_plane(const PlaneEnclosure& e, int d, double s, double t) {
  constexpr double u = 0x1p-53;
  for (double c : {s, t})
    if (c != 0 && !(std::fabs(c) > 0x1p-100 && std::fabs(c) < 0x1p100)) return std::nullopt;
  using number::two_sum;
  const double p1 = s * e.hi[1][d], e1 = std::fma(s, e.hi[1][d], -p1);
  const double p2 = t * e.hi[2][d], e2 = std::fma(t, e.hi[2][d], -p2);
  const double a1 = s * e.lo[1][d], a2 = t * e.lo[2][d];
  double s1 = 0, r1 = 0, big = 0, r2 = 0;
  two_sum(e.hi[0][d], p1, s1, r1);
  two_sum(s1, p2, big, r2);
  const double terms[7] = {e.lo[0][d], e1, e2, a1, a2, r1, r2};
  double small = 0, magnitude = 0;
  for (double x : terms) {
    small += x;
    magnitude += std::fabs(x);
  }
  // Bounds: the enclosures; a1, a2 rounded once (u each); the floating sum of 7 terms (6u·Σ);
  // a generous factor 2 covers the roundings of this sum of positive terms.
  const double bound =
      2 * (e.bound[0][d] + std::fabs(s) * e.bound[1][d] + std::fabs(t) * e.bound[2][d] +
           u * (std::fabs(a1) + std::fabs(a2)) + 6 * u * magnitude);
  double h = 0, l = 0;
  two_sum(big, small, h, l);
  if (!(std::fabs(h) > 0x1p-1000 && std::fabs(h) < 0x1p1000) || !std::isfinite(bound))
    return std::nullopt;
  const double up = (std::nextafter(h, HUGE_VAL) - h) / 2;
  const double down = (h - std::nextafter(h, -HUGE_VAL)) / 2;
  if (std::nextafter(l + bound, HUGE_VAL) < up && std::nextafter(l - bound, -HUGE_VAL) > -down)
    return h;
  return std::nullopt;
}

/// Template t's boundary points rounded for TetGen: rounded() of each exact coordinate — the
/// midpoint of its lazy interval when that is within 4 ulp, else the nearest double. For points
/// stored in face coordinates over K_m the nearest double comes from nearest_on_plane where it
/// decides (the same double, without exact K_m evaluation of each point).
template <class FT>
std::vector<std::array<double, 3>> rounded_boundary(const SurfaceBoundary<FT>& tb) {
  std::vector<std::array<double, 3>> out(tb.exact.size());
  std::vector<bool> done(tb.exact.size(), false);
  for (std::size_t f = 0; f < tb.facet_plane.size(); ++f) {
    if (!tb.facet_plane[f] || tb.facet_count[f] == 0) continue;
    const auto e = plane_enclosure(*tb.facet_plane[f]);
    if (!e.usable) continue;
    for (std::size_t k = 0; k < tb.facet_count[f]; ++k) {
      const std::size_t id = tb.facet_first[f] + k;
      const auto& st = (*tb.facet_st[f])[k];
      const auto [s_lo, s_hi] = CGAL::to_interval(st[0]);
      const auto [t_lo, t_hi] = CGAL::to_interval(st[1]);
      for (int d = 0; d < 3; ++d) {
        const FT& x = tb.exact[id][d];
        auto v = support::narrow_midpoint(x); // rounded()'s first case, unchanged
        if (!v && s_lo == s_hi && t_lo == t_hi) v = nearest_on_plane(e, d, s_lo, t_lo);
        out[id][d] = v ? *v : CGAL::to_double(CGAL::exact(x));
      }
      done[id] = true;
    }
  }
  for (std::size_t id = 0; id < tb.exact.size(); ++id)
    if (!done[id])
      out[id] = {rounded(tb.exact[id][0]), rounded(tb.exact[id][1]), rounded(tb.exact[id][2])};
  return out;
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
        if (!tb.facet_plane[f]) {
          tb.exact[p] =
              tb.exact[p] + core::scaled<FT, 3>(tb.exact[q] - tb.exact[p], FT(1) / FT(16));
          return;
        }
        // In face coordinates (the frame is orthogonal), so the face keeps its invariant
        // exact = plane.at(st) and only this face's list changes.
        const auto& plane = *tb.facet_plane[f];
        const P3<FT> d = tb.exact[q] - plane.p0;
        const std::array<FT, 2> sq{
            core::dot<FT, 3>(d, plane.u) / core::dot<FT, 3>(plane.u, plane.u),
            core::dot<FT, 3>(d, plane.v) / core::dot<FT, 3>(plane.v, plane.v)};
        auto st = *tb.facet_st[f];
        for (int i = 0; i < 2; ++i) st[0][i] = st[0][i] + (sq[i] - st[0][i]) / FT(16);
        tb.exact[p] = plane.at(st[0]);
        tb.facet_st[f] = std::make_shared<const std::vector<std::array<FT, 2>>>(std::move(st));
        return;
      }
    }
  }
  throw std::invalid_argument(
      "perturb_one_surface_mesh: no face mapped onto another face has interior vertices");
}

/// GenerationOptions::perturb_one_face_frame: as a defect in carrying a surface mesh would, the
/// frame of the first image face in face coordinates that a non-trivial mapping sends another
/// face onto moves within its plane by u/2^20, and its interior points follow it (exact =
/// at(s, t) still holds, the (s, t) list is the source's), so only the frames disagree.
template <class FT>
void perturb_one_face_frame(const core::BoundaryPatchPartition<FT, 3>& bpp,
                            std::vector<SurfaceBoundary<FT>>& boundaries) {
  for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
    const auto& m = bpp.mappings[l];
    if (m.whole_boundary) continue;
    const auto& source = boundaries[m.from_template()];
    auto& tb = boundaries[m.to_template()];
    for (auto [f, g] : bpp.letter_action[l]) {
      // Both faces in face coordinates and not symmetric: the faces the frame check decides.
      if (tb.facet_count[g] == 0 || !tb.facet_plane[g] || tb.facet_symmetric[g] ||
          !source.facet_plane[f] || source.facet_symmetric[f] ||
          (m.from_template() == m.to_template() && f == g))
        continue;
      auto& plane = *tb.facet_plane[g];
      plane.p0 = plane.p0 + core::scaled<FT, 3>(plane.u, FT(1) / FT(1 << 20));
      for (std::size_t k = 0; k < tb.facet_count[g]; ++k)
        tb.exact[tb.facet_first[g] + k] = plane.at((*tb.facet_st[g])[k]);
      return;
    }
  }
  throw std::invalid_argument(
      "perturb_one_face_frame: no face in face coordinates is the image of another face");
}

} // namespace symmesh::gen::surface3
