// Algorithm 5.7 (spec/generation.md#alg-5-7). Instantiated for the rationals (Epeck's FT) and for
// K_m through Lazy_exact_nt<Cyclotomic>, like the 2D path. The stages it shares with
// Algorithm 5.6 (the BPP, uniform line meshes, the SVB, the conventional input, rounding) come
// from the same headers; only the surface meshes and the mesher are 3D.
// The surface stage is in surface_meshes_3d.h, the certificate in certificate_3d.h.
#include "symmesh/gen/templated_tetrahedral_mesh.h"

#include "symmesh/gen/gmsh_mesher.h"
#include "symmesh/gen/interface_merging.h"
#include "symmesh/gen/template_meshing_3d.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <cmath>
#include <limits>

namespace symmesh::gen {
namespace {
using namespace surface3;

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
  // Local ids in arrays over the global vertices, not maps: with a map per region and a lookup
  // per vertex and region pair this bookkeeping took a quarter of a whole-geometry run, time
  // that the conventional baseline does not owe TetGen.
  constexpr mesh::IndexType none = std::numeric_limits<mesh::IndexType>::max();
  std::map<int, std::vector<std::size_t>> by_region;
  for (std::size_t c = 0; c < out.tetrahedra.size(); ++c) by_region[out.region[c]].push_back(c);
  auto& tm = r.templated.templated;
  tm = mesh::TemplatedMesh{};
  tm.point_dimension = 3;
  r.templated.tables.clear();
  r.templated.identifications.clear();
  std::vector<std::vector<mesh::IndexType>> local; // per region: global vertex -> local id
  for (const auto& [region, cells] : by_region) {
    mesh::MeshTemplate t;
    t.mesh.point_dimension = 3;
    std::vector<mesh::IndexType> ids_here(out.points.size(), none);
    for (std::size_t c : cells)
      for (std::size_t v : out.tetrahedra[c]) ids_here[v] = 0;
    for (std::size_t v = 0; v < ids_here.size(); ++v) // vertices in global order
      if (ids_here[v] != none) ids_here[v] = t.mesh.add_vertex(out.points[v].data());
    for (std::size_t c : cells) {
      mesh::IndexType v[4];
      for (int k = 0; k < 4; ++k) v[k] = ids_here[out.tetrahedra[c][std::size_t(k)]];
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
      for (std::size_t v = 0; v < out.points.size(); ++v)
        if (local[a][v] != none && local[b][v] != none)
          table.pairs.emplace_back(local[a][v], local[b][v]);
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
  p.min_dihedral_deg = o.tetgen_min_dihedral_deg;
  const auto out = surface3::mesh_and_repair(s, p, o, r);
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
  r.gmsh_optimizer_failure = g.optimizer_failure;
  if (o.progress && !g.optimizer_failure.empty())
    o.progress->message("Gmsh's optimizer failed (" + g.optimizer_failure +
                        "); the mesh is Gmsh's Delaunay without optimization");
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
/// `known_copies`: the copies of a group symmetry when the caller has them already (exact, from
/// support::symmetry_copies), else they are computed here.
template <class FT>
GenerationResult generate_3(const core::TemplatedStructure<FT, 3>& x, const GenerationOptions& o,
                            Symmetry symmetry = Symmetry::none, Whole whole = Whole::no,
                            std::vector<core::RigidTransformation<FT, 3>> known_copies = {}) {
  const bool rotational = symmetry == Symmetry::rotational;
  const bool group = symmetry == Symmetry::reflective || symmetry == Symmetry::combined;
  support::input_stage(x, o, "Algorithm 5.7");
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
  bool copy_zero_in_slice = false; // decided once: both checks below use it
  core::TemplatedStructure<FT, 3> two_copies;
  if (rotational) {
    std::string reason;
    rotations = support::rotation_order(x, reason);
    if (rotations == 0)
      throw std::invalid_argument("--method rotational: not a rotational slice structure: " +
                                  reason);
    copy_zero_in_slice = core::slice_of_copy_zero(x, rotations).has_value();
    if (const auto contact = non_consecutive_contact(x, rotations, copy_zero_in_slice))
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
    if (known_copies.empty()) known_copies = support::symmetry_copies(x, symmetry);
    copies = known_copies.size();
    two_copies.templates = x.templates;
    for (const auto& list : x.instances) two_copies.instances.push_back({list[0]});
  }
  const double symmetry_seconds = seconds_since(t0);
  const long symmetry_faults = minor_faults() - f0;
  stage("instance overlap (Eq. 4.2)", 0, "");
  // A group of copies: every overlap is the image of one with copy 0 (copy_zero_overlap).
  const auto overlap =
      group ? support::copy_zero_overlap(x)
            : core::find_instance_overlap_by_slices(x, rotations, copy_zero_in_slice);
  if (overlap) throw std::invalid_argument(core::overlap_message(*overlap));
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
    boundaries.push_back(line_meshes_3<FT>(sd, h2, o.size, even, false));
  surface_meshes(x, bpp, classes, groups, boundaries, h2, o.size, o.min_angle_deg);
  if (o.perturb_one_surface_mesh) perturb_one_surface_mesh(bpp, boundaries);
  if (o.perturb_one_face_frame) perturb_one_face_frame(bpp, boundaries);
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
    std::vector<std::vector<support::AffinePointRange<FT, 3>>> ranges;
    for (const auto& b : boundaries) {
      points.push_back(b.exact);
      ranges.emplace_back();
      for (std::size_t f = 0; f < b.facet_plane.size(); ++f)
        if (b.facet_plane[f] && b.facet_count[f] > 0) {
          const auto& pl = *b.facet_plane[f];
          ranges.back().push_back(
              {b.facet_first[f], b.facet_count[f], {pl.p0, pl.p0 + pl.u, pl.p0 + pl.v}});
        }
    }
    support::copy_candidates<FT, 3>(x, points, candidates, ranges);
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

  mesh_templates_3(x, bpp, boundaries, o, r);

  support::certificate_stage(o, r, [&] {
    if (o.direct_certificate) return certify_3(x, boundaries);
    if (group) return certify_copies(x, known_copies, bpp, boundaries);
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
  // The copies found by the last is_group that passed, handed on so generate_3 need not redo them.
  std::vector<core::RigidTransformation<FT, 3>> group_copies;
  Symmetry group_kind = Symmetry::none;
  const auto is_group = [&](Symmetry kind) {
    try {
      group_copies = support::symmetry_copies(x, kind);
      group_kind = kind;
      return true;
    } catch (const std::invalid_argument&) {
      return false;
    }
  };
  const auto copies_of = [&](Symmetry kind) {
    return group_kind == kind ? group_copies : std::vector<core::RigidTransformation<FT, 3>>{};
  };
  // The baselines mesh the boundary as the templated method does: rotational or, for a
  // reflective-rotational structure, combined (the mirrors' faces meshed once, as Alg. 6.5).
  const auto baseline_symmetry = [&] {
    return rotational_applies()           ? Symmetry::rotational
           : is_group(Symmetry::combined) ? Symmetry::combined
                                          : Symmetry::none;
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
    r = generate_3(x, options, Symmetry::reflective, Whole::no, copies_of(Symmetry::reflective));
    r.method = "reflective";
    break;
  case Method::combined:
    r = generate_3(x, options, Symmetry::combined, Whole::no, copies_of(Symmetry::combined));
    r.method = "combined";
    break;
  case Method::merge:
    // Slices of a rotation are merged copies 0 and 1 (merge_3 finds them); a group symmetry
    // merges copy 0 only.
    if (rotational_applies())
      r = generate_merge(x, options);
    else if (is_group(Symmetry::combined) || is_group(Symmetry::reflective))
      r = generate_merge(x, options, group_copies);
    else
      r = generate_merge(x, options);
    r.method = "merge";
    break;
  case Method::conventional:
    // The boundary meshes as the templated method makes them (rotational when it applies).
    {
      const auto s = baseline_symmetry();
      r = generate_3(x, options, s, Whole::tetgen, copies_of(s));
    }
    r.method = "conventional";
    break;
  case Method::gmsh:
    // The peer on the very surfaces the conventional baseline hands TetGen.
    {
      const auto s = baseline_symmetry();
      r = generate_3(x, options, s, Whole::gmsh, copies_of(s));
    }
    r.method = "gmsh";
    break;
  default:
    throw std::invalid_argument(
        "--method: only auto, bpp, rotational, reflective, combined, merge, conventional and gmsh "
        "generate 3D meshes so far (sao is planar; spec/generation.md#alg-5-7)");
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
