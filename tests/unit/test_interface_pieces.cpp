// Definition 4.7's domains are found from boundary triangles that meet (interf_geo = bnd ∩ bnd,
// spec/boundary-patches.md#def-4-7). Pairs that share vertices are decided by predicates
// (shared_corners, then shared_edge_meet, the same triangle, shared_vertex_meet) before CGAL's
// triangle intersection, and cuts at a triangle's corners (corner_cut) before CGAL's
// segment–triangle intersection; here each decision is compared with CGAL's intersection of the
// same elements, the independent definition, on small integer grids where coplanar and touching
// pairs are frequent.
#include <gtest/gtest.h>

#include "symmesh/core/kernel.h"
#include "symmesh/core/boundary_subdivision_impl.h"

#include <random>

using namespace symmesh::core;
using symmesh::Exact;

namespace {

using P3 = Point<Exact, 3>;
using K = CGAL::Epeck;

K::Triangle_3 triangle(const std::vector<P3>& t) {
  const auto cg = [](const P3& p) { return K::Point_3(p[0], p[1], p[2]); };
  return {cg(t[0]), cg(t[1]), cg(t[2])};
}

struct Grid {
  std::mt19937 rng;
  std::uniform_int_distribution<int> coord{-2, 2};
  explicit Grid(unsigned seed) : rng(seed) {}
  P3 point() { return P3{{Exact(coord(rng)), Exact(coord(rng)), Exact(coord(rng))}}; }
  /// A point of t's plane: t0 + s (t1 − t0) + u (t2 − t0) with small integers s, u.
  P3 in_plane(const std::vector<P3>& t) {
    const Exact s(coord(rng)), u(coord(rng));
    P3 p;
    for (int d = 0; d < 3; ++d) p[d] = t[0][d] + s * (t[1][d] - t[0][d]) + u * (t[2][d] - t[0][d]);
    return p;
  }
  std::vector<P3> triangle() {
    for (;;) {
      std::vector<P3> t{point(), point(), point()};
      if (affinely_independent<Exact, 3>(t)) return t;
    }
  }
};

} // namespace

// A pair that shares exactly one vertex, coplanar or not: when the predicates say the triangles
// meet only in it, CGAL's intersection is that point. For coplanar pairs the decision is also
// complete: every pair whose intersection is the shared vertex alone is decided.
TEST(InterfacePieces, SharedVertexMeetIsCgalsIntersection) {
  Grid g(20261201);
  int decided_coplanar = 0, decided_apart = 0, undecided = 0;
  for (int k = 0; k < 4000; ++k) {
    const auto a = g.triangle();
    const bool coplanar = k % 2 == 0;
    std::vector<P3> b{a[std::size_t(k % 3)], coplanar ? g.in_plane(a) : g.point(),
                      coplanar ? g.in_plane(a) : g.point()};
    if (!affinely_independent<Exact, 3>(b)) continue;
    int shared = 0;
    for (const auto& p : a) shared += std::find(b.begin(), b.end(), p) != b.end();
    if (shared != 1) continue;
    const auto r = CGAL::intersection(triangle(a), triangle(b));
    ASSERT_TRUE(r.has_value()); // they share a vertex
    const auto* point = boost::get<K::Point_3>(&*r);
    const auto fast = shared_vertex_meet<Exact>(a, b, shared_corners<Exact>(a, b));
    const bool only_vertex = point != nullptr;
    if (fast) {
      ASSERT_TRUE(only_vertex) << "case " << k << ": the triangles meet in more than a point";
      EXPECT_TRUE(point->x() == (*fast)[0] && point->y() == (*fast)[1] && point->z() == (*fast)[2]);
      (coplanar ? decided_coplanar : decided_apart) += 1;
    } else {
      EXPECT_FALSE(coplanar && only_vertex) << "case " << k << ": coplanar pair undecided";
      ++undecided;
    }
  }
  EXPECT_GT(decided_coplanar, 100);
  EXPECT_GT(decided_apart, 100);
  EXPECT_GT(undecided, 100); // overlapping pairs exist, and they are left to CGAL
}

// The interval filters in front of those tests decide only what the exact intersection
// confirms: a pair `certainly_apart` does not meet, and a pair sharing one vertex that
// `certainly_meet_only_at` it meets in that point alone. Both filters decide many pairs (the
// grid's coplanar and touching pairs included) and leave the others.
TEST(InterfacePieces, IntervalFiltersAgreeWithCgal) {
  Grid g(20261202);
  int apart = 0, apart_undecided = 0, only_at = 0, only_at_undecided = 0;
  for (int k = 0; k < 4000; ++k) {
    const auto a = g.triangle();
    const bool coplanar = k % 2 == 0;
    const auto other = [&] { return coplanar ? g.in_plane(a) : g.point(); };
    std::vector<P3> b{other(), other(), other()};
    if (!affinely_independent<Exact, 3>(b)) continue;
    if (certainly_apart<Exact>(a, b)) {
      ASSERT_FALSE(CGAL::do_intersect(triangle(a), triangle(b))) << "case " << k;
      ++apart;
    } else {
      ++apart_undecided;
    }
    b[0] = a[std::size_t(k % 3)];
    if (!affinely_independent<Exact, 3>(b)) continue;
    const auto shared = shared_corners<Exact>(a, b);
    if (shared.count != 1) continue;
    const int ia = k % 3, ib = 0;
    if (certainly_meet_only_at<Exact>(a, b, ia, ib)) {
      const auto r = CGAL::intersection(triangle(a), triangle(b));
      ASSERT_TRUE(r.has_value());
      ASSERT_NE(boost::get<K::Point_3>(&*r), nullptr) << "case " << k << ": more than a point";
      ++only_at;
    } else {
      ++only_at_undecided;
    }
  }
  EXPECT_GT(apart, 200);
  EXPECT_GT(apart_undecided, 200);
  EXPECT_GT(only_at, 200);
  EXPECT_GT(only_at_undecided, 100);
}

// The same triangle on both sides (vertices in another order) is its own intersection, and a
// coplanar triangle with one vertex moved is never taken for it.
TEST(InterfacePieces, SameTriangleIsItsIntersection) {
  Grid g(7);
  int same = 0, different = 0;
  for (int k = 0; k < 500; ++k) {
    const auto a = g.triangle();
    std::vector<P3> b{a[2], a[0], a[1]};
    if (k % 2) b[std::size_t(k % 3)] = g.in_plane(a);
    if (!affinely_independent<Exact, 3>(b)) continue;
    const bool fast = shared_corners<Exact>(a, b).count == 3;
    const auto r = CGAL::intersection(triangle(a), triangle(b));
    ASSERT_TRUE(r.has_value());
    std::vector<P3> cgal;
    if (const auto* t = boost::get<K::Triangle_3>(&*r))
      for (int i = 0; i < 3; ++i)
        cgal.push_back(P3{{t->vertex(i).x(), t->vertex(i).y(), t->vertex(i).z()}});
    if (const auto* v = boost::get<std::vector<K::Point_3>>(&*r))
      for (const auto& p : *v) cgal.push_back(P3{{p.x(), p.y(), p.z()}});
    const bool cgal_same = convex_cyclic_order<Exact>(cgal) == convex_cyclic_order<Exact>(a);
    // Sound (a moved vertex may still leave a inside b, which CGAL finds and this does not).
    EXPECT_TRUE(!fast || cgal_same) << "case " << k;
    EXPECT_TRUE(k % 2 == 1 || fast) << "case " << k << ": the same triangle, undecided";
    (fast ? same : different) += 1;
  }
  EXPECT_GT(same, 100);
  EXPECT_GT(different, 100);
}

// A cut from a corner: along an edge it is that edge, off the plane it meets the triangle only in
// the corner, as CGAL's segment–triangle intersection finds; in the plane it is left to CGAL.
TEST(InterfacePieces, CornerCutIsCgalsIntersection) {
  Grid g(31);
  int edge = 0, corner_only = 0, undecided = 0;
  for (int k = 0; k < 3000; ++k) {
    const auto tri = g.triangle();
    const P3 a = tri[std::size_t(k % 3)];
    const P3 b = k % 4 == 0   ? tri[std::size_t((k + 1) % 3)]
                 : k % 4 == 1 ? g.in_plane(tri)
                              : g.point();
    if (a == b) continue;
    const auto r = CGAL::intersection(
        K::Segment_3(K::Point_3(a[0], a[1], a[2]), K::Point_3(b[0], b[1], b[2])), triangle(tri));
    ASSERT_TRUE(r.has_value()); // a is a corner
    switch (corner_cut<Exact>(tri, a, b)) {
    case CornerCut::edge: {
      const auto* s = boost::get<K::Segment_3>(&*r);
      ASSERT_NE(s, nullptr) << "case " << k;
      EXPECT_TRUE((s->source() == K::Point_3(a[0], a[1], a[2]) &&
                   s->target() == K::Point_3(b[0], b[1], b[2])) ||
                  (s->source() == K::Point_3(b[0], b[1], b[2]) &&
                   s->target() == K::Point_3(a[0], a[1], a[2])))
          << "case " << k;
      ++edge;
      break;
    }
    case CornerCut::corner_only: {
      const auto* p = boost::get<K::Point_3>(&*r);
      ASSERT_NE(p, nullptr) << "case " << k << ": the cut meets the triangle in more than a corner";
      EXPECT_TRUE(*p == K::Point_3(a[0], a[1], a[2])) << "case " << k;
      ++corner_only;
      break;
    }
    case CornerCut::undecided:
      EXPECT_EQ(CGAL::orientation(triangle(tri).vertex(0), triangle(tri).vertex(1),
                                  triangle(tri).vertex(2), K::Point_3(b[0], b[1], b[2])),
                CGAL::COPLANAR)
          << "case " << k << ": only cuts in the plane are left to CGAL";
      ++undecided;
      break;
    }
  }
  EXPECT_GT(edge, 100);
  EXPECT_GT(corner_only, 100);
  EXPECT_GT(undecided, 100);
}
