/// PETSc as the solver engine of `symmesh solve` — spec/fem.md#petsc
///
/// The TCSR operator becomes a MATSHELL (its mult is Algorithm 7.2, its diagonal is summed per
/// instance) under KSPCG with PCJACOBI; the CSR reference becomes a MATAIJ. Instances are
/// distributed over the MPI ranks in contiguous blocks: the TCSR's instance-major numbering then
/// gives every rank a contiguous range of unknowns, the unknowns its instances share with other
/// ranks are PETSc ghost entries, and the interface values travel by the ghosts' scatters
/// (forward for x, reverse-add for A x). Every rank reads the mesh (the setup is replicated; the
/// solve is distributed), and the solution is gathered on every rank.
///
/// PETSc and MPI live in a module (libsymmesh_petsc.so) opened on first use, like the Gmsh peer:
/// the other commands do not pay for loading them.
#pragma once
#include "symmesh/fem/conjugate_gradient.h"
#include "symmesh/fem/templated_csr.h"

#include <functional>
#include <string>
#include <vector>

namespace symmesh::fem {

struct PetscSolveOptions {
  double rtol = 1e-12;
  std::size_t max_iterations = 100000;
  bool shell = true; ///< MATSHELL of the TCSR operator; false: MATAIJ of Algorithm 7.1's CSR
  std::function<void(std::size_t, double)> on_progress; ///< (iteration, ‖r‖₂/‖b‖₂), rank 0
};

/// PetscInitialize on start() (MPI_Init under mpirun), PetscFinalize on destruction.
class PetscSession {
public:
  PetscSession() = default;
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;
  ~PetscSession();

  /// False (with the reason) when the module or PETSc cannot be loaded.
  bool start(std::string* why);
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Solves the constrained system; x: the initial guess in, the whole solution out (every rank).
  /// ‖r‖₂ ≤ rtol ‖b‖₂ on the unpreconditioned residual, as conjugate_gradients does.
  CgResult solve(const TemplatedCsr& a, const std::vector<double>& b, std::vector<double>& x,
                 const PetscSolveOptions& o);
  /// The median seconds of one PETSc MatMult (MATSHELL of the TCSR, or MATAIJ of its CSR) over
  /// `repeats` calls, on one rank (the FEM benchmark).
  double matvec_seconds(const TemplatedCsr& a, bool shell, int repeats);

private:
  bool started_ = false;
  int rank_ = 0, size_ = 1;
};

} // namespace symmesh::fem
