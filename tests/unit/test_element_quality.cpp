// Exact element quality (spec/definitions.md#quality-exact): Definitions 2.12, 2.13, 2.14, 2.16,
// 2.17, 2.19, 2.20 on the right isosceles triangle and the regular tetrahedron with rational
// vertices, whose values are known in closed form.
#include <gtest/gtest.h>

#include "symmesh/core/element_quality.h"
#include "symmesh/core/kernel.h"

using namespace symmesh;
using namespace symmesh::core;

namespace {
template <int D>
Point<Exact, D> p(std::initializer_list<int> c) {
  Point<Exact, D> q;
  int d = 0;
  for (int v : c) q[d++] = Exact(v);
  return q;
}
Exact q(int a, int b) {
  return Exact(a) / Exact(b);
}
} // namespace

TEST(ElementQuality, RightIsoscelesTriangle) {
  const std::vector<Point<Exact, 2>> t{p<2>({0, 0}), p<2>({1, 0}), p<2>({0, 1})};
  EXPECT_EQ((squared_edge_range<Exact, 2>(t)), std::make_pair(Exact(1), Exact(2))); // Def 2.12
  EXPECT_EQ((squared_scaled_relative_volume<Exact, 2>(t)), Exact(1));  // (2!·1/2)², Def 2.13
  EXPECT_EQ((squared_circumradius<Exact, 2>(t)), q(1, 2));             // (√2/2)², Def 2.14
  EXPECT_EQ((squared_radius_edge_ratio<Exact, 2>(t)), q(1, 2));        // Def 2.17
  const auto [small, large] = smallest_and_largest_angle<Exact, 2>(t); // Def 2.16
  EXPECT_EQ(large, 0);                                                 // the right angle
  EXPECT_NE(small, 0);
  EXPECT_EQ((signed_squared_cosine<Exact, 2>(t[0], t[1], t[2])), std::make_pair(0, Exact(0)));
  EXPECT_EQ((signed_squared_cosine<Exact, 2>(t[1], t[2], t[0])), std::make_pair(1, q(1, 2)));
  EXPECT_EQ((squared_volume_length<Exact, 2>(t)), q(9, 64)); // (1/2)² / (4/3)², Def 2.19
  // An obtuse angle has a negative cosine and is the largest.
  const std::vector<Point<Exact, 2>> obtuse{p<2>({0, 0}), p<2>({4, 0}), p<2>({-1, 1})};
  EXPECT_EQ((smallest_and_largest_angle<Exact, 2>(obtuse).second), 0);
  EXPECT_EQ((signed_squared_cosine<Exact, 2>(obtuse[0], obtuse[1], obtuse[2]).first), -1);
}

TEST(ElementQuality, RegularTetrahedronAndLowerDimensionalElements) {
  const std::vector<Point<Exact, 3>> t{p<3>({0, 0, 0}), p<3>({1, 1, 0}), p<3>({1, 0, 1}),
                                       p<3>({0, 1, 1})};
  EXPECT_EQ((squared_edge_range<Exact, 3>(t)), std::make_pair(Exact(2), Exact(2)));
  EXPECT_EQ((squared_scaled_relative_volume<Exact, 3>(t)), Exact(4)); // (3!·1/3)²
  EXPECT_EQ((squared_circumradius<Exact, 3>(t)), q(3, 4));            // (√3/2)²
  EXPECT_EQ((squared_radius_edge_ratio<Exact, 3>(t)), q(3, 8)); // (√6/4)², the best tetrahedron
  EXPECT_EQ((squared_volume_length<Exact, 3>(t)), q(1, 72));    // (1/3)² / 2³
  // Relative volume (Def 2.13) of an edge and a triangle in R³.
  EXPECT_EQ((squared_scaled_relative_volume<Exact, 3>({p<3>({0, 0, 0}), p<3>({1, 2, 2})})),
            Exact(9));
  EXPECT_EQ((squared_scaled_relative_volume<Exact, 3>(
                {p<3>({0, 0, 0}), p<3>({1, 0, 0}), p<3>({0, 1, 0})})),
            Exact(1));
  // A flat tetrahedron has no circumball and zero volume.
  const std::vector<Point<Exact, 3>> flat{p<3>({0, 0, 0}), p<3>({1, 0, 0}), p<3>({0, 1, 0}),
                                          p<3>({1, 1, 0})};
  EXPECT_THROW((squared_circumradius<Exact, 3>(flat)), std::invalid_argument);
  EXPECT_EQ((squared_scaled_relative_volume<Exact, 3>(flat)), Exact(0));
}

TEST(ElementQuality, QualityVectorIsSorted) {
  const std::vector<std::vector<Point<Exact, 2>>> cells{{p<2>({0, 0}), p<2>({4, 0}), p<2>({-1, 1})},
                                                        {p<2>({0, 0}), p<2>({1, 0}), p<2>({0, 1})}};
  const auto v = quality_vector<Exact>(
      cells, [](const auto& c) { return squared_radius_edge_ratio<Exact, 2>(c); });
  ASSERT_EQ(v.size(), 2u);
  EXPECT_LT(v[0], v[1]);
  EXPECT_EQ(v[0], q(1, 2));
}

// Def 2.16 in 3D: the regular tetrahedron has every dihedral angle arccos(1/3); the corner
// tetrahedron has right dihedral angles along the axes and arccos(1/√3) along the far face.
TEST(ElementQuality, DihedralAnglesOfRegularAndCornerTetrahedra) {
  const std::vector<Point<Exact, 3>> regular{p<3>({1, 1, 1}), p<3>({1, -1, -1}), p<3>({-1, 1, -1}),
                                             p<3>({-1, -1, 1})};
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      int o[2], n = 0;
      for (int v = 0; v < 4; ++v)
        if (v != i && v != j) o[n++] = v;
      const auto [sign, c2] = signed_squared_dihedral_cosine<Exact>(regular[i], regular[j],
                                                                    regular[o[0]], regular[o[1]]);
      EXPECT_EQ(sign, 1);
      EXPECT_EQ(c2, Exact(1) / 9);
    }
  const std::vector<Point<Exact, 3>> corner{p<3>({0, 0, 0}), p<3>({1, 0, 0}), p<3>({0, 1, 0}),
                                            p<3>({0, 0, 1})};
  const auto [sign, c2] =
      signed_squared_dihedral_cosine<Exact>(corner[0], corner[1], corner[2], corner[3]);
  EXPECT_EQ(sign, 0); // a right angle along the x axis
  EXPECT_EQ(c2, Exact(0));
  const auto far =
      signed_squared_dihedral_cosine<Exact>(corner[1], corner[2], corner[3], corner[0]);
  EXPECT_EQ(far.first, 1);
  EXPECT_EQ(far.second, Exact(1) / 3);
  const auto [smallest, largest] = smallest_and_largest_dihedral_angle<Exact>(corner);
  EXPECT_EQ(smallest, (std::pair<int, int>{1, 2}));
  EXPECT_EQ(largest, (std::pair<int, int>{0, 1}));
  // A sliver (four nearly coplanar points) has a dihedral angle near 180°: negative cosine.
  const std::vector<Point<Exact, 3>> sliver{p<3>({0, 0, 0}), p<3>({4, 0, 0}), p<3>({2, 2, 1}),
                                            p<3>({2, -2, 1})};
  const auto flat =
      signed_squared_dihedral_cosine<Exact>(sliver[2], sliver[3], sliver[0], sliver[1]);
  EXPECT_EQ(flat.first, -1);
}
