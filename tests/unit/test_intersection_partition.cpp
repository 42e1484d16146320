// Unit tests of linear cells and Definitions A.26-A.30 (convex_cell.h, intersection_partition.h):
// hand-made cases whose answers are known by inspection.
#include <gtest/gtest.h>

#include "symmesh/core/element_complex.h"
#include "symmesh/core/intersection_partition.h"
#include "symmesh/core/kernel.h"

#include <algorithm>
#include <sstream>

using namespace symmesh::core;
using symmesh::Exact;
using P2 = Point<Exact, 2>;
using P3 = Point<Exact, 3>;
using C2 = ConvexCell<Exact, 2>;
using C3 = ConvexCell<Exact, 3>;
using L2 = LinearSet<Exact, 2>;
using L3 = LinearSet<Exact, 3>;

namespace {
P2 p2(int x, int y) {
  return P2{{Exact(x), Exact(y)}};
}
P2 p2q(int xn, int yn, int d) {
  return P2{{Exact(xn) / d, Exact(yn) / d}};
}
P3 p3(int x, int y, int z) {
  return P3{{Exact(x), Exact(y), Exact(z)}};
}
C2 cell2(std::vector<P2> p) {
  return make_convex_cell<Exact, 2>(p);
}
C3 cell3(std::vector<P3> p) {
  return make_convex_cell<Exact, 3>(p);
}
C2 square(int x0, int y0, int x1, int y1) {
  return cell2({p2(x0, y0), p2(x1, y0), p2(x1, y1), p2(x0, y1)});
}
L2 set2(std::vector<C2> cells) {
  L2 s{std::move(cells)};
  s.normalize();
  return s;
}
} // namespace

TEST(ConvexCell, CanonicalFormIgnoresInputOrderDuplicatesAndNonExtremePoints) {
  const std::vector<P2> pts{p2(0, 0), p2(2, 0), p2(2, 2), p2(0, 2), p2(1, 0), p2(1, 1), p2(0, 2)};
  const C2 a = cell2(pts);
  EXPECT_EQ(a.dim, 2);
  EXPECT_EQ(a.vertices, (std::vector<P2>{p2(0, 0), p2(0, 2), p2(2, 2), p2(2, 0)}));
  std::ostringstream why;
  EXPECT_TRUE(a.is_valid(&why)) << why.str();
  std::vector<P2> perm = pts;
  std::sort(perm.begin(), perm.end(), PointLess<Exact, 2>());
  do {
    EXPECT_EQ(cell2(perm), a);
  } while (std::next_permutation(perm.begin(), perm.end(), PointLess<Exact, 2>()));
  // 3D: the same square in the plane x + y + z = 2, given reversed and rotated.
  const C3 b = cell3({p3(2, 0, 0), p3(0, 2, 0), p3(0, 0, 2), p3(1, 1, 0)});
  const C3 c = cell3({p3(0, 0, 2), p3(1, 1, 0), p3(0, 2, 0), p3(2, 0, 0), p3(1, 0, 1)});
  EXPECT_EQ(b, c);
  EXPECT_EQ(b.dim, 2);
  EXPECT_EQ(b.vertices.size(), 3u); // (1,1,0) lies on the edge from (2,0,0) to (0,2,0)
}

TEST(ConvexCell, AffineDimensionIsDetectedAndPreconditionsThrow) {
  EXPECT_EQ(cell2({p2(1, 1), p2(1, 1)}).dim, 0);
  const C2 s = cell2({p2(2, 2), p2(0, 0), p2(1, 1), p2(3, 3)});
  EXPECT_EQ(s.dim, 1);
  EXPECT_EQ(s.vertices, (std::vector<P2>{p2(0, 0), p2(3, 3)}));
  EXPECT_EQ(cell3({p3(0, 0, 0), p3(0, 0, 2), p3(0, 0, 1)}).dim, 1);
  EXPECT_THROW(cell3({p3(0, 0, 0), p3(1, 0, 0), p3(0, 1, 0), p3(0, 0, 1)}), std::invalid_argument);
  EXPECT_THROW(cell2({}), std::invalid_argument);
}

TEST(ConvexCell, IsValidRejectsNonCanonicalCells) {
  C2 a = square(0, 0, 1, 1);
  std::reverse(a.vertices.begin() + 1, a.vertices.end());
  std::ostringstream why;
  EXPECT_FALSE(a.is_valid(&why));
  EXPECT_NE(why.str().find("canonical"), std::string::npos) << why.str();
  C2 b{2, {p2(0, 0), p2(0, 2), p2(1, 1), p2(2, 2), p2(2, 0)}}; // (1,1) is not extreme
  EXPECT_FALSE(b.is_valid());
  C2 c{1, {p2(0, 0), p2(0, 0)}};
  EXPECT_FALSE(c.is_valid());
  C3 d{2, {p3(0, 0, 0), p3(0, 1, 0), p3(1, 1, 1), p3(1, 0, 0)}}; // not coplanar
  EXPECT_FALSE(d.is_valid());
  L2 bad{{b}};
  EXPECT_THROW(ip(bad, bad), std::invalid_argument);
}

TEST(ConvexCell, ContainmentAndRelativeInterior) {
  const C2 t = cell2({p2(0, 0), p2(4, 0), p2(0, 4)});
  EXPECT_TRUE(contains(t, p2(2, 2)));
  EXPECT_FALSE(relative_interior_contains(t, p2(2, 2)));
  EXPECT_TRUE(relative_interior_contains(t, p2(1, 1)));
  EXPECT_FALSE(contains(t, p2q(9, 0, 2)));
  const C3 s = cell3({p3(0, 0, 0), p3(2, 2, 2)});
  EXPECT_TRUE(contains(s, p3(1, 1, 1)));
  EXPECT_TRUE(relative_interior_contains(s, p3(1, 1, 1)));
  EXPECT_FALSE(relative_interior_contains(s, p3(2, 2, 2)));
  EXPECT_FALSE(contains(s, p3(1, 1, 0)));
  const C3 q = cell3({p3(0, 0, 1), p3(2, 0, 1), p3(2, 2, 1), p3(0, 2, 1)});
  EXPECT_TRUE(relative_interior_contains(q, p3(1, 1, 1)));
  EXPECT_FALSE(contains(q, p3(1, 1, 0)));
  EXPECT_EQ(triangulate(q).size(), 2u);
  EXPECT_EQ(cell_edges(q).size(), 4u);
}

TEST(Intersect, TwoOverlappingTriangles) {
  const C2 a = cell2({p2(0, 0), p2(4, 0), p2(0, 4)});
  const C2 b = cell2({p2(1, 1), p2(5, 1), p2(1, 5)});
  const auto q = intersect(a, b);
  ASSERT_TRUE(q);
  EXPECT_EQ(*q, cell2({p2(1, 1), p2(3, 1), p2(1, 3)}));
  EXPECT_EQ(intersect(b, a), q);
  // A hexagon: a triangle and its point reflection through the centroid.
  const C2 c = cell2({p2(0, 0), p2(6, 0), p2(0, 6)});
  const C2 d = cell2({p2(4, 4), p2(-2, 4), p2(4, -2)});
  const auto h = intersect(c, d);
  ASSERT_TRUE(h);
  EXPECT_EQ(h->vertices.size(), 6u);
  EXPECT_TRUE(h->is_valid());
}

TEST(Intersect, TouchingSquaresMeetInASegment) {
  const auto q = intersect(square(0, 0, 2, 2), square(2, 1, 4, 3));
  ASSERT_TRUE(q);
  EXPECT_EQ(*q, cell2({p2(2, 1), p2(2, 2)}));
  EXPECT_EQ(q->dim, 1);
}

TEST(Intersect, CornerTouchIsAPoint) {
  const auto q = intersect(square(0, 0, 1, 1), square(1, 1, 2, 2));
  ASSERT_TRUE(q);
  EXPECT_EQ(q->dim, 0);
  EXPECT_EQ(q->vertices[0], p2(1, 1));
  EXPECT_FALSE(intersect(square(0, 0, 1, 1), cell2({p2(2, 0), p2(3, 1), p2(2, 2)})));
}

TEST(Intersect, Segments) {
  const auto x = intersect(cell2({p2(0, 0), p2(2, 2)}), cell2({p2(2, 0), p2(0, 2)}));
  ASSERT_TRUE(x);
  EXPECT_EQ(*x, cell2({p2(1, 1)}));
  const auto o = intersect(cell2({p2(0, 0), p2(2, 0)}), cell2({p2(3, 0), p2(1, 0)}));
  ASSERT_TRUE(o);
  EXPECT_EQ(*o, cell2({p2(1, 0), p2(2, 0)}));
  const auto t = intersect(cell2({p2(0, 0), p2(2, 0)}), cell2({p2(2, 0), p2(3, 0)}));
  ASSERT_TRUE(t);
  EXPECT_EQ(t->dim, 0);
  EXPECT_FALSE(intersect(cell2({p2(0, 0), p2(1, 0)}), cell2({p2(2, 0), p2(3, 0)})));
  EXPECT_FALSE(intersect(cell2({p2(0, 0), p2(2, 0)}), cell2({p2(0, 1), p2(2, 1)})));
  // 3D skew and crossing segments.
  EXPECT_FALSE(intersect(cell3({p3(0, 0, 0), p3(2, 0, 0)}), cell3({p3(1, -1, 1), p3(1, 1, 1)})));
  const auto c = intersect(cell3({p3(0, 0, 0), p3(2, 0, 0)}), cell3({p3(1, -1, -1), p3(1, 1, 1)}));
  ASSERT_TRUE(c);
  EXPECT_EQ(*c, cell3({p3(1, 0, 0)}));
}

TEST(Intersect, NonCoplanarTrianglesIn3DMeetInASegment) {
  // Triangle in z = 0 and a triangle in x = 1 crossing it: the common segment lies on the line
  // x = 1, z = 0; b cuts it to 1/2 <= y <= 2, inside a's 0 <= y <= 3.
  const C3 a = cell3({p3(0, 0, 0), p3(4, 0, 0), p3(0, 4, 0)});
  const C3 b = cell3({p3(1, 0, -1), p3(1, 2, -1), p3(1, 2, 3)});
  const auto q = intersect(a, b);
  ASSERT_TRUE(q);
  EXPECT_EQ(q->dim, 1);
  EXPECT_EQ(*q, cell3({P3{{Exact(1), Exact(1) / 2, Exact(0)}}, p3(1, 2, 0)}));
  EXPECT_EQ(intersect(b, a), q);
}

TEST(Intersect, ThreeDimensionalSpecialCases) {
  const C3 a = cell3({p3(0, 0, 0), p3(4, 0, 0), p3(0, 4, 0)});
  // Touching at a vertex from above; parallel planes; segment piercing; segment in the plane.
  const auto v = intersect(a, cell3({p3(0, 0, 0), p3(-1, 0, 1), p3(0, -1, 1)}));
  ASSERT_TRUE(v);
  EXPECT_EQ(*v, cell3({p3(0, 0, 0)}));
  EXPECT_FALSE(intersect(a, cell3({p3(0, 0, 1), p3(4, 0, 1), p3(0, 4, 1)})));
  const auto pierce = intersect(a, cell3({p3(1, 1, -1), p3(1, 1, 1)}));
  ASSERT_TRUE(pierce);
  EXPECT_EQ(*pierce, cell3({p3(1, 1, 0)}));
  const auto inplane = intersect(a, cell3({p3(-1, 1, 0), p3(5, 1, 0)}));
  ASSERT_TRUE(inplane);
  EXPECT_EQ(*inplane, cell3({p3(0, 1, 0), p3(3, 1, 0)}));
  // Coplanar polygons in a slanted plane.
  const C3 b = cell3({p3(2, 0, 0), p3(0, 2, 0), p3(0, 0, 2)});
  const C3 c = cell3({p3(1, 1, 0), p3(1, 0, 1), p3(0, 1, 1)});
  const auto bc = intersect(b, c);
  ASSERT_TRUE(bc);
  EXPECT_EQ(*bc, c);
}

TEST(LinearSet, UnionEqualityIsOnPointSets) {
  const L2 diag1 =
      set2({cell2({p2(0, 0), p2(2, 0), p2(2, 2)}), cell2({p2(0, 0), p2(2, 2), p2(0, 2)})});
  const L2 diag2 =
      set2({cell2({p2(0, 0), p2(2, 0), p2(0, 2)}), cell2({p2(2, 0), p2(2, 2), p2(0, 2)})});
  const L2 whole = set2({square(0, 0, 2, 2)});
  EXPECT_TRUE(union_equals(diag1, diag2));
  EXPECT_TRUE(union_equals(diag1, whole));
  // Four overlapping quarters-plus cover the square; three do not.
  L2 quads = set2({square(0, 0, 1, 1), square(1, 0, 2, 1), square(0, 1, 1, 2), square(1, 1, 2, 2)});
  EXPECT_TRUE(union_equals(quads, whole));
  quads.cells.pop_back();
  EXPECT_FALSE(union_equals(quads, whole));
  EXPECT_TRUE(subset_of(quads, whole));
  // A segment covered by two overlapping segments, and one with a gap.
  const L2 seg = set2({cell2({p2(0, 0), p2(4, 0)})});
  EXPECT_TRUE(subset_of(seg, set2({cell2({p2(0, 0), p2(3, 0)}), cell2({p2(2, 0), p2(4, 0)})})));
  EXPECT_FALSE(subset_of(seg, set2({cell2({p2(0, 0), p2(1, 0)}), cell2({p2(2, 0), p2(4, 0)}),
                                    cell2({p2q(3, 0, 2)})})));
  // A point is never enough to fill a gap in a polygon: the square minus a diagonal strip.
  EXPECT_FALSE(covered_by(square(0, 0, 2, 2), set2({cell2({p2(0, 0), p2(2, 0), p2(2, 1)}),
                                                    cell2({p2(0, 0), p2(2, 2), p2(0, 2)})})));
}

TEST(LinearSet, TinyGapsAreFound) {
  // Halves of a cell cut at h = ±1/1000 around its centroid: covered iff the gap is closed.
  const P2 w = p2(1, 2);
  for (const C2& c : {cell2({p2(0, 0), p2(2, 2)}), cell2({p2(0, 0), p2(3, 0), p2(0, 2)})}) {
    for (const int gap : {0, 1}) {
      const Exact h = Exact(gap) / 1000;
      const Exact mid = dot<Exact, 2>(w, centroid(c));
      const auto lo = clip_halfspace(c, P2{{-w[0], -w[1]}}, -(mid - h));
      const auto hi = clip_halfspace(c, w, mid + h);
      ASSERT_TRUE(lo && hi);
      EXPECT_EQ(covered_by(c, set2({*lo, *hi})), gap == 0) << c.dim;
    }
  }
  const C3 s = cell3({p3(0, 0, 0), p3(2, 2, 2)});
  const P3 m =
      P3{{Exact(1) + Exact(1) / 1000, Exact(1) + Exact(1) / 1000, Exact(1) + Exact(1) / 1000}};
  const L3 gap3{{cell3({p3(0, 0, 0), p3(1, 1, 1)}), cell3({m, p3(2, 2, 2)})}};
  EXPECT_FALSE(covered_by(s, gap3));
  const L3 closed3{{cell3({p3(0, 0, 0), p3(1, 1, 1)}), cell3({p3(1, 1, 1), p3(2, 2, 2)})}};
  EXPECT_TRUE(covered_by(s, closed3));
}

TEST(LinearSet, CoveredByAgreesWithSimplexCoveredByOnAConformingMesh) {
  ElementComplex<Exact, 2> m;
  m.points = {p2(0, 0), p2(2, 0), p2(2, 2), p2(0, 2)};
  m.elements = {Simplex{0, 1, 2}, Simplex{0, 2, 3}};
  m = face_completion(m);
  const L2 x = set2({cell2({p2(0, 0), p2(2, 0), p2(2, 2)}), cell2({p2(0, 0), p2(2, 2), p2(0, 2)})});
  for (const C2& c : {cell2({p2(1, 0), p2(2, 1), p2(1, 2)}), cell2({p2(1, 0), p2(3, 1), p2(1, 2)}),
                      cell2({p2(0, 0), p2(2, 2)}), cell2({p2(0, 1), p2(3, 1)})}) {
    bool simplex = true;
    for (const auto& t : triangulate(c)) simplex = simplex && simplex_covered_by<Exact, 2>(t, m);
    EXPECT_EQ(covered_by(c, x), simplex);
  }
}

TEST(IntersectionPartition, FigureA7IntersectionOfManifoldsIsNoManifold) {
  // B the unit square; A a C-shaped polygon touching B along its right edge and at the corner
  // (0, 1) of its top edge. A ∩ B = segment ∪ isolated point (Fig. A.7).
  const L2 b = set2({square(0, 0, 1, 1)});
  const L2 a =
      set2({square(1, 0, 2, 1), square(1, 1, 2, 2), square(1, 2, 2, 3), square(-1, 2, 0, 3),
            square(0, 2, 1, 3), cell2({p2(-1, 2), p2(0, 2), p2(0, 1)})});
  const auto c = ip(a, b);
  ASSERT_EQ(c.size(), 3u); // the segment, its end point (1,1) from square(1,1,2,2), and (0,1)
  std::vector<L2> parts;
  for (const auto& q : c) parts.push_back(linear_set(q));
  const L2 ab = union_of(parts);
  EXPECT_EQ(dimension(ab), 1);
  EXPECT_FALSE(is_pure_dimensional(ab));
  std::ostringstream why;
  EXPECT_FALSE(is_manifold_partition(parts, ab, &why));
  EXPECT_NE(why.str().find("pure"), std::string::npos) << why.str();
  EXPECT_TRUE(is_covering(parts, ab));
}

TEST(IntersectionPartition, NonConformingRepresentationBreaksTheManifoldPartition) {
  // A = rhombus with a T-junction at (1,0): a1 above [0,2], a2 and a3 below [0,1] and [1,2].
  const L2 a = set2({cell2({p2(0, 0), p2(2, 0), p2(1, 1)}), cell2({p2(0, 0), p2(1, 0), p2(1, -1)}),
                     cell2({p2(1, 0), p2(2, 0), p2(1, -1)})});
  const L2 b = set2({cell2({p2(0, 0), p2(2, 0)})});
  const auto c = ip(a, b);
  EXPECT_EQ(c.size(), 3u);
  std::vector<L2> parts;
  for (const auto& q : c) parts.push_back(linear_set(q));
  EXPECT_TRUE(is_covering(parts, b));
  EXPECT_FALSE(is_manifold_partition(parts, b));
  // With a conforming representation the same set gives a manifold partition.
  const L2 conf =
      set2({cell2({p2(0, 0), p2(1, 0), p2(1, 1)}), cell2({p2(1, 0), p2(2, 0), p2(1, 1)}),
            cell2({p2(0, 0), p2(1, 0), p2(1, -1)}), cell2({p2(1, 0), p2(2, 0), p2(1, -1)})});
  EXPECT_TRUE(union_equals(conf, a));
  std::vector<L2> parts2;
  for (const auto& q : ip(conf, b)) parts2.push_back(linear_set(q));
  std::ostringstream why;
  EXPECT_TRUE(is_manifold_partition(parts2, b, &why)) << why.str();
}

TEST(IntersectionPartition, RefinementOfTwoPartitionsOfASquare) {
  const L2 x = set2({square(0, 0, 2, 2)});
  // S: left/right halves plus the boundary edge at the bottom (lower-dimensional, allowed).
  const std::vector<L2> s{set2({square(0, 0, 1, 2)}), set2({square(1, 0, 2, 2)}),
                          set2({cell2({p2(0, 0), p2(2, 0)})})};
  // P: the two triangles of a diagonal.
  const std::vector<L2> p{set2({cell2({p2(0, 0), p2(2, 0), p2(2, 2)})}),
                          set2({cell2({p2(0, 0), p2(2, 2), p2(0, 2)})})};
  std::ostringstream why;
  ASSERT_TRUE(is_manifold_partition(s, x, &why)) << why.str();
  ASSERT_TRUE(is_manifold_partition(p, x, &why)) << why.str();
  const auto r = refine(s, p);
  EXPECT_TRUE(is_manifold_partition(r, x, &why)) << why.str();
  int cells2 = 0;
  for (const auto& e : r) cells2 += dimension(e) == 2;
  EXPECT_EQ(cells2, 4);
  // Only a covering: the halves overlap in [1/2, 3/2] x [0, 2]. Still a covering after refine.
  const std::vector<L2> cov{set2({cell2({p2(0, 0), p2(3, 0), p2(3, 4), p2(0, 4)})}),
                            set2({square(1, 0, 2, 2)})};
  const std::vector<L2> half{set2({cell2({p2(0, 0), p2q(3, 0, 2), p2q(3, 4, 2), p2(0, 2)})}),
                             set2({cell2({p2(1, 0), p2(2, 0), p2(2, 2), p2(1, 2)})})};
  EXPECT_TRUE(is_covering(half, x));
  EXPECT_FALSE(is_manifold_partition(half, x));
  const auto rc = refine(half, p);
  EXPECT_TRUE(is_covering(rc, x));
  EXPECT_FALSE(is_manifold_partition(rc, x));
  EXPECT_FALSE(is_covering(cov, x)); // sticks out of X
}

TEST(IntersectionPartition, ThreeDimensionalFoldedSurface) {
  // X: two unit squares folded along the x-axis edge; S splits each square, P is X itself.
  const C3 f1 = cell3({p3(0, 0, 0), p3(2, 0, 0), p3(2, 2, 0), p3(0, 2, 0)});
  const C3 f2 = cell3({p3(0, 0, 0), p3(2, 0, 0), p3(2, 0, 2), p3(0, 0, 2)});
  const L3 x{{f1, f2}};
  const std::vector<L3> s{L3{{cell3({p3(0, 0, 0), p3(1, 0, 0), p3(1, 2, 0), p3(0, 2, 0)}),
                              cell3({p3(0, 0, 0), p3(1, 0, 0), p3(1, 0, 2), p3(0, 0, 2)})}},
                          L3{{cell3({p3(1, 0, 0), p3(2, 0, 0), p3(2, 2, 0), p3(1, 2, 0)}),
                              cell3({p3(1, 0, 0), p3(2, 0, 0), p3(2, 0, 2), p3(1, 0, 2)})}}};
  const std::vector<L3> p{x};
  std::ostringstream why;
  EXPECT_TRUE(is_manifold_partition(s, x, &why)) << why.str();
  const auto r = refine(s, p);
  EXPECT_EQ(r.size(), 4u + 2u); // four quarter squares, plus the two halves of the fold edge
  EXPECT_TRUE(is_manifold_partition(r, x, &why)) << why.str();
  // A plane crossing X transversally meets it in a bent segment: ip is a partition of it.
  const L3 b{{cell3({p3(1, -1, -1), p3(1, 3, -1), p3(1, 3, 3), p3(1, -1, 3)})}};
  std::vector<L3> parts;
  for (const auto& q : ip(x, b)) parts.push_back(linear_set(q));
  ASSERT_EQ(parts.size(), 2u);
  const L3 ab = union_of(parts);
  EXPECT_EQ(dimension(ab), 1);
  EXPECT_TRUE(is_manifold_partition(parts, ab, &why)) << why.str();
}
