// Opens the PETSc module on first use (spec/fem.md#petsc, petsc_solver.h).
#include "symmesh/fem/petsc_solver.h"

#include "symmesh/mesh/module_path.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace symmesh::fem {
namespace {

std::vector<std::string> module_candidates() {
  static const char here = 0; // an address inside the object this loader is linked into
#ifdef SYMMESH_PETSC_MODULE_PATH
  return mesh::module_candidates("libsymmesh_petsc.so", SYMMESH_PETSC_MODULE_PATH, &here);
#else
  return mesh::module_candidates("libsymmesh_petsc.so", nullptr, &here);
#endif
}

void* module_handle(std::string* why) {
  static void* handle = nullptr;
  static std::string failure;
  static bool tried = false;
  if (!tried) {
    tried = true;
    std::string looked;
    for (const auto& path : module_candidates()) {
      if (!std::filesystem::exists(path)) {
        looked += (looked.empty() ? "" : ", ") + path;
        continue;
      }
      // GLOBAL: Open MPI's own plugins resolve libmpi's symbols from the global scope.
      handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
      if (!handle) failure = std::string("cannot load ") + path + ": " + dlerror();
      break;
    }
    if (!handle && failure.empty())
      failure = "libsymmesh_petsc.so not found (looked at " + looked + ")";
  }
  if (!handle && why) *why = "PETSc unavailable: " + failure;
  return handle;
}

template <class Entry>
Entry entry(const char* name) {
  std::string why;
  void* h = module_handle(&why);
  if (!h) throw std::runtime_error(why);
  const auto e = reinterpret_cast<Entry>(dlsym(h, name));
  if (!e) throw std::runtime_error(std::string("PETSc module: no entry point ") + name);
  return e;
}

} // namespace

bool PetscSession::start(std::string* why) {
  if (started_) return true;
  if (!module_handle(why)) return false;
  using Start = int (*)(int*, int*, std::string*);
  std::string error;
  if (entry<Start>("symmesh_petsc_start")(&rank_, &size_, &error) != 0) {
    if (why) *why = error;
    return false;
  }
  started_ = true;
  return true;
}

PetscSession::~PetscSession() {
  if (!started_) return;
  using Finish = void (*)();
  entry<Finish>("symmesh_petsc_finish")();
}

CgResult PetscSession::solve(const TemplatedCsr& a, const std::vector<double>& b,
                             std::vector<double>& x, const PetscSolveOptions& o) {
  if (!started_) throw std::logic_error("PetscSession::solve before start");
  using Solve = int (*)(const TemplatedCsr*, const std::vector<double>*, std::vector<double>*,
                        const PetscSolveOptions*, CgResult*, std::string*);
  CgResult r;
  std::string error;
  if (entry<Solve>("symmesh_petsc_solve")(&a, &b, &x, &o, &r, &error) != 0)
    throw std::invalid_argument("PETSc: " + error);
  return r;
}

double PetscSession::matvec_seconds(const TemplatedCsr& a, bool shell, int repeats) {
  if (!started_) throw std::logic_error("PetscSession::matvec_seconds before start");
  using Time = int (*)(const TemplatedCsr*, int, int, double*, std::string*);
  double seconds = 0;
  std::string error;
  if (entry<Time>("symmesh_petsc_matvec_seconds")(&a, shell ? 1 : 0, repeats, &seconds, &error))
    throw std::runtime_error("PETSc: " + error);
  return seconds;
}

} // namespace symmesh::fem
