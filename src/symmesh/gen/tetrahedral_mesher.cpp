// TetGen with the boundary kept, checked afterwards (spec/generation.md#mesher-3).
#include "symmesh/gen/tetrahedral_mesher.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tetgen.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <cstdint>
#include <limits>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace symmesh::gen {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

std::array<std::size_t, 3> sorted(std::array<std::size_t, 3> f) {
  std::sort(f.begin(), f.end());
  return f;
}

CGAL::Orientation orientation(const std::array<std::array<double, 3>, 4>& p) {
  const auto pt = [&](int k) {
    return K::Point_3(p[std::size_t(k)][0], p[std::size_t(k)][1], p[std::size_t(k)][2]);
  };
  return CGAL::orientation(pt(0), pt(1), pt(2), pt(3));
}

/// Swaps the last two vertices (c, d) of a negative tetrahedron x; a flat one is an error.
template <class Index>
void make_positive(const std::array<std::array<double, 3>, 4>& x, Index& c, Index& d,
                   const char* flat) {
  const auto o = orientation(x);
  if (o == CGAL::ZERO) throw MeshingError(flat);
  if (o == CGAL::NEGATIVE) std::swap(c, d);
}

/// Copies the surface into TetGen's input (arrays owned by tetgenio, freed by its destructor).
void fill_input(const SurfaceInput& s, tetgenio& in) {
  in.firstnumber = 0;
  in.numberofpoints = int(s.points.size());
  in.pointlist = new REAL[3 * s.points.size()];
  for (std::size_t v = 0; v < s.points.size(); ++v)
    for (int d = 0; d < 3; ++d) in.pointlist[3 * v + std::size_t(d)] = s.points[v][std::size_t(d)];
  in.numberoffacets = int(s.triangles.size());
  in.facetlist = new tetgenio::facet[s.triangles.size()];
  for (std::size_t f = 0; f < s.triangles.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    facet.numberofpolygons = 1;
    facet.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&facet.polygonlist[0]);
    facet.polygonlist[0].numberofvertices = 3;
    facet.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k)
      facet.polygonlist[0].vertexlist[k] = int(s.triangles[f][std::size_t(k)]);
  }
  if (!s.seeds.empty()) {
    in.numberofregions = int(s.seeds.size());
    in.regionlist = new REAL[5 * s.seeds.size()];
    for (std::size_t r = 0; r < s.seeds.size(); ++r) {
      for (int d = 0; d < 3; ++d)
        in.regionlist[5 * r + std::size_t(d)] = s.seeds[r].point[std::size_t(d)];
      in.regionlist[5 * r + 3] = s.seeds[r].region;
      in.regionlist[5 * r + 4] = -1; // no region-specific volume bound
    }
  }
}

void check_input(const SurfaceInput& s, const TetrahedralMeshingParameters& p) {
  if (!(p.size > 0) || !std::isfinite(p.size))
    throw std::invalid_argument("mesh size must be a positive number");
  if (!(p.radius_edge >= 1) || !std::isfinite(p.radius_edge))
    throw std::invalid_argument("radius-edge bound must be at least 1");
  if (!(p.min_dihedral_deg >= 0 && p.min_dihedral_deg < 70.5))
    throw std::invalid_argument("dihedral angle bound must be in [0, 70.5) degrees");
  std::set<std::array<double, 3>> seen;
  for (const auto& q : s.points) {
    if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      throw MeshingError("a boundary point is not finite");
    if (!seen.insert(q).second) {
      std::ostringstream at;
      at.precision(17);
      at << "two boundary points coincide at (" << q[0] << ", " << q[1] << ", " << q[2] << ")";
      throw MeshingError(at.str());
    }
  }
  for (const auto& t : s.triangles)
    for (std::size_t v : t)
      if (v >= s.points.size()) throw MeshingError("a boundary triangle names a missing point");
}
} // namespace

double volume_bound(double size) {
  return size * size * size / (6 * std::sqrt(2.0));
}

std::string tetgen_switches(const TetrahedralMeshingParameters& p, bool with_regions) {
  char dihedral[32] = "";
  if (p.min_dihedral_deg > 0) std::snprintf(dihedral, sizeof dihedral, "/%.6g", p.min_dihedral_deg);
  char buf[128];
  std::snprintf(buf, sizeof buf, "pYq%.6g%sa%.6g%szQ", p.radius_edge, dihedral,
                volume_bound(p.size), with_regions ? "A" : "");
  return buf;
}

namespace {
/// TetGen on `s` with `switches`, its output checked: input points kept in order, tetrahedra
/// positive, boundary = the input surface.
TetrahedralMeshOutput run_tetgen(const SurfaceInput& s, std::string switches) {
  tetgenio in, out;
  fill_input(s, in);
  tetgenbehavior behaviour;
  if (!behaviour.parse_commandline(switches.data()))
    throw std::logic_error("TetGen refused the switches " + switches);
  // TetGen 1.5.0's BRIO/Hilbert sort of the input points ends in an internal assertion (an abort,
  // not an exception) on some surfaces, e.g. the metal layer of the 8-TSV slice at size 0.1;
  // inserting the points in TetGen's own pseudo-random order (fixed seed) does not.
  behaviour.brio_hilbert = 0;
  try {
    tetrahedralize(&behaviour, &in, &out);
  } catch (int code) {
    throw MeshingError("TetGen failed (code " + std::to_string(code) +
                       "): the surface is not a valid closed PLC or cannot be kept");
  }
  TetrahedralMeshOutput m;
  if (out.numberofpoints < in.numberofpoints || out.numberofcorners != 4)
    throw MeshingError("TetGen dropped input points");
  for (int v = 0; v < out.numberofpoints; ++v)
    m.points.push_back({out.pointlist[3 * v], out.pointlist[3 * v + 1], out.pointlist[3 * v + 2]});
  for (std::size_t v = 0; v < s.points.size(); ++v)
    if (m.points[v] != s.points[v]) throw MeshingError("TetGen moved or reordered input points");
  const bool with_regions = !s.seeds.empty() && out.numberoftetrahedronattributes > 0;
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    std::array<std::size_t, 4> tet{};
    for (int k = 0; k < 4; ++k) tet[std::size_t(k)] = std::size_t(out.tetrahedronlist[4 * t + k]);
    std::array<std::array<double, 3>, 4> x{};
    for (int k = 0; k < 4; ++k) x[std::size_t(k)] = m.points[tet[std::size_t(k)]];
    make_positive(x, tet[2], tet[3], "TetGen made a flat tetrahedron");
    m.tetrahedra.push_back(tet);
    m.region.push_back(
        with_regions
            ? int(out.tetrahedronattributelist[std::size_t(t) *
                                               std::size_t(out.numberoftetrahedronattributes)])
            : 0);
  }
  if (const auto f = boundary_mismatch(s, m)) {
    std::ostringstream why;
    if (*f < s.triangles.size())
      why << "TetGen changed the boundary: input triangle " << *f << " (" << s.triangles[*f][0]
          << ", " << s.triangles[*f][1] << ", " << s.triangles[*f][2]
          << ") is not a face of the mesh (split or lost)";
    else
      why << "TetGen changed the boundary: the mesh has a boundary face that is no input "
             "triangle (a Steiner point on the boundary)";
    throw BoundaryChanged(why.str(), *f);
  }
  return m;
}
} // namespace

namespace {
/// Appends / reads back plain values through a byte buffer (the child-to-parent pipe).
template <class T>
void put(std::string& b, const T& v) {
  b.append(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class T>
T take(const std::string& b, std::size_t& at) {
  T v;
  if (at + sizeof v > b.size()) throw MeshingError("TetGen's result came back truncated");
  std::memcpy(&v, b.data() + at, sizeof v);
  at += sizeof v;
  return v;
}

/// run_tetgen in a child process. TetGen 1.5.0 ends some degenerate inputs (five cospherical,
/// coplanar points, for one) in an internal assertion — an abort of the whole process, not an
/// exception. In a child, an abort becomes a MeshingError here, so no input ever crashes the
/// command. The child sends the checked mesh, or the error it threw, through a pipe.
TetrahedralMeshOutput run_tetgen_guarded(const SurfaceInput& s, const std::string& switches) {
  int fd[2];
  if (pipe(fd) != 0) return run_tetgen(s, switches);
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    close(fd[0]);
    close(fd[1]);
    return run_tetgen(s, switches);
  }
  if (pid == 0) {
    close(fd[0]);
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) dup2(null, 2); // TetGen's assertion text is not the command's message
    std::string b;
    try {
      const auto m = run_tetgen(s, switches);
      put(b, char(0));
      put(b, m.points.size());
      for (const auto& q : m.points) put(b, q);
      put(b, m.tetrahedra.size());
      for (const auto& t : m.tetrahedra) put(b, t);
      for (int r : m.region) put(b, r);
    } catch (const BoundaryChanged& e) {
      put(b, char(2));
      put(b, e.triangle);
      b += e.what();
    } catch (const std::exception& e) {
      put(b, char(1));
      b += e.what();
    }
    for (std::size_t at = 0; at < b.size();) {
      const auto n = write(fd[1], b.data() + at, b.size() - at);
      if (n <= 0) break;
      at += std::size_t(n);
    }
    close(fd[1]);
    _exit(0);
  }
  close(fd[1]);
  std::string b;
  char chunk[65536];
  for (;;) {
    const auto n = read(fd[0], chunk, sizeof chunk);
    if (n <= 0) break;
    b.append(chunk, std::size_t(n));
  }
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || b.empty())
    throw MeshingError("TetGen aborted on this surface (an internal assertion of TetGen 1.5 on "
                       "degenerate, e.g. cospherical and coplanar, points)");
  std::size_t at = 0;
  const char kind = take<char>(b, at);
  if (kind == 2) {
    const auto triangle = take<std::size_t>(b, at);
    throw BoundaryChanged(b.substr(at), triangle);
  }
  if (kind == 1) throw MeshingError(b.substr(at));
  TetrahedralMeshOutput m;
  m.points.resize(take<std::size_t>(b, at));
  for (auto& q : m.points) q = take<std::array<double, 3>>(b, at);
  m.tetrahedra.resize(take<std::size_t>(b, at));
  for (auto& t : m.tetrahedra) t = take<std::array<std::size_t, 4>>(b, at);
  m.region.resize(m.tetrahedra.size());
  for (auto& r : m.region) r = take<int>(b, at);
  return m;
}
} // namespace

TetrahedralMeshOutput mesh_domain_3(const SurfaceInput& s, const TetrahedralMeshingParameters& p) {
  check_input(s, p);
  return run_tetgen_guarded(s, tetgen_switches(p, !s.seeds.empty()));
}

TetrahedralMeshOutput tetrahedralize_surface(const SurfaceInput& s) {
  check_input(s, TetrahedralMeshingParameters{1, 2});
  return run_tetgen_guarded(s, "pYzQ");
}

TetrahedralMeshOutput constrained_delaunay_tetrahedralization(const SurfaceInput& s) {
  check_input(s, TetrahedralMeshingParameters{1, 2});
  try {
    return run_tetgen_guarded(s, "pYzQO0");
  } catch (const MeshingError&) {
    // TetGen's abort on degenerate points depends on its insertion order: once more with the
    // points reversed (and the result numbered back).
  }
  const std::size_t n = s.points.size();
  SurfaceInput r = s;
  std::reverse(r.points.begin(), r.points.end());
  for (auto& t : r.triangles)
    for (auto& v : t) v = n - 1 - v;
  auto m = run_tetgen_guarded(r, "pYzQO0");
  std::reverse(m.points.begin(), m.points.begin() + std::ptrdiff_t(n));
  for (auto& t : m.tetrahedra)
    for (auto& v : t)
      if (v < n) v = n - 1 - v;
  return m;
}

std::optional<std::size_t> boundary_mismatch(const SurfaceInput& s,
                                             const TetrahedralMeshOutput& m) {
  // One sorted array of the 4T tetrahedron faces, not a map: a map node per face made this check
  // a tenth of template meshing (allocation and cache misses), and a whole-geometry run holds
  // ~4·10^7 faces. 32-bit vertex ids suffice, TetGen numbers points with int.
  if (m.points.size() > std::numeric_limits<std::uint32_t>::max())
    throw MeshingError("the mesh has more points than a face key holds");
  struct Face {
    std::array<std::uint32_t, 3> key;
    int region;
  };
  const auto key_of = [](const std::array<std::size_t, 3>& f) {
    const auto g = sorted(f);
    return std::array<std::uint32_t, 3>{std::uint32_t(g[0]), std::uint32_t(g[1]),
                                        std::uint32_t(g[2])};
  };
  std::vector<Face> faces;
  faces.reserve(4 * m.tetrahedra.size());
  for (std::size_t t = 0; t < m.tetrahedra.size(); ++t) {
    const auto& c = m.tetrahedra[t];
    const int r = t < m.region.size() ? m.region[t] : 0;
    for (int skip = 0; skip < 4; ++skip) {
      std::array<std::size_t, 3> f{};
      for (int k = 0, j = 0; k < 4; ++k)
        if (k != skip) f[std::size_t(j++)] = c[std::size_t(k)];
      faces.push_back({key_of(f), r});
    }
  }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) {
    return a.key < b.key || (a.key == b.key && a.region < b.region);
  });
  std::vector<std::array<std::uint32_t, 3>> input;
  input.reserve(s.triangles.size());
  for (const auto& t : s.triangles) {
    for (std::size_t v : t)
      if (v > std::numeric_limits<std::uint32_t>::max()) return &t - s.triangles.data();
    input.push_back(key_of(t));
  }
  const auto face_less = [](const Face& a, const std::array<std::uint32_t, 3>& k) {
    return a.key < k;
  };
  for (std::size_t f = 0; f < input.size(); ++f) {
    // An input triangle inside one region (a double-sided inner facet) is kept too.
    const auto it = std::lower_bound(faces.begin(), faces.end(), input[f], face_less);
    if (it == faces.end() || it->key != input[f]) return f;
  }
  std::sort(input.begin(), input.end());
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    const bool boundary = j - i == 1 || faces[i].region != faces[j - 1].region;
    if (boundary && !std::binary_search(input.begin(), input.end(), faces[i].key))
      return s.triangles.size();
    i = j;
  }
  return std::nullopt;
}

void orient_tetrahedra_positively(mesh::Mesh& m) {
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    if (m.cell_types[c] != mesh::ElementType::tetrahedron) continue;
    auto* v = m.cell_vertex_indices.data() + m.cell_vertex_index_offsets[c];
    std::array<std::array<double, 3>, 4> x{};
    for (int k = 0; k < 4; ++k) {
      const double* p = m.vertex(std::size_t(v[k]));
      x[std::size_t(k)] = {p[0], p[1], p[2]};
    }
    make_positive(x, v[2], v[3], "a tetrahedron of the mesh is flat");
  }
}

} // namespace symmesh::gen
