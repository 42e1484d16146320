// symmesh solve MESH.tmesh --bc BC.json [--coefficient REGION=VALUE ...] [--ksp-rtol R]
//                [--solver tcsr|csr|petsc|petsc-aij] -o SOLUTION.vtu [--templated U.tmesh]
//                [--report R.json] [--quiet]
//
// P1 FEM on a templated mesh (spec/fem.md): the stiffness matrix assembled once per template
// (TCSR), boundary conditions on the structure instance's boundary, conjugate gradients with
// Jacobi preconditioning on the TCSR operator (Algorithm 7.2), on the CSR matrix of Algorithm 7.1,
// or in PETSc (the TCSR operator as a MATSHELL, or the CSR as MATAIJ). The solution is written as
// point data "u" of the structure instance, and on request per template (each instance's values
// over its template's vertices) in a .tmesh.
#include "symmesh/apps/commands.h"
#include "symmesh/fem/boundary_conditions.h"
#include "symmesh/fem/conjugate_gradient.h"
#include "symmesh/fem/petsc_solver.h"
#include "symmesh/fem/templated_csr.h"
#include "symmesh/io/boundary_conditions_json.h"
#include "symmesh/io/mesh_writers.h"
#include "symmesh/io/templated_mesh_file.h"
#include "symmesh/io/templated_structure_json.h"
#include "symmesh/mesh/progress.h"
#include "symmesh/mesh/structure_instance.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace symmesh::apps {
namespace {

struct SolveOptions {
  std::string mesh, bc, out, report, templated, solver = "tcsr";
  std::vector<std::string> coefficients, reactions;
  double rtol = 1e-12;
  std::size_t max_iterations = 100000;
  bool quiet = false;
};

std::map<mesh::RegionIdType, double> parse_coefficients(const std::vector<std::string>& list,
                                                        const std::string& option = "--coefficient",
                                                        bool zero_allowed = false) {
  std::map<mesh::RegionIdType, double> c;
  for (const auto& item : list) {
    const auto eq = item.find('=');
    const std::string where = option + " " + item;
    if (eq == std::string::npos) throw std::invalid_argument(where + ": expected REGION=VALUE");
    std::size_t used = 0;
    long region = -1;
    double value = 0;
    try {
      region = std::stol(item.substr(0, eq), &used);
      if (used != eq) throw std::invalid_argument("");
      const std::string v = item.substr(eq + 1);
      value = std::stod(v, &used);
      if (used != v.size()) throw std::invalid_argument("");
    } catch (const std::exception&) {
      throw std::invalid_argument(where + ": expected an integer region and a number");
    }
    if (region < 0 || region > 65535)
      throw std::invalid_argument(where + ": the region must be in [0, 65535]");
    if (!(zero_allowed ? value >= 0 : value > 0) || !std::isfinite(value))
      throw std::invalid_argument(where + (zero_allowed ? ": must be a finite number >= 0"
                                                        : ": the coefficient must be a positive "
                                                          "finite number"));
    c[mesh::RegionIdType(region)] = value;
  }
  return c;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

int run_solve(const SolveOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const auto ext = std::filesystem::path(o.out).extension().string();
  if (ext != ".vtu") {
    print_error("-o " + o.out + ": the solution is written as point data of a .vtu file");
    return bad_input;
  }
  const bool petsc = o.solver == "petsc" || o.solver == "petsc-aij";
  if (o.solver != "tcsr" && o.solver != "csr" && !petsc) {
    print_error("--solver " + o.solver + ": expected tcsr, csr, petsc or petsc-aij");
    return bad_input;
  }
  if (!(o.rtol > 0 && o.rtol < 1)) {
    print_error("--ksp-rtol: must be in (0, 1)");
    return bad_input;
  }
  std::unique_ptr<mesh::Progress> progress;
  fem::PetscSession session;
  if (petsc) {
    std::string why;
    if (!session.start(&why)) {
      print_error("--solver " + o.solver + ": " + why);
      return bad_input;
    }
  }
  if (!o.quiet && session.rank() == 0)
    progress = std::make_unique<mesh::Progress>("symmesh solve", std::cerr);
  mesh::TemplatedMeshCompactSvb t;
  fem::TemplatedCsr a;
  std::vector<double> b, u;
  fem::BoundarySummary summary;
  fem::CgResult cg;
  double assembly_seconds = 0, solve_seconds = 0;
  std::size_t csr_bytes = 0;
  try {
    const auto coefficients = parse_coefficients(o.coefficients);
    const auto reactions = parse_coefficients(o.reactions, "--reaction", true);
    const auto bc = io::read_boundary_conditions(o.bc);
    if (progress) progress->stage("reading " + o.mesh, 0, "");
    t = io::read_tmesh(o.mesh);
    const auto coefficient = [&](mesh::RegionIdType r) {
      const auto it = coefficients.find(r);
      return it == coefficients.end() ? 1.0 : it->second;
    };
    for (const auto* given : {&coefficients, &reactions})
      for (const auto& [region, value] : *given) {
        bool used = false;
        for (const auto& tm : t.templated.templates)
          for (auto r : tm.region_ids) used = used || r == region;
        if (!used)
          throw std::invalid_argument(
              std::string(given == &coefficients ? "--coefficient " : "--reaction ") +
              std::to_string(region) + "=" + std::to_string(value) + ": no instance has region " +
              std::to_string(region));
      }
    const auto reaction = [&](mesh::RegionIdType r) {
      const auto it = reactions.find(r);
      return it == reactions.end() ? 0.0 : it->second;
    };
    const auto t0 = std::chrono::steady_clock::now();
    if (progress)
      progress->stage("assembly per template", t.templated.templates.size(), "templates");
    a = fem::assemble_templated_csr(t, coefficient, reaction);
    b = fem::apply_boundary_conditions(a, t, bc, u, &summary);
    assembly_seconds = seconds_since(t0);
    const auto t1 = std::chrono::steady_clock::now();
    fem::CgOptions cgo;
    cgo.rtol = o.rtol;
    cgo.max_iterations = o.max_iterations;
    if (progress) {
      progress->stage("conjugate gradients (" + o.solver + ")", 0, "iterations");
      cgo.on_progress = [&](std::size_t it, double) { progress->set_done(it); };
      cgo.report_every = 1;
    }
    if (o.solver == "tcsr") {
      cg = fem::conjugate_gradients([&](const double* x, double* y) { a.multiply(x, y); },
                                    a.diagonal(), b, u, cgo);
    } else if (o.solver == "csr") {
      const auto m = a.to_csr();
      csr_bytes = m.bytes();
      cg = fem::conjugate_gradients([&](const double* x, double* y) { m.multiply(x, y); },
                                    m.diagonal(), b, u, cgo);
    } else {
      fem::PetscSolveOptions po;
      po.rtol = o.rtol;
      po.max_iterations = o.max_iterations;
      po.shell = o.solver == "petsc";
      po.on_progress = cgo.on_progress;
      cg = session.solve(a, b, u, po);
    }
    solve_seconds = seconds_since(t1);
  } catch (const io::InputError& e) {
    progress.reset();
    print_error(e.what());
    return bad_input;
  } catch (const std::invalid_argument& e) {
    progress.reset();
    print_error(o.mesh + ": " + e.what());
    return bad_input;
  }
  if (!cg.converged) {
    progress.reset();
    print_error(o.mesh + ": conjugate gradients did not reach --ksp-rtol " +
                std::to_string(o.rtol) + " in " + std::to_string(cg.iterations) +
                " iterations (relative residual " + std::to_string(cg.relative_residual) +
                "); no output written");
    return negative;
  }
  if (session.rank() != 0) return ok;
  // The solution in the writer's vertex order (the structure instance view's numbering).
  const mesh::StructureInstance at(t);
  std::vector<double> point_u(at.vertex_count(), 0.0);
  at.for_each_instance([&](const mesh::StructureInstance::Instance& in) {
    const auto& g = *in.global;
    for (std::size_t v = 0; v < g.size(); ++v)
      point_u[std::size_t(g[v])] = u[std::size_t(a.global(in.index, v))];
  });
  io::MeshFileOptions w;
  w.point_data.push_back({"u", &point_u});
  w.progress = progress.get();
  io::write_mesh_file(at, o.out, w);
  if (!o.templated.empty()) {
    // Per template: each instance's values over its template's vertices.
    std::vector<std::vector<double>> per_instance;
    for (std::size_t k = 0; k < a.instances.size(); ++k) {
      const auto& tm = t.templated.templates[a.instances[k].template_index].mesh;
      std::vector<double> values(tm.vertex_count());
      for (std::size_t v = 0; v < values.size(); ++v) values[v] = u[std::size_t(a.global(k, v))];
      per_instance.push_back(std::move(values));
    }
    io::write_tmesh(t, o.templated, {{"u", std::move(per_instance)}});
  }
  double umin = HUGE_VAL, umax = -HUGE_VAL;
  for (double v : u) {
    umin = std::min(umin, v);
    umax = std::max(umax, v);
  }
  if (!o.report.empty()) {
    nlohmann::ordered_json j;
    j["solver"] = o.solver;
    j["unknowns"] = a.unknowns;
    j["dirichlet_unknowns"] = summary.dirichlet_unknowns;
    j["boundary_facets"] = summary.boundary_facets;
    j["dirichlet_facets"] = summary.dirichlet_facets;
    j["neumann_facets"] = summary.neumann_facets;
    j["iterations"] = cg.iterations;
    j["relative_residual"] = cg.relative_residual;
    j["ksp_rtol"] = o.rtol;
    j["ranks"] = session.size();
    j["u_min"] = umin;
    j["u_max"] = umax;
    j["bytes_tcsr"] = a.bytes();
    if (csr_bytes) j["bytes_csr"] = csr_bytes;
    j["seconds"] = seconds_since(start);
    j["seconds_assembly"] = assembly_seconds;
    j["seconds_solve"] = solve_seconds;
    j["peak_rss_bytes"] = peak_rss_bytes();
    std::ofstream os(o.report);
    os << j.dump(2) << "\n";
  }
  if (progress) {
    std::ostringstream line;
    line.precision(3);
    line << a.unknowns << " unknowns, " << cg.iterations << " CG iterations (" << o.solver
         << "), relative residual " << cg.relative_residual << ", u in [" << umin << ", " << umax
         << "], written to " << o.out;
    progress->message(line.str());
  }
  return ok;
}

} // namespace

void add_solve(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<SolveOptions>();
  auto* cmd = app.add_subcommand(
      "solve",
      "Solve -div(k grad u) + s u = f with P1 finite elements on a templated mesh (.tmesh): the "
      "stiffness matrix is assembled once per template (TCSR, Listing 7.1) and CG with "
      "Jacobi preconditioning runs on the templated operator (Algorithm 7.2). Exit 0: "
      "written; 1: CG did not converge (nothing written); 2: bad input.");
  cmd->add_option("mesh", o->mesh, "templated mesh (.tmesh, from generate --templated)")
      ->required();
  cmd->add_option("--bc", o->bc, "boundary conditions (JSON, spec/fem.md#bc-file)")->required();
  cmd->add_option("--coefficient", o->coefficients,
                  "REGION=VALUE: the coefficient k of a region (default 1); repeatable");
  cmd->add_option(
      "--reaction", o->reactions,
      "REGION=VALUE: a reaction coefficient s >= 0 of a region, -div(k grad u) + s u = f "
      "(default 0; the templates' mass matrices are then assembled too); repeatable");
  cmd->add_option("--ksp-rtol", o->rtol, "relative residual tolerance ||r|| <= rtol ||b||")
      ->capture_default_str();
  cmd->add_option("--max-iterations", o->max_iterations, "CG iteration limit")
      ->capture_default_str();
  cmd->add_option("--solver", o->solver,
                  "tcsr (own CG on the templated operator) | csr (own CG on the CSR matrix of "
                  "Algorithm 7.1) | petsc (PETSc KSPCG/PCJACOBI on the templated operator as a "
                  "MATSHELL; mpirun -n N distributes the instances) | petsc-aij (PETSc on the CSR "
                  "matrix as MATAIJ)")
      ->capture_default_str();
  cmd->add_option("-o,--output", o->out, "solution: .vtu with point data u")->required();
  cmd->add_option("--templated", o->templated,
                  "also write the templated mesh with the solution per instance over its "
                  "template's vertices (.tmesh, \"point_data\": {\"u\": …})");
  cmd->add_option("--report", o->report, "JSON report: unknowns, iterations, bytes, seconds");
  cmd->add_flag("--quiet", o->quiet, "no progress lines on stderr");
  cmd->callback([o, &exit_code] { exit_code = run_solve(*o); });
}

} // namespace symmesh::apps
