// Unit tests of Definitions 2.2, 2.3, 2.22, 2.23, 2.24 (multi-region geometry, PLC, visibility,
// constrained Delaunay, edge-protected) in the exact core.
#include <gtest/gtest.h>

#include "symmesh/core/constrained_delaunay.h"
#include "symmesh/core/edge_protected.h"
#include "symmesh/core/kernel.h"
#include "symmesh/core/multi_region_geometry.h"
#include "symmesh/core/plc.h"
#include "symmesh/core/visibility.h"

#include <sstream>

using namespace symmesh::core;
using symmesh::Exact;
using P2 = Point<Exact, 2>;
using P3 = Point<Exact, 3>;

namespace {
P2 p2(int x, int y) {
  return P2{{Exact(x), Exact(y)}};
}
P3 p3(int x, int y, int z) {
  return P3{{Exact(x), Exact(y), Exact(z)}};
}

template <int D>
MultiRegionMesh<Exact, D> multi(std::vector<Point<Exact, D>> pts,
                                std::vector<std::pair<Simplex, int>> cells) {
  MultiRegionMesh<Exact, D> m;
  m.mesh.points = std::move(pts);
  for (const auto& [c, r] : cells) {
    m.cell_region[c] = r;
    for (const auto& f : faces(c)) m.mesh.elements.push_back(f);
  }
  m.mesh.normalize();
  return m;
}

/// Two flat triangles on either side of the segment (0,0)-(4,0): each one's circumcircle holds the
/// other's apex. As two regions, the interface blocks the view: constrained Delaunay, not
/// Delaunay (Figure 2.12's situation).
MultiRegionMesh<Exact, 2> kite(int second_region) {
  return multi<2>({p2(0, 0), p2(4, 0), p2(2, 1), p2(2, -1)},
                  {{Simplex{0, 1, 2}, 1}, {Simplex{0, 1, 3}, second_region}});
}
} // namespace

TEST(MultiRegionGeometry, XiAndInterfaceOfTwoRegions) {
  const auto m = kite(2);
  MultiRegionGeometry<Exact, 2> g{m.mesh, m.cell_region};
  std::ostringstream why;
  ASSERT_TRUE(g.is_valid(&why)) << why.str();
  EXPECT_EQ(g.xi(p2(2, 0)), (std::set<int>{1, 2}));
  EXPECT_EQ(g.xi(P2{{Exact(2), Exact(1) / 2}}), (std::set<int>{1}));
  EXPECT_TRUE(g.xi(p2(5, 5)).empty());
  EXPECT_TRUE(g.in_interface({1, 2}, p2(1, 0)));
  EXPECT_FALSE(g.in_interface({1, 2}, P2{{Exact(2), Exact(-1) / 2}}));
  MultiRegionGeometry<Exact, 2> bad = g;
  bad.cell_region.erase(Simplex{0, 1, 3});
  EXPECT_FALSE(bad.is_valid());
}

TEST(Plc, InducedByAMultiRegionMeshIsValidAndConditionsFail) {
  const auto p = plc_of_multi_region_mesh(kite(2));
  std::ostringstream why;
  ASSERT_TRUE(p.is_multi_region(&why)) << why.str();
  EXPECT_EQ(p.cells_of_dimension(2).size(), 2u);
  EXPECT_EQ(p.cells_of_dimension(1).size(), 5u); // four boundary edges and the interface
  EXPECT_EQ(p.region_ids(), (std::set<int>{1, 2}));
  // (iii): drop the interface segment; both triangles' boundaries are no longer covered
  auto no_interface = p;
  no_interface.cells.erase(std::remove_if(no_interface.cells.begin(), no_interface.cells.end(),
                                          [](const PlcCell& c) {
                                            return c.dimension == 1 && c.pieces[0] == Simplex{0, 1};
                                          }),
                           no_interface.cells.end());
  std::ostringstream w3;
  EXPECT_FALSE(no_interface.is_valid(&w3));
  EXPECT_NE(w3.str().find("(iii)"), std::string::npos) << w3.str();
  // (ii): a vertex of P inside a 1-cell made of two carrier edges
  auto m = multi<2>({p2(0, 0), p2(2, 0), p2(4, 0), p2(2, 2)},
                    {{Simplex{0, 1, 3}, 1}, {Simplex{1, 2, 3}, 1}});
  auto q = plc_of_multi_region_mesh(m);
  ASSERT_TRUE(q.is_valid());
  PlcCell long_segment{1, {Simplex{0, 1}, Simplex{1, 2}}, 0};
  q.cells.push_back(long_segment);
  std::ostringstream w2;
  EXPECT_FALSE(q.is_valid(&w2));
  EXPECT_NE(w2.str().find("(ii)"), std::string::npos) << w2.str();
  // (iv): two facets of one dimension sharing a piece
  auto r = p;
  r.cells.push_back(r.cells[r.cells_of_dimension(1)[0]]);
  std::ostringstream w4;
  EXPECT_FALSE(r.is_valid(&w4));
  EXPECT_NE(w4.str().find("(iv)"), std::string::npos) << w4.str();
}

TEST(Visibility, InterfaceBlocksAndSharedEdgeDoesNot) {
  const auto two = plc_of_multi_region_mesh(kite(2));
  const auto one = plc_of_multi_region_mesh(kite(1));
  const P2 inside_top = P2{{Exact(2), Exact(1) / 2}};
  EXPECT_FALSE(visible(two, inside_top, p2(2, -1)));
  EXPECT_TRUE(visible(one, inside_top, p2(2, -1)));
  EXPECT_TRUE(visible(two, inside_top, p2(0, 0)));
  // through a vertex of P: blocked (the vertex is no face of the segment)
  EXPECT_FALSE(visible(one, p2(-1, 0), p2(4, 0)));
  const std::vector<P2> top{p2(0, 0), p2(4, 0), p2(2, 1)};
  EXPECT_FALSE(visible_from_relative_interior(top, p2(2, -1), visibility_blockers(two)));
  EXPECT_TRUE(visible_from_relative_interior(top, p2(2, -1), visibility_blockers(one)));
}

TEST(ConstrainedDelaunay, KiteAcrossAnInterfaceIsConstrainedDelaunayButNotDelaunay) {
  for (int second : {1, 2}) {
    const auto m = kite(second);
    const auto p = plc_of_multi_region_mesh(m);
    const ConstrainedDelaunay<Exact, 2> cd(p, m.mesh);
    EXPECT_FALSE(is_delaunay_mesh(m.mesh));
    EXPECT_EQ(cd.mesh_is_constrained_delaunay(), second == 2);
    EXPECT_EQ(cd.free_facets_constrained_delaunay(), second == 2);
    EXPECT_EQ(cd.free_facets_locally_delaunay(), second == 2);
    EXPECT_EQ(cd.free_facets().size(), second == 2 ? 0u : 1u);
    std::ostringstream why;
    EXPECT_EQ(is_constrained_delaunay_triangulation(m, p, &why), second == 2) << why.str();
  }
}

TEST(ConstrainedDelaunay, PreconditionsAreChecked) {
  const auto m = kite(2);
  auto p = plc_of_multi_region_mesh(m);
  // a mesh that does not respect P: the other diagonal of the kite crosses the interface
  const auto flipped = multi<2>({p2(0, 0), p2(4, 0), p2(2, 1), p2(2, -1)},
                                {{Simplex{0, 2, 3}, 1}, {Simplex{1, 2, 3}, 1}});
  EXPECT_THROW((ConstrainedDelaunay<Exact, 2>(p, flipped.mesh)), std::invalid_argument);
  const ConstrainedDelaunay<Exact, 2> cd(p, m.mesh);
  EXPECT_THROW(cd.is_constrained_delaunay(Simplex{0, 1}), std::invalid_argument);
}

TEST(EdgeProtected, KiteInterfaceIsNotStronglyDelaunay) {
  const auto m = kite(2);
  const auto p = plc_of_multi_region_mesh(m);
  std::ostringstream why;
  EXPECT_FALSE(is_edge_protected(p, &why));
  EXPECT_FALSE(is_edge_protected(m.mesh));
  // a square with its boundary only: every side is strongly Delaunay
  const auto sq = multi<2>({p2(0, 0), p2(2, 0), p2(2, 2), p2(0, 2)},
                           {{Simplex{0, 1, 2}, 1}, {Simplex{0, 2, 3}, 1}});
  EXPECT_TRUE(is_edge_protected(plc_of_multi_region_mesh(sq)));
  EXPECT_FALSE(is_edge_protected(sq.mesh)); // the diagonal is Delaunay but not strongly
}

TEST(Plc, ThreeDimensionalMergesCoplanarFacets) {
  // a unit cube split into 6 tetrahedra around the diagonal 0-6 (Kuhn), two regions by z-order
  std::vector<P3> pts{p3(0, 0, 0), p3(1, 0, 0), p3(1, 1, 0), p3(0, 1, 0),
                      p3(0, 0, 1), p3(1, 0, 1), p3(1, 1, 1), p3(0, 1, 1)};
  std::vector<std::pair<Simplex, int>> cells{{Simplex{0, 1, 2, 6}, 1}, {Simplex{0, 2, 3, 6}, 1},
                                             {Simplex{0, 3, 7, 6}, 1}, {Simplex{0, 7, 4, 6}, 1},
                                             {Simplex{0, 4, 5, 6}, 1}, {Simplex{0, 5, 1, 6}, 1}};
  const auto m = multi<3>(pts, cells);
  const auto p = plc_of_multi_region_mesh(m);
  std::ostringstream why;
  ASSERT_TRUE(p.is_multi_region(&why)) << why.str();
  EXPECT_EQ(p.cells_of_dimension(2).size(), 6u); // the six square faces
  EXPECT_EQ(p.cells_of_dimension(1).size(), 12u);
  EXPECT_TRUE(is_triangulation_of(m.mesh, p));
  const ConstrainedDelaunay<Exact, 3> cd(p, m.mesh);
  EXPECT_TRUE(cd.mesh_is_constrained_delaunay());
  EXPECT_TRUE(cd.free_facets_locally_delaunay());
  EXPECT_TRUE(is_edge_protected(p)); // cube edges are strongly Delaunay (centre (1/2, 0, 0))
}
