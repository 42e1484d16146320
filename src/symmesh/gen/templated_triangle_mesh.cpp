// Algorithm 5.5/5.6 (spec/generation.md#alg-5-6). Instantiated for the rationals (Epeck's FT)
// and for K_m through Lazy_exact_nt<Cyclotomic>, like `symmesh check`.
#include "symmesh/gen/templated_triangle_mesh.h"

#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/line_mesh_conformity.h"
#include "symmesh/core/slice_of_copies.h"
#include "symmesh/gen/generation_support.h"
#include "symmesh/gen/gmsh_mesher.h"
#include "symmesh/gen/interface_merging.h"
#include "symmesh/gen/pipeline_stages.h"
#include "symmesh/gen/region_templates.h"
#include "symmesh/gen/rotation_order.h"
#include "symmesh/gen/shared_vertex_bookkeeping.h"
#include "symmesh/gen/symmetry_copies.h"
#include "symmesh/gen/triangle_mesher.h"
#include "symmesh/mesh/union_find.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <CGAL/Lazy_exact_nt.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <cstdint>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <tuple>

#include <sys/resource.h>

namespace symmesh::gen {
namespace {
using support::Clock;
using support::exact_from_double;
using support::LazyCyclotomic;
using support::minor_faults;
using support::rounded;
using support::seconds_since;
using support::SvbCandidate;
using support::SvbPairs;

/// Triangles Mesh_2 makes per size² of area (spec/generation.md#cell-estimate).
constexpr double kTriangleAreaPerSize2 = 0.2;

/// Exact area of a geometry template's carrier: the sum of its triangles' areas.
template <class FT>
FT carrier_area(const core::ElementComplex<FT, 2>& c) {
  FT twice(0);
  for (const auto& e : c.elements) {
    if (e.dim() != 2) continue;
    const auto& a = c.points[e.v[0]];
    const auto& b = c.points[e.v[1]];
    const auto& d = c.points[e.v[2]];
    const FT o = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    twice += CGAL::is_negative(o) ? -o : o;
  }
  return twice / FT(2);
}

using support::FaceLine;
using support::parts_for;

/// Template t's boundary: the subdivision points (exact), and per edge face its line mesh, whose
/// k-th point is exactly a + (k/N)(b − a) (core::line_mesh_point); the mesher gets the points in
/// double: the subdivision points rounded from their exact values (rounded()), the interior
/// points interpolated in double between the rounded ends (within a few units of roundoff of the
/// exact points; conformity never depends on it, the SVB identifies them by index).
template <class FT>
struct TemplateBoundary {
  std::vector<core::Point<FT, 2>> exact_points; ///< exact coordinates of the subdivision points
  std::vector<FaceLine> lines;                  ///< per subdivision face (n = 0: not an edge)
  BoundaryInput input;
  std::vector<std::size_t> segment_face; ///< per input segment, its subdivision face
};

/// Every boundary point of the template exactly, in local ids (subdivision points, then the
/// interior points of each line mesh).
template <class FT>
std::vector<core::Point<FT, 2>> all_exact_points(const TemplateBoundary<FT>& tb) {
  auto out = tb.exact_points;
  for (const auto& line : tb.lines)
    for (std::size_t k = 1; k < line.n; ++k)
      out.push_back(
          core::line_mesh_point<FT>(tb.exact_points[line.a], tb.exact_points[line.b], k, line.n));
  return out;
}

/// `parts`: N per subdivision face when given (the sao refinement), else N from the size.
template <class FT>
TemplateBoundary<FT> line_meshes(const core::BoundarySubdivision<FT, 2>& sd, const FT& h2, double h,
                                 const std::vector<std::size_t>* parts = nullptr) {
  TemplateBoundary<FT> tb;
  tb.exact_points = sd.points;
  for (const auto& p : sd.points) tb.input.points.push_back({rounded(p[0]), rounded(p[1])});
  tb.lines.resize(sd.faces.size());
  for (std::size_t f = 0; f < sd.faces.size(); ++f) {
    const auto& face = sd.faces[f];
    if (face.dimension != 1) continue;
    FaceLine& line = tb.lines[f];
    line.a = face.vertices[0];
    line.b = face.vertices[1];
    line.n = parts ? (*parts)[f] : parts_for<FT, 2>(sd.points[line.a], sd.points[line.b], h2, h);
    line.first = tb.input.points.size();
    const auto a = tb.input.points[line.a], b = tb.input.points[line.b];
    std::size_t prev = line.a;
    for (std::size_t k = 1; k < line.n; ++k) {
      const double t = double(k) / double(line.n);
      tb.input.points.push_back({a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t});
      tb.input.segments.push_back({prev, tb.input.points.size() - 1});
      tb.segment_face.push_back(f);
      prev = tb.input.points.size() - 1;
    }
    tb.input.segments.push_back({prev, line.b});
    tb.segment_face.push_back(f);
  }
  return tb;
}

/// The (from, to) vertex pairs of one template boundary mapping, from its face-to-face action.
template <class FT>
std::vector<std::pair<mesh::IndexType, mesh::IndexType>>
mapping_pairs(const core::BoundaryPatchPartition<FT, 2>& bpp, std::size_t letter,
              const std::vector<TemplateBoundary<FT>>& boundaries) {
  const auto& m = bpp.mappings[letter];
  SvbPairs pairs;
  support::vertex_and_line_pairs<FT, 2>(bpp, letter, boundaries[m.from_template()].lines,
                                        boundaries[m.to_template()].lines, pairs);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

using support::rotation_order;

using support::Symmetry;
using support::symmetry_copies;

/// The mesh template's boundary edges (edges of exactly one triangle) are exactly the line
/// mesh's segments: then bnd(X_i) is the line mesh, with its exact points. Combinatorial only.
bool boundary_is_line_mesh(const mesh::Mesh& m, const BoundaryInput& in, std::string* why) {
  // Sorted edge keys rather than a map: a template has up to millions of triangles.
  const auto key = [](std::size_t a, std::size_t b) {
    return (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
  };
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * m.cell_count());
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    const auto* v = m.cell(c);
    for (int k = 0; k < 3; ++k)
      edges.push_back(key(std::size_t(v[k]), std::size_t(v[(k + 1) % 3])));
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::uint64_t> boundary, segments;
  for (std::size_t k = 0; k < edges.size();) {
    std::size_t run = k;
    while (run < edges.size() && edges[run] == edges[k]) ++run;
    if (run - k == 1) boundary.push_back(edges[k]);
    k = run;
  }
  for (const auto& s : in.segments) segments.push_back(key(s[0], s[1]));
  std::sort(segments.begin(), segments.end());
  if (boundary == segments) return true;
  if (why)
    *why = "the mesh template's boundary (" + std::to_string(boundary.size()) +
           " edges) is not its line mesh (" + std::to_string(segments.size()) + " segments)";
  return false;
}

/// Lemma 4.2, exactly, on the templates' boundary complexes (spec/lemmas.md#lemma-4-2-boundary):
/// the instances' interiors are disjoint (checked before meshing), so every non-conformity of
/// AT lies between transformed boundary elements. Each boundary complex is the uniform line mesh
/// of the subdivision faces, after checking that the mesher kept it as the template's boundary;
/// the check then runs face pair by face pair (spec/lemmas.md#lemma-4-2-line-meshes).
/// `rotations` > 0: x was checked to be invariant under its rotation of that order
/// (rotation_order), so only the pairs of a copy 0 and a copy k <= n/2 are decided
/// (spec/lemmas.md#lemma-4-2-rotational).
template <class FT>
core::Lemma42Verdict certify(const core::TemplatedStructure<FT, 2>& x,
                             const std::vector<TemplateBoundary<FT>>& boundaries,
                             const mesh::TemplatedMesh& tm, std::size_t rotations) {
  core::LineMeshStructure<FT> lines;
  lines.instances = x.instances;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    const auto& b = boundaries[i];
    std::string why;
    if (!boundary_is_line_mesh(tm.templates[i].mesh, b.input, &why)) {
      core::Lemma42Verdict v;
      v.holds = false;
      v.a = v.b = core::InstanceId{i, 0};
      v.detail = "template '" + x.templates[i].name + "': " + why;
      return v;
    }
    core::UniformLineMesh<FT> t;
    t.points = b.exact_points;
    for (const auto& line : b.lines)
      if (line.n > 0) t.faces.push_back({core::VertexId(line.a), core::VertexId(line.b), line.n});
    lines.templates.push_back(std::move(t));
  }
  return core::check_line_mesh_conformity(lines, rotations);
}

/// The smallest angle of a template's region at a boundary vertex (the sum of the angles its
/// triangles have there), with the template and the vertex. Any triangulation of the template
/// keeps the vertex and splits that angle among its triangles, so one of them has an angle no
/// larger: no method can meet a --min-angle above it (spec/generation.md#sao).
struct InputAngle {
  double degrees = 180;
  std::size_t template_index = 0;
  double x = 0, y = 0;
};

template <class FT>
InputAngle smallest_input_angle(const core::TemplatedStructure<FT, 2>& x) {
  InputAngle best;
  for (std::size_t t = 0; t < x.templates.size(); ++t) {
    const auto& m = x.templates[t].mesh;
    std::vector<std::array<double, 2>> p;
    for (const auto& q : m.points) p.push_back({rounded(q[0]), rounded(q[1])});
    std::vector<double> angle(p.size(), 0);
    std::map<std::pair<core::VertexId, core::VertexId>, int> edge_use;
    for (const auto& c : m.cells()) {
      if (c.dim() != 2) continue;
      for (int k = 0; k < 3; ++k) {
        const auto v = c.v[k], a = c.v[(k + 1) % 3], b = c.v[(k + 2) % 3];
        const double ux = p[a][0] - p[v][0], uy = p[a][1] - p[v][1];
        const double wx = p[b][0] - p[v][0], wy = p[b][1] - p[v][1];
        angle[v] += std::abs(std::atan2(ux * wy - uy * wx, ux * wx + uy * wy));
        ++edge_use[std::minmax(a, b)];
      }
    }
    for (const auto& [e, uses] : edge_use) {
      if (uses != 1) continue;
      for (const auto v : {e.first, e.second}) {
        const double deg = angle[v] * 180 / std::numbers::pi;
        if (deg < best.degrees) best = {deg, t, p[v][0], p[v][1]};
      }
    }
  }
  return best;
}

/// spec/generation.md#sao: mesh every template with the full Delaunay refinement (which may
/// split boundary segments); wherever it split a segment of face f, double N on every face
/// related to f by a template boundary mapping (so mapped faces keep equal N and the old split
/// points stay), and mesh again, until no template needs a boundary split. Then every triangle
/// meets the shape criterion and the boundaries are the line meshes, as Algorithm 5.6 needs.
/// Throws MeshingError after kMaxRounds rounds, or once a face would be refined more than
/// kMaxRefinement times as finely as at the start. (The re-split line meshes of the later rounds
/// are timed with the meshing.)
template <class FT>
std::vector<TriangleMeshOutput> refine_line_meshes_for_angle(
    const core::BoundaryPatchPartition<FT, 2>& bpp, const FT& h2, const GenerationOptions& o,
    std::vector<TemplateBoundary<FT>>& boundaries, const std::string& smallest_angle) {
  constexpr int kMaxRounds = 12;
  // Next to an input angle below 60° Delaunay refinement grades towards the corner without end
  // (every doubling is met by a further split there), and each doubling of a whole face makes the
  // templates' meshes larger; a face refined 32 times as finely ends the rounds.
  constexpr std::size_t kMaxRefinement = 32;
  const std::size_t nt = boundaries.size();
  std::vector<std::size_t> offset(nt + 1, 0);
  for (std::size_t t = 0; t < nt; ++t) offset[t + 1] = offset[t] + boundaries[t].lines.size();
  mesh::UnionFind classes(offset[nt]);
  for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
    const auto& m = bpp.mappings[l];
    if (m.whole_boundary) continue;
    for (auto [f, g] : bpp.letter_action[l])
      classes.unite(offset[m.from_template()] + f, offset[m.to_template()] + g);
  }
  std::vector<std::vector<std::size_t>> parts(nt);
  for (std::size_t t = 0; t < nt; ++t)
    for (const auto& line : boundaries[t].lines) parts[t].push_back(line.n);
  const auto initial_parts = parts;
  for (int round = 1;; ++round) {
    std::vector<TriangleMeshOutput> out;
    std::vector<bool> refine(offset[nt], false);
    std::size_t split = 0;
    for (std::size_t t = 0; t < nt; ++t) {
      MeshingParameters p;
      p.size = o.size;
      p.min_angle_deg = o.min_angle_deg;
      p.report_boundary_splits = true;
      out.push_back(mesh_domain_2(boundaries[t].input, p));
      for (std::size_t s : out.back().split_segments) {
        refine[classes.find(offset[t] + boundaries[t].segment_face[s])] = true;
        ++split;
      }
    }
    if (split == 0) return out;
    if (round == kMaxRounds)
      throw MeshingError("--min-angle " + std::to_string(o.min_angle_deg) +
                         ": the mesher still splits boundary segments after " +
                         std::to_string(kMaxRounds) + " refinements of the line meshes");
    std::size_t faces = 0;
    for (std::size_t t = 0; t < nt; ++t) {
      for (std::size_t f = 0; f < parts[t].size(); ++f)
        if (parts[t][f] > 0 && refine[classes.find(offset[t] + f)]) {
          if (parts[t][f] >= kMaxRefinement * initial_parts[t][f]) {
            const auto& line = boundaries[t].lines[f];
            const auto& pts = boundaries[t].input.points;
            std::ostringstream m;
            m << std::setprecision(4) << "--min-angle " << o.min_angle_deg
              << ": the mesher still splits the boundary segment (" << pts[line.a][0] << ", "
              << pts[line.a][1] << ")-(" << pts[line.b][0] << ", " << pts[line.b][1]
              << ") after its line mesh was made " << kMaxRefinement
              << " times finer; Delaunay refinement grades without end towards input angles "
                 "below 60° ("
              << smallest_angle << ")";
            throw MeshingError(m.str());
          }
          parts[t][f] *= 2;
          ++faces;
        }
      boundaries[t] = line_meshes<FT>(bpp.subdivisions[t], h2, o.size, &parts[t]);
    }
    if (o.progress)
      o.progress->message("sao: round " + std::to_string(round) + ": the mesher split " +
                          std::to_string(split) + " boundary segments; " + std::to_string(faces) +
                          " faces split twice as finely");
  }
}

template <class FT>
GenerationResult generate(const core::TemplatedStructure<FT, 2>& x, const GenerationOptions& o,
                          Symmetry symmetry = Symmetry::none, bool refine_for_angle = false) {
  const bool rotational = symmetry == Symmetry::rotational;
  const bool group = symmetry == Symmetry::reflective || symmetry == Symmetry::combined;
  support::input_stage(x, o, "Algorithm 5.6");
  std::string smallest_angle;
  if (refine_for_angle) {
    const auto a = smallest_input_angle(x);
    std::ostringstream where;
    where << std::setprecision(4) << "template '" << x.templates[a.template_index].name
          << "' has an angle of " << a.degrees << "° at (" << a.x << ", " << a.y << ")";
    smallest_angle = where.str();
    if (a.degrees < o.min_angle_deg) {
      std::ostringstream m;
      m << "--method sao --min-angle " << o.min_angle_deg << ": " << smallest_angle
        << ", so every triangulation of it has a triangle with an angle that small; lower "
           "--min-angle, or use another method (the report counts the triangles below it)";
      throw std::invalid_argument(m.str());
    }
  }
  // The rotational check comes first (timed with the BPP, whose shortcut it licenses): it lets
  // Eq. 4.2 be checked up to the rotation too.
  std::size_t rotations = 0;
  double symmetry_seconds = 0;
  const long faults_before_bpp = minor_faults();
  if (rotational) {
    const auto ts = Clock::now();
    std::string reason;
    rotations = rotation_order(x, reason);
    if (rotations == 0)
      throw std::invalid_argument("--method rotational: not a rotational slice structure: " +
                                  reason);
    symmetry_seconds = seconds_since(ts);
  }
  const long faults_symmetry = minor_faults() - faults_before_bpp;
  const auto say = [&](const std::string& s) {
    if (o.progress) o.progress->message(s);
  };
  const auto stage = [&](const std::string& name, std::size_t total, const std::string& unit) {
    if (o.progress) o.progress->stage(name, total, unit);
  };
  stage("instance overlap (Eq. 4.2)", 0, "");
  if (const auto overlap = core::find_instance_overlap_by_slices(x, rotations))
    throw std::invalid_argument(core::overlap_message(*overlap));
  GenerationResult r;
  auto t0 = Clock::now(); // the copies' preparation is timed with the BPP
  long f0 = minor_faults();
  auto& faults = r.timings.page_faults;
  core::TemplatedStructure<FT, 2> two_copies;
  if (rotational) {
    // Algorithm 6.2: the slice's two half-lines are all the BPP needs; the first two rotated
    // copies show both (every other neighbouring pair is a rotation of theirs).
    two_copies.templates = x.templates;
    for (const auto& list : x.instances) two_copies.instances.push_back({list[0], list[1]});
  }
  std::size_t copies = 0;
  if (group) {
    // Algorithms 6.1/6.4/6.5: the copy 0 of every template is the positive part (a multi-region
    // geometry); its BPP makes the region interfaces conform, and the mirrors need nothing
    // (Lemma 6.1: the reflection fixes them pointwise).
    copies = symmetry_copies(x, symmetry).size();
    two_copies.templates = x.templates;
    for (const auto& list : x.instances) two_copies.instances.push_back({list[0]});
  }
  const auto bpp = support::boundary_patch_stage(rotational || group ? two_copies : x, o,
                                                 symmetry_seconds + seconds_since(t0),
                                                 faults_symmetry + minor_faults() - f0, r);

  stage("line meshes", 0, "");
  t0 = Clock::now();
  f0 = minor_faults();
  const FT h = exact_from_double<FT>(o.size);
  const FT h2 = h * h;
  std::vector<TemplateBoundary<FT>> boundaries;
  for (const auto& sd : bpp.subdivisions) boundaries.push_back(line_meshes<FT>(sd, h2, o.size));
  r.timings.line_meshes = seconds_since(t0);
  faults.line_meshes = minor_faults() - f0;

  t0 = Clock::now();
  f0 = minor_faults();
  std::vector<TriangleMeshOutput> meshed;
  std::size_t estimated = 0;
  for (const auto& t : x.templates)
    estimated +=
        std::size_t(rounded(carrier_area(t.mesh)) / (kTriangleAreaPerSize2 * o.size * o.size));
  stage("template meshing", estimated, "triangles (total estimated)");
  if (refine_for_angle) {
    meshed = refine_line_meshes_for_angle(bpp, h2, o, boundaries,
                                          smallest_angle); // rounds: timed as meshing
  } else {
    std::size_t done = 0;
    for (const auto& b : boundaries) {
      MeshingParameters p;
      p.size = o.size;
      p.min_angle_deg = o.min_angle_deg;
      if (o.progress) p.on_progress = [&](std::size_t n) { o.progress->set_done(done + n); };
      meshed.push_back(mesh_domain_2(b.input, p));
      done += meshed.back().triangles.size();
      if (o.progress) o.progress->set_done(done);
    }
  }
  auto& tm = r.templated.templated;
  tm.point_dimension = 2;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    mesh::MeshTemplate t;
    t.mesh = triangle_mesh_of(meshed[i]);
    support::add_instances<2>(t, x.instances[i], tm);
    say("template " + std::to_string(i + 1) + "/" + std::to_string(x.templates.size()) + " ('" +
        x.templates[i].name + "'): " + std::to_string(t.mesh.cell_count()) + " triangles");
    tm.templates.push_back(std::move(t));
  }
  r.timings.template_meshing = seconds_since(t0);
  faults.template_meshing = minor_faults() - f0;

  stage("shared vertex bookkeeping", 0, "");
  t0 = Clock::now();
  f0 = minor_faults();
  auto candidates = support::svb_candidates<FT, 2>(
      x, bpp, [&](std::size_t l) { return mapping_pairs(bpp, l, boundaries); }, rotations, copies);
  std::vector<std::size_t> boundary_vertices;
  for (const auto& b : boundaries) boundary_vertices.push_back(b.input.points.size());
  if (group) {
    std::vector<std::vector<core::Point<FT, 2>>> points;
    for (const auto& b : boundaries) points.push_back(all_exact_points(b));
    support::copy_candidates<FT, 2>(x, points, candidates);
  }
  support::shared_vertex_bookkeeping<FT, 2>(x, boundary_vertices, std::move(candidates),
                                            r.templated);
  r.timings.svb = seconds_since(t0);
  faults.svb = minor_faults() - f0;

  support::certificate_stage(o, r, [&] { return certify(x, boundaries, tm, rotations); });
  return r;
}

using support::as_region_templates;

/// The Gmsh peer (spec/generation.md#gmsh): the regions of AT (exact, merged by exact point
/// equality) rounded once and meshed by Gmsh as a whole; one template per region, instanced
/// once, with the nodes Gmsh shares between regions as the SVB. Gmsh is not certified in exact
/// arithmetic: `lemma_4_2_holds` states that every region boundary edge is matched node for node
/// by a neighbouring region or lies on the outer boundary (combinatorial).
template <class FT>
GenerationResult generate_gmsh(const core::TemplatedStructure<FT, 2>& x,
                               const GenerationOptions& o) {
  support::input_stage(x, o, "");
  const auto whole = as_region_templates(x);
  PlanarRegions in;
  std::map<core::Point<FT, 2>, std::size_t, core::PointLess<FT, 2>> index;
  std::map<std::pair<std::size_t, std::size_t>, int> edge_use;
  std::vector<core::Point<FT, 2>> exact;
  std::vector<std::vector<std::array<std::size_t, 2>>> raw(whole.templates.size());
  for (std::size_t t = 0; t < whole.templates.size(); ++t) {
    const auto bnd = core::mesh_boundary(whole.templates[t].mesh);
    for (const auto& e : bnd.elements) {
      if (e.dim() != 1) continue;
      std::array<std::size_t, 2> ends{};
      for (int k = 0; k < 2; ++k) {
        const auto& p = bnd.points[e.v[k]];
        auto [it, inserted] = index.emplace(p, in.points.size());
        if (inserted) {
          in.points.push_back({rounded(p[0]), rounded(p[1])});
          exact.push_back(p);
        }
        ends[std::size_t(k)] = it->second;
      }
      raw[t].push_back(ends);
    }
  }
  // A region's corner can lie inside a neighbour's boundary edge (a T-junction): that edge is
  // split there (exact test), or Gmsh would put two nodes at the corner, one on each curve.
  for (std::size_t t = 0; t < whole.templates.size(); ++t) {
    PlanarRegions::Region region;
    region.id = whole.instances[t][0].region;
    for (const auto [a, b] : raw[t]) {
      std::vector<std::pair<FT, std::size_t>> inner;
      const auto& pa = exact[a];
      const auto& pb = exact[b];
      const double lo[2] = {std::min(in.points[a][0], in.points[b][0]),
                            std::min(in.points[a][1], in.points[b][1])};
      const double hi[2] = {std::max(in.points[a][0], in.points[b][0]),
                            std::max(in.points[a][1], in.points[b][1])};
      for (std::size_t v = 0; v < exact.size(); ++v) {
        const auto& q = in.points[v];
        // The rounded box, widened, only skips points far from the segment.
        const double slack = 1e-9 * (1 + hi[0] - lo[0] + hi[1] - lo[1]);
        if (v == a || v == b || q[0] < lo[0] - slack || q[0] > hi[0] + slack ||
            q[1] < lo[1] - slack || q[1] > hi[1] + slack)
          continue;
        if (core::point_on_segment<FT, 2>(pa, pb, exact[v]))
          inner.emplace_back(
              (exact[v][0] - pa[0]) * (pb[0] - pa[0]) + (exact[v][1] - pa[1]) * (pb[1] - pa[1]), v);
      }
      std::sort(inner.begin(), inner.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      std::size_t from = a;
      for (const auto& [along, v] : inner) {
        region.edges.push_back({from, v});
        from = v;
      }
      region.edges.push_back({from, b});
    }
    for (const auto& e : region.edges) ++edge_use[std::minmax(e[0], e[1])];
    in.regions.push_back(std::move(region));
  }
  GenerationResult r;
  const auto t0 = Clock::now();
  const long f0 = minor_faults();
  if (o.progress) o.progress->stage("gmsh meshing", 0, "");
  const auto g = mesh_with_gmsh(in, o.size);
  r.timings.template_meshing = seconds_since(t0);
  r.timings.page_faults.template_meshing = minor_faults() - f0;
  auto& tm = r.templated.templated;
  tm.point_dimension = 2;
  std::vector<std::map<std::size_t, mesh::IndexType>> local(in.regions.size());
  for (std::size_t t = 0; t < in.regions.size(); ++t) {
    mesh::MeshTemplate mt;
    mt.mesh.point_dimension = 2;
    for (const auto& tri : g.triangles[t]) {
      mesh::IndexType v[3];
      for (int k = 0; k < 3; ++k) {
        auto [it, inserted] = local[t].emplace(tri[std::size_t(k)], 0);
        if (inserted) it->second = mt.mesh.add_vertex(g.nodes[tri[std::size_t(k)]].data());
        v[k] = it->second;
      }
      mt.mesh.add_cell(mesh::ElementType::triangle, v);
    }
    orient_triangles_positively(mt.mesh);
    mt.transformation_indices.push_back(mesh::IndexType(tm.transformations.size()));
    mt.region_ids.push_back(mesh::RegionIdType(in.regions[t].id));
    mesh::Transformation identity;
    identity.matrix = {1, 0, 0, 1};
    identity.translation = {0, 0};
    tm.transformations.push_back(identity);
    if (o.progress)
      o.progress->message("gmsh: region " + std::to_string(in.regions[t].id) + ": " +
                          std::to_string(mt.mesh.cell_count()) + " triangles");
    tm.templates.push_back(std::move(mt));
  }
  // SVB from the shared node numbers, one table per pair of regions that share nodes.
  for (std::size_t a = 0; a < local.size(); ++a)
    for (std::size_t b = a + 1; b < local.size(); ++b) {
      std::vector<std::pair<mesh::IndexType, mesh::IndexType>> pairs;
      for (const auto& [node, la] : local[a])
        if (const auto it = local[b].find(node); it != local[b].end())
          pairs.emplace_back(la, it->second);
      if (pairs.empty()) continue;
      r.templated.identifications.push_back(
          {mesh::IndexType(a), mesh::IndexType(b), mesh::IndexType(r.templated.tables.size())});
      r.templated.tables.push_back({mesh::IndexType(a), mesh::IndexType(b), std::move(pairs)});
    }
  // Every input boundary edge of two regions must be split into the same nodes on both sides:
  // count the mesh boundary edges per region and match them by node numbers.
  std::map<std::pair<std::size_t, std::size_t>, int> mesh_boundary_use;
  for (std::size_t t = 0; t < g.triangles.size(); ++t) {
    std::map<std::pair<std::size_t, std::size_t>, int> count;
    for (const auto& tri : g.triangles[t])
      for (int k = 0; k < 3; ++k)
        ++count[std::minmax(tri[std::size_t(k)], tri[std::size_t((k + 1) % 3)])];
    for (const auto& [e, c] : count)
      if (c == 1) ++mesh_boundary_use[e];
  }
  std::size_t unmatched = 0, outer_inputs = 0;
  for (const auto& [e, c] : edge_use)
    if (c == 1) ++outer_inputs;
  std::size_t outer_mesh = 0;
  for (const auto& [e, c] : mesh_boundary_use) {
    if (c == 1) ++outer_mesh;
    if (c > 2) ++unmatched;
  }
  r.lemma_4_2_holds = unmatched == 0 && outer_mesh >= outer_inputs;
  if (!r.lemma_4_2_holds)
    r.lemma_4_2_failure = "Gmsh's region meshes do not share their interface nodes";
  return r;
}

// ----- sao: Section 6.3.2 (spec/generation.md#sao) --------------------------------------------

/// The carrier's boundary as one closed vertex cycle. Throws for a boundary that is not one
/// simple cycle.
template <class FT>
std::vector<core::Point<FT, 2>> boundary_cycle(const core::ElementComplex<FT, 2>& carrier) {
  const auto bnd = core::mesh_boundary(carrier);
  std::map<core::VertexId, std::vector<core::VertexId>> next;
  for (const auto& e : bnd.elements)
    if (e.dim() == 1) {
      next[e.v[0]].push_back(e.v[1]);
      next[e.v[1]].push_back(e.v[0]);
    }
  for (const auto& [v, around] : next)
    if (around.size() != 2)
      throw std::invalid_argument("--method sao: the slice's boundary is not one simple polygon");
  std::vector<core::VertexId> order{next.begin()->first};
  core::VertexId prev = order[0], cur = next.begin()->second[0];
  while (cur != order[0]) {
    order.push_back(cur);
    const auto& around = next[cur];
    const core::VertexId to = around[0] == prev ? around[1] : around[0];
    prev = cur;
    cur = to;
  }
  if (order.size() != next.size())
    throw std::invalid_argument("--method sao: the slice's boundary is not one simple polygon");
  std::vector<core::Point<FT, 2>> cycle;
  for (auto v : order) cycle.push_back(bnd.points[v]);
  return cycle;
}

/// An exact triangulation of a simple polygon by ear clipping (an ear: a convex corner whose
/// triangle holds no other polygon vertex, closed).
template <class FT>
core::ElementComplex<FT, 2> ear_triangulation(std::vector<core::Point<FT, 2>> polygon) {
  using core::detail::orientation_sign;
  FT twice_area = 0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const auto& a = polygon[k];
    const auto& b = polygon[(k + 1) % polygon.size()];
    twice_area += a[0] * b[1] - a[1] * b[0];
  }
  if (twice_area < 0) std::reverse(polygon.begin(), polygon.end());
  core::ElementComplex<FT, 2> c;
  c.points = polygon;
  std::vector<core::VertexId> left(polygon.size());
  for (std::size_t k = 0; k < left.size(); ++k) left[k] = core::VertexId(k);
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t k = 0; k < left.size() && !clipped; ++k) {
      const auto a = left[(k + left.size() - 1) % left.size()], b = left[k],
                 d = left[(k + 1) % left.size()];
      const auto &pa = polygon[a], &pb = polygon[b], &pd = polygon[d];
      if (orientation_sign<FT>(pa, pb, pd) <= 0) continue;
      const bool empty = std::none_of(left.begin(), left.end(), [&](core::VertexId v) {
        if (v == a || v == b || v == d) return false;
        const auto& q = polygon[v];
        return orientation_sign<FT>(pa, pb, q) >= 0 && orientation_sign<FT>(pb, pd, q) >= 0 &&
               orientation_sign<FT>(pd, pa, q) >= 0;
      });
      if (!empty) continue;
      c.elements.push_back(core::Simplex{a, b, d});
      left.erase(left.begin() + std::ptrdiff_t(k));
      clipped = true;
    }
    if (!clipped)
      throw std::invalid_argument("--method sao: the cut slice is not a simple polygon");
  }
  c.elements.push_back(core::Simplex{left[0], left[1], left[2]});
  for (auto& e : c.elements) {
    std::array<core::VertexId, 3> v{e.v[0], e.v[1], e.v[2]};
    std::sort(v.begin(), v.end());
    e = core::Simplex{v[0], v[1], v[2]};
  }
  c = core::face_completion(c);
  c.normalize();
  return c;
}

/// Section 6.3.2 on a rotational slice structure (one template, instances T_k = R^k ∘ T_0): the
/// slice has the rotation centre c as a vertex, with its two ray edges c-u and c-w, R' mapping
/// the first onto the ray of the second (R' = T_0^-1 ∘ T_1, the rotation in template
/// coordinates). The regular n-gon P with vertices R'^k(q), q the midpoint of c and u (so P's
/// vertices lie on the slice's rays, as the dissertation asks), is cut out: the centre template
/// P, instanced once by T_0, and the ring slice (the polygon with c replaced by q and R'(q)),
/// instanced like the slice.
/// Everything exact; throws std::invalid_argument naming what does not fit.
template <class FT>
core::TemplatedStructure<FT, 2> sao_cut(const core::TemplatedStructure<FT, 2>& x, std::size_t n) {
  using core::detail::orientation_sign;
  const auto fail = [](const std::string& why) {
    throw std::invalid_argument("--method sao: " + why);
  };
  if (x.templates.size() != 1) fail("cutting needs one slice template");
  const auto& t0 = x.instances[0][0].transformation;
  const auto t0_inv = t0.inverse();
  const auto rt = t0_inv * x.instances[0][1].transformation; // R' = T_0^-1 ∘ T_1
  // The centre: R'(c) = c, i.e. (I - A) c = b for R' = (A, b); I - A is invertible (R' != I).
  const auto& a = rt.matrix();
  const auto& b = rt.translation_part();
  const FT m00 = FT(1) - a[0][0], m01 = -a[0][1], m10 = -a[1][0], m11 = FT(1) - a[1][1];
  const FT det = m00 * m11 - m01 * m10;
  core::Point<FT, 2> c;
  c[0] = (b[0] * m11 - m01 * b[1]) / det;
  c[1] = (m00 * b[1] - m10 * b[0]) / det;
  const auto cycle = boundary_cycle(x.templates[0].mesh);
  const std::size_t k = std::size_t(std::find(cycle.begin(), cycle.end(), c) - cycle.begin());
  if (k == cycle.size()) fail("the rotation centre is not a vertex of the slice");
  // c's neighbours on the cycle: R' maps the ray edge c-u onto the ray of c-w, or the other way.
  const auto& before = cycle[(k + cycle.size() - 1) % cycle.size()];
  const auto& after = cycle[(k + 1) % cycle.size()];
  const auto midpoint = [&](const core::Point<FT, 2>& p) {
    core::Point<FT, 2> m;
    for (int d = 0; d < 2; ++d) m[d] = (c[d] + p[d]) / FT(2);
    return m;
  };
  bool forward = true; // q on c-after, R'(q) on c-before
  auto q = midpoint(after);
  auto rq = rt(q);
  if (!core::point_on_segment<FT, 2>(c, before, rq)) {
    forward = false;
    q = midpoint(before);
    rq = rt(q);
    if (!core::point_on_segment<FT, 2>(c, after, rq))
      fail("the rotation does not map the midpoint of one ray edge of the slice onto the other");
  }
  // The cut triangle (c, q, R'(q)) must hold no other part of the slice's boundary.
  for (std::size_t j = 0; j < cycle.size(); ++j) {
    const auto& e0 = cycle[j];
    const auto& e1 = cycle[(j + 1) % cycle.size()];
    if (e0 == c || e1 == c) continue;
    const auto inside = [&](const core::Point<FT, 2>& p) {
      return orientation_sign<FT>(c, q, p) >= 0 && orientation_sign<FT>(q, rq, p) >= 0 &&
             orientation_sign<FT>(rq, c, p) >= 0;
    };
    const bool crosses = orientation_sign<FT>(q, rq, e0) * orientation_sign<FT>(q, rq, e1) <= 0 &&
                         orientation_sign<FT>(e0, e1, q) * orientation_sign<FT>(e0, e1, rq) <= 0;
    if (inside(e0) || inside(e1) || crosses)
      fail("the centre polygon would cut the slice's boundary (edge " + std::to_string(j + 1) +
           ")");
  }
  std::vector<core::Point<FT, 2>> ring;
  for (std::size_t j = 0; j < cycle.size(); ++j) {
    if (j == k) {
      ring.push_back(forward ? rq : q);
      ring.push_back(forward ? q : rq);
    } else {
      ring.push_back(cycle[j]);
    }
  }
  std::vector<core::Point<FT, 2>> centre;
  for (std::size_t j = 0; j < n; ++j) centre.push_back(t0_inv(x.instances[0][j].transformation(q)));
  core::TemplatedStructure<FT, 2> out;
  out.templates.push_back({"centre", core::TemplateKind::geometry, ear_triangulation(centre)});
  out.instances.push_back({x.instances[0][0]});
  out.templates.push_back(
      {x.templates[0].name + " ring", core::TemplateKind::geometry, ear_triangulation(ring)});
  out.instances.push_back(x.instances[0]);
  return out;
}

using support::lazily;

template <class FT>
GenerationResult generate_by(const core::TemplatedStructure<FT, 2>& x, Method method,
                             const GenerationOptions& options) {
  std::string unused;
  if (method == Method::automatic) {
    // The most specialised method whose exact check passes (the cut of `symmesh cut` gives each
    // of them its input); bpp needs no symmetry.
    const auto is_group = [&](Symmetry kind) {
      try {
        symmetry_copies(x, kind);
        return true;
      } catch (const std::invalid_argument&) {
        return false;
      }
    };
    method = x.instances.empty()              ? Method::bpp
             : rotation_order(x, unused) > 0  ? Method::rotational
             : is_group(Symmetry::combined)   ? Method::combined
             : is_group(Symmetry::reflective) ? Method::reflective
                                              : Method::bpp;
  }
  GenerationResult r;
  switch (method) {
  case Method::rotational:
    r = generate(x, options, Symmetry::rotational);
    r.method = "rotational";
    break;
  case Method::reflective:
    r = generate(x, options, Symmetry::reflective);
    r.method = "reflective";
    break;
  case Method::combined:
    r = generate(x, options, Symmetry::combined);
    r.method = "combined";
    break;
  case Method::conventional:
    r = generate(as_region_templates(x), options);
    r.method = "conventional";
    break;
  case Method::gmsh:
    r = generate_gmsh(x, options);
    r.method = "gmsh";
    break;
  case Method::sao: {
    // A rotational slice is cut (Section 6.3.2); other structures (e.g. ngon-sao-n) are taken
    // as cut already. Either way the line meshes are refined until the angle holds.
    const std::size_t n = x.instances.size() == 1 ? rotation_order(x, unused) : 0;
    r = generate(n > 0 ? sao_cut(x, n) : x, options, Symmetry::none, true);
    r.method = "sao";
    break;
  }
  case Method::merge:
    r = generate_merge(x, options);
    r.method = "merge";
    break;
  case Method::automatic:
  case Method::bpp:
    r = generate(x, options);
    r.method = "bpp";
    break;
  }
  return r;
}
} // namespace

template <class FT>
CellEstimate estimate(const core::TemplatedStructure<FT, 2>& x, double size) {
  FT area(0);
  for (std::size_t i = 0; i < x.templates.size() && i < x.instances.size(); ++i)
    area += carrier_area(x.templates[i].mesh) * FT(int(x.instances[i].size()));
  CellEstimate e;
  e.measure = rounded(area);
  e.cells = e.measure / (kTriangleAreaPerSize2 * size * size);
  return e;
}

CellEstimate estimate_cells(const core::TemplatedStructure<Exact, 2>& x, double size) {
  return estimate(x, size);
}
CellEstimate estimate_cells(const core::TemplatedStructure<number::Cyclotomic, 2>& x, double size) {
  return estimate(lazily(x), size);
}

GenerationResult generate_triangle_mesh(const core::TemplatedStructure<Exact, 2>& x, Method method,
                                        const GenerationOptions& options) {
  return generate_by(x, method, options);
}
GenerationResult generate_triangle_mesh(const core::TemplatedStructure<number::Cyclotomic, 2>& x,
                                        Method method, const GenerationOptions& options) {
  return generate_by(lazily(x), method, options);
}

} // namespace symmesh::gen
