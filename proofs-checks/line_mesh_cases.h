/// Cases for Lemma 4.2 on uniform line meshes — spec/lemmas.md#lemma-4-2-line-meshes
///
/// Shared by lemma_4_2_interface_conformity.cpp (rationals) and lemma_4_2_cyclotomic.cpp (K_m):
/// the uniform line meshes of a templated structure's boundary complexes, split the way the
/// generator splits them (N = the smallest integer with N·h >= the face length, decided
/// exactly, so congruent faces get the same N), and the face-by-face verdict compared with the
/// direct conformity check of AT of the line meshes actually written out.
#pragma once
#include "symmesh/core/line_mesh_conformity.h"

#include <string>

namespace symmesh::proofs {

/// What the face-by-face check is given (`lines`, `rotation`) and what AT is made of (`actual`:
/// materialize(lines), unless a case writes other line meshes on purpose).
template <class FT>
struct LineMeshCase {
  core::LineMeshStructure<FT> lines;
  core::TemplatedStructure<FT, 2> actual;
  std::size_t rotation = 0;
};

/// Every boundary edge of every template a face, split into N parts for the size h.
/// \pre h > 0; the templates are 2D meshes
template <class FT>
core::LineMeshStructure<FT> uniform_line_meshes(const core::TemplatedStructure<FT, 2>& x,
                                                const FT& h) {
  core::LineMeshStructure<FT> out;
  out.instances = x.instances;
  for (const auto& t : x.templates) {
    const auto bnd = core::mesh_boundary(t.mesh);
    core::UniformLineMesh<FT> u;
    u.points = bnd.points;
    for (const auto& e : bnd.elements) {
      if (e.dim() != 1) continue;
      const auto d = bnd.points[e.v[1]] - bnd.points[e.v[0]];
      const FT l2 = core::dot<FT, 2>(d, d);
      std::size_t n = 1;
      while (FT(int(n * n)) * h * h < l2) ++n;
      u.faces.push_back({e.v[0], e.v[1], n});
    }
    out.templates.push_back(std::move(u));
  }
  return out;
}

template <class FT>
LineMeshCase<FT> uniform_case(const core::TemplatedStructure<FT, 2>& x, const FT& h,
                              std::size_t rotation = 0) {
  LineMeshCase<FT> c;
  c.lines = uniform_line_meshes<FT>(x, h);
  c.actual = core::materialize(c.lines);
  c.rotation = rotation;
  return c;
}

/// The face-by-face verdict and the direct check of AT(actual).
template <class FT>
struct LineMeshVerdicts {
  bool face_by_face = false, direct = false;
};
template <class FT>
LineMeshVerdicts<FT> line_mesh_verdicts(const LineMeshCase<FT>& c) {
  return {core::check_line_mesh_conformity(c.lines, c.rotation).holds,
          core::structure_instance_conforming(core::apply_template(c.actual))};
}

} // namespace symmesh::proofs
