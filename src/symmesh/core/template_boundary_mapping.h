/// Definition 4.7 (Template boundary mapping) and Definition A.2 (composition of restricted
/// functions) — spec/boundary-patches.md#def-4-7, #def-a-2
///
/// For neighbouring instances T_{i,g} (the "to" instance) and T_{j,h} (the "from" instance),
///   𝕋_{T_{i,g},T_{j,h}} = T_{i,g}^{-1} ∘ T_{j,h} restricted to
///   T_{j,h}^{-1}(interf_geo(T_{i,g},T_{j,h}))
/// (Eq. 4.9 with the dissertation's typo T_{i,h}^{-1} read as T_{j,h}^{-1}). It maps part of
/// bnd(X_j) onto part of bnd(X_i). The domain is kept exactly as the finite union of the convex
/// pieces facet_a ∩ facet_b over pairs of boundary facets of the two instances (points and
/// segments in 2D; points, segments and convex polygons in 3D), pulled back to template j.
#pragma once
#include "symmesh/core/element_complex.h"
#include "symmesh/core/rigid_transformation.h"
#include "symmesh/core/templated_structure.h"

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::core {

/// A closed convex piece of a linear set on a template boundary: 1 point, 2 points (segment), or
/// ≥ 3 coplanar points in convex cyclic order (a polygon, 3D only).
template <class FT, int D>
struct DomainPiece {
  std::vector<Point<FT, D>> vertices;
  int dimension() const { return vertices.size() >= 3 ? 2 : int(vertices.size()) - 1; }
};

/// x ∈ piece, exactly.
template <class FT, int D>
bool piece_contains(const DomainPiece<FT, D>& piece, const Point<FT, D>& x) {
  const auto& v = piece.vertices;
  if (v.size() == 1) return v[0] == x;
  if (v.size() == 2) return point_on_segment<FT, D>(v[0], v[1], x);
  if (v.size() == 3) return point_in_simplex<FT, D>(v, x);
  for (std::size_t k = 1; k + 1 < v.size(); ++k)
    if (point_in_simplex<FT, D>({v[0], v[k], v[k + 1]}, x)) return true;
  return false;
}

template <class FT, int D>
struct TemplateBoundaryMapping {
  InstanceId to;                  ///< T_{i,g}: the image lies on bnd(X_i)
  InstanceId from;                ///< T_{j,h}: the domain lies on bnd(X_j)
  RigidTransformation<FT, D> map; ///< T_{i,g}^{-1} ∘ T_{j,h}
  /// On bnd(X_j); unused when whole_boundary. template_boundary_mappings lists the inverse's
  /// domain as the same world pieces pulled back to X_i, vertex for vertex, so it holds the
  /// images of these vertices (the BPP reads images off it).
  std::vector<DomainPiece<FT, D>> domain;
  bool whole_boundary = false; ///< the trivial 𝕋_{T,T} = I on bnd*(X_j)
  std::size_t inverse = 0;     ///< index of 𝕋_{T_{j,h},T_{i,g}} in the same list

  std::size_t from_template() const { return from.i; }
  std::size_t to_template() const { return to.i; }

  /// \pre x ∈ bnd(X_j) (not checked: the subdivision only asks for boundary points)
  bool in_domain(const Point<FT, D>& x) const {
    if (whole_boundary) return true;
    for (const auto& p : domain)
      if (piece_contains<FT, D>(p, x)) return true;
    return false;
  }

  std::string name() const { return "𝕋_{" + to_string(to) + "," + to_string(from) + "}"; }
};

/// All template boundary mappings of X: one trivial identity per template (𝕋_{T_{i,1},T_{i,1}})
/// and, for every ordered pair of distinct neighbouring instances (Section 4.2), 𝕋_{T_a,T_b}.
/// The list is closed under inverses (Section 4.3: 𝕋_{a,b}^{-1} = 𝕋_{b,a}) and ordered
/// deterministically. \pre x.is_well_formed() (checked unless `check_well_formed` is false:
/// the caller has checked it) and no two instances overlap (Eq. 4.2). `on_progress(done, total)`,
/// when given, is called after each candidate pair of instances (boxes overlap) is decided.
/// `wanted(a, b)`, when given, restricts the list to the pairs it accepts (either order): a
/// caller that needs only some interfaces, e.g. those of one copy under a group, is spared the
/// exact interface decisions of the others; the list is then closed under inverses still.
template <class FT, int D>
std::vector<TemplateBoundaryMapping<FT, D>>
template_boundary_mappings(const TemplatedStructure<FT, D>& x, bool check_well_formed = true,
                           const std::function<void(std::size_t, std::size_t)>& on_progress = {},
                           const std::function<bool(InstanceId, InstanceId)>& wanted = {});

/// A composition of template boundary mappings (Def A.2): letters[0] is applied first. The
/// rigid map is the product of the letters' maps; its domain is the set of points on which every
/// letter is defined in turn (kept by the caller as subdivision faces).
template <class FT, int D>
struct Composition {
  std::vector<std::size_t> letters;
  RigidTransformation<FT, D> map;
};

template <class FT, int D>
Composition<FT, D> compose(const std::vector<TemplateBoundaryMapping<FT, D>>& mappings,
                           const std::vector<std::size_t>& letters) {
  Composition<FT, D> c;
  c.letters = letters;
  for (std::size_t l : letters) c.map = mappings.at(l).map * c.map;
  return c;
}

/// Thrown when closing the boundary subdivision under all compositions would need more than
/// the configured number of composed images (Section 4.3: 𝔗_X can be infinite, e.g. for an
/// irrational in-plane rotation, or very large, e.g. a glide reflection by a tiny offset).
class CompositionLimitExceeded : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

} // namespace symmesh::core
