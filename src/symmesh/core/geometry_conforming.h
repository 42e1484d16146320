/// Definition 2.10 (geometry-conformity) and Definition 4.5 (geometry-conforming templated mesh)
/// for linear geometries — spec/definitions.md#def-2-10, #def-4-5
#pragma once
#include "symmesh/core/multi_region_mesh.h"
#include "symmesh/core/templated_structure.h"

namespace symmesh::core {

/// us(M) = G for a pure D-dimensional mesh M and a linear geometry G given by a carrier mesh:
/// every cell of each lies in the underlying space of the other (exact `simplex_covered_by`).
template <class FT, int D>
bool geometry_conforms(const ElementComplex<FT, D>& m, const ElementComplex<FT, D>& g) {
  for (const auto& c : m.cells())
    if (!simplex_covered_by<FT, D>(m.coords(c), g)) return false;
  for (const auto& c : g.cells())
    if (!simplex_covered_by<FT, D>(g.coords(c), m)) return false;
  return true;
}

/// Def 2.10 for multi-region meshes: the same region ids, and each region of m geometry-conforms
/// to the region of g with the same id (so us(M) = G follows, and the regions match).
template <class FT, int D>
bool geometry_conforms(const MultiRegionMesh<FT, D>& m, const MultiRegionMesh<FT, D>& g) {
  if (m.region_ids() != g.region_ids()) return false;
  for (int i : m.region_ids())
    if (!geometry_conforms(m.region(i), g.region(i))) return false;
  return true;
}

/// Def 4.5: Γ geometry-conforms to Λ if (i) each mesh template geometry-conforms to its geometry
/// template, (ii) all transformations and (iii) all region indicators are the same.
template <class FT, int D>
bool is_geometry_conforming(const TemplatedStructure<FT, D>& gamma,
                            const TemplatedStructure<FT, D>& lambda, std::ostream* why = nullptr) {
  if (gamma.templates.size() != lambda.templates.size()) {
    if (why) *why << "different numbers of templates";
    return false;
  }
  for (std::size_t i = 0; i < gamma.templates.size(); ++i) {
    if (gamma.instances[i].size() != lambda.instances[i].size()) {
      if (why) *why << "template " << i + 1 << ": different numbers of instances";
      return false;
    }
    for (std::size_t g = 0; g < gamma.instances[i].size(); ++g) {
      if (gamma.instances[i][g].transformation != lambda.instances[i][g].transformation) {
        if (why) *why << to_string(InstanceId{i, g}) << ": transformations differ (ii)";
        return false;
      }
      if (gamma.instances[i][g].region != lambda.instances[i][g].region) {
        if (why) *why << to_string(InstanceId{i, g}) << ": region indicators differ (iii)";
        return false;
      }
    }
    if (!geometry_conforms(gamma.templates[i].mesh, lambda.templates[i].mesh)) {
      if (why) *why << "template " << i + 1 << " does not geometry-conform (i)";
      return false;
    }
  }
  return true;
}

} // namespace symmesh::core
