// symmesh generate GEOMETRY.json --size H [--min-angle A] [--method METHOD (spec/generation.md)]
//                  [--max-cells N] -o OUT.{vtu,msh,mesh} [--ascii] [--compress]
//                  [--templated OUT.tmesh] [--report REPORT.json] [--quiet]
#include "symmesh/api/generate_run.h"
#include "symmesh/apps/commands.h"
#include "symmesh/io/atomic_file.h"
#include "symmesh/io/mesh_writers.h"
#include "symmesh/io/templated_mesh_file.h"
#include "symmesh/mesh/progress.h"
#include "symmesh/mesh/structure_instance.h"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

namespace symmesh::apps {

std::size_t peak_rss_bytes() {
  return api::peak_rss_bytes();
}

namespace {

struct GenerateOptions {
  std::string file, out, report, templated;
  api::RunOptions run;
  bool quiet = false, ascii = false, compress = false;
};

int run_generate(GenerateOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const std::string ext = std::filesystem::path(o.out).extension().string();
  std::unique_ptr<mesh::Progress> progress;
  gen::GenerationResult r;
  try {
    api::check_method(o.run);
    if (o.out.empty() && o.templated.empty())
      throw api::Refusal(
          bad_input,
          "generate: give -o MESH (the structure instance) and/or --templated MESH.tmesh");
    if (!o.out.empty() && ext != ".vtu" && ext != ".msh" && ext != ".mesh")
      throw api::Refusal(bad_input,
                         "-o " + o.out + ": unknown mesh file extension (use .vtu, .msh or .mesh)");
    api::check_numbers(o.run);
    if (o.compress && (ext != ".vtu" || o.ascii))
      throw api::Refusal(bad_input, "--compress: applies to binary .vtu output only");
    if (!o.quiet) progress = std::make_unique<mesh::Progress>("symmesh generate", std::cerr);
    o.run.progress = progress.get();
    r = api::run_generation(api::read_structure_file(o.file), o.file, o.run);
  } catch (const api::Refusal& e) {
    progress.reset(); // no heartbeat line after the error
    print_error(e.what());
    return e.exit_code();
  }
  const double seconds = elapsed();
  // AT is streamed from the templated mesh, never materialised (mesh/structure_instance.h).
  const mesh::StructureInstance at(r.templated);
  const auto write_start = std::chrono::steady_clock::now();
  io::MeshFileOptions w;
  w.ascii = o.ascii;
  w.compress = o.compress;
  w.progress = progress.get();
  io::OutputGroup outputs; // all of -o, --templated and --report, or none of them
  if (!o.out.empty()) io::write_mesh_file(at, o.out, w);
  if (!o.templated.empty()) io::write_tmesh(r.templated, o.templated);
  const double write_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();
  if (!o.report.empty())
    io::write_file_atomically(
        o.report, api::generation_report(r, o.run, seconds, write_seconds).dump(2) + "\n");
  outputs.commit();
  const bool volumetric = r.templated.templated.point_dimension == 3;
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
  cmd->add_option("--size", o->run.size, "target edge length")->required();
  cmd->add_option("--min-angle", o->run.min_angle, "smallest angle in degrees, at most 33.8")
      ->capture_default_str();
  cmd->add_option("--method", o->run.method,
                  "auto (the first of rotational, combined, reflective that the structure is, else "
                  "bpp) | bpp (Algorithm 5.6) | "
                  "rotational (slices of a rotational symmetry, Section 6.3/Algorithm 6.2) | "
                  "reflective (Algorithms 6.1/6.4) | combined (reflective-rotational, Algorithm "
                  "6.5) | sao (small-angle optimisation, Section 6.3.2: a rotational slice is "
                  "cut into a centre n-gon and a ring slice, and the line meshes are refined "
                  "until every triangle meets --min-angle) | conventional (same mesher on the "
                  "whole geometry) | gmsh (Gmsh 2D Delaunay on the whole geometry) | merge (every "
                  "template meshed on its own, interfaces sewn by Algorithm 5.3, Section 5.1.1). "
                  "3D: auto, bpp "
                  "(Algorithm 5.7), rotational, reflective, combined, conventional (TetGen on the "
                  "whole geometry), gmsh (Gmsh 3D Delaunay on the whole geometry, the same "
                  "surfaces), merge (every face of every template surface-meshed on its own, the "
                  "interfaces merged by Algorithms 5.2-5.4, TetGen inside each template)")
      ->capture_default_str();
  cmd->add_option("-o,--output", o->out,
                  "structure instance: .vtu (binary, appended), .msh (4.1 binary) or .mesh "
                  "(Medit, text); may be left out when --templated is given (a structure "
                  "instance too large to write)");
  cmd->add_option("--max-cells", o->run.max_cells,
                  "refuse (exit 2, before any work) a --size whose estimated structure-instance "
                  "cell count is above N (default: memory / 250 bytes per cell)");
  cmd->add_flag("--ascii", o->ascii, "write .vtu / .msh as text instead of binary");
  cmd->add_flag("--compress", o->compress, ".vtu: zlib-compressed data blocks (VTK's compressor)");
  cmd->add_option("--report", o->report, "JSON report: cell counts, bytes, seconds, quality");
  cmd->add_option("--templated", o->templated,
                  "also write the templated mesh (.tmesh, spec/outputs.md#tmesh)");
  cmd->add_flag("--quiet", o->quiet, "no progress lines on stderr");
  cmd->add_flag(
      "!--no-repair", o->run.repair_outliers,
      "3D: keep TetGen's tetrahedra as they are (by default the few beyond "
      "radius-edge 1.414 or below a 10 degree dihedral angle are repaired by flips, "
      "removals and moves of TetGen's interior points; spec/generation.md#outlier-repair)");
  cmd->add_option("--tetgen-dihedral", o->run.tetgen_dihedral,
                  "3D: the smallest dihedral angle in degrees TetGen refines towards (its -q/D, "
                  "in every TetGen call, templates and whole geometry alike; 0: none, TetGen's "
                  "default; spec/generation.md#mesher-3)")
      ->capture_default_str();
  cmd->callback([o, &exit_code] { exit_code = run_generate(*o); });
}

} // namespace symmesh::apps
