// The FEM benchmark of Section 7.6 (issue 17, docs/benchmarks/fem.md; driver bench/fem.py).
//
// bench_fem EXAMPLE SIZE REPEATS CG_RTOL [--tcsr-only]: generates the built-in templated geometry
// EXAMPLE (an n-gon slice or an n-TSV) at SIZE with `--method auto`'s method, assembles the TCSR
// (every template's stiffness once) and the CSR of Algorithm 7.1 (the conventional matrix), and
// prints one JSON line: unknowns, bytes of the conventional mesh (MRMESH of AT) and of the
// templated mesh (Listing 4.1; with Listing 4.2's SVB; with the compact SVB), bytes of CSR and
// TCSR, and the median seconds of one matrix-vector product — own CSR, own TCSR (Algorithm 7.2),
// PETSc MATAIJ, PETSc MATSHELL of the TCSR — timed side by side, REPEATS rounds interleaved (each
// round times each of them once, in turn); and the seconds of CG with Jacobi to CG_RTOL on the
// TCSR and on the CSR (0: skipped). All with the whole boundary Dirichlet and source 1.
// --tcsr-only (a structure instance too large for the CSR): no CSR, no PETSc; the TCSR product
// and 50 CG iterations on it are timed, and the peak RSS is reported.
#include "symmesh/fem/boundary_conditions.h"
#include "symmesh/fem/conjugate_gradient.h"
#include "symmesh/fem/petsc_solver.h"
#include "symmesh/fem/templated_csr.h"
#include "symmesh/gen/templated_tetrahedral_mesh.h"
#include "symmesh/gen/templated_triangle_mesh.h"
#include "symmesh/io/examples.h"
#include "symmesh/io/templated_structure_json.h"
#include "symmesh/mesh/structure_instance.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <sys/resource.h>

using namespace symmesh;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

mesh::TemplatedMeshCompactSvb generate(const io::AnyStructure& x, double size, std::string& m) {
  gen::GenerationOptions o;
  o.size = size;
  return std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        gen::GenerationResult r;
        if constexpr (std::is_same_v<S, io::Structure2> ||
                      std::is_same_v<S, io::CyclotomicStructure2>)
          r = gen::generate_triangle_mesh(s, gen::Method::automatic, o);
        else
          r = gen::generate_tetrahedral_mesh(s, gen::Method::automatic, o);
        m = r.method;
        return std::move(r.templated);
      },
      x);
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 5 && argc != 6) {
    std::cerr << "usage: bench_fem EXAMPLE SIZE REPEATS CG_RTOL [--tcsr-only]\n";
    return 2;
  }
  const bool tcsr_only = argc == 6 && std::string(argv[5]) == "--tcsr-only";
  const std::string example = argv[1];
  const double size = std::stod(argv[2]);
  const int repeats = std::stoi(argv[3]);
  const double cg_rtol = std::stod(argv[4]);
  fem::PetscSession petsc;
  std::string why;
  if (!petsc.start(&why)) {
    std::cerr << why << "\n";
    return 2;
  }
  nlohmann::ordered_json j;
  j["example"] = example;
  j["size"] = size;
  auto t0 = Clock::now();
  std::string method;
  const auto t =
      generate(io::parse_templated_structure(io::example_document(example).dump()), size, method);
  j["method"] = method;
  j["seconds_generate"] = since(t0);
  const mesh::StructureInstance at(t);
  const int dim = at.dimension();
  const std::size_t nv = at.vertex_count(), nc = at.cell_count();
  const std::size_t k = std::size_t(dim) + 1;
  j["cells"] = nc;
  j["instances"] = at.instance_count();
  // MRMESH of AT (Listing 2.2): coordinates, types, indices, offsets, regions.
  j["bytes_mesh_conventional"] = nv * std::size_t(dim) * 8 + nc * (1 + 4 * k + 2) + 4 * (nc + 1);
  j["bytes_templated"] = t.templated.bytes();
  j["bytes_templated_svb"] = mesh::to_listing_4_2(t).bytes();
  j["bytes_templated_compact_svb"] = t.bytes();
  t0 = Clock::now();
  auto a = fem::assemble_templated_csr(t, [](mesh::RegionIdType r) { return 1.0 + 0.25 * r; });
  fem::BoundaryConditions bc;
  bc.source = 1;
  bc.dirichlet.push_back({{"all", {}, {}, {}, {}, {}}, 0.0});
  std::vector<double> u0;
  const auto b = fem::apply_boundary_conditions(a, t, bc, u0);
  j["seconds_assemble_tcsr"] = since(t0);
  j["unknowns"] = a.unknowns;
  j["bytes_tcsr"] = a.bytes();
  if (tcsr_only) {
    std::vector<double> x(a.unknowns, 1.0), y(a.unknowns);
    std::vector<double> times;
    for (int r = 0; r < repeats; ++r) {
      const auto s = Clock::now();
      a.multiply(x.data(), y.data());
      times.push_back(since(s));
    }
    j["matvec_seconds"] = {{"tcsr", median(times)}};
    fem::CgOptions o;
    o.rtol = 1e-300;
    o.max_iterations = 50;
    auto u = u0;
    const auto s = Clock::now();
    fem::conjugate_gradients([&](const double* p, double* q) { a.multiply(p, q); }, a.diagonal(), b,
                             u, o);
    j["cg_50_iterations_seconds"] = since(s);
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    j["peak_rss_bytes"] = ru.ru_maxrss * 1024L;
    std::cout << j.dump() << std::endl;
    return 0;
  }
  t0 = Clock::now();
  const auto csr = a.to_csr();
  j["seconds_algorithm_7_1"] = since(t0);
  j["nonzeros"] = csr.nonzeros();
  j["bytes_csr"] = csr.bytes();
  std::vector<double> x(a.unknowns, 1.0), y(a.unknowns);
  csr.multiply(x.data(), y.data()); // warm-up
  a.multiply(x.data(), y.data());
  std::vector<double> own_csr, own_tcsr, petsc_aij, petsc_shell;
  // Several products per timing when one is short, so that the clock's resolution does not count.
  const int inner = a.unknowns < 100000 ? 20 : 1;
  for (int r = 0; r < repeats; ++r) {
    auto s = Clock::now();
    for (int i = 0; i < inner; ++i) csr.multiply(x.data(), y.data());
    own_csr.push_back(since(s) / inner);
    s = Clock::now();
    for (int i = 0; i < inner; ++i) a.multiply(x.data(), y.data());
    own_tcsr.push_back(since(s) / inner);
    petsc_aij.push_back(petsc.matvec_seconds(a, false, 3));
    petsc_shell.push_back(petsc.matvec_seconds(a, true, 3));
  }
  j["matvec_seconds"] = {{"csr", median(own_csr)},
                         {"tcsr", median(own_tcsr)},
                         {"petsc_aij", median(petsc_aij)},
                         {"petsc_shell", median(petsc_shell)}};
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  j["peak_rss_bytes"] = ru.ru_maxrss * 1024L;
  j["matvec_all"] = {
      {"csr", own_csr}, {"tcsr", own_tcsr}, {"petsc_aij", petsc_aij}, {"petsc_shell", petsc_shell}};
  if (cg_rtol > 0) {
    fem::CgOptions o;
    o.rtol = cg_rtol;
    std::vector<double> cg_csr, cg_tcsr;
    std::size_t iterations = 0;
    for (int r = 0; r < repeats; ++r) {
      auto u = u0;
      auto s = Clock::now();
      const auto rc = fem::conjugate_gradients(
          [&](const double* p, double* q) { csr.multiply(p, q); }, csr.diagonal(), b, u, o);
      cg_csr.push_back(since(s));
      u = u0;
      s = Clock::now();
      const auto rt = fem::conjugate_gradients(
          [&](const double* p, double* q) { a.multiply(p, q); }, a.diagonal(), b, u, o);
      cg_tcsr.push_back(since(s));
      iterations = rt.iterations;
      if (rc.iterations != rt.iterations) j["cg_iterations_csr"] = rc.iterations;
    }
    j["cg_rtol"] = cg_rtol;
    j["cg_iterations"] = iterations;
    j["cg_seconds"] = {{"csr", median(cg_csr)}, {"tcsr", median(cg_tcsr)}};
  }
  std::cout << j.dump() << std::endl;
  return 0;
}
