// Boundary-condition JSON (spec/fem.md#bc-file).
#include "symmesh/io/boundary_conditions_json.h"

#include "symmesh/io/templated_structure_json.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace symmesh::io {
namespace {
using J = nlohmann::json;

[[noreturn]] void bad(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

void only_keys(const J& j, const std::string& path, const std::set<std::string>& allowed) {
  if (!j.is_object()) bad(path, "expected an object");
  for (const auto& [k, v] : j.items())
    if (!allowed.count(k)) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      bad(path + "." + k, "unknown key (expected one of: " + list + ")");
    }
}

double finite(const J& j, const std::string& path) {
  if (!j.is_number()) bad(path, "expected a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) bad(path, "not a finite number");
  return v;
}

std::size_t index(const J& j, const std::string& path, std::size_t max) {
  if (!j.is_number_integer() || j.get<long long>() < 0 || std::size_t(j.get<long long>()) > max)
    bad(path, "expected an integer in [0, " + std::to_string(max) + "]");
  return std::size_t(j.get<long long>());
}

fem::BoundarySelector selector(const J& j, const std::string& path) {
  only_keys(j, path, {"region", "template", "instance", "box", "plane"});
  fem::BoundarySelector s;
  s.where = path;
  if (j.contains("region"))
    s.region = mesh::RegionIdType(
        index(j["region"], path + ".region", std::numeric_limits<mesh::RegionIdType>::max()));
  if (j.contains("template"))
    s.template_index = index(j["template"], path + ".template", std::size_t(1) << 31);
  if (j.contains("instance"))
    s.instance = index(j["instance"], path + ".instance", std::size_t(1) << 31);
  if (j.contains("box")) {
    const std::string p = path + ".box";
    only_keys(j["box"], p, {"min", "max"});
    std::array<std::array<double, 3>, 2> box{};
    int k = 0;
    for (const char* key : {"min", "max"}) {
      if (!j["box"].contains(key)) bad(p, std::string("missing field \"") + key + "\"");
      const J& a = j["box"][key];
      if (!a.is_array() || a.size() < 2 || a.size() > 3)
        bad(p + "." + key, "expected 2 or 3 numbers");
      for (std::size_t d = 0; d < a.size(); ++d)
        box[std::size_t(k)][d] = finite(a[d], p + "." + key + "[" + std::to_string(d) + "]");
      if (a.size() == 2) box[std::size_t(k)][2] = k == 0 ? -HUGE_VAL : HUGE_VAL;
      ++k;
    }
    for (int d = 0; d < 3; ++d)
      if (box[0][std::size_t(d)] > box[1][std::size_t(d)])
        bad(p, "min[" + std::to_string(d) + "] > max[" + std::to_string(d) + "]");
    s.box = box;
  }
  if (j.contains("plane")) {
    const std::string p = path + ".plane";
    only_keys(j["plane"], p, {"normal", "offset"});
    if (!j["plane"].contains("normal")) bad(p, "missing field \"normal\"");
    const J& n = j["plane"]["normal"];
    if (!n.is_array() || n.size() < 2 || n.size() > 3)
      bad(p + ".normal", "expected 2 or 3 numbers");
    std::array<double, 4> plane{0, 0, 0, 0};
    double nn = 0;
    for (std::size_t d = 0; d < n.size(); ++d) {
      plane[d] = finite(n[d], p + ".normal[" + std::to_string(d) + "]");
      nn += plane[d] * plane[d];
    }
    if (nn == 0) bad(p + ".normal", "the zero vector");
    if (j["plane"].contains("offset")) plane[3] = finite(j["plane"]["offset"], p + ".offset");
    s.plane = plane;
  }
  return s;
}

std::vector<fem::BoundaryCondition> conditions(const J& doc, const char* key, const char* value) {
  std::vector<fem::BoundaryCondition> out;
  if (!doc.contains(key)) return out;
  const J& list = doc[key];
  if (!list.is_array()) bad(key, "expected an array");
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string p = std::string(key) + "[" + std::to_string(k) + "]";
    only_keys(list[k], p, {"on", value});
    if (!list[k].contains(value)) bad(p, std::string("missing field \"") + value + "\"");
    fem::BoundaryCondition c;
    c.on = selector(list[k].contains("on") ? list[k]["on"] : J::object(), p + ".on");
    c.value = finite(list[k][value], p + "." + value);
    out.push_back(c);
  }
  return out;
}

fem::BoundaryConditions parse_document(const J& doc);
} // namespace

fem::BoundaryConditions parse_boundary_conditions(const std::string& text,
                                                  const std::string& source) {
  J doc;
  try {
    doc = J::parse(text);
  } catch (const J::exception& e) {
    throw InputError(source + ": malformed JSON: " + e.what());
  }
  try {
    return parse_document(doc);
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
}

namespace {
fem::BoundaryConditions parse_document(const J& doc) {
  only_keys(doc, "(top level)", {"symmesh", "description", "source", "dirichlet", "neumann"});
  if (doc.value("symmesh", "") != "boundary-conditions/1")
    bad("symmesh", "must be \"boundary-conditions/1\"");
  fem::BoundaryConditions bc;
  if (doc.contains("source")) bc.source = finite(doc["source"], "source");
  bc.dirichlet = conditions(doc, "dirichlet", "value");
  bc.neumann = conditions(doc, "neumann", "flux");
  return bc;
}
} // namespace

fem::BoundaryConditions read_boundary_conditions(const std::string& path) {
  std::ifstream is(path);
  if (!is) throw InputError(path + ": cannot open");
  std::ostringstream ss;
  ss << is.rdbuf();
  return parse_boundary_conditions(ss.str(), path);
}

} // namespace symmesh::io
