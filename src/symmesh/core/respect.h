/// Definition 2.9 (respect) and 2.10 (geometry-conformity) for linear sets —
/// spec/definitions.md#def-2-9, #def-2-10
///
/// A simplex E respects X iff E ∩ X is a union of faces of E. Since E is the disjoint union of
/// the relative interiors of its faces and X is closed, this holds iff for every face f of E
/// either relint(f) ∩ X = ∅ or f ⊆ X (spec/definitions.md#respect-by-faces).
#pragma once
#include "symmesh/core/element_complex.h"

namespace symmesh::core {

/// X given as an intersection of convex hulls of point sets (each set non-empty).
template <class FT, int D>
using ConvexIntersection = std::vector<std::vector<Point<FT, D>>>;

template <class FT, int D>
bool face_inside_convex(const std::vector<Point<FT, D>>& f, const ConvexIntersection<FT, D>& x) {
  for (const auto& p : f)
    for (const auto& hull : x)
      if (!common_point<FT, D>({{{p}, false}, {hull, false}}).closed_meet) return false;
  return true;
}

template <class FT, int D>
bool relint_meets_convex(const std::vector<Point<FT, D>>& f, const ConvexIntersection<FT, D>& x) {
  std::vector<ConvexGroup<FT, D>> groups{{f, true}};
  for (const auto& hull : x) groups.push_back({hull, false});
  return common_point<FT, D>(groups).strict_meet;
}

/// The respect test of spec/definitions.md#respect-by-faces: E respects a closed X iff every face
/// f of E is inside X or has a relative interior disjoint from X.
template <class FT, int D, class Inside, class RelintMeets>
bool respects_by_faces(const std::vector<Point<FT, D>>& e, Inside&& inside, RelintMeets&& meets) {
  std::vector<VertexId> ids(e.size());
  for (std::size_t i = 0; i < e.size(); ++i) ids[i] = VertexId(i);
  const Simplex s = Simplex::from_range(ids.data(), ids.data() + ids.size());
  for (const auto& f : faces(s)) {
    std::vector<Point<FT, D>> fp;
    for (VertexId v : f) fp.push_back(e[v]);
    if (!inside(fp) && meets(fp)) return false;
  }
  return true;
}

/// E respects X = ⋂ conv(x_j).
template <class FT, int D>
bool respects(const std::vector<Point<FT, D>>& e, const ConvexIntersection<FT, D>& x) {
  return respects_by_faces<FT, D>(
      e, [&](const auto& f) { return face_inside_convex<FT, D>(f, x); },
      [&](const auto& f) { return relint_meets_convex<FT, D>(f, x); });
}

/// E respects X = us(M), M a face-complete conforming complex. \pre DIM(E) <= 2 or E is a cell
template <class FT, int D>
bool respects_underlying_space(const std::vector<Point<FT, D>>& e, const ElementComplex<FT, D>& m) {
  return respects_by_faces<FT, D>(
      e, [&](const auto& f) { return simplex_covered_by<FT, D>(f, m); },
      [&](const auto& f) {
        for (const auto& g : m.elements)
          if (relative_interiors_meet<FT, D>(f, m.coords(g))) return true;
        return false;
      });
}

} // namespace symmesh::core
