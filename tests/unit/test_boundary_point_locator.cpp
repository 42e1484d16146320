// The SVB's copy identifications look template points up by certified interval boxes before an
// exact comparison (gen/shared_vertex_bookkeeping.h, spec/generation.md#reflective-3d):
// BoundaryPointLocator must find exactly the points an exact ordered map finds — for probes equal
// to a stored point, for probes that miss, and for points on the grid's cell boundaries.
#include <gtest/gtest.h>

#include "symmesh/core/kernel.h"
#include "symmesh/gen/shared_vertex_bookkeeping.h"

#include <map>
#include <random>
#include <vector>

using symmesh::Exact;
using P = symmesh::core::Point<Exact, 3>;

namespace {

/// Both answers for probe q: the locator's (by box and by point) and the exact map's.
void expect_same_answer(const symmesh::gen::support::BoundaryPointLocator<Exact, 3>& locator,
                        const std::map<P, std::size_t, symmesh::core::PointLess<Exact, 3>>& exact,
                        const P& q) {
  const auto it = exact.find(q);
  const auto found = locator.find(q);
  ASSERT_EQ(found.has_value(), it != exact.end());
  if (found) {
    EXPECT_EQ(*found, it->second);
  }
  typename symmesh::gen::support::BoundaryPointLocator<Exact, 3>::Box box;
  for (int d = 0; d < 3; ++d) box[std::size_t(d)] = CGAL::to_interval(q[d]);
  int built = 0;
  const auto by_box = locator.find(box, [&] {
    ++built;
    return q;
  });
  EXPECT_EQ(by_box, found);
  EXPECT_LE(built, 1); // the exact probe is built at most once
}

} // namespace

TEST(BoundaryPointLocator, FindsWhatTheExactMapFinds) {
  std::mt19937 rng(20261201);
  std::uniform_int_distribution<int> num(-60, 60), den(1, 9);
  std::vector<P> pts;
  // Random rationals, and points on multiples of the grid's cell (2^-20 of the extent 8).
  for (int k = 0; k < 400; ++k)
    pts.push_back(
        P{{Exact(num(rng)) / den(rng), Exact(num(rng)) / den(rng), Exact(num(rng)) / den(rng)}});
  for (int k = 0; k < 50; ++k)
    pts.push_back(
        P{{Exact(k) * Exact(8) / Exact(1 << 20), Exact(-k) * Exact(8) / Exact(1 << 20), Exact(8)}});
  std::map<P, std::size_t, symmesh::core::PointLess<Exact, 3>> exact;
  std::vector<P> unique;
  for (const auto& p : pts)
    if (exact.emplace(p, unique.size()).second) unique.push_back(p);
  const symmesh::gen::support::BoundaryPointLocator<Exact, 3> locator(unique);
  for (const auto& p : unique) expect_same_answer(locator, exact, p);
  // Probes that miss: shifted by a third of a cell, or by one unit in the 40th binary place.
  for (const auto& p : unique) {
    expect_same_answer(locator, exact, P{{p[0] + Exact(8) / Exact(3 << 20), p[1], p[2]}});
    expect_same_answer(locator, exact, P{{p[0], p[1], p[2] + Exact(1) / Exact(double(1LL << 40))}});
  }
  // Images under a signed permutation that maps the set partly onto itself (x <-> -x).
  for (const auto& p : unique) expect_same_answer(locator, exact, P{{-p[0], p[1], p[2]}});
}
