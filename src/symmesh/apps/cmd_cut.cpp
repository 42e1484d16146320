// symmesh cut GEOMETRY.json (--rotation N | --mirror NX,NY [--mirror NX,NY] | --rotation N
//            --mirror NX,NY) [--start X,Y] -o PIECE.json [--report REPORT.json] [--quiet]
// The cut of a whole symmetric object into its fundamental piece (spec/generation.md#cut).
#include "symmesh/apps/commands.h"
#include "symmesh/core/structure_report.h"
#include "symmesh/gen/symmetry_cut.h"
#include "symmesh/io/atomic_file.h"
#include "symmesh/io/number_text.h"
#include "symmesh/io/templated_structure_json.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <variant>

namespace symmesh::apps {
namespace {

using number::Cyclotomic;
using J = nlohmann::ordered_json;

struct CutOptions {
  std::string file, out, report, start;
  int rotation = 0;
  std::vector<std::string> mirrors;
  bool quiet = false;
};

/// "X,Y" with exact rational components; `what` names the option in errors.
gen::CutPoint parse_vector(const std::string& text, const std::string& what) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    throw io::InputError(what + " " + text + ": expected two exact numbers X,Y (e.g. 1,0)");
  gen::CutPoint p;
  const std::string part[2] = {text.substr(0, comma), text.substr(comma + 1)};
  for (int i = 0; i < 2; ++i)
    p[i] = Cyclotomic(mpq_class(io::exact_to_string(io::parse_exact(part[i], what))));
  return p;
}

J point_json(const gen::CutPoint& p) {
  return J::array({io::number_text(p[0]), io::number_text(p[1])});
}
J ring_json(const std::vector<gen::CutPoint>& ring) {
  J out = J::array();
  for (const auto& p : ring) out.push_back(point_json(p));
  return out;
}

J element_json(const gen::CutResult& r, const gen::GroupElement& e) {
  std::vector<J> parts;
  if (e.k != 0) parts.push_back(J{{"rotation", J{{"order", r.rotation_order}, {"k", e.k}}}});
  for (std::size_t j = 0; j < r.mirrors.size(); ++j)
    if (e.mirror_bits & (1u << j))
      parts.push_back(J{{"reflection", J{{"normal", point_json(r.mirrors[j])}}}});
  if (parts.empty()) return J{{"identity", J::object()}};
  J t = parts.back();
  for (std::size_t i = parts.size() - 1; i-- > 0;) t = J{{"compose", J::array({parts[i], t})}};
  return t;
}

std::string symmetry_text(const gen::CutResult& r) {
  std::string s;
  if (r.rotation_order >= 2) s = "rotation of order " + std::to_string(r.rotation_order);
  for (const auto& m : r.mirrors)
    s += (s.empty() ? "" : " and ") + std::string("mirror with normal (") + io::number_text(m[0]) +
         ", " + io::number_text(m[1]) + ")";
  return s;
}

std::string algorithm_of(const gen::CutResult& r) {
  if (r.rotation_order >= 2 && !r.mirrors.empty()) return "Algorithm 6.5 half-slice";
  if (r.rotation_order >= 2)
    return r.start_kind == "given" ? "Algorithm 6.2 slice (given first ray)"
                                   : "Algorithm 6.2 slice (first ray by Algorithm 6.3)";
  return r.mirrors.size() == 2 ? "Algorithm 6.4 positive part" : "Algorithm 6.1 positive part";
}

J document_json(const gen::CutResult& r, const std::string& source) {
  J instances = J::array();
  for (const auto& e : r.group) instances.push_back(J{{"transformation", element_json(r, e)}});
  J templates = J::array();
  std::map<int, int> per_region;
  for (const auto& p : r.pieces) {
    J inst = instances;
    for (auto& i : inst) i["region"] = p.region;
    J t{{"name",
         "region" + std::to_string(p.region) + "_piece" + std::to_string(++per_region[p.region])},
        {"kind", "geometry"},
        {"polygon", ring_json(p.outer)}};
    if (!p.holes.empty()) {
      t["holes"] = J::array();
      for (const auto& h : p.holes) t["holes"].push_back(ring_json(h));
    }
    t["instances"] = inst;
    templates.push_back(t);
  }
  return J{{"symmesh", "templated-structure/1"},
           {"dimension", 2},
           {"description", "The " + algorithm_of(r) + " of " + source + " by its " +
                               symmetry_text(r) + " (symmesh cut), instanced by the " +
                               std::to_string(r.group.size()) + " symmetries."},
           {"templates", templates}};
}

J report_json(const gen::CutResult& r, const CutOptions& o, double seconds) {
  J j{{"input", o.file},
      {"algorithm", algorithm_of(r)},
      {"rotation_order", r.rotation_order},
      {"mirrors", J::array()},
      {"pieces", r.pieces.size()},
      {"instances_per_piece", r.group.size()},
      {"field_order", r.field ? r.field->m() : 0},
      {"seconds", seconds}};
  for (const auto& m : r.mirrors) j["mirrors"].push_back(point_json(m));
  if (r.rotation_order >= 2 && r.mirrors.empty()) {
    j["start_direction"] = point_json(r.start_direction);
    j["start_angle_deg"] = r.start_angle_deg;
    j["start_kind"] = r.start_kind;
    j["smallest_new_angle_deg"] = r.smallest_new_angle_deg;
    j["smallest_new_angle_at_x_axis_deg"] = r.smallest_new_angle_at_x_axis_deg;
  }
  return j;
}

int run_cut(const CutOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (o.out.empty()) {
    print_error("cut: give -o PIECE.json");
    return bad_input;
  }
  gen::CutResult r;
  std::string text;
  try {
    gen::SymmetrySpec spec;
    spec.rotation_order = o.rotation;
    for (const auto& m : o.mirrors) spec.mirrors.push_back(parse_vector(m, "--mirror"));
    if (!o.start.empty()) spec.start = parse_vector(o.start, "--start");
    const auto x = io::read_templated_structure(o.file);
    r = std::visit(
        [&](const auto& s) -> gen::CutResult {
          using S = std::decay_t<decltype(s)>;
          if constexpr (std::is_same_v<S, io::Structure2> ||
                        std::is_same_v<S, io::CyclotomicStructure2>) {
            std::ostringstream why;
            if (!s.is_well_formed(&why)) throw gen::CutError(why.str());
            if (const auto w = core::find_instance_overlap(s))
              throw gen::CutError(core::overlap_message(*w));
          }
          if constexpr (std::is_same_v<S, io::Structure2>) {
            const auto c = core::convert_numbers<Cyclotomic>(
                s, [](const Exact& v) { return Cyclotomic(mpq_class(io::exact_to_string(v))); });
            return gen::cut_to_fundamental_piece(c, spec);
          } else if constexpr (std::is_same_v<S, io::CyclotomicStructure2>) {
            return gen::cut_to_fundamental_piece(s, spec);
          } else {
            throw gen::CutError("3D objects are not supported by cut yet");
          }
        },
        x);
    text = document_json(r, o.file).dump(2) + "\n";
    // The pieces go through the reader's checks (simple rings, holes inside) before any output.
    io::parse_templated_structure(text, o.out);
  } catch (const io::InputError& e) {
    print_error(e.what());
    return bad_input;
  } catch (const std::invalid_argument& e) {
    print_error(o.file + ": " + e.what());
    return bad_input;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    io::write_file_atomically(o.out, text);
  } catch (const std::runtime_error& e) {
    print_error(std::string("cut: ") + e.what());
    return bad_input;
  }
  try {
    if (!o.report.empty())
      io::write_file_atomically(o.report, report_json(r, o, seconds).dump(2) + "\n");
  } catch (const std::runtime_error& e) {
    std::error_code ignored;
    std::filesystem::remove(o.out, ignored); // no partial output: the piece goes too
    print_error(std::string("cut: ") + e.what());
    return bad_input;
  }
  if (!o.quiet) {
    std::cerr << "symmesh cut: " << algorithm_of(r) << ": " << r.pieces.size() << " piece(s) x "
              << r.group.size() << " instances";
    if (r.rotation_order >= 2 && r.mirrors.empty())
      std::cerr << std::fixed << std::setprecision(2) << "; first ray at " << r.start_angle_deg
                << " deg (" << r.start_kind << "), smallest new angle " << r.smallest_new_angle_deg
                << " deg (x-axis: " << r.smallest_new_angle_at_x_axis_deg << " deg)";
    std::cerr << std::fixed << std::setprecision(2) << " [" << seconds << " s]\n";
  }
  return ok;
}
} // namespace

void add_cut(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CutOptions>();
  auto* cmd = app.add_subcommand(
      "cut", "Cut a whole symmetric 2D object (a templated geometry, usually one template with "
             "the identity) into the piece the symmetric methods mesh: the slice of a rotation "
             "(Algorithm 6.2, first ray by Algorithm 6.3), the positive part of one or two "
             "orthogonal mirrors (Algorithms 6.1, 6.4), or the half-slice of a mirror and a "
             "rotation (Algorithm 6.5); all about the origin, exact, symmetry verified "
             "(spec/generation.md#cut).");
  cmd->add_option("geometry", o->file, "whole object (templated-geometry JSON)")->required();
  cmd->add_option("--rotation", o->rotation, "order n >= 2 of the rotational symmetry");
  cmd->add_option("--mirror", o->mirrors,
                  "normal X,Y (exact rationals) of a mirror line through the origin; the piece "
                  "is on the side the normal points to (at most two, orthogonal)");
  cmd->add_option("--start", o->start,
                  "rotation only: direction X,Y of the slice's first ray (default: Algorithm "
                  "6.3, the ray that maximises the smallest angle the cut introduces)");
  cmd->add_option("-o,--output", o->out, "templated-geometry JSON of the piece")->required();
  cmd->add_option("--report", o->report, "JSON report (start ray, angles, counts)");
  cmd->add_flag("--quiet", o->quiet, "no summary line on stderr");
  cmd->callback([o, &exit_code] { exit_code = run_cut(*o); });
}

} // namespace symmesh::apps
