// Runner and registration list of the lemma properties.
#include "proofs-checks/registry.h"

#include <rapidcheck/detail/Configuration.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace symmesh::proofs {

// One registration function per proofs-checks file (defined there).
void register_lemma_2_1(std::vector<Property>&);
void register_lemma_2_2(std::vector<Property>&);
void register_lemma_2_3(std::vector<Property>&);
void register_lemma_2_4(std::vector<Property>&);
void register_lemma_2_5(std::vector<Property>&);
void register_lemma_2_6(std::vector<Property>&);
void register_lemma_2_7(std::vector<Property>&);
void register_lemma_4_1(std::vector<Property>&);
void register_lemma_4_2(std::vector<Property>&);
void register_lemma_4_3(std::vector<Property>&);
void register_lemma_4_4(std::vector<Property>&);
void register_lemma_4_5(std::vector<Property>&);
void register_lemma_6_1(std::vector<Property>&);
void register_lemma_6_2(std::vector<Property>&);
void register_lemma_A_1(std::vector<Property>&);
void register_lemma_A_2(std::vector<Property>&);
void register_lemma_A_3(std::vector<Property>&);
void register_lemma_A_4(std::vector<Property>&);
void register_at_multi_region_equivalence(std::vector<Property>&);
void register_bpp_invariance(std::vector<Property>&);
void register_algorithm_6_2(std::vector<Property>&);
void register_cyclotomic_field(std::vector<Property>&);
void register_lemma_4_1_cyclotomic(std::vector<Property>&);
void register_lemma_4_2_cyclotomic(std::vector<Property>&);
void register_section_5_2_1(std::vector<Property>&);
void register_section_5_2_1_tmesh(std::vector<Property>&);
void register_section_5_2_2(std::vector<Property>&);
void register_section_5_2_2_tmesh(std::vector<Property>&);
void register_section_5_2_3(std::vector<Property>&);
void register_section_5_2_4(std::vector<Property>&);
void register_section_5_2_6(std::vector<Property>&);
void register_section_6_3(std::vector<Property>&);
void register_technique_5_8(std::vector<Property>&);

const std::vector<Property>& all_properties() {
  static const std::vector<Property> props = [] {
    std::vector<Property> p;
    for (RegisterFn f : {register_lemma_2_1,
                         register_lemma_2_2,
                         register_lemma_2_3,
                         register_lemma_2_4,
                         register_lemma_2_5,
                         register_lemma_2_6,
                         register_lemma_2_7,
                         register_lemma_4_1,
                         register_lemma_4_2,
                         register_lemma_4_3,
                         register_lemma_4_4,
                         register_lemma_4_5,
                         register_lemma_6_1,
                         register_lemma_6_2,
                         register_lemma_A_1,
                         register_lemma_A_2,
                         register_lemma_A_3,
                         register_lemma_A_4,
                         register_at_multi_region_equivalence,
                         register_bpp_invariance,
                         register_algorithm_6_2,
                         register_cyclotomic_field,
                         register_lemma_4_1_cyclotomic,
                         register_lemma_4_2_cyclotomic,
                         register_section_5_2_1,
                         register_section_5_2_1_tmesh,
                         register_section_5_2_2,
                         register_section_5_2_2_tmesh,
                         register_section_5_2_3,
                         register_section_5_2_4,
                         register_section_5_2_6,
                         register_section_6_3,
                         register_technique_5_8})
      f(p);
    return p;
  }();
  return props;
}

namespace {
struct Failure {
  bool set = false;
  std::string json, svg;
};
thread_local Failure last_failure;
} // namespace

void record_failure(const std::string& json, const std::string& svg) {
  last_failure = Failure{true, json, svg};
}

Outcome run(const Property& p, const RunOptions& o) {
  // RapidCheck reads RC_PARAMS once and, without it, announces a random seed that this runner
  // then overrides; give it ours first so that its announcement is the seed actually used.
  static const bool user_params = std::getenv("RC_PARAMS") != nullptr;
  if (!user_params) setenv("RC_PARAMS", ("seed=" + std::to_string(o.seed)).c_str(), 0);
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  const char* env = user_params ? std::getenv("RC_PARAMS") : nullptr;
  const bool env_seed = env && std::string(env).find("seed") != std::string::npos;
  const bool env_cases = env && std::string(env).find("max_success") != std::string::npos;
  if (!env_seed) params.seed = o.seed;
  if (!env_cases || params.maxSuccess < o.cases) params.maxSuccess = o.cases;
  rc::detail::TestMetadata meta;
  meta.id = p.lemma + "." + p.name;
  meta.description = p.statement;
  last_failure = Failure{};
  const auto prop = o.dropped && p.make_dropped ? p.make_dropped() : p.make();
  const auto result = rc::detail::checkProperty(prop, meta, params);
  Outcome out;
  out.seed = params.seed;
  out.cases = params.maxSuccess;
  if (result.template is<rc::detail::SuccessResult>()) {
    out.passed = true;
    return out;
  }
  std::ostringstream msg;
  rc::detail::printResultMessage(result, msg);
  out.message = msg.str();
  if (o.write_counterexamples && last_failure.set) {
    namespace fs = std::filesystem;
    fs::create_directories(o.counterexample_dir);
    const std::string stem =
        o.counterexample_dir + "/" + p.lemma + "_" + p.name + (o.dropped ? "_dropped" : "");
    std::ofstream(stem + ".json") << last_failure.json << "\n";
    if (!last_failure.svg.empty()) std::ofstream(stem + ".svg") << last_failure.svg;
    out.counterexample_path = stem + ".json";
  }
  return out;
}

} // namespace symmesh::proofs
