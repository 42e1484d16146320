// Exact Delaunay verdict of a generated 3D templated mesh's structure instance (Technique 5.8,
// Section 5.2.5) — spec/adaptation.md#technique-5-8
//
// Shared by the Technique 5.8 property (technique_5_8_make_delaunay.cpp) and the fuzz harness of
// Technique 5.8 in 3D (fuzz/fuzz_delaunay_3d.cpp): every interior triangle of AT, found from the
// SVB's numbering, tested both ways with exact in-sphere signs on the result's doubles (taken as
// rationals) — the apex of one cell not strictly inside the circumsphere of the other. With every
// interior triangle locally Delaunay, AT is a constrained Delaunay tetrahedralization of its
// domain, Delaunay where the domain is convex.
#pragma once
#include "proofs-checks/box_inputs.h"
#include "symmesh/mesh/structure_instance.h"
#include "symmesh/mesh/templated_mesh.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace symmesh::proofs {

using ExactPoint = std::array<mpq_class, 3>;

/// det of the 4×4 lifted matrix [p_i − e, |p_i − e|²]: its sign tells the side of e with respect
/// to the sphere through p_0..p_3 (the opposite sign of a far point's means inside).
inline mpq_class lifted_determinant(const std::array<const ExactPoint*, 4>& p,
                                    const ExactPoint& e) {
  mpq_class m[4][4];
  for (int i = 0; i < 4; ++i) {
    mpq_class lift = 0;
    for (int k = 0; k < 3; ++k) {
      m[i][k] = (*p[std::size_t(i)])[std::size_t(k)] - e[std::size_t(k)];
      lift += m[i][k] * m[i][k];
    }
    m[i][3] = lift;
  }
  const auto det3 = [&](int r0, int r1, int r2, int c0, int c1, int c2) -> mpq_class {
    return m[r0][c0] * (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) -
           m[r0][c1] * (m[r1][c0] * m[r2][c2] - m[r1][c2] * m[r2][c0]) +
           m[r0][c2] * (m[r1][c0] * m[r2][c1] - m[r1][c1] * m[r2][c0]);
  };
  // Expansion along the first row; kMinor[c] are the columns of the minor of entry (0, c).
  static constexpr int kMinor[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  mpq_class d = 0;
  for (int c = 0; c < 4; ++c) {
    const mpq_class term = m[0][c] * det3(1, 2, 3, kMinor[c][0], kMinor[c][1], kMinor[c][2]);
    if (c % 2)
      d -= term;
    else
      d += term;
  }
  return d;
}

/// One cell of AT: its AT vertex numbers, its instance, and its vertices twice: the template's
/// coordinates and the instance's image of them as the library computes it
/// (Transformation::apply, doubles), both taken as exact rationals.
struct ExactCell {
  std::array<mesh::IndexType, 4> ids;
  std::size_t instance = 0;
  std::array<ExactPoint, 4> in_template, image;
  int far_in_template = 0, far_image = 0; ///< side of a point far outside the circumsphere
};

inline int far_side(const std::array<ExactPoint, 4>& x) {
  ExactPoint far = x[0];
  far[0] += mpq_class(1L << 40); // beyond the circumsphere of every non-degenerate cell here
  return sgn(lifted_determinant({&x[0], &x[1], &x[2], &x[3]}, far));
}

/// Interior triangles of AT: how many, and how many not locally Delaunay. A cospherical tie
/// (the apex exactly on the circumsphere) is locally Delaunay; an apex inside by any margin is
/// not, also where the five points are cospherical up to rounding (the library resolves those
/// by vertex deletion or insertion: technique_5_8_3d.cpp, resolve_slivers).
struct DelaunayVerdict {
  std::size_t interior = 0, not_locally_delaunay = 0, overfull = 0;
  /// Of those, the ones whose apex is inside by more than rounding: |D| / L^5 > 1e-9 (the
  /// library's allowance where rounded copies make ties systematic, technique_5_8_3d.cpp).
  std::size_t beyond_rounding = 0;
  mpq_class volume = 0;
};

/// Every interior triangle of AT locally Delaunay both ways. Two cells of one instance are tested
/// in their template's coordinates (a rigid copy of the template, which the library keeps
/// Delaunay); two cells of different instances in the instances' images, the coordinates in
/// which the library decides Definition 4.10 (identified copies of a vertex may differ there by
/// the rounding of the transformations, and a cospherical tie is decided by those doubles). All
/// signs are exact.
inline DelaunayVerdict exact_delaunay_verdict(const mesh::TemplatedMeshCompactSvb& t) {
  DelaunayVerdict out;
  const mesh::StructureInstance si(t);
  std::vector<ExactCell> cells;
  si.for_each_cell([&](const mesh::StructureInstance::Instance& in, std::size_t c,
                       const std::array<mesh::IndexType, 4>& ids) {
    const auto& m = in.mesh_template->mesh;
    const auto local = mesh::oriented_cell(m, c, in.reverses);
    ExactCell e;
    e.ids = ids;
    e.instance = in.index;
    std::array<const double*, 4> corners{};
    for (std::size_t q = 0; q < 4; ++q) {
      const double* v = m.vertex(std::size_t(local[q]));
      corners[q] = v;
      double image[3];
      in.transformation->apply(v, image);
      for (std::size_t i = 0; i < 3; ++i) {
        e.in_template[q][i] = v[i];
        e.image[q][i] = image[i];
      }
    }
    out.volume += boxes::simplex_measure_times_factorial(corners, 3) / 6;
    e.far_in_template = far_side(e.in_template);
    e.far_image = far_side(e.image);
    cells.push_back(std::move(e));
  });
  std::map<std::array<mesh::IndexType, 3>, std::vector<std::pair<std::size_t, std::size_t>>> facets;
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (std::size_t apex = 0; apex < 4; ++apex) {
      std::array<mesh::IndexType, 3> f;
      std::size_t n = 0;
      for (std::size_t q = 0; q < 4; ++q)
        if (q != apex) f[n++] = cells[c].ids[q];
      std::sort(f.begin(), f.end());
      facets[f].push_back({c, apex});
    }
  // Whether apex `a` of cell `d` lies strictly inside the circumsphere of cell `c` (exact).
  // Whether apex `a` of cell `d` lies strictly inside the circumsphere of cell `c` (exact), and
  // by how much: |D| / L^5, L the largest distance among the five points.
  const auto inside = [&](const ExactCell& c, const ExactCell& d, std::size_t a, double& by) {
    const bool own = c.instance == d.instance;
    const auto& x = own ? c.in_template : c.image;
    const auto& e = own ? d.in_template[a] : d.image[a];
    const mpq_class det = lifted_determinant({&x[0], &x[1], &x[2], &x[3]}, e);
    if (!(sgn(det) != 0 && sgn(det) == -(own ? c.far_in_template : c.far_image))) return false;
    double span = 0;
    const std::array<const ExactPoint*, 5> p{&x[0], &x[1], &x[2], &x[3], &e};
    for (const auto* u : p)
      for (const auto* w : p) {
        double dd = 0;
        for (std::size_t k = 0; k < 3; ++k) dd += std::pow(mpq_class((*u)[k] - (*w)[k]).get_d(), 2);
        span = std::max(span, std::sqrt(dd));
      }
    by = std::abs(det.get_d()) / std::pow(span, 5);
    return true;
  };
  for (const auto& [f, on] : facets) {
    if (on.size() > 2) ++out.overfull;
    if (on.size() != 2) continue;
    ++out.interior;
    const auto& [c1, a1] = on[0];
    const auto& [c2, a2] = on[1];
    double by1 = 0, by2 = 0;
    const bool in1 = inside(cells[c1], cells[c2], a2, by1),
               in2 = inside(cells[c2], cells[c1], a1, by2);
    if (in1 || in2) ++out.not_locally_delaunay;
    if (std::max(by1, by2) > 1e-9) ++out.beyond_rounding;
  }
  return out;
}

} // namespace symmesh::proofs
