/// Reading templated-structure JSON, part 5 (internal): 3D geometry templates given as a PLC —
/// planar, simple, closed, edge-manifold, embedded faces and the carrier tetrahedralization —
/// spec/input-format.md#plc
#pragma once
#include "symmesh/io/structure_json/polygons.h"

#include "symmesh/core/element_complex.h"
#include "symmesh/gen/carrier_tetrahedralization.h"
#include "symmesh/gen/triangle_mesher.h"

namespace symmesh::io::structure_json {

// ---------------------------------------------------------------------------------------------
// Faces (3D geometry templates given as a PLC): validation and the carrier tetrahedralization

/// The vertices of a template, pairwise distinct (exact comparison).
template <class FT, int D>
std::vector<core::Point<FT, D>> read_vertices(const json& vj, const std::string& vp) {
  expect_array(vj, vp, "an array of vertices");
  if (vj.empty()) fail(vp, "no vertices (a template must not be empty)");
  std::vector<core::Point<FT, D>> points;
  std::map<core::Point<FT, D>, std::size_t, core::PointLess<FT, D>> seen;
  for (std::size_t k = 0; k < vj.size(); ++k) {
    points.push_back(get_point<FT, D>(vj[k], at(vp, k)));
    auto [it, inserted] = seen.emplace(points.back(), k);
    if (!inserted)
      fail(at(vp, k),
           "duplicate vertex (same coordinates as vertices[" + std::to_string(it->second) + "])");
  }
  return points;
}

/// One ring of a face: vertex indices into the template's vertices.
inline std::vector<std::size_t> read_index_ring(const json& j, const std::string& path,
                                                std::size_t nv) {
  expect_array(j, path, "an array of vertex indices");
  if (j.size() < 3)
    fail(path, "a polygon needs at least 3 vertices, got " + std::to_string(j.size()));
  std::vector<std::size_t> ring;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const json& v = j[k];
    if (!v.is_number_integer())
      fail(at(path, k), "a vertex index must be a JSON integer, got " + type_name(v) +
                            (v.is_number_float() ? " " + v.dump() : ""));
    if (v.is_number_unsigned() ? v.get<std::uint64_t>() >= nv : true)
      fail(at(path, k),
           "vertex index " + v.dump() + " out of range (" + std::to_string(nv) + " vertices)");
    ring.push_back(std::size_t(v.get<std::uint64_t>()));
  }
  return ring;
}

using core::cross;

/// One polygonal face (with holes): checked planar and simple, triangulated in its own plane.
/// The triangles index the template's vertices.
template <class FT>
std::vector<std::array<std::size_t, 3>> triangulate_face(const json& fj, const std::string& fp,
                                                         const std::vector<core::Point<FT, 3>>& x,
                                                         std::vector<bool>& used) {
  std::vector<std::vector<std::size_t>> ids;
  std::vector<std::string> paths;
  if (fj.is_array()) {
    ids.push_back(read_index_ring(fj, fp, x.size()));
    paths.push_back(fp);
  } else {
    expect_object(fj, fp,
                  "a face: an array of vertex indices or {\"polygon\": [...], \"holes\": [[...]]}");
    check_keys(fj, fp, {"polygon", "holes"});
    ids.push_back(read_index_ring(require(fj, "polygon", fp), dot(fp, "polygon"), x.size()));
    paths.push_back(dot(fp, "polygon"));
    if (fj.contains("holes")) {
      const std::string hp = dot(fp, "holes");
      expect_array(fj["holes"], hp, "an array of polygons");
      for (std::size_t k = 0; k < fj["holes"].size(); ++k) {
        ids.push_back(read_index_ring(fj["holes"][k], at(hp, k), x.size()));
        paths.push_back(at(hp, k));
      }
    }
  }
  std::map<std::size_t, std::string> seen;
  for (std::size_t r = 0; r < ids.size(); ++r)
    for (std::size_t k = 0; k < ids[r].size(); ++k) {
      auto [it, inserted] = seen.emplace(ids[r][k], at(paths[r], k));
      if (!inserted)
        fail(at(paths[r], k), "vertex " + std::to_string(ids[r][k]) +
                                  " appears twice in the face (also " + it->second +
                                  "; polygons are closed implicitly)");
      used[ids[r][k]] = true;
    }
  // The plane: the first two non-parallel edge directions from the first vertex.
  const auto& outer = ids[0];
  const core::Point<FT, 3>& p0 = x[outer[0]];
  core::Point<FT, 3> n;
  bool has_plane = false;
  for (std::size_t k = 2; k < outer.size() && !has_plane; ++k) {
    n = cross(x[outer[1]] - p0, x[outer[k]] - p0);
    has_plane = n[0] != FT(0) || n[1] != FT(0) || n[2] != FT(0);
  }
  if (!has_plane) fail(fp, "the face has zero area (its vertices are collinear)");
  for (std::size_t r = 0; r < ids.size(); ++r)
    for (std::size_t k = 0; k < ids[r].size(); ++k)
      if (core::dot(n, x[ids[r][k]] - p0) != FT(0))
        fail(at(paths[r], k), "the face is not planar: vertex " + std::to_string(ids[r][k]) +
                                  " is off the plane of its first vertices");
  // Drop a coordinate the plane is not parallel to: the projection is one-to-one on the plane,
  // so simplicity, nesting and the triangulation carry over exactly.
  const int drop = n[0] != FT(0) ? 0 : (n[1] != FT(0) ? 1 : 2);
  std::vector<Ring<FT>> rings;
  std::vector<std::size_t> global;
  for (std::size_t r = 0; r < ids.size(); ++r) {
    Ring<FT> ring;
    ring.path = paths[r];
    for (std::size_t v : ids[r]) {
      core::Point<FT, 2> q;
      for (int d = 0, e = 0; d < 3; ++d)
        if (d != drop) q[e++] = x[v][d];
      ring.pts.push_back(q);
      global.push_back(v);
    }
    rings.push_back(std::move(ring));
  }
  auto triangles = triangulate_rings(rings, fp);
  for (auto& t : triangles)
    for (auto& v : t) v = global[v];
  return triangles;
}

/// vertices + faces: a closed polyhedral surface; the carrier is tetrahedralized from it.
template <class FT>
core::ElementComplex<FT, 3> read_faces(const json& tj, const std::string& tpath) {
  const std::string vp = dot(tpath, "vertices");
  const std::string fp = dot(tpath, "faces");
  gen::TriangulatedSurface<FT> surface;
  surface.points = read_vertices<FT, 3>(require(tj, "vertices", tpath), vp);
  const json& fj = require(tj, "faces", tpath);
  expect_array(fj, fp, "an array of faces");
  if (fj.size() < 4)
    fail(fp, "a closed surface needs at least 4 faces, got " + std::to_string(fj.size()));
  std::vector<bool> used(surface.points.size(), false);
  for (std::size_t f = 0; f < fj.size(); ++f)
    for (const auto& t : triangulate_face<FT>(fj[f], at(fp, f), surface.points, used)) {
      surface.triangles.push_back(t);
      surface.face.push_back(f);
    }
  for (std::size_t k = 0; k < used.size(); ++k)
    if (!used[k]) fail(at(vp, k), "vertex is not used by any face");
  if (const auto d = gen::find_surface_defect(surface)) fail(at(fp, d->face), d->what);
  try {
    return gen::carrier_tetrahedralization(surface);
  } catch (const gen::MeshingError& e) {
    fail(fp,
         std::string("no carrier tetrahedralization without a point on the surface: ") + e.what());
  }
}

} // namespace symmesh::io::structure_json
