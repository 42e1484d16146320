// The PETSc module (libsymmesh_petsc.so): KSPCG/PCJACOBI on the TCSR operator as a distributed
// MATSHELL, or on the CSR matrix as MATAIJ (spec/fem.md#petsc, petsc_solver.h).
#include "symmesh/fem/petsc_solver.h"

#include <petscksp.h>

#include <algorithm>
#include <string>
#include <vector>

namespace {

constexpr PetscErrorCode kOk = 0; // PETSC_SUCCESS arrives in PETSc 3.19

using symmesh::fem::CgResult;
using symmesh::fem::GlobalIndex;
using symmesh::fem::InstanceMap;
using symmesh::fem::PetscSolveOptions;
using symmesh::fem::TemplatedCsr;

/// This rank's part: instances [first_instance, end_instance), unknowns [rstart, rend) owned,
/// the ghosts (other ranks' unknowns its instances touch) after them in the local form.
struct Part {
  const TemplatedCsr* a = nullptr;
  PetscInt rstart = 0, rend = 0;
  std::vector<PetscInt> ghosts;       ///< sorted global ids
  std::vector<InstanceMap> instances; ///< boundary ids and interior_first in local ids
  std::vector<GlobalIndex> dirichlet; ///< owned Dirichlet unknowns, local ids
  Vec xg = nullptr, yg = nullptr;     ///< ghosted work vectors
  std::size_t local_size() const { return std::size_t(rend - rstart) + ghosts.size(); }
};

GlobalIndex local_id(const Part& p, GlobalIndex g) {
  if (g >= p.rstart && g < p.rend) return g - GlobalIndex(p.rstart);
  const auto it = std::lower_bound(p.ghosts.begin(), p.ghosts.end(), PetscInt(g));
  return GlobalIndex(p.rend - p.rstart) + GlobalIndex(it - p.ghosts.begin());
}

/// Contiguous blocks of instances with about N / size unknowns each.
void split(const TemplatedCsr& a, int rank, int size, Part& p) {
  std::vector<std::size_t> end(a.instances.size());
  for (std::size_t k = 0; k < a.instances.size(); ++k) {
    const auto& t = a.templates[a.instances[k].template_index];
    end[k] = std::size_t(a.instances[k].interior_first) + (t.vertices - t.boundary);
  }
  const auto block_start = [&](int r) -> std::size_t { // first instance of rank r
    const std::size_t target = a.unknowns * std::size_t(r) / std::size_t(size);
    return std::size_t(std::upper_bound(end.begin(), end.end(), target) - end.begin());
  };
  const std::size_t k0 = rank == 0 ? 0 : block_start(rank);
  const std::size_t k1 = rank == size - 1 ? a.instances.size() : block_start(rank + 1);
  p.a = &a;
  p.rstart = PetscInt(k0 == 0 ? 0 : end[k0 - 1]);
  p.rend = PetscInt(k1 == 0 ? 0 : end[k1 - 1]);
  if (k1 <= k0) p.rend = p.rstart;
  for (std::size_t k = k0; k < k1; ++k)
    for (GlobalIndex g : a.instances[k].boundary_ids()) {
      const GlobalIndex u = g < 0 ? -1 - g : g;
      if (u < p.rstart || u >= p.rend) p.ghosts.push_back(u);
    }
  std::sort(p.ghosts.begin(), p.ghosts.end());
  p.ghosts.erase(std::unique(p.ghosts.begin(), p.ghosts.end()), p.ghosts.end());
  for (std::size_t k = k0; k < k1; ++k) {
    InstanceMap in = a.instances[k];
    in.interior_first = local_id(p, in.interior_first);
    auto ids = in.boundary_ids();
    for (auto& g : ids) g = g < 0 ? -1 - local_id(p, -1 - g) : local_id(p, g);
    in.set_boundary(ids);
    p.instances.push_back(std::move(in));
  }
  for (GlobalIndex d : a.dirichlet)
    if (d >= p.rstart && d < p.rend) p.dirichlet.push_back(d - GlobalIndex(p.rstart));
}

/// Algorithm 7.2 on this rank's instances: x's owned part and ghosts in, A x's owned part out
/// (the ghost rows' partial sums are added to their owners by the reverse scatter).
PetscErrorCode shell_mult(Mat m, Vec x, Vec y) {
  Part* p = nullptr;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(m, &p));
  PetscCall(VecCopy(x, p->xg));
  PetscCall(VecGhostUpdateBegin(p->xg, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGhostUpdateEnd(p->xg, INSERT_VALUES, SCATTER_FORWARD));
  Vec xl = nullptr, yl = nullptr;
  PetscCall(VecGhostGetLocalForm(p->xg, &xl));
  PetscCall(VecGhostGetLocalForm(p->yg, &yl));
  const PetscScalar* xa = nullptr;
  PetscScalar* ya = nullptr;
  PetscCall(VecGetArrayRead(xl, &xa));
  PetscCall(VecGetArray(yl, &ya));
  symmesh::fem::multiply_instances(p->a->templates, p->instances, p->local_size(), p->dirichlet, xa,
                                   ya, true);
  PetscCall(VecRestoreArray(yl, &ya));
  PetscCall(VecRestoreArrayRead(xl, &xa));
  PetscCall(VecGhostRestoreLocalForm(p->yg, &yl));
  PetscCall(VecGhostRestoreLocalForm(p->xg, &xl));
  PetscCall(VecGhostUpdateBegin(p->yg, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecGhostUpdateEnd(p->yg, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecCopy(p->yg, y));
  PetscFunctionReturn(kOk);
}

/// The diagonal summed per instance (Dirichlet rows: 1), without forming the matrix.
PetscErrorCode shell_diagonal(Mat m, Vec d) {
  Part* p = nullptr;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(m, &p));
  Vec dl = nullptr;
  PetscCall(VecSet(p->yg, 0.0));
  PetscCall(VecGhostGetLocalForm(p->yg, &dl));
  PetscScalar* da = nullptr;
  PetscCall(VecGetArray(dl, &da));
  symmesh::fem::add_diagonal_instances(p->a->templates, p->instances, true, da);
  PetscCall(VecRestoreArray(dl, &da));
  PetscCall(VecGhostRestoreLocalForm(p->yg, &dl));
  PetscCall(VecGhostUpdateBegin(p->yg, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecGhostUpdateEnd(p->yg, ADD_VALUES, SCATTER_REVERSE));
  PetscCall(VecCopy(p->yg, d));
  PetscScalar* owned = nullptr;
  PetscCall(VecGetArray(d, &owned));
  for (GlobalIndex g : p->dirichlet) owned[g] = 1.0;
  PetscCall(VecRestoreArray(d, &owned));
  PetscFunctionReturn(kOk);
}

/// The CSR matrix of Algorithm 7.1 as MATAIJ, this rank's rows.
PetscErrorCode aij_matrix(const TemplatedCsr& a, const Part& p, Mat* m) {
  PetscFunctionBeginUser;
  const auto csr = a.to_csr(true);
  const PetscInt n = p.rend - p.rstart;
  std::vector<PetscInt> rows(std::size_t(n) + 1), cols;
  std::vector<PetscScalar> vals;
  for (PetscInt r = 0; r < n; ++r) {
    const auto g = std::size_t(p.rstart + r);
    for (auto e = csr.row_start[g]; e < csr.row_start[g + 1]; ++e) {
      cols.push_back(PetscInt(csr.column[std::size_t(e)]));
      vals.push_back(csr.value[std::size_t(e)]);
    }
    rows[std::size_t(r) + 1] = PetscInt(cols.size());
  }
  PetscCall(MatCreate(PETSC_COMM_WORLD, m));
  PetscCall(MatSetSizes(*m, n, n, PetscInt(a.unknowns), PetscInt(a.unknowns)));
  PetscCall(MatSetType(*m, MATAIJ));
  PetscCall(MatSeqAIJSetPreallocationCSR(*m, rows.data(), cols.data(), vals.data()));
  PetscCall(MatMPIAIJSetPreallocationCSR(*m, rows.data(), cols.data(), vals.data()));
  PetscFunctionReturn(kOk);
}

struct Monitor {
  const PetscSolveOptions* o = nullptr;
  double bnorm = 1;
  int rank = 0;
};

PetscErrorCode monitor(KSP, PetscInt it, PetscReal rnorm, void* ctx) {
  auto* m = static_cast<Monitor*>(ctx);
  if (m->rank == 0 && m->o->on_progress) m->o->on_progress(std::size_t(it), rnorm / m->bnorm);
  return kOk;
}

PetscErrorCode solve(const TemplatedCsr& a, const std::vector<double>& b, std::vector<double>& x,
                     const PetscSolveOptions& o, CgResult& r) {
  PetscFunctionBeginUser;
  PetscMPIInt rank = 0, size = 1;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  Part p;
  split(a, rank, size, p);
  const PetscInt n = p.rend - p.rstart, N = PetscInt(a.unknowns);
  PetscCall(
      VecCreateGhost(PETSC_COMM_WORLD, n, N, PetscInt(p.ghosts.size()), p.ghosts.data(), &p.xg));
  PetscCall(VecDuplicate(p.xg, &p.yg));
  Vec vb = nullptr, vx = nullptr;
  PetscCall(VecCreateMPI(PETSC_COMM_WORLD, n, N, &vb));
  PetscCall(VecDuplicate(vb, &vx));
  PetscScalar *ba = nullptr, *xa = nullptr;
  PetscCall(VecGetArray(vb, &ba));
  PetscCall(VecGetArray(vx, &xa));
  for (PetscInt i = 0; i < n; ++i) {
    ba[i] = b[std::size_t(p.rstart + i)];
    xa[i] = x[std::size_t(p.rstart + i)];
  }
  PetscCall(VecRestoreArray(vx, &xa));
  PetscCall(VecRestoreArray(vb, &ba));
  Mat m = nullptr;
  if (o.shell) {
    PetscCall(MatCreateShell(PETSC_COMM_WORLD, n, n, N, N, &p, &m));
    PetscCall(MatShellSetOperation(m, MATOP_MULT, reinterpret_cast<void (*)(void)>(shell_mult)));
    PetscCall(MatShellSetOperation(m, MATOP_GET_DIAGONAL,
                                   reinterpret_cast<void (*)(void)>(shell_diagonal)));
  } else {
    PetscCall(aij_matrix(a, p, &m));
  }
  KSP ksp = nullptr;
  PC pc = nullptr;
  PetscCall(KSPCreate(PETSC_COMM_WORLD, &ksp));
  PetscCall(KSPSetOperators(ksp, m, m));
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCJACOBI));
  PetscCall(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED));
  PetscCall(KSPSetTolerances(ksp, o.rtol, 0.0, PETSC_DEFAULT, PetscInt(o.max_iterations)));
  PetscCall(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE));
  Monitor mon;
  mon.o = &o;
  mon.rank = rank;
  PetscReal bnorm = 0;
  PetscCall(VecNorm(vb, NORM_2, &bnorm));
  mon.bnorm = bnorm > 0 ? bnorm : 1;
  PetscCall(KSPMonitorSet(ksp, monitor, &mon, nullptr));
  PetscCall(KSPSolve(ksp, vb, vx));
  PetscInt its = 0;
  PetscReal rnorm = 0;
  KSPConvergedReason reason;
  PetscCall(KSPGetIterationNumber(ksp, &its));
  PetscCall(KSPGetResidualNorm(ksp, &rnorm));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  r.iterations = std::size_t(its);
  r.relative_residual = bnorm > 0 ? rnorm / bnorm : rnorm;
  r.converged = reason > 0;
  // The whole solution on every rank.
  VecScatter all = nullptr;
  Vec everything = nullptr;
  PetscCall(VecScatterCreateToAll(vx, &all, &everything));
  PetscCall(VecScatterBegin(all, vx, everything, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(all, vx, everything, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar* ea = nullptr;
  PetscCall(VecGetArrayRead(everything, &ea));
  x.assign(ea, ea + N);
  PetscCall(VecRestoreArrayRead(everything, &ea));
  PetscCall(VecScatterDestroy(&all));
  PetscCall(VecDestroy(&everything));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&m));
  PetscCall(VecDestroy(&vx));
  PetscCall(VecDestroy(&vb));
  PetscCall(VecDestroy(&p.yg));
  PetscCall(VecDestroy(&p.xg));
  PetscFunctionReturn(kOk);
}

/// Median seconds of one MatMult over `repeats` timed calls (after one warm-up), one rank.
PetscErrorCode matvec_seconds(const TemplatedCsr& a, bool shell, int repeats, double& seconds) {
  PetscFunctionBeginUser;
  Part p;
  split(a, 0, 1, p);
  const PetscInt N = PetscInt(a.unknowns);
  PetscCall(VecCreateGhost(PETSC_COMM_WORLD, N, N, 0, nullptr, &p.xg));
  PetscCall(VecDuplicate(p.xg, &p.yg));
  Vec x = nullptr, y = nullptr;
  PetscCall(VecCreateMPI(PETSC_COMM_WORLD, N, N, &x));
  PetscCall(VecDuplicate(x, &y));
  PetscCall(VecSet(x, 1.0));
  Mat m = nullptr;
  if (shell) {
    PetscCall(MatCreateShell(PETSC_COMM_WORLD, N, N, N, N, &p, &m));
    PetscCall(MatShellSetOperation(m, MATOP_MULT, reinterpret_cast<void (*)(void)>(shell_mult)));
  } else {
    PetscCall(aij_matrix(a, p, &m));
  }
  PetscCall(MatMult(m, x, y));
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const double t0 = MPI_Wtime();
    PetscCall(MatMult(m, x, y));
    t.push_back(MPI_Wtime() - t0);
  }
  std::sort(t.begin(), t.end());
  seconds = t[t.size() / 2];
  PetscCall(MatDestroy(&m));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&p.yg));
  PetscCall(VecDestroy(&p.xg));
  PetscFunctionReturn(kOk);
}

} // namespace

extern "C" {

/// For the FEM benchmark (bench/fem_bench.cpp): PETSc's MatMult time of the MATSHELL (shell != 0)
/// or of the MATAIJ of Algorithm 7.1.
__attribute__((visibility("default"))) int symmesh_petsc_matvec_seconds(const TemplatedCsr* a,
                                                                        int shell, int repeats,
                                                                        double* seconds,
                                                                        std::string* error) {
  if (matvec_seconds(*a, shell != 0, repeats, *seconds) != kOk) {
    *error = "MatMult timing failed";
    return 1;
  }
  return 0;
}

__attribute__((visibility("default"))) int symmesh_petsc_start(int* rank, int* size,
                                                               std::string* error) {
  if (PetscInitializeNoArguments() != kOk) {
    *error = "PetscInitialize failed";
    return 1;
  }
  // Errors come back as codes (and a message below), not as PETSc's traceback on stderr.
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  PetscMPIInt r = 0, s = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  MPI_Comm_size(PETSC_COMM_WORLD, &s);
  *rank = r;
  *size = s;
  return 0;
}

__attribute__((visibility("default"))) void symmesh_petsc_finish() {
  PetscFinalize();
}

__attribute__((visibility("default"))) int
symmesh_petsc_solve(const TemplatedCsr* a, const std::vector<double>* b, std::vector<double>* x,
                    const PetscSolveOptions* o, CgResult* r, std::string* error) {
  const PetscErrorCode e = solve(*a, *b, *x, *o, *r);
  if (e != kOk) {
    const char* text = nullptr;
    PetscErrorMessage(e, &text, nullptr);
    *error =
        std::string("error ") + std::to_string(int(e)) + (text ? std::string(": ") + text : "");
    return 1;
  }
  return 0;
}
}
