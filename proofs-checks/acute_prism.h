// A triangular prism template with an acute crease between two legs, for the property of
// Technique 5.8's crease mirroring (technique_5_8_make_delaunay.cpp) and the fuzz harness of
// Technique 5.8 in 3D (fuzz/fuzz_delaunay_3d.cpp) — spec/adaptation.md#properties
//
// Built directly as a generated templated mesh (three tetrahedra, double coordinates): the legs
// y = 0 (length 1) and the plane at `degrees` (length `leg`), height 1; alone, or with its mirror
// image across y = 0 (an exact signed permutation, identified along that leg).
#pragma once
#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/mesh/templated_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace symmesh::proofs {

/// A triangular prism template, its crease of `degrees` between the legs y = 0 (length 1) and
/// the one at that angle (length `leg`), height 1; alone or with its mirror image across y = 0.
struct AcutePrism {
  int degrees = 10;
  double leg = 0.7;
  bool mirrored = false;
  int refinements = 0;

  std::string description() const {
    return "prism, " + std::to_string(degrees) + "-degree crease, leg " + std::to_string(leg) +
           (mirrored ? ", mirrored across y = 0" : "") + ", " + std::to_string(refinements) +
           " refinements";
  }
  mesh::TemplatedMeshCompactSvb build() const {
    const double a = degrees * 3.14159265358979323846 / 180;
    mesh::TemplatedMeshCompactSvb t;
    t.templated.point_dimension = 3;
    mesh::MeshTemplate m;
    m.mesh.point_dimension = 3;
    const double c = leg * std::cos(a), sn = leg * std::sin(a);
    const double v[6][3] = {{0, 0, 0}, {1, 0, 0}, {c, sn, 0}, {0, 0, 1}, {1, 0, 1}, {c, sn, 1}};
    for (const auto& q : v) m.mesh.add_vertex(q);
    for (std::array<mesh::IndexType, 4> cell :
         {std::array<mesh::IndexType, 4>{0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 5}}) {
      double e[3][3];
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) e[k][i] = v[cell[std::size_t(k + 1)]][i] - v[cell[0]][i];
      const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                         e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
      if (det < 0) std::swap(cell[2], cell[3]);
      m.mesh.add_cell(mesh::ElementType::tetrahedron, cell.data());
    }
    t.templated.transformations.push_back({{1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}});
    m.transformation_indices.push_back(0);
    m.region_ids.push_back(1);
    if (mirrored) {
      t.templated.transformations.push_back({{1, 0, 0, 0, -1, 0, 0, 0, 1}, {0, 0, 0}});
      m.transformation_indices.push_back(1);
      m.region_ids.push_back(1);
      t.tables.push_back({0, 0, {{0, 0}, {1, 1}, {3, 3}, {4, 4}}});
      t.identifications.push_back({0, 1, 0});
    }
    t.templated.templates.push_back(std::move(m));
    adapt::expand_identifications(t);
    for (int k = 0; k < refinements; ++k)
      adapt::refine_where(t, [](const adapt::CellView&) { return true; });
    return t;
  }
};

} // namespace symmesh::proofs
