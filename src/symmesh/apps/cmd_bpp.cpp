// symmesh bpp FILE -o OUT.{svg,vtu,json} [--json] [--max-compositions N] [--quiet]
#include "symmesh/apps/commands.h"
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/io/atomic_file.h"
#include "symmesh/io/bpp_output.h"
#include "symmesh/io/templated_structure_json.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <variant>

namespace symmesh::apps {
namespace {

enum class Format { svg, vtu, json };

struct BppCliOptions {
  std::string file, out;
  bool json = false, quiet = false;
  // Signed, so that a negative value is refused rather than wrapped round to a huge guard.
  long long max_compositions = (long long)core::BppOptions{}.max_compositions;
};

std::optional<Format> format_of(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".svg") return Format::svg;
  if (ext == ".vtu") return Format::vtu;
  if (ext == ".json") return Format::json;
  return std::nullopt;
}

/// Reads a templated structure with the messages of load_well_formed (apps/load.h), but without
/// its full analysis: Lemma 4.2, the structure instance and a partition at the default guard
/// would all be computed and thrown away before the partition asked for here.
template <class FT, int D>
bool is_templated_structure(const core::TemplatedStructure<FT, D>& x, const std::string& path) {
  std::ostringstream why;
  if (!x.is_well_formed(&why)) {
    print_error(path + ": " + why.str());
    return false;
  }
  if (const auto o = core::find_instance_overlap(x)) {
    print_error(path + ": " + core::overlap_message(*o));
    return false;
  }
  return true;
}

template <class FT, int D>
std::size_t facet_patch_total(const core::BoundaryPatchPartition<FT, D>& bpp) {
  std::size_t n = 0;
  for (const auto& p : bpp.patches) n += p.dimension == D - 1;
  return n;
}

/// "symmesh: bpp: 32 templates, 1234 mappings, 56 patches (40 facet), 12 classes, regular, 0.8 s"
template <class FT, int D>
void print_progress(const core::BoundaryPatchPartition<FT, D>& bpp, double seconds) {
  char time[32];
  std::snprintf(time, sizeof time, "%.2f s", seconds);
  std::cerr << "symmesh: bpp: " << bpp.subdivisions.size() << " templates, " << bpp.mappings.size()
            << " mappings, " << bpp.patches.size() << " patches (" << facet_patch_total(bpp)
            << " facet), " << bpp.classes.size() << " classes, "
            << (bpp.regular() ? "regular" : "IRREGULAR") << ", " << time << "\n";
}

template <class FT, int D>
std::string render(const core::TemplatedStructure<FT, D>& x,
                   const core::BoundaryPatchPartition<FT, D>& bpp, Format f) {
  if (f == Format::vtu) return io::bpp_vtu(bpp);
  if (f == Format::json) return io::bpp_json(x, bpp).dump(2) + "\n";
  if constexpr (D == 2) return io::bpp_svg(x, bpp);
  throw std::logic_error("bpp: SVG of a 3D partition"); // refused before computing
}

template <class FT, int D>
int run_on(const core::TemplatedStructure<FT, D>& x, const BppCliOptions& o,
           std::optional<Format> f) {
  if (!is_templated_structure(x, o.file)) return bad_input;
  if (D == 3 && f == Format::svg) {
    print_error("-o " + o.out + ": SVG output is 2D only; use .vtu (or .json) for a 3D structure");
    return bad_input;
  }
  core::BppOptions options;
  options.max_compositions = std::size_t(o.max_compositions);
  const auto start = std::chrono::steady_clock::now();
  core::BoundaryPatchPartition<FT, D> bpp;
  try {
    bpp = core::boundary_patch_partition(x, options);
  } catch (const core::CompositionLimitExceeded& e) {
    print_error(o.file + ": " + e.what() + " (now --max-compositions " +
                std::to_string(o.max_compositions) + ")");
    return bad_input;
  }
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  if (!o.quiet) print_progress(bpp, took.count());
  if (o.json) std::cout << io::bpp_json(x, bpp).dump(2) << "\n";
  if (f) {
    io::write_file_atomically(o.out, render(x, bpp, *f));
    if (!o.quiet) std::cerr << "symmesh: wrote " << o.out << "\n";
  }
  return ok;
}

int run_bpp(const BppCliOptions& o) {
  if (o.out.empty() && !o.json) {
    print_error("bpp: nothing to write: give -o OUT.{svg,vtu,json} or --json");
    return bad_input;
  }
  if (o.max_compositions < 1) {
    print_error("--max-compositions: must be at least 1");
    return bad_input;
  }
  std::optional<Format> f;
  if (!o.out.empty()) {
    f = format_of(o.out);
    if (!f) {
      print_error("-o " + o.out + ": unknown output format (use .svg, .vtu or .json)");
      return bad_input;
    }
  }
  io::AnyStructure x;
  try {
    x = io::read_templated_structure(o.file);
  } catch (const io::InputError& e) {
    print_error(e.what());
    return bad_input;
  }
  try {
    return std::visit([&](const auto& s) { return run_on(s, o, f); }, x);
  } catch (const std::runtime_error& e) { // the output file could not be written
    print_error(e.what());
    return bad_input;
  }
}

} // namespace

void add_bpp(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<BppCliOptions>();
  auto* cmd = app.add_subcommand(
      "bpp", "Boundary patch partition (Algorithm 4.1) with the patch relation (Def 4.8) and the "
             "regularity of the instance graph (Def 4.9). Output by extension: .svg (2D), .vtu "
             "(ParaView, 2D and 3D) or .json. Exit 0: computed (regular or not); 2: bad input or "
             "the composition guard was hit.");
  cmd->add_option("file", o->file, "templated-structure JSON (spec/input-format.md)")->required();
  cmd->add_option("-o,--output", o->out, "output file: .svg (2D only), .vtu or .json");
  cmd->add_flag("--json", o->json, "print the partition as JSON on stdout");
  cmd->add_option("--max-compositions", o->max_compositions,
                  "stop with exit 2 when closing the boundary subdivision needs more composed "
                  "images than this (guards against an exploding 𝔗_X)")
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "no progress line on stderr");
  cmd->callback([o, &exit_code] { exit_code = run_bpp(*o); });
}

} // namespace symmesh::apps
