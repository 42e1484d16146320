/// Where an optional module (a shared object opened on first use: the Gmsh peer, PETSc) is looked
/// for — spec/generation.md#gmsh, spec/fem.md#petsc, docs/api.md#modules: in $SYMMESH_MODULE_DIR
/// when set, next to the running executable (an installed or copied tree), beside the shared
/// object the loader is linked into and in its symmesh/ folder (libsymmesh.so of an installed
/// package, which the Python module also loads), then where the build put it.
#pragma once
#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace symmesh::mesh {

/// `here`: the address of an object defined in the loader's own translation unit, from which
/// dladdr finds the shared object the loader is linked into; nullptr skips those candidates.
inline std::vector<std::string> module_candidates(const std::string& file_name,
                                                  const char* build_path,
                                                  const void* here = nullptr) {
  std::vector<std::string> out;
  const auto add = [&](const std::filesystem::path& p) {
    if (std::find(out.begin(), out.end(), p.string()) == out.end()) out.push_back(p.string());
  };
  if (const char* dir = std::getenv("SYMMESH_MODULE_DIR"); dir && *dir)
    add(dir / std::filesystem::path(file_name));
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) add(exe.parent_path() / file_name);
  Dl_info info{};
  if (here && dladdr(here, &info) && info.dli_fname && *info.dli_fname) {
    const auto dir = std::filesystem::absolute(info.dli_fname, ec).parent_path();
    if (!ec) {
      add(dir / file_name);
      add(dir / "symmesh" / file_name);
    }
  }
  if (build_path) add(build_path);
  return out;
}

} // namespace symmesh::mesh
