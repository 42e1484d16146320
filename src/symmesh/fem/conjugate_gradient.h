/// Conjugate gradients with Jacobi preconditioning — spec/fem.md#cg
///
/// The same iteration for the TCSR operator (Algorithm 7.2) and the CSR reference, so that their
/// solutions and iteration counts can be compared: only the operator and its diagonal differ.
/// Stops when ‖r‖₂ ≤ rtol · ‖b‖₂ (PETSc's default unpreconditioned-norm test is the
/// preconditioned one; spec/fem.md#cg says how the two are made to agree).
#pragma once
#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <vector>

namespace symmesh::fem {

struct CgOptions {
  double rtol = 1e-12;
  std::size_t max_iterations = 100000;
  /// Called every `report_every` iterations and at the end with (iteration, ‖r‖₂ / ‖b‖₂).
  std::function<void(std::size_t, double)> on_progress;
  std::size_t report_every = 100;
};

struct CgResult {
  std::size_t iterations = 0;
  double relative_residual = 0;
  bool converged = false;
};

/// Solves A x = b for symmetric positive definite A given as apply(x, y) (y = A x) with diagonal
/// `diagonal`. x holds the initial guess and receives the solution.
/// \pre diagonal entries positive (else std::invalid_argument: the system is singular)
template <class Apply>
CgResult conjugate_gradients(Apply&& apply, const std::vector<double>& diagonal,
                             const std::vector<double>& b, std::vector<double>& x,
                             const CgOptions& o = {}) {
  const std::size_t n = b.size();
  for (double d : diagonal)
    if (!(d > 0) || !std::isfinite(d))
      throw std::invalid_argument("the system matrix has a non-positive diagonal entry");
  std::vector<double> r(n), z(n), p(n), q(n);
  apply(x.data(), q.data());
  double bb = 0, rz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    r[i] = b[i] - q[i];
    z[i] = r[i] / diagonal[i];
    p[i] = z[i];
    rz += r[i] * z[i];
    bb += b[i] * b[i];
  }
  const double bnorm = std::sqrt(bb);
  CgResult res;
  const auto residual = [&] {
    double rr = 0;
    for (double v : r) rr += v * v;
    return bnorm > 0 ? std::sqrt(rr) / bnorm : std::sqrt(rr);
  };
  res.relative_residual = residual();
  if (bnorm == 0) {
    std::fill(x.begin(), x.end(), 0.0);
    res.converged = true;
    res.relative_residual = 0;
    return res;
  }
  while (res.relative_residual > o.rtol && res.iterations < o.max_iterations) {
    apply(p.data(), q.data());
    double pq = 0;
    for (std::size_t i = 0; i < n; ++i) pq += p[i] * q[i];
    if (!(pq > 0)) throw std::invalid_argument("the system matrix is not positive definite");
    const double alpha = rz / pq;
    double rz_new = 0, rr = 0;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += alpha * p[i];
      r[i] -= alpha * q[i];
      z[i] = r[i] / diagonal[i];
      rz_new += r[i] * z[i];
      rr += r[i] * r[i];
    }
    const double beta = rz_new / rz;
    rz = rz_new;
    for (std::size_t i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
    ++res.iterations;
    res.relative_residual = std::sqrt(rr) / bnorm;
    if (o.on_progress && res.iterations % o.report_every == 0)
      o.on_progress(res.iterations, res.relative_residual);
  }
  res.converged = res.relative_residual <= o.rtol;
  if (o.on_progress) o.on_progress(res.iterations, res.relative_residual);
  return res;
}

} // namespace symmesh::fem
