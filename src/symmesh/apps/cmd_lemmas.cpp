// symmesh lemmas [--cases N] [--seed S] [--only Lemma_4_2] [--dim D] [--drop-hypothesis]
#include "symmesh/apps/commands.h"

#include <chrono>
#include <cstdio>
#include <iostream>

#ifdef SYMMESH_HAVE_PROOFS
#include "proofs-checks/registry.h"
#endif

namespace symmesh::apps {
namespace {
struct LemmaOptions {
  int cases = 300;
  std::uint64_t seed = 20261122;
  std::vector<std::string> only;
  int dim = 0;
  bool dropped = false;
  bool list = false;
  bool quiet = false;
  std::string out = "counterexamples";
};

#ifdef SYMMESH_HAVE_PROOFS
bool selected(const proofs::Property& p, const LemmaOptions& o) {
  if (o.dim && p.dimension != o.dim) return false;
  if (o.dropped && !p.make_dropped) return false;
  if (o.only.empty()) return true;
  for (const auto& k : o.only)
    if (p.lemma == k) return true;
  return false;
}

int run_lemmas(const LemmaOptions& o) {
  if (o.cases < 1) {
    print_error("--cases must be at least 1");
    return bad_input;
  }
  std::vector<const proofs::Property*> todo;
  for (const auto& p : proofs::all_properties())
    if (selected(p, o)) todo.push_back(&p);
  if (todo.empty()) {
    print_error("no lemma property matches the selection (see symmesh lemmas --list)");
    return bad_input;
  }
  if (o.list) {
    for (const auto* p : todo)
      std::cout << p->lemma << "\t" << p->name << "\t" << p->dimension << "D\t"
                << (p->kind == proofs::Kind::holds ? "holds" : "counterexample") << "\t"
                << p->statement << "\n";
    return ok;
  }
  proofs::RunOptions ro;
  ro.cases = o.cases;
  ro.seed = o.seed;
  ro.counterexample_dir = o.out;
  ro.dropped = o.dropped;
  int failed = 0;
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t k = 0;
  for (const auto* p : todo) {
    ++k;
    const auto t = std::chrono::steady_clock::now();
    const auto out = proofs::run(*p, ro);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    const bool good = o.dropped ? !out.passed : out.passed;
    failed += !good;
    char line[512];
    std::snprintf(
        line, sizeof line, "%-28s %-44s %dD %-14s %5d cases  %-8s %7.2f s", p->lemma.c_str(),
        p->name.c_str(), p->dimension, p->kind == proofs::Kind::holds ? "holds" : "counterexample",
        out.cases,
        o.dropped ? (out.passed ? "MISSED" : "caught") : (out.passed ? "passed" : "FAILED"), s);
    std::cout << line << "\n";
    if (!out.counterexample_path.empty())
      std::cout << "    counterexample: " << out.counterexample_path << "\n";
    if (!out.passed && !o.dropped) std::cout << "    " << out.message << "\n";
    if (!o.quiet) {
      const double el =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "[lemmas] %zu/%zu properties, %d failed, %.1f s elapsed\n", k,
                   todo.size(), failed, el);
    }
  }
  std::cout << (todo.size() - failed) << " passed, " << failed << " failed\n";
  std::cout << "seed " << o.seed << ", " << o.cases << " cases per property"
            << (o.dropped ? " (hypothesis dropped: a failure is the expected outcome)" : "")
            << "\n";
  return failed ? negative : ok;
}
#endif
} // namespace

void add_lemmas(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<LemmaOptions>();
  auto* cmd = app.add_subcommand(
      "lemmas", "Check the dissertation's lemmas on random 2D and 3D templated structures in exact "
                "arithmetic (RapidCheck). One line per property; a failing case is shrunk and "
                "written to the counterexample folder as JSON (+ SVG in 2D).");
  cmd->add_option("--cases", o->cases, "successful random cases per property")
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "random seed (runs are reproducible)")->capture_default_str();
  cmd->add_option("--only", o->only, "only these lemmas, e.g. Lemma_4_2 (repeatable)");
  cmd->add_option("--dim", o->dim, "only 2D or only 3D properties")->check(CLI::IsMember({2, 3}));
  cmd->add_flag("--drop-hypothesis", o->dropped,
                "run each conclusion on inputs that violate a hypothesis: every check must fail "
                "(shows that the checks can fail); counterexamples are written");
  cmd->add_flag("--list", o->list, "list the properties and exit");
  cmd->add_option("--out", o->out, "folder for counterexamples")->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "no progress lines on stderr");
#ifdef SYMMESH_HAVE_PROOFS
  cmd->callback([o, &exit_code] { exit_code = run_lemmas(*o); });
#else
  cmd->callback([&exit_code] {
    print_error("this build has no proofs-checks (configure with -DSYMMESH_BUILD_TESTS=ON)");
    exit_code = bad_input;
  });
#endif
}

} // namespace symmesh::apps
