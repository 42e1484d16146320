// libFuzzer harness: random sequences of adaptation operations (Section 5.2, Technique 5.8) on
// generated templated meshes — the operations of `symmesh adapt`
// (adapt/templated_mesh_adaptation.h). The first byte picks one of five small meshes (2D n-gon
// slices, a reflective-rotational star, the MOSFET, the 8-TSV in 3D), made once by the generator;
// every further 3 bytes are one operation and its arguments: an edge bisection (with its related
// edges), smoothing sweeps, Lawson flips, Technique 5.8 with a small round cap, the quality pass,
// or --refine-where with an expression taken from the bytes. After each operation: the compact SVB
// is valid, the structure instance conforms (the certificate: every cell positive, no facet of AT
// in three cells, AT's boundary measure unchanged — a hanging vertex would add an interface to it)
// and AT's area or volume is unchanged; and the operation done on the templates equals it done on
// AT: every vertex pair the identification tables name is still one point of AT (each instance's
// image of it agrees), so every related copy moved, and was inserted, like the vertex itself.
// A refusal the operation documents (std::invalid_argument
// for a bad expression, AdaptationLimit for the round cap) is fine; any other exception, a failed
// check, a crash or a hang is a finding.
#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/api/generate_run.h"
#include "symmesh/io/examples.h"
#include "symmesh/mesh/structure_instance.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {
using symmesh::mesh::TemplatedMeshCompactSvb;

struct Seed {
  TemplatedMeshCompactSvb mesh;
  double boundary = 0, measure = 0;
};

/// AT's total area (2D) or volume (3D), from the templates (rigid maps keep it).
double measure_of(const TemplatedMeshCompactSvb& t) {
  double total = 0;
  const int d = t.templated.point_dimension;
  for (const auto& mt : t.templated.templates) {
    const auto& m = mt.mesh;
    double sum = 0;
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
      const auto* v = m.cell(c);
      const auto p = [&](int k) { return &m.vertex_coords[std::size_t(v[k]) * std::size_t(d)]; };
      if (d == 2) {
        sum += 0.5 * ((p(1)[0] - p(0)[0]) * (p(2)[1] - p(0)[1]) -
                      (p(1)[1] - p(0)[1]) * (p(2)[0] - p(0)[0]));
      } else {
        double a[3], b[3], e[3];
        for (int i = 0; i < 3; ++i)
          a[i] = p(1)[i] - p(0)[i], b[i] = p(2)[i] - p(0)[i], e[i] = p(3)[i] - p(0)[i];
        sum += (a[0] * (b[1] * e[2] - b[2] * e[1]) - a[1] * (b[0] * e[2] - b[2] * e[0]) +
                a[2] * (b[0] * e[1] - b[1] * e[0])) /
               6;
      }
    }
    total += sum * double(mt.instance_count());
  }
  return total;
}

const std::vector<Seed>& seeds() {
  static const std::vector<Seed> all = [] {
    const std::array<std::pair<const char*, double>, 5> objects{
        {{"ngon-slice-5", 0.4},
         {"ngon-sao-8", 0.4},
         {"star-reflective-rotational", 0.4},
         {"mosfet", 1.0},
         {"tsv-8", 0.8}}};
    std::vector<Seed> out;
    for (const auto& [name, size] : objects) {
      symmesh::api::RunOptions o;
      o.size = size;
      o.min_angle = 20;
      const auto x =
          symmesh::api::parse_structure_text(symmesh::io::example_document(name).dump(), name);
      Seed s;
      s.mesh = symmesh::api::run_generation(x, name, o).templated;
      symmesh::adapt::expand_identifications(s.mesh);
      s.boundary = symmesh::adapt::certify_conformity(s.mesh).boundary_measure;
      s.measure = measure_of(s.mesh);
      out.push_back(std::move(s));
    }
    return out;
  }();
  return all;
}

/// Every identified pair (template vertex a of instance i, b of instance j) is one point of AT:
/// T_i(a) and T_j(b) agree up to the rounding of the two transformations.
bool identified_points_agree(const TemplatedMeshCompactSvb& t) {
  const int d = t.templated.point_dimension;
  std::vector<std::pair<std::size_t, std::size_t>> where; // instance -> (template, local)
  for (std::size_t ti = 0; ti < t.templated.templates.size(); ++ti)
    for (std::size_t k = 0; k < t.templated.templates[ti].instance_count(); ++k)
      where.emplace_back(ti, k);
  const auto image = [&](std::size_t instance, symmesh::mesh::IndexType v, double* out) {
    const auto& mt = t.templated.templates[where[instance].first];
    const auto& f =
        t.templated.transformations[std::size_t(mt.transformation_indices[where[instance].second])];
    f.apply(&mt.mesh.vertex_coords[std::size_t(v) * std::size_t(d)], out);
  };
  for (const auto& id : t.identifications)
    for (const auto& pair : t.tables[std::size_t(id.table)].pairs) {
      double x[3], y[3];
      image(std::size_t(id.from_instance), pair.first, x);
      image(std::size_t(id.to_instance), pair.second, y);
      for (int k = 0; k < d; ++k)
        if (std::abs(x[k] - y[k]) > 1e-9 * (1 + std::abs(x[k]))) return false;
    }
  return true;
}

void check(const TemplatedMeshCompactSvb& t, const Seed& s) {
  if (!t.is_valid()) __builtin_trap();
  if (!identified_points_agree(t)) __builtin_trap();
  if (!symmesh::adapt::certify_conformity(t, s.boundary).holds) __builtin_trap();
  if (std::abs(measure_of(t) - s.measure) > 1e-9 * std::max(1.0, s.measure)) __builtin_trap();
}

/// One operation from three bytes.
void apply(TemplatedMeshCompactSvb& t, const std::uint8_t* op) {
  namespace adapt = symmesh::adapt;
  const auto& templates = t.templated.templates;
  switch (op[0] % 6) {
  case 0: { // bisect one edge of one cell
    const std::size_t ti = op[1] % templates.size();
    const auto& m = templates[ti].mesh;
    const std::size_t c = (std::size_t(op[2]) * 2654435761u) % m.cell_count();
    const int arity = t.templated.point_dimension + 1;
    const int k = op[1] / 16 % arity, l = (k + 1 + op[1] / 64 % (arity - 1)) % arity;
    const auto a = m.cell(c)[k], b = m.cell(c)[l];
    adapt::bisect_edges(t, {{ti, std::min(a, b), std::max(a, b)}});
    break;
  }
  case 1:
    adapt::smooth_vertices(t, 1 + op[1] % 3, op[2] & 1);
    break;
  case 2:
    if (t.templated.point_dimension == 2) adapt::make_templates_delaunay(t);
    break;
  case 3:
    if (t.templated.point_dimension == 2) {
      try {
        adapt::make_delaunay(t, 1 + op[1] % 4);
      } catch (const adapt::AdaptationLimit&) {
        // the documented refusal; the mesh is left as the last full round made it
      }
    }
    break;
  case 4:
    adapt::improve_quality(t, 1 + op[1] % 2);
    break;
  default: { // --refine-where with a small expression from the bytes
    static const char* const names[] = {"x",       "y",      "z",        "size",
                                        "quality", "region", "template", "instance"};
    static const char* const ops[] = {"<", "<=", ">", ">=", "==", "!="};
    const std::string e = std::string(names[op[1] % 8]) + " " + ops[op[1] / 8 % 6] + " " +
                          std::to_string((int(op[2]) - 128) / 64.0);
    adapt::refine_where(t, adapt::parse_cell_predicate(e));
  }
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 64) return 0; // at most 21 operations: each input stays fast
  const auto& s = seeds()[data[0] % seeds().size()];
  auto t = s.mesh;
  // Cells grow by bisection; a cap of 1000 template cells keeps every input's cost bounded (the
  // checks after each operation walk all of AT).
  for (std::size_t i = 1; i + 3 <= size; i += 3) {
    std::size_t cells = 0;
    for (const auto& mt : t.templated.templates) cells += mt.mesh.cell_count();
    if (cells > 1000) break;
    apply(t, data + i);
    check(t, s);
  }
  return 0;
}
