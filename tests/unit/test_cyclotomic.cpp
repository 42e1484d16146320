// Unit tests of the real cyclotomic field K_m = Q(cos 2π/m) (spec/number-type.md).
#include <gtest/gtest.h>

#include "symmesh/number/cyclotomic.h"

#include <mpfr.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

using namespace symmesh::number;

namespace {

constexpr long double kPi = 3.141592653589793238462643383279502884L;

QPolynomial poly(std::initializer_list<long> coefficients) {
  QPolynomial p;
  for (long c : coefficients) p.emplace_back(c);
  return p;
}

/// Random element with coefficients num/den, num ∈ [-range, range], den ∈ [1, max_den]; about a
/// quarter of the coefficients are zero (sparse elements too).
Cyclotomic random_element(const CyclotomicFieldPtr& f, std::mt19937& rng, int range = 9,
                          int max_den = 5) {
  std::uniform_int_distribution<int> num(-range, range), den(1, max_den), zero(0, 3);
  std::vector<mpq_class> c(f->degree());
  for (auto& x : c) {
    if (zero(rng) == 0) continue;
    x = mpq_class(num(rng), den(rng));
    x.canonicalize();
  }
  return Cyclotomic(f, c);
}

/// Independent evaluation in long double (Horner in c = 2cos(2π/m)) and a bound on its scale.
std::pair<long double, long double> approx(const Cyclotomic& x) {
  const long double c = 2 * std::cos(2 * kPi / x.field()->m());
  long double v = 0, scale = 0;
  const auto& a = x.coefficients();
  for (std::size_t i = a.size(); i-- > 0;) {
    v = v * c + static_cast<long double>(a[i].get_d());
    scale = scale * std::fabs(c) + std::fabs(static_cast<long double>(a[i].get_d()));
  }
  return {v, scale};
}

/// Empty if the field axioms hold on `count` random triples, else the first violation.
std::string axiom_violation(const CyclotomicFieldPtr& f, unsigned seed, int count, int range = 9,
                            int max_den = 5) {
  std::mt19937 rng(seed);
  const Cyclotomic zero = f->zero(), one = f->one();
  try {
    for (int t = 0; t < count; ++t) {
      const Cyclotomic a = random_element(f, rng, range, max_den);
      const Cyclotomic b = random_element(f, rng, range, max_den);
      const Cyclotomic c = random_element(f, rng, range, max_den);
      if (a + b != b + a) return "a+b != b+a";
      if ((a + b) + c != a + (b + c)) return "(a+b)+c != a+(b+c)";
      if (a * b != b * a) return "ab != ba";
      if ((a * b) * c != a * (b * c)) return "(ab)c != a(bc)";
      if (a * (b + c) != a * b + a * c) return "a(b+c) != ab+ac";
      if (a + zero != a || a * one != a) return "neutral elements";
      if (!(a - a).is_zero() || a + (-a) != zero) return "additive inverse";
      if (!a.is_zero()) {
        if (a * a.inverse() != one) return "a * a^-1 != 1";
        if ((b / a) * a != b) return "(b/a)a != b";
        if (!b.is_zero() && (a * b).is_zero()) return "zero divisors";
      }
    }
  } catch (const std::exception& e) {
    return std::string("exception: ") + e.what();
  }
  return {};
}

/// Empty if cos²(2πk/n) + sin²(2πk/n) == 1 for every k, else the first failing k.
std::string pythagoras_violation(const CyclotomicFieldPtr& f, int n) {
  for (int k = 0; k < n; ++k) {
    const Cyclotomic c = f->cos_2pi(k, n), s = f->sin_2pi(k, n);
    if (c * c + s * s != Cyclotomic(1)) return "k = " + std::to_string(k);
  }
  return {};
}

using Matrix = std::array<Cyclotomic, 4>; // row-major 2x2

Matrix mul(const Matrix& x, const Matrix& y) {
  return {x[0] * y[0] + x[1] * y[2], x[0] * y[1] + x[1] * y[3], x[2] * y[0] + x[3] * y[2],
          x[2] * y[1] + x[3] * y[3]};
}

} // namespace

TEST(CyclotomicPolynomial, SmallCasesAndDegrees) {
  EXPECT_EQ(cyclotomic_polynomial(1), poly({-1, 1}));
  EXPECT_EQ(cyclotomic_polynomial(2), poly({1, 1}));
  EXPECT_EQ(cyclotomic_polynomial(4), poly({1, 0, 1}));
  EXPECT_EQ(cyclotomic_polynomial(5), poly({1, 1, 1, 1, 1}));
  EXPECT_EQ(cyclotomic_polynomial(8), poly({1, 0, 0, 0, 1}));
  EXPECT_EQ(cyclotomic_polynomial(12), poly({1, 0, -1, 0, 1}));
  for (int m = 1; m <= 150; ++m) {
    const QPolynomial p = cyclotomic_polynomial(m);
    EXPECT_EQ(static_cast<int>(p.size()) - 1, euler_phi(m)) << "m = " << m;
    EXPECT_EQ(p.back(), 1);
    for (const auto& c : p) EXPECT_EQ(c.get_den(), 1) << "m = " << m;
  }
}

TEST(CyclotomicField, Degrees) {
  EXPECT_EQ(CyclotomicField::get(8)->degree(), 2);
  EXPECT_EQ(CyclotomicField::get(16)->degree(), 4);
  EXPECT_EQ(CyclotomicField::get(20)->degree(), 4);
  EXPECT_EQ(CyclotomicField::get(60)->degree(), 8);
  EXPECT_EQ(CyclotomicField::get(128)->degree(), 32);
  for (int m = 3; m <= 200; ++m)
    EXPECT_EQ(CyclotomicField::get(m)->degree(), euler_phi(m) / 2) << "m = " << m;
  EXPECT_EQ(CyclotomicField::get(8), CyclotomicField::get(8)); // one shared instance per m
  EXPECT_THROW(CyclotomicField::get(2), std::invalid_argument);
}

TEST(CyclotomicField, MinimalPolynomials) {
  EXPECT_EQ(CyclotomicField::get(8)->minimal_polynomial(), poly({-2, 0, 1})); // x² − 2
  EXPECT_EQ(minimal_polynomial_2cos(3), poly({1, 1}));                        // c = −1
  EXPECT_EQ(minimal_polynomial_2cos(4), poly({0, 1}));                        // c = 0
  EXPECT_EQ(minimal_polynomial_2cos(6), poly({-1, 1}));                       // c = 1
  EXPECT_EQ(minimal_polynomial_2cos(5), poly({-1, 1, 1}));                    // golden ratio
  EXPECT_EQ(minimal_polynomial_2cos(12), poly({-3, 0, 1}));                   // √3
  EXPECT_EQ(minimal_polynomial_2cos(16), poly({2, 0, -4, 0, 1}));
  // Every minimal polynomial is monic, integral and vanishes at 2cos(2π/m) (checked in MPFR).
  for (int m = 3; m <= 130; ++m) {
    const QPolynomial p = minimal_polynomial_2cos(m);
    mpfr_t c, v, t;
    mpfr_inits2(600, c, v, t, static_cast<mpfr_ptr>(nullptr));
    mpfr_const_pi(c, MPFR_RNDN);
    mpfr_mul_ui(c, c, 2, MPFR_RNDN);
    mpfr_div_ui(c, c, static_cast<unsigned long>(m), MPFR_RNDN);
    mpfr_cos(c, c, MPFR_RNDN);
    mpfr_mul_ui(c, c, 2, MPFR_RNDN);
    mpfr_set_zero(v, 1);
    for (std::size_t i = p.size(); i-- > 0;) {
      EXPECT_EQ(p[i].get_den(), 1);
      mpfr_mul(v, v, c, MPFR_RNDN);
      mpfr_set_q(t, p[i].get_mpq_t(), MPFR_RNDN);
      mpfr_add(v, v, t, MPFR_RNDN);
    }
    mpfr_abs(v, v, MPFR_RNDN);
    EXPECT_LT(mpfr_get_d(v, MPFR_RNDU), 1e-100) << "m = " << m;
    mpfr_clears(c, v, t, static_cast<mpfr_ptr>(nullptr));
  }
}

TEST(CyclotomicField, SmallestFieldForOrders) {
  EXPECT_EQ(smallest_field_for_orders({}), 4);
  EXPECT_EQ(smallest_field_for_orders({5}), 20);
  EXPECT_EQ(smallest_field_for_orders({8, 6}), 24);
  EXPECT_EQ(smallest_field_for_orders({5, 6, 128}), 1920);
  EXPECT_THROW(smallest_field_for_orders({0}), std::invalid_argument);
}

TEST(CyclotomicField, FieldAxiomsOnRandomElements) {
  for (int m : {8, 12, 20, 60, 128}) {
    const auto f = CyclotomicField::get(m);
    EXPECT_EQ(axiom_violation(f, 20260 + m, m == 128 ? 15 : 40), "") << "m = " << m;
  }
}

TEST(CyclotomicField, CosSquaredPlusSinSquaredIsOne) {
  for (int n : {5, 8, 16, 32, 128}) {
    const auto f = CyclotomicField::get(smallest_field_for_orders({n}));
    EXPECT_EQ(pythagoras_violation(f, n), "") << "n = " << n;
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(f->cos_2pi(k, n).to_double(), std::cos(2 * M_PI * k / n), 1e-14);
      EXPECT_NEAR(f->sin_2pi(k, n).to_double(), std::sin(2 * M_PI * k / n), 1e-14);
    }
  }
  // Special values are exact.
  const auto f = CyclotomicField::get(24);
  EXPECT_EQ(f->cos_2pi(1, 6), Cyclotomic(mpq_class(1, 2)));
  EXPECT_EQ(f->sin_2pi(1, 12), Cyclotomic(mpq_class(1, 2)));
  EXPECT_EQ(f->sin_2pi(1, 4), Cyclotomic(1));
  EXPECT_EQ(f->cos_2pi(1, 4), Cyclotomic(0));
  EXPECT_EQ(f->cos_2pi(-5, 8), f->cos_2pi(5, 8));
  EXPECT_EQ(f->sin_2pi(-1, 8), -f->sin_2pi(1, 8));
  const Cyclotomic s3 = f->sin_2pi(1, 6); // √3 / 2
  EXPECT_EQ(s3 * s3, Cyclotomic(mpq_class(3, 4)));
}

TEST(CyclotomicField, RotationComposedNTimesIsIdentity) {
  for (int n : {8, 16, 32, 64, 128}) {
    const auto start = std::chrono::steady_clock::now();
    const auto f = CyclotomicField::get(smallest_field_for_orders({n}));
    const Cyclotomic c = f->cos_2pi(1, n), s = f->sin_2pi(1, n);
    const Matrix r{c, -s, s, c};
    Matrix x{Cyclotomic(1), Cyclotomic(0), Cyclotomic(0), Cyclotomic(1)};
    for (int i = 1; i <= n; ++i) {
      x = mul(x, r);
      if (i == n / 4) {
        EXPECT_EQ(x, (Matrix{0, -1, 1, 0})) << "quarter turn, n = " << n;
      }
      if (i == n / 2) {
        EXPECT_EQ(x, (Matrix{-1, 0, 0, -1})) << "half turn, n = " << n;
      }
    }
    EXPECT_EQ(x, (Matrix{1, 0, 0, 1})) << "n = " << n;
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ timing   ] R(2pi/%d) composed %d times in K_%d: %.2f ms\n", n, n, f->m(), ms);
    if (n == 128) {
      EXPECT_LT(ms, 1000.0);
    }
  }
}

TEST(CyclotomicField, SignAgreesWithIndependentEvaluation) {
  std::mt19937 rng(424242);
  int decided = 0;
  for (int m : {8, 12, 20, 60, 128}) {
    const auto f = CyclotomicField::get(m);
    for (int t = 0; t < 200; ++t) {
      const Cyclotomic a = random_element(f, rng);
      const auto [v, scale] = approx(a);
      if (std::fabs(v) <= 1e-9L * (1 + scale)) continue; // not decided by long double
      ++decided;
      EXPECT_EQ(a.sign(), v > 0 ? 1 : -1) << a;
      EXPECT_EQ(a > Cyclotomic(0), v > 0);
      EXPECT_EQ(std::signbit(a.to_double()), v < 0);
      EXPECT_NEAR(a.to_double(), static_cast<double>(v), 1e-9 * static_cast<double>(1 + scale));
      const auto [lo, hi] = a.to_interval();
      EXPECT_LE(lo, hi);
      EXPECT_TRUE(lo > 0 || hi < 0) << "interval of a non-zero element contains 0";
    }
  }
  EXPECT_GT(decided, 900);
  EXPECT_EQ(CyclotomicField::get(60)->zero().sign(), 0);
}

TEST(CyclotomicField, SignOfNearlyEqualValues) {
  // x = cos(2π/128) against rationals r within 2^-e of it; the reference is MPFR at 3000 bits.
  const auto f = CyclotomicField::get(128);
  const Cyclotomic x = f->cos_2pi(1, 128);
  mpfr_t ref, t;
  mpfr_init2(ref, 3000);
  mpfr_const_pi(ref, MPFR_RNDN);
  mpfr_div_ui(ref, ref, 64, MPFR_RNDN);
  mpfr_cos(ref, ref, MPFR_RNDN);
  for (long e : {50L, 60L, 200L, 1000L, 2500L}) {
    mpfr_init2(t, e + 10);
    mpfr_set(t, ref, MPFR_RNDN);
    mpq_class r, eps(1);
    mpfr_get_q(r.get_mpq_t(), t);
    mpq_div_2exp(eps.get_mpq_t(), eps.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    const int expected = mpfr_cmp_q(ref, r.get_mpq_t()) > 0 ? 1 : -1;
    EXPECT_EQ((x - Cyclotomic(r)).sign(), expected) << "e = " << e;
    EXPECT_NE(x, Cyclotomic(r));
    EXPECT_GT(x, Cyclotomic(mpq_class(r - eps))) << "e = " << e;
    EXPECT_LT(x, Cyclotomic(mpq_class(r + eps))) << "e = " << e;
    EXPECT_EQ(compare(Cyclotomic(mpq_class(r + eps)), x), 1);
    mpfr_clear(t);
  }
  mpfr_clear(ref);
  // Nearly equal field elements: cos(2π/128) vs its Chebyshev-expanded double angle identity.
  const Cyclotomic c2 = f->cos_2pi(2, 128);
  EXPECT_EQ(2 * x * x - 1, c2);
  EXPECT_EQ((2 * x * x - 1 - c2).sign(), 0);
  mpq_class tiny(1);
  mpq_div_2exp(tiny.get_mpq_t(), tiny.get_mpq_t(), 3000);
  EXPECT_EQ((2 * x * x - 1 - c2 + Cyclotomic(tiny)).sign(), 1); // rational, decided exactly
  EXPECT_EQ((x * x - c2 / 2 - Cyclotomic(mpq_class(1, 2)) - Cyclotomic(tiny) * x).sign(), -1);
}

TEST(CyclotomicField, RationalModeAndPromotion) {
  const Cyclotomic zero(0), one(1);
  EXPECT_TRUE(zero.is_rational_mode());
  EXPECT_TRUE(zero.is_zero());
  EXPECT_EQ(one.sign(), 1);
  EXPECT_EQ(Cyclotomic(mpq_class(1, 3)) + Cyclotomic(mpq_class(2, 3)), one);
  EXPECT_EQ(Cyclotomic(mpq_class(-3, 4)).inverse(), Cyclotomic(mpq_class(-4, 3)));
  EXPECT_LT(Cyclotomic(mpq_class(1, 3)), Cyclotomic(mpq_class(1, 2)));
  EXPECT_THROW(zero.inverse(), std::domain_error);
  EXPECT_THROW(one / zero, std::domain_error);
  EXPECT_DOUBLE_EQ(Cyclotomic(mpq_class(1, 4)).to_double(), 0.25);

  const auto f = CyclotomicField::get(8);
  const Cyclotomic c = f->generator(); // √2
  EXPECT_EQ(one + c, f->element({1, 1}));
  EXPECT_EQ(c + one, f->element({1, 1}));
  EXPECT_EQ(2 * c, f->element({0, 2}));
  EXPECT_EQ(c * c, Cyclotomic(2));
  EXPECT_EQ(Cyclotomic(2), c * c);
  EXPECT_EQ(f->zero(), zero);
  EXPECT_NE(c, one);
  EXPECT_EQ(one / c, c / 2);
  EXPECT_EQ(zero - c, -c);
  EXPECT_EQ(abs(-c), c);
  EXPECT_GT(c, Cyclotomic(mpq_class(1414213, 1000000)));
  EXPECT_LT(c, Cyclotomic(mpq_class(1414214, 1000000)));
  EXPECT_THROW(c / f->zero(), std::domain_error);
  EXPECT_THROW(f->zero().inverse(), std::domain_error);
  EXPECT_THROW(c + CyclotomicField::get(12)->generator(), std::invalid_argument);
  EXPECT_THROW(f->cos_2pi(1, 3), std::invalid_argument);
  EXPECT_THROW(CyclotomicField::get(10)->sin_2pi(1, 5), std::invalid_argument);
  const auto k10 = CyclotomicField::get(10); // c = 2cos 36° = golden ratio, c² = c + 1
  EXPECT_EQ(k10->cos_2pi(1, 10), k10->generator() / 2);
  EXPECT_EQ(k10->cos_2pi(1, 5), (k10->generator() - 1) / 2);

  std::ostringstream os;
  os << c / 2 << ' ' << Cyclotomic(mpq_class(3, 4));
  EXPECT_EQ(os.str(), "K8[0, 1/2] 3/4");
  const auto [lo, hi] = c.to_interval();
  EXPECT_LT(lo, hi);
  EXPECT_LE(lo, std::sqrt(2.0));
  EXPECT_GE(hi, std::sqrt(2.0));
}

TEST(CyclotomicField, WrongMinimalPolynomialIsCaught) {
  // The right one passes both checks.
  EXPECT_EQ(axiom_violation(CyclotomicField::get(8), 7, 50, 2, 1), "");
  EXPECT_EQ(pythagoras_violation(CyclotomicField::get(8), 8), "");

  // x² − 1 = (x − 1)(x + 1) is reducible: not a field (c − 1 has no inverse, zero divisors),
  // and cos² + sin² = c²/2 = 1/2.
  const auto reducible =
      CyclotomicField::make_with_minimal_polynomial_for_testing(8, poly({-1, 0, 1}));
  EXPECT_NE(axiom_violation(reducible, 7, 50, 2, 1), "");
  EXPECT_NE(pythagoras_violation(reducible, 8), "");
  EXPECT_THROW(reducible->element({-1, 1}).inverse(), std::logic_error);

  // x² − 3 is irreducible, so Q[x]/(x² − 3) is a field (Q(√3)) and the axioms hold; but it is not
  // the minimal polynomial of 2cos(2π/8): cos² + sin² = c²/2 = 3/2.
  const auto wrong_field =
      CyclotomicField::make_with_minimal_polynomial_for_testing(8, poly({-3, 0, 1}));
  EXPECT_EQ(axiom_violation(wrong_field, 7, 20), "");
  EXPECT_NE(pythagoras_violation(wrong_field, 8), "");

  // Degree 4, wrong constant term (x⁴ − 4x² + 1 is the minimal polynomial of 2cos(2π/24)).
  const auto wrong16 =
      CyclotomicField::make_with_minimal_polynomial_for_testing(16, poly({1, 0, -4, 0, 1}));
  EXPECT_NE(pythagoras_violation(wrong16, 16), "");
  // A reducible degree-4 polynomial: (x² − 2)².
  const auto square =
      CyclotomicField::make_with_minimal_polynomial_for_testing(16, poly({4, 0, -4, 0, 1}));
  EXPECT_NE(axiom_violation(square, 11, 50, 2, 1), "");
  EXPECT_NE(pythagoras_violation(square, 16), "");
  EXPECT_FALSE(wrong16->same_field(*CyclotomicField::get(16)));
}

// is_cos_2pi / is_sin_2pi decide x == ±cos, ±sin on the coefficients (the rotational generator's
// rotation check): they agree with == on the built elements, for every k, and refuse neighbours,
// the other sign and elements of another field.
TEST(CyclotomicField, IsCosSinAgreeWithTheBuiltElements) {
  const auto f = CyclotomicField::get(128);
  const auto other = CyclotomicField::get(64);
  for (long k = 0; k < 128; ++k) {
    const Cyclotomic c = f->cos_2pi(k, 128), s = f->sin_2pi(k, 128);
    EXPECT_TRUE(f->is_cos_2pi(c, k, 128)) << k;
    EXPECT_TRUE(f->is_sin_2pi(s, k, 128)) << k;
    EXPECT_TRUE(f->is_sin_2pi(-s, k, 128, -1)) << k;
    EXPECT_EQ(f->is_cos_2pi(c, k + 1, 128), c == f->cos_2pi(k + 1, 128)) << k;
    EXPECT_EQ(f->is_sin_2pi(s, k, 128, -1), s.is_zero()) << k;
    EXPECT_EQ(f->is_cos_2pi(s, k, 128), s == c) << k;
  }
  // Rational-mode values (the identity's 1 and 0) and the same value in a subfield's K_64.
  EXPECT_TRUE(f->is_cos_2pi(Cyclotomic(1), 0, 128));
  EXPECT_TRUE(f->is_sin_2pi(Cyclotomic(0), 0, 128));
  EXPECT_FALSE(f->is_cos_2pi(Cyclotomic(0), 0, 128));
  EXPECT_FALSE(f->is_cos_2pi(other->cos_2pi(1, 64), 2, 128)); // another field: not compared
}

namespace {
/// Σ a_i c^i at `bits` of precision, with c = 2cos(2π/m) from MPFR: an evaluation independent of
/// the field's cached powers, filter and double-double code.
double reference_value(const Cyclotomic& x, mpfr_prec_t bits, mpfr_t out) {
  mpfr_t c, coef;
  mpfr_inits2(bits, c, coef, static_cast<mpfr_ptr>(nullptr));
  mpfr_const_pi(c, MPFR_RNDN);
  mpfr_mul_ui(c, c, 2, MPFR_RNDN);
  mpfr_div_ui(c, c, static_cast<unsigned long>(x.field()->m()), MPFR_RNDN);
  mpfr_cos(c, c, MPFR_RNDN);
  mpfr_mul_ui(c, c, 2, MPFR_RNDN);
  mpfr_set_zero(out, 1);
  const auto& a = x.coefficients();
  for (std::size_t i = a.size(); i-- > 0;) {
    mpfr_mul(out, out, c, MPFR_RNDN);
    mpfr_set_q(coef, a[i].get_mpq_t(), MPFR_RNDN);
    mpfr_add(out, out, coef, MPFR_RNDN);
  }
  mpfr_clears(c, coef, static_cast<mpfr_ptr>(nullptr));
  return mpfr_get_d(out, MPFR_RNDN);
}
} // namespace

TEST(CyclotomicField, ToIntervalIsNarrowWhereThePowerBasisCancels) {
  // A cosine of K_128 in the basis 1, c, ..., c^31 has Σ|a_i c^i| up to 2^43 times its value:
  // the double filter alone encloses it only to about 2^-10 relative (checked below, so this test
  // would notice if the basis changed), the double-double evaluation to a few units in the last
  // place. Every enclosure must contain the value (MPFR at 1000 bits, Horner, independent).
  mpfr_t ref;
  mpfr_init2(ref, 1000);
  for (int m : {32, 64, 128}) {
    const auto f = CyclotomicField::get(m);
    double widest_filter = 0;
    for (long k = 0; k < m; ++k)
      for (const Cyclotomic& x :
           {f->cos_2pi(k, m), f->sin_2pi(k, m), Cyclotomic(mpq_class(37, 100)) * f->cos_2pi(k, m),
            f->cos_2pi(k, m) * f->sin_2pi(3, m) + Cyclotomic(mpq_class(-7, 3))}) {
        if (x.is_zero()) continue;
        const double v = reference_value(x, 1000, ref);
        const auto [lo, hi] = x.to_interval();
        EXPECT_TRUE(mpfr_cmp_d(ref, lo) >= 0 && mpfr_cmp_d(ref, hi) <= 0)
            << "m = " << m << ", k = " << k << ": [" << lo << ", " << hi << "] misses " << x;
        EXPECT_LE(hi - lo, 0x1p-46 * std::fabs(v)) << "m = " << m << ", k = " << k << ": " << x;
        double sum = 0, bound = 0;
        if (f->filtered_value(x.coefficients(), sum, bound))
          widest_filter = std::max(widest_filter, bound / std::fabs(v));
        double value = 0;
        ASSERT_TRUE(f->double_double_value(x.coefficients(), value, bound)) << x;
        EXPECT_LE(std::fabs(value - v), bound) << x;
      }
    if (m == 128) {
      EXPECT_GT(widest_filter, 0x1p-20);
    }
  }
  mpfr_clear(ref);
}

TEST(CyclotomicField, DoubleDoubleEnclosureHoldsTo106Bits) {
  // hi + lo ± bound of double_double_enclosure (MPFR at 256 bits, split into two doubles) against
  // MPFR at 1000 bits, on cosines, sines and random elements with large coefficients; the bound is
  // about 2^-106 of the value (what two doubles hold), far below half an ulp, which is what lets
  // gen/ round affine combinations correctly without exact evaluation.
  std::mt19937_64 rng(20261130);
  mpfr_t ref, diff;
  mpfr_inits2(1000, ref, diff, static_cast<mpfr_ptr>(nullptr));
  int checked = 0;
  for (int m : {12, 64, 128}) {
    const auto f = CyclotomicField::get(m);
    std::uniform_int_distribution<std::int64_t> num(-(std::int64_t(1) << 62), std::int64_t(1)
                                                                                  << 62);
    for (int t = 0; t < 100; ++t) {
      std::vector<mpq_class> c(f->degree());
      for (auto& x : c) x = mpq_class(mpz_class(static_cast<long>(num(rng))), 3);
      for (const Cyclotomic& x : {Cyclotomic(f, c), f->cos_2pi(t, m), f->sin_2pi(t + 1, m),
                                  Cyclotomic(f, {mpq_class(t + 1, 7)})}) {
        if (x.is_zero()) continue;
        double hi = 0, lo = 0, bound = 0;
        x.double_double_enclosure(hi, lo, bound);
        const double v = reference_value(x, 1000, ref);
        mpfr_sub_d(diff, ref, hi, MPFR_RNDN);
        mpfr_sub_d(diff, diff, lo, MPFR_RNDN);
        mpfr_abs(diff, diff, MPFR_RNDN);
        EXPECT_LE(mpfr_get_d(diff, MPFR_RNDU), bound) << x;
        EXPECT_LE(bound, 0x1p-100 * std::fabs(v)) << x;
        EXPECT_EQ(hi, x.to_double()) << x;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1100);
  mpfr_clears(ref, diff, static_cast<mpfr_ptr>(nullptr));
}

TEST(CyclotomicField, DoubleDoubleBoundHoldsOnRandomElements) {
  // The bound of double_double_value against MPFR at 1000 bits, on random elements whose
  // coefficients have up to 53-bit numerators and denominators (the split is exact there), and
  // its refusal of a coefficient with more bits.
  std::mt19937_64 rng(20261129);
  mpfr_t ref, diff;
  mpfr_inits2(1000, ref, diff, static_cast<mpfr_ptr>(nullptr));
  int checked = 0;
  for (int m : {5, 12, 60, 64, 128}) {
    const auto f = CyclotomicField::get(m);
    std::uniform_int_distribution<std::int64_t> num(-(std::int64_t(1) << 52), std::int64_t(1)
                                                                                  << 52);
    std::uniform_int_distribution<std::int64_t> den(1, std::int64_t(1) << 52);
    for (int t = 0; t < 200; ++t) {
      std::vector<mpq_class> c(f->degree());
      for (auto& x : c) {
        x = mpq_class(mpz_class(static_cast<long>(num(rng))),
                      mpz_class(static_cast<long>(den(rng))));
        x.canonicalize();
      }
      const Cyclotomic x(f, c);
      double value = 0, bound = 0;
      ASSERT_TRUE(f->double_double_value(x.coefficients(), value, bound));
      reference_value(x, 1000, ref);
      mpfr_sub_d(diff, ref, value, MPFR_RNDN);
      EXPECT_LE(std::fabs(mpfr_get_d(diff, MPFR_RNDU)), bound) << x;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 1000);
  mpq_class wide(mpz_class(1) << 60, 3);
  const auto f = CyclotomicField::get(64);
  double value = 0, bound = 0;
  EXPECT_FALSE(f->double_double_value({wide, mpq_class(1)}, value, bound));
  mpfr_clears(ref, diff, static_cast<mpfr_ptr>(nullptr));
}
