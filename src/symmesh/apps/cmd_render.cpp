// symmesh render MESH.tmesh -o PICTURE.{svg,png} | OUT.vtm [--color ...] [--width PX]
//   [--patches STRUCTURE.json] [--quiet]
#include "symmesh/apps/commands.h"
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/io/atomic_file.h"
#include "symmesh/io/bpp_output.h"
#include "symmesh/io/mesh_render.h"
#include "symmesh/io/templated_mesh_file.h"
#include "symmesh/io/templated_structure_json.h"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>

namespace symmesh::apps {
namespace {
struct RenderOptions {
  std::string mesh, out, patches;
  io::MeshRenderOptions picture;
  bool quiet = false;
};

std::string extension(const std::string& path) {
  return std::filesystem::path(path).extension().string();
}

/// Options and file names are checked before the mesh is read, so bad input costs nothing.
bool options_ok(const RenderOptions& o) {
  if (extension(o.mesh) != ".tmesh") {
    print_error("render: " + o.mesh + ": expected a templated mesh .tmesh (symmesh generate ... " +
                "--templated X.tmesh)");
    return false;
  }
  const std::string ext = extension(o.out);
  if (ext != ".svg" && ext != ".png" && ext != ".vtm") {
    print_error("render: -o " + o.out + ": unknown output format '" + ext +
                "' (use .svg, .png or .vtm)");
    return false;
  }
  if (!o.patches.empty() && ext == ".vtm") {
    print_error("render: --patches draws over a picture (.svg, .png), not into a .vtm");
    return false;
  }
  return true;
}

/// The boundary patches (Algorithm 4.1, exact) of the structure the mesh was generated from.
/// \pre the structure has the mesh's templates with as many instances each; else
/// std::invalid_argument naming both counts
template <class FT>
io::PatchOverlay overlay_of(const core::TemplatedStructure<FT, 2>& x,
                            const mesh::TemplatedMeshCompactSvb& t, const std::string& path) {
  const auto& templates = t.templated.templates;
  std::size_t instances = 0;
  for (const auto& list : x.instances) instances += list.size();
  bool same = x.templates.size() == templates.size();
  for (std::size_t i = 0; same && i < templates.size(); ++i)
    same = x.instances[i].size() == templates[i].instance_count();
  if (!same)
    throw std::invalid_argument(
        "--patches " + path + ": its " + std::to_string(x.templates.size()) + " templates and " +
        std::to_string(instances) + " instances are not the mesh's " +
        std::to_string(templates.size()) + " and " + std::to_string(t.templated.instance_count()) +
        " (give the structure the mesh was generated from)");
  return io::patch_overlay(core::boundary_patch_partition(x));
}

io::PatchOverlay read_overlay(const std::string& path, const mesh::TemplatedMeshCompactSvb& t) {
  const auto any = io::read_templated_structure(path);
  if (const auto* x = std::get_if<io::Structure2>(&any)) return overlay_of(*x, t, path);
  if (const auto* x = std::get_if<io::CyclotomicStructure2>(&any)) return overlay_of(*x, t, path);
  throw std::invalid_argument("--patches " + path + ": boundary patches are drawn in 2D only");
}

/// Writes the picture or the multiblock; returns what was written, for the progress line.
std::string write_output(const mesh::TemplatedMeshCompactSvb& t, const RenderOptions& o) {
  const std::string ext = extension(o.out);
  if (ext == ".vtm") return std::to_string(io::write_vtm(t, o.out)) + " blocks";
  const std::string svg = io::mesh_svg(t, o.picture);
  if (ext == ".svg")
    io::write_file_atomically(o.out, svg);
  else
    io::write_png_from_svg(svg, o.out);
  return std::to_string(t.templated.point_dimension) + "D picture";
}

int run_render(RenderOptions o) {
  if (!options_ok(o)) return bad_input;
  const auto start = std::chrono::steady_clock::now();
  try {
    const auto t = io::read_tmesh(o.mesh);
    io::PatchOverlay overlay;
    if (!o.patches.empty()) {
      overlay = read_overlay(o.patches, t);
      o.picture.patches = &overlay;
    }
    const std::string what = write_output(t, o);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!o.quiet)
      std::cerr << "symmesh render: wrote " << o.out << " (" << what << ", "
                << t.templated.instance_count() << " instances, " << s << " s)\n";
  } catch (const std::exception& e) {
    print_error("render: " + std::string(e.what()));
    return bad_input;
  }
  return ok;
}
} // namespace

void add_render(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<RenderOptions>();
  auto* cmd = app.add_subcommand(
      "render", "Draw a templated mesh (.tmesh from generate --templated): 2D cells coloured by "
                "instance, template, region or quality with interfaces and boundary; 3D its "
                "boundary surface, or a ParaView multiblock .vtm with one block per template.");
  cmd->add_option("mesh", o->mesh, "templated mesh (.tmesh)")->required();
  cmd->add_option("-o,--output", o->out, "output: .svg, .png or .vtm")->required();
  const std::map<std::string, io::CellColour> colours{{"instance", io::CellColour::instance},
                                                      {"template", io::CellColour::template_},
                                                      {"region", io::CellColour::region},
                                                      {"quality", io::CellColour::quality}};
  cmd->add_option("--color", o->picture.colour,
                  "cell colouring: template (default), instance, region, quality (2D: smallest "
                  "angle)")
      ->transform(CLI::CheckedTransformer(colours, CLI::ignore_case));
  cmd->add_option("--width", o->picture.width, "pixels of the longer side (100..4000)")
      ->capture_default_str();
  cmd->add_option("--patches", o->patches,
                  "2D: draw the boundary patches (Algorithm 4.1) of this templated structure, the "
                  "one the mesh was generated from, coloured by relation class");
  cmd->add_flag("-q,--quiet", o->quiet, "no progress line on stderr");
  cmd->callback([o, &exit_code] { exit_code = run_render(*o); });
}

} // namespace symmesh::apps
