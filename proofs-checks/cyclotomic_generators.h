/// RapidCheck generators and independent evaluation for the real cyclotomic field K_m —
/// spec/number-type.md (the number type), spec/lemmas.md#lemma-4-1, spec/lemmas.md#lemma-4-2
///
/// Shared by cyclotomic_field.cpp (field axioms, rotations, certified sign, wrong minimal
/// polynomials) and lemma_4_1_cyclotomic.cpp / lemma_4_2_cyclotomic.cpp (Lemmas 4.1 and 4.2 on
/// rotational structures whose coordinates lie in K_m). The picks follow generators.cpp: every
/// random choice is an integer pick inside rc::gen::exec, so cases are reproducible from the
/// runner's seed and RapidCheck shrinks the picks (smaller n, fewer radii, smaller coefficients).
///
/// The independent evaluation (`mpfr_value`) is plain MPFR at kBits bits, round-to-nearest, with
/// c = 2cos(2π/m) from mpfr_const_pi and mpfr_cos: it shares nothing with the type's certified
/// interval code (CyclotomicField::sign) nor with its Chebyshev table of 2cos(2πj/m).
#pragma once
#include <rapidcheck.h>

#include "symmesh/number/cyclotomic_cgal.h"

#include "symmesh/core/templated_structure.h"

#include <mpfr.h>

#include <ostream>
#include <string>
#include <vector>

namespace symmesh::proofs::cyclo {

using number::Cyclotomic;
using number::CyclotomicField;
using number::CyclotomicFieldPtr;
using number::QPolynomial;
using KPoint = core::Point<Cyclotomic, 2>;
using KMotion = core::RigidTransformation<Cyclotomic, 2>;
using KComplex = core::ElementComplex<Cyclotomic, 2>;
using KStructure = core::TemplatedStructure<Cyclotomic, 2>;

/// The moduli m of the field properties: {5, 7, 8, 12, 16, 20, 32, 60, 128}
/// (degrees d = φ(m)/2 = 2, 3, 2, 2, 4, 4, 8, 8, 32).
const std::vector<int>& field_moduli();
/// The moduli with 4 | m, so that sin(2πk/n) ∈ K_m for n | m: {8, 12, 16, 20, 24, 32, 40, 60, 128}.
const std::vector<int>& rotation_moduli();
/// The positive divisors of m, increasing.
std::vector<int> divisors(int m);

// ----- picks: only valid inside rc::gen::exec --------------------------------------------------

/// A uniform pick in [lo, hi] (at full RapidCheck size, as in generators.cpp).
int pick(int lo, int hi);
bool chance(int percent);
/// Also true with the given probability, but false when the pick is shrunk (for optional
/// features that a minimal counterexample should not have).
bool rare(int percent);
/// One of the values.
int pick_of(const std::vector<int>& values);
/// num/den with num ∈ [-range, range], den ∈ [1, max_den].
mpq_class random_rational(int range, int max_den);
/// A random element of f: dense, sparse (about a quarter of the coefficients zero), a single
/// monomial, a rational, a value cos(2πk/n) / 2cos(2πj/m) of the field's table, or a product of
/// two such; sometimes with large coefficients (numerators up to 10^6).
Cyclotomic random_element(const CyclotomicFieldPtr& f);

// ----- independent high-precision evaluation ---------------------------------------------------

/// Working precision of the independent evaluation, and the magnitude below which its sign is
/// not trusted (|value| <= 2^-kTrustExponent is "undecided").
constexpr long kBits = 4000;
constexpr long kTrustExponent = 3000;

/// An MPFR number (RAII, move-only).
class BigFloat {
public:
  explicit BigFloat(long bits = kBits) { mpfr_init2(v_, bits); }
  ~BigFloat() {
    if (live_) mpfr_clear(v_);
  }
  BigFloat(BigFloat&& o) noexcept : live_(o.live_) {
    *v_ = *o.v_;
    o.live_ = false;
  }
  BigFloat(const BigFloat&) = delete;
  BigFloat& operator=(const BigFloat&) = delete;
  BigFloat& operator=(BigFloat&&) = delete;
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }

private:
  mpfr_t v_;
  bool live_ = true;
};

/// Σ a_i (2cos(2π/m))^i of x (or its rational value) with plain MPFR at kBits bits.
BigFloat mpfr_value(const Cyclotomic& x);
/// The sign of v when |v| > 2^-kTrustExponent, else 0 (undecided).
int trusted_sign(const BigFloat& v);
/// floor(v · 2^k) / 2^k: a rational r with 0 <= v - r < 2^-k (up to the evaluation error).
mpq_class dyadic_floor(const BigFloat& v, long k);
/// log2 |v| rounded down (v != 0).
long exponent_of(const BigFloat& v);

// ----- rotations ------------------------------------------------------------------------------

/// rot(2πk/n) about `center`, through core::RigidTransformation::rotation_2d (which checks
/// cos² + sin² = 1 exactly and throws std::invalid_argument otherwise). \pre n | m, 4 | m.
KMotion rotation(const CyclotomicFieldPtr& f, long k, long n, const KPoint& center);
KPoint make_point(const Cyclotomic& x, const Cyclotomic& y);

// ----- wrong minimal polynomials (test hook) --------------------------------------------------

/// "K_m" over a monic polynomial of degree φ(m)/2 other than the minimal polynomial of
/// 2cos(2π/m): the minimal polynomial of another 2cos(2π/m') of the same degree (irreducible,
/// wrong), the true one perturbed in one coefficient, a product (y - r)·Q, or a square Q².
struct WrongField {
  CyclotomicFieldPtr field;
  std::string kind; ///< "other_cyclotomic", "perturbed", "linear_factor", "square"
  QPolynomial poly;
  bool reducible = false;
  /// For reducible polynomials: two non-constant factors with poly = factor_a · factor_b.
  QPolynomial factor_a, factor_b;
};
/// A wrong field for K_m (picks: inside rc::gen::exec); only reducible polynomials if
/// `reducible_only`. \pre φ(m)/2 >= 2
WrongField wrong_field(int m, bool reducible_only = false);
/// "y^2 - 2" style text.
std::string polynomial_text(const QPolynomial& p);
/// p(c) reduced in f (coefficients of degree >= d folded by the field's own multiplication).
Cyclotomic evaluate_in(const CyclotomicFieldPtr& f, const QPolynomial& p);

// ----- rotational structures (Lemmas 4.1, 4.2 over K_m) -------------------------------------

/// A slice template in the wedge 0 <= angle <= 2π/n: radii 0 < r_1 < ... < r_k on the ray at
/// angle 0 and 0 < s_1 < ... < s_l on the ray at angle 2π/n (coordinates s·(cos, sin) in K_m),
/// the centre triangle (O, r_1, s_1), a zipper triangulation of the strip between the two
/// chains (random advance per step; equal chains give the quad-by-quad diagonal choices and
/// fans alike), and optionally rational points strictly inside random triangles (each splits
/// its triangle into three). One template, instanced by rot(2πi/n), i = 0..n-1, about the
/// origin, optionally followed by one global rational motion (translation, reflection in the
/// x-axis). With same_radii, s = r (Lemma 4.2's hypotheses hold: a templated mesh); otherwise
/// the outer radius is the same but the interior radii differ (an extra, a missing or a moved
/// radius), so consecutive slices meet along differently subdivided segments.
struct RotationalStructure {
  KStructure x;
  std::string recipe;
  int m = 0, n = 0;
  bool same_radii = true;
};
inline std::ostream& operator<<(std::ostream& os, const RotationalStructure& s) {
  return os << s.recipe;
}
rc::Gen<RotationalStructure> rotational_structure(bool same_radii);

/// Failure record: {"lemma", "recipe", "m", "n", "template": {points (exact and approximate),
/// elements}, "instances": [{matrix, translation}]} (exact numbers as "K<m>[a0, ...]").
std::string rotational_record(const std::string& lemma, const RotationalStructure& s);
/// The structure instance as SVG (output only: coordinates via to_double).
std::string rotational_picture(const RotationalStructure& s);

/// Producers for SYMMESH_PROOF_ASSERT (called only on failure).
inline auto rotational_failure_record(const char* lemma, const RotationalStructure& s) {
  return [lemma, &s] { return rotational_record(lemma, s); };
}
inline auto rotational_failure_picture(const RotationalStructure& s) {
  return [&s] { return rotational_picture(s); };
}

} // namespace symmesh::proofs::cyclo
