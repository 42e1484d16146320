// Definition 3.1 (refined mesh), spec/definitions.md#def-3-1: midpoint refinements refine their
// mesh in 2D and 3D; the reverse direction (the dissertation's printed inclusion), a changed
// region, and a mesh with the other diagonals do not. Definition 2.11 (geometry of a mesh, Eq.
// 2.9) on the same meshes: ξ̃(x) is the regions of the cells holding x, and a refinement describes
// the same geometry.
#include <gtest/gtest.h>

#include "symmesh/core/kernel.h"
#include "symmesh/core/geometry_of_mesh.h"
#include "symmesh/core/refined_mesh.h"

#include <map>
#include <sstream>

using namespace symmesh;
using namespace symmesh::core;

namespace {

template <int D>
MultiRegionMesh<Exact, D> make(const std::vector<Point<Exact, D>>& points,
                               const std::vector<std::pair<Simplex, int>>& cells) {
  MultiRegionMesh<Exact, D> m;
  ElementComplex<Exact, D> c;
  c.points = points;
  for (const auto& [s, r] : cells) c.elements.push_back(s);
  m.mesh = face_completion(c);
  m.mesh.normalize();
  for (const auto& [s, r] : cells) m.cell_region[s] = r;
  return m;
}

Point<Exact, 2> p2(int x, int y) {
  Point<Exact, 2> p;
  p[0] = Exact(x);
  p[1] = Exact(y);
  return p;
}

/// Two unit squares (regions 1, 2), each split by a diagonal; `other` flips the diagonals.
MultiRegionMesh<Exact, 2> squares(bool other = false) {
  const std::vector<Point<Exact, 2>> pts{p2(0, 0), p2(1, 0), p2(2, 0),
                                         p2(0, 1), p2(1, 1), p2(2, 1)};
  if (other)
    return make<2>(pts, {{Simplex{0, 1, 3}, 1},
                         {Simplex{1, 3, 4}, 1},
                         {Simplex{1, 2, 4}, 2},
                         {Simplex{2, 4, 5}, 2}});
  return make<2>(
      pts,
      {{Simplex{0, 1, 4}, 1}, {Simplex{0, 3, 4}, 1}, {Simplex{1, 2, 5}, 2}, {Simplex{1, 4, 5}, 2}});
}

/// Every triangle split into 4 at its edge midpoints (red refinement), regions kept.
MultiRegionMesh<Exact, 2> midpoint_refinement(const MultiRegionMesh<Exact, 2>& m) {
  std::vector<Point<Exact, 2>> pts = m.mesh.points;
  std::map<std::pair<VertexId, VertexId>, VertexId> mid;
  const auto midpoint = [&](VertexId a, VertexId b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    const auto it = mid.find(key);
    if (it != mid.end()) return it->second;
    pts.push_back(scaled<Exact, 2>(pts[a] + pts[b], Exact(1) / Exact(2)));
    return mid[key] = VertexId(pts.size() - 1);
  };
  std::vector<std::pair<Simplex, int>> cells;
  for (const auto& [c, r] : m.cell_region) {
    const VertexId a = *c.begin(), b = *(c.begin() + 1), d = *(c.begin() + 2);
    const VertexId ab = midpoint(a, b), bd = midpoint(b, d), da = midpoint(d, a);
    for (const auto& s :
         {Simplex{a, ab, da}, Simplex{ab, b, bd}, Simplex{da, bd, d}, Simplex{ab, bd, da}})
      cells.push_back({s, r});
  }
  return make<2>(pts, cells);
}

} // namespace

TEST(RefinedMesh, MidpointRefinementRefinesItsMesh2D) {
  const auto m = squares();
  const auto r = midpoint_refinement(m);
  std::ostringstream why;
  EXPECT_TRUE(is_refinement(m, r, &why)) << why.str();
  EXPECT_TRUE(is_refinement(m, m)); // every mesh refines itself
  // The inclusion as printed in Def 3.1 (cells of R are unions of cells of M) is the reverse:
  EXPECT_FALSE(is_refinement(r, m, &why));
  EXPECT_NE(why.str().find("lies in no cell"), std::string::npos);
}

TEST(RefinedMesh, RegionsMustFollowTheParent) {
  const auto m = squares();
  auto r = midpoint_refinement(m);
  r.cell_region.begin()->second = 7;
  std::ostringstream why;
  EXPECT_FALSE(is_refinement(m, r, &why));
  EXPECT_NE(why.str().find("region"), std::string::npos);
}

TEST(RefinedMesh, ANonNestedMeshIsNoRefinement) {
  const auto m = squares();
  EXPECT_FALSE(is_refinement(m, squares(true)));
  EXPECT_FALSE(is_refinement(m, midpoint_refinement(squares(true))));
}

TEST(RefinedMesh, BisectedTetrahedron3D) {
  std::vector<Point<Exact, 3>> pts(5);
  const int c[5][3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 0, 0}};
  for (int i = 0; i < 5; ++i)
    for (int d = 0; d < 3; ++d) pts[std::size_t(i)][d] = Exact(c[i][d]);
  const auto m = make<3>(pts, {{Simplex{0, 1, 2, 3}, 1}});
  const auto r = make<3>(pts, {{Simplex{0, 2, 3, 4}, 1}, {Simplex{1, 2, 3, 4}, 1}});
  std::ostringstream why;
  EXPECT_TRUE(is_refinement(m, r, &why)) << why.str();
  EXPECT_FALSE(is_refinement(r, m));
  // One child only: the parent is not covered.
  EXPECT_FALSE(is_refinement(m, make<3>(pts, {{Simplex{0, 2, 3, 4}, 1}}), &why));
  EXPECT_NE(why.str().find("not the union"), std::string::npos);
}

namespace {
Point<Exact, 2> q2(int x, int y, int d) {
  Point<Exact, 2> p;
  p[0] = Exact(x) / Exact(d);
  p[1] = Exact(y) / Exact(d);
  return p;
}
} // namespace

TEST(GeometryOfMesh, RegionsAtPointsEq29) {
  const auto m = squares();
  EXPECT_EQ(geometry_regions_at(m, q2(1, 1, 4)), (std::set<int>{1})); // inside region 1
  EXPECT_EQ(geometry_regions_at(m, q2(7, 1, 4)), (std::set<int>{2})); // inside region 2
  EXPECT_EQ(geometry_regions_at(m, q2(1, 1, 2) + q2(1, 0, 2)), (std::set<int>{1, 2})); // x = 1
  EXPECT_EQ(geometry_regions_at(m, q2(1, 0, 1)), (std::set<int>{1, 2})); // shared vertex
  EXPECT_TRUE(geometry_regions_at(m, q2(5, 1, 2)).empty());              // off us(M)
  EXPECT_FALSE(in_geometry(m, q2(5, 1, 2)));
  EXPECT_TRUE(in_geometry(m, q2(1, 1, 2)));
  // A refinement describes the same geometry (Def 3.1 with Eq. 2.9), at every vertex and centroid
  // of the refinement's cells.
  const auto r = midpoint_refinement(m);
  for (const auto& c : r.mesh.cells()) {
    const auto pts = r.mesh.coords(c);
    Point<Exact, 2> g = zero_point<Exact, 2>();
    for (const auto& p : pts) {
      EXPECT_EQ(geometry_regions_at(m, p), geometry_regions_at(r, p));
      g = g + p;
    }
    g = scaled<Exact, 2>(g, Exact(1) / Exact(3));
    EXPECT_EQ(geometry_regions_at(m, g), geometry_regions_at(r, g));
  }
  // The other diagonals: same geometry, and not a refinement.
  EXPECT_EQ(geometry_regions_at(squares(true), q2(1, 1, 4)), (std::set<int>{1}));
}
