// Boundary conditions on AT's boundary facets (spec/fem.md#bc).
#include "symmesh/fem/boundary_conditions.h"

#include "symmesh/fem/p1_element.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace symmesh::fem {
namespace {

struct InstanceInfo {
  std::size_t template_index = 0;
  mesh::RegionIdType region = 0;
  const mesh::Transformation* transformation = nullptr;
};

bool selects(const BoundarySelector& s, std::size_t instance, const InstanceInfo& in,
             const std::array<std::array<double, 3>, 3>& x, int dim) {
  if (s.region && *s.region != in.region) return false;
  if (s.template_index && *s.template_index != in.template_index) return false;
  if (s.instance && *s.instance != instance) return false;
  if (s.plane)
    for (int v = 0; v < dim; ++v) {
      const auto& p = *s.plane;
      double nx = 0, scale = std::abs(p[3]);
      for (int d = 0; d < dim; ++d) {
        nx += p[std::size_t(d)] * x[std::size_t(v)][std::size_t(d)];
        scale += std::abs(p[std::size_t(d)] * x[std::size_t(v)][std::size_t(d)]);
      }
      if (std::abs(nx - p[3]) > 1e-9 * std::max(scale, 1e-300)) return false;
    }
  if (s.box)
    for (int v = 0; v < dim; ++v)
      for (int d = 0; d < dim; ++d) {
        const double c = x[std::size_t(v)][std::size_t(d)];
        if (c < (*s.box)[0][std::size_t(d)] || c > (*s.box)[1][std::size_t(d)]) return false;
      }
  return true;
}

double simplex_volume(const mesh::Mesh& m, std::size_t c, int dim) {
  const auto* v = m.cell(c);
  if (dim == 2) {
    std::array<std::array<double, 2>, 3> g{};
    return barycentric_gradients<2>(
        {m.vertex(std::size_t(v[0])), m.vertex(std::size_t(v[1])), m.vertex(std::size_t(v[2]))}, g);
  }
  std::array<std::array<double, 3>, 4> g{};
  return barycentric_gradients<3>({m.vertex(std::size_t(v[0])), m.vertex(std::size_t(v[1])),
                                   m.vertex(std::size_t(v[2])), m.vertex(std::size_t(v[3]))},
                                  g);
}

double facet_measure(const std::array<std::array<double, 3>, 3>& x, int dim) {
  double u[3], w[3];
  for (int d = 0; d < 3; ++d) {
    u[d] = x[1][std::size_t(d)] - x[0][std::size_t(d)];
    w[d] = x[2][std::size_t(d)] - x[0][std::size_t(d)];
  }
  if (dim == 2) return std::sqrt(u[0] * u[0] + u[1] * u[1]);
  const double c0 = u[1] * w[2] - u[2] * w[1], c1 = u[2] * w[0] - u[0] * w[2],
               c2 = u[0] * w[1] - u[1] * w[0];
  return 0.5 * std::sqrt(c0 * c0 + c1 * c1 + c2 * c2);
}

} // namespace

std::vector<double> apply_boundary_conditions(TemplatedCsr& a,
                                              const mesh::TemplatedMeshCompactSvb& t,
                                              const BoundaryConditions& bc, std::vector<double>& u,
                                              BoundarySummary* summary) {
  const int dim = a.dimension;
  std::vector<InstanceInfo> info;
  for (std::size_t i = 0; i < t.templated.templates.size(); ++i) {
    const auto& tm = t.templated.templates[i];
    for (std::size_t g = 0; g < tm.instance_count(); ++g)
      info.push_back({i, tm.region_ids[g],
                      &t.templated.transformations[std::size_t(tm.transformation_indices[g])]});
  }
  // Per template: its boundary facets (template vertex ids).
  std::vector<std::vector<std::array<GlobalIndex, 3>>> facets;
  for (const auto& tm : t.templated.templates)
    facets.push_back(template_boundary_facets(tm.mesh, dim));
  // Unknowns on two or more instances, then the facets all of whose vertices are such: an
  // interface facet is one of them that two instances have.
  std::vector<std::uint8_t> seen(a.unknowns, 0);
  std::vector<GlobalIndex> ids;
  for (const auto& in : a.instances) {
    in.boundary_ids(ids);
    for (GlobalIndex g : ids) {
      auto& s = seen[std::size_t(g < 0 ? -1 - g : g)];
      if (s < 2) ++s;
    }
  }
  std::map<std::array<GlobalIndex, 3>, int> shared_facets;
  const auto facet_globals = [&](std::size_t k, const std::array<GlobalIndex, 3>& vertices) {
    std::array<GlobalIndex, 3> g{-1, -1, -1};
    for (int q = 0; q < dim; ++q)
      g[std::size_t(q)] = a.global(k, std::size_t(vertices[std::size_t(q)]));
    std::sort(g.begin(), g.begin() + dim);
    return g;
  };
  const auto all_shared = [&](const std::array<GlobalIndex, 3>& g) {
    for (int q = 0; q < dim; ++q)
      if (seen[std::size_t(g[std::size_t(q)])] < 2) return false;
    return true;
  };
  for (std::size_t k = 0; k < a.instances.size(); ++k)
    for (const auto& f : facets[a.instances[k].template_index]) {
      const auto g = facet_globals(k, f);
      if (all_shared(g)) ++shared_facets[g];
    }
  // Visit AT's boundary facets with their coordinates.
  const auto for_each_facet = [&](auto&& visit) {
    for (std::size_t k = 0; k < a.instances.size(); ++k) {
      const auto& tm = t.templated.templates[info[k].template_index].mesh;
      for (const auto& f : facets[info[k].template_index]) {
        const auto g = facet_globals(k, f);
        if (all_shared(g) && shared_facets[g] > 1) continue;
        std::array<std::array<double, 3>, 3> x{};
        std::array<GlobalIndex, 3> unknowns{-1, -1, -1};
        for (int q = 0; q < dim; ++q) {
          const auto v = std::size_t(f[std::size_t(q)]);
          info[k].transformation->apply(tm.vertex(v), x[std::size_t(q)].data());
          unknowns[std::size_t(q)] = a.global(k, v);
        }
        visit(k, x, unknowns);
      }
    }
  };
  BoundarySummary s;
  s.dirichlet_facets.assign(bc.dirichlet.size(), 0);
  s.neumann_facets.assign(bc.neumann.size(), 0);
  std::vector<double> b(a.unknowns, 0.0);
  // The last Dirichlet entry that selects a facet at a vertex sets its value (whatever the order
  // in which the facets are visited: a vertex where two entries meet gets the later entry's value).
  std::vector<int> entry_of(a.unknowns, -1);
  for_each_facet([&](std::size_t k, const auto& x, const auto& unknowns) {
    ++s.boundary_facets;
    for (std::size_t e = 0; e < bc.dirichlet.size(); ++e)
      if (selects(bc.dirichlet[e].on, k, info[k], x, dim)) {
        ++s.dirichlet_facets[e];
        for (int q = 0; q < dim; ++q) {
          int& at = entry_of[std::size_t(unknowns[std::size_t(q)])];
          at = std::max(at, int(e));
        }
      }
    for (std::size_t e = 0; e < bc.neumann.size(); ++e)
      if (selects(bc.neumann[e].on, k, info[k], x, dim)) {
        ++s.neumann_facets[e];
        const double share = bc.neumann[e].value * facet_measure(x, dim) / dim;
        for (int q = 0; q < dim; ++q) b[std::size_t(unknowns[std::size_t(q)])] += share;
      }
  });
  for (std::size_t e = 0; e < bc.dirichlet.size(); ++e)
    if (s.dirichlet_facets[e] == 0)
      throw std::invalid_argument(bc.dirichlet[e].on.where + ": selects no boundary facet");
  for (std::size_t e = 0; e < bc.neumann.size(); ++e)
    if (s.neumann_facets[e] == 0)
      throw std::invalid_argument(bc.neumann[e].on.where + ": selects no boundary facet");
  std::vector<GlobalIndex> nodes;
  std::vector<double> value(a.unknowns, 0.0);
  for (std::size_t g = 0; g < a.unknowns; ++g)
    if (entry_of[g] >= 0) {
      nodes.push_back(GlobalIndex(g));
      value[g] = bc.dirichlet[std::size_t(entry_of[g])].value;
    }
  if (nodes.empty())
    throw std::invalid_argument("dirichlet: no Dirichlet data; the pure Neumann problem is "
                                "singular");
  s.dirichlet_unknowns = nodes.size();
  // The source: F = source · ∫ φ_i, ∫ φ_i = Σ |T| / (D + 1) (exact for a constant source).
  if (bc.source != 0) {
    std::vector<std::vector<double>> load;
    for (const auto& tm : t.templated.templates) {
      std::vector<double> l(tm.mesh.vertex_count(), 0.0);
      for (std::size_t c = 0; c < tm.mesh.cell_count(); ++c) {
        const double share = simplex_volume(tm.mesh, c, dim) / (dim + 1);
        for (int q = 0; q <= dim; ++q) l[std::size_t(tm.mesh.cell(c)[q])] += share;
      }
      load.push_back(std::move(l));
    }
    for (std::size_t k = 0; k < a.instances.size(); ++k) {
      const auto& l = load[a.instances[k].template_index];
      for (std::size_t v = 0; v < l.size(); ++v) b[std::size_t(a.global(k, v))] += bc.source * l[v];
    }
  }
  a.set_dirichlet(nodes);
  u = value;
  std::vector<double> au(a.unknowns);
  a.multiply(value.data(), au.data(), false);
  for (std::size_t g = 0; g < a.unknowns; ++g) b[g] = entry_of[g] >= 0 ? value[g] : b[g] - au[g];
  if (summary) *summary = s;
  return b;
}

} // namespace symmesh::fem
