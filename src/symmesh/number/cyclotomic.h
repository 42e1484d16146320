// Exact arithmetic in the real cyclotomic field K_m = Q(cos 2π/m) (spec/number-type.md).
//
// An element is a vector of rationals (GMP mpq) in the power basis 1, c, ..., c^{d-1} of
// c = 2cos(2π/m), d = φ(m)/2 = [K_m : Q]. + − × are exact polynomial arithmetic modulo the exact
// minimal polynomial of c; the inverse is exact (extended Euclid over Q[x]); the zero test is a
// coefficient test; sign and comparison are decided by certified MPFR interval evaluation at
// doubling precision (it terminates because zero was already excluded exactly).
// Double values (to_double, to_interval) are for output only.
#pragma once

#include <gmpxx.h>

#include <initializer_list>
#include <iosfwd>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace symmesh::number {

class Cyclotomic;
class CyclotomicField;
using CyclotomicFieldPtr = std::shared_ptr<const CyclotomicField>;

/// A polynomial over Q: coefficients from degree 0 upwards, no trailing zeros (zero = empty).
using QPolynomial = std::vector<mpq_class>;

/// Euler's totient φ(m), m >= 1.
int euler_phi(int m);
/// The m-th cyclotomic polynomial Φ_m (exact: x^m − 1 divided by Φ_e for every e | m, e < m).
QPolynomial cyclotomic_polynomial(int m);
/// The minimal polynomial over Q of 2cos(2π/m), m >= 3: monic, integral, degree φ(m)/2. From Φ_m
/// by x^{-d}Φ_m(x) = a_d + Σ_k a_{d+k}(x^k + x^{-k}) and x^k + x^{-k} = D_k(x + 1/x) (D_0 = 2,
/// D_1 = y, D_k = y D_{k-1} − D_{k-2}).
QPolynomial minimal_polynomial_2cos(int m);
/// lcm(4, orders...): the smallest m such that K_m holds cos and sin of 2πk/n for every order n.
int smallest_field_for_orders(const std::vector<int>& orders);

/// K_m = Q(cos 2π/m), m >= 3. Shared and immutable (caches of Chebyshev values and of
/// high-precision powers of c are filled lazily under a mutex).
class CyclotomicField : public std::enable_shared_from_this<CyclotomicField> {
  struct Private {};

public:
  /// The field K_m (one shared instance per m).
  static CyclotomicFieldPtr get(int m);
  /// TEST HOOK: K_m with `monic` (low degree first) in place of the true minimal polynomial of
  /// c = 2cos(2π/m). The result is not a field unless `monic` is right; tests use it to show that
  /// the axiom checks catch a wrong minimal polynomial.
  static CyclotomicFieldPtr make_with_minimal_polynomial_for_testing(int m, QPolynomial monic);

  CyclotomicField(Private, int m, QPolynomial minimal_polynomial);
  ~CyclotomicField();
  CyclotomicField(const CyclotomicField&) = delete;
  CyclotomicField& operator=(const CyclotomicField&) = delete;

  int m() const { return m_; }
  /// d = φ(m)/2, the dimension of the basis 1, c, ..., c^{d-1}.
  int degree() const { return d_; }
  /// Monic, d + 1 coefficients, low degree first.
  const QPolynomial& minimal_polynomial() const { return minpoly_; }
  /// Same m and same minimal polynomial.
  bool same_field(const CyclotomicField& other) const;

  /// The element Σ coefficients[i] c^i; coefficients.size() <= d.
  Cyclotomic element(std::vector<mpq_class> coefficients) const;
  Cyclotomic zero() const;
  Cyclotomic one() const;
  /// c = 2cos(2π/m).
  Cyclotomic generator() const;
  /// 2cos(2πj/m) for any integer j.
  Cyclotomic two_cos_2pi_over_m(long j) const;
  /// cos(2πk/n); requires n > 0 and n | m.
  Cyclotomic cos_2pi(long k, long n) const;
  /// sin(2πk/n) = cos(2π(k m/n − m/4)/m); requires n > 0, n | m and 4 | m.
  Cyclotomic sin_2pi(long k, long n) const;
  /// x == sign·cos(2πk/n), resp. sign·sin(2πk/n), decided on the coefficients against the
  /// cached Chebyshev values, without building the element (the rotational generator compares
  /// every instance matrix with them). Same requirements as cos_2pi / sin_2pi; sign = ±1. An
  /// element of another field is not compared (false); rationals are.
  bool is_cos_2pi(const Cyclotomic& x, long k, long n, int sign = 1) const;
  bool is_sin_2pi(const Cyclotomic& x, long k, long n, int sign = 1) const;

  // Coefficient-level operations (vectors of size d), used by Cyclotomic.
  std::vector<mpq_class> multiply(const std::vector<mpq_class>& a,
                                  const std::vector<mpq_class>& b) const;
  /// Throws std::domain_error for 0; std::logic_error when the (test-hooked) minimal polynomial
  /// shares a factor with a, i.e. is not irreducible.
  std::vector<mpq_class> inverse(const std::vector<mpq_class>& a) const;
  /// Σ a_i ĉ^i in double and a bound on its distance to the exact value; false when a
  /// coefficient is outside the double range the bound assumes.
  bool filtered_value(const std::vector<mpq_class>& a, double& value, double& bound) const;
  /// Σ a_i c^i in double-double (error-free products and sums, c^i to about 2^-106) and a bound
  /// on its distance to the exact value: a narrow enclosure where the power basis cancels (a
  /// cosine of K_128 in this basis has Σ|a_i c^i| ≈ 2^43 times its value). false when a
  /// coefficient's numerator or denominator has more than 53 bits or a magnitude leaves the range
  /// the bound assumes.
  bool double_double_value(const std::vector<mpq_class>& a, double& value, double& bound) const;
  /// hi + lo with |hi + lo − Σ a_i c^i| <= bound ≈ 2^-106 |value| (MPFR at 256 bits; hi the
  /// value rounded, lo the rest rounded): enough to round an affine combination of such values
  /// with double coefficients correctly without evaluating it exactly (gen/surface_meshes_3d.h).
  void double_double_enclosure(const std::vector<mpq_class>& a, double& hi, double& lo,
                               double& bound) const;
  /// Sign by a double evaluation with a rigorous error bound; 0 when that bound does not decide.
  int filtered_sign(const std::vector<mpq_class>& a) const;
  /// filtered_sign of a − b (same degree), without forming a − b.
  int filtered_sign_of_difference(const std::vector<mpq_class>& a,
                                  const std::vector<mpq_class>& b) const;
  /// Certified sign of Σ a_i c^i.
  int sign(const std::vector<mpq_class>& a) const;
  /// Interval [lo, hi] of doubles containing the value; excludes 0 for non-zero elements (unless
  /// the value underflows a double).
  std::pair<double, double> to_interval(const std::vector<mpq_class>& a) const;
  double to_double(const std::vector<mpq_class>& a) const;

  /// Highest working precision (bits) of the certified sign; exceeding it means a wrong minimal
  /// polynomial (std::runtime_error).
  static constexpr long max_precision_bits = 1L << 20;

private:
  struct Powers;
  std::shared_ptr<const Powers> powers(long precision) const;
  const std::vector<mpq_class>& two_cos_cached(long j) const;
  /// x == sign·(1/2)·2cos(2πj/m).
  bool is_half_two_cos(const Cyclotomic& x, long j, int sign) const;
  std::vector<mpq_class> times_c(const std::vector<mpq_class>& v) const;
  /// multiply on machine integers, for numerators below 2^31 and a small reduction table.
  std::vector<mpq_class> multiply_small(const std::vector<mpz_class>& an, const mpz_class& ad,
                                        const std::vector<mpz_class>& bn,
                                        const mpz_class& bd) const;

  int m_;
  int d_;
  QPolynomial minpoly_;
  std::vector<mpq_class> c_to_d_;                     // c^d in the basis
  std::vector<std::vector<mpz_class>> reduction_num_; // c^{d+j}·reduction_den_, j = 0..d-2
  mpz_class reduction_den_;
  mutable std::mutex mutex_;
  mutable std::vector<std::shared_ptr<const Powers>> powers_;
  mutable std::vector<std::vector<mpq_class>> two_cos_; // 2cos(2πj/m), j = 0..
  std::vector<double> c_pow_double_;                    // c^i to nearest double, for filtered_sign
  std::vector<double> c_pow_low_; // c^i − c_pow_double_[i] to nearest: c^i in double-double
  bool small_reduction_ = false;  // reduction table entries and denominator below 2^40
  std::vector<std::vector<long long>> reduction_small_;
};

/// Copy-on-write coefficient storage: copies of an element share one vector (the core copies
/// points and matrices freely, and a copy of d rationals costs 2d allocations), and the first
/// write through a shared copy unshares it. Not for concurrent writers.
class CoefficientVector {
public:
  explicit CoefficientVector(std::size_t n = 0) : p_(std::make_shared<std::vector<mpq_class>>(n)) {}
  CoefficientVector(std::initializer_list<mpq_class> values)
      : p_(std::make_shared<std::vector<mpq_class>>(values)) {}
  CoefficientVector(std::vector<mpq_class> values)
      : p_(std::make_shared<std::vector<mpq_class>>(std::move(values))) {}

  const std::vector<mpq_class>& get() const { return *p_; }
  operator const std::vector<mpq_class>&() const { return *p_; }
  std::size_t size() const { return p_->size(); }
  const mpq_class& operator[](std::size_t i) const { return (*p_)[i]; }
  mpq_class& operator[](std::size_t i) { return own()[i]; }
  auto begin() const { return p_->cbegin(); }
  auto end() const { return p_->cend(); }
  auto begin() { return own().begin(); }
  auto end() { return own().end(); }
  void resize(std::size_t n) { own().resize(n); }
  friend bool operator==(const CoefficientVector& a, const CoefficientVector& b) {
    return a.p_ == b.p_ || *a.p_ == *b.p_;
  }

private:
  std::vector<mpq_class>& own() {
    if (p_.use_count() > 1) p_ = std::make_shared<std::vector<mpq_class>>(*p_);
    return *p_;
  }
  std::shared_ptr<std::vector<mpq_class>> p_;
};

/// An element of K_m, or (with no field) a plain rational: `Cyclotomic(0)`, `Cyclotomic(1)` work
/// before a field is chosen, and mixing a rational with a field element promotes it.
class Cyclotomic {
public:
  Cyclotomic() : coefficients_(1) {}
  Cyclotomic(int v) : coefficients_{mpq_class(v)} {}
  Cyclotomic(long v) : coefficients_{mpq_class(v)} {}
  Cyclotomic(const mpz_class& v) : coefficients_{mpq_class(v)} {}
  /// gmpxx does not reduce mpq_class(2, 2); == compares coefficients, so they are kept in
  /// lowest terms from the start.
  Cyclotomic(const mpq_class& v) : coefficients_{v} { coefficients_[0].canonicalize(); }
  /// Σ coefficients[i] c^i in `field` (coefficients.size() <= degree; padded with zeros).
  Cyclotomic(CyclotomicFieldPtr field, std::vector<mpq_class> coefficients);

  /// No field: a rational number.
  bool is_rational_mode() const { return field_ == nullptr; }
  const CyclotomicFieldPtr& field() const { return field_; }
  /// Size 1 in rational mode, d in a field.
  const std::vector<mpq_class>& coefficients() const { return coefficients_.get(); }
  /// The value is rational (every coefficient of c^i, i >= 1, is zero).
  bool is_rational() const;
  /// The value when is_rational().
  const mpq_class& rational_value() const { return coefficients_[0]; }

  bool is_zero() const;
  /// -1, 0, 1, certified.
  int sign() const;
  /// Throws std::domain_error for 0.
  Cyclotomic inverse() const;
  /// Output only.
  double to_double() const;
  /// Output only: doubles lo <= value <= hi.
  std::pair<double, double> to_interval() const;
  /// Output only: hi + lo within `bound` (about 2^-106 relative) of the value
  /// (CyclotomicField::double_double_enclosure; rationals likewise).
  void double_double_enclosure(double& hi, double& lo, double& bound) const;

  Cyclotomic operator-() const;
  Cyclotomic& operator+=(const Cyclotomic& o);
  Cyclotomic& operator-=(const Cyclotomic& o);
  Cyclotomic& operator*=(const Cyclotomic& o);
  Cyclotomic& operator/=(const Cyclotomic& o);

  friend Cyclotomic operator+(Cyclotomic a, const Cyclotomic& b) { return a += b; }
  friend Cyclotomic operator-(Cyclotomic a, const Cyclotomic& b) { return a -= b; }
  friend Cyclotomic operator*(Cyclotomic a, const Cyclotomic& b) { return a *= b; }
  friend Cyclotomic operator/(Cyclotomic a, const Cyclotomic& b) { return a /= b; }

  friend bool operator==(const Cyclotomic& a, const Cyclotomic& b);
  friend bool operator!=(const Cyclotomic& a, const Cyclotomic& b) { return !(a == b); }
  /// Sign of a − b.
  friend int compare(const Cyclotomic& a, const Cyclotomic& b);
  friend bool operator<(const Cyclotomic& a, const Cyclotomic& b) { return compare(a, b) < 0; }
  friend bool operator>(const Cyclotomic& a, const Cyclotomic& b) { return compare(a, b) > 0; }
  friend bool operator<=(const Cyclotomic& a, const Cyclotomic& b) { return compare(a, b) <= 0; }
  friend bool operator>=(const Cyclotomic& a, const Cyclotomic& b) { return compare(a, b) >= 0; }

  /// Rational mode: the rational ("3/4"); field element: "K<m>[a0, a1, ..., a_{d-1}]".
  friend std::ostream& operator<<(std::ostream& os, const Cyclotomic& x);

private:
  /// The field of a binary operation (null if both are rational); throws std::invalid_argument
  /// for elements of different fields.
  static CyclotomicFieldPtr common_field(const Cyclotomic& a, const Cyclotomic& b);
  /// Coefficients of this in `field` (a copy, promoted from rational mode when needed).
  std::vector<mpq_class> coefficients_in(const CyclotomicFieldPtr& field) const;

  CyclotomicFieldPtr field_;
  CoefficientVector coefficients_;
};

Cyclotomic abs(const Cyclotomic& x);

} // namespace symmesh::number
