// Rounding of surface-mesh points stored in face coordinates (gen/surface_meshes_3d.h,
// spec/number-type.md#double-double): nearest_on_plane must give the double nearest to the exact
// value p0 + s·u + t·v — what rounding the exact K_m value gives — whenever it decides, decide
// almost always, and refuse a value that is exactly halfway between two doubles.
#include <gtest/gtest.h>

#include "symmesh/number/cyclotomic_cgal.h"
// (the CGAL traits of Cyclotomic first)
#include "symmesh/gen/surface_meshes_3d.h"

#include <gmpxx.h>

#include <random>

using namespace symmesh;
using gen::support::LazyCyclotomic;
using number::Cyclotomic;
using number::CyclotomicField;
using P = core::Point<LazyCyclotomic, 3>;

namespace {

LazyCyclotomic rational(std::int64_t n, std::int64_t d) {
  return LazyCyclotomic(
      Cyclotomic(mpq_class(mpz_class(static_cast<long>(n)), mpz_class(static_cast<long>(d)))));
}

LazyCyclotomic lazy(const mpq_class& q) {
  return LazyCyclotomic(Cyclotomic(q));
}

} // namespace

TEST(NearestOnPlane, IsTheNearestDoubleOfTheExactValue) {
  std::mt19937_64 rng(20261129);
  std::uniform_int_distribution<std::int64_t> num(-1000, 1000);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int decided = 0, total = 0;
  for (int m : {16, 64, 128}) {
    const auto f = CyclotomicField::get(m);
    for (int trial = 0; trial < 20; ++trial) {
      // A face frame rotated by 2πk/m about the z axis: p0 on a circle, u and v orthogonal.
      const long k = long(rng() % std::uint64_t(m));
      const LazyCyclotomic c(f->cos_2pi(k, m)), s(f->sin_2pi(k, m));
      const LazyCyclotomic r = rational(num(rng) + 2001, 1000), z = rational(num(rng), 7);
      const LazyCyclotomic a = rational(num(rng), 997), b = rational(num(rng) + 2001, 991);
      gen::surface3::FacePlane<LazyCyclotomic> plane;
      plane.p0 = P{{r * c, r * s, z}};
      plane.u = P{{a * c, a * s, b}};
      plane.v = P{{-s * b, c * b, lazy(0)}};
      const auto e = gen::surface3::plane_enclosure(plane);
      ASSERT_TRUE(e.usable);
      for (int p = 0; p < 50; ++p) {
        const double sd = unit(rng), td = unit(rng);
        const P x = plane.at({gen::support::exact_from_double<LazyCyclotomic>(sd),
                              gen::support::exact_from_double<LazyCyclotomic>(td)});
        for (int d = 0; d < 3; ++d) {
          ++total;
          const auto v = gen::surface3::nearest_on_plane(e, d, sd, td);
          if (!v) continue;
          ++decided;
          EXPECT_EQ(*v, CGAL::exact(x[d]).to_double())
              << "m = " << m << ", k = " << k << ", coordinate " << d;
        }
      }
    }
  }
  EXPECT_EQ(total, 9000);
  EXPECT_GE(decided, total - total / 100) << "decided " << decided << " of " << total;
}

TEST(NearestOnPlane, RefusesAValueHalfwayBetweenTwoDoubles) {
  // A midpoint between two neighbouring doubles (above and below a power of two, where the gaps
  // differ, and negative): no enclosure decides which is nearer, so the caller must evaluate
  // exactly (the dropped hypothesis: "x is not within the bound of a midpoint"). 2^-70 of the
  // value off the midpoint — far inside half an ulp, far outside the 2^-100 bound — it decides,
  // and gives the correctly rounded double. The value comes either as p0 or as s·u.
  const auto f = CyclotomicField::get(64);
  const auto pow2 = [](int e) {
    return e >= 0 ? mpq_class(mpz_class(1) << e) : mpq_class(1) / mpq_class(mpz_class(1) << -e);
  };
  const std::vector<mpq_class> midpoints = {1 + pow2(-53), 1 - pow2(-54), -(1 + pow2(-53)),
                                            pow2(10) * (1 - pow2(-54)),
                                            -pow2(-3) * (1 - pow2(-54))};
  int decided = 0;
  for (const auto& mid : midpoints)
    for (int side : {-1, 0, 1})
      for (bool as_product : {false, true}) {
        const mpq_class x0 = mid + side * abs(mid) * pow2(-70);
        gen::surface3::FacePlane<LazyCyclotomic> plane;
        plane.p0 =
            P{{lazy(as_product ? mpq_class(0) : x0), LazyCyclotomic(f->cos_2pi(1, 64)), lazy(0)}};
        plane.u = P{{lazy(as_product ? mpq_class(2 * x0) : mpq_class(0)), lazy(1), lazy(0)}};
        plane.v = P{{lazy(0), lazy(0), lazy(1)}};
        const auto e = gen::surface3::plane_enclosure(plane);
        const auto v = gen::surface3::nearest_on_plane(e, 0, 0.5, 0.25);
        if (side == 0) {
          EXPECT_FALSE(v.has_value()) << mid << ": " << *v;
          continue;
        }
        ASSERT_TRUE(v.has_value()) << mid << ", side " << side;
        EXPECT_EQ(*v, Cyclotomic(x0).to_double()) << mid << ", side " << side;
        EXPECT_NE(*v, Cyclotomic(mid - side * abs(mid) * pow2(-70)).to_double()) << mid;
        ++decided;
        // The y coordinate, cos(2π/64) + 0.5, is far from any midpoint.
        const auto y = gen::surface3::nearest_on_plane(e, 1, 0.5, 0.25);
        ASSERT_TRUE(y.has_value());
        EXPECT_EQ(*y, (f->cos_2pi(1, 64) + Cyclotomic(mpq_class(1, 2))).to_double());
      }
  EXPECT_EQ(decided, 20);
}
