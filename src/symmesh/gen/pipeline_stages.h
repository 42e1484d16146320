/// The stages of the generation pipeline that are the same code in 2D and 3D, with their timing,
/// page faults and progress lines — spec/generation.md#pipeline: the boundary patch partition
/// (Algorithm 4.1) and the Lemma 4.2 certificate step, after the input checks every generator
/// makes first (whose checker is dimension-specific).
/// Internal to gen/.
#pragma once
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/interface_conformity.h"
#include "symmesh/gen/generation_support.h"
#include "symmesh/gen/templated_triangle_mesh.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace symmesh::gen::support {

/// The preconditions every generator's exact steps rely on: a finite positive size, a
/// well-formed structure (Definition 4.1) and, when `method` is not empty, geometry templates
/// only (`method` names the algorithm in the message, since each states its own requirement).
/// Throws std::invalid_argument with the one line the CLI prints before exiting 2.
template <class FT, int D>
void input_stage(const core::TemplatedStructure<FT, D>& x, const GenerationOptions& o,
                 const std::string& method) {
  if (!(o.size > 0) || !std::isfinite(o.size))
    throw std::invalid_argument("--size must be a positive number");
  if (o.progress) o.progress->stage("templates well-formed", 0, "");
  std::ostringstream why;
  if (!x.is_well_formed(&why)) throw std::invalid_argument(why.str());
  if (!method.empty() && !x.all_of_kind(core::TemplateKind::geometry))
    throw std::invalid_argument(method + " needs geometry templates (\"kind\": \"geometry\")");
}

/// Algorithm 4.1 on `s` (x itself, or the copies a symmetric method needs), timed with the
/// method's symmetry check that preceded it (`symmetry_seconds`, `symmetry_faults`).
/// \pre s.is_well_formed() was checked by the caller
template <class FT, int D>
core::BoundaryPatchPartition<FT, D>
boundary_patch_stage(const core::TemplatedStructure<FT, D>& s, const GenerationOptions& o,
                     double symmetry_seconds, long symmetry_faults, GenerationResult& r) {
  if (o.progress) o.progress->stage("boundary patch partition", 0, "");
  const auto t0 = Clock::now();
  const long f0 = minor_faults();
  core::BppOptions bpp_options;
  bpp_options.well_formed_checked = true;
  if (o.progress)
    bpp_options.on_progress = [&](std::size_t done, std::size_t total) {
      if (done == 0)
        o.progress->stage("boundary patch partition: mappings", total, "instance pairs");
      o.progress->set_done(done);
    };
  auto bpp = core::boundary_patch_partition(s, bpp_options);
  r.timings.boundary_patch_partition = symmetry_seconds + seconds_since(t0);
  r.timings.page_faults.boundary_patch_partition = symmetry_faults + minor_faults() - f0;
  if (o.progress)
    o.progress->message("boundary patch partition: " + std::to_string(bpp.patches.size()) +
                        " patches, " + std::to_string(bpp.mappings.size()) + " mappings");
  return bpp;
}

/// Runs `certify()` (returning a core::Lemma42Verdict), times it and records the verdict.
template <class Certify>
void certificate_stage(const GenerationOptions& o, GenerationResult& r, Certify&& certify) {
  if (o.progress) o.progress->stage("Lemma 4.2 certificate", 0, "");
  const auto t0 = Clock::now();
  const long f0 = minor_faults();
  const core::Lemma42Verdict verdict = std::forward<Certify>(certify)();
  r.timings.certificate = seconds_since(t0);
  r.timings.page_faults.certificate = minor_faults() - f0;
  r.lemma_4_2_holds = verdict.holds;
  if (!verdict.holds)
    r.lemma_4_2_failure =
        core::to_string(verdict.a) + ", " + core::to_string(verdict.b) + ": " + verdict.detail;
  if (o.progress)
    o.progress->message("Lemma 4.2 certificate: " + std::string(verdict.holds ? "holds" : "FAILS") +
                        " (" + std::to_string(verdict.pairs_checked) + " instance pairs)");
}

} // namespace symmesh::gen::support
