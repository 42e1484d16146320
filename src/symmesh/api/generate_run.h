/// One generation run as `symmesh generate` does it, shared by the CLI and the public API
/// (symmesh.h) — spec/generation.md, docs/api.md#generate
///
/// Reading a templated geometry, checking the options, refusing an infeasible size before any
/// work, running the chosen method and the Lemma 4.2 certificate, and the report. Every refusal
/// is a Refusal carrying the CLI's exit code and its one-line message, so that the CLI, the C++
/// API and the Python module say the same thing for the same input.
#pragma once
#include "symmesh/gen/templated_triangle_mesh.h"
#include "symmesh/io/templated_structure_json.h"
#include "symmesh/mesh/progress.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace symmesh::api {

/// The CLI's exit codes (apps/commands.h) for the two kinds of refusal.
inline constexpr int kBadInput = 2, kNegative = 1;

/// A refusal: what() is the one-line message the CLI prints after "symmesh: error: ".
class Refusal : public std::runtime_error {
public:
  Refusal(int exit_code, const std::string& message)
      : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

private:
  int exit_code_;
};

struct RunOptions {
  std::string method = "auto"; ///< a name of `generate --method`
  double size = 0, min_angle = 20;
  double max_cells = 0;        ///< 0: the default from the machine's memory
  bool repair_outliers = true; ///< 3D: the outlier repair after TetGen (generate --no-repair)
  double tetgen_dihedral =
      mesh::kDihedralBoundDeg; ///< 3D: TetGen's -q/D (generate --tetgen-dihedral; 0: none)
  mesh::Progress* progress = nullptr;
};

/// Refuses (kBadInput) an unknown method, a size that is not positive, a smallest angle outside
/// [0, 33.8] and a negative max_cells, with the CLI's messages.
void check_method(const RunOptions& o);
void check_numbers(const RunOptions& o);

/// Reads a templated structure from a file or from JSON text; every reader error is a Refusal
/// (kBadInput) with the reader's message.
io::AnyStructure read_structure_file(const std::string& path);
io::AnyStructure parse_structure_text(const std::string& text, const std::string& source);

/// Runs generation as `symmesh generate` does. `source` names the input in messages.
/// \pre check_method(o) and check_numbers(o) passed.
/// Throws Refusal: kBadInput for an infeasible size, input the method cannot take or a mesher
/// failure; kNegative when the generated templated mesh fails the Lemma 4.2 certificate.
gen::GenerationResult run_generation(const io::AnyStructure& x, const std::string& source,
                                     const RunOptions& o);

/// The JSON report of `generate --report` (docs/api.md#report) for a certified run
/// that took `seconds` to generate and `write_seconds` to write.
nlohmann::ordered_json generation_report(const gen::GenerationResult& r, const RunOptions& o,
                                         double seconds, double write_seconds);

/// Peak resident set size of this process, in bytes (getrusage).
std::size_t peak_rss_bytes();

} // namespace symmesh::api
