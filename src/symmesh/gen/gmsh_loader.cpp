// Opens the Gmsh module on first use (spec/generation.md#gmsh, #gmsh-3d, gmsh_mesher.h).
#include "symmesh/gen/gmsh_mesher.h"
#include "symmesh/gen/triangle_mesher.h"

#include "symmesh/mesh/module_path.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace symmesh::gen {
namespace {

std::vector<std::string> module_candidates() {
  static const char here = 0; // an address inside the object this loader is linked into
#ifdef SYMMESH_GMSH_MODULE_PATH
  return mesh::module_candidates("libsymmesh_gmsh.so", SYMMESH_GMSH_MODULE_PATH, &here);
#else
  return mesh::module_candidates("libsymmesh_gmsh.so", nullptr, &here);
#endif
}

/// The module's handle, opened once; throws MeshingError when it cannot be.
void* module_handle() {
  static std::once_flag once;
  static void* handle = nullptr;
  static std::string failure;
  std::call_once(once, [] {
    std::string tried;
    for (const auto& path : module_candidates()) {
      if (!std::filesystem::exists(path)) {
        tried += (tried.empty() ? "" : ", ") + path;
        continue;
      }
      // LOCAL: Gmsh's symbols (among them its own copy of TetGen's classes) stay out of the
      // global scope, so libtet keeps binding to itself. (DEEPBIND would also keep Gmsh off
      // libtet's copy, but it breaks libstdc++'s locale facets in the module: std::bad_cast.)
      handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) failure = std::string("cannot load ") + path + ": " + dlerror();
      return;
    }
    failure = "libsymmesh_gmsh.so not found (looked at " + tried + ")";
  });
  if (!handle) throw MeshingError("Gmsh baseline unavailable: " + failure);
  return handle;
}

/// The module's entry point `name` of type Entry (an extern "C" function of gmsh_mesher.cpp).
template <class Entry>
Entry load_entry(const char* name) {
  void* handle = module_handle();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, name));
  if (!entry)
    throw MeshingError(std::string("Gmsh baseline unavailable: no entry point ") + name +
                       " in libsymmesh_gmsh.so");
  return entry;
}

} // namespace

GmshTriangles mesh_with_gmsh(const PlanarRegions& regions, double size) {
  using Entry = int (*)(const PlanarRegions*, double, GmshTriangles*, std::string*);
  static const Entry entry = load_entry<Entry>("symmesh_mesh_with_gmsh");
  GmshTriangles out;
  std::string error;
  if (entry(&regions, size, &out, &error) != 0) throw MeshingError(error);
  return out;
}

/// spec/generation.md#gmsh-3d
GmshTetrahedra mesh_with_gmsh_3d(const ClosedSurfaces& regions, double size) {
  using Entry = int (*)(const ClosedSurfaces*, double, GmshTetrahedra*, std::string*);
  static const Entry entry = load_entry<Entry>("symmesh_mesh_with_gmsh_3d");
  GmshTetrahedra out;
  std::string error;
  if (entry(&regions, size, &out, &error) != 0) throw MeshingError(error);
  return out;
}

} // namespace symmesh::gen
