// .tmesh writer and reader (spec/outputs.md#tmesh).
#include "symmesh/io/templated_mesh_file.h"

#include "symmesh/io/atomic_file.h"

#include "symmesh/io/templated_structure_json.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace symmesh::io {
namespace {
using J = nlohmann::ordered_json;

[[noreturn]] void bad(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

const J& field(const J& j, const char* key, const std::string& path) {
  if (!j.is_object() || !j.contains(key)) bad(path, std::string("missing field \"") + key + "\"");
  return j[key];
}

const J& array_field(const J& j, const char* key, const std::string& path) {
  const J& a = field(j, key, path);
  if (!a.is_array()) bad(path + "." + key, "expected an array");
  return a;
}

double finite(const J& j, const std::string& path) {
  if (!j.is_number()) bad(path, "expected a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) bad(path, "not a finite number");
  return v;
}

mesh::IndexType index(const J& j, const std::string& path, std::size_t bound) {
  if (!j.is_number_integer()) bad(path, "expected an integer");
  const auto v = j.get<long long>();
  if (v < 0 || std::size_t(v) >= bound)
    bad(path, "index " + std::to_string(v) + " out of range [0, " + std::to_string(bound) + ")");
  return mesh::IndexType(v);
}
} // namespace

void write_tmesh(const mesh::TemplatedMeshCompactSvb& t, const std::string& path,
                 const InstancePointData& point_data) {
  const auto& tm = t.templated;
  std::size_t instance = 0;
  J doc;
  doc["symmesh"] = "templated-mesh/1";
  doc["dimension"] = tm.point_dimension;
  J templates = J::array();
  for (const auto& tp : tm.templates) {
    J vertices = J::array(), cells = J::array(), instances = J::array();
    for (std::size_t v = 0; v < tp.mesh.vertex_count(); ++v) {
      J p = J::array();
      for (int d = 0; d < tm.point_dimension; ++d) p.push_back(tp.mesh.vertex(v)[d]);
      vertices.push_back(p);
    }
    for (std::size_t c = 0; c < tp.mesh.cell_count(); ++c) {
      J cell = J::array();
      for (int k = 0; k < mesh::vertex_count(tp.mesh.cell_types[c]); ++k)
        cell.push_back(tp.mesh.cell(c)[k]);
      cells.push_back(cell);
    }
    for (std::size_t g = 0; g < tp.instance_count(); ++g, ++instance) {
      J in{{"transformation", tp.transformation_indices[g]}, {"region", tp.region_ids[g]}};
      if (!point_data.empty()) {
        J data = J::object();
        for (const auto& [name, values] : point_data) {
          if (instance >= values.size() || values[instance].size() != tp.mesh.vertex_count())
            throw std::logic_error("write_tmesh: point data '" + name + "' has the wrong size");
          data[name] = values[instance];
        }
        in["point_data"] = data;
      }
      instances.push_back(in);
    }
    templates.push_back(J{{"vertices", vertices}, {"cells", cells}, {"instances", instances}});
  }
  doc["templates"] = templates;
  J transformations = J::array();
  for (const auto& f : tm.transformations)
    transformations.push_back(J{{"matrix", f.matrix}, {"translation", f.translation}});
  doc["transformations"] = transformations;
  J tables = J::array();
  for (const auto& tb : t.tables) {
    J pairs = J::array();
    for (auto [a, b] : tb.pairs) pairs.push_back(J::array({a, b}));
    tables.push_back(
        J{{"from_template", tb.from_template}, {"to_template", tb.to_template}, {"pairs", pairs}});
  }
  doc["identification_tables"] = tables;
  J ids = J::array();
  for (const auto& id : t.identifications)
    ids.push_back(J::array({id.from_instance, id.to_instance, id.table}));
  doc["identifications"] = ids;
  write_file_atomically(path, doc.dump() + "\n");
}

mesh::TemplatedMeshCompactSvb read_tmesh(const std::string& path) {
  std::ifstream is(path);
  if (!is) throw InputError(path + ": cannot open");
  J doc;
  try {
    doc = J::parse(is);
  } catch (const J::exception& e) {
    // parse_error, and out_of_range for a number beyond double's range (found by fuzz_tmesh).
    throw InputError(path + ": malformed JSON: " + e.what());
  }
  if (!doc.is_object() || doc.value("symmesh", "") != "templated-mesh/1")
    bad(path, "\"symmesh\" must be \"templated-mesh/1\"");
  mesh::TemplatedMeshCompactSvb t;
  auto& tm = t.templated;
  const J& dim = field(doc, "dimension", "dimension");
  if (!dim.is_number_integer() || (dim.get<int>() != 2 && dim.get<int>() != 3))
    bad("dimension", "must be 2 or 3");
  tm.point_dimension = dim.get<int>();
  const std::size_t n = std::size_t(tm.point_dimension);
  const J& fs = array_field(doc, "transformations", "");
  for (std::size_t k = 0; k < fs.size(); ++k) {
    const std::string p = "transformations[" + std::to_string(k) + "]";
    mesh::Transformation f;
    const J& a = array_field(fs[k], "matrix", p);
    const J& b = array_field(fs[k], "translation", p);
    if (a.size() != n * n || b.size() != n) bad(p, "wrong matrix or translation size");
    for (std::size_t i = 0; i < a.size(); ++i) f.matrix.push_back(finite(a[i], p + ".matrix"));
    for (std::size_t i = 0; i < b.size(); ++i)
      f.translation.push_back(finite(b[i], p + ".translation"));
    tm.transformations.push_back(f);
  }
  const J& ts = array_field(doc, "templates", "");
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const std::string p = "templates[" + std::to_string(i) + "]";
    mesh::MeshTemplate tp;
    tp.mesh.point_dimension = tm.point_dimension;
    const J& vs = array_field(ts[i], "vertices", p);
    for (std::size_t v = 0; v < vs.size(); ++v) {
      const std::string vp = p + ".vertices[" + std::to_string(v) + "]";
      if (!vs[v].is_array() || vs[v].size() != n) bad(vp, "wrong number of coordinates");
      double x[3] = {0, 0, 0};
      for (std::size_t d = 0; d < n; ++d) x[d] = finite(vs[v][d], vp);
      tp.mesh.add_vertex(x);
    }
    const J& cs = array_field(ts[i], "cells", p);
    for (std::size_t c = 0; c < cs.size(); ++c) {
      const std::string cp = p + ".cells[" + std::to_string(c) + "]";
      if (!cs[c].is_array() || cs[c].size() != n + 1)
        bad(cp, "a cell needs dimension + 1 vertices");
      mesh::IndexType v[4] = {0, 0, 0, 0};
      for (std::size_t k = 0; k <= n; ++k) v[k] = index(cs[c][k], cp, tp.mesh.vertex_count());
      tp.mesh.add_cell(n == 2 ? mesh::ElementType::triangle : mesh::ElementType::tetrahedron, v);
    }
    const J& is_ = array_field(ts[i], "instances", p);
    for (std::size_t g = 0; g < is_.size(); ++g) {
      const std::string ip = p + ".instances[" + std::to_string(g) + "]";
      tp.transformation_indices.push_back(
          index(field(is_[g], "transformation", ip), ip + ".transformation", fs.size()));
      tp.region_ids.push_back(
          mesh::RegionIdType(index(field(is_[g], "region", ip), ip + ".region", 65536)));
    }
    tm.templates.push_back(std::move(tp));
  }
  const J& tbs = array_field(doc, "identification_tables", "");
  for (std::size_t k = 0; k < tbs.size(); ++k) {
    const std::string p = "identification_tables[" + std::to_string(k) + "]";
    mesh::VertexIdentificationTable tb;
    tb.from_template = index(field(tbs[k], "from_template", p), p, tm.templates.size());
    tb.to_template = index(field(tbs[k], "to_template", p), p, tm.templates.size());
    const auto nf = tm.templates[std::size_t(tb.from_template)].mesh.vertex_count();
    const auto nt = tm.templates[std::size_t(tb.to_template)].mesh.vertex_count();
    const J& ps = array_field(tbs[k], "pairs", p);
    for (std::size_t q = 0; q < ps.size(); ++q) {
      const std::string pp = p + ".pairs[" + std::to_string(q) + "]";
      if (!ps[q].is_array() || ps[q].size() != 2) bad(pp, "expected a pair");
      tb.pairs.emplace_back(index(ps[q][0], pp, nf), index(ps[q][1], pp, nt));
    }
    t.tables.push_back(std::move(tb));
  }
  const J& ids = array_field(doc, "identifications", "");
  const std::size_t instances = tm.instance_count();
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const std::string p = "identifications[" + std::to_string(k) + "]";
    if (!ids[k].is_array() || ids[k].size() != 3) bad(p, "expected [from, to, table]");
    t.identifications.push_back({index(ids[k][0], p, instances), index(ids[k][1], p, instances),
                                 index(ids[k][2], p, t.tables.size())});
  }
  std::ostringstream why;
  if (!t.is_valid(&why)) bad(path, why.str());
  return t;
}

} // namespace symmesh::io
