/// Algorithm 5.7, template stage (internal to gen/): every template tetrahedralized by TetGen with
/// its surface mesh kept as its boundary, whatever made the surface meshes (the face classes of
/// the boundary patch partition, or independent meshes merged by Algorithms 5.2-5.4) —
/// spec/generation.md#alg-5-7
#pragma once
#include "symmesh/gen/certificate_3d.h"
#include "symmesh/gen/outlier_repair.h"
#include "symmesh/gen/tetrahedral_mesher.h"

#include <string>
#include <vector>

namespace symmesh::gen::surface3 {

/// TetGen on `s` (mesh_domain_3), then, unless o.repair_outliers is off, the outlier repair
/// (spec/generation.md#outlier-repair), its counts added to r.
inline TetrahedralMeshOutput mesh_and_repair(const SurfaceInput& s,
                                             const TetrahedralMeshingParameters& p,
                                             const GenerationOptions& o, GenerationResult& r) {
  auto out = mesh_domain_3(s, p);
  if (!o.repair_outliers) return out;
  const auto t0 = Clock::now();
  OutlierBounds bounds;
  if (p.size > 0) bounds.max_volume = volume_bound(p.size);
  const auto repair = repair_outliers(s, out, bounds);
  r.timings.outlier_repair += seconds_since(t0);
  r.outliers_before += repair.outliers_before;
  r.outliers_after += repair.outliers_after;
  r.repair_flips += repair.flips;
  r.repair_moves += repair.moves;
  r.repair_removals += repair.removals;
  if (o.progress && repair.outliers_before > 0)
    o.progress->message("outlier repair: " + std::to_string(repair.outliers_before) + " -> " +
                        std::to_string(repair.outliers_after) +
                        " tetrahedra beyond radius-edge 1.414 or below 10 degrees (" +
                        std::to_string(repair.flips) + " flips, " + std::to_string(repair.moves) +
                        " moves, " + std::to_string(repair.removals) + " removals)");
  return out;
}

/// Fills r.templated.templated with one TetGen mesh per template (its surface points first, in
/// their local ids, which the SVB refers to) and every instance's transformation and region.
/// A TetGen boundary change or failure is a MeshingError naming the template and, where it can,
/// the boundary patch and face.
template <class FT>
void mesh_templates_3(const core::TemplatedStructure<FT, 3>& x,
                      const core::BoundaryPatchPartition<FT, 3>& bpp,
                      const std::vector<SurfaceBoundary<FT>>& boundaries,
                      const GenerationOptions& o, GenerationResult& r) {
  const auto t0 = Clock::now();
  const long f0 = minor_faults();
  if (o.progress) o.progress->stage("template meshing (TetGen)", x.templates.size(), "templates");
  auto& tm = r.templated.templated;
  tm.point_dimension = 3;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    SurfaceInput s;
    s.points = rounded_boundary(boundaries[i]);
    s.triangles = boundaries[i].triangles;
    TetrahedralMeshingParameters p;
    p.size = o.size;
    p.min_dihedral_deg = o.tetgen_min_dihedral_deg;
    TetrahedralMeshOutput out;
    try {
      out = mesh_and_repair(s, p, o, r);
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
    if (o.progress)
      o.progress->message("template " + std::to_string(i + 1) + "/" +
                          std::to_string(x.templates.size()) + " ('" + x.templates[i].name +
                          "'): " + std::to_string(t.mesh.cell_count()) + " tetrahedra, " +
                          std::to_string(boundaries[i].triangles.size()) + " boundary triangles");
    tm.templates.push_back(std::move(t));
    if (o.progress) o.progress->set_done(i + 1);
  }
  r.timings.template_meshing = seconds_since(t0);
  r.timings.page_faults.template_meshing = minor_faults() - f0;
}

} // namespace symmesh::gen::surface3
