// The templated-structure JSON format: reader and writer — spec/input-format.md
//
// Reading is in three steps: nlohmann::json parses the text (a parser callback rejects
// duplicate keys and knows their JSON path), the shape of the document is validated field by
// field (every error names the field by its JSON path), and 2D geometry templates given as a
// polygon are triangulated exactly with a constrained Delaunay triangulation. Eq. 4.2 and
// conformity are not checked here: that is core::analyse.
// The reader's parts, in the order a document is read, are in structure_json/: fields.h
// (errors, numbers, field access), numbers.h (symbolic numbers, the kernel), transformations.h,
// polygons.h (2D), faces.h (3D PLC); this file reads templates and whole structures, writes them,
// and is the public API.
#include "symmesh/io/templated_structure_json.h"

#include "symmesh/io/structure_json/faces.h"
#include "symmesh/io/structure_json/fields.h"
#include "symmesh/io/structure_json/numbers.h"
#include "symmesh/io/structure_json/polygons.h"
#include "symmesh/io/structure_json/transformations.h"

#include "symmesh/gen/triangle_mesher.h"

#include <filesystem>
#include <fstream>
#include <numeric>

namespace symmesh::io {

namespace {

using namespace structure_json;

// ---------------------------------------------------------------------------------------------
// Templates

/// vertices + cells, with the shape checks of spec/input-format.md.
template <class FT, int D>
core::ElementComplex<FT, D> read_cells(const json& tj, const std::string& tpath) {
  const std::string vp = dot(tpath, "vertices");
  const std::string cp = dot(tpath, "cells");
  const json& vj = require(tj, "vertices", tpath);
  const json& cj = require(tj, "cells", tpath);
  core::ElementComplex<FT, D> m;
  m.points = read_vertices<FT, D>(vj, vp);
  expect_array(cj, cp, "an array of cells");
  if (cj.empty()) fail(cp, "no cells (a template must not be empty)");
  const std::size_t nv = m.points.size();
  std::vector<bool> used(nv, false);
  std::map<core::Simplex, std::size_t> cells;
  for (std::size_t c = 0; c < cj.size(); ++c) {
    const std::string path = at(cp, c);
    const json& cell = cj[c];
    const std::string shape =
        D == 2 ? "a triangle: 3 vertex indices" : "a tetrahedron: 4 vertex indices";
    expect_array(cell, path, shape);
    if (cell.size() != std::size_t(D + 1))
      fail(path, "a cell in " + std::to_string(D) + "D is " + shape + ", got " +
                     std::to_string(cell.size()));
    std::array<core::VertexId, 4> ids{};
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const json& v = cell[k];
      if (!v.is_number_integer())
        fail(at(path, k), "a vertex index must be a JSON integer, got " + type_name(v) +
                              (v.is_number_float() ? " " + v.dump() : ""));
      if (v.is_number_unsigned() ? v.get<std::uint64_t>() >= nv : true)
        fail(path,
             "vertex index " + v.dump() + " out of range (" + std::to_string(nv) + " vertices)");
      ids[k] = core::VertexId(v.get<std::uint64_t>());
      for (std::size_t l = 0; l < k; ++l)
        if (ids[l] == ids[k])
          fail(path, "vertex index " + std::to_string(ids[k]) + " appears twice");
      used[ids[k]] = true;
    }
    const core::Simplex s = core::Simplex::from_range(ids.data(), ids.data() + D + 1);
    if (!core::affinely_independent<FT, D>(m.coords(s)))
      fail(path, std::string("degenerate cell: its vertices are affinely dependent (zero ") +
                     (D == 2 ? "area" : "volume") + ")");
    auto [it, inserted] = cells.emplace(s, c);
    if (!inserted) fail(path, "the same cell as cells[" + std::to_string(it->second) + "]");
    m.elements.push_back(s);
  }
  for (std::size_t k = 0; k < nv; ++k)
    if (!used[k]) fail(at(vp, k), "vertex is not used by any cell");
  return m;
}

template <class FT, int D>
std::vector<core::InstanceSpec<FT, D>> read_instances(const json& tj, const std::string& tpath) {
  const std::string ip = dot(tpath, "instances");
  const json& ij = require(tj, "instances", tpath);
  expect_array(ij, ip, "an array of instances");
  if (ij.empty()) fail(ip, "no instances (every template needs at least one)");
  std::vector<core::InstanceSpec<FT, D>> out;
  for (std::size_t g = 0; g < ij.size(); ++g) {
    const std::string gp = at(ip, g);
    const json& inst = ij[g];
    expect_object(inst, gp, "an instance object {\"transformation\": ..., \"region\": ...}");
    check_keys(inst, gp, {"transformation", "region"});
    core::InstanceSpec<FT, D> spec;
    spec.transformation =
        parse_transformation<FT, D>(require(inst, "transformation", gp), dot(gp, "transformation"));
    if (inst.contains("region"))
      spec.region =
          int(get_integer(inst["region"], dot(gp, "region"), std::numeric_limits<int>::min(),
                          std::numeric_limits<int>::max()));
    out.push_back(std::move(spec));
  }
  return out;
}

template <class FT, int D>
core::TemplatedStructure<FT, D> read_structure(const json& root) {
  core::TemplatedStructure<FT, D> x;
  const json& ts = root["templates"];
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const std::string tp = at("templates", i);
    const json& tj = ts[i];
    expect_object(tj, tp, "a template object");
    check_keys(tj, tp,
               {"name", "kind", "vertices", "cells", "faces", "polygon", "holes", "instances"});
    core::Template<FT, D> t;
    t.name =
        tj.contains("name") ? get_string(tj["name"], dot(tp, "name")) : "X" + std::to_string(i + 1);
    if (tj.contains("kind")) {
      const std::string kind = get_string(tj["kind"], dot(tp, "kind"));
      if (kind == "mesh")
        t.kind = core::TemplateKind::mesh;
      else if (kind == "geometry")
        t.kind = core::TemplateKind::geometry;
      else
        fail(dot(tp, "kind"),
             "unknown kind " + quote_text(kind) + " (expected \"mesh\" or \"geometry\")");
    }
    const bool has_polygon = tj.contains("polygon");
    if (tj.contains("holes") && !has_polygon) fail(dot(tp, "holes"), "\"holes\" needs \"polygon\"");
    if (has_polygon) {
      if (D != 2)
        fail(dot(tp, "polygon"), "\"polygon\" is for 2D geometry templates only (this file is 3D)");
      if (t.kind != core::TemplateKind::geometry)
        fail(dot(tp, "polygon"),
             "\"polygon\" is for geometry templates only: add \"kind\": \"geometry\" "
             "or give a mesh template by \"vertices\" and \"cells\"");
      for (const char* k : {"vertices", "cells", "faces"})
        if (tj.contains(k))
          fail(tp,
               std::string(
                   "give either \"polygon\" or \"vertices\" and \"cells\", not both (found \"") +
                   k + "\")");
      if constexpr (D == 2) t.mesh = triangulate_polygon<FT>(tj, tp);
    } else if (tj.contains("faces")) {
      if (D != 3)
        fail(dot(tp, "faces"), "\"faces\" is for 3D geometry templates only (this file is 2D; "
                               "use \"polygon\")");
      if (t.kind != core::TemplateKind::geometry)
        fail(dot(tp, "faces"),
             "\"faces\" is for geometry templates only: add \"kind\": "
             "\"geometry\" or give a mesh template by \"vertices\" and \"cells\"");
      if (tj.contains("cells"))
        fail(tp, "give either \"faces\" or \"cells\" with the \"vertices\", not both");
      if constexpr (D == 3) t.mesh = read_faces<FT>(tj, tp);
    } else {
      if (!tj.contains("vertices") && !tj.contains("cells"))
        fail(tp, std::string("missing fields \"vertices\" and \"cells\"") +
                     (t.kind != core::TemplateKind::geometry ? ""
                      : D == 2                               ? " (or \"polygon\")"
                                                             : " (or \"vertices\" and \"faces\")"));
      t.mesh = read_cells<FT, D>(tj, tp);
    }
    t.mesh = core::face_completion(t.mesh);
    t.mesh.normalize();
    x.templates.push_back(std::move(t));
    x.instances.push_back(read_instances<FT, D>(tj, tp));
  }
  return x;
}

// ---------------------------------------------------------------------------------------------
// Writing

/// Compact one-line JSON with a space after ',' and ':'.
std::string inline_json(const ojson& j) {
  if (j.is_array()) {
    std::string s = "[";
    for (std::size_t k = 0; k < j.size(); ++k) s += (k ? ", " : "") + inline_json(j[k]);
    return s + "]";
  }
  if (j.is_object()) {
    std::string s = "{";
    bool first = true;
    for (const auto& item : j.items()) {
      s += (first ? "" : ", ") +
           ojson(item.key()).dump(-1, ' ', false, ojson::error_handler_t::replace) + ": " +
           inline_json(item.value());
      first = false;
    }
    return s + "}";
  }
  return j.dump(-1, ' ', false, ojson::error_handler_t::replace);
}

/// Pretty printing that keeps short arrays and objects (points, cells, transformations) on one
/// line.
void write_pretty(std::string& out, const ojson& j, int indent, bool force_expand = false) {
  constexpr std::size_t kWidth = 120;
  const std::string flat = inline_json(j);
  if (!j.is_structured() || j.empty() ||
      (!force_expand && flat.size() + std::size_t(indent) <= kWidth)) {
    out += flat;
    return;
  }
  const std::string pad(std::size_t(indent + 2), ' ');
  out += j.is_array() ? "[\n" : "{\n";
  std::size_t k = 0;
  for (const auto& item : j.items()) {
    out += pad;
    if (j.is_object())
      out += ojson(item.key()).dump(-1, ' ', false, ojson::error_handler_t::replace) + ": ";
    write_pretty(out, item.value(), indent + 2);
    out += ++k < j.size() ? ",\n" : "\n";
  }
  out += std::string(std::size_t(indent), ' ') + (j.is_array() ? "]" : "}");
}

std::string pretty(const ojson& j) {
  std::string out;
  write_pretty(out, j, 0, true);
  return out + "\n";
}

template <class FT, int D>
ojson point_json(const core::Point<FT, D>& p) {
  ojson a = ojson::array();
  for (int d = 0; d < D; ++d) a.push_back(number_text(p[d]));
  return a;
}

ojson simplex_json(const core::Simplex& s) {
  ojson a = ojson::array();
  for (core::VertexId v : s) a.push_back(v);
  return a;
}

template <class FT, int D>
ojson transformation_json(const Rigid<FT, D>& t) {
  ojson m = ojson::array();
  for (int i = 0; i < D; ++i) {
    ojson row = ojson::array();
    for (int j = 0; j < D; ++j) row.push_back(number_text(t.matrix()[i][j]));
    m.push_back(row);
  }
  ojson o = ojson::object();
  o["matrix"] = m;
  o["translation"] = point_json<FT, D>(t.translation_part());
  return o;
}

template <class FT, int D>
std::string structure_to_json(const core::TemplatedStructure<FT, D>& x) {
  ojson root = ojson::object();
  root["symmesh"] = kFormat;
  root["dimension"] = D;
  ojson ts = ojson::array();
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    const auto& t = x.templates[i];
    ojson tj = ojson::object();
    tj["name"] = t.name;
    tj["kind"] = t.kind == core::TemplateKind::mesh ? "mesh" : "geometry";
    ojson vs = ojson::array();
    for (const auto& p : t.mesh.points) vs.push_back(point_json<FT, D>(p));
    tj["vertices"] = vs;
    ojson cs = ojson::array();
    for (const auto& e : t.mesh.elements)
      if (e.dim() == D) cs.push_back(simplex_json(e));
    tj["cells"] = cs;
    ojson is = ojson::array();
    if (i < x.instances.size())
      for (const auto& spec : x.instances[i]) {
        ojson ij = ojson::object();
        ij["transformation"] = transformation_json<FT, D>(spec.transformation);
        ij["region"] = spec.region;
        is.push_back(ij);
      }
    tj["instances"] = is;
    ts.push_back(tj);
  }
  root["templates"] = ts;
  return pretty(root);
}

template <class FT, int D>
std::string element_complex_to_json(const core::ElementComplex<FT, D>& m) {
  ojson root = ojson::object();
  root["dimension"] = D;
  ojson vs = ojson::array();
  for (const auto& p : m.points) vs.push_back(point_json<FT, D>(p));
  root["vertices"] = vs;
  ojson es = ojson::array();
  for (const auto& e : m.elements) es.push_back(simplex_json(e));
  root["elements"] = es;
  return pretty(root);
}

} // namespace

std::string number_text(const number::Cyclotomic& x) {
  return number_text<number::Cyclotomic>(x);
}

// ---------------------------------------------------------------------------------------------
// Public API

Exact parse_exact(const std::string& text, const std::string& field) {
  return to_exact(parse_rational(text, field));
}

std::string exact_to_string(const Exact& x) {
  // Exact values are kept in canonical form (lowest terms, positive denominator).
  return rational_text(raw_mpq(CGAL::exact(x)));
}

AnyStructure parse_templated_structure(const std::string& text, const std::string& source) {
  json root;
  try {
    root = json::parse(text, DuplicateKeyGuard(source));
  } catch (const json::parse_error& e) {
    fail_malformed(source, e);
  } catch (const json::out_of_range& e) {
    // A JSON number beyond double range ("1e999"): nlohmann reports it as out_of_range, with the
    // token but no position (found by the fuzzer: it escaped as an uncaught exception).
    std::string what = e.what();
    const auto quote = what.find('\'');
    std::string token = quote == std::string::npos ? what : what.substr(quote);
    if (token.size() > 40) token = token.substr(0, 37) + "...";
    fail(source, "malformed JSON: the number " + token +
                     " is out of range (write exact numbers as strings, e.g. \"1e999\")");
  }
  try {
    expect_object(root, source, "a JSON object at the top level");
    check_keys(root, source, {"symmesh", "dimension", "templates", "description"});
    const std::string fmt = get_string(require(root, "symmesh", source), "symmesh");
    if (fmt != kFormat)
      fail("symmesh", "unsupported format " + quote_text(fmt) + " (expected \"" + kFormat + "\")");
    if (root.contains("description")) get_string(root["description"], "description");
    const int dim = int(
        get_integer(require(root, "dimension", source), "dimension", 2, 3, "the integer 2 or 3"));
    const json& ts = require(root, "templates", source);
    expect_array(ts, "templates", "an array of templates");
    if (ts.empty()) fail("templates", "no templates");
    number::CyclotomicFieldPtr field = choose_field(root);
    if (!field) {
      if (dim == 2) return read_structure<Exact, 2>(root);
      return read_structure<Exact, 3>(root);
    }
    FieldScope scope(field);
    if (dim == 2) return read_structure<Cyclotomic, 2>(root);
    return read_structure<Cyclotomic, 3>(root);
  } catch (const InputError&) {
    throw;
  } catch (const json::exception& e) {
    // Not expected (every access is type-checked first); kept so that input never escapes as
    // anything but an InputError.
    fail(source, std::string("invalid input: ") + e.what());
  } catch (const std::invalid_argument& e) {
    fail(source, std::string("invalid input: ") + e.what());
  }
}

AnyStructure read_templated_structure(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "cannot open file (it is a directory)");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open file");
  std::ostringstream buf;
  buf << in.rdbuf();
  if (in.bad()) fail(path, "cannot read file");
  return parse_templated_structure(buf.str(), path);
}

std::string to_json(const Structure2& x) {
  return structure_to_json<Exact, 2>(x);
}
std::string to_json(const Structure3& x) {
  return structure_to_json<Exact, 3>(x);
}
std::string to_json(const CyclotomicStructure2& x) {
  return structure_to_json<Cyclotomic, 2>(x);
}
std::string to_json(const CyclotomicStructure3& x) {
  return structure_to_json<Cyclotomic, 3>(x);
}

std::string complex_to_json(const core::ElementComplex<Exact, 2>& m) {
  return element_complex_to_json<Exact, 2>(m);
}
std::string complex_to_json(const core::ElementComplex<Exact, 3>& m) {
  return element_complex_to_json<Exact, 3>(m);
}

namespace {
/// The field of a K_m structure: that of its first number in a field (the reader puts every
/// number in the field; a structure built in code may hold rationals only).
template <int D>
number::CyclotomicFieldPtr field_of(const core::TemplatedStructure<Cyclotomic, D>& x) {
  for (const auto& t : x.templates)
    for (const auto& p : t.mesh.points)
      for (const auto& c : p)
        if (c.field()) return c.field();
  for (const auto& specs : x.instances)
    for (const auto& spec : specs)
      for (const auto& row : spec.transformation.matrix())
        for (const auto& a : row)
          if (a.field()) return a.field();
  return nullptr;
}
} // namespace

int field_order(const AnyStructure& x) {
  return std::visit(
      [](const auto& s) -> int {
        if constexpr (requires { field_of(s); }) {
          const auto f = field_of(s);
          return f ? f->m() : 0;
        } else {
          return 0;
        }
      },
      x);
}

std::string kernel_name(const AnyStructure& x) {
  if (std::holds_alternative<Structure2>(x) || std::holds_alternative<Structure3>(x))
    return "rational (CGAL Epeck, exact)";
  const int m = field_order(x);
  if (m == 0) return "K_m (exact real cyclotomic field; all numbers rational)";
  return "K_" + std::to_string(m) + " = Q(cos 2pi/" + std::to_string(m) +
         ") (exact real cyclotomic field)";
}

} // namespace symmesh::io
