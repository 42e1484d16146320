// The real cyclotomic field K_m = Q(cos 2π/m): exact arithmetic, certified sign (MPFR).
#include "symmesh/number/cyclotomic.h"
#include "symmesh/number/error_free.h"

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <ostream>
#include <stdexcept>
#include <string>

namespace symmesh::number {

namespace {

void trim(QPolynomial& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}

int deg(const QPolynomial& p) {
  return static_cast<int>(p.size()) - 1;
}

/// Quotient and remainder of a by b (b non-zero) over Q.
std::pair<QPolynomial, QPolynomial> divmod(QPolynomial a, const QPolynomial& b) {
  trim(a);
  const int db = deg(b);
  if (db < 0) throw std::domain_error("polynomial division by zero");
  QPolynomial q(std::max(0, deg(a) - db + 1));
  while (deg(a) >= db) {
    const int shift = deg(a) - db;
    mpq_class f = a.back() / b.back();
    q[shift] = f;
    for (int i = 0; i <= db; ++i) a[shift + i] -= f * b[i];
    a.pop_back(); // leading term cancelled exactly
    trim(a);
  }
  trim(q);
  return {q, a};
}

QPolynomial mul(const QPolynomial& a, const QPolynomial& b) {
  if (a.empty() || b.empty()) return {};
  QPolynomial r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  trim(r);
  return r;
}

QPolynomial sub(QPolynomial a, const QPolynomial& b) {
  if (a.size() < b.size()) a.resize(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) a[i] -= b[i];
  trim(a);
  return a;
}

/// Common denominator form: v = num / den.
void to_common(const std::vector<mpq_class>& v, std::vector<mpz_class>& num, mpz_class& den) {
  den = 1;
  for (const auto& x : v)
    if (x.get_den() != 1) mpz_lcm(den.get_mpz_t(), den.get_mpz_t(), x.get_den_mpz_t());
  num.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] == 0) {
      num[i] = 0;
    } else if (den == 1) {
      num[i] = v[i].get_num();
    } else {
      mpz_divexact(num[i].get_mpz_t(), den.get_mpz_t(), v[i].get_den_mpz_t());
      num[i] *= v[i].get_num();
    }
  }
}

/// Numerators below 2^31 in magnitude: products and sums of up to 256 of them fit an __int128
/// with room for a reduction factor below 2^40 (see multiply_small).
constexpr std::size_t kSmallBits = 31;
constexpr std::size_t kSmallReductionBits = 40;

bool fits_small(const std::vector<mpz_class>& v) {
  return std::all_of(v.begin(), v.end(), [](const mpz_class& x) {
    return mpz_sizeinbase(x.get_mpz_t(), 2) <= kSmallBits;
  });
}

mpz_class from_int128(__int128 v) {
  const bool negative = v < 0;
  unsigned __int128 u = negative ? -static_cast<unsigned __int128>(v) : v;
  mpz_class r(static_cast<unsigned long>(static_cast<unsigned long long>(u >> 64)));
  r <<= 64;
  r += mpz_class(static_cast<unsigned long>(static_cast<unsigned long long>(u)));
  return negative ? mpz_class(-r) : r;
}

/// RAII MPFR interval [lo, hi].
struct Interval {
  mpfr_t lo, hi;
  explicit Interval(mpfr_prec_t p) {
    mpfr_init2(lo, p);
    mpfr_init2(hi, p);
  }
  ~Interval() {
    mpfr_clear(lo);
    mpfr_clear(hi);
  }
  Interval(const Interval&) = delete;
  Interval& operator=(const Interval&) = delete;
};

/// r = a·b with outward rounding; r must not alias a or b.
void interval_mul(Interval& r, const Interval& a, const Interval& b, mpfr_prec_t p) {
  mpfr_t t;
  mpfr_init2(t, p);
  const mpfr_srcptr as[2] = {a.lo, a.hi};
  const mpfr_srcptr bs[2] = {b.lo, b.hi};
  bool first = true;
  for (auto x : as)
    for (auto y : bs) {
      mpfr_mul(t, x, y, MPFR_RNDD);
      if (first || mpfr_less_p(t, r.lo)) mpfr_set(r.lo, t, MPFR_RNDD);
      mpfr_mul(t, x, y, MPFR_RNDU);
      if (first || mpfr_greater_p(t, r.hi)) mpfr_set(r.hi, t, MPFR_RNDU);
      first = false;
    }
  mpfr_clear(t);
}

constexpr long start_precision = 128;

} // namespace

// ---------------------------------------------------------------- free functions

int euler_phi(int m) {
  if (m < 1) throw std::invalid_argument("euler_phi: m must be >= 1");
  int result = m;
  int n = m;
  for (int p = 2; p * p <= n; ++p)
    if (n % p == 0) {
      while (n % p == 0) n /= p;
      result -= result / p;
    }
  if (n > 1) result -= result / n;
  return result;
}

QPolynomial cyclotomic_polynomial(int m) {
  if (m < 1) throw std::invalid_argument("cyclotomic_polynomial: m must be >= 1");
  static std::mutex mutex;
  static std::map<int, QPolynomial> cache;
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(m);
    if (it != cache.end()) return it->second;
  }
  QPolynomial p(m + 1);
  p[0] = -1;
  p[m] = 1;
  for (int e = 1; e < m; ++e)
    if (m % e == 0) {
      auto [q, r] = divmod(p, cyclotomic_polynomial(e));
      if (!r.empty()) throw std::logic_error("cyclotomic_polynomial: inexact division");
      p = std::move(q);
    }
  std::lock_guard<std::mutex> lock(mutex);
  cache.emplace(m, p);
  return p;
}

QPolynomial minimal_polynomial_2cos(int m) {
  if (m < 3) throw std::invalid_argument("minimal_polynomial_2cos: m must be >= 3");
  const QPolynomial phi = cyclotomic_polynomial(m);
  const int d = deg(phi) / 2;
  // D_k(y) with x^k + x^{-k} = D_k(x + 1/x).
  QPolynomial d_prev{mpq_class(2)}, d_cur{mpq_class(0), mpq_class(1)};
  QPolynomial result{phi[d]};
  for (int k = 1; k <= d; ++k) {
    if (k > 1) {
      QPolynomial next = sub(mul(QPolynomial{mpq_class(0), mpq_class(1)}, d_cur), d_prev);
      d_prev = std::move(d_cur);
      d_cur = std::move(next);
    }
    if (phi[d + k] != phi[d - k]) throw std::logic_error("cyclotomic polynomial not palindromic");
    QPolynomial term = d_cur;
    for (auto& t : term) t *= phi[d + k];
    if (result.size() < term.size()) result.resize(term.size());
    for (std::size_t i = 0; i < term.size(); ++i) result[i] += term[i];
  }
  trim(result);
  if (deg(result) != d || result.back() != 1)
    throw std::logic_error("minimal_polynomial_2cos: not monic of degree phi(m)/2");
  return result;
}

int smallest_field_for_orders(const std::vector<int>& orders) {
  long m = 4;
  for (int n : orders) {
    if (n <= 0) throw std::invalid_argument("smallest_field_for_orders: orders must be > 0");
    m = std::lcm(m, static_cast<long>(n));
    if (m > (1L << 30)) throw std::overflow_error("smallest_field_for_orders: m too large");
  }
  return static_cast<int>(m);
}

// ---------------------------------------------------------------- CyclotomicField

struct CyclotomicField::Powers {
  long precision;
  std::vector<std::unique_ptr<Interval>> c_pow; // enclosures of c^0 .. c^{d-1}
};

CyclotomicFieldPtr CyclotomicField::get(int m) {
  static std::mutex mutex;
  static std::map<int, CyclotomicFieldPtr> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(m);
  if (it != cache.end()) return it->second;
  CyclotomicFieldPtr field =
      std::make_shared<CyclotomicField>(Private{}, m, minimal_polynomial_2cos(m));
  cache.emplace(m, field);
  return field;
}

CyclotomicFieldPtr CyclotomicField::make_with_minimal_polynomial_for_testing(int m,
                                                                             QPolynomial monic) {
  return std::make_shared<CyclotomicField>(Private{}, m, std::move(monic));
}

CyclotomicField::CyclotomicField(Private, int m, QPolynomial minimal_polynomial)
    : m_(m), minpoly_(std::move(minimal_polynomial)) {
  if (m < 3) throw std::invalid_argument("CyclotomicField: m must be >= 3");
  trim(minpoly_);
  if (minpoly_.size() < 2 || minpoly_.back() != 1)
    throw std::invalid_argument("CyclotomicField: minimal polynomial must be monic of degree >= 1");
  d_ = deg(minpoly_);
  // c^d = −Σ_{i<d} p_i c^i; c^{d+j} = c·c^{d+j-1}.
  c_to_d_.resize(d_);
  for (int i = 0; i < d_; ++i) c_to_d_[i] = -minpoly_[i];
  std::vector<std::vector<mpq_class>> rows;
  if (d_ >= 2) rows.push_back(c_to_d_);
  for (int j = 1; j <= d_ - 2; ++j) rows.push_back(times_c(rows.back()));
  reduction_den_ = 1;
  for (const auto& row : rows)
    for (const auto& x : row)
      mpz_lcm(reduction_den_.get_mpz_t(), reduction_den_.get_mpz_t(), x.get_den_mpz_t());
  for (const auto& row : rows) {
    std::vector<mpz_class> num(d_);
    for (int i = 0; i < d_; ++i) {
      mpq_class scaled = row[i] * mpq_class(reduction_den_);
      num[i] = scaled.get_num();
    }
    reduction_num_.push_back(std::move(num));
  }
  small_reduction_ =
      d_ <= 256 && mpz_sizeinbase(reduction_den_.get_mpz_t(), 2) <= kSmallReductionBits;
  for (const auto& row : reduction_num_) {
    std::vector<long long> small;
    for (const auto& x : row) {
      small_reduction_ =
          small_reduction_ && mpz_sizeinbase(x.get_mpz_t(), 2) <= kSmallReductionBits;
      small.push_back(small_reduction_ ? x.get_si() : 0);
    }
    reduction_small_.push_back(std::move(small));
  }
  const auto pw = powers(start_precision);
  mpfr_t rest;
  mpfr_init2(rest, start_precision);
  for (const auto& p : pw->c_pow) {
    c_pow_double_.push_back(mpfr_get_d(p->lo, MPFR_RNDN));
    mpfr_sub_d(rest, p->lo, c_pow_double_.back(), MPFR_RNDN); // exact: cancels leading bits
    c_pow_low_.push_back(mpfr_get_d(rest, MPFR_RNDN));
  }
  mpfr_clear(rest);
}

CyclotomicField::~CyclotomicField() = default;

bool CyclotomicField::same_field(const CyclotomicField& other) const {
  return this == &other || (m_ == other.m_ && minpoly_ == other.minpoly_);
}

Cyclotomic CyclotomicField::element(std::vector<mpq_class> coefficients) const {
  return Cyclotomic(shared_from_this(), std::move(coefficients));
}
Cyclotomic CyclotomicField::zero() const {
  return element({});
}
Cyclotomic CyclotomicField::one() const {
  return element({mpq_class(1)});
}
Cyclotomic CyclotomicField::generator() const {
  if (d_ == 1) return element({c_to_d_[0]});
  return element({mpq_class(0), mpq_class(1)});
}

std::vector<mpq_class> CyclotomicField::times_c(const std::vector<mpq_class>& v) const {
  std::vector<mpq_class> w(d_);
  for (int i = 0; i + 1 < d_; ++i) w[i + 1] = v[i];
  if (v[d_ - 1] != 0)
    for (int i = 0; i < d_; ++i) w[i] += v[d_ - 1] * c_to_d_[i];
  return w;
}

const std::vector<mpq_class>& CyclotomicField::two_cos_cached(long j) const {
  // Caller holds mutex_. 2cos(jθ) = c·2cos((j−1)θ) − 2cos((j−2)θ).
  while (static_cast<long>(two_cos_.size()) <= j) {
    const std::size_t n = two_cos_.size();
    std::vector<mpq_class> v(d_);
    if (n == 0) {
      v[0] = 2;
    } else if (n == 1) {
      v = generator().coefficients();
    } else {
      v = times_c(two_cos_[n - 1]);
      for (int i = 0; i < d_; ++i) v[i] -= two_cos_[n - 2][i];
    }
    two_cos_.push_back(std::move(v));
  }
  return two_cos_[j];
}

Cyclotomic CyclotomicField::two_cos_2pi_over_m(long j) const {
  j %= m_;
  if (j < 0) j += m_;
  if (j > m_ / 2) j = m_ - j;
  std::vector<mpq_class> v;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    v = two_cos_cached(j);
  }
  return element(std::move(v));
}

Cyclotomic CyclotomicField::cos_2pi(long k, long n) const {
  if (n <= 0 || m_ % n != 0)
    throw std::invalid_argument("cos_2pi: n must divide m = " + std::to_string(m_));
  const long j = (k % n) * (m_ / n);
  return two_cos_2pi_over_m(j) / Cyclotomic(2);
}

Cyclotomic CyclotomicField::sin_2pi(long k, long n) const {
  if (m_ % 4 != 0) throw std::invalid_argument("sin_2pi: m must be a multiple of 4");
  if (n <= 0 || m_ % n != 0)
    throw std::invalid_argument("sin_2pi: n must divide m = " + std::to_string(m_));
  const long j = (k % n) * (m_ / n) - m_ / 4;
  return two_cos_2pi_over_m(j) / Cyclotomic(2);
}

bool CyclotomicField::is_half_two_cos(const Cyclotomic& x, long j, int sign) const {
  if (sign != 1 && sign != -1)
    throw std::invalid_argument("is_cos_2pi/is_sin_2pi: sign must be +1 or -1");
  if (x.field() && !x.field()->same_field(*this)) return false;
  j %= m_;
  if (j < 0) j += m_;
  if (j > m_ / 2) j = m_ - j;
  const auto& xs = x.coefficients();
  mpq_class twice; // 2·sign·x_i, compared with the cached 2cos coefficient
  std::lock_guard<std::mutex> lock(mutex_);
  const auto& tc = two_cos_cached(j);
  for (std::size_t i = 0; i < tc.size(); ++i) {
    if (i >= xs.size()) {
      if (sgn(tc[i]) != 0) return false;
      continue;
    }
    mpq_mul_2exp(twice.get_mpq_t(), xs[i].get_mpq_t(), 1);
    if (sign < 0) mpq_neg(twice.get_mpq_t(), twice.get_mpq_t());
    if (!mpq_equal(twice.get_mpq_t(), tc[i].get_mpq_t())) return false;
  }
  return true;
}

bool CyclotomicField::is_cos_2pi(const Cyclotomic& x, long k, long n, int sign) const {
  if (n <= 0 || m_ % n != 0)
    throw std::invalid_argument("is_cos_2pi: n must divide m = " + std::to_string(m_));
  return is_half_two_cos(x, (k % n) * (m_ / n), sign);
}

bool CyclotomicField::is_sin_2pi(const Cyclotomic& x, long k, long n, int sign) const {
  if (m_ % 4 != 0) throw std::invalid_argument("is_sin_2pi: m must be a multiple of 4");
  if (n <= 0 || m_ % n != 0)
    throw std::invalid_argument("is_sin_2pi: n must divide m = " + std::to_string(m_));
  return is_half_two_cos(x, (k % n) * (m_ / n) - m_ / 4, sign);
}

std::vector<mpq_class> CyclotomicField::multiply_small(const std::vector<mpz_class>& an,
                                                       const mpz_class& ad,
                                                       const std::vector<mpz_class>& bn,
                                                       const mpz_class& bd) const {
  // The same computation as the general path of multiply, on machine integers: |an|, |bn| <
  // 2^31, so each product sum is below 2^70, and each reduced coefficient below
  // 2^70 · 2^40 · 2d < 2^119 (d <= 256).
  std::vector<long long> x(d_), y(d_);
  for (int i = 0; i < d_; ++i) {
    x[std::size_t(i)] = an[std::size_t(i)].get_si();
    y[std::size_t(i)] = bn[std::size_t(i)].get_si();
  }
  std::vector<__int128> p(std::size_t(2 * d_ - 1), 0);
  for (int i = 0; i < d_; ++i) {
    if (x[std::size_t(i)] == 0) continue;
    for (int j = 0; j < d_; ++j)
      p[std::size_t(i + j)] += static_cast<__int128>(x[std::size_t(i)]) * y[std::size_t(j)];
  }
  const long long rd = reduction_den_.get_si();
  std::vector<__int128> r(static_cast<std::size_t>(d_));
  for (int i = 0; i < d_; ++i) r[std::size_t(i)] = p[std::size_t(i)] * rd;
  for (int j = 0; j + 1 < d_; ++j) {
    const __int128 top = p[std::size_t(d_ + j)];
    if (top == 0) continue;
    const auto& row = reduction_small_[std::size_t(j)];
    for (int i = 0; i < d_; ++i) r[std::size_t(i)] += top * row[std::size_t(i)];
  }
  mpz_class den = ad * bd;
  if (rd != 1) den *= reduction_den_;
  std::vector<mpq_class> out(static_cast<std::size_t>(d_));
  for (int i = 0; i < d_; ++i) {
    if (r[std::size_t(i)] == 0) continue;
    out[std::size_t(i)] = mpq_class(from_int128(r[std::size_t(i)]), den);
    out[std::size_t(i)].canonicalize();
  }
  return out;
}

std::vector<mpq_class> CyclotomicField::multiply(const std::vector<mpq_class>& a,
                                                 const std::vector<mpq_class>& b) const {
  std::vector<mpz_class> an, bn;
  mpz_class ad, bd;
  to_common(a, an, ad);
  to_common(b, bn, bd);
  if (small_reduction_ && fits_small(an) && fits_small(bn)) return multiply_small(an, ad, bn, bd);
  std::vector<mpz_class> p(2 * d_ - 1);
  for (int i = 0; i < d_; ++i) {
    if (an[i] == 0) continue;
    for (int j = 0; j < d_; ++j)
      if (bn[j] != 0) mpz_addmul(p[i + j].get_mpz_t(), an[i].get_mpz_t(), bn[j].get_mpz_t());
  }
  const bool unit_den = reduction_den_ == 1;
  std::vector<mpz_class> r(d_);
  for (int i = 0; i < d_; ++i) {
    if (unit_den)
      r[i] = p[i];
    else
      r[i] = p[i] * reduction_den_;
  }
  for (int j = 0; j + 1 < d_; ++j) {
    const mpz_class& top = p[d_ + j];
    if (top == 0) continue;
    for (int i = 0; i < d_; ++i)
      if (reduction_num_[j][i] != 0)
        mpz_addmul(r[i].get_mpz_t(), top.get_mpz_t(), reduction_num_[j][i].get_mpz_t());
  }
  mpz_class den = ad * bd;
  if (!unit_den) den *= reduction_den_;
  std::vector<mpq_class> out(d_);
  for (int i = 0; i < d_; ++i) {
    if (r[i] == 0) continue;
    out[i] = mpq_class(r[i], den);
    out[i].canonicalize();
  }
  return out;
}

std::vector<mpq_class> CyclotomicField::inverse(const std::vector<mpq_class>& a) const {
  // Extended Euclid over Q[x]: s·a ≡ r (mod P); at the end r is a non-zero constant.
  QPolynomial r0 = minpoly_, r1(a.begin(), a.end());
  trim(r1);
  if (r1.empty()) throw std::domain_error("Cyclotomic: division by zero");
  QPolynomial s0, s1{mpq_class(1)};
  // Monic remainders (s scaled alike) keep the intermediate rationals small.
  const auto make_monic = [](QPolynomial& r, QPolynomial& s) {
    const mpq_class inv = 1 / r.back();
    for (auto& x : r) x *= inv;
    for (auto& x : s) x *= inv;
  };
  make_monic(r1, s1);
  while (deg(r1) > 0) {
    auto [q, r] = divmod(r0, r1);
    if (r.empty())
      throw std::logic_error("CyclotomicField: minimal polynomial is reducible (gcd with an "
                             "element is not constant)");
    QPolynomial s = sub(s0, mul(q, s1));
    make_monic(r, s);
    r0 = std::move(r1);
    r1 = std::move(r);
    s0 = std::move(s1);
    s1 = std::move(s);
  }
  std::vector<mpq_class> out(d_);
  const mpq_class inv = 1 / r1[0];
  // s1 has degree < d (deg s_k < deg P − deg r_{k-1}), still reduce defensively.
  const QPolynomial rem = divmod(s1, minpoly_).second;
  for (std::size_t i = 0; i < rem.size(); ++i) out[i] = rem[i] * inv;
  return out;
}

std::shared_ptr<const CyclotomicField::Powers> CyclotomicField::powers(long precision) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& p : powers_)
    if (p->precision == precision) return p;
  auto result = std::make_shared<Powers>();
  result->precision = precision;
  const mpfr_prec_t prec = precision;
  // c ∈ [2cos(arg_hi), 2cos(arg_lo)], arg = 2π/m ∈ (0, 2π/3]: cos is decreasing there.
  Interval c(prec), arg(prec);
  mpfr_const_pi(arg.lo, MPFR_RNDD);
  mpfr_const_pi(arg.hi, MPFR_RNDU);
  mpfr_mul_ui(arg.lo, arg.lo, 2, MPFR_RNDD);
  mpfr_mul_ui(arg.hi, arg.hi, 2, MPFR_RNDU);
  mpfr_div_ui(arg.lo, arg.lo, static_cast<unsigned long>(m_), MPFR_RNDD);
  mpfr_div_ui(arg.hi, arg.hi, static_cast<unsigned long>(m_), MPFR_RNDU);
  mpfr_cos(c.lo, arg.hi, MPFR_RNDD);
  mpfr_cos(c.hi, arg.lo, MPFR_RNDU);
  mpfr_mul_ui(c.lo, c.lo, 2, MPFR_RNDD);
  mpfr_mul_ui(c.hi, c.hi, 2, MPFR_RNDU);
  auto one = std::make_unique<Interval>(prec);
  mpfr_set_ui(one->lo, 1, MPFR_RNDD);
  mpfr_set_ui(one->hi, 1, MPFR_RNDU);
  result->c_pow.push_back(std::move(one));
  for (int i = 1; i < d_; ++i) {
    auto next = std::make_unique<Interval>(prec);
    interval_mul(*next, *result->c_pow.back(), c, prec);
    result->c_pow.push_back(std::move(next));
  }
  powers_.push_back(result);
  return result;
}

namespace {

/// Enclosure of Σ a_i c^i (or of a_0 when powers is null) at precision `prec`.
void evaluate(Interval& sum, const std::vector<mpq_class>& a,
              const std::vector<std::unique_ptr<Interval>>* powers, mpfr_prec_t prec) {
  mpfr_set_zero(sum.lo, 1);
  mpfr_set_zero(sum.hi, 1);
  Interval coef(prec), term(prec);
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == 0) continue;
    mpfr_set_q(coef.lo, a[i].get_mpq_t(), MPFR_RNDD);
    mpfr_set_q(coef.hi, a[i].get_mpq_t(), MPFR_RNDU);
    if (i == 0) {
      mpfr_add(sum.lo, sum.lo, coef.lo, MPFR_RNDD);
      mpfr_add(sum.hi, sum.hi, coef.hi, MPFR_RNDU);
      continue;
    }
    interval_mul(term, coef, *(*powers)[i], prec);
    mpfr_add(sum.lo, sum.lo, term.lo, MPFR_RNDD);
    mpfr_add(sum.hi, sum.hi, term.hi, MPFR_RNDU);
  }
}

bool excludes_zero(const Interval& x) {
  return mpfr_sgn(x.lo) > 0 || mpfr_sgn(x.hi) < 0;
}

bool all_zero(const std::vector<mpq_class>& a) {
  return std::all_of(a.begin(), a.end(), [](const mpq_class& x) { return x == 0; });
}

bool only_constant(const std::vector<mpq_class>& a) {
  return std::all_of(a.begin() + 1, a.end(), [](const mpq_class& x) { return x == 0; });
}

} // namespace

bool CyclotomicField::filtered_value(const std::vector<mpq_class>& a, double& value,
                                     double& bound) const {
  // Each |â_i − a_i| <= 2u|a_i| (mpq_get_d truncates), |ĉ^i − c^i| <= 1.01u|c^i|, and d products
  // and sums add at most (d + 2)u relative to Σ|a_i c^i| (u = 2^-53, no underflow or overflow:
  // the range test below). The bound (4d + 16)u·Σ|â_i ĉ^i| covers that with a wide margin.
  double sum = 0, magnitude = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == 0) continue;
    const double x = a[i].get_d();
    if (!(std::fabs(x) > 1e-250 && std::fabs(x) < 1e250)) return false;
    const double t = x * c_pow_double_[i];
    sum += t;
    magnitude += std::fabs(t);
  }
  value = sum;
  bound = magnitude * (4.0 * d_ + 16.0) * 0x1p-53;
  return true;
}

namespace {
/// q = hi + lo with |hi + lo − q| <= 2u²|q| when its numerator and denominator are doubles:
/// hi = n/d rounded, and the remainder n − hi·d is a double (that of a correctly rounded
/// division), so fma gives it exactly; lo is its quotient by d, rounded.
bool split_rational(const mpq_class& q, double& hi, double& lo) {
  if (mpz_sizeinbase(q.get_num_mpz_t(), 2) > 53 || mpz_sizeinbase(q.get_den_mpz_t(), 2) > 53)
    return false;
  const double n = mpz_get_d(q.get_num_mpz_t()), d = mpz_get_d(q.get_den_mpz_t());
  hi = n / d;
  lo = std::fma(-hi, d, n) / d;
  return true;
}

} // namespace

bool CyclotomicField::double_double_value(const std::vector<mpq_class>& a, double& value,
                                          double& bound) const {
  // Per non-zero coefficient a_i = h + l (split_rational) and c^i = C + L (c_pow_double_,
  // c_pow_low_; |C + L − c^i| <= 1.01u²|c^i| from the 128-bit enclosure), with u = 2^-53:
  //   p + q = h·C exactly (fma), r = h·L + l·C rounded twice, l·L dropped;
  //   s + t = s + p exactly (two_sum), and e accumulates t + q + r.
  // Errors, with P = Σ|h·C| (`mag`) and Q = Σ(|t| + |q| + |r|) (`small`), both as computed:
  //   the splits of a_i and c^i and the dropped l·L: <= 5.1u²|h·C| per term;
  //   r's two roundings: <= 2u(|h·L| + |l·C|)(1 + u) <= 4.1u²|h·C|;
  //   e, a floating sum of 3d terms: <= γ_3d·Q <= 3.1d·u·Q (3d·u < 0.01);
  //   value = s + e rounded: <= u|value|.
  // The bound 2u|value| + 16u²·P + 4d·u·Q covers these with margin for the rounding of P and Q.
  constexpr double u = 0x1p-53;
  double s = 0, e = 0, mag = 0, small = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == 0) continue;
    double h = 0, l = 0;
    if (!split_rational(a[i], h, l) || !(std::fabs(h) > 1e-200 && std::fabs(h) < 1e200))
      return false;
    const double C = c_pow_double_[i], L = c_pow_low_[i];
    const double p = h * C;
    const double q = std::fma(h, C, -p);
    const double r = h * L + l * C;
    double t = 0;
    two_sum(s, p, s, t);
    e += (t + q) + r;
    mag += std::fabs(p);
    small += std::fabs(t) + std::fabs(q) + std::fabs(r);
  }
  if (!(mag < 1e200)) return false;
  value = s + e;
  bound = 2 * u * std::fabs(value) + 16 * u * u * mag + 4.0 * d_ * u * small;
  return true;
}

int CyclotomicField::filtered_sign(const std::vector<mpq_class>& a) const {
  double sum = 0, bound = 0;
  if (!filtered_value(a, sum, bound)) return 0;
  if (sum > bound) return 1;
  if (sum < -bound) return -1;
  return 0;
}

int CyclotomicField::filtered_sign_of_difference(const std::vector<mpq_class>& a,
                                                 const std::vector<mpq_class>& b) const {
  // As filtered_sign, for Σ (a_i − b_i) c^i without forming a − b: each of the 2d products
  // carries the error bound of filtered_sign, and the 2d-term sum at most (2d + 2)u more.
  if (&a == &b) return 0; // shared storage (copy-on-write copies): equal
  double sum = 0, magnitude = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (const int side : {1, -1}) {
      const mpq_class& q = side > 0 ? a[i] : b[i];
      if (q == 0) continue;
      const double x = q.get_d();
      if (!(std::fabs(x) > 1e-250 && std::fabs(x) < 1e250)) return 0;
      const double t = x * c_pow_double_[i];
      sum += side * t;
      magnitude += std::fabs(t);
    }
  }
  const double bound = magnitude * (8.0 * d_ + 16.0) * 0x1p-53;
  if (sum > bound) return 1;
  if (sum < -bound) return -1;
  return 0;
}

int CyclotomicField::sign(const std::vector<mpq_class>& a) const {
  if (only_constant(a)) return sgn(a[0]);
  if (const int s = filtered_sign(a)) return s;
  double value = 0, bound = 0;
  if (double_double_value(a, value, bound) && (value > bound || value < -bound))
    return value > 0 ? 1 : -1;
  // a ≠ 0 and 1, c, ..., c^{d-1} are linearly independent over Q (for the true minimal
  // polynomial), so the value is non-zero and the enclosures shrink onto it.
  for (long prec = start_precision; prec <= max_precision_bits; prec *= 2) {
    auto pw = powers(prec);
    Interval sum(prec);
    evaluate(sum, a, &pw->c_pow, prec);
    if (mpfr_sgn(sum.lo) > 0) return 1;
    if (mpfr_sgn(sum.hi) < 0) return -1;
  }
  throw std::runtime_error("CyclotomicField::sign: no decision at the maximal precision (wrong "
                           "minimal polynomial?)");
}

std::pair<double, double> CyclotomicField::to_interval(const std::vector<mpq_class>& a) const {
  if (all_zero(a)) return {0.0, 0.0};
  // Lazy kernels call this per node. The filter's enclosure (one rounding step wider on each
  // side; its bound has a wide margin over the true error) when it is narrow; where the power
  // basis cancels it is wide (up to 2^-10 relative for a cosine of K_128), and so is every
  // interval computed from it, sending predicates to exact evaluation: then the double-double
  // enclosure, a few units in the last place at the cost of d fma, if it is the narrower.
  const auto enclosure = [](double v, double b) {
    return std::pair{std::nextafter(v - b, -HUGE_VAL), std::nextafter(v + b, HUGE_VAL)};
  };
  double sum = 0, bound = 0;
  const bool filtered = filtered_value(a, sum, bound) && (sum > bound || sum < -bound);
  if (filtered && bound <= 0x1p-50 * std::fabs(sum)) return enclosure(sum, bound);
  double value = 0, value_bound = 0;
  if (double_double_value(a, value, value_bound) && (value > value_bound || value < -value_bound))
    if (!filtered || value_bound < bound) return enclosure(value, value_bound);
  if (filtered) return enclosure(sum, bound);
  for (long prec = start_precision;; prec *= 2) {
    auto pw = powers(prec);
    Interval sum(prec);
    evaluate(sum, a, &pw->c_pow, prec);
    if (excludes_zero(sum) || prec * 2 > max_precision_bits)
      return {mpfr_get_d(sum.lo, MPFR_RNDD), mpfr_get_d(sum.hi, MPFR_RNDU)};
  }
}

namespace {
/// hi + lo ± bound from an enclosure [x.lo, x.hi] at `prec` bits: hi = RN(x.lo), lo = RN(x.lo −
/// hi) (exact in MPFR: x.lo − hi has at most prec bits), bound = |x.lo − hi − lo| + (x.hi − x.lo),
/// rounded up.
void split_enclosure(const Interval& x, mpfr_prec_t prec, double& hi, double& lo, double& bound) {
  mpfr_t r;
  mpfr_init2(r, prec);
  hi = mpfr_get_d(x.lo, MPFR_RNDN);
  mpfr_sub_d(r, x.lo, hi, MPFR_RNDN);
  lo = mpfr_get_d(r, MPFR_RNDN);
  mpfr_sub_d(r, r, lo, MPFR_RNDU);
  mpfr_abs(r, r, MPFR_RNDU);
  const double rest = mpfr_get_d(r, MPFR_RNDU);
  mpfr_sub(r, x.hi, x.lo, MPFR_RNDU);
  bound = std::nextafter(rest + mpfr_get_d(r, MPFR_RNDU), HUGE_VAL);
  mpfr_clear(r);
}
} // namespace

void CyclotomicField::double_double_enclosure(const std::vector<mpq_class>& a, double& hi,
                                              double& lo, double& bound) const {
  constexpr long prec = 256;
  const auto pw = powers(prec);
  Interval sum(prec);
  evaluate(sum, a, &pw->c_pow, prec);
  split_enclosure(sum, prec, hi, lo, bound);
}

double CyclotomicField::to_double(const std::vector<mpq_class>& a) const {
  if (all_zero(a)) return 0.0;
  for (long prec = start_precision;; prec *= 2) {
    auto pw = powers(prec);
    Interval sum(prec);
    evaluate(sum, a, &pw->c_pow, prec);
    const double lo = mpfr_get_d(sum.lo, MPFR_RNDN), hi = mpfr_get_d(sum.hi, MPFR_RNDN);
    if ((excludes_zero(sum) && lo == hi) || prec >= 4096) return lo;
  }
}

// ---------------------------------------------------------------- Cyclotomic

Cyclotomic::Cyclotomic(CyclotomicFieldPtr field, std::vector<mpq_class> coefficients)
    : field_(std::move(field)), coefficients_(std::move(coefficients)) {
  for (auto& x : coefficients_) x.canonicalize(); // == compares coefficients
  if (!field_) {
    if (coefficients_.size() > 1 && !only_constant(coefficients_))
      throw std::invalid_argument("Cyclotomic: a rational needs one coefficient");
    coefficients_.resize(1);
    return;
  }
  if (static_cast<int>(coefficients_.size()) > field_->degree())
    throw std::invalid_argument("Cyclotomic: more coefficients than the field degree");
  coefficients_.resize(field_->degree());
}

bool Cyclotomic::is_rational() const {
  return only_constant(coefficients_);
}

bool Cyclotomic::is_zero() const {
  return all_zero(coefficients_);
}

int Cyclotomic::sign() const {
  if (!field_) return sgn(coefficients_[0]);
  return field_->sign(coefficients_);
}

Cyclotomic Cyclotomic::inverse() const {
  if (is_zero()) throw std::domain_error("Cyclotomic: division by zero");
  if (!field_) return Cyclotomic(mpq_class(1 / coefficients_[0]));
  return Cyclotomic(field_, field_->inverse(coefficients_));
}

double Cyclotomic::to_double() const {
  if (!field_) {
    mpfr_t t;
    mpfr_init2(t, 53);
    mpfr_set_q(t, coefficients_[0].get_mpq_t(), MPFR_RNDN);
    const double r = mpfr_get_d(t, MPFR_RNDN);
    mpfr_clear(t);
    return r;
  }
  return field_->to_double(coefficients_);
}

void Cyclotomic::double_double_enclosure(double& hi, double& lo, double& bound) const {
  if (field_) return field_->double_double_enclosure(coefficients_, hi, lo, bound);
  constexpr long prec = 256;
  Interval x(prec);
  mpfr_set_q(x.lo, coefficients_[0].get_mpq_t(), MPFR_RNDD);
  mpfr_set_q(x.hi, coefficients_[0].get_mpq_t(), MPFR_RNDU);
  split_enclosure(x, prec, hi, lo, bound);
}

std::pair<double, double> Cyclotomic::to_interval() const {
  if (!field_) {
    mpfr_t lo, hi;
    mpfr_init2(lo, 53);
    mpfr_init2(hi, 53);
    mpfr_set_q(lo, coefficients_[0].get_mpq_t(), MPFR_RNDD);
    mpfr_set_q(hi, coefficients_[0].get_mpq_t(), MPFR_RNDU);
    std::pair<double, double> r{mpfr_get_d(lo, MPFR_RNDD), mpfr_get_d(hi, MPFR_RNDU)};
    mpfr_clear(lo);
    mpfr_clear(hi);
    return r;
  }
  return field_->to_interval(coefficients_);
}

CyclotomicFieldPtr Cyclotomic::common_field(const Cyclotomic& a, const Cyclotomic& b) {
  if (!a.field_) return b.field_;
  if (!b.field_) return a.field_;
  if (a.field_ != b.field_ && !a.field_->same_field(*b.field_))
    throw std::invalid_argument("Cyclotomic: elements of different fields");
  return a.field_;
}

std::vector<mpq_class> Cyclotomic::coefficients_in(const CyclotomicFieldPtr& field) const {
  if (!field || field_) return coefficients_;
  std::vector<mpq_class> v(field->degree());
  v[0] = coefficients_[0];
  return v;
}

Cyclotomic Cyclotomic::operator-() const {
  Cyclotomic r = *this;
  for (auto& x : r.coefficients_) x = -x;
  return r;
}

Cyclotomic& Cyclotomic::operator+=(const Cyclotomic& o) {
  auto f = common_field(*this, o);
  if (!field_ && f) {
    coefficients_ = coefficients_in(f);
    field_ = f;
  }
  if (o.field_ || !f) {
    // Most coefficients of a point's or a rotation's entry are 0 (a few powers of ζ): skipping
    // them saves mpq_add's gcds and temporaries, which dominated the exact steps in K_256.
    for (std::size_t i = 0; i < coefficients_.size(); ++i) {
      const auto& c = o.coefficients_[i];
      if (sgn(c) == 0) continue;
      if (sgn(coefficients_[i]) == 0)
        coefficients_[i] = c;
      else
        coefficients_[i] += c;
    }
  } else {
    coefficients_[0] += o.coefficients_[0];
  }
  return *this;
}

Cyclotomic& Cyclotomic::operator-=(const Cyclotomic& o) {
  auto f = common_field(*this, o);
  if (!field_ && f) {
    coefficients_ = coefficients_in(f);
    field_ = f;
  }
  if (o.field_ || !f) {
    for (std::size_t i = 0; i < coefficients_.size(); ++i) {
      const auto& c = o.coefficients_[i];
      if (sgn(c) == 0) continue;
      if (sgn(coefficients_[i]) == 0)
        mpq_neg(coefficients_[i].get_mpq_t(), c.get_mpq_t());
      else
        coefficients_[i] -= c;
    }
  } else {
    coefficients_[0] -= o.coefficients_[0];
  }
  return *this;
}

Cyclotomic& Cyclotomic::operator*=(const Cyclotomic& o) {
  auto f = common_field(*this, o);
  if (!f) {
    coefficients_[0] *= o.coefficients_[0];
  } else if (!o.field_ || !field_ || o.is_rational() || is_rational()) {
    // One side is a rational scalar (rotation matrices and translations are full of 0, ±1 and
    // ±1/2): d rational products instead of a polynomial product and its reduction.
    const bool scalar_is_o = !o.field_ || o.is_rational();
    const mpq_class s = scalar_is_o ? o.coefficients_[0] : coefficients_[0];
    if (!scalar_is_o)
      coefficients_ = o.coefficients_; // this is the scalar, s keeps its value
    else if (!field_)
      coefficients_ = coefficients_in(f);
    field_ = f;
    if (s == 0) {
      coefficients_ = CoefficientVector(std::size_t(f->degree()));
    } else if (s != 1) {
      for (auto& x : coefficients_) x *= s;
    }
  } else {
    coefficients_ = f->multiply(coefficients_, o.coefficients_);
  }
  return *this;
}

Cyclotomic& Cyclotomic::operator/=(const Cyclotomic& o) {
  if (o.is_zero()) throw std::domain_error("Cyclotomic: division by zero");
  if (!o.field_ || o.is_rational()) {
    // Division by a rational: no inverse in the field needed.
    const mpq_class inv = 1 / o.coefficients_[0];
    auto f = common_field(*this, o);
    if (!field_ && f) {
      coefficients_ = coefficients_in(f);
      field_ = f;
    }
    for (auto& x : coefficients_) x *= inv;
    return *this;
  }
  return *this *= o.inverse();
}

bool operator==(const Cyclotomic& a, const Cyclotomic& b) {
  auto f = Cyclotomic::common_field(a, b);
  if (!f) return a.coefficients_[0] == b.coefficients_[0];
  if (a.field_ && b.field_) return a.coefficients_ == b.coefficients_;
  const Cyclotomic& r = a.field_ ? b : a; // the rational one
  const Cyclotomic& e = a.field_ ? a : b;
  return e.is_rational() && e.coefficients_[0] == r.coefficients_[0];
}

int compare(const Cyclotomic& a, const Cyclotomic& b) {
  if (a.is_rational() && b.is_rational()) return sgn(a.coefficients_[0] - b.coefficients_[0]);
  const auto f = Cyclotomic::common_field(a, b);
  if (a.field_ && b.field_) {
    if (const int s = f->filtered_sign_of_difference(a.coefficients_, b.coefficients_)) return s;
  }
  return (a - b).sign();
}

std::ostream& operator<<(std::ostream& os, const Cyclotomic& x) {
  if (!x.field_) return os << x.coefficients_[0];
  os << 'K' << x.field_->m() << '[';
  for (std::size_t i = 0; i < x.coefficients_.size(); ++i)
    os << (i ? ", " : "") << x.coefficients_[i];
  return os << ']';
}

Cyclotomic abs(const Cyclotomic& x) {
  return x.sign() < 0 ? -x : x;
}

} // namespace symmesh::number
