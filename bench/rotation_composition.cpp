// Micro-benchmark: compose the exact rotation rot(2π/n) n times and decide exactly whether the
// product is the identity, with
//   cyclotomic : symmesh::number::Cyclotomic in K_lcm(4,n) (cos_2pi / sin_2pi), or
//   core       : CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt::FT (CORE::Expr),
//                cos/sin of 2π/n by half-angle square roots from θ = π/2 (n = 2^k, k >= 2).
//
// Usage: bench_rotation_composition --type cyclotomic|core --n N [--repeats R] [--first-repeat K]
//                                   [--limit-seconds L] [--memory-limit-mb M] [--header]
// (--first-repeat: number of the first repeat in the output, default 1.)
//
// Every repeat runs in a forked child process (fresh caches, fresh CORE DAG) that the parent
// kills after L seconds. One CSV line per repeat on stdout:
//   type,n,repeat,seconds,is_identity,status
// status is ok, timeout (seconds is then the limit, is_identity empty) or error (the child died,
// e.g. out of memory under the --memory-limit-mb address-space limit). `seconds` is wall time
// in the child for building the matrix, the n − 1 matrix products and the exact identity test.
#include "forked_timebox.h"

#include <symmesh/number/cyclotomic.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel_with_sqrt.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>

namespace {

template <class T>
using Matrix = std::array<std::array<T, 2>, 2>;

template <class T>
Matrix<T> multiply(const Matrix<T>& a, const Matrix<T>& b) {
  Matrix<T> r;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j];
  return r;
}

/// R^n by n − 1 successive products P ← P·R, then the exact test P == I.
template <class T>
bool compose_is_identity(const Matrix<T>& rotation, long n) {
  Matrix<T> p = rotation;
  for (long i = 1; i < n; ++i) p = multiply(p, rotation);
  const T one(1), zero(0);
  return p[0][0] == one && p[0][1] == zero && p[1][0] == zero && p[1][1] == one;
}

bool run_cyclotomic(long n) {
  using symmesh::number::Cyclotomic;
  using symmesh::number::CyclotomicField;
  const int m = symmesh::number::smallest_field_for_orders({static_cast<int>(n)});
  const auto field = CyclotomicField::get(m);
  const Cyclotomic c = field->cos_2pi(1, n);
  const Cyclotomic s = field->sin_2pi(1, n);
  const Matrix<Cyclotomic> rotation{{{c, -s}, {s, c}}};
  return compose_is_identity(rotation, n);
}

bool run_core(long n) {
  using FT = CGAL::Exact_predicates_exact_constructions_kernel_with_sqrt::FT;
  long k = 4; // θ = 2π/k
  if (n < 4) throw std::invalid_argument("core: n must be a power of two >= 4");
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
  const Matrix<FT> rotation{{{cos_theta, -sin_theta}, {sin_theta, cos_theta}}};
  return compose_is_identity(rotation, n);
}

struct Options {
  std::string type;
  long n = 0;
  int repeats = 1;
  int first_repeat = 1;
  double limit_seconds = 60;
  long memory_limit_mb = 4096;
  bool header = false;
};

[[noreturn]] void usage(const char* message) {
  std::cerr << "bench_rotation_composition: " << message << "\n"
            << "usage: bench_rotation_composition --type cyclotomic|core --n N [--repeats R]"
               " [--first-repeat K] [--limit-seconds L] [--memory-limit-mb M] [--header]\n";
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
      if (arg == "--type")
        o.type = value();
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
      else
        usage(("unknown argument " + arg).c_str());
    } catch (const std::logic_error&) {
      usage(("bad value for " + arg).c_str());
    }
  }
  if (o.type != "cyclotomic" && o.type != "core") usage("--type must be cyclotomic or core");
  if (o.n < 3) usage("--n must be >= 3");
  if (o.repeats < 1) usage("--repeats must be >= 1");
  if (o.first_repeat < 1) usage("--first-repeat must be >= 1");
  if (!(o.limit_seconds > 0)) usage("--limit-seconds must be > 0");
  return o;
}

/// One repeat in a forked, time-boxed child (forked_timebox.h). Returns the CSV fields
/// seconds,is_identity,status.
std::string run_once(const Options& o) {
  const auto result = symmesh_bench::run_forked(
      [&] {
        const auto start = std::chrono::steady_clock::now();
        const bool identity = o.type == "cyclotomic" ? run_cyclotomic(o.n) : run_core(o.n);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        char line[64];
        std::snprintf(line, sizeof line, "%.6f,%s", seconds, identity ? "true" : "false");
        return std::string(line);
      },
      o.limit_seconds, o.memory_limit_mb, "bench_rotation_composition");
  char fields[128];
  switch (result.status) {
  case symmesh_bench::ForkedResult::Status::ok:
    return result.output + ",ok";
  case symmesh_bench::ForkedResult::Status::timeout:
    std::snprintf(fields, sizeof fields, "%.6f,,timeout", o.limit_seconds);
    return fields;
  default:
    return ",,error";
  }
}

} // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  if (o.header) std::cout << "type,n,repeat,seconds,is_identity,status\n" << std::flush;
  for (int r = o.first_repeat; r < o.first_repeat + o.repeats; ++r) {
    const std::string fields = run_once(o);
    std::cout << o.type << ',' << o.n << ',' << r << ',' << fields << '\n' << std::flush;
  }
  return 0;
}
