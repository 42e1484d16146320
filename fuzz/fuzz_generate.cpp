// libFuzzer harness: `symmesh generate` on small templated geometries (2D and 3D) made from
// arbitrary bytes — the reader, the method choice, the boundary patch partition, the line and
// surface meshes, the mesher and the Lemma 4.2 certificate, through the same run as the CLI
// (api/generate_run.h). The first byte picks the size and the method (auto, bpp, conventional or
// merge, the interface sewing of Section 5.1.1); the rest is the JSON
// document. Every outcome must be a certified templated mesh or a refusal with the CLI's
// bad-input exit code (a one-line message); a certificate failure on generated output, any other
// exception, a crash or a hang is a finding.
#include "symmesh/api/generate_run.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2 || size > 4096) return 0;
  static const char* const methods[] = {"auto", "bpp", "conventional", "merge"};
  symmesh::api::RunOptions o;
  o.method = methods[data[0] % 4];
  o.size = 0.05 * double(1 + (data[0] >> 2) % 8); // 0.05 … 0.4
  o.min_angle = 20;
  o.max_cells = 20000; // refuse (exit 2) anything larger: the harness must stay fast
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    symmesh::api::check_method(o);
    symmesh::api::check_numbers(o);
    const auto x = symmesh::api::parse_structure_text(text, "fuzz");
    const auto r = symmesh::api::run_generation(x, "fuzz", o);
    (void)r;
  } catch (const symmesh::api::Refusal& e) {
    // Generated output that fails its own certificate is a bug, not bad input. The one other
    // negative outcome is documented: --method merge giving up on a structure whose
    // transformations carry hanging points to ever new places (spec/generation.md#merge).
    // In 3D the give-up is the overlay still differing after its rounds (#merge-3d).
    const std::string what = e.what();
    const bool merge_gave_up =
        o.method == "merge" && (what.find("still has hanging vertices") != std::string::npos ||
                                what.find("still differs after") != std::string::npos);
    if (e.exit_code() != symmesh::api::kBadInput && !merge_gave_up) __builtin_trap();
  }
  return 0;
}
