// Unit tests of the exact core: transformations, predicates, complexes, AT and Lemma 4.2.
#include <gtest/gtest.h>

#include "symmesh/core/delaunay.h"
#include "symmesh/core/kernel.h"
#include "symmesh/core/multi_region_mesh.h"
#include "symmesh/core/respect.h"
#include "symmesh/core/structure_report.h"

#include <random>

using namespace symmesh::core;
using symmesh::Exact;
using P2 = Point<Exact, 2>;
using P3 = Point<Exact, 3>;
using T2 = RigidTransformation<Exact, 2>;
using T3 = RigidTransformation<Exact, 3>;

namespace {
P2 p2(int x, int y) {
  return P2{{Exact(x), Exact(y)}};
}
P2 p2q(int xn, int xd, int yn, int yd) {
  return P2{{Exact(xn) / xd, Exact(yn) / yd}};
}
P3 p3(int x, int y, int z) {
  return P3{{Exact(x), Exact(y), Exact(z)}};
}

ElementComplex<Exact, 2> complex2(std::vector<P2> pts, std::vector<Simplex> cells) {
  ElementComplex<Exact, 2> m;
  m.points = std::move(pts);
  m.elements = std::move(cells);
  return face_completion(m);
}

/// The unit square split along its diagonal, edges (0,0)-(1,0) and (0,1)-(1,1) split at
/// x = split_bottom and x = split_top.
ElementComplex<Exact, 2> split_square(Exact split_bottom, Exact split_top) {
  std::vector<P2> pts{p2(0, 0), P2{{split_bottom, Exact(0)}}, p2(1, 0),
                      p2(1, 1), P2{{split_top, Exact(1)}},    p2(0, 1)};
  return complex2(pts, {{0, 1, 5}, {1, 4, 5}, {1, 2, 4}, {2, 3, 4}});
}

TemplatedStructure<Exact, 2> one_template(ElementComplex<Exact, 2> m, std::vector<T2> ts) {
  TemplatedStructure<Exact, 2> x;
  x.templates.push_back({"X1", TemplateKind::mesh, std::move(m)});
  std::vector<InstanceSpec<Exact, 2>> inst;
  for (auto& t : ts) inst.push_back({t, 1});
  x.instances.push_back(inst);
  return x;
}
} // namespace

TEST(RigidTransformation, ReflectionIsAnInvolutionAndImproper) {
  const auto r = T2::reflection(p2(3, 4), Exact(2));
  EXPECT_TRUE((r * r).is_identity());
  EXPECT_EQ(r.determinant_of_linear_part(), Exact(-1));
  const auto q = r(p2q(6, 25, 8, 25)); // a point on the line 3x + 4y = 2 is fixed
  EXPECT_EQ(q, p2q(6, 25, 8, 25));
}

TEST(RigidTransformation, PythagoreanRotationComposesExactly) {
  const auto r = T2::rotation_2d(Exact(3) / 5, Exact(4) / 5, p2(1, 1));
  EXPECT_EQ(r(p2(1, 1)), p2(1, 1));
  EXPECT_EQ(r * r.inverse(), T2());
  EXPECT_THROW(T2::rotation_2d(Exact(1) / 2, Exact(1) / 2, p2(0, 0)), std::invalid_argument);
}

TEST(RigidTransformation, QuaternionRotationIsOrthogonal) {
  const auto r = T3::rotation_quaternion(Exact(1), Exact(2), Exact(3), Exact(4), p3(0, 0, 0));
  EXPECT_TRUE(r.is_valid());
  EXPECT_EQ(r.determinant_of_linear_part(), Exact(1));
  EXPECT_EQ((r * r.inverse()), T3());
}

// rotation_about_axis checks |u| = 1 and c² + s² = 1 only; Rodrigues' matrix is then orthogonal
// (is_valid agrees), fixes the axis line and turns a perpendicular vector by the angle. Dropping
// either hypothesis is refused.
TEST(RigidTransformation, AxisRotationIsOrthogonalAndFixesItsAxis) {
  const P3 u{{Exact(1) / 3, Exact(2) / 3, Exact(2) / 3}};
  const P3 c = p3(1, 0, -2);
  const P3 on_axis{{Exact(4) / 3, Exact(2) / 3, Exact(-4) / 3}}; // c + u
  const auto r = T3::rotation_about_axis(Exact(3) / 5, Exact(4) / 5, u, c);
  EXPECT_TRUE(r.is_valid());
  EXPECT_EQ(r.determinant_of_linear_part(), Exact(1));
  EXPECT_EQ(r(c), c);
  EXPECT_EQ(r(on_axis), on_axis);
  const auto z = T3::rotation_about_axis(Exact(0), Exact(1), p3(0, 0, 1), p3(0, 0, 0));
  EXPECT_EQ(z(p3(1, 0, 5)), p3(0, 1, 5));
  EXPECT_THROW(T3::rotation_about_axis(Exact(3) / 5, Exact(4) / 5, p3(1, 1, 0), c),
               std::invalid_argument);
  EXPECT_THROW(T3::rotation_about_axis(Exact(1) / 2, Exact(1) / 2, u, c), std::invalid_argument);
}

TEST(RigidTransformation, NonOrthogonalMatrixIsRejected) {
  T2::Mat a{{{Exact(1), Exact(1) / 1000}, {Exact(0), Exact(1)}}};
  EXPECT_THROW(T2::from_matrix(a, p2(0, 0)), std::invalid_argument);
  T2::Mat s{{{Exact(0), Exact(0)}, {Exact(0), Exact(0)}}};
  EXPECT_THROW(T2::from_matrix(s, p2(0, 0)), std::invalid_argument);
}

TEST(Predicates, RelativeInteriors) {
  // Two segments crossing at (1/2, 1/2); touching at an endpoint; collinear overlapping.
  EXPECT_TRUE((relative_interiors_meet<Exact, 2>({p2(0, 0), p2(1, 1)}, {p2(1, 0), p2(0, 1)})));
  EXPECT_FALSE((relative_interiors_meet<Exact, 2>({p2(0, 0), p2(1, 1)}, {p2(1, 1), p2(2, 0)})));
  EXPECT_TRUE((closed_simplices_meet<Exact, 2>({p2(0, 0), p2(1, 1)}, {p2(1, 1), p2(2, 0)})));
  EXPECT_TRUE((relative_interiors_meet<Exact, 2>({p2(0, 0), p2(2, 0)}, {p2(1, 0), p2(3, 0)})));
  // A vertex in the middle of an edge (Fig. 2.7).
  EXPECT_TRUE((relative_interiors_meet<Exact, 2>({p2(0, 0), p2(2, 0)}, {p2(1, 0)})));
  // 3D: a segment piercing a triangle, and one passing beside it.
  EXPECT_TRUE((relative_interiors_meet<Exact, 3>({p3(0, 0, 0), p3(4, 0, 0), p3(0, 4, 0)},
                                                 {p3(1, 1, -1), p3(1, 1, 1)})));
  EXPECT_FALSE((relative_interiors_meet<Exact, 3>({p3(0, 0, 0), p3(4, 0, 0), p3(0, 4, 0)},
                                                  {p3(5, 5, -1), p3(5, 5, 1)})));
}

// The two-triangle fast path (separating axis theorem over the 6 edge lines) against the
// general decision (all candidate planes, then the exact LP), on random triangles of a 4x4 grid,
// where shared edges, shared vertices, vertices on edges and collinear edges are frequent.
TEST(Predicates, TriangleEdgeLinesAgreeWithTheGeneralDecision) {
  std::mt19937 rng(20261122);
  std::uniform_int_distribution<int> coord(0, 3);
  const auto random_triangle = [&] {
    for (;;) {
      std::vector<P2> t{p2(coord(rng), coord(rng)), p2(coord(rng), coord(rng)),
                        p2(coord(rng), coord(rng))};
      if (detail::orientation_sign<Exact>(t[0], t[1], t[2]) != 0) return t;
    }
  };
  int interiors_meet = 0, closed_meet_only = 0, apart = 0;
  for (int k = 0; k < 3000; ++k) {
    const auto a = random_triangle(), b = random_triangle();
    const bool rel = !weakly_separated<Exact, 2>(a, b) &&
                     common_point<Exact, 2>({{a, true}, {b, true}}).strict_meet;
    const bool closed = !strictly_separated<Exact, 2>(a, b) &&
                        common_point<Exact, 2>({{a, false}, {b, false}}).closed_meet;
    ASSERT_EQ((relative_interiors_meet<Exact, 2>(a, b)), rel) << "case " << k;
    ASSERT_EQ((closed_simplices_meet<Exact, 2>(a, b)), closed) << "case " << k;
    (rel ? interiors_meet : (closed ? closed_meet_only : apart))++;
  }
  // The sample exercises all three outcomes, touching (closed only) included.
  EXPECT_GT(interiors_meet, 100);
  EXPECT_GT(closed_meet_only, 100);
  EXPECT_GT(apart, 100);
}

// The closed-form plane barycentric coordinates: Σ μ_i b_i = x and Σ μ_i = 1 exactly, and "not in
// the affine hull" exactly when x is off the segment's line.
TEST(Predicates, PlaneBarycentricCoordinatesReproduceThePoint) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-3, 3);
  const auto point = [&] { return p2(coord(rng), coord(rng)); };
  int on_line = 0, off_line = 0;
  for (int k = 0; k < 2000; ++k) {
    std::vector<P2> b{point(), point()};
    if (k % 2 == 0) b.push_back(point());
    if (!affinely_independent<Exact, 2>(b)) continue;
    const P2 x = point();
    const auto mu = barycentric<Exact, 2>(b, x);
    if (b.size() == 2 && detail::orientation_sign<Exact>(b[0], b[1], x) != 0) {
      EXPECT_FALSE(mu.has_value());
      ++off_line;
      continue;
    }
    ASSERT_TRUE(mu.has_value());
    if (b.size() == 2) ++on_line;
    Exact sum(0), px(0), py(0);
    for (std::size_t i = 0; i < b.size(); ++i) {
      sum += (*mu)[i];
      px += (*mu)[i] * b[i][0];
      py += (*mu)[i] * b[i][1];
    }
    EXPECT_TRUE(sum == 1 && px == x[0] && py == x[1]);
  }
  EXPECT_GT(on_line, 20);
  EXPECT_GT(off_line, 100);
}

// point_in_simplex decides triangles and tetrahedra by orientation signs (no division); the
// barycentric coordinates (all >= 0) are the independent definition it must agree with. Small
// grids make points on edges, faces and vertices frequent.
template <int D>
void expect_point_in_simplex_agrees(std::size_t vertices, unsigned seed, int* inside,
                                    int* on_boundary, int* outside) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-2, 2);
  const auto point = [&] {
    Point<Exact, D> p;
    for (int d = 0; d < D; ++d) p[d] = Exact(coord(rng));
    return p;
  };
  for (int k = 0; k < 3000; ++k) {
    std::vector<Point<Exact, D>> b;
    for (std::size_t i = 0; i < vertices; ++i) b.push_back(point());
    if (!affinely_independent<Exact, D>(b)) continue;
    Point<Exact, D> x = point();
    if (k % 3 == 0) // on an edge (k even) or in the plane of three vertices (k odd), exactly
      for (int d = 0; d < D; ++d) x[d] = (b[0][d] + b[1][d] + (k % 2 ? b[2][d] : b[1][d])) / 3;
    if (k % 3 == 1) { // the centroid: inside
      for (int d = 0; d < D; ++d) {
        x[d] = Exact(0);
        for (const auto& v : b) x[d] += v[d];
        x[d] /= int(b.size());
      }
    }
    const auto mu = barycentric<Exact, D>(b, x);
    bool by_mu = mu.has_value();
    bool zero = false;
    if (mu)
      for (const auto& m : *mu) by_mu = by_mu && m >= 0, zero = zero || m == 0;
    ASSERT_TRUE((detail::point_in_simplex_by_signs<Exact, D>(b, x).has_value()));
    EXPECT_EQ((point_in_simplex<Exact, D>(b, x)), by_mu) << "case " << k;
    (!by_mu ? *outside : zero ? *on_boundary : *inside) += 1;
  }
}

TEST(Predicates, PointInSimplexBySignsAgreesWithBarycentricCoordinates) {
  for (const auto& [d, n] : {std::pair{2, 3}, std::pair{3, 3}, std::pair{3, 4}}) {
    int inside = 0, on_boundary = 0, outside = 0;
    if (d == 2)
      expect_point_in_simplex_agrees<2>(std::size_t(n), 11, &inside, &on_boundary, &outside);
    else
      expect_point_in_simplex_agrees<3>(std::size_t(n), 13 + unsigned(n), &inside, &on_boundary,
                                        &outside);
    EXPECT_GT(inside, 20) << d << "D, " << n << " vertices";
    EXPECT_GT(on_boundary, 20) << d << "D, " << n << " vertices";
    EXPECT_GT(outside, 20) << d << "D, " << n << " vertices";
  }
}

// The plane fast paths for points, segments and triangles against the general decision.
TEST(Predicates, PlaneSimplexPairsAgreeWithTheGeneralDecision) {
  std::mt19937 rng(20261123);
  std::uniform_int_distribution<int> coord(0, 3), size(1, 3);
  const auto random_simplex = [&] {
    for (;;) {
      std::vector<P2> s;
      const int n = size(rng);
      for (int k = 0; k < n; ++k) s.push_back(p2(coord(rng), coord(rng)));
      if (affinely_independent<Exact, 2>(s)) return s;
    }
  };
  int meet = 0, apart = 0;
  for (int k = 0; k < 4000; ++k) {
    const auto a = random_simplex(), b = random_simplex();
    if (a.size() == 3 && b.size() == 3) continue;
    bool general;
    if (a.size() == 1 && b.size() == 1)
      general = a[0] == b[0];
    else if (weakly_separated<Exact, 2>(a, b))
      general = false;
    else
      general = common_point<Exact, 2>({{a, true}, {b, true}}).strict_meet;
    ASSERT_EQ((relative_interiors_meet<Exact, 2>(a, b)), general) << "case " << k;
    (general ? meet : apart)++;
  }
  EXPECT_GT(meet, 100);
  EXPECT_GT(apart, 100);
}

TEST(Predicates, TriangleEdgeLinesOnTouchingTriangles) {
  const std::vector<P2> a{p2(0, 0), p2(2, 0), p2(0, 2)};
  // Shared edge: interiors disjoint, closed sets meet.
  EXPECT_FALSE((relative_interiors_meet<Exact, 2>(a, {p2(2, 0), p2(0, 2), p2(2, 2)})));
  EXPECT_TRUE((closed_simplices_meet<Exact, 2>(a, {p2(2, 0), p2(0, 2), p2(2, 2)})));
  // A vertex of b in the middle of an edge of a, b outside.
  EXPECT_FALSE((relative_interiors_meet<Exact, 2>(a, {p2(1, 1), p2(3, 1), p2(1, 3)})));
  EXPECT_TRUE((closed_simplices_meet<Exact, 2>(a, {p2(1, 1), p2(3, 1), p2(1, 3)})));
  // Nested, and crossing without any vertex inside the other (a star of David).
  EXPECT_TRUE(
      (relative_interiors_meet<Exact, 2>(a, {p2q(1, 4, 1, 4), p2q(1, 2, 1, 4), p2q(1, 4, 1, 2)})));
  EXPECT_TRUE((relative_interiors_meet<Exact, 2>({p2(0, 0), p2(6, 0), p2(3, 6)},
                                                 {p2(0, 4), p2(6, 4), p2(3, -2)})));
  // Apart: a gap beyond the hypotenuse of a.
  EXPECT_FALSE((closed_simplices_meet<Exact, 2>(a, {p2(3, 0), p2(3, 3), p2(1, 3)})));
}

TEST(ElementComplex, SplitSquareIsAMeshAndBoundaryIsFound) {
  const auto m = split_square(Exact(1) / 3, Exact(2) / 3);
  std::ostringstream why;
  EXPECT_TRUE(is_mesh(m, &why)) << why.str();
  const auto b = mesh_boundary(m);
  EXPECT_EQ(b.elements_of_dimension(1).size(), 6u);
  EXPECT_EQ(b.elements_of_dimension(0).size(), 6u);
}

TEST(ElementComplex, DanglingAndNonFaceCompleteAreDetected) {
  auto m = split_square(Exact(1) / 3, Exact(2) / 3);
  m.elements.push_back(Simplex{0, 3}); // the other diagonal: crosses, and has no co-face cell
  m.normalize();
  EXPECT_FALSE(has_no_dangling_elements(m));
  EXPECT_FALSE(is_conforming(m));
  ElementComplex<Exact, 2> t;
  t.points = {p2(0, 0), p2(1, 0), p2(0, 1)};
  t.elements = {Simplex{0, 1, 2}};
  EXPECT_FALSE(is_face_complete(t));
}

TEST(ElementComplex, CoveredByIsExact) {
  const auto m = split_square(Exact(1) / 3, Exact(2) / 3);
  EXPECT_TRUE((simplex_covered_by<Exact, 2>({p2(0, 0), p2(1, 1)}, m)));
  EXPECT_TRUE((simplex_covered_by<Exact, 2>({p2(0, 0), p2(1, 0), p2(1, 1)}, m)));
  EXPECT_FALSE((simplex_covered_by<Exact, 2>({p2(0, 0), p2(2, 0)}, m)));
  EXPECT_FALSE((simplex_covered_by<Exact, 2>({p2(0, 0), p2(2, 0), p2(0, 1)}, m)));
  EXPECT_TRUE((simplex_covered_by<Exact, 2>({p2q(1, 2, 0, 1)}, m)));
}

TEST(TemplatedStructure, ReflectionGivesATemplatedMesh) {
  // Template on x >= 0 touching x = 0 along a split edge; instances I and refl about x = 0.
  const auto m = complex2({p2(0, 0), p2(0, 1), p2(0, 2), p2(1, 0), p2(1, 2)},
                          {{0, 1, 3}, {1, 3, 4}, {1, 2, 4}});
  const auto x = one_template(m, {T2(), T2::reflection(p2(1, 0), Exact(0))});
  const auto r = analyse(x);
  EXPECT_TRUE(r.templated_structure);
  EXPECT_TRUE(r.templated_mesh);
  EXPECT_TRUE(r.lemma42.holds);
  EXPECT_EQ(r.graph_edges.size(), 2u); // trivial loop + the self-interface
}

TEST(TemplatedStructure, TranslationWithMismatchedSplitsFailsLemma42) {
  // Fig. 4.4: bottom edge split at 1/3, top edge at 2/3; stacking by translation (0, 1).
  const auto m = split_square(Exact(1) / 3, Exact(2) / 3);
  const auto x = one_template(m, {T2(), T2::translation(p2(0, 1))});
  const auto r = analyse(x);
  EXPECT_TRUE(r.templated_structure);
  EXPECT_FALSE(r.templated_mesh);
  EXPECT_FALSE(r.lemma42.holds);
  EXPECT_EQ(r.lemma42.condition, 1);
  EXPECT_TRUE(r.lemma42_agrees);
  // Matching splits conform.
  const auto ok = analyse(
      one_template(split_square(Exact(1) / 3, Exact(1) / 3), {T2(), T2::translation(p2(0, 1))}));
  EXPECT_TRUE(ok.templated_mesh);
  EXPECT_TRUE(ok.lemma42.holds);
}

TEST(TemplatedStructure, OverlapViolatesEq42) {
  const auto m = split_square(Exact(1) / 3, Exact(1) / 3);
  const auto r = analyse(one_template(m, {T2(), T2::translation(p2q(1, 2, 0, 1))}));
  EXPECT_FALSE(r.templated_structure);
  ASSERT_TRUE(r.overlap.has_value());
}

TEST(Delaunay, SquareDiagonalIsDelaunayButNotStrongly) {
  // Four cocircular points: both diagonals are Delaunay, neither strongly Delaunay.
  const auto m = complex2({p2(0, 0), p2(1, 0), p2(1, 1), p2(0, 1)}, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_TRUE(is_delaunay_mesh(m));
  EXPECT_TRUE(is_locally_delaunay_in(m, Simplex{0, 2}));
  EXPECT_FALSE(is_strongly_delaunay_in(m, Simplex{0, 2}));
  // A flat quadrilateral with the long diagonal is not Delaunay.
  const auto bad = complex2({p2(0, 0), p2(2, -1), p2(4, 0), p2(2, 1)}, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_FALSE(is_delaunay_mesh(bad));
  EXPECT_FALSE(is_locally_delaunay_in(bad, Simplex{0, 2}));
}

TEST(Respect, TriangleAndCuttingLine) {
  const std::vector<P2> tri{p2(0, 0), p2(4, 0), p2(0, 4)};
  EXPECT_TRUE((respects<Exact, 2>(tri, {tri})));
  EXPECT_FALSE((respects<Exact, 2>(tri, {{p2(1, -1), p2(1, 5)}})));
  EXPECT_TRUE((respects<Exact, 2>(tri, {{p2(-1, 0), p2(5, 0)}}))); // along an edge
}

#include "symmesh/core/geometry_conforming.h"
#include "symmesh/core/restricted_transformation.h"

TEST(GeometryConformity, RefinedSquareConformsToCoarseSquare) {
  const auto fine = split_square(Exact(1) / 3, Exact(2) / 3);
  const auto coarse = complex2({p2(0, 0), p2(1, 0), p2(1, 1), p2(0, 1)}, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_TRUE(geometry_conforms(fine, coarse));
  const auto half = complex2({p2(0, 0), p2(1, 0), p2(1, 1)}, {{0, 1, 2}});
  EXPECT_FALSE(geometry_conforms(fine, half));
}

TEST(GeometryConformity, TemplatedMeshOfTemplatedGeometry) {
  const auto fine = split_square(Exact(1) / 3, Exact(1) / 3);
  const auto coarse = complex2({p2(0, 0), p2(1, 0), p2(1, 1), p2(0, 1)}, {{0, 1, 2}, {0, 2, 3}});
  auto gamma = one_template(fine, {T2(), T2::translation(p2(0, 1))});
  auto lambda = one_template(coarse, {T2(), T2::translation(p2(0, 1))});
  lambda.templates[0].kind = TemplateKind::geometry;
  EXPECT_TRUE(is_geometry_conforming(gamma, lambda));
  lambda.instances[0][1].region = 2;
  EXPECT_FALSE(is_geometry_conforming(gamma, lambda));
}

TEST(RestrictedTransformation, AgreementOnADomain) {
  // The reflection about x = 0 and the identity agree exactly on the segment x = 0.
  ElementComplex<Exact, 2> seg;
  seg.points = {p2(0, 0), p2(0, 1)};
  seg.elements = {Simplex{0}, Simplex{1}, Simplex{0, 1}};
  const auto r = T2::reflection(p2(1, 0), Exact(0));
  EXPECT_TRUE(agree_on(r, T2(), seg));
  seg.points[1] = p2(1, 1);
  EXPECT_FALSE(agree_on(r, T2(), seg));
  RestrictedTransformation<Exact, 2> f{T2::translation(p2(2, 0)), seg};
  EXPECT_EQ(f(p2q(1, 2, 1, 2)), p2q(5, 2, 1, 2));
  EXPECT_THROW(f(p2(5, 5)), std::domain_error);
  EXPECT_EQ(f.inverse()(p2q(5, 2, 1, 2)), p2q(1, 2, 1, 2));
}

#include <random>

namespace {
/// Random simplices on a tiny integer grid, so that shared, collinear and coplanar vertices
/// are frequent; fixed seed.
template <int D>
std::vector<Point<Exact, D>> random_simplex(std::mt19937& rng) {
  std::uniform_int_distribution<int> coord(0, 2), count(1, D + 1);
  for (;;) {
    std::vector<Point<Exact, D>> s(count(rng));
    for (auto& p : s)
      for (int d = 0; d < D; ++d) p[d] = Exact(coord(rng));
    if (affinely_independent<Exact, D>(s)) return s;
  }
}

template <int D>
void separation_filters_agree_with_lp() {
  std::mt19937 rng(20261122);
  int separated = 0, meeting = 0, by_axis = 0;
  for (int k = 0; k < 1500; ++k) {
    const auto a = random_simplex<D>(rng), b = random_simplex<D>(rng);
    const auto lp = common_point<Exact, D>({{a, true}, {b, true}});
    if (detail::axis_projections_separate<Exact, D>(a, b)) {
      ++by_axis;
      ASSERT_FALSE(lp.strict_meet) << "disjoint axis projections claimed for meeting interiors";
    }
    if (weakly_separated<Exact, D>(a, b)) {
      ++separated;
      ASSERT_FALSE(lp.strict_meet) << "weak separation claimed for meeting relative interiors";
    }
    if (strictly_separated<Exact, D>(a, b)) {
      ASSERT_FALSE(lp.closed_meet) << "strict separation claimed for meeting simplices";
    }
    meeting += lp.strict_meet;
  }
  EXPECT_GT(separated, 100); // the filter does real work
  EXPECT_GT(by_axis, 100);   // and so do the axis projections
  EXPECT_GT(meeting, 100);   // and the sample has both outcomes
}
} // namespace

// A simplex's relative interior projects to the open interval between its extreme coordinates,
// or to the one coordinate of a flat direction: a flat triangle through a tetrahedron's interior
// is not told apart (its z-projection is the point 1, inside (0, 3)), while two tetrahedra on
// either side of the plane x = 1 are.
TEST(Predicates, AxisProjectionsOfRelativeInteriors) {
  const std::vector<P3> tet{p3(0, 0, 0), p3(3, 0, 0), p3(0, 3, 0), p3(0, 0, 3)};
  const std::vector<P3> flat{p3(-1, -1, 1), p3(2, 0, 1), p3(0, 2, 1)};
  EXPECT_FALSE((detail::axis_projections_separate<Exact, 3>(tet, flat)));
  EXPECT_TRUE((relative_interiors_meet<Exact, 3>(tet, flat)));
  const std::vector<P3> left{p3(0, 0, 0), p3(1, 0, 0), p3(1, 1, 0), p3(1, 1, 1)};
  const std::vector<P3> right{p3(1, 0, 0), p3(2, 0, 0), p3(1, 1, 0), p3(1, 1, 1)};
  EXPECT_TRUE((detail::axis_projections_separate<Exact, 3>(left, right)));
  EXPECT_FALSE((relative_interiors_meet<Exact, 3>(left, right)));
  // A point on the boundary of the other's box is outside its relative interior's projection.
  EXPECT_TRUE((detail::axis_projections_separate<Exact, 3>({p3(1, 1, 1)}, left)));
}

TEST(Predicates, SeparationFiltersNeverContradictTheExactLP2D) {
  separation_filters_agree_with_lp<2>();
}
TEST(Predicates, SeparationFiltersNeverContradictTheExactLP3D) {
  separation_filters_agree_with_lp<3>();
}

namespace {
/// The interval filter of the candidate planes (spec/number-type.md, "Candidate planes discarded
/// on intervals") may only discard a plane that the exact side signs reject in both
/// orientations. Coordinates in thirds, so that the enclosures are proper intervals and points on
/// a plane give signs the intervals cannot decide.
template <int D>
void interval_filter_discards_only_rejected_planes() {
  std::mt19937 rng(20261127);
  int discarded = 0, kept_certifying = 0;
  for (int k = 0; k < 400; ++k) {
    auto a = random_simplex<D>(rng), b = random_simplex<D>(rng);
    for (auto* s : {&a, &b})
      for (auto& p : *s)
        for (int d = 0; d < D; ++d) p[d] = p[d] / 3;
    const auto pts = detail::candidate_points<Exact, D>(a, b);
    const auto ipts = detail::enclosures<Exact, D>(pts);
    const auto ia = detail::enclosures<Exact, D>(a), ib = detail::enclosures<Exact, D>(b);
    detail::for_each_candidate<D>(pts.size(), [&](const detail::CandidatePlane& c) {
      const auto n = detail::candidate_normal<Exact, D>(pts, c);
      const auto fa = detail::side_flags<Exact, D>(a, pts[c.i], n);
      const auto fb = detail::side_flags<Exact, D>(b, pts[c.i], n);
      const bool certifies = (!fa[2] && !fb[0]) || (!fa[0] && !fb[2]);
      const auto in = detail::candidate_normal<detail::Enclosure, D>(ipts, c);
      if (detail::certainly_not_separating<D>(ia, ib, ipts[c.i], in)) {
        ++discarded;
        EXPECT_FALSE(certifies) << "the filter discarded a plane with a and b on opposite sides";
      } else {
        kept_certifying += certifies;
      }
      return false;
    });
  }
  EXPECT_GT(discarded, 1000);     // the filter does real work
  EXPECT_GT(kept_certifying, 50); // and the planes that certify are kept
}
} // namespace

TEST(Predicates, IntervalFilterDiscardsOnlyPlanesTheExactTestRejects2D) {
  interval_filter_discards_only_rejected_planes<2>();
}
TEST(Predicates, IntervalFilterDiscardsOnlyPlanesTheExactTestRejects3D) {
  interval_filter_discards_only_rejected_planes<3>();
}

// The conformity check of a mesh (find_nonconformity) meets mostly neighbours: elements that share
// vertices but are not faces of one another. For those the candidate planes must certify the
// separation on their own — through the shared points, which weakly_separated tries first — so
// that the exact LP is left to the rare pairs the candidates miss. Checked on the Kuhn
// tetrahedralization of a 2x2x2 grid of unit cubes (6 tetrahedra per cube along the diagonal),
// every pair of its face completion that shares a vertex.
// Also with spacing 1/3, whose coordinates have proper enclosures: the interval filter must
// keep the planes through the shared points.
static void separation_certifies_every_neighbour_pair(const Exact& spacing) {
  ElementComplex<Exact, 3> m;
  const auto id = [](int x, int y, int z) { return VertexId(x + 3 * y + 9 * z); };
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x)
        m.points.push_back(P3{{Exact(x) * spacing, Exact(y) * spacing, Exact(z) * spacing}});
  std::array<int, 3> perm{0, 1, 2};
  for (int cube = 0; cube < 8; ++cube) {
    std::sort(perm.begin(), perm.end());
    do {
      std::array<int, 3> c{cube % 2, (cube / 2) % 2, cube / 4};
      std::vector<VertexId> v{id(c[0], c[1], c[2])};
      for (int k : perm) {
        ++c[k];
        v.push_back(id(c[0], c[1], c[2]));
      }
      m.elements.push_back(Simplex::from_range(v.data(), v.data() + v.size()));
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
  const auto fc = face_completion(m);
  ASSERT_EQ(m.elements.size(), 48u);
  ASSERT_TRUE(is_conforming(fc));
  int neighbours = 0;
  for (std::size_t i = 0; i < fc.elements.size(); ++i)
    for (std::size_t j = i + 1; j < fc.elements.size(); ++j) {
      const Simplex &a = fc.elements[i], &b = fc.elements[j];
      if (a.is_face_of(b) || b.is_face_of(a)) continue;
      bool share = false;
      for (VertexId u : a)
        for (VertexId w : b) share = share || u == w;
      if (!share) continue;
      ++neighbours;
      ASSERT_TRUE((weakly_separated<Exact, 3>(fc.coords(a), fc.coords(b))))
          << "neighbours " << i << " and " << j << " left to the LP";
    }
  EXPECT_GT(neighbours, 1000); // the pairs of the check, not a handful
}

TEST(Predicates, SeparationCertifiesEveryNeighbourPairOfAConformingMesh) {
  separation_certifies_every_neighbour_pair(Exact(1));
  separation_certifies_every_neighbour_pair(Exact(1) / 3);
}

// Eq. 4.2 up to the rotation (spec/lemmas.md#lemma-4-2-rotational): with two templates instanced
// by the quarter turns, deciding copy 0 against copies k <= n/2 finds the same overlaps as all
// pairs — including an overlap that only the pair ((1,0), (2,3)), k = 3 > n/2, shows directly
// (it is found as ((2,0), (1,1)) instead).
TEST(FindInstanceOverlap, UpToTheRotationAgreesWithAllPairs) {
  const auto quarter = [](int k) {
    static const int c[] = {1, 0, -1, 0}, s[] = {0, 1, 0, -1};
    return T2::rotation_2d(Exact(c[k % 4]), Exact(s[k % 4]), p2(0, 0));
  };
  const auto structure = [&](std::vector<P2> a, std::vector<P2> b) {
    TemplatedStructure<Exact, 2> x;
    for (auto* pts : {&a, &b}) {
      x.templates.push_back({"t", TemplateKind::geometry, complex2(*pts, {Simplex{0, 1, 2}})});
      x.instances.emplace_back();
      for (int k = 0; k < 4; ++k) x.instances.back().push_back({quarter(k), 1});
    }
    return x;
  };
  // The first quadrant as two triangles (0°–45°, 45°–90°), turned four times: no overlap.
  const auto apart = structure({p2(0, 0), p2(1, 0), p2(1, 1)}, {p2(0, 0), p2(1, 1), p2(0, 1)});
  EXPECT_FALSE(find_instance_overlap(apart).has_value());
  EXPECT_FALSE(find_instance_overlap(apart, 4).has_value());
  // Template 2 = template 1 turned once: instance (2, 3) = (1, 0).
  const auto twice = structure({p2(0, 0), p2(1, 0), p2(0, 1)}, {p2(0, 0), p2(0, 1), p2(-1, 0)});
  EXPECT_TRUE(find_instance_overlap(twice).has_value());
  EXPECT_TRUE(find_instance_overlap(twice, 4).has_value());
}

// ---------------------------------------------------------------------------------------------
// Definition 2.5 (mesh partition), 2.6 (ξ on faces, Eq. 2.4), 2.7 (region interface, Eq. 2.5) on
// two unit squares side by side, each split by a diagonal, one region per square.

namespace {
MultiRegionMesh<Exact, 2> two_square_regions() {
  MultiRegionMesh<Exact, 2> mr;
  ElementComplex<Exact, 2> cells;
  cells.points = {p2(0, 0), p2(1, 0), p2(2, 0), p2(0, 1), p2(1, 1), p2(2, 1)};
  cells.elements = {Simplex{0, 1, 4}, Simplex{0, 4, 3}, Simplex{1, 2, 5}, Simplex{1, 5, 4}};
  mr.mesh = face_completion(cells);
  mr.mesh.normalize();
  mr.cell_region = {
      {Simplex{0, 1, 4}, 1}, {Simplex{0, 3, 4}, 1}, {Simplex{1, 2, 5}, 2}, {Simplex{1, 4, 5}, 2}};
  return mr;
}
} // namespace

TEST(MultiRegionMesh, XiRegionsAndRegionInterface) {
  const auto mr = two_square_regions();
  std::ostringstream why;
  EXPECT_TRUE(mr.is_valid(&why)) << why.str();
  // Eq. 2.4: ξ of a face is the union over its co-face cells.
  EXPECT_EQ(mr.xi(Simplex{1, 4}), (std::set<int>{1, 2}));
  EXPECT_EQ(mr.xi(Simplex{0}), (std::set<int>{1}));
  EXPECT_EQ(mr.xi(Simplex{2, 5}), (std::set<int>{2}));
  // A region is the face completion of its cells (Lemma 2.2: a mesh).
  EXPECT_EQ(mr.region(1).cells().size(), 2u);
  EXPECT_TRUE(is_mesh(mr.region(2)));
  // Eq. 2.5: the interface of regions 1 and 2 is the common edge with its two vertices.
  const auto interf = mr.region_interface({1, 2});
  std::vector<Simplex> expected{Simplex{1}, Simplex{4}, Simplex{1, 4}};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(interf.elements, expected);
  EXPECT_EQ(mr.region_interface({1}).elements, mr.region(1).elements);
}

TEST(MultiRegionMesh, MeshPartitionAndItsFailures) {
  const auto mr = two_square_regions();
  std::ostringstream why;
  EXPECT_TRUE(is_mesh_partition(mr.mesh, {mr.region(1), mr.region(2)}, &why)) << why.str();
  // The parts must cover the mesh exactly ...
  why.str("");
  EXPECT_FALSE(is_mesh_partition(mr.mesh, {mr.region(1)}, &why));
  EXPECT_NE(why.str().find("do not cover"), std::string::npos) << why.str();
  // ... share no cell ...
  why.str("");
  EXPECT_FALSE(is_mesh_partition(mr.mesh, {mr.mesh, mr.region(2)}, &why));
  EXPECT_NE(why.str().find("share a cell"), std::string::npos) << why.str();
  // ... and be meshes (face-complete).
  auto cells_only = mr.region(1);
  cells_only.elements = cells_only.cells();
  EXPECT_FALSE(is_mesh_partition(mr.mesh, {cells_only, mr.region(2)}));
}

TEST(GeometryConformity, MultiRegionMeshesMustMatchRegionByRegion) {
  // Def 2.10 with regions: the two split squares against the same rectangle carried by two
  // cells per square the other way round (other diagonals), regions by square.
  const auto mesh = two_square_regions();
  MultiRegionMesh<Exact, 2> geometry;
  ElementComplex<Exact, 2> cells;
  cells.points = mesh.mesh.points;
  cells.elements = {Simplex{0, 1, 3}, Simplex{1, 4, 3}, Simplex{1, 2, 4}, Simplex{2, 5, 4}};
  geometry.mesh = face_completion(cells);
  geometry.mesh.normalize();
  geometry.cell_region = {
      {Simplex{0, 1, 3}, 1}, {Simplex{1, 3, 4}, 1}, {Simplex{1, 2, 4}, 2}, {Simplex{2, 4, 5}, 2}};
  EXPECT_TRUE(geometry_conforms(mesh, geometry));
  // Same underlying space, regions swapped: us(M) = G still, but the regions do not match.
  EXPECT_TRUE(geometry_conforms(mesh.mesh, geometry.mesh));
  auto swapped = geometry;
  for (auto& [c, r] : swapped.cell_region) r = 3 - r;
  EXPECT_FALSE(geometry_conforms(mesh, swapped));
  // Other region ids altogether.
  auto renamed = geometry;
  for (auto& [c, r] : renamed.cell_region) r += 10;
  EXPECT_FALSE(geometry_conforms(mesh, renamed));
}
