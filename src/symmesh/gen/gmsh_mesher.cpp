// The Gmsh peer baseline, built as the module libsymmesh_gmsh.so that gmsh_loader.cpp opens on
// first use — spec/generation.md#gmsh
#include "symmesh/gen/gmsh_mesher.h"

#include "symmesh/gen/triangle_mesher.h"

#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace symmesh::gen {
namespace {

using Loop = std::vector<std::size_t>; // vertex ids around a closed curve

/// Splits a region's boundary edges into closed curves; a vertex of degree other than 2 is a
/// pinched or open outline, which Gmsh's plane surfaces cannot take.
std::vector<Loop> closed_curves(const PlanarRegions::Region& r) {
  std::map<std::size_t, std::vector<std::size_t>> next;
  for (const auto& e : r.edges) {
    next[e[0]].push_back(e[1]);
    next[e[1]].push_back(e[0]);
  }
  for (const auto& [v, n] : next)
    if (n.size() != 2)
      throw MeshingError("Gmsh baseline: region " + std::to_string(r.id) + ": boundary vertex " +
                         std::to_string(v) + " has " + std::to_string(n.size()) +
                         " boundary edges (need 2)");
  std::map<std::size_t, bool> seen;
  std::vector<Loop> loops;
  for (const auto& [start, unused] : next) {
    if (seen[start]) continue;
    Loop loop{start};
    seen[start] = true;
    std::size_t prev = start, cur = next[start][0];
    while (cur != start) {
      loop.push_back(cur);
      seen[cur] = true;
      const auto& n = next[cur];
      const std::size_t to = n[0] == prev ? n[1] : n[0];
      prev = cur;
      cur = to;
    }
    loops.push_back(loop);
  }
  return loops;
}

double signed_area(const std::vector<std::array<double, 2>>& p, const Loop& l) {
  double a = 0;
  for (std::size_t k = 0; k < l.size(); ++k) {
    const auto& u = p[l[k]];
    const auto& v = p[l[(k + 1) % l.size()]];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return a / 2;
}

/// Even-odd test; the loops of one region are vertex-disjoint, so a vertex of one loop is never
/// on another.
bool inside(const std::vector<std::array<double, 2>>& p, const Loop& l, std::array<double, 2> q) {
  bool in = false;
  for (std::size_t k = 0, j = l.size() - 1; k < l.size(); j = k++) {
    const auto& a = p[l[k]];
    const auto& b = p[l[j]];
    if ((a[1] > q[1]) != (b[1] > q[1]) &&
        q[0] < (b[0] - a[0]) * (q[1] - a[1]) / (b[1] - a[1]) + a[0])
      in = !in;
  }
  return in;
}

/// Gmsh's last logged error, after it threw an exception of its own.
std::string last_gmsh_error() {
  std::string why;
  gmsh::logger::getLastError(why);
  return why.empty() ? std::string("Gmsh failed") : why;
}

/// Gmsh reports a failure by an exception of its own and its last logged error.
[[noreturn]] void throw_gmsh_error() {
  throw MeshingError("Gmsh baseline: " + last_gmsh_error());
}

/// Gmsh's API state is global: initialise on entry, finalise on every exit.
struct GmshSession {
  GmshSession() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::model::add("symmesh");
  }
  ~GmshSession() { gmsh::finalize(); }
};

} // namespace

GmshTriangles mesh_with_gmsh_in_module(const PlanarRegions& in, double size) {
  if (!(size > 0) || !std::isfinite(size)) throw MeshingError("Gmsh baseline: size must be > 0");
  GmshSession session;
  std::map<std::size_t, int> point_tag;
  std::map<std::pair<std::size_t, std::size_t>, int> line_tag; // (from, to) as created
  const auto point = [&](std::size_t v) {
    auto [it, inserted] = point_tag.emplace(v, 0);
    if (inserted)
      it->second = gmsh::model::geo::addPoint(in.points[v][0], in.points[v][1], 0, size);
    return it->second;
  };
  const auto signed_line = [&](std::size_t a, std::size_t b) {
    if (const auto it = line_tag.find({b, a}); it != line_tag.end()) return -it->second;
    auto [it, inserted] = line_tag.emplace(std::make_pair(a, b), 0);
    if (inserted) it->second = gmsh::model::geo::addLine(point(a), point(b));
    return it->second;
  };
  std::vector<std::vector<int>> surfaces(in.regions.size());
  try {
    for (std::size_t r = 0; r < in.regions.size(); ++r) {
      const auto loops = closed_curves(in.regions[r]);
      std::vector<int> loop_tag, depth(loops.size(), 0), parent(loops.size(), -1);
      for (const auto& l : loops) {
        std::vector<int> curve;
        for (std::size_t k = 0; k < l.size(); ++k)
          curve.push_back(signed_line(l[k], l[(k + 1) % l.size()]));
        loop_tag.push_back(gmsh::model::geo::addCurveLoop(curve));
      }
      for (std::size_t a = 0; a < loops.size(); ++a)
        for (std::size_t b = 0; b < loops.size(); ++b)
          if (a != b && inside(in.points, loops[b], in.points[loops[a][0]])) {
            ++depth[a];
            if (parent[a] < 0 ||
                std::abs(signed_area(in.points, loops[b])) <
                    std::abs(signed_area(in.points, loops[std::size_t(parent[a])])))
              parent[a] = int(b);
          }
      for (std::size_t a = 0; a < loops.size(); ++a) {
        if (depth[a] % 2) continue;
        std::vector<int> wires{loop_tag[a]};
        for (std::size_t h = 0; h < loops.size(); ++h)
          if (depth[h] == depth[a] + 1 && parent[h] == int(a)) wires.push_back(loop_tag[h]);
        surfaces[r].push_back(gmsh::model::geo::addPlaneSurface(wires));
      }
    }
    gmsh::model::geo::synchronize();
    gmsh::option::setNumber("Mesh.Algorithm", 5); // Delaunay (-algo del2d)
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::model::mesh::generate(2);
  } catch (const MeshingError&) {
    throw;
  } catch (...) {
    throw_gmsh_error();
  }
  GmshTriangles out;
  std::vector<std::size_t> tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
  std::map<std::size_t, std::size_t> index;
  for (std::size_t k = 0; k < tags.size(); ++k) {
    index[tags[k]] = out.nodes.size();
    out.nodes.push_back({coords[3 * k], coords[3 * k + 1]});
  }
  out.triangles.resize(in.regions.size());
  for (std::size_t r = 0; r < in.regions.size(); ++r)
    for (int s : surfaces[r]) {
      std::vector<std::size_t> elements, nodes;
      gmsh::model::mesh::getElementsByType(2, elements, nodes, s);
      for (std::size_t k = 0; k + 2 < nodes.size(); k += 3)
        out.triangles[r].push_back(
            {index.at(nodes[k]), index.at(nodes[k + 1]), index.at(nodes[k + 2])});
    }
  return out;
}

namespace {

/// Gmsh's own failure inside generate(3), as opposed to a check of ours; `why` is Gmsh's message.
struct GmshInternalError : MeshingError {
  explicit GmshInternalError(const std::string& w) : MeshingError("Gmsh baseline: " + w), why(w) {}
  std::string why;
};

/// The node tags of each discrete surface's triangles, by the regions it bounds (the second
/// `outside` for an outer boundary).
using SurfaceNodes = std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>>;

/// One Gmsh session: the discrete model of the surfaces, generate(3) with or without Gmsh's
/// optimizer, the tetrahedra read back. \p start: when the model building began (the time
/// measured is from there).
GmshTetrahedra mesh_discrete_volumes(const ClosedSurfaces& in, double size,
                                     const SurfaceNodes& surface_nodes, bool optimize,
                                     std::chrono::steady_clock::time_point start) {
  constexpr std::size_t outside = std::size_t(-1);
  GmshSession session;
  std::vector<int> volumes;
  try {
    std::vector<std::vector<int>> bounding(in.regions.size());
    std::vector<int> surfaces;
    for (const auto& [pair, nodes] : surface_nodes) {
      surfaces.push_back(gmsh::model::addDiscreteEntity(2));
      bounding[pair.first].push_back(surfaces.back());
      if (pair.second != outside) bounding[pair.second].push_back(surfaces.back());
    }
    // Node k of the input is tag k + 1, classified on its surface(s) by reclassifyNodes.
    std::vector<std::size_t> tags(in.points.size());
    std::vector<double> coords;
    coords.reserve(3 * in.points.size());
    for (std::size_t k = 0; k < in.points.size(); ++k) {
      tags[k] = k + 1;
      coords.insert(coords.end(), in.points[k].begin(), in.points[k].end());
    }
    gmsh::model::mesh::addNodes(2, surfaces.at(0), tags, coords);
    std::size_t k = 0;
    for (const auto& [pair, nodes] : surface_nodes)
      gmsh::model::mesh::addElementsByType(surfaces[k++], 2, {}, nodes); // 2: 3-node triangle
    gmsh::model::mesh::reclassifyNodes();
    gmsh::vectorpair volume_dim_tags;
    for (std::size_t r = 0; r < in.regions.size(); ++r) {
      volumes.push_back(gmsh::model::addDiscreteEntity(3, -1, bounding[r]));
      volume_dim_tags.emplace_back(3, volumes.back());
    }
    // A discrete volume is meshed only once it has a "geometry" (Gmsh's documented way:
    // createGeometry, which for a volume only marks it meshable). The surfaces get none, so their
    // triangles stay as given.
    gmsh::model::mesh::createGeometry(volume_dim_tags);
    gmsh::option::setNumber("Mesh.Algorithm3D", 1); // Delaunay (-algo del3d)
    gmsh::option::setNumber("Mesh.MeshSizeMax", size);
    // Keep the node tags: input point k stays tag k + 1 (Gmsh renumbers after meshing otherwise).
    gmsh::option::setNumber("Mesh.Renumber", 0);
    gmsh::option::setNumber("Mesh.Optimize", optimize ? 1 : 0);
    gmsh::model::mesh::generate(3);
  } catch (const MeshingError&) {
    throw;
  } catch (...) {
    throw GmshInternalError(last_gmsh_error());
  }
  GmshTetrahedra out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.nodes = in.points;
  std::vector<std::size_t> tags;
  std::vector<double> coords, parametric;
  gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
  // Tag -> node index: Gmsh numbers its own nodes after the input's (Mesh.Renumber = 0 keeps
  // them), so the tags are about dense.
  std::vector<std::size_t> index(tags.empty() ? 0
                                              : *std::max_element(tags.begin(), tags.end()) + 1);
  std::vector<bool> seen(in.points.size(), false);
  for (std::size_t k = 0; k < tags.size(); ++k) {
    const std::array<double, 3> q{coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]};
    if (tags[k] >= 1 && tags[k] <= in.points.size()) {
      if (q != in.points[tags[k] - 1])
        throw MeshingError("Gmsh baseline: Gmsh moved input point " + std::to_string(tags[k] - 1));
      seen[tags[k] - 1] = true;
      index[tags[k]] = tags[k] - 1;
      continue;
    }
    index[tags[k]] = out.nodes.size();
    out.nodes.push_back(q);
  }
  if (std::find(seen.begin(), seen.end(), false) != seen.end())
    throw MeshingError("Gmsh baseline: Gmsh dropped an input point");
  out.tetrahedra.resize(in.regions.size());
  for (std::size_t r = 0; r < in.regions.size(); ++r) {
    std::vector<std::size_t> elements, nodes;
    gmsh::model::mesh::getElementsByType(4, elements, nodes, volumes[r]); // 4: 4-node tetrahedron
    for (std::size_t k = 0; k + 3 < nodes.size(); k += 4)
      out.tetrahedra[r].push_back({index.at(nodes[k]), index.at(nodes[k + 1]),
                                   index.at(nodes[k + 2]), index.at(nodes[k + 3])});
  }
  return out;
}

} // namespace

GmshTetrahedra mesh_with_gmsh_3d_in_module(const ClosedSurfaces& in, double size) {
  const auto start = std::chrono::steady_clock::now();
  if (!(size > 0) || !std::isfinite(size)) throw MeshingError("Gmsh baseline: size must be > 0");
  if (in.regions.empty()) throw MeshingError("Gmsh baseline: no region to mesh");
  for (const auto& p : in.points)
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw MeshingError("Gmsh baseline: a boundary point is not finite");
  // The regions each triangle bounds (one: on the outer boundary; two: an interface), by its
  // sorted vertices; the triangle is handed to Gmsh once, as first given.
  struct Sides {
    std::array<std::size_t, 3> triangle;
    std::vector<std::size_t> regions;
  };
  std::map<std::array<std::size_t, 3>, Sides> sides;
  std::vector<std::array<std::size_t, 3>> order;
  for (std::size_t r = 0; r < in.regions.size(); ++r) {
    if (in.regions[r].triangles.empty())
      throw MeshingError("Gmsh baseline: region " + std::to_string(in.regions[r].id) +
                         " has no boundary triangles");
    for (const auto& t : in.regions[r].triangles) {
      for (std::size_t v : t)
        if (v >= in.points.size())
          throw MeshingError("Gmsh baseline: a boundary triangle names a missing point");
      auto key = t;
      std::sort(key.begin(), key.end());
      auto [it, fresh] = sides.emplace(key, Sides{t, {}});
      if (fresh) order.push_back(key);
      auto& rs = it->second.regions;
      if (std::find(rs.begin(), rs.end(), r) != rs.end() || rs.size() == 2)
        throw MeshingError("Gmsh baseline: a boundary triangle is listed twice by region " +
                           std::to_string(in.regions[r].id) + " or by three regions");
      rs.push_back(r);
    }
  }
  // One discrete surface per outer boundary of a region and per interface of two regions: the
  // volumes then share their interface surfaces, hence their nodes there. The surfaces' mesh is
  // the input triangles; a discrete surface without a parametrization is never remeshed.
  constexpr std::size_t outside = std::size_t(-1);
  SurfaceNodes surface_nodes;
  for (const auto& key : order) {
    const auto& s = sides.at(key);
    const auto pair = s.regions.size() == 1 ? std::make_pair(s.regions[0], outside)
                                            : std::make_pair(std::min(s.regions[0], s.regions[1]),
                                                             std::max(s.regions[0], s.regions[1]));
    auto& nodes = surface_nodes[pair];
    for (std::size_t v : s.triangle) nodes.push_back(v + 1); // Gmsh tags start at 1
  }
  // Gmsh's optimizer may fail on its own data structures (see gmsh_mesher.h); the peer then
  // falls back to the unoptimized Delaunay mesh and says so.
  try {
    return mesh_discrete_volumes(in, size, surface_nodes, true, start);
  } catch (const GmshInternalError& e) {
    auto out =
        mesh_discrete_volumes(in, size, surface_nodes, false, std::chrono::steady_clock::now());
    out.optimizer_failure = e.why;
    return out;
  }
}

} // namespace symmesh::gen

/// The module's entry points (looked up by gmsh_loader.cpp). Errors come back as text: no
/// exception crosses the module boundary.
extern "C" __attribute__((visibility("default"))) int
symmesh_mesh_with_gmsh(const symmesh::gen::PlanarRegions* in, double size,
                       symmesh::gen::GmshTriangles* out, std::string* error) noexcept {
  try {
    *out = symmesh::gen::mesh_with_gmsh_in_module(*in, size);
    return 0;
  } catch (const std::exception& e) {
    *error = e.what();
  } catch (...) {
    *error = "Gmsh failed";
  }
  return 1;
}

/// The 3D entry point, the same way (spec/generation.md#gmsh-3d).
extern "C" __attribute__((visibility("default"))) int
symmesh_mesh_with_gmsh_3d(const symmesh::gen::ClosedSurfaces* in, double size,
                          symmesh::gen::GmshTetrahedra* out, std::string* error) noexcept {
  try {
    *out = symmesh::gen::mesh_with_gmsh_3d_in_module(*in, size);
    return 0;
  } catch (const std::exception& e) {
    *error = e.what();
  } catch (...) {
    *error = "Gmsh failed";
  }
  return 1;
}
