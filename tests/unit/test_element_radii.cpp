// Definition 2.15 (min-containment radius, inradius) and Definition 2.18 (radius ratio) in double,
// spec/definitions.md#def-2-15: closed forms for the equilateral, right and obtuse triangles, the
// regular and the corner tetrahedron (whose circumcentre lies outside it, so its min-containment
// ball is the circumball of its far face).
#include <gtest/gtest.h>

#include "symmesh/mesh/element_radii.h"

#include <cmath>
#include <stdexcept>

using namespace symmesh::mesh;

TEST(ElementRadii, TrianglesDefs215And218) {
  const double s3 = std::sqrt(3.0);
  const std::vector<Vertex3> equilateral{{0, 0, 0}, {1, 0, 0}, {0.5, s3 / 2, 0}};
  EXPECT_NEAR(inradius(equilateral), s3 / 6, 1e-15);
  EXPECT_NEAR(circumradius(equilateral), s3 / 3, 1e-15);
  EXPECT_NEAR(min_containment_radius(equilateral), s3 / 3, 1e-15);
  EXPECT_NEAR(radius_ratio(equilateral), 0.5, 1e-15);
  // Right isosceles: R = hypotenuse / 2 = min-containment; r = (a + b - c) / 2.
  const std::vector<Vertex3> right{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_NEAR(circumradius(right), std::sqrt(2.0) / 2, 1e-15);
  EXPECT_NEAR(min_containment_radius(right), std::sqrt(2.0) / 2, 1e-15);
  EXPECT_NEAR(inradius(right), (2 - std::sqrt(2.0)) / 2, 1e-15);
  // Obtuse: the smallest ball is on the long edge, smaller than the circumball.
  const std::vector<Vertex3> obtuse{{0, 0, 0}, {4, 0, 0}, {1, 1, 0}};
  EXPECT_NEAR(min_containment_radius(obtuse), 2.0, 1e-14);
  EXPECT_GT(circumradius(obtuse), 2.0 + 0.1);
  EXPECT_LT(radius_ratio(obtuse), radius_ratio(right));
}

TEST(ElementRadii, TetrahedraDefs215And218) {
  const std::vector<Vertex3> regular{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  EXPECT_NEAR(circumradius(regular), std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(inradius(regular), std::sqrt(3.0) / 3, 1e-14);
  EXPECT_NEAR(radius_ratio(regular), 1.0 / 3, 1e-14);
  EXPECT_NEAR(min_containment_radius(regular), std::sqrt(3.0), 1e-14);
  const std::vector<Vertex3> corner{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_NEAR(circumradius(corner), std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(inradius(corner), 1 / (3 + std::sqrt(3.0)), 1e-15);
  EXPECT_NEAR(min_containment_radius(corner), std::sqrt(2.0 / 3), 1e-15);
  EXPECT_THROW((void)inradius({{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
  EXPECT_THROW((void)circumradius({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}), std::invalid_argument);
}
