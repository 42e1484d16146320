// symmesh generate GEOMETRY.json --size H [--min-angle A] [--method METHOD (spec/generation.md)]
//                  [--max-cells N] -o OUT.{vtu,msh,mesh} [--ascii] [--compress]
//                  [--templated OUT.tmesh] [--report REPORT.json] [--quiet]
#include "symmesh/apps/commands.h"
#include "symmesh/gen/templated_tetrahedral_mesh.h"
#include "symmesh/gen/templated_triangle_mesh.h"
#include "symmesh/gen/triangle_mesher.h"
#include "symmesh/io/mesh_writers.h"
#include "symmesh/io/templated_mesh_file.h"
#include "symmesh/mesh/progress.h"
#include "symmesh/mesh/quality.h"
#include "symmesh/mesh/structure_instance.h"
#include "symmesh/io/templated_structure_json.h"

#include <nlohmann/json.hpp>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <variant>

namespace symmesh::apps {

std::size_t peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return std::size_t(u.ru_maxrss) * 1024;
}

namespace {

struct GenerateOptions {
  std::string file, out, report, templated, method = "auto";
  double size = 0, min_angle = 20;
  double max_cells = 0; ///< 0: the default from the machine's memory
  bool quiet = false, ascii = false, compress = false;
};

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

template <class FT, int D>
gen::GenerationResult run_method(const core::TemplatedStructure<FT, D>& x, const GenerateOptions& o,
                                 const gen::GenerationOptions& g) {
  const std::map<std::string, gen::Method> methods{{"auto", gen::Method::automatic},
                                                   {"bpp", gen::Method::bpp},
                                                   {"rotational", gen::Method::rotational},
                                                   {"reflective", gen::Method::reflective},
                                                   {"combined", gen::Method::combined},
                                                   {"conventional", gen::Method::conventional},
                                                   {"gmsh", gen::Method::gmsh},
                                                   {"sao", gen::Method::sao}};
  const auto method = methods.at(o.method);
  if constexpr (D == 2)
    return gen::generate_triangle_mesh(x, method, g);
  else
    return gen::generate_tetrahedral_mesh(x, method, g);
}

struct InfeasibleSize : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Refuses, before any work, a --size that would give more cells than --max-cells.
void refuse_infeasible_size(const gen::CellEstimate& e, const GenerateOptions& o) {
  const bool by_default = o.max_cells == 0;
  const double limit = by_default ? default_max_cells() : o.max_cells;
  if (e.cells <= limit) return;
  throw InfeasibleSize(
      "--size " + round_text(o.size) + ": the structure instance would have about " +
      round_text(e.cells) +
      (e.dimension == 2
           ? " triangles (area " + round_text(e.measure) + " at about 0.2·size² per triangle)"
           : " tetrahedra (volume " + round_text(e.measure) + " at about 2 per size³/(6√2))") +
      ", above the limit of " + round_text(limit) +
      (by_default
           ? " (" + round_text(physical_memory_bytes() / double(1ull << 30)) + " GiB of memory / " +
                 round_text(kBytesPerCell) + " bytes per cell; raise it with --max-cells)"
           : " (--max-cells)"));
}

/// Tetrahedron quality of AT from the templates (Table 7.1's measures): dihedral angles,
/// radius-edge ratio, and the tetrahedra whose smallest dihedral angle is below 10°.
nlohmann::ordered_json tetrahedron_quality_json(const mesh::TemplatedMesh& t) {
  constexpr double kDihedralBoundDeg = 10;
  const auto q = mesh::tetrahedron_quality(t, kDihedralBoundDeg);
  nlohmann::ordered_json j;
  j["tetrahedra"] = q.tetrahedra;
  j["min_dihedral_deg"] = q.min_dihedral_deg;
  j["max_dihedral_deg"] = q.max_dihedral_deg;
  j["max_radius_edge_ratio"] = q.max_radius_edge_ratio;
  j["dihedral_bound_deg"] = kDihedralBoundDeg;
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

int run_generate(const GenerateOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  if (o.method != "auto" && o.method != "bpp" && o.method != "rotational" &&
      o.method != "reflective" && o.method != "combined" && o.method != "conventional" &&
      o.method != "gmsh" && o.method != "sao") {
    print_error("--method " + o.method +
                ": unknown (use auto, bpp, reflective, rotational, sao, combined, conventional "
                "or gmsh)");
    return bad_input;
  }
  if (o.out.empty() && o.templated.empty()) {
    print_error("generate: give -o MESH (the structure instance) and/or --templated MESH.tmesh");
    return bad_input;
  }
  const std::string ext = std::filesystem::path(o.out).extension().string();
  if (!o.out.empty() && ext != ".vtu" && ext != ".msh" && ext != ".mesh") {
    print_error("-o " + o.out + ": unknown mesh file extension (use .vtu, .msh or .mesh)");
    return bad_input;
  }
  if (!(o.size > 0) || !std::isfinite(o.size)) {
    print_error("--size " + round_text(o.size) + ": must be a positive number");
    return bad_input;
  }
  // Mesh_2's Delaunay refinement terminates only for bounds up to about 33.8°.
  if (!(o.min_angle >= 0 && o.min_angle <= 33.8)) {
    print_error("--min-angle " + round_text(o.min_angle) +
                ": must be between 0 and 33.8 degrees (Delaunay refinement does not terminate "
                "above)");
    return bad_input;
  }
  if (!(o.max_cells >= 0) || !std::isfinite(o.max_cells)) {
    print_error("--max-cells " + round_text(o.max_cells) + ": must be a positive number");
    return bad_input;
  }
  if (o.compress && (ext != ".vtu" || o.ascii)) {
    print_error("--compress: applies to binary .vtu output only");
    return bad_input;
  }
  std::unique_ptr<mesh::Progress> progress;
  if (!o.quiet) progress = std::make_unique<mesh::Progress>("symmesh generate", std::cerr);
  gen::GenerationOptions g;
  g.size = o.size;
  g.min_angle_deg = o.min_angle;
  g.progress = progress.get();
  gen::GenerationResult r;
  try {
    const auto x = io::read_templated_structure(o.file);
    r = std::visit(
        [&](const auto& s) -> gen::GenerationResult {
          refuse_infeasible_size(gen::estimate_cells(s, o.size), o);
          return run_method(s, o, g);
        },
        x);
  } catch (const InfeasibleSize& e) {
    progress.reset(); // no heartbeat line after the error
    print_error(e.what());
    return bad_input;
  } catch (const io::InputError& e) {
    progress.reset();
    print_error(e.what());
    return bad_input;
  } catch (const std::invalid_argument& e) {
    progress.reset();
    print_error(o.file + ": " + e.what());
    return bad_input;
  } catch (const gen::MeshingError& e) {
    progress.reset();
    print_error(o.file + ": meshing failed: " + e.what());
    return bad_input;
  }
  const double seconds = elapsed();
  if (!r.lemma_4_2_holds) {
    progress.reset();
    print_error(o.file + ": the generated templated mesh fails the Lemma 4.2 certificate (" +
                r.lemma_4_2_failure + "); no output written");
    return negative;
  }
  // AT is streamed from the templated mesh, never materialised (mesh/structure_instance.h).
  const mesh::StructureInstance at(r.templated);
  const auto svb = mesh::to_listing_4_2(r.templated);
  const auto write_start = std::chrono::steady_clock::now();
  io::MeshFileOptions w;
  w.ascii = o.ascii;
  w.compress = o.compress;
  w.progress = progress.get();
  if (!o.out.empty()) io::write_mesh_file(at, o.out, w);
  if (!o.templated.empty()) io::write_tmesh(r.templated, o.templated);
  const double write_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();
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
  const bool volumetric = r.templated.templated.point_dimension == 3;
  if (!volumetric) {
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
  }
  j["lemma_4_2_holds"] = r.lemma_4_2_holds;
  if (!o.report.empty()) {
    std::ofstream os(o.report);
    os << j.dump(2) << "\n";
  }
  if (progress)
    progress->message(
        std::to_string(at.cell_count()) + (volumetric ? " tetrahedra in " : " triangles in ") +
        std::to_string(r.templated.templated.instance_count()) + " instances of " +
        std::to_string(r.templated.templated.templates.size()) + " templates, written to " +
        (o.out.empty() ? o.templated
                       : o.out + (o.templated.empty() ? std::string() : " and " + o.templated)));
  return ok;
}
} // namespace

void add_generate(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<GenerateOptions>();
  auto* cmd = app.add_subcommand(
      "generate", "Generate a templated mesh of a templated geometry -- triangles in 2D (Algorithm "
                  "5.6), tetrahedra by TetGen in 3D (Algorithm 5.7), over the boundary patch "
                  "partition -- or a conventional baseline, certify it "
                  "with Lemma 4.2 and write the structure instance. Exit 0: written; 1: the "
                  "certificate failed (nothing written); 2: bad input.");
  cmd->add_option("file", o->file, "templated-geometry JSON (spec/input-format.md)")->required();
  cmd->add_option("--size", o->size, "target edge length")->required();
  cmd->add_option("--min-angle", o->min_angle, "smallest angle in degrees, at most 33.8")
      ->capture_default_str();
  cmd->add_option("--method", o->method,
                  "auto (the first of rotational, combined, reflective that the structure is, else "
                  "bpp) | bpp (Algorithm 5.6) | "
                  "rotational (slices of a rotational symmetry, Section 6.3/Algorithm 6.2) | "
                  "reflective (Algorithms 6.1/6.4) | combined (reflective-rotational, Algorithm "
                  "6.5) | sao (small-angle optimisation, Section 6.3.2: a rotational slice is "
                  "cut into a centre n-gon and a ring slice, and the line meshes are refined "
                  "until every triangle meets --min-angle) | conventional (same mesher on the "
                  "whole geometry) | gmsh (Gmsh 2D Delaunay on the whole geometry). 3D: auto, bpp "
                  "(Algorithm 5.7), rotational, reflective, combined, conventional (TetGen on the "
                  "whole geometry), gmsh (Gmsh 3D Delaunay on the whole geometry, the same "
                  "surfaces)")
      ->capture_default_str();
  cmd->add_option("-o,--output", o->out,
                  "structure instance: .vtu (binary, appended), .msh (4.1 binary) or .mesh "
                  "(Medit, text); may be left out when --templated is given (a structure "
                  "instance too large to write)");
  cmd->add_option("--max-cells", o->max_cells,
                  "refuse (exit 2, before any work) a --size whose estimated structure-instance "
                  "cell count is above N (default: memory / 250 bytes per cell)");
  cmd->add_flag("--ascii", o->ascii, "write .vtu / .msh as text instead of binary");
  cmd->add_flag("--compress", o->compress, ".vtu: zlib-compressed data blocks (VTK's compressor)");
  cmd->add_option("--report", o->report, "JSON report: cell counts, bytes, seconds, quality");
  cmd->add_option("--templated", o->templated,
                  "also write the templated mesh (.tmesh, spec/outputs.md#tmesh)");
  cmd->add_flag("--quiet", o->quiet, "no progress lines on stderr");
  cmd->callback([o, &exit_code] { exit_code = run_generate(*o); });
}

} // namespace symmesh::apps
