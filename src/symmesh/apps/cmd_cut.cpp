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

/// "X,Y" (or "X,Y,Z" when count = 3) with exact rational components; `what` names the option.
std::vector<Cyclotomic> parse_components(const std::string& text, const std::string& what,
                                         std::size_t count) {
  std::vector<std::string> parts{""};
  for (char c : text)
    if (c == ',')
      parts.emplace_back();
    else
      parts.back() += c;
  if (parts.size() != count)
    throw io::InputError(what + " " + text + ": expected " + std::to_string(count) +
                         " exact numbers separated by commas (e.g. " +
                         (count == 2 ? "1,0" : "1,0,0") + ")");
  std::vector<Cyclotomic> out;
  for (const auto& part : parts)
    out.push_back(Cyclotomic(mpq_class(io::exact_to_string(io::parse_exact(part, what)))));
  return out;
}

gen::CutPoint parse_vector(const std::string& text, const std::string& what) {
  const auto c = parse_components(text, what, 2);
  return {c[0], c[1]};
}

gen::CutPoint3 parse_vector3(const std::string& text, const std::string& what) {
  const auto c = parse_components(text, what, 3);
  return {c[0], c[1], c[2]};
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

J point3_json(const gen::CutPoint3& p) {
  return J::array({io::number_text(p[0]), io::number_text(p[1]), io::number_text(p[2])});
}

J element3_json(const gen::CutResult3& r, const gen::GroupElement& e) {
  std::vector<J> parts;
  if (e.k != 0)
    parts.push_back(J{{"rotation", J{{"order", r.rotation_order}, {"k", e.k}, {"axis", "z"}}}});
  for (std::size_t j = 0; j < r.mirrors.size(); ++j)
    if (e.mirror_bits & (1u << j))
      parts.push_back(J{{"reflection", J{{"normal", point3_json(r.mirrors[j])}}}});
  if (parts.empty()) return J{{"identity", J::object()}};
  J t = parts.back();
  for (std::size_t i = parts.size() - 1; i-- > 0;) t = J{{"compose", J::array({parts[i], t})}};
  return t;
}

std::string algorithm_of(const gen::CutResult3& r) {
  if (r.rotation_order >= 2 && !r.mirrors.empty()) return "Algorithm 6.5 half-slice (3D)";
  if (r.rotation_order >= 2) return "Algorithm 6.2 slice about the z axis";
  return r.mirrors.size() == 1 ? "Algorithm 6.1 positive part (3D)"
                               : "Algorithm 6.4 positive part (3D)";
}

std::string symmetry_text(const gen::CutResult3& r) {
  std::string s;
  if (r.rotation_order >= 2)
    s = "rotation of order " + std::to_string(r.rotation_order) + " about the z axis";
  for (const auto& m : r.mirrors)
    s += (s.empty() ? "" : " and ") + std::string("mirror plane with normal (") +
         io::number_text(m[0]) + ", " + io::number_text(m[1]) + ", " + io::number_text(m[2]) + ")";
  return s;
}

/// One template per piece (an instance of the object, clipped), instanced by the group.
J document_json(const gen::CutResult3& r, const std::string& source) {
  J instances = J::array();
  for (const auto& e : r.group) instances.push_back(J{{"transformation", element3_json(r, e)}});
  J templates = J::array();
  for (const auto& p : r.pieces) {
    J inst = instances;
    for (auto& i : inst) i["region"] = p.region;
    J vertices = J::array(), cells = J::array();
    for (const auto& q : p.points) vertices.push_back(point3_json(q));
    for (const auto& t : p.tetrahedra) cells.push_back(J::array({t[0], t[1], t[2], t[3]}));
    templates.push_back(J{{"name", p.name + "_piece"},
                          {"kind", "geometry"},
                          {"vertices", vertices},
                          {"cells", cells},
                          {"instances", inst}});
  }
  return J{{"symmesh", "templated-structure/1"},
           {"dimension", 3},
           {"description", "The " + algorithm_of(r) + " of " + source + " by its " +
                               symmetry_text(r) + " (symmesh cut), instanced by the " +
                               std::to_string(r.group.size()) + " symmetries."},
           {"templates", templates}};
}

J report_json(const gen::CutResult3& r, const CutOptions& o, double seconds) {
  J j{{"input", o.file},
      {"dimension", 3},
      {"algorithm", algorithm_of(r)},
      {"rotation_order", r.rotation_order},
      {"mirrors", J::array()},
      {"pieces", r.pieces.size()},
      {"instances_per_piece", r.group.size()},
      {"field_order", r.field ? r.field->m() : 0},
      {"seconds", seconds}};
  for (const auto& m : r.mirrors) j["mirrors"].push_back(point3_json(m));
  if (r.rotation_order >= 2 && r.mirrors.empty())
    j["start_direction"] = point3_json(r.start_direction);
  return j;
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

/// The 2D or 3D cut of the object in `o.file`; `text` is the piece's JSON, checked by the reader.
std::variant<gen::CutResult, gen::CutResult3> cut_file(const CutOptions& o, std::string& text) {
  const auto x = io::read_templated_structure(o.file);
  return std::visit(
      [&](const auto& s) -> std::variant<gen::CutResult, gen::CutResult3> {
        using S = std::decay_t<decltype(s)>;
        std::ostringstream why;
        if (!s.is_well_formed(&why)) throw gen::CutError(why.str());
        if (const auto w = core::find_instance_overlap(s))
          throw gen::CutError(core::overlap_message(*w));
        const auto to_cyclotomic = [](const auto& e) {
          return core::convert_numbers<Cyclotomic>(
              e, [](const Exact& v) { return Cyclotomic(mpq_class(io::exact_to_string(v))); });
        };
        if constexpr (std::is_same_v<S, io::Structure2> ||
                      std::is_same_v<S, io::CyclotomicStructure2>) {
          gen::SymmetrySpec spec;
          spec.rotation_order = o.rotation;
          for (const auto& m : o.mirrors) spec.mirrors.push_back(parse_vector(m, "--mirror"));
          if (!o.start.empty()) spec.start = parse_vector(o.start, "--start");
          gen::CutResult r;
          if constexpr (std::is_same_v<S, io::Structure2>)
            r = gen::cut_to_fundamental_piece(to_cyclotomic(s), spec);
          else
            r = gen::cut_to_fundamental_piece(s, spec);
          text = document_json(r, o.file).dump(2) + "\n";
          return r;
        } else {
          gen::SymmetrySpec3 spec;
          spec.rotation_order = o.rotation;
          for (const auto& m : o.mirrors) spec.mirrors.push_back(parse_vector3(m, "--mirror"));
          if (!o.start.empty()) spec.start = parse_vector(o.start, "--start");
          gen::CutResult3 r;
          if constexpr (std::is_same_v<S, io::Structure3>)
            r = gen::cut_to_fundamental_piece(to_cyclotomic(s), spec);
          else
            r = gen::cut_to_fundamental_piece(s, spec);
          text = document_json(r, o.file).dump(2) + "\n";
          return r;
        }
      },
      x);
}

int run_cut(const CutOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  if (o.out.empty()) {
    print_error("cut: give -o PIECE.json");
    return bad_input;
  }
  std::variant<gen::CutResult, gen::CutResult3> result;
  std::string text;
  try {
    result = cut_file(o, text);
    // The pieces go through the reader's checks (simple rings, holes inside, non-degenerate
    // cells) before any output.
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
      io::write_file_atomically(
          o.report,
          std::visit([&](const auto& r) { return report_json(r, o, seconds); }, result).dump(2) +
              "\n");
  } catch (const std::runtime_error& e) {
    std::error_code ignored;
    std::filesystem::remove(o.out, ignored); // no partial output: the piece goes too
    print_error(std::string("cut: ") + e.what());
    return bad_input;
  }
  if (!o.quiet) {
    std::visit(
        [&](const auto& r) {
          std::cerr << "symmesh cut: " << algorithm_of(r) << ": " << r.pieces.size()
                    << " piece(s) x " << r.group.size() << " instances";
          if constexpr (std::is_same_v<std::decay_t<decltype(r)>, gen::CutResult>)
            if (r.rotation_order >= 2 && r.mirrors.empty())
              std::cerr << std::fixed << std::setprecision(2) << "; first ray at "
                        << r.start_angle_deg << " deg (" << r.start_kind << "), smallest new angle "
                        << r.smallest_new_angle_deg
                        << " deg (x-axis: " << r.smallest_new_angle_at_x_axis_deg << " deg)";
        },
        result);
    std::cerr << std::fixed << std::setprecision(2) << " [" << seconds << " s]\n";
  }
  return ok;
}
} // namespace

void add_cut(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<CutOptions>();
  auto* cmd = app.add_subcommand(
      "cut", "Cut a whole symmetric 2D or 3D object (a templated geometry, usually one template "
             "with the identity) into the piece the symmetric methods mesh: the slice of a "
             "rotation (Algorithm 6.2; 2D: first ray by Algorithm 6.3; 3D: about the z axis), "
             "the positive part of one or two (3D: up to three) orthogonal mirrors (Algorithms "
             "6.1, 6.4), or the half-slice of a mirror and a rotation (Algorithm 6.5); all about "
             "the origin, exact, symmetry verified (spec/generation.md#cut, #cut-3d).");
  cmd->add_option("geometry", o->file, "whole object (templated-geometry JSON)")->required();
  cmd->add_option("--rotation", o->rotation, "order n >= 2 of the rotational symmetry");
  cmd->add_option("--mirror", o->mirrors,
                  "normal X,Y (3D: X,Y,Z; exact rationals) of a mirror line (plane) through the "
                  "origin; the piece is on the side the normal points to (at most two, in 3D "
                  "three, orthogonal)");
  cmd->add_option("--start", o->start,
                  "rotation only: direction X,Y of the slice's first ray (default: Algorithm "
                  "6.3, the ray that maximises the smallest angle the cut introduces; 3D: the "
                  "first half-plane, default the x axis)");
  cmd->add_option("-o,--output", o->out, "templated-geometry JSON of the piece")->required();
  cmd->add_option("--report", o->report, "JSON report (start ray, angles, counts)");
  cmd->add_flag("--quiet", o->quiet, "no summary line on stderr");
  cmd->callback([o, &exit_code] { exit_code = run_cut(*o); });
}

} // namespace symmesh::apps
