// Tie-breaking of the surface meshes (gen/surface_meshes_3d.h canonical_ties,
// spec/generation.md#surface-meshes): every pair of triangles whose four points lie on one circle
// gets the diagonal through the lexicographically smallest of them, so that the side faces of a
// thin column, each a strip of rectangles, are split by one order of the column's edges and
// never wind around it (a Schönhardt-like twist, which TetGen can fill only with an interior
// point and flat cells). The dropped hypothesis: a quad that is no tie keeps its diagonal.
#include <gtest/gtest.h>

#include "symmesh/core/kernel.h"
#include "symmesh/gen/surface_meshes_3d.h"

#include <set>
#include <vector>

using namespace symmesh;
using symmesh::Exact;
using P = core::Point<Exact, 3>;

namespace {

/// A vertical strip face in the plane y = y0 from x = 0 to x = w, z = 0 .. levels−1: points
/// (0, z) then (w, z); each rectangle split by the diagonal from its lower right corner
/// to its upper left one (not through its smallest point, the lower left), or, with \p skew, the
/// right side shifted up by a quarter, so that no quad is a tie.
gen::surface3::FacetMesh<Exact> strip(std::size_t levels, const Exact& w, bool skew,
                                      std::vector<P>& exact,
                                      std::vector<std::array<double, 2>>& q) {
  gen::surface3::FacetMesh<Exact> m;
  const Exact lift = skew ? Exact(1) / 4 : Exact(0);
  for (std::size_t side = 0; side < 2; ++side)
    for (std::size_t k = 0; k < levels; ++k) {
      const Exact x = side == 0 ? Exact(0) : w, z = Exact(int(k)) + (side == 0 ? Exact(0) : lift);
      m.boundary_ids.push_back(exact.size());
      exact.push_back(P{{x, Exact(3), z}});
      q.push_back({CGAL::to_double(x), CGAL::to_double(z)});
    }
  const auto left = [](std::size_t k) { return k; };
  const auto right = [&](std::size_t k) { return levels + k; };
  for (std::size_t k = 0; k + 1 < levels; ++k) {
    // counter-clockwise in (x, z), sharing the diagonal from right k to left k+1
    m.triangles.push_back({left(k), right(k), left(k + 1)});
    m.triangles.push_back({right(k), right(k + 1), left(k + 1)});
  }
  return m;
}

std::set<std::array<std::size_t, 2>> diagonals(const gen::surface3::FacetMesh<Exact>& m,
                                               std::size_t levels) {
  std::set<std::array<std::size_t, 2>> out;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) {
      std::size_t a = t[std::size_t(i)], b = t[std::size_t((i + 1) % 3)];
      if (a > b) std::swap(a, b);
      if (a < levels && b >= levels && b - levels != a) out.insert({a, b});
    }
  return out;
}

} // namespace

TEST(CanonicalTies, RectangleStripDiagonalsRunThroughTheSmallestPoint) {
  const std::size_t levels = 6;
  std::vector<P> exact;
  std::vector<std::array<double, 2>> q;
  auto m = strip(levels, Exact(1) / 20, false, exact, q);
  // Before: each rectangle's diagonal joins right k and left k+1, neither its smallest point
  // (left k: x = 0, then the lower z).
  for (std::size_t k = 0; k + 1 < levels; ++k)
    ASSERT_TRUE(diagonals(m, levels).count({k + 1, levels + k}));
  gen::surface3::canonical_ties(m, exact, q);
  const auto after = diagonals(m, levels);
  ASSERT_EQ(after.size(), levels - 1);
  for (std::size_t k = 0; k + 1 < levels; ++k)
    EXPECT_TRUE(after.count({k, levels + k + 1})) << "rectangle " << k;
  // Still a triangulation of the strip of the same orientation: every triangle counter-clockwise.
  for (const auto& t : m.triangles) {
    const auto &a = q[t[0]], &b = q[t[1]], &c = q[t[2]];
    EXPECT_GT((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]), 0);
  }
}

TEST(CanonicalTies, NoTieKeepsItsDiagonal) {
  const std::size_t levels = 6;
  std::vector<P> exact;
  std::vector<std::array<double, 2>> q;
  auto m = strip(levels, Exact(1) / 20, true, exact, q);
  const auto before = m.triangles;
  gen::surface3::canonical_ties(m, exact, q);
  EXPECT_EQ(m.triangles, before);
}
