// TCSR assembly and Algorithms 7.1, 7.2 (spec/fem.md#tcsr).
#include "symmesh/fem/templated_csr.h"

#include "symmesh/fem/p1_element.h"
#include "symmesh/mesh/structure_instance.h"
#include "symmesh/mesh/union_find.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace symmesh::fem {
namespace {

using mesh::IndexType;

/// The facets of cell c (D vertex ids each, sorted) of a simplex mesh.
template <int D>
std::array<std::array<GlobalIndex, 3>, D + 1> cell_facets(const mesh::Mesh& m, std::size_t c) {
  std::array<std::array<GlobalIndex, 3>, D + 1> f{};
  const IndexType* v = m.cell(c);
  for (int skip = 0; skip <= D; ++skip) {
    std::array<GlobalIndex, 3> facet{-1, -1, -1};
    int n = 0;
    for (int k = 0; k <= D; ++k)
      if (k != skip) facet[std::size_t(n++)] = v[k];
    std::sort(facet.begin(), facet.begin() + D);
    f[std::size_t(skip)] = facet;
  }
  return f;
}

template <int D>
std::vector<std::array<GlobalIndex, 3>> boundary_facets(const mesh::Mesh& m) {
  std::vector<std::array<GlobalIndex, 3>> facets;
  facets.reserve(m.cell_count() * (D + 1));
  for (std::size_t c = 0; c < m.cell_count(); ++c)
    for (const auto& f : cell_facets<D>(m, c)) facets.push_back(f);
  std::sort(facets.begin(), facets.end());
  std::vector<std::array<GlobalIndex, 3>> boundary;
  for (std::size_t k = 0; k < facets.size();) {
    std::size_t e = k + 1;
    while (e < facets.size() && facets[e] == facets[k]) ++e;
    if (e - k > 2) throw std::invalid_argument("a facet lies in more than two cells");
    if (e - k == 1) boundary.push_back(facets[k]);
    k = e;
  }
  return boundary;
}

template <int D>
TemplateMatrix template_matrix(const mesh::Mesh& m, std::size_t index, bool with_mass) {
  const auto expected = D == 2 ? mesh::ElementType::triangle : mesh::ElementType::tetrahedron;
  for (std::size_t c = 0; c < m.cell_count(); ++c)
    if (m.cell_types[c] != expected)
      throw std::invalid_argument("template " + std::to_string(index) + ", cell " +
                                  std::to_string(c) + ": P1 assembly needs " +
                                  (D == 2 ? "triangles" : "tetrahedra") + " only");
  TemplateMatrix t;
  t.vertices = m.vertex_count();
  std::vector<char> on_boundary(t.vertices, 0);
  try {
    for (const auto& f : boundary_facets<D>(m))
      for (int q = 0; q < D; ++q) on_boundary[std::size_t(f[std::size_t(q)])] = 1;
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("template " + std::to_string(index) + ": " + e.what());
  }
  t.row_of.assign(t.vertices, -1);
  GlobalIndex next = 0;
  for (std::size_t v = 0; v < t.vertices; ++v)
    if (on_boundary[v]) t.row_of[v] = next++;
  t.boundary = std::size_t(next);
  const auto cell_rows = [&](std::size_t c) {
    std::array<GlobalIndex, 4> r{};
    for (int k = 0; k <= D; ++k) r[std::size_t(k)] = t.row_of[std::size_t(m.cell(c)[k])];
    return r;
  };
  const auto element = [&](std::size_t c) {
    std::array<const double*, D + 1> x{};
    for (int k = 0; k <= D; ++k) x[std::size_t(k)] = m.vertex(std::size_t(m.cell(c)[k]));
    return p1_stiffness<D>(x);
  };
  // Interior rows in breadth-first order from the boundary rows (Cuthill–McKee from the whole
  // boundary): neighbouring rows get near row numbers, so the product's accesses to the block of
  // instance values stay within a few layers of rows however large the template is. The
  // pattern comes from the vertex adjacency of the cells (boundary rows numbered, interior rows
  // by vertex id for the moment).
  std::vector<GlobalIndex> provisional = t.row_of;
  for (std::size_t v = 0; v < t.vertices; ++v)
    if (provisional[v] < 0) provisional[v] = next++;
  std::vector<GlobalIndex> vertex_of_provisional(t.vertices);
  for (std::size_t v = 0; v < t.vertices; ++v)
    vertex_of_provisional[std::size_t(provisional[v])] = GlobalIndex(v);
  const auto pattern = assemble_csr<D>(
      t.vertices, m.cell_count(),
      [&](std::size_t c) {
        std::array<GlobalIndex, 4> r{};
        for (int k = 0; k <= D; ++k) r[std::size_t(k)] = provisional[std::size_t(m.cell(c)[k])];
        return r;
      },
      [](std::size_t) { return ElementMatrix<D>{}; });
  next = GlobalIndex(t.boundary);
  std::vector<GlobalIndex> queue(t.boundary);
  for (std::size_t r = 0; r < t.boundary; ++r) queue[r] = GlobalIndex(r);
  std::vector<char> seen(t.vertices, 0);
  for (std::size_t r = 0; r < t.boundary; ++r) seen[r] = 1;
  const auto visit_from = [&](std::size_t head) {
    for (; head < queue.size(); ++head) {
      const auto r = std::size_t(queue[head]);
      for (auto e = pattern.row_start[r]; e < pattern.row_start[r + 1]; ++e) {
        const auto q = std::size_t(pattern.column[std::size_t(e)]);
        if (seen[q]) continue;
        seen[q] = 1;
        queue.push_back(GlobalIndex(q));
        t.row_of[std::size_t(vertex_of_provisional[q])] = next++;
      }
    }
  };
  visit_from(0);
  for (std::size_t r = t.boundary; r < t.vertices; ++r) // parts without boundary (none in a mesh
    if (!seen[r]) {                                     // template, which is bounded)
      seen[r] = 1;
      queue.push_back(GlobalIndex(r));
      t.row_of[std::size_t(vertex_of_provisional[r])] = next++;
      visit_from(queue.size() - 1);
    }
  t.stiffness = assemble_csr<D>(t.vertices, m.cell_count(), cell_rows, element);
  if (with_mass) // the same cells give the same pattern
    t.mass = assemble_csr<D>(t.vertices, m.cell_count(), cell_rows, [&](std::size_t c) {
               std::array<const double*, D + 1> x{};
               for (int k = 0; k <= D; ++k) x[std::size_t(k)] = m.vertex(std::size_t(m.cell(c)[k]));
               return p1_mass<D>(x);
             }).value;
  return t;
}

} // namespace

std::vector<GlobalIndex> TemplateMatrix::vertex_of() const {
  std::vector<GlobalIndex> v(vertices);
  for (std::size_t k = 0; k < vertices; ++k) v[std::size_t(row_of[k])] = GlobalIndex(k);
  return v;
}

std::vector<std::array<GlobalIndex, 3>> template_boundary_facets(const mesh::Mesh& m, int dim) {
  return dim == 2 ? boundary_facets<2>(m) : boundary_facets<3>(m);
}

void InstanceMap::set_boundary(const std::vector<GlobalIndex>& ids) {
  boundary_rows = ids.size();
  runs_.clear();
  list_.clear();
  for (std::size_t r = 0; r < ids.size();) {
    Run run;
    run.row = std::uint32_t(r);
    run.first = ids[r];
    run.length = 1;
    if (r + 1 < ids.size() && (ids[r + 1] < 0) == (ids[r] < 0) &&
        (ids[r + 1] - ids[r] == 1 || ids[r + 1] - ids[r] == -1))
      run.delta = ids[r + 1] - ids[r];
    while (r + run.length < ids.size() && (ids[r + run.length] < 0) == (ids[r] < 0) &&
           ids[r + run.length] - ids[r + run.length - 1] == run.delta)
      ++run.length;
    r += run.length;
    runs_.push_back(run);
  }
  if (runs_.size() * sizeof(Run) >= ids.size() * sizeof(GlobalIndex)) {
    runs_.clear();
    runs_.shrink_to_fit();
    list_ = ids;
  } else {
    runs_.shrink_to_fit();
  }
}

GlobalIndex InstanceMap::boundary(std::size_t r) const {
  if (runs_.empty()) return list_[r];
  const auto it = std::upper_bound(runs_.begin(), runs_.end(), r,
                                   [](std::size_t row, const Run& q) { return row < q.row; });
  const Run& q = *(it - 1);
  return q.first + q.delta * GlobalIndex(r - q.row);
}

void InstanceMap::boundary_ids(std::vector<GlobalIndex>& out) const {
  if (runs_.empty()) {
    out = list_;
    return;
  }
  out.resize(boundary_rows);
  for (const Run& q : runs_)
    for (std::uint32_t k = 0; k < q.length; ++k)
      out[q.row + k] = q.first + q.delta * GlobalIndex(k);
}

GlobalIndex TemplatedCsr::global(std::size_t instance, std::size_t vertex) const {
  const auto& in = instances[instance];
  const auto& t = templates[in.template_index];
  const auto r = std::size_t(t.row_of[vertex]);
  if (r >= t.boundary) return in.interior_first + GlobalIndex(r - t.boundary);
  const GlobalIndex g = in.boundary(r);
  return g < 0 ? -1 - g : g;
}

namespace {

/// Instances of one template processed together (Algorithm 7.2 as a product of the template
/// matrix with a block of instance vectors): each matrix entry is loaded once for the block, so
/// the template's CSR arrays cost 1/kBlock of a load per product, and the instance values are
/// gathered into a contiguous block (boundary rows by lookup, interior rows from their
/// consecutive range).
constexpr std::size_t kBlock = 8;

// An AVX2 clone chosen at load time where the CPU has it: the kBlock lanes of a template entry
// are then two 256-bit multiplies and adds instead of four 128-bit ones. No FMA: each lane is
// still one rounded multiply and one rounded add per entry, so the results are the same bits on
// every machine.
__attribute__((target_clones("avx2", "default"))) void
multiply_block(const TemplateMatrix& t, const InstanceMap* const* in, std::size_t lanes,
               const double* x, double* y, bool constrained, std::vector<double>& xb,
               std::vector<double>& yb, std::array<std::vector<GlobalIndex>, kBlock>& ids) {
  const auto& k = t.stiffness;
  const std::size_t nb = t.boundary, nv = t.vertices;
  if (lanes < kBlock)
    xb.assign(nv * kBlock, 0.0); // unused lanes: zeros, not garbage
  else
    xb.resize(nv * kBlock);
  // Row by row, lane by lane: the block is written once, front to back, while the lanes' x
  // values are read as kBlock sequential streams (a lane-major loop would sweep the whole block
  // kBlock times).
  const double* xi[kBlock] = {};
  for (std::size_t w = 0; w < lanes; ++w) {
    in[w]->boundary_ids(ids[w]);
    xi[w] = x + in[w]->interior_first - GlobalIndex(nb);
  }
  for (std::size_t r = 0; r < nb; ++r)
    for (std::size_t w = 0; w < lanes; ++w) {
      const GlobalIndex g = ids[w][r];
      xb[r * kBlock + w] = g >= 0 ? x[g] : constrained ? 0.0 : x[-1 - g];
    }
  for (std::size_t r = nb; r < nv; ++r)
    for (std::size_t w = 0; w < lanes; ++w) xb[r * kBlock + w] = xi[w][r];
  double kappa[kBlock] = {}, sigma[kBlock] = {};
  double* yi[kBlock] = {};
  for (std::size_t w = 0; w < lanes; ++w) {
    kappa[w] = in[w]->coefficient;
    sigma[w] = in[w]->reaction;
    yi[w] = y + in[w]->interior_first - GlobalIndex(nb);
  }
  yb.resize(nb * kBlock);
  const bool mass = !t.mass.empty();
  for (std::size_t r = 0; r < nv; ++r) {
    double acc[kBlock] = {}, accm[kBlock] = {};
    for (std::int64_t e = k.row_start[r]; e < k.row_start[r + 1]; ++e) {
      const double v = k.value[std::size_t(e)];
      const double* col = &xb[std::size_t(k.column[std::size_t(e)]) * kBlock];
      for (std::size_t w = 0; w < kBlock; ++w) acc[w] += v * col[w];
    }
    if (mass) // the reaction term σ M_t, on the same pattern
      for (std::int64_t e = k.row_start[r]; e < k.row_start[r + 1]; ++e) {
        const double v = t.mass[std::size_t(e)];
        const double* col = &xb[std::size_t(k.column[std::size_t(e)]) * kBlock];
        for (std::size_t w = 0; w < kBlock; ++w) accm[w] += v * col[w];
      }
    if (r < nb) {
      for (std::size_t w = 0; w < kBlock; ++w)
        yb[r * kBlock + w] = kappa[w] * acc[w] + sigma[w] * accm[w];
    } else { // interior rows: this instance's alone
      for (std::size_t w = 0; w < lanes; ++w) yi[w][r] = kappa[w] * acc[w] + sigma[w] * accm[w];
    }
  }
  for (std::size_t r = 0; r < nb; ++r)
    for (std::size_t w = 0; w < lanes; ++w) {
      const GlobalIndex g = ids[w][r];
      if (g >= 0)
        y[g] += yb[r * kBlock + w];
      else if (!constrained)
        y[-1 - g] += yb[r * kBlock + w];
    }
}

} // namespace

void multiply_instances(const std::vector<TemplateMatrix>& templates,
                        const std::vector<InstanceMap>& instances, std::size_t unknowns,
                        const std::vector<GlobalIndex>& dirichlet, const double* x, double* y,
                        bool constrained) {
  std::fill(y, y + unknowns, 0.0);
  std::vector<double> xb, yb;
  std::array<std::vector<GlobalIndex>, kBlock> ids;
  std::vector<const InstanceMap*> block;
  const auto flush = [&] {
    if (block.empty()) return;
    multiply_block(templates[block[0]->template_index], block.data(), block.size(), x, y,
                   constrained, xb, yb, ids);
    block.clear();
  };
  for (const auto& in : instances) {
    if (!block.empty() && block[0]->template_index != in.template_index) flush();
    block.push_back(&in);
    if (block.size() == kBlock) flush();
  }
  flush();
  if (constrained)
    for (GlobalIndex d : dirichlet) y[d] = x[d];
}

void TemplatedCsr::multiply(const double* x, double* y, bool constrained) const {
  multiply_instances(templates, instances, unknowns, dirichlet, x, y, constrained);
}

void add_diagonal_instances(const std::vector<TemplateMatrix>& templates,
                            const std::vector<InstanceMap>& instances, bool skip_dirichlet,
                            double* d) {
  std::vector<GlobalIndex> ids;
  for (const auto& in : instances) {
    const auto& t = templates[in.template_index];
    const auto& k = t.stiffness;
    in.boundary_ids(ids);
    for (std::size_t r = 0; r < t.vertices; ++r) {
      GlobalIndex g = r < t.boundary ? ids[r] : in.interior_first + GlobalIndex(r - t.boundary);
      if (g < 0) {
        if (skip_dirichlet) continue;
        g = -1 - g;
      }
      for (std::int64_t e = k.row_start[r]; e < k.row_start[r + 1]; ++e)
        if (std::size_t(k.column[std::size_t(e)]) == r)
          d[std::size_t(g)] += in.coefficient * k.value[std::size_t(e)] +
                               (t.mass.empty() ? 0.0 : in.reaction * t.mass[std::size_t(e)]);
    }
  }
}

std::vector<double> TemplatedCsr::diagonal(bool constrained) const {
  std::vector<double> d(unknowns, 0.0);
  add_diagonal_instances(templates, instances, constrained, d.data());
  if (constrained)
    for (GlobalIndex g : dirichlet) d[std::size_t(g)] = 1.0;
  return d;
}

CsrMatrix TemplatedCsr::to_csr(bool constrained) const {
  // Entries with duplicates (shared rows get one run per instance), then merged per row.
  std::vector<std::int64_t> count(unknowns + 1, 0);
  std::vector<std::vector<GlobalIndex>> ids(instances.size());
  for (std::size_t i = 0; i < instances.size(); ++i) instances[i].boundary_ids(ids[i]);
  const auto row_global = [&](std::size_t i, std::size_t r) {
    const auto& in = instances[i];
    const auto& t = templates[in.template_index];
    if (r >= t.boundary) return in.interior_first + GlobalIndex(r - t.boundary);
    return ids[i][r];
  };
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const auto& t = templates[instances[i].template_index];
    for (std::size_t r = 0; r < t.vertices; ++r) {
      GlobalIndex g = row_global(i, r);
      if (g < 0) g = -1 - g;
      count[std::size_t(g) + 1] += t.stiffness.row_start[r + 1] - t.stiffness.row_start[r];
    }
  }
  for (std::size_t r = 0; r < unknowns; ++r) count[r + 1] += count[r];
  std::vector<std::int64_t> fill(count.begin(), count.end() - 1);
  std::vector<std::pair<GlobalIndex, double>> entries(static_cast<std::size_t>(count[unknowns]));
  for (std::size_t i = 0; i < instances.size(); ++i) {
    const auto& in = instances[i];
    const auto& t = templates[in.template_index];
    const auto& k = t.stiffness;
    for (std::size_t r = 0; r < t.vertices; ++r) {
      GlobalIndex g = row_global(i, r);
      const bool dirichlet_row = g < 0;
      if (g < 0) g = -1 - g;
      for (std::int64_t e = k.row_start[r]; e < k.row_start[r + 1]; ++e) {
        GlobalIndex c = row_global(i, std::size_t(k.column[std::size_t(e)]));
        const bool dirichlet_column = c < 0;
        if (c < 0) c = -1 - c;
        double v = in.coefficient * k.value[std::size_t(e)] +
                   (t.mass.empty() ? 0.0 : in.reaction * t.mass[std::size_t(e)]);
        if (constrained && (dirichlet_row || dirichlet_column)) v = 0; // identity added below
        entries[std::size_t(fill[std::size_t(g)]++)] = {c, v};
      }
    }
  }
  CsrMatrix a;
  a.rows = unknowns;
  a.row_start.assign(unknowns + 1, 0);
  for (std::size_t r = 0; r < unknowns; ++r) {
    auto* begin = entries.data() + count[r];
    auto* end = entries.data() + count[r + 1];
    std::sort(begin, end, [](const auto& p, const auto& q) { return p.first < q.first; });
    for (auto* e = begin; e != end; ++e) {
      if (!a.column.empty() && a.row_start[r] < std::int64_t(a.column.size()) &&
          a.column.back() == e->first) {
        a.value.back() += e->second;
      } else {
        a.column.push_back(e->first);
        a.value.push_back(e->second);
      }
    }
    a.row_start[r + 1] = std::int64_t(a.column.size());
  }
  if (constrained)
    for (GlobalIndex d : dirichlet) {
      auto* begin = a.column.data() + a.row_start[std::size_t(d)];
      auto* end = a.column.data() + a.row_start[std::size_t(d) + 1];
      a.value[std::size_t(std::lower_bound(begin, end, d) - a.column.data())] = 1.0;
    }
  return a;
}

void TemplatedCsr::set_dirichlet(std::vector<GlobalIndex> nodes) {
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  dirichlet = std::move(nodes);
  std::vector<GlobalIndex> ids;
  for (auto& in : instances) {
    in.boundary_ids(ids);
    for (auto& g : ids) {
      const GlobalIndex u = g < 0 ? -1 - g : g;
      g = std::binary_search(dirichlet.begin(), dirichlet.end(), u) ? -1 - u : u;
    }
    in.set_boundary(ids);
  }
}

std::size_t TemplatedCsr::bytes() const {
  std::size_t b = dirichlet.size() * sizeof(GlobalIndex);
  for (const auto& t : templates) b += t.bytes();
  for (const auto& in : instances) b += in.bytes();
  return b;
}

bool TemplatedCsr::is_valid(std::ostream* why) const {
  const auto fail = [&](const std::string& m) {
    if (why) *why << "TemplatedCsr: " << m;
    return false;
  };
  for (const auto& t : templates) {
    if (!t.stiffness.is_valid(why)) return false;
    if (t.boundary > t.vertices || t.row_of.size() != t.vertices || t.stiffness.rows != t.vertices)
      return fail("template sizes do not match");
  }
  for (const auto& in : instances) {
    if (in.template_index >= templates.size()) return fail("instance of a missing template");
    const auto& t = templates[in.template_index];
    if (in.boundary_rows != t.boundary) return fail("boundary map size");
    if (in.interior_first < 0 ||
        std::size_t(in.interior_first) + (t.vertices - t.boundary) > unknowns)
      return fail("interior range out of bounds");
    for (GlobalIndex g : in.boundary_ids())
      if ((g < 0 ? -1 - g : g) >= GlobalIndex(unknowns)) return fail("boundary id out of range");
  }
  return true;
}

TemplatedCsr assemble_templated_csr(const mesh::TemplatedMeshCompactSvb& t,
                                    const std::function<double(mesh::RegionIdType)>& coefficient,
                                    const std::function<double(mesh::RegionIdType)>& reaction) {
  std::ostringstream why;
  if (!t.is_valid(&why)) throw std::invalid_argument("templated mesh: " + why.str());
  TemplatedCsr a;
  a.dimension = t.templated.point_dimension;
  if (a.dimension != 2 && a.dimension != 3)
    throw std::invalid_argument("P1 assembly needs a 2D or 3D templated mesh");
  bool with_mass = false;
  if (reaction)
    for (const auto& tm : t.templated.templates)
      for (auto r : tm.region_ids) {
        const double sigma = reaction(r);
        if (!(sigma >= 0) || !std::isfinite(sigma))
          throw std::invalid_argument("the reaction coefficient of region " + std::to_string(r) +
                                      " must be a finite number >= 0");
        with_mass = with_mass || sigma > 0;
      }
  for (std::size_t i = 0; i < t.templated.templates.size(); ++i) {
    const auto& m = t.templated.templates[i].mesh;
    a.templates.push_back(a.dimension == 2 ? template_matrix<2>(m, i, with_mass)
                                           : template_matrix<3>(m, i, with_mass));
  }
  // Instances in global (template-major) order; union-find over their boundary rows.
  std::vector<std::size_t> slot_first{0};
  for (std::size_t i = 0; i < t.templated.templates.size(); ++i) {
    const auto& tm = t.templated.templates[i];
    for (std::size_t g = 0; g < tm.instance_count(); ++g) {
      InstanceMap in;
      in.template_index = std::uint32_t(i);
      in.coefficient = coefficient(tm.region_ids[g]);
      in.reaction = with_mass ? reaction(tm.region_ids[g]) : 0.0;
      if (!(in.coefficient > 0) || !std::isfinite(in.coefficient))
        throw std::invalid_argument("the coefficient of region " +
                                    std::to_string(tm.region_ids[g]) +
                                    " must be a positive finite number");
      a.instances.push_back(std::move(in));
      slot_first.push_back(slot_first.back() + a.templates[i].boundary);
    }
  }
  if (slot_first.back() > std::size_t(std::numeric_limits<GlobalIndex>::max()))
    throw std::invalid_argument("more than 2^31 boundary unknowns");
  mesh::UnionFind classes(slot_first.back());
  for (const auto& id : t.identifications) {
    const auto& table = t.tables[std::size_t(id.table)];
    const auto& from = a.templates[table.from_template];
    const auto& to = a.templates[table.to_template];
    for (const auto& [p, q] : table.pairs) {
      const auto rp = std::size_t(from.row_of[std::size_t(p)]);
      const auto rq = std::size_t(to.row_of[std::size_t(q)]);
      if (rp >= from.boundary || rq >= to.boundary)
        throw std::invalid_argument("templated mesh: an identified vertex is not on its "
                                    "template's boundary");
      classes.unite(slot_first[std::size_t(id.from_instance)] + rp,
                    slot_first[std::size_t(id.to_instance)] + rq);
    }
  }
  std::vector<GlobalIndex> number(slot_first.back(), -1);
  std::size_t next = 0;
  for (std::size_t k = 0; k < a.instances.size(); ++k) {
    auto& in = a.instances[k];
    const auto& tm = a.templates[in.template_index];
    std::vector<GlobalIndex> ids(tm.boundary);
    for (std::size_t r = 0; r < tm.boundary; ++r) {
      auto& n = number[classes.find(slot_first[k] + r)];
      if (n < 0) n = GlobalIndex(next++);
      ids[r] = n;
    }
    in.set_boundary(ids);
    in.interior_first = GlobalIndex(next);
    next += tm.vertices - tm.boundary;
    if (next > std::size_t(std::numeric_limits<GlobalIndex>::max()))
      throw std::invalid_argument("more than 2^31 unknowns");
  }
  a.unknowns = next;
  return a;
}

namespace {

/// A cell's vertices as its instance's transformation x -> A x + b of the template's, in long
/// double: the products of two doubles keep 64 of their 106 bits, so the cell's edge vectors are
/// exact to about 1e-19 |x| instead of the 1e-16 |x| of AT's double coordinates.
template <int D>
std::array<std::array<long double, D>, D + 1>
extended_cell(const mesh::StructureInstance::Instance& in, std::size_t c) {
  const auto& m = in.mesh_template->mesh;
  const auto v = mesh::oriented_cell(m, c, in.reverses);
  const auto& f = *in.transformation;
  std::array<std::array<long double, D>, D + 1> x{};
  for (int k = 0; k <= D; ++k) {
    const double* p = m.vertex(std::size_t(v[std::size_t(k)]));
    for (int r = 0; r < D; ++r) {
      long double s = f.translation[std::size_t(r)];
      for (int q = 0; q < D; ++q)
        s += static_cast<long double>(f.matrix[std::size_t(r * D + q)]) * p[q];
      x[std::size_t(k)][std::size_t(r)] = s;
    }
  }
  return x;
}

template <int D, class Real>
ElementMatrix<D> cell_matrix(const std::array<const Real*, D + 1>& p, double kappa, double sigma) {
  auto e = p1_stiffness<D, Real>(p);
  const auto m = p1_mass<D, Real>(p);
  for (std::size_t i = 0; i <= std::size_t(D); ++i)
    for (std::size_t j = 0; j <= std::size_t(D); ++j) e[i][j] = kappa * e[i][j] + sigma * m[i][j];
  return e;
}

template <int D>
CsrMatrix assemble_direct(const mesh::StructureInstance& at,
                          const std::function<double(mesh::RegionIdType)>& coefficient,
                          const std::function<double(mesh::RegionIdType)>& reaction,
                          const TemplatedCsr& numbering, CellCoordinates coordinates) {
  // AT's coordinates and cells, renumbered to the TCSR's unknowns through the instances.
  std::vector<GlobalIndex> unknown_of(at.vertex_count(), -1);
  at.for_each_instance([&](const mesh::StructureInstance::Instance& in) {
    const auto& g = *in.global;
    for (std::size_t v = 0; v < g.size(); ++v)
      unknown_of[std::size_t(g[v])] = numbering.global(in.index, v);
  });
  std::vector<double> x(numbering.unknowns * std::size_t(D), 0.0);
  std::size_t next = 0;
  at.for_each_vertex([&](const double* p) {
    for (int d = 0; d < D; ++d)
      x[std::size_t(unknown_of[next]) * std::size_t(D) + std::size_t(d)] = p[d];
    ++next;
  });
  std::vector<std::array<GlobalIndex, 4>> cells;
  std::vector<double> kappa, sigma;
  std::vector<std::array<std::array<long double, D>, D + 1>> extended;
  at.for_each_cell([&](const mesh::StructureInstance::Instance& in, std::size_t c,
                       const std::array<IndexType, 4>& v) {
    std::array<GlobalIndex, 4> g{};
    for (int k = 0; k <= D; ++k) g[std::size_t(k)] = unknown_of[std::size_t(v[std::size_t(k)])];
    cells.push_back(g);
    kappa.push_back(coefficient(in.region));
    sigma.push_back(reaction ? reaction(in.region) : 0.0);
    if (coordinates == CellCoordinates::extended_per_cell)
      extended.push_back(extended_cell<D>(in, c));
  });
  return assemble_csr<D>(
      numbering.unknowns, cells.size(), [&](std::size_t c) { return cells[c]; },
      [&](std::size_t c) {
        if (coordinates == CellCoordinates::extended_per_cell) {
          std::array<const long double*, D + 1> p{};
          for (std::size_t k = 0; k <= std::size_t(D); ++k) p[k] = extended[c][k].data();
          return cell_matrix<D, long double>(p, kappa[c], sigma[c]);
        }
        std::array<const double*, D + 1> p{};
        for (std::size_t k = 0; k <= std::size_t(D); ++k)
          p[k] = &x[std::size_t(cells[c][k]) * std::size_t(D)];
        return cell_matrix<D, double>(p, kappa[c], sigma[c]);
      });
}

} // namespace

CsrMatrix
assemble_structure_instance_csr(const mesh::TemplatedMeshCompactSvb& t,
                                const std::function<double(mesh::RegionIdType)>& coefficient,
                                const std::function<double(mesh::RegionIdType)>& reaction,
                                const TemplatedCsr& numbering, CellCoordinates coordinates) {
  const mesh::StructureInstance at(t);
  if (at.dimension() == 2)
    return assemble_direct<2>(at, coefficient, reaction, numbering, coordinates);
  return assemble_direct<3>(at, coefficient, reaction, numbering, coordinates);
}

CsrMatrix constrain(const CsrMatrix& a, const std::vector<GlobalIndex>& dirichlet) {
  CsrMatrix b = a;
  const auto is_dirichlet = [&](GlobalIndex g) {
    return std::binary_search(dirichlet.begin(), dirichlet.end(), g);
  };
  for (std::size_t r = 0; r < b.rows; ++r)
    for (std::int64_t e = b.row_start[r]; e < b.row_start[r + 1]; ++e) {
      const GlobalIndex c = b.column[std::size_t(e)];
      if (is_dirichlet(GlobalIndex(r)) || is_dirichlet(c))
        b.value[std::size_t(e)] = std::size_t(c) == r ? 1.0 : 0.0;
    }
  return b;
}

} // namespace symmesh::fem
