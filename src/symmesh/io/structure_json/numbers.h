/// Reading templated-structure JSON, part 2 (internal): symbolic numbers (cos, sin, sqrt,
/// arithmetic) and the kernel of a document, Q or the real cyclotomic field K_m chosen from the
/// rotation orders it uses — spec/input-format.md#symbolic-numbers, spec/number-type.md
#pragma once
#include "symmesh/io/structure_json/fields.h"
#include "symmesh/io/number_text.h"
#include "symmesh/number/subfield_embedding.h"

#include "symmesh/core/exact_kernel_of.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <CGAL/Lazy_exact_nt.h>

namespace symmesh::io::structure_json {

// ---------------------------------------------------------------------------------------------
// Symbolic numbers and the kernel of a document (spec/input-format.md#symbolic-numbers,
// spec/number-type.md#kernel-choice)

/// The largest m of a field K_m a document may ask for: K_m has degree φ(m)/2, and every
/// product costs about its square, so m = 1024 (degree 256) is already slow.
constexpr long long kMaxFieldOrder = 1024;

/// The field of the document being read, null for the rational kernel. A document is read in
/// one kernel, chosen by a pre-scan before any number is built, so the field is state of the
/// whole read rather than a parameter of every reader function.
thread_local number::CyclotomicFieldPtr t_field;

class FieldScope {
public:
  explicit FieldScope(number::CyclotomicFieldPtr field) { t_field = std::move(field); }
  ~FieldScope() { t_field.reset(); }
  FieldScope(const FieldScope&) = delete;
  FieldScope& operator=(const FieldScope&) = delete;
};

/// The symmetry orders a document needs, each with the first JSON path asking for it.
using OrderDemands = std::map<long long, std::string>;

inline void demand(OrderDemands& d, long long order, const std::string& path) {
  if (order != 1 && order != 2 && order != 4) d.emplace(order, path);
}

/// A leaf of a written number: a rational, cos(2pi*k/n), sin(2pi*k/n) or K<m>[a_0, ...].
struct WrittenNumber {
  enum class Kind { rational, cos, sin, field_element } kind = Kind::rational;
  mpq_class value = 0;    ///< rational
  long long k = 0, n = 1; ///< cos/sin of 2πk/n in lowest terms (n is the order)
  int m = 0;              ///< field_element: K_m
  std::vector<mpq_class> coefficients;
};

/// 2πk/n in lowest terms 2πk'/n' with 0 <= k' < n'.
inline std::pair<long long, long long> reduce_angle(long long k, long long n) {
  long long kk = ((k % n) + n) % n;
  const long long g = std::gcd(kk, n);
  return {kk / g, n / g};
}

/// cos and sin of 2πk/n when they are rational (order n ∈ {1, 2, 4} in lowest terms).
inline std::optional<std::pair<int, int>> rational_cos_sin(long long k, long long n) {
  const auto [kk, order] = reduce_angle(k, n);
  if (order == 1) return std::pair{1, 0};
  if (order == 2) return std::pair{-1, 0};
  if (order == 4) return std::pair{0, kk == 1 ? 1 : -1};
  return std::nullopt;
}

/// A number as written (spec/input-format.md#numbers): an arithmetic expression with + - * /
/// and parentheses over WrittenNumber leaves, e.g. "cos(2pi*1/5)/cos(2pi*1/10)".
struct NumberExpr {
  enum class Op { leaf, add, sub, mul, div, neg } op = Op::leaf;
  WrittenNumber leaf;
  std::vector<NumberExpr> args;
};

/// Recursive descent over the text without spaces; every error names the field and the text.
class NumberParser {
public:
  NumberParser(const std::string& raw, const std::string& path) : raw_(raw), path_(path) {
    for (char c : raw)
      if (c != ' ') text_ += c;
  }

  NumberExpr parse() {
    if (text_.empty()) error("empty expression");
    NumberExpr e = sum(0);
    if (pos_ != text_.size()) error("unexpected '" + std::string(1, text_[pos_]) + "'");
    return e;
  }

private:
  static constexpr int kMaxDepth = 64;

  [[noreturn]] void error(const std::string& what) const {
    fail(path_, quote_text(raw_) + " is not an exact number: " + what +
                    " (expected rationals, "
                    "cos(2pi*k/n), sin(2pi*k/n), K<m>[a_0, ...], + - * / and parentheses)");
  }
  bool eat(char c) {
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!eat(c)) error(std::string("expected '") + c + "'");
  }
  bool starts(const char* word) const { return text_.compare(pos_, std::strlen(word), word) == 0; }

  NumberExpr node(NumberExpr::Op op, std::vector<NumberExpr> args) {
    NumberExpr e;
    e.op = op;
    e.args = std::move(args);
    return e;
  }

  NumberExpr sum(int depth) {
    if (depth > kMaxDepth) error("nested too deeply");
    NumberExpr e = product(depth);
    while (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) {
      const auto op = text_[pos_++] == '+' ? NumberExpr::Op::add : NumberExpr::Op::sub;
      e = node(op, {std::move(e), product(depth)});
    }
    return e;
  }
  NumberExpr product(int depth) {
    NumberExpr e = unary(depth);
    while (pos_ < text_.size() && (text_[pos_] == '*' || text_[pos_] == '/')) {
      const auto op = text_[pos_++] == '*' ? NumberExpr::Op::mul : NumberExpr::Op::div;
      e = node(op, {std::move(e), unary(depth)});
    }
    return e;
  }
  NumberExpr unary(int depth) {
    if (depth > kMaxDepth) error("nested too deeply");
    if (eat('+')) return unary(depth + 1);
    if (eat('-')) return node(NumberExpr::Op::neg, {unary(depth + 1)});
    return primary(depth);
  }
  NumberExpr primary(int depth) {
    if (eat('(')) {
      NumberExpr e = sum(depth + 1);
      expect(')');
      return e;
    }
    NumberExpr e;
    if (starts("cos(") || starts("sin(")) {
      e.leaf.kind = starts("cos(") ? WrittenNumber::Kind::cos : WrittenNumber::Kind::sin;
      pos_ += 4;
      if (!starts("2pi")) error("expected 2pi after " + text_.substr(pos_ - 4, 4));
      pos_ += 3;
      const long long k = eat('*') ? integer(-1000000000, 1000000000) : 1;
      expect('/');
      const long long n = integer(1, 1000000);
      expect(')');
      std::tie(e.leaf.k, e.leaf.n) = reduce_angle(k, n);
      return e;
    }
    if (eat('K')) {
      e.leaf.kind = WrittenNumber::Kind::field_element;
      e.leaf.m = int(integer(3, kMaxFieldOrder));
      expect('[');
      do e.leaf.coefficients.push_back(field_coefficient());
      while (eat(','));
      expect(']');
      const std::size_t d = std::size_t(number::euler_phi(e.leaf.m) / 2);
      if (e.leaf.coefficients.size() != d)
        error("K" + std::to_string(e.leaf.m) + " has degree " + std::to_string(d) + ", so an " +
              "element has " + std::to_string(d) + " coefficients (of 1, c, ..., c^" +
              std::to_string(d - 1) + " for c = 2cos(2pi/" + std::to_string(e.leaf.m) + ")), got " +
              std::to_string(e.leaf.coefficients.size()));
      return e;
    }
    e.leaf.value = parse_rational(literal(), path_);
    return e;
  }
  /// An unsigned decimal: digits, '.', an exponent ("1.5e-3").
  std::string literal() {
    const std::size_t start = pos_;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      const bool exponent_sign = (c == '-' || c == '+') && pos_ > start &&
                                 (text_[pos_ - 1] == 'e' || text_[pos_ - 1] == 'E');
      if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' ||
            exponent_sign))
        break;
      ++pos_;
    }
    if (pos_ == start)
      error(pos_ < text_.size() ? "unexpected '" + std::string(1, text_[pos_]) + "'"
                                : "unexpected end");
    return text_.substr(start, pos_ - start);
  }
  /// A coefficient of K<m>[...]: [sign] decimal [/ decimal].
  mpq_class field_coefficient() {
    std::string sign;
    if (pos_ < text_.size() && (text_[pos_] == '-' || text_[pos_] == '+')) sign = text_[pos_++];
    std::string q = sign + literal();
    if (eat('/')) q += "/" + literal();
    return parse_rational(q, path_);
  }
  long long integer(long long lo, long long hi) {
    const std::size_t start = pos_;
    if (pos_ < text_.size() && (text_[pos_] == '-' || text_[pos_] == '+')) ++pos_;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    std::string d = text_.substr(start, pos_ - start);
    bool negative = false;
    if (!d.empty() && (d[0] == '-' || d[0] == '+')) {
      negative = d[0] == '-';
      d.erase(0, 1);
    }
    if (d.empty()) error("expected an integer");
    d = strip_zeros(d);
    const std::string range = " (" + std::to_string(lo) + ".." + std::to_string(hi) + ")";
    if (d.size() > 12) error(text_.substr(start, pos_ - start) + " is out of range" + range);
    const long long v = negative ? -std::stoll(d) : std::stoll(d);
    if (v < lo || v > hi) error(std::to_string(v) + " is out of range" + range);
    return v;
  }

  const std::string& raw_;
  const std::string& path_;
  std::string text_;
  std::size_t pos_ = 0;
};

/// Plain rationals keep the rational grammar and its messages; anything with a function, a
/// field literal or an operator beyond "n/d" is an expression.
inline bool is_expression(const std::string& text) {
  return text.find_first_of("([*K") != std::string::npos || text.find("cos") != std::string::npos ||
         text.find("sin") != std::string::npos;
}

/// The orders a written number needs (cos/sin of order n need K_m with n | m; K<m'> needs m' | m).
inline void collect_orders(const NumberExpr& e, const std::string& path, OrderDemands& d) {
  if (e.op == NumberExpr::Op::leaf) {
    if (e.leaf.kind == WrittenNumber::Kind::cos || e.leaf.kind == WrittenNumber::Kind::sin)
      demand(d, e.leaf.n, path);
    if (e.leaf.kind == WrittenNumber::Kind::field_element) d.emplace(e.leaf.m, path);
  }
  for (const auto& a : e.args) collect_orders(a, path, d);
}

/// An {"order": n, "k": k} object (rotation or reflection angle); malformed ones are left to the
/// reader, which reports them with their path.
inline void scan_angle(const json& v, const std::string& path, OrderDemands& d) {
  if (!v.is_object() || !v.contains("order") || !v["order"].is_number_integer()) return;
  long long k = 1;
  if (v.contains("k") && v["k"].is_number_integer()) k = v["k"].get<long long>();
  const long long n = v["order"].get<long long>();
  if (n < 1 || n > 1000000 || k < -1000000000 || k > 1000000000) return;
  demand(d, reduce_angle(k, n).second, dot(path, "order"));
}

/// Collects the orders of every symbolic rotation/reflection and symbolic number.
inline void scan_orders(const json& j, const std::string& path, OrderDemands& d) {
  if (j.is_object()) {
    for (const auto& item : j.items()) {
      const std::string& key = item.key();
      if (key == "name" || key == "description") continue;
      const std::string p = path.empty() ? key : dot(path, key);
      if (key == "rotation" || key == "angle") scan_angle(item.value(), p, d);
      scan_orders(item.value(), p, d);
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) scan_orders(j[i], at(path, i), d);
  } else if (j.is_string()) {
    const std::string& s = j.get_ref<const std::string&>();
    if (!is_expression(s)) return;
    try {
      collect_orders(NumberParser(s, path).parse(), path, d);
    } catch (const InputError&) {
      // not a number: the reader reports it where a number is expected
    }
  }
}

/// The kernel of a document: null (rationals) when every order is 1, 2 or 4, otherwise K_m for
/// the smallest m divisible by 4 and by every order.
inline number::CyclotomicFieldPtr choose_field(const json& root) {
  OrderDemands d;
  scan_orders(root, "", d);
  if (d.empty()) return nullptr;
  long long m = 4;
  std::string orders;
  for (const auto& [order, path] : d) {
    m = std::lcm(m, order);
    orders += (orders.empty() ? "" : ", ") + std::to_string(order);
    if (m > kMaxFieldOrder)
      fail(path, "the symmetry orders " + orders + " need the field K_m with m = lcm(4, " + orders +
                     ") > " + std::to_string(kMaxFieldOrder) + ", the largest supported");
  }
  return number::CyclotomicField::get(int(m));
}

inline mpq_class to_mpq(const Rational& r) {
  mpq_class q;
  mpq_set(q.get_mpq_t(), raw_mpq(r));
  return q;
}

inline Exact to_exact(const mpq_class& q) {
  Rational r;
  mpq_set(raw_mpq(r), q.get_mpq_t());
  return Exact(r);
}

/// q as a number of the kernel.
template <class FT>
FT from_rational(const mpq_class& q) {
  if constexpr (std::is_same_v<FT, Exact>)
    return to_exact(q);
  else
    return t_field ? t_field->element({q}) : FT(q);
}

/// cos(2πk/n), sin(2πk/n) in the kernel of the document.
template <class FT>
std::pair<FT, FT> cos_sin(long long k, long long n, const std::string& path) {
  if constexpr (std::is_same_v<FT, Exact>) {
    const auto cs = rational_cos_sin(k, n);
    if (!cs) fail(path, "internal error: order " + std::to_string(n) + " in the rational kernel");
    return {FT(cs->first), FT(cs->second)};
  } else {
    if (!t_field) fail(path, "internal error: no field chosen");
    const auto [kk, order] = reduce_angle(k, n);
    return {t_field->cos_2pi(long(kk), long(order)), t_field->sin_2pi(long(kk), long(order))};
  }
}

template <class FT>
FT evaluate(const NumberExpr& e, const std::string& raw, const std::string& path) {
  using Op = NumberExpr::Op;
  using Kind = WrittenNumber::Kind;
  switch (e.op) {
  case Op::add:
    return evaluate<FT>(e.args[0], raw, path) + evaluate<FT>(e.args[1], raw, path);
  case Op::sub:
    return evaluate<FT>(e.args[0], raw, path) - evaluate<FT>(e.args[1], raw, path);
  case Op::mul:
    return evaluate<FT>(e.args[0], raw, path) * evaluate<FT>(e.args[1], raw, path);
  case Op::neg:
    return -evaluate<FT>(e.args[0], raw, path);
  case Op::div: {
    const FT d = evaluate<FT>(e.args[1], raw, path);
    if (d == 0) fail(path, quote_text(raw) + " divides by zero");
    return evaluate<FT>(e.args[0], raw, path) / d;
  }
  case Op::leaf:
    break;
  }
  const WrittenNumber& w = e.leaf;
  if (w.kind == Kind::rational) return from_rational<FT>(w.value);
  if (w.kind == Kind::cos || w.kind == Kind::sin) {
    const auto [c, s] = cos_sin<FT>(w.k, w.n, path);
    return w.kind == Kind::cos ? c : s;
  }
  if constexpr (std::is_same_v<FT, Exact>) {
    fail(path, "internal error: a field element in the rational kernel");
  } else {
    return number::embed_subfield_element(*t_field, int(w.m), w.coefficients);
  }
}

template <class FT>
FT get_number(const json& j, const std::string& path) {
  if (j.is_string()) {
    const std::string& text = j.get_ref<const std::string&>();
    if (!is_expression(text)) return from_rational<FT>(parse_rational(text, path));
    return evaluate<FT>(NumberParser(text, path).parse(), text, path);
  }
  if (j.is_number_integer()) return from_rational<FT>(parse_rational(j.dump(), path));
  if (j.is_number_float())
    fail(path, "the JSON number " + j.dump() +
                   " is not exact: give non-integer (and very large) numbers as strings, e.g. "
                   "\"0.25\" or \"1/4\"");
  fail(path,
       "expected an exact number (a string such as \"3/5\", \"-0.25\" or \"cos(2pi*1/8)\", or a "
       "JSON integer), got " +
           type_name(j));
}

/// Exact text of a number as the reader accepts it back: "n/d", or "K<m>[a_0, ...]".
template <class FT>
std::string number_text(const FT& x) {
  if constexpr (std::is_same_v<FT, Exact>) {
    return exact_to_string(x);
  } else {
    if (x.is_rational()) return rational_text(x.rational_value().get_mpq_t());
    std::ostringstream os;
    os << x;
    return os.str();
  }
}

/// |u| when it is rational (u · u the square of a rational), which a rotation axis needs.
template <class FT>
std::optional<FT> rational_sqrt(const FT& x) {
  mpq_class q;
  if constexpr (std::is_same_v<FT, Exact>) {
    q = to_mpq(CGAL::exact(x));
  } else {
    if (!x.is_rational()) return std::nullopt;
    q = x.rational_value();
  }
  if (q < 0 || !mpz_perfect_square_p(q.get_num_mpz_t()) || !mpz_perfect_square_p(q.get_den_mpz_t()))
    return std::nullopt;
  mpz_class num, den;
  mpz_sqrt(num.get_mpz_t(), q.get_num_mpz_t());
  mpz_sqrt(den.get_mpz_t(), q.get_den_mpz_t());
  return from_rational<FT>(mpq_class(num, den));
}

template <class FT, int D>
core::Point<FT, D> get_point(const json& j, const std::string& path,
                             const char* what = "coordinates") {
  expect_array(j, path, "an array of " + std::to_string(D) + " " + what);
  if (j.size() != std::size_t(D))
    fail(path, "expected " + std::to_string(D) + " " + what + " (dimension " + std::to_string(D) +
                   "), got " + std::to_string(j.size()));
  core::Point<FT, D> p;
  for (int d = 0; d < D; ++d) p[d] = get_number<FT>(j[std::size_t(d)], at(path, std::size_t(d)));
  return p;
}

template <int D>
std::array<int, D> get_int_array(const json& j, const std::string& path, long long lo,
                                 long long hi) {
  expect_array(j, path, "an array of " + std::to_string(D) + " integers");
  if (j.size() != std::size_t(D))
    fail(path, "expected " + std::to_string(D) + " integers, got " + std::to_string(j.size()));
  std::array<int, D> a{};
  for (int d = 0; d < D; ++d)
    a[d] = int(get_integer(j[std::size_t(d)], at(path, std::size_t(d)), lo, hi));
  return a;
}

} // namespace symmesh::io::structure_json
