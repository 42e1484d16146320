/// Registry of lemma properties — spec/traceability.md#lemma-to-proofs-checks
///
/// Every proofs-checks file registers RapidCheck properties here, so that ctest (label `proofs`)
/// and `symmesh lemmas` run the very same code. A property of kind `holds` generates only inputs
/// satisfying the lemma's hypotheses and asserts its conclusion; a `counterexample` property
/// drops one hypothesis and asserts that the conclusion then fails on the generated family.
/// `dropped` (when set) runs the `holds` conclusion on the hypothesis-dropping generator: it must
/// fail, which shows that the check can fail; `symmesh lemmas --drop-hypothesis` uses it.
#pragma once
#include <rapidcheck.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace symmesh::proofs {

enum class Kind { holds, counterexample };

struct Property {
  std::string lemma; ///< e.g. "Lemma_4_2" (the --only key)
  std::string name;  ///< e.g. "conclusion_2d"
  int dimension = 2; ///< 2 or 3
  Kind kind = Kind::holds;
  std::string statement;                              ///< what is asserted, in words
  std::function<rc::detail::Property()> make;         ///< the property
  std::function<rc::detail::Property()> make_dropped; ///< optional: conclusion without a hypothesis
};

using RegisterFn = void (*)(std::vector<Property>&);

/// All properties of all proofs-checks files, in a fixed order.
const std::vector<Property>& all_properties();

struct RunOptions {
  int cases = 300;               ///< successful cases required per property
  std::uint64_t seed = 20261122; ///< fixed by default: runs are reproducible
  bool seed_from_env = false;    ///< RC_PARAMS seed=... overrides
  std::string counterexample_dir = "counterexamples";
  bool write_counterexamples = true;
  bool dropped = false; ///< run make_dropped instead of make
};

struct Outcome {
  bool passed = false;
  int cases = 0;
  std::uint64_t seed = 0;
  std::string message;             ///< RapidCheck's failure description
  std::string counterexample_path; ///< JSON file written for a failure
};

/// Runs one property with RapidCheck (max_success = cases, seed fixed), shrinking on failure and
/// writing the last failing case (the shrunk one) to counterexample_dir as JSON (+ SVG in 2D).
Outcome run(const Property& p, const RunOptions& options);

/// Called by property bodies just before a failing RC_ASSERT: the text of the failing case.
void record_failure(const std::string& lemma_case_json, const std::string& svg = {});

/// Asserts `cond`; on failure records the case (producers are only called on failure).
#define SYMMESH_PROOF_ASSERT(cond, json_producer, svg_producer)                                    \
  do {                                                                                             \
    const bool symmesh_ok_ = static_cast<bool>(cond);                                              \
    if (!symmesh_ok_) ::symmesh::proofs::record_failure((json_producer)(), (svg_producer)());      \
    RC_ASSERT(symmesh_ok_);                                                                        \
  } while (0)

} // namespace symmesh::proofs
