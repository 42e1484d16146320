// symmesh adapt IN.tmesh [--clone K]... [--split-where EXPR]... [--refine-where EXPR]... [--smooth
// N] [--improve]
//   [--delaunay] [--merge-identical] [--merge-congruent [--congruence-tolerance REL]] -o OUT.tmesh
//   [--vtu OUT.vtu] [--report R.json] [--max-rounds N] [--quiet]
// Section 5.2 / Technique 5.8 on a generated templated mesh — spec/adaptation.md#adapt-command
#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/adapt/tmesh_template_cloning.h"
#include "symmesh/apps/commands.h"
#include "symmesh/io/atomic_file.h"
#include "symmesh/io/mesh_writers.h"
#include "symmesh/io/templated_mesh_file.h"
#include "symmesh/mesh/structure_instance.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

namespace symmesh::apps {
namespace {
struct AdaptOptions {
  std::string in, out, vtu, report;
  std::vector<std::string> refine_where, split_where;
  std::vector<std::size_t> clone; ///< instances, numbered as in the input
  std::size_t smooth = 0, max_rounds = 64, improve_rounds = 8;
  double congruence_tolerance = 0; ///< --merge-congruent up to this fraction of the diameter
  bool delaunay = false, improve = false, merge_identical = false, merge_congruent = false,
       quiet = false;
};

std::string extension(const std::string& path) {
  return std::filesystem::path(path).extension().string();
}

/// Options are checked before the mesh is read, so bad input costs nothing and writes nothing.
bool options_ok(const AdaptOptions& o) {
  if (extension(o.in) != ".tmesh") {
    print_error("adapt: " + o.in + ": expected a templated mesh .tmesh (symmesh generate ... " +
                "--templated X.tmesh)");
    return false;
  }
  if (extension(o.out) != ".tmesh") {
    print_error("adapt: -o " + o.out + ": the adapted mesh is written as a .tmesh");
    return false;
  }
  if (!o.vtu.empty() && extension(o.vtu) != ".vtu") {
    print_error("adapt: --vtu " + o.vtu + ": expected a .vtu file name");
    return false;
  }
  if (!(o.congruence_tolerance >= 0 && o.congruence_tolerance < 1e-3)) {
    print_error("adapt: --congruence-tolerance " + std::to_string(o.congruence_tolerance) +
                ": must be at least 0 and below 1e-3 (a fraction of the template's diameter; "
                "1e-9 covers rounding)");
    return false;
  }
  if (o.congruence_tolerance > 0 && !o.merge_congruent) {
    print_error("adapt: --congruence-tolerance: applies to --merge-congruent, which is not given");
    return false;
  }
  if (!o.delaunay && !o.improve && o.smooth == 0 && o.refine_where.empty() && o.clone.empty() &&
      o.split_where.empty() && !o.merge_identical && !o.merge_congruent) {
    print_error("adapt: nothing to do: give --clone K, --split-where, --refine-where, --smooth N, "
                "--improve, "
                "--delaunay, --merge-identical or --merge-congruent");
    return false;
  }
  return true;
}

struct Counts {
  std::size_t template_cells = 0, at_cells = 0, at_vertices = 0;
  double quality = 0;
};

Counts counts_of(const mesh::TemplatedMeshCompactSvb& t) {
  Counts c;
  for (const auto& mt : t.templated.templates) c.template_cells += mt.mesh.cell_count();
  const mesh::StructureInstance at(t);
  c.at_cells = at.cell_count();
  c.at_vertices = at.vertex_count();
  c.quality = adapt::smallest_quality(t);
  return c;
}

nlohmann::json to_json(const Counts& c) {
  return {{"template_cells", c.template_cells},
          {"cells_structure_instance", c.at_cells},
          {"vertices_structure_instance", c.at_vertices},
          {"smallest_angle_deg", c.quality}}; // the smallest dihedral angle in 3D
}

/// Section 5.2.1: each instance (numbered as in the input) gets its own copy of its template, in
/// the given order; the report and the progress line give its template and its new number.
template <class Say>
void clone_instances(mesh::TemplatedMeshCompactSvb& t, const std::vector<std::size_t>& clone,
                     nlohmann::json& steps, const Say& say) {
  const std::size_t n = t.templated.instance_count();
  std::vector<std::size_t> now(n); // the current number of each input instance
  for (std::size_t g = 0; g < n; ++g) now[g] = g;
  for (const std::size_t g : clone) {
    if (g >= n)
      throw std::invalid_argument("--clone " + std::to_string(g) +
                                  ": no such instance (the mesh has " + std::to_string(n) + ")");
    const auto c = adapt::clone_template(t, now[g]);
    for (auto& q : now)
      if (q > now[g]) --q;
    now[g] = c.instance;
    steps.push_back({{"clone", g}, {"template", c.template_index}, {"instance", c.instance}});
    say("clone: instance " + std::to_string(g) + " has its own template " +
        std::to_string(c.template_index) + " and is now instance " + std::to_string(c.instance));
  }
}

/// Section 5.2.1: every template with cells on both sides of `where` (template coordinates)
/// splits; the cells where it holds become a new template, instanced like the old one.
template <class Say>
void split_templates(mesh::TemplatedMeshCompactSvb& t, const std::string& expression,
                     const adapt::CellPredicate& where, nlohmann::json& steps, const Say& say) {
  const auto splits = adapt::split_where(t, where);
  nlohmann::json list = nlohmann::json::array();
  for (const auto& s : splits) {
    list.push_back(
        {{"template", s.template_index}, {"new_template", s.new_template}, {"cells", s.cells}});
    say("split-where \"" + expression + "\": " + std::to_string(s.cells) + " cells of template " +
        std::to_string(s.template_index) + " are now template " + std::to_string(s.new_template) +
        ", instanced like it");
  }
  if (splits.empty())
    say("split-where \"" + expression + "\": no template has cells on both sides");
  steps.push_back({{"split_where", expression}, {"splits", list}});
}

int run_adapt(const AdaptOptions& o) {
  if (!options_ok(o)) return bad_input;
  std::unique_ptr<mesh::Progress> progress;
  if (!o.quiet) progress = std::make_unique<mesh::Progress>("symmesh adapt", std::cerr);
  const auto say = [&](const std::string& line) {
    if (progress) progress->message(line);
  };
  mesh::TemplatedMeshCompactSvb t;
  std::vector<adapt::CellPredicate> where, split;
  adapt::ConformityCertificate input;
  try {
    for (const auto& e : o.split_where) split.push_back(adapt::parse_template_cell_predicate(e));
    for (const auto& e : o.refine_where) where.push_back(adapt::parse_cell_predicate(e));
    t = io::read_tmesh(o.in);
    // Throws on cells that are not triangles / tetrahedra.
    input = adapt::certify_conformity(t);
    if (!input.holds)
      throw std::invalid_argument(o.in + ": the input does not conform: " + input.why);
  } catch (const std::exception& e) {
    print_error("adapt: " + std::string(e.what()));
    return bad_input;
  }
  nlohmann::json report;
  report["input"] = o.in;
  try {
    const auto before = counts_of(t);
    report["before"] = to_json(before);
    const auto added = adapt::expand_identifications(t);
    say("read " + o.in + ": " + std::to_string(t.templated.templates.size()) + " templates, " +
        std::to_string(t.templated.instance_count()) + " instances, " +
        std::to_string(before.at_cells) + " cells in AT (" + std::to_string(added) +
        " direct instance pairs added)");
    nlohmann::json steps = nlohmann::json::array();
    clone_instances(t, o.clone, steps, say);
    for (std::size_t k = 0; k < split.size(); ++k)
      split_templates(t, o.split_where[k], split[k], steps, say);
    for (std::size_t k = 0; k < where.size(); ++k) {
      const auto n = adapt::refine_where(t, where[k]);
      steps.push_back({{"refine_where", o.refine_where[k]}, {"edges_bisected", n}});
      say("refine-where \"" + o.refine_where[k] + "\": " + std::to_string(n) +
          " template edges bisected");
    }
    if (o.smooth > 0) {
      const auto r = adapt::smooth_vertices(t, o.smooth, false);
      steps.push_back({{"smooth", o.smooth},
                       {"moves", r.interior_moves + r.boundary_moves},
                       {"boundary_moves", r.boundary_moves}});
      say("smooth: " + std::to_string(r.interior_moves) + " moves of template-interior vertices, " +
          std::to_string(r.boundary_moves) + " of template-boundary vertices in their patch");
    }
    if (o.improve) {
      const auto r = adapt::improve_quality(t, o.improve_rounds);
      steps.push_back({{"improve", r.rounds}, {"moves", r.moves}, {"flips", r.flips}});
      say("improve: " + std::to_string(r.rounds) + " rounds, " + std::to_string(r.moves) +
          " moves, " + std::to_string(r.flips) + " flips");
    }
    if (o.delaunay) {
      const auto r = adapt::make_delaunay(t, o.max_rounds, progress.get());
      steps.push_back({{"delaunay", r.rounds},
                       {"flips", r.flips},
                       {"edges_bisected", r.bisections},
                       {"crease_mirror_points", r.crease_mirror_points}});
      say("delaunay: " + std::to_string(r.flips) + " flips, " + std::to_string(r.bisections) +
          " interface edges bisected, " + std::to_string(r.crease_mirror_points) +
          " crease mirror points inserted in " + std::to_string(r.rounds) + " rounds");
    }
    // Section 5.2.1 merges, each reported as its step and a progress line.
    const auto merge_step = [&](const std::string& option, const std::string& key, auto merge) {
      const auto before_merge = t.templated.templates.size();
      const std::size_t n = merge(t);
      steps.push_back({{key, n}, {"templates", t.templated.templates.size()}});
      say(option + ": " + std::to_string(n) + " templates merged (" + std::to_string(before_merge) +
          " -> " + std::to_string(t.templated.templates.size()) + ")");
    };
    if (o.merge_identical)
      merge_step("merge-identical", "merge_identical", [](mesh::TemplatedMeshCompactSvb& m) {
        return adapt::merge_identical_templates(m);
      });
    if (o.merge_congruent)
      merge_step("merge-congruent", "merge_congruent", [&](mesh::TemplatedMeshCompactSvb& m) {
        return adapt::merge_congruent_templates(m, o.congruence_tolerance);
      });
    std::ostringstream why;
    if (!t.is_valid(&why)) throw std::logic_error("the adapted mesh is not valid: " + why.str());
    const auto cert = adapt::certify_conformity(t, input.boundary_measure);
    if (!cert.holds) throw std::logic_error("the adapted mesh does not conform: " + cert.why);
    const auto after = counts_of(t);
    report["steps"] = steps;
    report["after"] = to_json(after);
    report["cells_structure_instance"] = after.at_cells;
    report["conforming"] = true;
    report["boundary_measure"] = cert.boundary_measure;
    say("certified: AT conforms (" + std::to_string(after.at_cells) + " cells, boundary " +
        std::to_string(cert.boundary_measure) + "); smallest " +
        (t.templated.point_dimension == 2 ? "angle " : "dihedral angle ") +
        std::to_string(before.quality) + " -> " + std::to_string(after.quality) + " deg");
  } catch (const adapt::AdaptationLimit& e) {
    print_error("adapt: " + std::string(e.what()));
    return negative;
  } catch (const std::invalid_argument& e) {
    print_error("adapt: " + std::string(e.what()));
    return bad_input;
  } catch (const std::exception& e) {
    print_error("adapt: " + std::string(e.what()));
    return negative;
  }
  io::OutputGroup outputs; // all of -o, --vtu and --report, or none of them
  io::write_tmesh(t, o.out);
  if (!o.vtu.empty()) {
    const mesh::StructureInstance at(t);
    io::MeshFileOptions w;
    w.progress = progress.get();
    io::write_mesh_file(at, o.vtu, w);
  }
  if (!o.report.empty()) {
    report["seconds"] = progress ? progress->elapsed() : 0.0;
    report["peak_rss_bytes"] = peak_rss_bytes();
    io::write_file_atomically(o.report, report.dump(2) + "\n");
  }
  outputs.commit();
  say("wrote " + o.out + (o.vtu.empty() ? "" : " and " + o.vtu));
  return ok;
}
} // namespace

void add_adapt(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<AdaptOptions>();
  auto* cmd = app.add_subcommand(
      "adapt",
      "Adapt a templated mesh (.tmesh from generate --templated) on its templates (Section 5.2): "
      "bisect the longest edge of cells that match --refine-where, smooth vertices (boundary "
      "vertices inside their patch, with their related copies), improve quality by smoothing and "
      "flips, and make it Delaunay (Technique 5.8); --clone first gives instances their own "
      "template, --split-where then splits templates along a cell set, --merge-identical and "
      "--merge-congruent last merge identical or congruent templates (Section 5.2.1). Steps run "
      "in that order; every instance of a template changes alike, so the mesh "
      "stays templated and symmetric, and the result is certified conforming before it is "
      "written.");
  cmd->add_option("mesh", o->in, "templated mesh (.tmesh)")->required();
  cmd->add_option("-o,--output", o->out, "adapted templated mesh (.tmesh)")->required();
  cmd->add_option("--vtu", o->vtu, "also write the structure instance as .vtu");
  cmd->add_option("--report", o->report, "JSON report: counts before/after, steps, seconds");
  cmd->add_option("--clone", o->clone,
                  "give instance K (global number, template-major, as in the input) its own copy "
                  "of its template, so that later steps can change it alone (Section 5.2.1); "
                  "repeatable; it becomes the last instance, and --refine-where sees the new "
                  "numbers");
  cmd->add_option("--split-where", o->split_where,
                  "split every template whose cells lie on both sides of EXPR, evaluated on the "
                  "template's own cells (x y z: centroid in template coordinates; size quality "
                  "template as for --refine-where): the cells where it holds become a new "
                  "template with the same instances, identified along the cut, so AT is unchanged "
                  "(Section 5.2.1); runs after --clone; repeatable");
  cmd->add_option("--refine-where", o->refine_where,
                  "bisect the longest edge of every cell with an instance image where EXPR holds: "
                  "TERM [and TERM]..., TERM = NAME OP NUMBER, NAME in x y z (centroid) size "
                  "(longest edge) quality (smallest angle, deg) region template instance; "
                  "repeatable");
  cmd->add_option("--smooth", o->smooth,
                  "Laplacian sweeps: template-interior vertices, and template-boundary vertices "
                  "where the boundary is flat, moved with every related vertex (Eq. 5.1)");
  cmd->add_flag("--improve", o->improve,
                "quality pass (Section 5.2.6): quality-increasing smoothing and flips inside "
                "templates (2D: Delaunay flips; 3D: 2-3/3-2 flips raising the smallest dihedral "
                "angle)");
  cmd->add_flag("--delaunay", o->delaunay,
                "make AT Delaunay (Technique 5.8; every interior edge (2D) / triangle (3D) locally "
                "Delaunay; 3D: template boundaries refined until no triangle is encroached, then "
                "TetGen's constrained Delaunay tetrahedralization of each template)");
  cmd->add_flag("--merge-identical", o->merge_identical,
                "last step: merge templates that are identical (the same coordinates and cells) "
                "into one, their instances together (Section 5.2.1)");
  cmd->add_flag("--merge-congruent", o->merge_congruent,
                "last step (after --merge-identical): merge templates congruent by an exact motion "
                "R (R(X_j) = X_i with the coordinates taken exactly: translations, mirrors, signed "
                "permutations; no tolerance) into one, the merged instances' transformations "
                "composed with R^-1 (Section 5.2.1)");
  cmd->add_option("--congruence-tolerance", o->congruence_tolerance,
                  "--merge-congruent: also merge templates congruent only up to this fraction of "
                  "the template's diameter (e.g. 1e-9: copies rotated by 2*pi/n whose coordinates "
                  "were rounded); R is made orthonormal and the merged instances' points move by "
                  "that much at most. Default 0: exact motions only");
  cmd->add_option(
         "--max-rounds", o->max_rounds,
         "Technique 5.8: rounds of interface insertions before giving up (exit 1); 0 = flips only")
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "no progress lines");
  cmd->callback([o, &exit_code] { exit_code = run_adapt(*o); });
}

} // namespace symmesh::apps
