// The generation run of `symmesh generate` and the public API (generate_run.h).
#include "symmesh/api/generate_run.h"

#include "symmesh/gen/templated_tetrahedral_mesh.h"
#include "symmesh/gen/triangle_mesher.h"
#include "symmesh/mesh/quality.h"
#include "symmesh/mesh/structure_instance.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <iomanip>
#include <map>
#include <algorithm>
#include <sstream>
#include <variant>

namespace symmesh::api {

std::size_t peak_rss_bytes() {
  // TetGen runs in a child process (gen/tetrahedral_mesher.cpp): its peak counts too.
  rusage self{}, children{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &children);
  return std::size_t(std::max(self.ru_maxrss, children.ru_maxrss)) * 1024;
}

namespace {

/// Peak bytes per structure-instance cell of the most memory-hungry path (the conventional
/// method meshing AT whole with Mesh_2): 231 MiB at 961 408 triangles of the 128-gon, measured
/// as the whole command's peak RSS (spec/generation.md#cell-estimate).
constexpr double kBytesPerCell = 250;

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 8.0 * (1ull << 30);
}

double default_max_cells() {
  return std::floor(physical_memory_bytes() / kBytesPerCell);
}

std::string round_text(double v) {
  std::ostringstream s;
  s << std::setprecision(3) << v;
  return s.str();
}

const std::map<std::string, gen::Method>& methods() {
  static const std::map<std::string, gen::Method> m{{"auto", gen::Method::automatic},
                                                    {"bpp", gen::Method::bpp},
                                                    {"rotational", gen::Method::rotational},
                                                    {"reflective", gen::Method::reflective},
                                                    {"combined", gen::Method::combined},
                                                    {"conventional", gen::Method::conventional},
                                                    {"gmsh", gen::Method::gmsh},
                                                    {"sao", gen::Method::sao},
                                                    {"merge", gen::Method::merge}};
  return m;
}

template <class FT, int D>
gen::GenerationResult run_method(const core::TemplatedStructure<FT, D>& x, const RunOptions& o) {
  gen::GenerationOptions g;
  g.size = o.size;
  g.min_angle_deg = o.min_angle;
  g.progress = o.progress;
  g.repair_outliers = o.repair_outliers;
  g.tetgen_min_dihedral_deg = o.tetgen_dihedral;
  const auto method = methods().at(o.method);
  if constexpr (D == 2)
    return gen::generate_triangle_mesh(x, method, g);
  else
    return gen::generate_tetrahedral_mesh(x, method, g);
}

/// Refuses, before any work, a size that would give more cells than max_cells.
void refuse_infeasible_size(const gen::CellEstimate& e, const RunOptions& o) {
  const bool by_default = o.max_cells == 0;
  const double limit = by_default ? default_max_cells() : o.max_cells;
  if (e.cells <= limit) return;
  throw Refusal(
      kBadInput,
      "--size " + round_text(o.size) + ": the structure instance would have about " +
          round_text(e.cells) +
          (e.dimension == 2
               ? " triangles (area " + round_text(e.measure) + " at about 0.2·size² per triangle)"
               : " tetrahedra (volume " + round_text(e.measure) + " at about 2 per size³/(6√2))") +
          ", above the limit of " + round_text(limit) +
          (by_default ? " (" + round_text(physical_memory_bytes() / double(1ull << 30)) +
                            " GiB of memory / " + round_text(kBytesPerCell) +
                            " bytes per cell; raise it with --max-cells)"
                      : " (--max-cells)"));
}

/// Tetrahedron quality of AT from the templates (Table 7.1's measures): dihedral angles,
/// radius-edge ratio, and the tetrahedra whose smallest dihedral angle is below 10°.
nlohmann::ordered_json tetrahedron_quality_json(const mesh::TemplatedMesh& t) {
  const auto q = mesh::tetrahedron_quality(t, mesh::kDihedralBoundDeg);
  nlohmann::ordered_json j;
  j["tetrahedra"] = q.tetrahedra;
  j["min_dihedral_deg"] = q.min_dihedral_deg;
  j["max_dihedral_deg"] = q.max_dihedral_deg;
  j["max_radius_edge_ratio"] = q.max_radius_edge_ratio;
  j["dihedral_bound_deg"] = mesh::kDihedralBoundDeg;
  j["below_dihedral_bound"] = q.below_bound;
  j["min_dihedral_histogram_bin_deg"] = 5;
  j["min_dihedral_histogram"] = q.histogram;
  return j;
}

/// MRMESH bytes of AT (Listing 2.2) from its counts: the arrays as mesh::MrMesh::bytes() counts
/// them, without building it.
std::size_t mrmesh_bytes(const mesh::StructureInstance& at) {
  std::size_t indices = 0;
  for (const auto& t : at.templated().templated.templates)
    indices += t.mesh.cell_vertex_indices.size() * t.instance_count();
  const std::size_t nc = at.cell_count();
  return at.vertex_count() * std::size_t(at.dimension()) * sizeof(mesh::NumericType) +
         nc * sizeof(mesh::ElementType) + indices * sizeof(mesh::IndexType) +
         (nc + 1) * sizeof(mesh::IndexType) + nc * sizeof(mesh::RegionIdType);
}

} // namespace

void check_method(const RunOptions& o) {
  if (!methods().count(o.method))
    throw Refusal(kBadInput, "--method " + o.method +
                                 ": unknown (use auto, bpp, reflective, rotational, sao, combined, "
                                 "conventional or gmsh)");
}

void check_numbers(const RunOptions& o) {
  if (!(o.size > 0) || !std::isfinite(o.size))
    throw Refusal(kBadInput, "--size " + round_text(o.size) + ": must be a positive number");
  // Mesh_2's Delaunay refinement terminates only for bounds up to about 33.8°.
  if (!(o.min_angle >= 0 && o.min_angle <= 33.8))
    throw Refusal(kBadInput, "--min-angle " + round_text(o.min_angle) +
                                 ": must be between 0 and 33.8 degrees (Delaunay refinement "
                                 "does not terminate above)");
  if (!(o.tetgen_dihedral >= 0 && o.tetgen_dihedral < 70.5))
    throw Refusal(kBadInput, "--tetgen-dihedral " + round_text(o.tetgen_dihedral) +
                                 ": must be at least 0 and below 70.5 degrees (a regular "
                                 "tetrahedron's dihedral angle)");
  if (!(o.max_cells >= 0) || !std::isfinite(o.max_cells))
    throw Refusal(kBadInput,
                  "--max-cells " + round_text(o.max_cells) + ": must be a positive number");
}

io::AnyStructure read_structure_file(const std::string& path) {
  try {
    return io::read_templated_structure(path);
  } catch (const io::InputError& e) {
    throw Refusal(kBadInput, e.what());
  } catch (const std::invalid_argument& e) {
    throw Refusal(kBadInput, path + ": " + e.what());
  }
}

io::AnyStructure parse_structure_text(const std::string& text, const std::string& source) {
  try {
    return io::parse_templated_structure(text, source);
  } catch (const io::InputError& e) {
    throw Refusal(kBadInput, e.what());
  } catch (const std::invalid_argument& e) {
    throw Refusal(kBadInput, source + ": " + e.what());
  }
}

gen::GenerationResult run_generation(const io::AnyStructure& x, const std::string& source,
                                     const RunOptions& o) {
  gen::GenerationResult r;
  try {
    r = std::visit(
        [&](const auto& s) -> gen::GenerationResult {
          refuse_infeasible_size(gen::estimate_cells(s, o.size), o);
          return run_method(s, o);
        },
        x);
  } catch (const io::InputError& e) {
    throw Refusal(kBadInput, e.what());
  } catch (const std::invalid_argument& e) {
    throw Refusal(kBadInput, source + ": " + e.what());
  } catch (const gen::MeshingError& e) {
    throw Refusal(kBadInput, source + ": meshing failed: " + e.what());
  } catch (const gen::MergeError& e) {
    throw Refusal(kNegative, source + ": " + e.what() + "; no output written");
  }
  if (!r.lemma_4_2_holds)
    throw Refusal(kNegative, source +
                                 ": the generated templated mesh fails the Lemma 4.2 "
                                 "certificate (" +
                                 r.lemma_4_2_failure + "); no output written");
  return r;
}

nlohmann::ordered_json generation_report(const gen::GenerationResult& r, const RunOptions& o,
                                         double seconds, double write_seconds) {
  // AT is counted from the templated mesh, never materialised (mesh/structure_instance.h).
  const mesh::StructureInstance at(r.templated);
  const auto svb = mesh::to_listing_4_2(r.templated);
  std::size_t template_cells = 0;
  for (const auto& t : r.templated.templated.templates) template_cells += t.mesh.cell_count();
  nlohmann::ordered_json j;
  j["method"] = r.method;
  j["size"] = o.size;
  j["min_angle_requested_deg"] = o.min_angle;
  j["cells_structure_instance"] = at.cell_count();
  j["vertices_structure_instance"] = at.vertex_count();
  j["cells_templates"] = template_cells;
  j["templates"] = r.templated.templated.templates.size();
  j["instances"] = r.templated.templated.instance_count();
  j["bytes_mesh"] = mrmesh_bytes(at);
  j["bytes_templated"] = r.templated.templated.bytes();
  j["bytes_templated_svb"] = svb.bytes();
  j["bytes_templated_svb_compact"] = r.templated.bytes();
  j["seconds"] = seconds;
  j["seconds_breakdown"] = {{"boundary_patch_partition", r.timings.boundary_patch_partition},
                            {"line_meshes", r.timings.line_meshes},
                            {"template_meshing", r.timings.template_meshing},
                            {"svb", r.timings.svb},
                            {"lemma_4_2_certificate", r.timings.certificate}};
  const auto& f = r.timings.page_faults;
  j["page_faults_breakdown"] = {{"boundary_patch_partition", f.boundary_patch_partition},
                                {"line_meshes", f.line_meshes},
                                {"template_meshing", f.template_meshing},
                                {"svb", f.svb},
                                {"lemma_4_2_certificate", f.certificate}};
  j["seconds_write"] = write_seconds;
  j["peak_rss_bytes"] = peak_rss_bytes();
  if (r.templated.templated.point_dimension != 3) {
    const auto q = mesh::triangle_quality(r.templated.templated, o.min_angle);
    j["min_angle_deg"] = q.min_angle_deg;
    j["quality"] = {{"triangles", q.triangles},
                    {"min_angle_deg", q.min_angle_deg},
                    {"max_radius_edge_ratio", q.max_radius_edge_ratio},
                    {"below_min_angle", q.below_bound},
                    {"min_angle_histogram_bin_deg", 5},
                    {"min_angle_histogram", q.histogram}};
  } else {
    j["quality"] = tetrahedron_quality_json(r.templated.templated);
    if (r.method != "gmsh") j["tetgen_min_dihedral_deg"] = o.tetgen_dihedral;
    // Which Gmsh mesh this is: optimized (Gmsh's default), or the retry after its optimizer
    // failed (gmsh_mesher.h).
    if (r.method == "gmsh")
      j["gmsh_optimizer"] =
          r.gmsh_optimizer_failure.empty()
              ? nlohmann::ordered_json{{"optimized", true}}
              : nlohmann::ordered_json{{"optimized", false}, {"failure", r.gmsh_optimizer_failure}};
    if (o.repair_outliers && r.method != "gmsh")
      j["outlier_repair"] = {{"template_cells_before", r.outliers_before},
                             {"template_cells_after", r.outliers_after},
                             {"flips", r.repair_flips},
                             {"moves", r.repair_moves},
                             {"removals", r.repair_removals},
                             {"seconds_within_template_meshing", r.timings.outlier_repair}};
  }
  j["lemma_4_2_holds"] = r.lemma_4_2_holds;
  if (r.method == "merge")
    j["interface_merging"] = {{"pairs_merged", r.merge_merged},
                              {"points_moved", r.merge_moves},
                              {"points_inserted", r.merge_insertions},
                              {"rounds", r.merge_rounds}};
  return j;
}

} // namespace symmesh::api
