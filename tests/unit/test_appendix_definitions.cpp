// Appendix A definitions on element complexes, spec/definitions.md#def-a-1 … #def-a-19:
// Def A.1 (closure, interior, boundary of us(E)), Def A.3 (balls), Def A.4 (bounded, connected),
// Def A.11/A.12 (co-faces, co-facets, neighbours; Eq. A.10–A.14) and Def A.19/A.20
// (k-interpolation combinations and when they parameterize an element), each on cases whose
// answer is known by hand, including ones where the answer is "no".
#include <gtest/gtest.h>

#include "exact_fixtures.h"

#include "symmesh/core/ball.h"
#include "symmesh/core/bounded_connected.h"
#include "symmesh/core/closure_interior_boundary.h"
#include "symmesh/core/interpolation_combination.h"
#include "symmesh/core/kernel.h"
#include "symmesh/core/neighbour_elements.h"

#include <stdexcept>

using namespace symmesh::core;
using symmesh::Exact;
using namespace symmesh::test;

namespace {

/// The unit square split along the diagonal 0–3, plus a dangling edge 3–4 leaving it.
ElementComplex<Exact, 2> square_with_tail() {
  return complex_of<2>({p2(0, 0), p2(1, 0), p2(0, 1), p2(1, 1), p2(2, 2)},
                       {Simplex{0, 1, 3}, Simplex{0, 2, 3}, Simplex{3, 4}});
}

} // namespace

TEST(ClosureInteriorBoundary, SquareWithATailDefA1) {
  const auto e = square_with_tail();
  const Exact h = Exact(1) / 2;
  EXPECT_TRUE(in_interior(e, p2(h, h)));                       // on the shared diagonal
  EXPECT_TRUE(in_interior(e, p2(Exact(1) / 4, h)));            // inside a cell
  EXPECT_TRUE(on_boundary(e, p2(h, 0)));                       // on a boundary edge
  EXPECT_TRUE(on_boundary(e, p2(1, 1)));                       // a corner the tail leaves from
  EXPECT_TRUE(on_boundary(e, p2(Exact(3) / 2, Exact(3) / 2))); // on the tail: no interior
  EXPECT_FALSE(in_closure(e, p2(2, 0)));
  EXPECT_FALSE(on_boundary(e, p2(2, 0)));
}

TEST(ClosureInteriorBoundary, TwoTetrahedraAndTheirCommonFacetDefA1) {
  const auto e = complex_of<3>({p3(0, 0, 0), p3(1, 0, 0), p3(0, 1, 0), p3(0, 0, 1), p3(1, 1, 1)},
                               {Simplex{0, 1, 2, 3}, Simplex{1, 2, 3, 4}});
  const Exact t = Exact(1) / 3;
  EXPECT_TRUE(in_interior(e, p3(t, t, t))); // centroid of the shared facet
  EXPECT_TRUE(on_boundary(e, p3(t, t, 0))); // on the facet z = 0
  EXPECT_TRUE(on_boundary(e, p3(1, 1, 1)));
  // Two triangles touching only at a vertex: that vertex is on the boundary though every
  // boundary edge through it has one co-face.
  const auto bow = complex_of<2>({p2(0, 0), p2(1, 0), p2(0, 1), p2(-1, 0), p2(0, -1)},
                                 {Simplex{0, 1, 2}, Simplex{0, 3, 4}});
  EXPECT_TRUE(on_boundary(bow, p2(0, 0)));
  EXPECT_FALSE(in_interior(bow, p2(0, 0)));
}

TEST(ClosureInteriorBoundary, NonConformingInputIsRefused) {
  // Two overlapping triangles.
  const auto e = complex_of<2>({p2(0, 0), p2(2, 0), p2(0, 2), p2(1, 1), p2(3, 1), p2(1, 3)},
                               {Simplex{0, 1, 2}, Simplex{3, 4, 5}});
  EXPECT_THROW((void)in_interior(e, p2(0, 0)), std::invalid_argument);
}

TEST(Ball, ClosedOpenAndHalfBallsEqA2ToA4) {
  const Ball<Exact, 2> closed{p2(1, 1), Exact(2), BallKind::closed};
  const Ball<Exact, 2> open{p2(1, 1), Exact(2), BallKind::open};
  const Ball<Exact, 2> half{p2(1, 1), Exact(2), BallKind::half};
  EXPECT_TRUE(closed.is_valid());
  EXPECT_TRUE(closed.contains(p2(2, 2))); // on the sphere, radius √2
  EXPECT_FALSE(open.contains(p2(2, 2)));
  EXPECT_TRUE(open.contains(p2(2, 1)));
  EXPECT_TRUE(half.contains(p2(2, 2)));
  EXPECT_FALSE(half.contains(p2(1, 0))); // below the centre's last coordinate
  EXPECT_FALSE(closed.contains(p2(3, 1)));
  // At the origin the half-ball is Eq. A.4 as printed (y_n >= 0).
  const auto unit_half = unit_ball<Exact, 3>(BallKind::half);
  EXPECT_TRUE(unit_half.contains(p3(0, 0, 1)));
  EXPECT_FALSE(unit_half.contains(p3(0, 0, Exact(-1) / 2)));
  EXPECT_FALSE((Ball<Exact, 2>{p2(0, 0), Exact(0), BallKind::closed}.is_valid()));
}

TEST(BoundedConnected, ComponentsAndBoundingBallDefA4) {
  const auto e = square_with_tail();
  const auto ball = bounding_ball(e);
  ASSERT_TRUE(ball.has_value());
  for (const auto& p : e.points) EXPECT_TRUE(ball->contains(p));
  EXPECT_TRUE(is_connected(e));
  EXPECT_FALSE(bounding_ball(ElementComplex<Exact, 2>{}).has_value());
  EXPECT_TRUE(is_connected(ElementComplex<Exact, 2>{}));
  // Two disjoint triangles, and a segment crossing one of them without sharing a vertex.
  auto two = complex_of<2>({p2(0, 0), p2(1, 0), p2(0, 1), p2(5, 5), p2(6, 5), p2(5, 6)},
                           {Simplex{0, 1, 2}, Simplex{3, 4, 5}});
  EXPECT_EQ(connected_components(two).size(), 2u);
  EXPECT_FALSE(is_connected(two));
  two.points.push_back(p2(Exact(1) / 4, Exact(1) / 4));
  two.points.push_back(p2(Exact(21) / 4, Exact(4)));
  two.elements.push_back(Simplex{6, 7}); // starts in the first triangle, ends below the second
  two.elements.push_back(Simplex{6});
  two.elements.push_back(Simplex{7});
  two.normalize();
  EXPECT_EQ(connected_components(two).size(), 2u);
  two.points[7] = p2(Exact(21) / 4, Exact(21) / 4); // now it ends inside the second
  EXPECT_TRUE(is_connected(two));
}

TEST(NeighbourElements, CofacesCofacetsAndNeighboursEqA10ToA14) {
  const auto e = square_with_tail();
  const Simplex v3{3}, diag{0, 3}, tail{3, 4};
  EXPECT_EQ(cofacets(e, diag), (std::vector<Simplex>{Simplex{0, 1, 3}, Simplex{0, 2, 3}}));
  EXPECT_EQ(cofaces(e, v3, 2), (std::vector<Simplex>{Simplex{0, 1, 3}, Simplex{0, 2, 3}}));
  EXPECT_EQ(cofaces(e, v3).size(), 7u); // 3 itself, edges 0-3, 1-3, 2-3, 3-4, both triangles
  const auto n = neighbours(e, tail);
  EXPECT_TRUE(std::find(n.begin(), n.end(), tail) != n.end()); // E is its own neighbour
  EXPECT_TRUE(std::find(n.begin(), n.end(), Simplex{0, 1, 3}) != n.end());
  EXPECT_TRUE(std::find(n.begin(), n.end(), Simplex{0, 1}) == n.end());
  // Eq. A.14: triangles sharing an edge with triangle 013: itself and 023 (through 0-3).
  EXPECT_EQ(neighbours(e, Simplex{0, 1, 3}, 1, 2),
            (std::vector<Simplex>{Simplex{0, 1, 3}, Simplex{0, 2, 3}}));
  EXPECT_TRUE(neighbours(e, tail, 1, 2).empty());
  EXPECT_THROW((void)cofaces(e, Simplex{1, 2}), std::invalid_argument);
  // Without face-completeness only the faces present count: the two triangles alone share no
  // element, so they are not neighbours.
  ElementComplex<Exact, 2> bare;
  bare.points = e.points;
  bare.elements = {Simplex{0, 1, 3}, Simplex{0, 2, 3}};
  bare.normalize();
  EXPECT_EQ(neighbours(bare, Simplex{0, 1, 3}), (std::vector<Simplex>{Simplex{0, 1, 3}}));
}

TEST(InterpolationCombination, EqA18EvaluatesTheRecursion) {
  const std::vector<Point<Exact, 2>> q{p2(0, 0), p2(2, 0), p2(0, 2), p2(3, 3)};
  const Exact h = Exact(1) / 2;
  EXPECT_EQ((interpolation_combination<Exact, 2>(q, {0, 0})), q[0]);
  EXPECT_EQ((interpolation_combination<Exact, 2>(q, {1, 0})), q[1]);
  EXPECT_EQ((interpolation_combination<Exact, 2>(q, {0, 1})), q[2]);
  EXPECT_EQ((interpolation_combination<Exact, 2>(q, {1, 1})), q[3]);
  // (1-h)((1-h)t1 + h t2) + h((1-h)t3 + h t4) = (t1+t2+t3+t4)/4.
  EXPECT_EQ((interpolation_combination<Exact, 2>(q, {h, h})), p2(Exact(5) / 4, Exact(5) / 4));
  // Linear in each parameter: I(α, 1/2) is the average of I(0, 1/2) and I(1, 1/2) at α = 1/2.
  const auto a = interpolation_combination<Exact, 2>(q, {0, h});
  const auto b = interpolation_combination<Exact, 2>(q, {1, h});
  EXPECT_EQ((interpolation_combination<Exact, 2>(q, {h, h})), (scaled<Exact, 2>(a + b, h)));
  // k = 3 (8 corners): the unit cube's corners give back the parameters.
  std::vector<Point<Exact, 3>> cube;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) cube.push_back(p3(x, y, z));
  const Exact t = Exact(1) / 3;
  EXPECT_EQ((interpolation_combination<Exact, 3>(cube, {t, h, 1})), p3(t, h, 1));
  EXPECT_THROW(((void)interpolation_combination<Exact, 2>(q, {h})), std::invalid_argument);
}

TEST(InterpolationCombination, ParameterizedElementsDefA19) {
  EXPECT_TRUE((is_parameterized_element<Exact, 3>({p3(0, 0, 0), p3(1, 2, 3)})));
  EXPECT_FALSE((is_parameterized_element<Exact, 3>({p3(1, 2, 3), p3(1, 2, 3)})));
  // Order t1 t2 t3 t4 = (0,0) (1,0) (0,1) (1,1): the boundary runs t1 t2 t4 t3.
  EXPECT_TRUE((is_parameterized_element<Exact, 2>({p2(0, 0), p2(1, 0), p2(0, 1), p2(1, 1)})));
  EXPECT_TRUE((is_parameterized_element<Exact, 2>({p2(0, 0), p2(0, 1), p2(1, 0), p2(1, 1)})));
  // Bow tie (t3, t4 swapped): the map folds.
  EXPECT_FALSE((is_parameterized_element<Exact, 2>({p2(0, 0), p2(1, 0), p2(1, 1), p2(0, 1)})));
  // Non-convex (t4 pulled inside): the Jacobian changes sign.
  EXPECT_FALSE((is_parameterized_element<Exact, 2>({p2(0, 0), p2(4, 0), p2(0, 4), p2(1, 1)})));
  // A straight angle at t4: a triangle, still a homeomorphic image of the square.
  EXPECT_TRUE((is_parameterized_element<Exact, 2>({p2(0, 0), p2(2, 0), p2(0, 2), p2(1, 1)})));
  // Collinear corners: zero area.
  EXPECT_FALSE((is_parameterized_element<Exact, 2>({p2(0, 0), p2(1, 0), p2(2, 0), p2(3, 0)})));
  EXPECT_THROW(((void)is_parameterized_element<Exact, 3>(
                   {p3(0, 0, 0), p3(1, 0, 0), p3(0, 1, 0), p3(1, 1, 0)})),
               std::invalid_argument);
}
