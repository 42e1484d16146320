// The real cyclotomic field K_m = Q(cos 2π/m) as the core's exact number type —
// spec/number-type.md (#the-field, #operations, #certified-sign-and-why-it-terminates,
// #test-hook); ARCHITECTURE.md "Exactness"
//
// Properties of symmesh::number::Cyclotomic on random elements of random fields K_m,
// m ∈ {5, 7, 8, 12, 16, 20, 32, 60, 128}, every equality exact (coefficient comparison):
//  - field axioms: + and × associative and commutative, distributive, neutral elements,
//    additive inverse, a ≠ 0 ⇒ a·a⁻¹ = 1, no zero divisors; also with rational-mode operands
//    (Cyclotomic(q) before a field is chosen) on either side, and with aliased operands and
//    copies that share their coefficient storage;
//  - the rotation group: rot(2π/n)^n = I exactly (and no smaller power is I), every power
//    rot(2π/n)^j = rot(2πj/n), rot(2πk1/n)∘rot(2πk2/n) = rot(2π(k1+k2)/n), about random
//    rational centres (core::RigidTransformation<Cyclotomic, 2>); cos² + sin² = 1 for every k;
//  - the certified sign agrees with an independent evaluation Σ a_i (2cos 2π/m)^i in plain MPFR
//    at 4000 bits whenever |value| > 2^-3000 (values down to 2^-2500 are generated on purpose),
//    and compare() is a total order (reflexive, antisymmetric, transitive, translation invariant);
//  - the hypothesis "the minimal polynomial is the right one" is necessary: over a wrong monic
//    polynomial of the same degree (make_with_minimal_polynomial_for_testing: another
//    cyclotomic minimal polynomial, the true one perturbed, (y - r)·Q, Q²) the same battery of
//    checks finds a violation in every case (zero divisors, an inverse that throws
//    std::logic_error, the Chebyshev recurrence of 2cos(2πj/m) broken at j = m/2, cos² + sin² ≠ 1,
//    rot^n ≠ I, or the sign of a product disagreeing with the true value). Detection is not
//    luck: across the fold j = m/2 the recurrence holds modulo P' only if P' divides
//    ∏_{e | m} P_e (P_e the minimal polynomial of 2cos(2π/e)); for m odd in the list the only
//    monic divisor of degree φ(m)/2 is P_m, and for 4 | m, cos² + sin² = 1 at k = 0 adds
//    P' | D_{m/4}², which for the m listed leaves only P_m as well.
#include "proofs-checks/cyclotomic_generators.h"
#include "proofs-checks/registry.h"

#include <nlohmann/json.hpp>

#include <sstream>
#include <stdexcept>

namespace symmesh::proofs {
namespace {

using namespace cyclo;

constexpr const char* kLemma = "Cyclotomic_field";

// ----- cases -----------------------------------------------------------------------------------

/// A field (true or with a wrong minimal polynomial), three elements, a rotation order n | m
/// (when 4 | m), two angles and a rotation centre.
struct FieldCase {
  int m = 0;
  CyclotomicFieldPtr field;
  std::string kind = "true minimal polynomial";
  bool reducible = false;
  std::vector<Cyclotomic> xs;
  int n = 1;
  long k1 = 0, k2 = 0;
  KPoint center;
  std::string recipe;
};
std::ostream& operator<<(std::ostream& os, const FieldCase& c) {
  return os << c.recipe;
}

/// num/den in lowest terms: gmpxx's mpq_class(num, den) is not canonicalised, and Cyclotomic
/// stores input rationals as given (a non-canonical 2/2 would then compare unequal to 1).
mpq_class canonical(const mpz_class& num, const mpz_class& den) {
  mpq_class q(num, den);
  q.canonicalize();
  return q;
}

std::string text_of(const Cyclotomic& x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

void describe(FieldCase& c) {
  std::ostringstream os;
  os << "K_" << c.m << " over " << polynomial_text(c.field->minimal_polynomial()) << " (" << c.kind
     << "); elements";
  for (const auto& x : c.xs) os << " " << x;
  if (c.m % 4 == 0)
    os << "; n = " << c.n << ", k1 = " << c.k1 << ", k2 = " << c.k2 << ", centre ("
       << text_of(c.center[0]) << ", " << text_of(c.center[1]) << ")";
  c.recipe = os.str();
}

/// Moves the coefficient vectors of `xs` (elements of the true K_m) into `f` (same degree).
std::vector<Cyclotomic> rehome(const CyclotomicFieldPtr& f, const std::vector<Cyclotomic>& xs) {
  std::vector<Cyclotomic> out;
  for (const auto& x : xs)
    out.push_back(x.is_rational_mode() ? x : Cyclotomic(f, x.coefficients()));
  return out;
}

enum class FieldKind { truth, wrong, zero_divisors };

/// m from `moduli`; three random elements; with `wrong`, the same coefficient vectors over a wrong
/// minimal polynomial; with `zero_divisors`, a reducible one and its two factors as a and b.
rc::Gen<FieldCase> field_case(std::vector<int> moduli, FieldKind kind) {
  return rc::gen::exec([moduli, kind] {
    FieldCase c;
    c.m = pick_of(moduli);
    const auto truth = CyclotomicField::get(c.m);
    for (int i = 0; i < 3; ++i) c.xs.push_back(random_element(truth));
    c.field = truth;
    if (kind != FieldKind::truth) {
      const WrongField w = wrong_field(c.m, kind == FieldKind::zero_divisors);
      c.field = w.field;
      c.kind = w.kind;
      c.reducible = w.reducible;
      c.xs = rehome(w.field, c.xs);
      if (kind == FieldKind::zero_divisors) {
        c.xs[0] = evaluate_in(w.field, w.factor_a);
        c.xs[1] = evaluate_in(w.field, w.factor_b);
      }
    }
    if (c.m % 4 == 0) {
      const auto ds = divisors(c.m);
      c.n = rare(30) ? c.m : pick_of(ds); // n = m: every rotation of the field
      c.k1 = pick(-2 * c.n, 2 * c.n);
      c.k2 = pick(-2 * c.n, 2 * c.n);
    }
    c.center = chance(40) ? make_point(0, 0)
                          : make_point(Cyclotomic(random_rational(9, 4)),
                                       Cyclotomic(random_rational(9, 4)));
    describe(c);
    return c;
  });
}

/// The failure record: the case and what failed.
auto record(const FieldCase& c, const std::string& what) {
  return [&c, what] {
    nlohmann::ordered_json j;
    j["lemma"] = kLemma;
    j["failed"] = what;
    j["m"] = c.m;
    j["minimal_polynomial"] = polynomial_text(c.field->minimal_polynomial());
    j["kind"] = c.kind;
    j["number_format"] = "K<m>[a0, a1, ...] = sum a_i (2cos(2pi/m))^i";
    std::vector<std::string> xs;
    for (const auto& x : c.xs) xs.push_back(text_of(x));
    j["elements"] = xs;
    j["recipe"] = c.recipe;
    return j.dump(1);
  };
}
auto no_picture() {
  return [] { return std::string(); };
}

#define FIELD_ASSERT(cond, c, what) SYMMESH_PROOF_ASSERT(cond, record(c, what), no_picture())

// ----- the checks (shared by the holds and the counterexample properties) ----------------------

/// Violated field axioms on (a, b, c), by name; empty if none.
std::vector<std::string> axiom_violations(const FieldCase& fc) {
  std::vector<std::string> v;
  const auto& f = fc.field;
  const Cyclotomic &a = fc.xs[0], &b = fc.xs[1], &c = fc.xs[2];
  const Cyclotomic zero = f->zero(), one = f->one();
  const auto check = [&v](bool ok, const char* name) {
    if (!ok) v.push_back(name);
  };
  check(a + b == b + a, "a+b = b+a");
  check((a + b) + c == a + (b + c), "(a+b)+c = a+(b+c)");
  check(a * b == b * a, "ab = ba");
  check((a * b) * c == a * (b * c), "(ab)c = a(bc)");
  check(a * (b + c) == a * b + a * c, "a(b+c) = ab+ac");
  check((a + b) * c == a * c + b * c, "(a+b)c = ac+bc");
  check(a + zero == a && zero + a == a, "a+0 = a");
  check(a * one == a && one * a == a, "a·1 = a");
  check(a + (-a) == zero && (a - a).is_zero(), "a+(-a) = 0");
  check(a - b == a + (-b), "a-b = a+(-b)");
  // Mixed operands: a rational-mode Cyclotomic(q) (no field yet) on either side is promoted.
  const mpq_class q(-7, 3);
  const Cyclotomic rq(q), fq = f->element({q});
  check(a * rq == a * fq && rq * a == fq * a && rq * a == a * rq, "q·a = a·q = [q]·a");
  check(a + rq == a + fq && rq + a == fq + a && rq + a == a + rq, "q+a = a+q = [q]+a");
  check(rq - a == fq - a && a - rq == a - fq && rq - a == -(a - rq), "q-a = -(a-q)");
  check(Cyclotomic(1) * a == a && Cyclotomic(0) * a == zero && Cyclotomic(0) + a == a,
        "1·a = a, 0·a = 0, 0+a = a (rational mode)");
  // Aliasing: copies may share storage; operands may be the same object.
  {
    Cyclotomic x = a, y = a;
    x += x;
    y *= Cyclotomic(2);
    check(x == y && x == a + a, "x += x");
    x = a;
    x -= x;
    check(x.is_zero(), "x -= x");
    x = a;
    x *= x;
    check(x == a * a, "x *= x");
    x = a;
    const Cyclotomic copy = x;
    check(compare(x, copy) == 0 && compare(x, x) == 0 && x == copy, "compare(x, copy of x) = 0");
    x += b;
    check(copy == a && x == a + b, "writing a copy leaves the original");
  }
  check(!(a.is_zero() != (a == zero)), "is_zero() = (a == 0)");
  for (const Cyclotomic* x : {&a, &b}) {
    if (x->is_zero()) continue;
    try {
      const Cyclotomic inv = x->inverse();
      check(*x * inv == one, "a·a⁻¹ = 1");
      check(inv.inverse() == *x, "(a⁻¹)⁻¹ = a");
      check((c / *x) * *x == c, "(c/a)·a = c");
    } catch (const std::logic_error& e) {
      v.push_back(std::string("a⁻¹ throws std::logic_error: ") + e.what());
    }
  }
  check(a.is_zero() || b.is_zero() || !(a * b).is_zero(), "no zero divisors");
  return v;
}

/// c·2cos(2πj/m) = 2cos(2π(j+1)/m) + 2cos(2π(j-1)/m) for j = 1..m with the field's table (which
/// folds j > m/2 to m - j): the recurrence across the fold needs the right minimal polynomial.
std::vector<std::string> chebyshev_violations(const FieldCase& fc) {
  const auto& f = fc.field;
  const Cyclotomic c = f->generator();
  for (long j = 1; j <= fc.m; ++j)
    if (c * f->two_cos_2pi_over_m(j) != f->two_cos_2pi_over_m(j + 1) + f->two_cos_2pi_over_m(j - 1))
      return {"Chebyshev recurrence 2cos·2cos(2πj/m) at j = " + std::to_string(j)};
  return {};
}

/// cos² + sin² = 1 for every k = 0..n (and -1), with n | m.
std::vector<std::string> pythagoras_violations(const CyclotomicFieldPtr& f, long n) {
  for (long k = -1; k <= n; ++k) {
    const Cyclotomic co = f->cos_2pi(k, n), si = f->sin_2pi(k, n);
    if (co * co + si * si != Cyclotomic(1))
      return {"cos² + sin² = 1 at 2π·" + std::to_string(k) + "/" + std::to_string(n)};
  }
  return {};
}

/// The rotation group generated by rot(2π/n) about the centre, exactly; empty if it holds.
std::vector<std::string> rotation_violations(const FieldCase& fc) {
  const auto& f = fc.field;
  const long n = fc.n;
  try {
    const KMotion r = rotation(f, 1, n, fc.center);
    KMotion p; // I
    for (long j = 1; j <= n; ++j) {
      p = r * p;
      if (j < n && p.is_identity()) return {"rot(2π/n)^j = I for j < n"};
      if (p != rotation(f, j, n, fc.center)) return {"rot(2π/n)^j != rot(2πj/n)"};
    }
    if (!p.is_identity()) return {"rot(2π/n)^n != I"};
    const KMotion a = rotation(f, fc.k1, n, fc.center), b = rotation(f, fc.k2, n, fc.center);
    if (a * b != rotation(f, fc.k1 + fc.k2, n, fc.center))
      return {"rot(2πk1/n)∘rot(2πk2/n) != rot(2π(k1+k2)/n)"};
    if (a.inverse() != rotation(f, -fc.k1, n, fc.center)) return {"rot(2πk/n)⁻¹ != rot(-2πk/n)"};
    if (a * a.inverse() != KMotion()) return {"R R⁻¹ != I"};
    if (a.determinant_of_linear_part() != Cyclotomic(1)) return {"det rot != 1"};
    if (!a.is_valid()) return {"rot not orthogonal"};
    if (a(fc.center) != fc.center) return {"the centre moves"};
  } catch (const std::invalid_argument& e) {
    return {std::string("rotation rejected (std::invalid_argument): ") + e.what()};
  }
  return {};
}

/// x − r for the two dyadic rationals r bracketing the true value v (r_lo <= v < r_lo + 2^-40):
/// the certified sign must be the sign of v − r. x is a value computed in the field, v its
/// intended value computed independently.
std::vector<std::string> bracket_violations(const Cyclotomic& x, const BigFloat& v,
                                            const char* what) {
  const mpq_class lo = dyadic_floor(v, 40);
  const mpq_class hi = lo + mpq_class(1, mpz_class(1) << 40);
  std::vector<std::string> out;
  for (const mpq_class& r : {lo, hi}) {
    BigFloat d(kBits);
    mpfr_sub_q(d.get(), v.get(), r.get_mpq_t(), MPFR_RNDN);
    const int t = trusted_sign(d);
    if (t != 0 && (x - Cyclotomic(r)).sign() != t)
      out.push_back(std::string("certified sign of ") + what + " - r disagrees with MPFR");
  }
  return out;
}

BigFloat product(const BigFloat& a, const BigFloat& b) {
  BigFloat p(kBits);
  mpfr_mul(p.get(), a.get(), b.get(), MPFR_RNDN);
  return p;
}

std::vector<std::string> sign_violations(const FieldCase& fc) {
  const Cyclotomic &a = fc.xs[0], &b = fc.xs[1], &c = fc.xs[2];
  const BigFloat va = mpfr_value(a), vb = mpfr_value(b), vc = mpfr_value(c);
  std::vector<std::string> out;
  const int t = trusted_sign(va);
  if (t != 0 && a.sign() != t) out.push_back("sign(a) != MPFR sign");
  for (auto& s : bracket_violations(a * b, product(va, vb), "ab")) out.push_back(s);
  for (auto& s : bracket_violations(b * c, product(vb, vc), "bc")) out.push_back(s);
  return out;
}

/// The whole battery.
std::vector<std::string> battery(const FieldCase& fc) {
  std::vector<std::string> v = axiom_violations(fc);
  const auto add = [&v](std::vector<std::string> w) { v.insert(v.end(), w.begin(), w.end()); };
  add(sign_violations(fc));
  add(chebyshev_violations(fc));
  if (fc.m % 4 == 0) {
    try {
      add(pythagoras_violations(fc.field, fc.m));
    } catch (const std::exception& e) {
      v.push_back(std::string("cos/sin table: ") + e.what());
    }
    add(rotation_violations(fc));
  }
  return v;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : "; ") + x;
  return s;
}

/// A short class of a violation, for the tag statistics.
std::string category(const std::string& v) {
  static const std::pair<const char*, const char*> keys[] = {
      {"zero divisors", "zero divisors"},
      {"logic_error", "inverse throws"},
      {"a·a⁻¹", "a*a^-1 != 1"},
      {"Chebyshev", "Chebyshev recurrence"},
      {"cos² + sin²", "cos^2 + sin^2 != 1"},
      {"rotation rejected", "rotation not orthogonal"},
      {"rot", "rotation group"},
      {"sign", "sign != MPFR"}};
  for (const auto& [key, name] : keys)
    if (v.find(key) != std::string::npos) return name;
  return v;
}

// ----- properties --------------------------------------------------------------------------------

void field_axioms(const FieldCase& c) {
  const auto v = axiom_violations(c);
  FIELD_ASSERT(v.empty(), c, joined(v));
}

void rotation_group(const FieldCase& c) {
  RC_TAG("n = " + std::to_string(c.n));
  const auto v = rotation_violations(c);
  FIELD_ASSERT(v.empty(), c, joined(v));
}

/// cos² + sin² = 1 for every k, and the table's symmetries (periodicity, parity, double angle).
void pythagoras(const FieldCase& c) {
  const auto& f = c.field;
  const long n = c.n;
  const auto v = pythagoras_violations(f, n);
  FIELD_ASSERT(v.empty(), c, joined(v));
  for (long k = 0; k < n; ++k) {
    const Cyclotomic co = f->cos_2pi(k, n), si = f->sin_2pi(k, n);
    FIELD_ASSERT(f->cos_2pi(k + n, n) == co && f->sin_2pi(k - n, n) == si, c, "periodicity");
    FIELD_ASSERT(f->cos_2pi(-k, n) == co && f->sin_2pi(-k, n) == -si, c, "parity");
    FIELD_ASSERT(f->cos_2pi(2 * k, n) == Cyclotomic(2) * co * co - Cyclotomic(1) &&
                     f->sin_2pi(2 * k, n) == Cyclotomic(2) * si * co,
                 c, "double angle");
  }
}

/// The certified sign of x against MPFR, and the output enclosure around the MPFR value.
void sign_matches(const FieldCase& c, const Cyclotomic& x, const BigFloat& v, const char* what) {
  const int t = trusted_sign(v);
  const int s = x.sign();
  FIELD_ASSERT((s == 0) == x.is_zero(), c, std::string("sign 0 iff zero: ") + what);
  if (t != 0) FIELD_ASSERT(s == t, c, std::string("certified sign != MPFR sign: ") + what);
  FIELD_ASSERT((-x).sign() == -s && abs(x).sign() == (s != 0), c,
               std::string("sign of -x, |x|: ") + what);
  const auto [lo, hi] = x.to_interval();
  FIELD_ASSERT(lo <= hi, c, std::string("to_interval lo <= hi: ") + what);
  if (!x.is_zero() && trusted_sign(v) != 0) {
    FIELD_ASSERT(mpfr_cmp_d(v.get(), lo) >= 0 && mpfr_cmp_d(v.get(), hi) <= 0, c,
                 std::string("to_interval does not enclose the value: ") + what);
    if (exponent_of(v) > -1000)
      FIELD_ASSERT(lo > 0 || hi < 0, c, std::string("to_interval contains 0: ") + what);
  }
}

/// Precision classes for the tags.
std::string magnitude_tag(const BigFloat& v) {
  if (mpfr_zero_p(v.get())) return "|v| = 0";
  const long e = exponent_of(v);
  if (e >= -20) return "|v| >= 2^-20";
  if (e >= -200) return "2^-200 <= |v| < 2^-20";
  if (e >= -1000) return "2^-1000 <= |v| < 2^-200";
  if (e > -kTrustExponent) return "2^-3000 < |v| < 2^-1000";
  return "|v| <= 2^-3000 (not compared)";
}

void certified_sign(const FieldCase& c) {
  const Cyclotomic &a = c.xs[0], &b = c.xs[1];
  const BigFloat va = mpfr_value(a), vb = mpfr_value(b);
  sign_matches(c, a, va, "a");
  // a - r for a dyadic r within 2^-k of the value: the certified sign needs about k bits.
  static const long ks[] = {4, 30, 100, 300, 1000, 1800, 2500};
  const long k = ks[pick(0, 6)];
  const mpq_class r =
      dyadic_floor(va, k) + (chance(50) ? mpq_class(0) : mpq_class(1, mpz_class(1) << k));
  const Cyclotomic near = a - Cyclotomic(r);
  BigFloat vn(kBits);
  mpfr_sub_q(vn.get(), va.get(), r.get_mpq_t(), MPFR_RNDN);
  RC_TAG(magnitude_tag(vn));
  sign_matches(c, near, vn, "a - r (r within 2^-k of a)");
  // products: the field's multiplication against the product of the independent values.
  const auto pv = bracket_violations(a * b, product(va, vb), "ab");
  FIELD_ASSERT(pv.empty(), c, joined(pv));
  sign_matches(c, a * b, product(va, vb), "ab");
}

/// compare() on triples of nearby values: a total order consistent with ==, MPFR, translations
/// and scalings.
void compare_order(const FieldCase& c) {
  const auto& f = c.field;
  const Cyclotomic base = c.xs[0];
  std::vector<Cyclotomic> t;
  for (int i = 0; i < 3; ++i) {
    const long k = pick(1, 3) == 1 ? pick(1, 12) : pick(100, 2000);
    switch (pick(0, 3)) {
    case 0:
      t.push_back(base);
      break;
    case 1:
      t.push_back(base + Cyclotomic(canonical(pick(-3, 3), mpz_class(1) << k)));
      break;
    case 2:
      t.push_back(base + random_element(f) * Cyclotomic(mpq_class(1, mpz_class(1) << k)));
      break;
    default:
      t.push_back(random_element(f));
    }
  }
  std::vector<BigFloat> v;
  for (const auto& x : t) v.push_back(mpfr_value(x));
  const Cyclotomic shift = c.xs[1];
  const mpq_class q = canonical(pick(1, 9), pick(1, 9));
  int equal_pairs = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    FIELD_ASSERT(compare(t[i], t[i]) == 0, c, "compare(a, a) = 0");
    for (std::size_t j = 0; j < 3; ++j) {
      const int cij = compare(t[i], t[j]);
      FIELD_ASSERT(cij == -compare(t[j], t[i]), c, "antisymmetry");
      FIELD_ASSERT((cij == 0) == (t[i] == t[j]), c,
                   "compare = 0 iff ==: " + text_of(t[i]) + " vs " + text_of(t[j]) + ", compare " +
                       std::to_string(cij));
      FIELD_ASSERT((t[i] < t[j]) == (cij < 0) && (t[i] <= t[j]) == (cij <= 0) &&
                       (t[i] > t[j]) == (cij > 0) && (t[i] >= t[j]) == (cij >= 0),
                   c, "operators agree with compare");
      FIELD_ASSERT(int(CGAL::compare(t[i], t[j])) == cij, c, "CGAL::compare agrees");
      FIELD_ASSERT(compare(t[i] + shift, t[j] + shift) == cij, c, "translation invariance");
      FIELD_ASSERT(compare(t[i] * Cyclotomic(q), t[j] * Cyclotomic(q)) == cij &&
                       compare(t[i] * Cyclotomic(-q), t[j] * Cyclotomic(-q)) == -cij,
                   c, "scaling by ±q");
      BigFloat d(kBits);
      mpfr_sub(d.get(), v[i].get(), v[j].get(), MPFR_RNDN);
      const int ts = trusted_sign(d);
      if (ts != 0) FIELD_ASSERT(cij == ts, c, "compare agrees with MPFR");
      if (i < j && cij == 0) ++equal_pairs;
      for (std::size_t l = 0; l < 3; ++l) {
        const int cjl = compare(t[j], t[l]), cil = compare(t[i], t[l]);
        if (cij <= 0 && cjl <= 0) FIELD_ASSERT(cil <= 0, c, "transitivity of <=");
        if (cij < 0 && cjl <= 0) FIELD_ASSERT(cil < 0, c, "transitivity of <");
      }
    }
  }
  RC_TAG(std::to_string(equal_pairs) + " equal pair(s)");
}

void battery_holds(const FieldCase& c) {
  const auto v = battery(c);
  FIELD_ASSERT(v.empty(), c, joined(v));
}

void battery_detects(const FieldCase& c) {
  const auto v = battery(c);
  RC_TAG(c.kind);
  if (!v.empty()) RC_TAG(c.kind + ": " + category(v.front()));
  FIELD_ASSERT(!v.empty(), c, "no check detected the wrong minimal polynomial");
}

rc::detail::Property with(std::vector<int> moduli, FieldKind kind, void (*body)(const FieldCase&)) {
  return rc::detail::toProperty([moduli, kind, body] { body(*field_case(moduli, kind)); });
}

} // namespace

void register_cyclotomic_field(std::vector<Property>& p) {
  const auto& all = field_moduli();
  const auto& rot = rotation_moduli();
  p.push_back({kLemma, "field_axioms", 2, Kind::holds,
               "K_m, m ∈ {5,7,8,12,16,20,32,60,128}, random elements (dense, sparse, monomials, "
               "rationals, table values cos(2πk/n), products): + and × associative and "
               "commutative, distributive, neutral elements, additive inverse, a ≠ 0 ⇒ a·a⁻¹ = 1 "
               "and (a⁻¹)⁻¹ = a, no zero divisors, rational-mode operands on either side, aliased "
               "operands and shared copies (x += x, x -= x, compare(x, copy of x) = 0), all "
               "with exact ==",
               [all] { return with(all, FieldKind::truth, field_axioms); },
               [all] { return with(all, FieldKind::zero_divisors, field_axioms); }});
  p.push_back({kLemma, "rotation_group", 2, Kind::holds,
               "K_m with 4 | m, n | m, random rational centre: rot(2π/n)^j = rot(2πj/n) for "
               "j = 1..n, no power below n is I, rot(2π/n)^n = I exactly, "
               "rot(2πk1/n)∘rot(2πk2/n) = rot(2π(k1+k2)/n), R⁻¹ = rot(-2πk/n), det R = 1 "
               "(core::RigidTransformation<Cyclotomic, 2>)",
               [rot] { return with(rot, FieldKind::truth, rotation_group); },
               [rot] { return with(rot, FieldKind::wrong, rotation_group); }});
  p.push_back({kLemma, "cos2_plus_sin2_every_k", 2, Kind::holds,
               "K_m with 4 | m, n | m: cos²(2πk/n) + sin²(2πk/n) = 1 exactly for every k, with "
               "periodicity, parity and the double-angle formulas of the cos/sin table",
               [rot] { return with(rot, FieldKind::truth, pythagoras); },
               [rot] { return with(rot, FieldKind::wrong, pythagoras); }});
  p.push_back({kLemma, "certified_sign_matches_mpfr", 2, Kind::holds,
               "the certified sign of a, of a - r for dyadic r within 2^-k of a (k up to 2500) "
               "and of products ab equals the sign of Σ a_i (2cos 2π/m)^i evaluated in plain "
               "MPFR at 4000 bits whenever |value| > 2^-3000; sign 0 iff zero; to_interval "
               "encloses the value",
               [all] { return with(all, FieldKind::truth, certified_sign); },
               [all] { return with(all, FieldKind::wrong, certified_sign); }});
  p.push_back({kLemma,
               "compare_total_order",
               2,
               Kind::holds,
               "compare() on triples of nearby values (equal, 2^-k apart, k up to 2000): "
               "reflexive, antisymmetric, transitive, 0 iff ==, agrees with <, <=, >, >=, "
               "CGAL::compare and MPFR, invariant under translation and positive scaling",
               [all] { return with(all, FieldKind::truth, compare_order); },
               {}});
  p.push_back({kLemma, "axiom_battery_true_field", 2, Kind::holds,
               "the battery of the wrong-minimal-polynomial counterexample (field axioms, signs "
               "of ab - r against MPFR, the Chebyshev recurrence of 2cos(2πj/m) for j = 1..m, "
               "cos² + sin² = 1 for every k, the rotation group) passes on the true K_m",
               [all] { return with(all, FieldKind::truth, battery_holds); },
               [all] { return with(all, FieldKind::wrong, battery_holds); }});
  p.push_back({kLemma,
               "wrong_minimal_polynomial_counterexample",
               2,
               Kind::counterexample,
               "K_m over a wrong monic polynomial of degree φ(m)/2 (another cyclotomic minimal "
               "polynomial, the true one perturbed, (y - r)·Q, Q²): the same battery finds a "
               "violation in every case (zero divisors, a⁻¹ throwing std::logic_error, the "
               "Chebyshev recurrence, cos² + sin² ≠ 1, rot^n ≠ I, a sign disagreeing with the "
               "true value)",
               [all] { return with(all, FieldKind::wrong, battery_detects); },
               {}});
}

} // namespace symmesh::proofs
