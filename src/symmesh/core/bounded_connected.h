/// Definition A.4 (bounded, connected, piecewise connected) on the underlying space of a finite
/// set of closed simplices — spec/definitions.md#def-a-1
///
/// us(𝓔) is bounded: a closed ball about its first vertex through its farthest vertex holds every
/// simplex (balls are convex); `bounding_ball` is that witness. A finite union of closed connected
/// sets is connected iff the graph "the two closed sets meet" is connected (a split into two
/// non-empty parts with cl(X_1) ∩ X_2 = X_1 ∩ cl(X_2) = ∅ would separate the graph, and vice
/// versa), so the components of that graph, decided by exact `closed_simplices_meet`, are the
/// connected components of us(𝓔). Every such union is piecewise connected, with the components as
/// the witness. No face-completeness or conformity is needed.
#pragma once
#include "symmesh/core/ball.h"
#include "symmesh/core/element_complex.h"

#include <numeric>
#include <optional>
#include <vector>

namespace symmesh::core {

/// A closed ball holding us(e) (Def A.4 bounded); nullopt for the empty set.
template <class FT, int D>
std::optional<Ball<FT, D>> bounding_ball(const ElementComplex<FT, D>& e) {
  if (e.elements.empty()) return std::nullopt;
  Ball<FT, D> b{e.points.at(*e.elements.front().begin()), FT(1), BallKind::closed};
  for (const auto& s : e.elements)
    for (VertexId v : s) {
      const auto d = e.points.at(v) - b.center;
      const FT dd = dot<FT, D>(d, d);
      if (b.squared_radius < dd) b.squared_radius = dd;
    }
  return b;
}

/// The connected components of us(e), each as the indices of its elements in e.elements, ordered
/// by their first element.
template <class FT, int D>
std::vector<std::vector<std::size_t>> connected_components(const ElementComplex<FT, D>& e) {
  const std::size_t n = e.elements.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::vector<Box<FT, D>> boxes;
  for (const auto& s : e.elements) boxes.push_back(box_of<FT, D>(e.coords(s)));
  for_each_overlapping_pair<FT, D>(boxes, [&](std::size_t i, std::size_t j) {
    if (find(i) != find(j) &&
        closed_simplices_meet<FT, D>(e.coords(e.elements[i]), e.coords(e.elements[j])))
      parent[find(i)] = find(j);
    return true;
  });
  std::vector<std::vector<std::size_t>> out;
  std::vector<std::size_t> slot(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t r = find(i);
    if (slot[r] == n) slot[r] = out.size(), out.emplace_back();
    out[slot[r]].push_back(i);
  }
  return out;
}

/// Def A.4 connected (the empty set is).
template <class FT, int D>
bool is_connected(const ElementComplex<FT, D>& e) {
  return connected_components(e).size() <= 1;
}

} // namespace symmesh::core
