// libFuzzer harness: random sequences of adaptation operations (Section 5.2, Technique 5.8) on
// generated templated meshes — the operations of `symmesh adapt`
// (adapt/templated_mesh_adaptation.h). The first byte picks one of five small meshes (2D n-gon
// slices, a reflective-rotational star, the MOSFET, the 8-TSV in 3D), made once by the generator;
// every further 3 bytes are one operation and its arguments: an edge bisection (with its related
// edges), smoothing sweeps, Lawson flips, Technique 5.8 with a small round cap, the quality pass,
// or --refine-where with an expression taken from the bytes. After each operation: the compact SVB
// is valid, the structure instance conforms (the certificate: every cell positive, no facet of AT
// in three cells, AT's boundary measure unchanged — a hanging vertex would add an interface to it)
// and AT's area or volume is unchanged; every vertex pair the identification tables name is still
// one point of AT (each instance's image of it agrees), so every related copy moved, and was
// inserted, like the vertex itself. And the operation done on the templates equals the operation
// done on AT, where AT defines it (agrees_with_at):
//   - bisecting a template edge = bisecting, in AT, the smallest set of AT edges that holds the
//     edge's images and, with any image of a template edge, all its images (found from AT's
//     numbering, not from the library's tables): AT's points after are exactly the points before
//     plus one midpoint per edge of that set;
//   - --refine-where: the points before plus midpoints of edges of AT before;
//   - Lawson flips inside templates: the same points, the same number of cells;
//   - smoothing: the same cells (the same AT vertex numbers); the quality pass: the same number
//     of vertices; Technique 5.8: every point before is still a point.
// Points are compared up to the rounding of the transformations (doubles, harness only).
// A refusal the operation documents (std::invalid_argument for a bad expression, AdaptationLimit
// for the round cap) is fine; any other exception, a failed check, a crash or a hang is a finding.
#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/api/generate_run.h"
#include "symmesh/io/examples.h"
#include "symmesh/mesh/structure_instance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {
using symmesh::mesh::IndexType;
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

/// AT as a plain mesh: its points, its cells (AT vertex numbers) and, per instance, its template
/// and the AT number of each template vertex — from the structure-instance view.
struct At {
  int arity = 0; ///< vertices per cell
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<IndexType, 4>> cells;
  std::vector<std::size_t> template_of;
  std::vector<std::vector<IndexType>> global;
};

At at_of(const TemplatedMeshCompactSvb& t) {
  const symmesh::mesh::StructureInstance view(t);
  At a;
  const int d = view.dimension();
  a.arity = d + 1;
  view.for_each_vertex([&](const double* x) {
    std::array<double, 3> p{};
    for (int k = 0; k < d; ++k) p[std::size_t(k)] = x[k];
    a.points.push_back(p);
  });
  view.for_each_instance([&](const symmesh::mesh::StructureInstance::Instance& in) {
    a.template_of.push_back(in.template_index);
    a.global.push_back(*in.global);
  });
  view.for_each_cell(
      [&](const auto&, std::size_t, const std::array<IndexType, 4>& v) { a.cells.push_back(v); });
  return a;
}

bool same_point(const std::array<double, 3>& x, const std::array<double, 3>& y) {
  for (std::size_t k = 0; k < 3; ++k)
    if (std::abs(x[k] - y[k]) > 1e-9 * (1 + std::abs(x[k]))) return false;
  return true;
}

/// Points bucketed on a grid much coarser than the rounding and much finer than a mesh edge, so
/// that two points that agree up to rounding lie in neighbouring buckets.
class PointSet {
public:
  explicit PointSet(const std::vector<std::array<double, 3>>& p) : p_(p), used_(p.size(), 0) {
    for (std::size_t i = 0; i < p_.size(); ++i) buckets_[key(p_[i])].push_back(i);
  }
  /// Finds a point equal to x up to rounding; with `take`, one not taken yet, and takes it.
  bool find(const std::array<double, 3>& x, bool take) {
    const auto k = key(x);
    for (long i = -1; i <= 1; ++i)
      for (long j = -1; j <= 1; ++j)
        for (long l = -1; l <= 1; ++l) {
          const auto it = buckets_.find({k[0] + i, k[1] + j, k[2] + l});
          if (it == buckets_.end()) continue;
          for (const auto q : it->second)
            if ((!take || !used_[q]) && same_point(p_[q], x)) {
              if (take) used_[q] = 1;
              return true;
            }
        }
    return false;
  }
  const std::vector<char>& taken() const { return used_; }

private:
  static std::array<long, 3> key(const std::array<double, 3>& x) {
    return {long(std::floor(x[0] * 1e6)), long(std::floor(x[1] * 1e6)),
            long(std::floor(x[2] * 1e6))};
  }
  const std::vector<std::array<double, 3>>& p_;
  std::vector<char> used_;
  std::map<std::array<long, 3>, std::vector<std::size_t>> buckets_;
};

/// True when `actual` equals `expected` as a multiset of points (up to rounding).
bool same_points(const std::vector<std::array<double, 3>>& expected,
                 const std::vector<std::array<double, 3>>& actual) {
  if (expected.size() != actual.size()) return false;
  PointSet set(actual);
  for (const auto& x : expected)
    if (!set.find(x, true)) return false;
  return true;
}

using AtEdge = std::pair<IndexType, IndexType>;
AtEdge edge_of(IndexType a, IndexType b) {
  return {std::min(a, b), std::max(a, b)};
}

std::array<double, 3> midpoint(const At& a, const AtEdge& e) {
  std::array<double, 3> m{};
  for (std::size_t k = 0; k < 3; ++k)
    m[k] = 0.5 * (a.points[std::size_t(e.first)][k] + a.points[std::size_t(e.second)][k]);
  return m;
}

/// The AT edges that bisecting edge {u, v} of template `ti` must bisect to keep AT templated:
/// its images and, closed, every image of any template edge that has an image among them.
std::set<AtEdge> bisection_closure(const TemplatedMeshCompactSvb& t, const At& a, std::size_t ti,
                                   AtEdge uv) {
  std::vector<std::set<AtEdge>> template_edges(t.templated.templates.size());
  for (std::size_t k = 0; k < template_edges.size(); ++k) {
    const auto& m = t.templated.templates[k].mesh;
    for (std::size_t c = 0; c < m.cell_count(); ++c)
      for (int i = 0; i < a.arity; ++i)
        for (int j = i + 1; j < a.arity; ++j)
          template_edges[k].insert(edge_of(m.cell(c)[i], m.cell(c)[j]));
  }
  const auto image = [&](std::size_t in, const AtEdge& e) {
    return edge_of(a.global[in][std::size_t(e.first)], a.global[in][std::size_t(e.second)]);
  };
  std::map<AtEdge, std::vector<std::pair<std::size_t, AtEdge>>> preimages;
  for (std::size_t in = 0; in < a.template_of.size(); ++in)
    for (const auto& e : template_edges[a.template_of[in]])
      preimages[image(in, e)].emplace_back(a.template_of[in], e);
  std::set<AtEdge> closure;
  std::set<std::pair<std::size_t, AtEdge>> seen{{ti, uv}};
  std::vector<std::pair<std::size_t, AtEdge>> work{{ti, uv}};
  while (!work.empty()) {
    const auto [k, e] = work.back();
    work.pop_back();
    for (std::size_t in = 0; in < a.template_of.size(); ++in) {
      if (a.template_of[in] != k || !closure.insert(image(in, e)).second) continue;
      for (const auto& p : preimages[image(in, e)])
        if (seen.insert(p).second) work.push_back(p);
    }
  }
  return closure;
}

/// Every point of `before` is a point of `after`; with `midpoints_only`, every other point of
/// `after` is the midpoint of an edge of `before`.
bool points_kept(const At& before, const At& after, bool midpoints_only) {
  PointSet set(after.points);
  for (const auto& x : before.points)
    if (!set.find(x, true)) return false;
  if (!midpoints_only) return true;
  std::set<AtEdge> edges;
  for (const auto& c : before.cells)
    for (int i = 0; i < before.arity; ++i)
      for (int j = i + 1; j < before.arity; ++j)
        edges.insert(edge_of(c[std::size_t(i)], c[std::size_t(j)]));
  std::vector<std::array<double, 3>> mids;
  for (const auto& e : edges) mids.push_back(midpoint(before, e));
  PointSet mid_set(mids);
  for (std::size_t q = 0; q < after.points.size(); ++q)
    if (!set.taken()[q] && !mid_set.find(after.points[q], false)) return false;
  return true;
}

/// What AT after operation `kind` must be, given AT before (see the file comment).
enum class Expect { bisection, midpoints, same_points, same_cells, same_vertex_count, superset };

bool agrees_with_at(Expect kind, const At& before, const At& after,
                    const std::set<AtEdge>& closure) {
  switch (kind) {
  case Expect::bisection: {
    auto expected = before.points;
    for (const auto& e : closure) expected.push_back(midpoint(before, e));
    return same_points(expected, after.points);
  }
  case Expect::midpoints:
    return points_kept(before, after, true);
  case Expect::same_points:
    return before.cells.size() == after.cells.size() && same_points(before.points, after.points);
  case Expect::same_cells:
    return before.cells == after.cells;
  case Expect::same_vertex_count:
    return before.points.size() == after.points.size();
  case Expect::superset:
    return points_kept(before, after, false);
  }
  return false;
}

/// One operation from three bytes, on `t` whose AT is `before`; returns what AT after it must be
/// (a bisection also gives the AT edges it must bisect).
Expect apply(TemplatedMeshCompactSvb& t, const std::uint8_t* op, const At& before,
             std::set<AtEdge>& closure) {
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
    closure = bisection_closure(t, before, ti, edge_of(a, b));
    adapt::bisect_edges(t, {{ti, std::min(a, b), std::max(a, b)}});
    return Expect::bisection;
  }
  case 1:
    adapt::smooth_vertices(t, 1 + op[1] % 3, op[2] & 1);
    return Expect::same_cells;
  case 2:
    if (t.templated.point_dimension == 2) adapt::make_templates_delaunay(t);
    return Expect::same_points;
  case 3:
    if (t.templated.point_dimension == 2) {
      try {
        adapt::make_delaunay(t, 1 + op[1] % 4);
      } catch (const adapt::AdaptationLimit&) {
        // the documented refusal; the mesh is left as the last full round made it
      }
    }
    return Expect::superset;
  case 4:
    adapt::improve_quality(t, 1 + op[1] % 2);
    return Expect::same_vertex_count;
  default: { // --refine-where with a small expression from the bytes
    static const char* const names[] = {"x",       "y",      "z",        "size",
                                        "quality", "region", "template", "instance"};
    static const char* const ops[] = {"<", "<=", ">", ">=", "==", "!="};
    const std::string e = std::string(names[op[1] % 8]) + " " + ops[op[1] / 8 % 6] + " " +
                          std::to_string((int(op[2]) - 128) / 64.0);
    adapt::refine_where(t, adapt::parse_cell_predicate(e));
    return Expect::midpoints;
  }
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 64) return 0; // at most 21 operations: each input stays fast
  const auto& s = seeds()[data[0] % seeds().size()];
  auto t = s.mesh;
  // Cells grow by bisection; a cap of 200 template cells keeps every input's cost bounded (the
  // checks after each operation walk all of AT): the seeds have 4-65 template cells, so an
  // input still refines each about threefold, and runs about 5x as fast as with a cap of 1000.
  auto before = at_of(t);
  for (std::size_t i = 1; i + 3 <= size; i += 3) {
    std::size_t cells = 0;
    for (const auto& mt : t.templated.templates) cells += mt.mesh.cell_count();
    if (cells > 200) break;
    std::set<AtEdge> closure;
    const auto kind = apply(t, data + i, before, closure);
    check(t, s);
    auto after = at_of(t);
    if (!agrees_with_at(kind, before, after, closure)) __builtin_trap();
    before = std::move(after);
  }
  return 0;
}
