// Definition 2.8 (triangulation of a point set), Eq. 2.6 against Eq. 2.5 (region interface),
// Definition 4.1 (geometry decomposition, template, instance) and Definition 4.2 (mesh
// decomposition, template, instance) — spec/definitions.md#def-2-8, #eq-2-6, #def-4-1, #def-4-2.
// Each on a case that holds and on cases where one condition fails.
#include <gtest/gtest.h>

#include "exact_fixtures.h"

#include "symmesh/core/geometry_decomposition.h"
#include "symmesh/core/geometry_of_mesh.h"
#include "symmesh/core/kernel.h"
#include "symmesh/core/mesh_decomposition.h"
#include "symmesh/core/triangulation_of_points.h"

#include <sstream>
#include <stdexcept>

using namespace symmesh::core;
using symmesh::Exact;
using namespace symmesh::test;

namespace {

template <int D>
MultiRegionMesh<Exact, D> mesh_of(const std::vector<Point<Exact, D>>& pts,
                                  const std::vector<std::pair<Simplex, int>>& cells) {
  std::vector<Simplex> s;
  for (const auto& [c, r] : cells) s.push_back(c);
  MultiRegionMesh<Exact, D> m{complex_of<D>(pts, s), {}};
  for (const auto& [c, r] : cells) m.cell_region[c] = r;
  return m;
}

template <int D>
MultiRegionGeometry<Exact, D> geometry_of(const std::vector<Point<Exact, D>>& pts,
                                          const std::vector<std::pair<Simplex, int>>& cells) {
  const auto m = mesh_of<D>(pts, cells);
  return {m.mesh, m.cell_region};
}

const std::vector<Point<Exact, 2>> kRectangle{p2(0, 0), p2(1, 0), p2(2, 0),
                                              p2(0, 1), p2(1, 1), p2(2, 1)};

/// [0,2]x[0,1]: the left square region 1, the right one region 2, diagonals from the bottom left.
MultiRegionMesh<Exact, 2> rectangle() {
  return mesh_of<2>(
      kRectangle,
      {{Simplex{0, 1, 4}, 1}, {Simplex{0, 3, 4}, 1}, {Simplex{1, 2, 5}, 2}, {Simplex{1, 4, 5}, 2}});
}

/// The unit cube's corners (index = x + 2y + 4z) and its six tetrahedra around the diagonal 0–7.
std::vector<Point<Exact, 3>> cube_corners() {
  std::vector<Point<Exact, 3>> c;
  for (int i = 0; i < 8; ++i) c.push_back(p3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  return c;
}
std::vector<Simplex> cube_tetrahedra() {
  return {Simplex{0, 1, 3, 7}, Simplex{0, 1, 5, 7}, Simplex{0, 2, 3, 7},
          Simplex{0, 2, 6, 7}, Simplex{0, 4, 5, 7}, Simplex{0, 4, 6, 7}};
}

} // namespace

TEST(TriangulationOfPoints, ConvexHullAndVerticesDef28) {
  const std::vector<Point<Exact, 2>> square{p2(0, 0), p2(1, 0), p2(0, 1), p2(1, 1)};
  EXPECT_TRUE(is_triangulation_of_points(
      complex_of<2>(square, {Simplex{0, 1, 3}, Simplex{0, 2, 3}}), square));
  auto with_centre = square;
  with_centre.push_back(p2(Exact(1) / 2, Exact(1) / 2));
  std::ostringstream why;
  EXPECT_FALSE(is_triangulation_of_points(
      complex_of<2>(with_centre, {Simplex{0, 1, 3}, Simplex{0, 2, 3}}), with_centre, &why));
  EXPECT_NE(why.str().find("elem_0"), std::string::npos) << why.str();
  EXPECT_TRUE(
      is_triangulation_of_points(complex_of<2>(with_centre, {Simplex{0, 1, 4}, Simplex{1, 3, 4},
                                                             Simplex{3, 2, 4}, Simplex{2, 0, 4}}),
                                 with_centre));
  // An L: every point is a vertex, but us(M) is not the hull.
  const std::vector<Point<Exact, 2>> ell{p2(0, 0), p2(2, 0), p2(2, 1),
                                         p2(1, 1), p2(1, 2), p2(0, 2)};
  why.str("");
  EXPECT_FALSE(is_triangulation_of_points(
      complex_of<2>(ell, {Simplex{0, 1, 2}, Simplex{0, 2, 3}, Simplex{0, 3, 4}, Simplex{0, 4, 5}}),
      ell, &why));
  EXPECT_NE(why.str().find("conv"), std::string::npos) << why.str();
  EXPECT_THROW((void)is_triangulation_of_points(complex_of<2>(square, {Simplex{0, 1}}),
                                                {p2(0, 0), p2(1, 0)}),
               std::invalid_argument);
}

TEST(TriangulationOfPoints, CubeAndCubeWithATetrahedronMissingDef28) {
  const auto corners = cube_corners();
  auto tets = cube_tetrahedra();
  EXPECT_TRUE(is_triangulation_of_points(complex_of<3>(corners, tets), corners));
  tets.pop_back(); // every corner is still a vertex
  EXPECT_FALSE(is_triangulation_of_points(complex_of<3>(corners, tets), corners));
}

TEST(RegionInterface, Eq26EqualsEq25) {
  const auto m = rectangle();
  for (const auto& ids : std::vector<std::vector<int>>{{1}, {2}, {1, 2}})
    EXPECT_EQ(pointwise_region_interface(m, ids).elements, m.region_interface(ids).elements);
  EXPECT_EQ(m.region_interface({1, 2}).elements,
            (std::vector<Simplex>{Simplex{1}, Simplex{4}, Simplex{1, 4}}));
  std::vector<std::pair<Simplex, int>> cells;
  const auto tets = cube_tetrahedra();
  for (std::size_t i = 0; i < tets.size(); ++i) cells.push_back({tets[i], int(i % 3)});
  const auto cube = mesh_of<3>(cube_corners(), cells);
  for (const auto& ids : std::vector<std::vector<int>>{{0}, {0, 1}, {1, 2}, {0, 1, 2}})
    EXPECT_EQ(pointwise_region_interface(cube, ids).elements, cube.region_interface(ids).elements);
}

TEST(MeshDecomposition, BlocksTemplatesAndInstancesDef42) {
  const auto m = rectangle();
  const auto left = mesh_of<2>(kRectangle, {{Simplex{0, 1, 4}, 1}, {Simplex{0, 3, 4}, 1}});
  const auto right = mesh_of<2>(kRectangle, {{Simplex{1, 2, 5}, 2}, {Simplex{1, 4, 5}, 2}});
  EXPECT_TRUE(is_mesh_decomposition(m, {left, right}));
  std::ostringstream why;
  EXPECT_FALSE(is_mesh_decomposition(m, {left}, &why)) << "does not cover";
  auto relabelled = right;
  relabelled.cell_region[Simplex{1, 4, 5}] = 1;
  why.str("");
  EXPECT_FALSE(is_mesh_decomposition(m, {left, relabelled}, &why));
  EXPECT_NE(why.str().find("ξ_i"), std::string::npos) << why.str();
  // The left square as a template of region 2 placed by a translation gives the right block;
  // the mirror image about x = 1 has the other diagonal, and a template of region 1 the wrong ξ.
  const auto templ = mesh_of<2>(kRectangle, {{Simplex{0, 1, 4}, 2}, {Simplex{0, 3, 4}, 2}});
  using T = RigidTransformation<Exact, 2>;
  EXPECT_TRUE(is_mesh_instance(templ, right, T::translation(p2(1, 0))));
  EXPECT_FALSE(is_mesh_instance(templ, right, T::reflection(p2(1, 0), Exact(1))));
  EXPECT_FALSE(is_mesh_instance(left, right, T::translation(p2(1, 0))));
}

TEST(GeometryDecomposition, BlocksTemplatesAndInstancesDef41) {
  const auto m = rectangle();
  const MultiRegionGeometry<Exact, 2> g{m.mesh, m.cell_region};
  // Blocks with their own carriers (the other diagonals).
  const std::vector<Point<Exact, 2>> unit{p2(0, 0), p2(1, 0), p2(0, 1), p2(1, 1)};
  const auto left = geometry_of<2>(unit, {{Simplex{0, 1, 2}, 1}, {Simplex{1, 2, 3}, 1}});
  const std::vector<Point<Exact, 2>> shifted{p2(1, 0), p2(2, 0), p2(1, 1), p2(2, 1)};
  const auto right = geometry_of<2>(shifted, {{Simplex{0, 1, 2}, 2}, {Simplex{1, 2, 3}, 2}});
  EXPECT_TRUE(is_geometry_decomposition(g, {left, right}));
  std::ostringstream why;
  EXPECT_FALSE(is_geometry_decomposition(g, {left}, &why));
  EXPECT_NE(why.str().find("cover"), std::string::npos) << why.str();
  // Overlapping blocks: [0, 3/2] x [0, 1] (region 1 only where G has region 1? no: it leaves it).
  const std::vector<Point<Exact, 2>> wide{p2(0, 0), p2(Exact(3) / 2, 0), p2(0, 1),
                                          p2(Exact(3) / 2, 1)};
  const auto wide_left = geometry_of<2>(wide, {{Simplex{0, 1, 2}, 1}, {Simplex{1, 2, 3}, 1}});
  EXPECT_FALSE(is_geometry_decomposition(g, {wide_left, right}));
  // Two blocks of G's right half, one of them twice: overlap with matching regions.
  const auto right_bottom = geometry_of<2>(shifted, {{Simplex{0, 1, 2}, 2}});
  why.str("");
  EXPECT_FALSE(is_geometry_decomposition(g, {left, right, right_bottom}, &why));
  EXPECT_NE(why.str().find("overlap"), std::string::npos) << why.str();
  const auto wrong_region = geometry_of<2>(shifted, {{Simplex{0, 1, 2}, 1}, {Simplex{1, 2, 3}, 2}});
  EXPECT_FALSE(is_geometry_decomposition(g, {left, wrong_region}));
  // Geometry template: the unit square of region 2 placed by a translation (any carrier).
  const auto templ = geometry_of<2>(unit, {{Simplex{0, 1, 3}, 2}, {Simplex{0, 2, 3}, 2}});
  using T = RigidTransformation<Exact, 2>;
  EXPECT_TRUE(is_geometry_instance(templ, right, T::translation(p2(1, 0))));
  EXPECT_TRUE(is_geometry_instance(templ, right, T::reflection(p2(1, 0), Exact(1))));
  EXPECT_FALSE(is_geometry_instance(templ, right, T::translation(p2(1, Exact(1) / 2))));
  EXPECT_FALSE(is_geometry_instance(templ, left, T()));
}
