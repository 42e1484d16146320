// libFuzzer harness: feeds arbitrary bytes to the templated-structure JSON reader and, when they
// parse, to the full analysis (Eq. 4.2, AT, Lemma 4.2, instance graph). Bad input must surface as
// InputError or a negative verdict — never a crash, hang or other exception.
#include "symmesh/core/structure_report.h"
#include "symmesh/io/templated_structure_json.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0; // keep structures small: the analysis is quadratic
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto x = symmesh::io::parse_templated_structure(text, "fuzz");
    const auto r = std::visit([](const auto& s) { return symmesh::core::analyse(s); }, x);
    if (r.templated_structure && r.mesh_templates && !r.lemma42_agrees) __builtin_trap();
  } catch (const symmesh::io::InputError&) {
  }
  return 0;
}
