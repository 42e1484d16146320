/// Where an optional module (a shared object opened on first use: the Gmsh peer, PETSc) is looked
/// for — spec/generation.md#gmsh, spec/fem.md#petsc: next to the running executable (an installed
/// or copied tree), then where the build put it.
#pragma once
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace symmesh::mesh {

inline std::vector<std::string> module_candidates(const std::string& file_name,
                                                  const char* build_path) {
  std::vector<std::string> out;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back((exe.parent_path() / file_name).string());
  if (build_path) out.push_back(build_path);
  return out;
}

} // namespace symmesh::mesh
