// libFuzzer harness: feeds arbitrary bytes to the templated-mesh reader (.tmesh, spec/outputs.md
// #tmesh) and, when they read, to the structure instance view the writers and `render` use.
// Bad input must surface as InputError (a one-line message naming the field) — never a crash, a
// hang, another exception, or a mesh that reads but is not valid.
#include "symmesh/io/templated_mesh_file.h"
#include "symmesh/io/templated_structure_json.h"
#include "symmesh/mesh/structure_instance.h"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {
/// read_tmesh reads a path: one file per process, rewritten for every input.
const std::string& scratch_path() {
  static const std::string path =
      "/tmp/symmesh-fuzz-tmesh-" + std::to_string(::getpid()) + ".tmesh";
  return path;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 1 << 16) return 0;
  {
    std::ofstream out(scratch_path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  try {
    const auto t = symmesh::io::read_tmesh(scratch_path());
    // read_tmesh validates what it returns (the file's \pre for every consumer).
    if (!t.is_valid()) __builtin_trap();
    const symmesh::mesh::StructureInstance at(t);
    if (at.instance_count() != t.templated.instance_count()) __builtin_trap();
  } catch (const symmesh::io::InputError&) {
  }
  return 0;
}
