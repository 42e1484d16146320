// Symmetric surface meshes (spec/generation.md#symmetric-surface-meshes): for a face and a group
// G of its isometries, face_group closes the generators, and symmetric_facet_mesh returns a
// triangulation of the face that every element of G maps onto itself — checked here exactly, as
// sets of triangles of exact points, independently of how the mesh was built — and that covers
// the face (exact area).
#include <gtest/gtest.h>

#include "symmesh/core/kernel.h"
#include "symmesh/gen/symmetric_surface_mesh.h"

#include <gmpxx.h>

#include <set>

using namespace symmesh;
using FT = Exact;
using P = gen::symmetric::P3<FT>;
using Map = gen::symmetric::Map3<FT>;
using Triangle = std::array<P, 3>;

namespace {

P point(const FT& x, const FT& y) {
  P p;
  p[0] = x;
  p[1] = y;
  p[2] = FT(0);
  return p;
}

FT fraction(int a, int b) {
  return FT(a) / FT(b);
}

/// A polygon face in the plane z = 0: its rings (each a closed list of corners) split into
/// `parts[k]` equal parts per edge of ring k.
struct Face {
  std::vector<P> points;
  std::vector<gen::symmetric::Segment> segments;
};

Face face(const std::vector<std::vector<P>>& rings, int parts) {
  Face f;
  for (const auto& ring : rings) {
    const std::size_t first = f.points.size();
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const P& a = ring[k];
      const P& b = ring[(k + 1) % ring.size()];
      for (int i = 0; i < parts; ++i)
        f.points.push_back(a + core::scaled<FT, 3>(b - a, fraction(i, parts)));
    }
    for (std::size_t k = first; k < f.points.size(); ++k)
      f.segments.push_back({k, k + 1 < f.points.size() ? k + 1 : first});
  }
  return f;
}

/// Rotation by 90° about (cx, cy) in the plane z = 0.
Map quarter_turn(const FT& cx, const FT& cy) {
  typename Map::Mat a{};
  a[0] = {FT(0), FT(-1), FT(0)};
  a[1] = {FT(1), FT(0), FT(0)};
  a[2] = {FT(0), FT(0), FT(1)};
  P b;
  b[0] = cx + cy;
  b[1] = cy - cx;
  b[2] = FT(0);
  return Map::from_matrix(a, b);
}

Map half_turn(const FT& cx, const FT& cy) {
  return quarter_turn(cx, cy) * quarter_turn(cx, cy);
}

Map mirror_x(const FT& x) { // the mirror line x = const
  P n;
  n[0] = FT(1);
  n[1] = FT(0);
  n[2] = FT(0);
  return Map::reflection(n, x);
}

P up() {
  P n;
  n[0] = FT(0);
  n[1] = FT(0);
  n[2] = FT(1);
  return n;
}

struct Result {
  std::vector<P> all;
  std::vector<std::array<std::size_t, 3>> triangles;
};

Result mesh_face(const Face& f, const gen::symmetric::FaceGroup<FT>& g, double size) {
  gen::MeshingParameters p;
  p.size = size;
  p.min_angle_deg = 25;
  auto m = gen::symmetric::symmetric_facet_mesh<FT>(
      g, up(), f.points, f.segments,
      [](const P& q) {
        return std::array<double, 2>{CGAL::to_double(q[0]), CGAL::to_double(q[1])};
      },
      [](const std::array<double, 2>& q) {
        return point(FT(mpq_class(q[0])), FT(mpq_class(q[1])));
      },
      [size](const P& a, const P& b) {
        const double l = std::sqrt(CGAL::to_double(core::dot<FT, 3>(b - a, b - a)));
        return std::max<std::size_t>(1, std::size_t(std::ceil(l / size)));
      },
      p, "test face");
  Result r;
  r.all = f.points;
  r.all.insert(r.all.end(), m.interior.begin(), m.interior.end());
  r.triangles = m.triangles;
  return r;
}

std::set<Triangle, std::less<>> triangle_set(const std::vector<Triangle>& list) {
  std::set<Triangle, std::less<>> s;
  for (auto t : list) {
    std::sort(t.begin(), t.end(), core::PointLess<FT, 3>());
    s.insert(t);
  }
  return s;
}

/// Every element maps the triangle set onto itself; the triangles cover `area` exactly.
void expect_invariant(const Result& r, const gen::symmetric::FaceGroup<FT>& g, const FT& area) {
  std::vector<Triangle> tris;
  FT sum(0);
  for (const auto& c : r.triangles) {
    tris.push_back({r.all[c[0]], r.all[c[1]], r.all[c[2]]});
    const auto& a = r.all[c[0]];
    const auto& b = r.all[c[1]];
    const auto& d = r.all[c[2]];
    const FT twice = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    EXPECT_NE(twice, FT(0));
    sum += twice < FT(0) ? -twice : twice;
  }
  EXPECT_EQ(sum, FT(2) * area);
  EXPECT_EQ(r.triangles.size() % g.order(), 0u);
  const auto original = triangle_set(tris);
  EXPECT_EQ(original.size(), tris.size());
  for (const auto& e : g.elements) {
    std::vector<Triangle> image;
    for (const auto& t : tris) image.push_back({e(t[0]), e(t[1]), e(t[2])});
    EXPECT_TRUE(triangle_set(image) == original);
  }
}

std::vector<P> square(const FT& lo, const FT& hi) {
  return {point(lo, lo), point(hi, lo), point(hi, hi), point(lo, hi)};
}

std::vector<P> corners(const std::vector<P>& ring) {
  return ring;
}

} // namespace

TEST(SymmetricSurfaceMesh, FaceGroupClosesGenerators) {
  const auto c = corners(square(FT(0), FT(1)));
  const FT h = fraction(1, 2);
  EXPECT_EQ(gen::symmetric::face_group<FT>(c, {quarter_turn(h, h)}).order(), 4u);
  const auto d4 = gen::symmetric::face_group<FT>(c, {quarter_turn(h, h), mirror_x(h)});
  EXPECT_EQ(d4.order(), 8u);
  EXPECT_EQ(std::count(d4.reflection.begin(), d4.reflection.end(), true), 4);
  std::ostringstream why;
  EXPECT_TRUE(d4.is_valid(&why)) << why.str();
  // A map that does not send the face onto itself is a caller's bug.
  EXPECT_THROW(gen::symmetric::face_group<FT>(c, {quarter_turn(FT(0), FT(0))}), std::logic_error);
}

TEST(SymmetricSurfaceMesh, CyclicGroupWithCentreInsideTheFace) {
  const FT h = fraction(1, 2);
  const auto f = face({square(FT(0), FT(1))}, 5);
  const auto g =
      gen::symmetric::face_group<FT>(corners(square(FT(0), FT(1))), {quarter_turn(h, h)});
  const auto r = mesh_face(f, g, 0.15);
  expect_invariant(r, g, FT(1));
  // The check can fail: the C_4 mesh is not also invariant under the mirror x = 1/2.
  std::vector<Triangle> tris, mirrored;
  for (const auto& c : r.triangles) {
    tris.push_back({r.all[c[0]], r.all[c[1]], r.all[c[2]]});
    mirrored.push_back(
        {mirror_x(h)(r.all[c[0]]), mirror_x(h)(r.all[c[1]]), mirror_x(h)(r.all[c[2]])});
  }
  EXPECT_FALSE(triangle_set(tris) == triangle_set(mirrored));
  const auto g2 = gen::symmetric::face_group<FT>(corners(square(FT(0), FT(1))), {half_turn(h, h)});
  expect_invariant(mesh_face(f, g2, 0.15), g2, FT(1));
}

TEST(SymmetricSurfaceMesh, DihedralGroupsCutAlongTheMirrors) {
  const FT h = fraction(1, 2);
  // The mirrors x = 1/2 and y = 1/2 meet the boundary at edge midpoints: even line meshes.
  const auto f = face({square(FT(0), FT(1))}, 4);
  const auto d4 = gen::symmetric::face_group<FT>(corners(square(FT(0), FT(1))),
                                                 {quarter_turn(h, h), mirror_x(h)});
  expect_invariant(mesh_face(f, d4, 0.15), d4, FT(1));
  const auto d1 = gen::symmetric::face_group<FT>(corners(square(FT(0), FT(1))), {mirror_x(h)});
  expect_invariant(mesh_face(f, d1, 0.15), d1, FT(1));
  // With an odd line mesh the mirror crosses a segment: the caller must make it even.
  const auto odd = face({square(FT(0), FT(1))}, 3);
  EXPECT_THROW(mesh_face(odd, d1, 0.15), std::logic_error);
}

TEST(SymmetricSurfaceMesh, CyclicGroupWithCentreInAHole) {
  const FT h = fraction(1, 2);
  const auto f = face({square(FT(-1), FT(2)), square(FT(0), FT(1))}, 4);
  const auto g =
      gen::symmetric::face_group<FT>(corners(square(FT(-1), FT(2))), {quarter_turn(h, h)});
  expect_invariant(mesh_face(f, g, 0.2), g, FT(8));
  // The dihedral group of the same annulus: mirrors cut it into eight pieces.
  const auto d4 = gen::symmetric::face_group<FT>(corners(square(FT(-1), FT(2))),
                                                 {quarter_turn(h, h), mirror_x(h)});
  expect_invariant(mesh_face(f, d4, 0.2), d4, FT(8));
}
