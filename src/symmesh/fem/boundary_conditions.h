/// Boundary conditions on the structure instance, applied to a TCSR system — spec/fem.md#bc
///
/// Data are given on facets of the structure instance's boundary (edges in 2D, triangles in 3D)
/// chosen by selectors: a facet is selected when every given key holds — the region, template or
/// global instance number of the instance it belongs to, and a closed box holding all its
/// vertices, and a hyperplane n·x = d (a line in 2D) on which all its vertices lie up to a relative
/// 1e-9 (the vertices of rotated instances are rounded). An empty selector is the whole boundary.
/// AT's boundary facets are found per instance from the template's boundary facets, dropping those
/// that a second instance also has (an interface): no structure-instance mesh is built.
#pragma once
#include "symmesh/fem/templated_csr.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace symmesh::fem {

struct BoundarySelector {
  std::string where; ///< its JSON path, for messages (e.g. "dirichlet[0].on")
  std::optional<mesh::RegionIdType> region;
  std::optional<std::size_t> template_index, instance;
  std::optional<std::array<std::array<double, 3>, 2>> box; ///< min, max (z ignored in 2D)
  std::optional<std::array<double, 4>> plane;              ///< n (3 entries), d: n·x = d
};

struct BoundaryCondition {
  BoundarySelector on;
  double value = 0; ///< Dirichlet value u, or Neumann flux g = κ ∂u/∂n
};

/// -div(κ ∇u) = source in Ω, u = value on the Dirichlet facets, κ ∂u/∂n = flux on the Neumann
/// facets, κ ∂u/∂n = 0 on the rest. Later entries win where Dirichlet facets share vertices.
struct BoundaryConditions {
  std::vector<BoundaryCondition> dirichlet, neumann;
  double source = 0;
};

struct BoundarySummary {
  std::size_t boundary_facets = 0, dirichlet_unknowns = 0;
  std::vector<std::size_t> dirichlet_facets, neumann_facets; ///< per entry
};

/// Marks the Dirichlet unknowns in `a` and returns the right-hand side of the constrained system
/// (b = F + N − A u_D on free rows, b = u_D on Dirichlet rows); `u` receives u_D (zero elsewhere),
/// the initial guess. Throws std::invalid_argument naming the selector that selects no boundary
/// facet, or when no Dirichlet unknown exists (the pure Neumann problem is singular).
std::vector<double> apply_boundary_conditions(TemplatedCsr& a,
                                              const mesh::TemplatedMeshCompactSvb& t,
                                              const BoundaryConditions& bc, std::vector<double>& u,
                                              BoundarySummary* summary = nullptr);

} // namespace symmesh::fem
