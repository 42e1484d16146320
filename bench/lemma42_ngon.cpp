// Benchmark: the Lemma 4.2 check (interface conformity) of an n-gon slice structure with the
// exact symmesh core, over
//   cyclotomic : symmesh::number::Cyclotomic in K_m, m = lcm(4, n) (cos_2pi / sin_2pi), or
//   core       : CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt::FT
//                (Lazy_exact_nt<CORE::Expr>), cos/sin of 2π/n by half-angle square roots from
//                θ = π/2 (n = 2^k, k >= 2);
//   cyclotomic_lazy (optional, not run by `make bench`): CGAL::Lazy_exact_nt<Cyclotomic>, i.e.
//                K_m behind CGAL's interval filter, the way Epeck wraps its exact type (the
//                exact LP then runs on Cyclotomic itself, ExactOf in core/exact_lp.h).
//
// The structure: one mesh template, a triangulated wedge of angle θ = 2π/n with apex (0,0),
// vertices at the radii 1, 3/2, 5/2 on the radial edge along angle 0 and on the radial edge along
// angle θ (1 + 2·2 = 5 triangles, 7 vertices), instanced n times by T_i = rot(θ)^i about the
// origin, i = 0..n-1 (T_0 = I, T_i = R·T_{i-1}, RigidTransformation::operator*). Neighbouring
// wedges share their radial edges exactly, so AT is an n-gon fan mesh and Lemma 4.2 holds.
//
// One timed run = R = RigidTransformation::rotation_2d(cos θ, sin θ, 0) (which checks
// cos² + sin² = 1 exactly), the template, the n transformations, apply_template (AT, Eq. 4.3:
// exactly-equal points become one vertex) and check_interface_conformity (the Lemma 4.2
// checker over all C(n,2) neighbouring pairs — every two wedges meet at the centre). For
// cyclotomic (and cyclotomic_lazy) the field construction K_m is included, for core the nested
// square roots.
//
// The answer is checked, untimed: the verdict must be "holds", with C(n,2) pairs checked,
// 3n + 1 vertices and 5n triangles in AT. Anything else is a wrong answer: the repeat is
// reported with status "wrong" and the program exits with status 1 (a benchmark whose answer
// is wrong must fail loudly).
//
// Usage: bench_lemma42_ngon --kernel cyclotomic|core|cyclotomic_lazy --n N [--repeats R]
//          [--first-repeat K] [--limit-seconds L] [--memory-limit-mb M] [--header]
//          [--break-conformity]
// (--first-repeat: number of the first repeat in the output, default 1; the driver script runs
// one repeat per call. --break-conformity: a self-check of the harness, moves one template
// vertex so that Lemma 4.2 fails; the run must then end with WRONG ANSWER and exit status 1.)
//
// Every repeat runs in a forked child (bench/forked_timebox.h) killed after L seconds. One CSV
// line per repeat on stdout:
//   n,kernel,repeat,seconds,status,verdict,pairs_checked,vertices,triangles,
//   seconds_transformations,seconds_apply_template,seconds_lemma42
// status is ok, timeout (seconds = L, other fields empty), error or wrong (seconds = wall time
// until the child ended, e.g. ran out of memory under the --memory-limit-mb cap).
#include "forked_timebox.h"

#include <symmesh/core/interface_conformity.h>
#include <symmesh/core/templated_structure.h>
#include <symmesh/number/cyclotomic_cgal.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>
#include <CGAL/Lazy_exact_nt.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

namespace {

using namespace symmesh::core;
using symmesh_bench::WrongAnswer;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// The radii of the template's vertices on both radial edges (numerator, denominator).
constexpr std::array<std::array<int, 2>, 3> radii{{{1, 1}, {3, 2}, {5, 2}}};

/// Self-check of the harness (--break-conformity): the middle radius on the edge along angle θ
/// becomes 7/4, so neighbouring wedges no longer conform and the answer "holds" is wrong.
bool break_conformity = false;

/// The wedge template: apex 0, a_k = (r_k, 0) = vertex 1 + k, b_k = r_k (c, s) = vertex 4 + k.
template <class FT>
ElementComplex<FT, 2> wedge(const FT& c, const FT& s) {
  using P = Point<FT, 2>;
  constexpr VertexId nr = radii.size();
  ElementComplex<FT, 2> m;
  m.points.push_back(P{{FT(0), FT(0)}});
  for (const auto& r : radii) m.points.push_back(P{{FT(r[0]) / FT(r[1]), FT(0)}});
  for (const auto& r : radii) {
    const FT rr = break_conformity && r[0] == 3 ? FT(7) / FT(4) : FT(r[0]) / FT(r[1]);
    m.points.push_back(P{{rr * c, rr * s}});
  }
  const auto a = [](VertexId k) { return 1 + k; };
  const auto b = [](VertexId k) { return 1 + nr + k; };
  m.elements.push_back(Simplex{0, a(0), b(0)});
  for (VertexId k = 0; k + 1 < nr; ++k) {
    m.elements.push_back(Simplex{a(k), a(k + 1), b(k + 1)});
    m.elements.push_back(Simplex{a(k), b(k + 1), b(k)});
  }
  return face_completion(m);
}

struct Timings {
  double transformations = 0, apply_template = 0, lemma42 = 0;
};

/// Builds the n-gon slice structure from cos θ, sin θ (already computed, inside the timed region
/// of the caller), runs AT and the Lemma 4.2 checker, checks the answer; returns the CSV fields
/// verdict,pairs_checked,vertices,triangles and the phase timings.
template <class FT>
std::string ngon_lemma42(long n, const FT& c, const FT& s, Timings& t) {
  using T = RigidTransformation<FT, 2>;
  auto start = Clock::now();
  const T r = T::rotation_2d(c, s, Point<FT, 2>{{FT(0), FT(0)}});
  TemplatedStructure<FT, 2> x;
  x.templates.push_back({"wedge", TemplateKind::mesh, wedge(c, s)});
  std::vector<InstanceSpec<FT, 2>> inst;
  inst.reserve(static_cast<std::size_t>(n));
  T ti; // T_0 = I
  for (long i = 0; i < n; ++i) {
    inst.push_back({ti, 1});
    if (i + 1 < n) ti = r * ti;
  }
  x.instances.push_back(std::move(inst));
  t.transformations += seconds_since(start);

  start = Clock::now();
  const auto si = apply_template(x);
  t.apply_template = seconds_since(start);

  start = Clock::now();
  const Lemma42Verdict v = check_interface_conformity(x, si);
  t.lemma42 = seconds_since(start);

  // The exact answer (untimed, counts only).
  const std::size_t pairs = static_cast<std::size_t>(n * (n - 1) / 2);
  const std::size_t vertices = static_cast<std::size_t>(radii.size() * n + 1);
  const std::size_t triangles = static_cast<std::size_t>((2 * radii.size() - 1) * n);
  const std::size_t got_triangles = si.at.cell_region.size();
  if (!v.holds)
    throw WrongAnswer("Lemma 4.2 verdict 'fails' for the n-gon slice structure, n = " +
                      std::to_string(n) + ": pair " + to_string(v.a) + ", " + to_string(v.b) +
                      ", condition " + std::to_string(v.condition) + ": " + v.detail);
  if (v.pairs_checked != pairs || si.at.mesh.points.size() != vertices ||
      got_triangles != triangles)
    throw WrongAnswer(
        "n = " + std::to_string(n) + ": expected " + std::to_string(pairs) + " pairs, " +
        std::to_string(vertices) + " vertices, " + std::to_string(triangles) + " triangles; got " +
        std::to_string(v.pairs_checked) + ", " + std::to_string(si.at.mesh.points.size()) + ", " +
        std::to_string(got_triangles));
  return "holds," + std::to_string(v.pairs_checked) + ',' +
         std::to_string(si.at.mesh.points.size()) + ',' + std::to_string(got_triangles);
}

std::string format_row(double seconds, const std::string& fields, const Timings& t) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "%.6f,ok,%s,%.6f,%.6f,%.6f", seconds, fields.c_str(),
                t.transformations, t.apply_template, t.lemma42);
  return buffer;
}

std::string run_cyclotomic(long n) {
  using symmesh::number::Cyclotomic;
  using symmesh::number::CyclotomicField;
  Timings t;
  const auto start = Clock::now();
  const int m = std::lcm(4, static_cast<int>(n));
  const auto field = CyclotomicField::get(m);
  const Cyclotomic c = field->cos_2pi(1, n);
  const Cyclotomic s = field->sin_2pi(1, n);
  t.transformations = seconds_since(start);
  const std::string fields = ngon_lemma42<Cyclotomic>(n, c, s, t);
  return format_row(seconds_since(start), fields, t);
}

std::string run_cyclotomic_lazy(long n) {
  using symmesh::number::Cyclotomic;
  using symmesh::number::CyclotomicField;
  using L = CGAL::Lazy_exact_nt<Cyclotomic>;
  Timings t;
  const auto start = Clock::now();
  const int m = std::lcm(4, static_cast<int>(n));
  const auto field = CyclotomicField::get(m);
  const L c(field->cos_2pi(1, n));
  const L s(field->sin_2pi(1, n));
  t.transformations = seconds_since(start);
  const std::string fields = ngon_lemma42<L>(n, c, s, t);
  return format_row(seconds_since(start), fields, t);
}

std::string run_core(long n) {
  using FT = CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt::FT;
  if (n < 4) throw std::invalid_argument("core: n must be a power of two >= 4");
  Timings t;
  const auto start = Clock::now();
  long k = 4;                    // θ = 2π/k
  FT cos_theta(0), sin_theta(1); // θ = π/2
  while (k < n) {
    // cos(θ/2) = sqrt((1 + cos θ)/2), sin(θ/2) = sqrt((1 − cos θ)/2), 0 < θ/2 < π/2.
    const FT half_cos = CGAL::sqrt((FT(1) + cos_theta) / FT(2));
    const FT half_sin = CGAL::sqrt((FT(1) - cos_theta) / FT(2));
    cos_theta = half_cos;
    sin_theta = half_sin;
    k *= 2;
  }
  if (k != n) throw std::invalid_argument("core: n must be a power of two >= 4");
  t.transformations = seconds_since(start);
  const std::string fields = ngon_lemma42<FT>(n, cos_theta, sin_theta, t);
  return format_row(seconds_since(start), fields, t);
}

struct Options {
  std::string kernel;
  long n = 0;
  int repeats = 1;
  int first_repeat = 1;
  double limit_seconds = 60;
  long memory_limit_mb = 4096;
  bool header = false;
  bool break_conformity = false;
};

[[noreturn]] void usage(const char* message) {
  std::cerr
      << "bench_lemma42_ngon: " << message << "\n"
      << "usage: bench_lemma42_ngon --kernel cyclotomic|core|cyclotomic_lazy --n N [--repeats R]"
         " [--first-repeat K] [--limit-seconds L] [--memory-limit-mb M] [--header]"
         " [--break-conformity]\n";
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(("missing value for " + arg).c_str());
      return argv[++i];
    };
    try {
      if (arg == "--kernel")
        o.kernel = value();
      else if (arg == "--n")
        o.n = std::stol(value());
      else if (arg == "--repeats")
        o.repeats = std::stoi(value());
      else if (arg == "--first-repeat")
        o.first_repeat = std::stoi(value());
      else if (arg == "--limit-seconds")
        o.limit_seconds = std::stod(value());
      else if (arg == "--memory-limit-mb")
        o.memory_limit_mb = std::stol(value());
      else if (arg == "--header")
        o.header = true;
      else if (arg == "--break-conformity")
        o.break_conformity = true;
      else
        usage(("unknown argument " + arg).c_str());
    } catch (const std::logic_error&) {
      usage(("bad value for " + arg).c_str());
    }
  }
  if (o.kernel != "cyclotomic" && o.kernel != "core" && o.kernel != "cyclotomic_lazy")
    usage("--kernel must be cyclotomic, core or cyclotomic_lazy");
  if (o.n < 3 || o.n > 4096) usage("--n must be in 3..4096");
  if (o.repeats < 1) usage("--repeats must be >= 1");
  if (o.first_repeat < 1) usage("--first-repeat must be >= 1");
  if (!(o.limit_seconds > 0)) usage("--limit-seconds must be > 0");
  return o;
}

} // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  break_conformity = o.break_conformity;
  if (o.header)
    std::cout << "n,kernel,repeat,seconds,status,verdict,pairs_checked,vertices,triangles,"
                 "seconds_transformations,seconds_apply_template,seconds_lemma42\n"
              << std::flush;
  bool wrong = false;
  for (int r = o.first_repeat; r < o.first_repeat + o.repeats; ++r) {
    const auto result = symmesh_bench::run_forked(
        [&] {
          if (o.kernel == "cyclotomic") return run_cyclotomic(o.n);
          if (o.kernel == "cyclotomic_lazy") return run_cyclotomic_lazy(o.n);
          return run_core(o.n);
        },
        o.limit_seconds, o.memory_limit_mb, "bench_lemma42_ngon");
    std::cout << o.n << ',' << o.kernel << ',' << r << ',';
    switch (result.status) {
    case symmesh_bench::ForkedResult::Status::ok:
      std::cout << result.output;
      break;
    case symmesh_bench::ForkedResult::Status::timeout: {
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "%.6f,timeout,,,,,,,", o.limit_seconds);
      std::cout << buffer;
      break;
    }
    default: {
      wrong = wrong || result.status == symmesh_bench::ForkedResult::Status::wrong;
      char buffer[64];
      std::snprintf(buffer, sizeof buffer, "%.6f,", result.seconds);
      std::cout << buffer << symmesh_bench::to_string(result.status) << ",,,,,,,";
    }
    }
    std::cout << '\n' << std::flush;
  }
  if (wrong) {
    std::cerr << "bench_lemma42_ngon: WRONG ANSWER for kernel " << o.kernel << ", n = " << o.n
              << " (see above); failing\n";
    return 1;
  }
  return 0;
}
