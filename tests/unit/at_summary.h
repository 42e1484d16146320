// The structure instance of a 3D templated mesh summarised independently of the generator
// (shared by the generation, mesher and outlier-repair tests): AT assembled from the SVB, faces
// counted by vertex ids, volumes and boundary area from the double coordinates.
#pragma once
#include "symmesh/mesh/templated_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>

namespace symmesh::test {

/// The signed volume of tetrahedron abcd (positive when abcd is positively oriented).
inline double signed_volume(const double* a, const double* b, const double* c, const double* d) {
  double u[3][3];
  for (int k = 0; k < 3; ++k) {
    u[0][k] = b[k] - a[k];
    u[1][k] = c[k] - a[k];
    u[2][k] = d[k] - a[k];
  }
  return (u[0][0] * (u[1][1] * u[2][2] - u[1][2] * u[2][1]) -
          u[0][1] * (u[1][0] * u[2][2] - u[1][2] * u[2][0]) +
          u[0][2] * (u[1][0] * u[2][1] - u[1][1] * u[2][0])) /
         6;
}

struct AtSummary {
  std::size_t tetrahedra = 0, non_positive = 0, faces_in_more_than_two = 0;
  double volume = 0, boundary_area = 0;
};

/// Independent of the generator: the structure instance from the SVB, face counts by vertex ids,
/// volumes and boundary area from the double coordinates.
inline AtSummary summarise(const mesh::TemplatedMeshCompactSvb& t) {
  const auto at = mesh::assemble_structure_instance(t);
  const auto& m = at.mesh.mesh;
  AtSummary s;
  std::map<std::array<int, 3>, int> faces;
  const auto p = [&](int v, int d) { return m.vertex(std::size_t(v))[d]; };
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    const auto* v = m.cell(c);
    const double vol = signed_volume(m.vertex(std::size_t(v[0])), m.vertex(std::size_t(v[1])),
                                     m.vertex(std::size_t(v[2])), m.vertex(std::size_t(v[3])));
    if (!(vol > 0)) ++s.non_positive;
    s.volume += vol;
    ++s.tetrahedra;
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      int n = 0;
      for (int k = 0; k < 4; ++k)
        if (k != skip) f[std::size_t(n++)] = v[k];
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  }
  for (const auto& [f, n] : faces) {
    if (n > 2) ++s.faces_in_more_than_two;
    if (n != 1) continue;
    double u[3], w[3];
    for (int d = 0; d < 3; ++d) {
      u[d] = p(f[1], d) - p(f[0], d);
      w[d] = p(f[2], d) - p(f[0], d);
    }
    const double cx = u[1] * w[2] - u[2] * w[1], cy = u[2] * w[0] - u[0] * w[2],
                 cz = u[0] * w[1] - u[1] * w[0];
    s.boundary_area += 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
  }
  return s;
}

} // namespace symmesh::test
