// Generators and independent MPFR evaluation for the K_m proofs-checks (see
// cyclotomic_generators.h; spec/number-type.md).
#include "proofs-checks/cyclotomic_generators.h"

#include "symmesh/core/element_complex.h"
#include "symmesh/io/templated_structure_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <mutex>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace symmesh::proofs::cyclo {

using core::Simplex;
using core::VertexId;

const std::vector<int>& field_moduli() {
  static const std::vector<int> m{5, 7, 8, 12, 16, 20, 32, 60, 128};
  return m;
}

const std::vector<int>& rotation_moduli() {
  static const std::vector<int> m{8, 12, 16, 20, 24, 32, 40, 60, 128};
  return m;
}

std::vector<int> divisors(int m) {
  std::vector<int> out;
  for (int e = 1; e <= m; ++e)
    if (m % e == 0) out.push_back(e);
  return out;
}

// ----- picks -----------------------------------------------------------------------------------

int pick(int lo, int hi) {
  return *rc::gen::resize(100, rc::gen::inRange(lo, hi + 1));
}

bool chance(int percent) {
  return pick(0, 99) < percent;
}

bool rare(int percent) {
  return pick(0, 99) >= 100 - percent;
}

int pick_of(const std::vector<int>& values) {
  return values[static_cast<std::size_t>(pick(0, int(values.size()) - 1))];
}

mpq_class random_rational(int range, int max_den) {
  mpq_class q(pick(-range, range), pick(1, max_den));
  q.canonicalize();
  return q;
}

namespace {

Cyclotomic coefficient_element(const CyclotomicFieldPtr& f) {
  const int d = f->degree();
  std::vector<mpq_class> c(static_cast<std::size_t>(d));
  const bool large = rare(15);
  const int range = large ? 1000000 : 9;
  const int max_den = large ? 1000 : 6;
  switch (pick(0, 5)) {
  case 0: // a rational
    c[0] = random_rational(range, max_den);
    break;
  case 1: // a monomial q c^i
    c[static_cast<std::size_t>(pick(0, d - 1))] = random_rational(range, max_den);
    break;
  case 2: // dense
    for (auto& x : c) x = random_rational(range, max_den);
    break;
  default: // sparse
    for (auto& x : c)
      if (!chance(25)) x = random_rational(range, max_den);
  }
  return f->element(std::move(c));
}

Cyclotomic table_element(const CyclotomicFieldPtr& f) {
  const int m = f->m();
  if (m % 4 == 0 && chance(50)) {
    const auto ds = divisors(m);
    const int n = pick_of(ds);
    const long k = pick(-n, 2 * n);
    return chance(50) ? f->cos_2pi(k, n) : f->sin_2pi(k, n);
  }
  return f->two_cos_2pi_over_m(pick(-m, 2 * m));
}

} // namespace

Cyclotomic random_element(const CyclotomicFieldPtr& f) {
  switch (pick(0, 9)) {
  case 0:
    return table_element(f);
  case 1:
    return coefficient_element(f) * (chance(50) ? table_element(f) : coefficient_element(f));
  case 2:
    return table_element(f) + Cyclotomic(random_rational(9, 6));
  default:
    return coefficient_element(f);
  }
}

// ----- independent evaluation ------------------------------------------------------------------

namespace {
/// 2cos(2π/m) at kBits + 64 bits, round-to-nearest (cached per m).
const BigFloat& two_cos(int m) {
  static std::mutex mutex;
  static std::map<int, BigFloat> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(m);
  if (it != cache.end()) return it->second;
  BigFloat c(kBits + 64);
  mpfr_const_pi(c.get(), MPFR_RNDN);
  mpfr_mul_ui(c.get(), c.get(), 2, MPFR_RNDN);
  mpfr_div_ui(c.get(), c.get(), static_cast<unsigned long>(m), MPFR_RNDN);
  mpfr_cos(c.get(), c.get(), MPFR_RNDN);
  mpfr_mul_ui(c.get(), c.get(), 2, MPFR_RNDN);
  return cache.emplace(m, std::move(c)).first->second;
}
} // namespace

BigFloat mpfr_value(const Cyclotomic& x) {
  BigFloat v(kBits);
  const auto& a = x.coefficients();
  if (x.is_rational_mode()) {
    mpfr_set_q(v.get(), a[0].get_mpq_t(), MPFR_RNDN);
    return v;
  }
  const BigFloat& c = two_cos(x.field()->m());
  BigFloat t(kBits);
  mpfr_set_zero(v.get(), 1);
  for (std::size_t i = a.size(); i-- > 0;) { // Horner
    mpfr_mul(v.get(), v.get(), c.get(), MPFR_RNDN);
    mpfr_set_q(t.get(), a[i].get_mpq_t(), MPFR_RNDN);
    mpfr_add(v.get(), v.get(), t.get(), MPFR_RNDN);
  }
  return v;
}

int trusted_sign(const BigFloat& v) {
  if (mpfr_zero_p(v.get())) return 0;
  if (mpfr_get_exp(v.get()) <= -kTrustExponent) return 0;
  return mpfr_sgn(v.get());
}

mpq_class dyadic_floor(const BigFloat& v, long k) {
  BigFloat t(kBits);
  mpfr_mul_2si(t.get(), v.get(), k, MPFR_RNDN); // exact
  mpz_class z;
  mpfr_get_z(z.get_mpz_t(), t.get(), MPFR_RNDD);
  mpz_class den;
  mpz_ui_pow_ui(den.get_mpz_t(), 2, static_cast<unsigned long>(k));
  mpq_class r(z, den);
  r.canonicalize();
  return r;
}

long exponent_of(const BigFloat& v) {
  return static_cast<long>(mpfr_get_exp(v.get())) - 1;
}

// ----- rotations -------------------------------------------------------------------------------

KPoint make_point(const Cyclotomic& x, const Cyclotomic& y) {
  KPoint p;
  p[0] = x;
  p[1] = y;
  return p;
}

KMotion rotation(const CyclotomicFieldPtr& f, long k, long n, const KPoint& center) {
  return KMotion::rotation_2d(f->cos_2pi(k, n), f->sin_2pi(k, n), center);
}

// ----- wrong minimal polynomials ---------------------------------------------------------------

namespace {

QPolynomial trimmed(QPolynomial p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
  return p;
}

QPolynomial multiply(const QPolynomial& a, const QPolynomial& b) {
  if (a.empty() || b.empty()) return {};
  QPolynomial r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return trimmed(r);
}

/// Minimal polynomials of 2cos(2π/m') of degree `degree`, m' in [3, 600] (cached).
const std::vector<std::pair<int, QPolynomial>>& cyclotomic_minpolys_of_degree(int degree) {
  static std::mutex mutex;
  static std::map<int, std::vector<std::pair<int, QPolynomial>>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(degree);
  if (it != cache.end()) return it->second;
  std::vector<std::pair<int, QPolynomial>> out;
  for (int m = 3; m <= 600; ++m)
    if (number::euler_phi(m) == 2 * degree) out.emplace_back(m, number::minimal_polynomial_2cos(m));
  return cache.emplace(degree, std::move(out)).first->second;
}

/// A random monic polynomial of the given degree: the minimal polynomial of some 2cos(2π/m')
/// when one exists, or small integer coefficients.
QPolynomial random_monic(int degree) {
  const auto& known = cyclotomic_minpolys_of_degree(degree);
  if (!known.empty() && chance(50))
    return known[static_cast<std::size_t>(pick(0, int(known.size()) - 1))].second;
  QPolynomial q(static_cast<std::size_t>(degree + 1));
  for (int i = 0; i < degree; ++i) q[static_cast<std::size_t>(i)] = pick(-3, 3);
  q.back() = 1;
  return q;
}

} // namespace

std::string polynomial_text(const QPolynomial& p) {
  std::ostringstream os;
  bool first = true;
  for (std::size_t i = p.size(); i-- > 0;) {
    if (p[i] == 0) continue;
    mpq_class a = p[i];
    if (!first)
      os << (a < 0 ? " - " : " + ");
    else if (a < 0)
      os << "-";
    first = false;
    a = abs(a);
    if (a != 1 || i == 0) os << a;
    if (i >= 1) os << (a != 1 ? "*" : "") << "y";
    if (i >= 2) os << "^" << i;
  }
  return first ? "0" : os.str();
}

Cyclotomic evaluate_in(const CyclotomicFieldPtr& f, const QPolynomial& p) {
  Cyclotomic r = f->zero();
  const Cyclotomic c = f->generator();
  for (std::size_t i = p.size(); i-- > 0;) r = r * c + Cyclotomic(p[i]);
  return r;
}

WrongField wrong_field(int m, bool reducible_only) {
  const QPolynomial truth = number::minimal_polynomial_2cos(m);
  const int d = int(truth.size()) - 1;
  std::vector<QPolynomial> others;
  for (const auto& [mm, p] : cyclotomic_minpolys_of_degree(d))
    if (p != truth) others.push_back(p);
  // The applicable kinds, so that one pick decides (no redraws: picks replay while shrinking).
  std::vector<int> kinds;
  if (!reducible_only && !others.empty()) kinds.push_back(0);
  if (!reducible_only) kinds.push_back(1);
  kinds.push_back(2);
  if (d % 2 == 0) kinds.push_back(3);
  WrongField w;
  switch (pick_of(kinds)) {
  case 0: // irreducible, wrong
    w.kind = "other_cyclotomic";
    w.poly = others[static_cast<std::size_t>(pick(0, int(others.size()) - 1))];
    break;
  case 1: { // usually irreducible; the checks do not rely on it either way
    w.kind = "perturbed";
    w.poly = truth;
    int delta = pick(-3, 2);
    if (delta >= 0) ++delta;
    w.poly[static_cast<std::size_t>(pick(0, d - 1))] += delta;
    break;
  }
  case 2: // (y - r)·Q: reducible; never P, which is irreducible of degree >= 2
    w.kind = "linear_factor";
    w.factor_a = {-random_rational(4, 3), mpq_class(1)};
    w.factor_b = random_monic(d - 1);
    w.poly = multiply(w.factor_a, w.factor_b);
    w.reducible = true;
    break;
  default: // Q²: reducible; never P, which is square-free
    w.kind = "square";
    w.factor_a = random_monic(d / 2);
    w.factor_b = w.factor_a;
    w.poly = multiply(w.factor_a, w.factor_b);
    w.reducible = true;
  }
  if (d < 2 || w.poly == truth) throw std::logic_error("wrong_field: needs degree >= 2");
  w.field = CyclotomicField::make_with_minimal_polynomial_for_testing(m, w.poly);
  return w;
}

// ----- rotational structures -------------------------------------------------------------------

namespace {

/// Upper bound on the number of cells of AT of a rotational structure (as kMaxAtCells of
/// generators.cpp): about n² · (cells per slice)² exact predicates in K_m per check.
constexpr int kMaxAtCells = 24;

/// 0 < r_1 < ... < r_k with rational steps.
std::vector<mpq_class> random_radii(int k) {
  std::vector<mpq_class> r;
  mpq_class x = 0;
  const int q = pick(1, 3);
  for (int i = 0; i < k; ++i) {
    mpq_class step(pick(1, 4), q);
    step.canonicalize();
    x += step;
    r.push_back(x);
  }
  return r;
}

std::string radii_text(const std::vector<mpq_class>& r) {
  std::ostringstream os;
  os << "{";
  for (std::size_t i = 0; i < r.size(); ++i) os << (i ? ", " : "") << r[i];
  return os.str() + "}";
}

/// The other chain: same outer radius, different interior radii.
std::vector<mpq_class> different_radii(const std::vector<mpq_class>& r, std::string& how) {
  std::vector<mpq_class> s = r;
  const std::size_t k = r.size();
  const int option = k >= 2 ? pick(0, 2) : 0;
  const auto inside = [](const mpq_class& lo, const mpq_class& hi) -> mpq_class {
    mpq_class t(pick(1, 4), 5); // a point strictly inside (lo, hi)
    t.canonicalize();
    return lo + t * (hi - lo);
  };
  if (option == 0) { // an extra interior radius
    const std::size_t i = static_cast<std::size_t>(pick(0, int(k) - 1));
    const mpq_class lo = i == 0 ? mpq_class(0) : r[i - 1];
    s.insert(s.begin() + long(i), inside(lo, r[i]));
    how = "extra radius " + s[i].get_str();
  } else if (option == 1) { // a missing interior radius
    const std::size_t i = static_cast<std::size_t>(pick(0, int(k) - 2));
    how = "missing radius " + s[i].get_str();
    s.erase(s.begin() + long(i));
  } else { // a moved interior radius
    const std::size_t i = static_cast<std::size_t>(pick(0, int(k) - 2));
    const mpq_class lo = i == 0 ? mpq_class(0) : r[i - 1];
    mpq_class v = inside(lo, r[i + 1]);
    if (v == r[i]) v = (v + r[i + 1]) / 2;
    how = "radius " + r[i].get_str() + " moved to " + v.get_str();
    s[i] = v;
  }
  return s;
}

int orientation(const KPoint& a, const KPoint& b, const KPoint& c) {
  return ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).sign();
}

bool strictly_inside(const KPoint& p, const KPoint& a, const KPoint& b, const KPoint& c) {
  const int o = orientation(a, b, c);
  return o != 0 && orientation(a, b, p) == o && orientation(b, c, p) == o &&
         orientation(c, a, p) == o;
}

/// A rational point near a random interior point of triangle t (weights 1..4, rounded to
/// 2^-bits); added and t split into three when it is strictly inside t.
bool add_rational_point(KComplex& mesh, std::vector<std::array<VertexId, 3>>& tris,
                        std::string& recipe) {
  const std::size_t t = static_cast<std::size_t>(pick(0, int(tris.size()) - 1));
  const auto tri = tris[t];
  const int w0 = pick(1, 4), w1 = pick(1, 4), w2 = pick(1, 4);
  KPoint p;
  const mpq_class sum(w0 + w1 + w2);
  for (int i = 0; i < 2; ++i) {
    const Cyclotomic x =
        (Cyclotomic(w0) * mesh.points[tri[0]][i] + Cyclotomic(w1) * mesh.points[tri[1]][i] +
         Cyclotomic(w2) * mesh.points[tri[2]][i]) /
        Cyclotomic(sum);
    p[i] = Cyclotomic(dyadic_floor(mpfr_value(x), pick(2, 12)));
  }
  if (!strictly_inside(p, mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]))
    return false;
  const VertexId v = VertexId(mesh.points.size());
  mesh.points.push_back(p);
  tris[t] = {tri[0], tri[1], v};
  tris.push_back({tri[1], tri[2], v});
  tris.push_back({tri[2], tri[0], v});
  recipe += " +(" + p[0].rational_value().get_str() + ", " + p[1].rational_value().get_str() + ")";
  return true;
}

} // namespace

rc::Gen<RotationalStructure> rotational_structure(bool same_radii) {
  return rc::gen::withSize([same_radii](int size) {
    return rc::gen::exec([same_radii, size] {
      // n = 16 (120 neighbouring pairs, all meeting at the centre) is the costliest: less often.
      static const std::vector<int> orders{3, 4, 5, 6, 8, 5, 10, 8, 12, 16};
      const int top = size < 25 ? 3 : size < 50 ? 6 : 9;
      RotationalStructure s;
      // The checks cost about (cells of AT)² exact predicates in K_m: keep AT at most
      // kMaxAtCells cells (2 per radius and rational point, at most 3 radii, 2 points per slice).
      const auto slice_budget = [&s] { return kMaxAtCells / s.n; };
      s.same_radii = same_radii;
      s.n = orders[static_cast<std::size_t>(pick(0, top))];
      s.m = number::smallest_field_for_orders({s.n});
      if (rare(20) && s.m <= 20) s.m *= pick(2, 3); // a larger field than needed
      const auto f = CyclotomicField::get(s.m);
      const int k = pick(1, std::clamp(slice_budget() / 2, 1, size < 50 ? 2 : 3));
      std::vector<mpq_class> a_side = random_radii(k), b_side = a_side;
      std::string how;
      if (!same_radii) {
        b_side = different_radii(a_side, how);
        if (chance(50)) std::swap(a_side, b_side);
      }
      // Template: O, A_i = (r_i, 0), B_j = s_j (cos 2π/n, sin 2π/n).
      KComplex mesh;
      mesh.points.push_back(make_point(Cyclotomic(0), Cyclotomic(0)));
      for (const auto& x : a_side) mesh.points.push_back(make_point(Cyclotomic(x), Cyclotomic(0)));
      const Cyclotomic co = f->cos_2pi(1, s.n), si = f->sin_2pi(1, s.n);
      for (const auto& x : b_side)
        mesh.points.push_back(make_point(Cyclotomic(x) * co, Cyclotomic(x) * si));
      const auto A = [](std::size_t i) { return VertexId(1 + i); };
      const auto B = [&a_side](std::size_t j) { return VertexId(1 + a_side.size() + j); };
      std::vector<std::array<VertexId, 3>> tris{{0, A(0), B(0)}};
      std::string zip;
      std::size_t i = 0, j = 0;
      while (i + 1 < a_side.size() || j + 1 < b_side.size()) {
        const bool advance_a = j + 1 == b_side.size() || (i + 1 < a_side.size() && chance(50));
        if (advance_a) {
          tris.push_back({A(i), A(i + 1), B(j)});
          ++i;
          zip += "a";
        } else {
          tris.push_back({A(i), B(j), B(j + 1)});
          ++j;
          zip += "b";
        }
      }
      std::string extra;
      const int cells = int(tris.size());
      const int extras = pick(0, std::clamp((slice_budget() - cells) / 2, 0, size < 50 ? 1 : 2));
      for (int e = 0; e < extras; ++e) add_rational_point(mesh, tris, extra);
      for (const auto& t : tris) mesh.elements.push_back(Simplex{t[0], t[1], t[2]});
      mesh = core::face_completion(mesh);
      s.x.templates.push_back({"slice", core::TemplateKind::mesh, std::move(mesh)});
      // Instances: G ∘ rot(2πi/n).
      KMotion g;
      std::string motion = "none";
      if (rare(30)) {
        const KPoint t =
            make_point(Cyclotomic(random_rational(6, 2)), Cyclotomic(random_rational(6, 2)));
        g = KMotion::translation(t);
        motion = "translation (" + t[0].rational_value().get_str() + ", " +
                 t[1].rational_value().get_str() + ")";
        if (rare(50)) {
          g = g * KMotion::signed_permutation({0, 1}, {1, -1}, make_point(0, 0));
          motion += " after reflection in the x-axis";
        }
      }
      const bool one_region = chance(50);
      std::vector<core::InstanceSpec<Cyclotomic, 2>> inst;
      const KPoint origin = make_point(Cyclotomic(0), Cyclotomic(0));
      for (int q = 0; q < s.n; ++q)
        inst.push_back({g * rotation(f, q, s.n, origin), one_region ? 1 : pick(1, 2)});
      s.x.instances.push_back(std::move(inst));
      std::ostringstream rec;
      rec << "rotational slice n=" << s.n << " in K_" << s.m << ", radii on angle 0 "
          << radii_text(a_side) << ", on angle 2pi/n " << radii_text(b_side)
          << (same_radii ? "" : " (" + how + ")") << ", zipper '" << zip << "'"
          << (extra.empty() ? "" : ", rational points" + extra) << ", global motion " << motion;
      s.recipe = rec.str();
      return s;
    });
  });
}

// ----- failure records -------------------------------------------------------------------------

std::string rotational_record(const std::string& lemma, const RotationalStructure& s) {
  // The templated-structure format itself (K_m numbers as "K<m>[a0, ...]"), so that
  // `symmesh check FILE` reads the counterexample in the same field.
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(symmesh::io::to_json(s.x));
  j["description"] = "counterexample of " + lemma + " (" + s.recipe +
                     "; n = " + std::to_string(s.n) + " in K_" + std::to_string(s.m) + ")";
  return j.dump(1);
}

std::string rotational_picture(const RotationalStructure& s) {
  // Output only: the structure instance in doubles.
  std::vector<std::array<double, 6>> tris;
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  const auto& mesh = s.x.templates.at(0).mesh;
  for (const auto& spec : s.x.instances.at(0))
    for (const auto& c : mesh.cells()) {
      std::array<double, 6> t{};
      int k = 0;
      for (VertexId v : c) {
        const auto p = spec.transformation(mesh.points[v]);
        for (int i = 0; i < 2; ++i) {
          const double x = p[i].to_double();
          t[std::size_t(k++)] = x;
          lo[i] = std::min(lo[i], x);
          hi[i] = std::max(hi[i], x);
        }
      }
      tris.push_back(t);
    }
  const double w = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const double scale = 480.0 / (w > 0 ? w : 1.0);
  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"520\" height=\"520\">\n";
  for (const auto& t : tris) {
    os << "<polygon fill=\"#cde\" stroke=\"#124\" stroke-width=\"0.7\" points=\"";
    for (int v = 0; v < 3; ++v)
      os << 20 + (t[std::size_t(2 * v)] - lo[0]) * scale << ","
         << 500 - (t[std::size_t(2 * v + 1)] - lo[1]) * scale << " ";
    os << "\"/>\n";
  }
  os << "</svg>\n";
  return os.str();
}

} // namespace symmesh::proofs::cyclo
