// The templated-structure JSON format: reader and writer — spec/input-format.md
//
// Reading is in three steps: nlohmann::json parses the text (a parser callback rejects
// duplicate keys and knows their JSON path), the shape of the document is validated field by
// field (every error names the field by its JSON path), and 2D geometry templates given as a
// polygon are triangulated exactly with a constrained Delaunay triangulation. Eq. 4.2 and
// conformity are not checked here: that is core::analyse.
#include "symmesh/io/templated_structure_json.h"
#include "symmesh/io/number_text.h"
#include "symmesh/number/subfield_embedding.h"

#include "symmesh/core/element_complex.h"
#include "symmesh/core/exact_kernel_of.h"
#include "symmesh/gen/carrier_tetrahedralization.h"
#include "symmesh/gen/triangle_mesher.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <gmp.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

namespace symmesh::io {

namespace {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;
/// The exact type behind Exact (Lazy_exact_nt<ET>): GMP rationals, either gmpxx's mpq_class
/// (CGAL_USE_GMPXX, as CGAL's CMake target sets it) or boost::multiprecision's mpq_rational.
using Rational = std::decay_t<decltype(CGAL::exact(std::declval<Exact>()))>;

template <class R>
mpq_ptr raw_mpq(R& q) {
  if constexpr (requires { q.get_mpq_t(); })
    return q.get_mpq_t();
  else
    return q.backend().data();
}
template <class R>
mpq_srcptr raw_mpq(const R& q) {
  if constexpr (requires { q.get_mpq_t(); })
    return q.get_mpq_t();
  else
    return q.backend().data();
}

constexpr const char* kFormat = "templated-structure/1";
constexpr std::size_t kMaxNumberLength = 100000;
constexpr long kMaxExponent = 10000;
constexpr int kMaxComposeDepth = 100;

// ---------------------------------------------------------------------------------------------
// Errors

/// Error messages are one line: control characters (from user strings) become spaces.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t' || c == '\f' || c == '\v') c = ' ';
  return s;
}

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  throw InputError(one_line(path + ": " + message));
}

/// A user string quoted for an error message, shortened if long.
std::string quote_text(const std::string& s) {
  constexpr std::size_t kMax = 40;
  if (s.size() <= kMax) return "\"" + s + "\"";
  return "\"" + s.substr(0, kMax) + "...\"";
}

std::string type_name(const json& j) {
  if (j.is_number_float()) return "a non-integer number";
  if (j.is_number()) return "an integer";
  return std::string(j.is_array() || j.is_object() ? "an " : "a ") + j.type_name();
}

std::string at(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}
std::string dot(const std::string& path, const std::string& key) {
  return path + "." + key;
}

// ---------------------------------------------------------------------------------------------
// Exact numbers

bool all_digits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

/// Strips leading zeros (keeps one digit).
std::string strip_zeros(const std::string& digits) {
  const auto nz = digits.find_first_not_of('0');
  return nz == std::string::npos ? "0" : digits.substr(nz);
}

/// ±num/den from decimal digit strings (den != 0), reduced to lowest terms.
mpq_class make_rational(bool negative, const std::string& num, const std::string& den) {
  mpq_class q;
  const std::string text = (negative ? "-" : "") + strip_zeros(num) + "/" + strip_zeros(den);
  if (mpq_set_str(q.get_mpq_t(), text.c_str(), 10) != 0)
    throw std::logic_error("make_rational: GMP rejected " + text);
  mpq_canonicalize(q.get_mpq_t());
  return q;
}

/// "n" or "n/d" of a canonical rational (mpq_get_str omits a denominator 1).
std::string rational_text(mpq_srcptr q) {
  std::string out(mpz_sizeinbase(mpq_numref(q), 10) + mpz_sizeinbase(mpq_denref(q), 10) + 3, '\0');
  mpq_get_str(out.data(), 10, q);
  out.resize(std::char_traits<char>::length(out.c_str()));
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// "n", "n/d" or a decimal, exactly (spec/input-format.md#numbers).
mpq_class parse_rational(const std::string& text, const std::string& field) {
  if (text.empty()) fail(field, "empty string is not a number");
  if (text.size() > kMaxNumberLength)
    fail(field, "number has more than " + std::to_string(kMaxNumberLength) + " characters");
  {
    std::string l = lower(text);
    if (!l.empty() && (l[0] == '+' || l[0] == '-')) l.erase(0, 1);
    if (l == "nan" || l == "inf" || l == "infinity")
      fail(field, quote_text(text) + " is not allowed: NaN and infinities are not exact numbers");
  }
  const std::string bad = quote_text(text) +
                          " is not an exact number (expected \"n\", \"n/d\" or a decimal such as "
                          "\"-0.25\" or \"1.5e-3\")";
  std::size_t i = 0;
  bool negative = false;
  if (text[0] == '+' || text[0] == '-') {
    negative = text[0] == '-';
    i = 1;
  }
  const std::string body = text.substr(i);
  if (const auto slash = body.find('/'); slash != std::string::npos) {
    const std::string num = body.substr(0, slash);
    const std::string den = body.substr(slash + 1);
    if (!all_digits(num) || !all_digits(den)) fail(field, bad);
    if (strip_zeros(den) == "0") fail(field, quote_text(text) + " has a zero denominator");
    return (make_rational(negative, num, den));
  }
  {
    // decimal := (digits ["." [digits]] | "." digits) [("e"|"E") [sign] digits]
    std::string mantissa = body, exponent;
    if (const auto e = body.find_first_of("eE"); e != std::string::npos) {
      mantissa = body.substr(0, e);
      exponent = body.substr(e + 1);
      if (exponent.empty()) fail(field, bad);
    }
    std::string int_part = mantissa, frac_part;
    if (const auto p = mantissa.find('.'); p != std::string::npos) {
      int_part = mantissa.substr(0, p);
      frac_part = mantissa.substr(p + 1);
      if (int_part.empty() && frac_part.empty()) fail(field, bad);
      if (!int_part.empty() && !all_digits(int_part)) fail(field, bad);
      if (!frac_part.empty() && !all_digits(frac_part)) fail(field, bad);
    } else if (!all_digits(int_part)) {
      fail(field, bad);
    }
    long e10 = 0;
    if (!exponent.empty()) {
      bool eneg = false;
      std::string ed = exponent;
      if (ed[0] == '+' || ed[0] == '-') {
        eneg = ed[0] == '-';
        ed.erase(0, 1);
      }
      if (!all_digits(ed)) fail(field, bad);
      const auto nz = ed.find_first_not_of('0');
      ed = nz == std::string::npos ? "0" : ed.substr(nz);
      if (ed.size() > 6 || std::stol(ed) > kMaxExponent)
        fail(field, "the exponent of " + quote_text(text) + " is out of range (at most " +
                        std::to_string(kMaxExponent) + ")");
      e10 = eneg ? -std::stol(ed) : std::stol(ed);
    }
    e10 -= long(frac_part.size());
    const std::string digits = int_part + frac_part;
    if (e10 >= 0)
      return (make_rational(negative, digits + std::string(std::size_t(e10), '0'), "1"));
    return (make_rational(negative, digits, "1" + std::string(std::size_t(-e10), '0')));
  }
}

// ---------------------------------------------------------------------------------------------
// Duplicate keys: nlohmann keeps the last of equal keys silently; a parser callback tracks the
// JSON path of the value being parsed and rejects a key seen twice in one object.

class DuplicateKeyGuard {
public:
  explicit DuplicateKeyGuard(std::string root) : root_(std::move(root)) {}

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
    case json::parse_event_t::object_start:
    case json::parse_event_t::array_start:
      count_array_element();
      frames_.push_back(Frame{event == json::parse_event_t::object_start, {}, {}, 0});
      break;
    case json::parse_event_t::object_end:
    case json::parse_event_t::array_end:
      if (!frames_.empty()) frames_.pop_back();
      break;
    case json::parse_event_t::key: {
      Frame& f = frames_.back();
      std::string k = parsed.is_string() ? parsed.get<std::string>() : parsed.dump();
      if (!f.keys.insert(k).second) fail(container_path(), "duplicate field " + quote_text(k));
      f.key = std::move(k);
      break;
    }
    case json::parse_event_t::value:
      count_array_element();
      break;
    }
    return true;
  }

private:
  struct Frame {
    bool object = false;
    std::set<std::string> keys;
    std::string key;      // the key being parsed (objects)
    std::size_t next = 0; // the index of the next element (arrays)
  };

  void count_array_element() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().next;
  }

  /// Path of the innermost open container.
  std::string container_path() const {
    std::string p;
    for (std::size_t i = 0; i + 1 < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.object)
        p += p.empty() ? f.key : "." + f.key;
      else
        p += "[" + std::to_string(f.next - 1) + "]";
    }
    return p.empty() ? root_ : p;
  }

  std::string root_;
  std::vector<Frame> frames_;
};

/// Turns nlohmann's "[json.exception.parse_error.101] parse error at line 3, column 5: msg"
/// into "SOURCE: malformed JSON at line 3 column 5: msg".
[[noreturn]] void fail_malformed(const std::string& source, const json::parse_error& e) {
  static const std::regex re(R"(line (\d+), column (\d+): (.*))");
  const std::string what = e.what();
  std::smatch m;
  if (std::regex_search(what, m, re))
    fail(source,
         "malformed JSON at line " + m[1].str() + " column " + m[2].str() + ": " + m[3].str());
  const auto colon = what.find("] ");
  fail(source, "malformed JSON: " + (colon == std::string::npos ? what : what.substr(colon + 2)));
}

// ---------------------------------------------------------------------------------------------
// Field access

/// Rejects fields of `obj` other than `allowed`.
void check_keys(const json& obj, const std::string& path,
                std::initializer_list<const char*> allowed) {
  for (const auto& item : obj.items()) {
    const std::string& k = item.key();
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return k == a; })) {
      std::string list;
      for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      fail(path, "unknown field " + quote_text(k) + " (expected one of: " + list + ")");
    }
  }
}

const json& require(const json& obj, const char* key, const std::string& path) {
  auto it = obj.find(key);
  if (it == obj.end()) fail(path, std::string("missing field \"") + key + "\"");
  return *it;
}

void expect_object(const json& j, const std::string& path, const std::string& what = "an object") {
  if (!j.is_object()) fail(path, "expected " + what + ", got " + type_name(j));
}

void expect_array(const json& j, const std::string& path, const std::string& what = "an array") {
  if (!j.is_array()) fail(path, "expected " + what + ", got " + type_name(j));
}

std::string get_string(const json& j, const std::string& path) {
  if (!j.is_string()) fail(path, "expected a string, got " + type_name(j));
  return j.get<std::string>();
}

long long get_integer(const json& j, const std::string& path, long long lo, long long hi,
                      const std::string& what = "an integer") {
  if (j.is_number_float())
    fail(path, "expected " + what + ", got the non-integer number " + j.dump());
  if (!j.is_number_integer()) fail(path, "expected " + what + ", got " + type_name(j));
  if (j.is_number_unsigned()) {
    const auto u = j.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(hi) || (lo > 0 && u < static_cast<std::uint64_t>(lo)))
      fail(path,
           j.dump() + " is out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")");
    return static_cast<long long>(u);
  }
  const auto v = j.get<std::int64_t>();
  if (v < lo || v > hi)
    fail(path,
         j.dump() + " is out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")");
  return v;
}

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

void demand(OrderDemands& d, long long order, const std::string& path) {
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
std::pair<long long, long long> reduce_angle(long long k, long long n) {
  long long kk = ((k % n) + n) % n;
  const long long g = std::gcd(kk, n);
  return {kk / g, n / g};
}

/// cos and sin of 2πk/n when they are rational (order n ∈ {1, 2, 4} in lowest terms).
std::optional<std::pair<int, int>> rational_cos_sin(long long k, long long n) {
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
bool is_expression(const std::string& text) {
  return text.find_first_of("([*K") != std::string::npos || text.find("cos") != std::string::npos ||
         text.find("sin") != std::string::npos;
}

/// The orders a written number needs (cos/sin of order n need K_m with n | m; K<m'> needs m' | m).
void collect_orders(const NumberExpr& e, const std::string& path, OrderDemands& d) {
  if (e.op == NumberExpr::Op::leaf) {
    if (e.leaf.kind == WrittenNumber::Kind::cos || e.leaf.kind == WrittenNumber::Kind::sin)
      demand(d, e.leaf.n, path);
    if (e.leaf.kind == WrittenNumber::Kind::field_element) d.emplace(e.leaf.m, path);
  }
  for (const auto& a : e.args) collect_orders(a, path, d);
}

/// An {"order": n, "k": k} object (rotation or reflection angle); malformed ones are left to the
/// reader, which reports them with their path.
void scan_angle(const json& v, const std::string& path, OrderDemands& d) {
  if (!v.is_object() || !v.contains("order") || !v["order"].is_number_integer()) return;
  long long k = 1;
  if (v.contains("k") && v["k"].is_number_integer()) k = v["k"].get<long long>();
  const long long n = v["order"].get<long long>();
  if (n < 1 || n > 1000000 || k < -1000000000 || k > 1000000000) return;
  demand(d, reduce_angle(k, n).second, dot(path, "order"));
}

/// Collects the orders of every symbolic rotation/reflection and symbolic number.
void scan_orders(const json& j, const std::string& path, OrderDemands& d) {
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
number::CyclotomicFieldPtr choose_field(const json& root) {
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

mpq_class to_mpq(const Rational& r) {
  mpq_class q;
  mpq_set(q.get_mpq_t(), raw_mpq(r));
  return q;
}

Exact to_exact(const mpq_class& q) {
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

// ---------------------------------------------------------------------------------------------
// Transformations

constexpr const char* kTransformationKinds =
    "identity, translation, reflection, rotation, signed_permutation, matrix, compose";

template <class FT, int D>
using Rigid = core::RigidTransformation<FT, D>;

/// Runs a core constructor; its std::invalid_argument becomes an InputError at `path`.
template <class F>
auto guarded(const std::string& path, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    fail(path, e.what());
  }
}

/// x -> A (x - c) + c, checked to be rigid.
template <class FT, int D>
Rigid<FT, D> about_center(const typename Rigid<FT, D>::Mat& a, const core::Point<FT, D>& c,
                          const std::string& path) {
  core::Point<FT, D> b;
  for (int i = 0; i < D; ++i) {
    FT s = c[i];
    for (int j = 0; j < D; ++j) s -= a[i][j] * c[j];
    b[i] = s;
  }
  return guarded(path, [&] { return Rigid<FT, D>::from_matrix(a, b); });
}

/// {"order": n, "k": k} (k defaults to 1): the angle 2πk/n.
std::pair<long long, long long> get_angle(const json& v, const std::string& path) {
  const long long n =
      get_integer(require(v, "order", path), dot(path, "order"), 1, 1000000, "a positive integer");
  long long k = 1;
  if (v.contains("k")) k = get_integer(v["k"], dot(path, "k"), -1000000000, 1000000000);
  return {k, n};
}

/// "x", "y" or "z": the index of a coordinate axis.
int get_coordinate_axis(const json& j, const std::string& path) {
  if (j.is_string()) {
    const std::string a = j.get<std::string>();
    if (a == "x" || a == "y" || a == "z") return a[0] - 'x';
  }
  fail(path, "expected a coordinate axis \"x\", \"y\" or \"z\", got " + j.dump());
}

/// The unit direction of a rotation axis: "x"/"y"/"z" or a vector of rational length.
template <class FT>
core::Point<FT, 3> get_unit_axis(const json& j, const std::string& path) {
  core::Point<FT, 3> u = core::zero_point<FT, 3>();
  if (j.is_string()) {
    u[get_coordinate_axis(j, path)] = from_rational<FT>(1);
    return u;
  }
  u = get_point<FT, 3>(j, path, "direction components");
  const FT uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  if (uu == 0) fail(path, "the axis is the zero vector");
  const auto length = rational_sqrt(uu);
  if (!length)
    fail(path, "the axis has irrational length sqrt(" + number_text(uu) +
                   "): give an axis of rational length (e.g. [1, 2, 2]) or a coordinate axis");
  for (auto& x : u) x /= *length;
  return u;
}

/// Rotation by 2πk/n ("order", "k"): about "center" in 2D, about the line through "center" along
/// "axis" in 3D (Rodrigues: R = cI + s[u]x + (1 - c) u uᵀ for a unit axis u).
template <class FT, int D>
Rigid<FT, D> symbolic_rotation(const json& r, const std::string& path,
                               const core::Point<FT, D>& center) {
  if constexpr (D == 2)
    check_keys(r, path, {"order", "k", "center"});
  else
    check_keys(r, path, {"order", "k", "axis", "center"});
  const auto [k, n] = get_angle(r, path);
  const auto [c, s] = cos_sin<FT>(k, n, dot(path, "order"));
  typename Rigid<FT, D>::Mat a;
  if constexpr (D == 2) {
    a = {{{c, -s}, {s, c}}};
  } else {
    const auto u = get_unit_axis<FT>(require(r, "axis", path), dot(path, "axis"));
    const FT one = from_rational<FT>(1);
    const FT t = one - c;
    a = {{{c + t * u[0] * u[0], t * u[0] * u[1] - s * u[2], t * u[0] * u[2] + s * u[1]},
          {t * u[1] * u[0] + s * u[2], c + t * u[1] * u[1], t * u[1] * u[2] - s * u[0]},
          {t * u[2] * u[0] - s * u[1], t * u[2] * u[1] + s * u[0], c + t * u[2] * u[2]}}};
  }
  return about_center<FT, D>(a, center, path);
}

template <class FT, int D>
Rigid<FT, D> parse_rotation(const json& r, const std::string& path) {
  expect_object(r, path);
  core::Point<FT, D> center = core::zero_point<FT, D>();
  if (r.contains("center")) center = get_point<FT, D>(r["center"], dot(path, "center"));
  if (r.contains("order")) return symbolic_rotation<FT, D>(r, path, center);
  if constexpr (D == 3) {
    if (!r.contains("quaternion"))
      fail(path, "a 3D rotation is given by \"quaternion\": [w, x, y, z] or by \"order\", \"k\" "
                 "and \"axis\" (and an optional \"center\")");
    check_keys(r, path, {"quaternion", "center"});
    const std::string qp = dot(path, "quaternion");
    const json& q = r["quaternion"];
    expect_array(q, qp, "an array of 4 exact numbers [w, x, y, z]");
    if (q.size() != 4) fail(qp, "expected 4 numbers [w, x, y, z], got " + std::to_string(q.size()));
    std::array<FT, 4> c;
    for (std::size_t k = 0; k < 4; ++k) c[k] = get_number<FT>(q[k], at(qp, k));
    return guarded(
        qp, [&] { return Rigid<FT, D>::rotation_quaternion(c[0], c[1], c[2], c[3], center); });
  } else {
    if (r.contains("quaternion")) fail(dot(path, "quaternion"), "quaternion rotations are 3D only");
    if (r.contains("cos") || r.contains("sin")) {
      check_keys(r, path, {"cos", "sin", "center"});
      const FT c = get_number<FT>(require(r, "cos", path), dot(path, "cos"));
      const FT s = get_number<FT>(require(r, "sin", path), dot(path, "sin"));
      return guarded(path, [&] { return Rigid<FT, D>::rotation_2d(c, s, center); });
    }
    fail(path, "a 2D rotation is given by \"cos\" and \"sin\" or by \"order\" and \"k\" (and an "
               "optional \"center\")");
  }
}

/// Reflection through the line (2D) or the plane containing "axis" (3D) that passes through
/// "through" at the angle πk/n: {"angle": {"order": n, "k": k}}. Its matrix has cos and sin of
/// 2πk/n, so it needs the same field as a rotation of order n.
template <class FT, int D>
Rigid<FT, D> angle_reflection(const json& v, const std::string& path) {
  if constexpr (D == 2)
    check_keys(v, path, {"angle", "through"});
  else
    check_keys(v, path, {"angle", "axis", "through"});
  const std::string ap = dot(path, "angle");
  const json& aj = v["angle"];
  expect_object(aj, ap, "an object {\"order\": n, \"k\": k} (the angle pi*k/n)");
  check_keys(aj, ap, {"order", "k"});
  const auto [k, n] = get_angle(aj, ap);
  const auto [c, s] = cos_sin<FT>(k, n, dot(ap, "order"));
  core::Point<FT, D> through = core::zero_point<FT, D>();
  if (v.contains("through")) through = get_point<FT, D>(v["through"], dot(path, "through"));
  int fixed = 2; // the axis the plane contains (3D)
  if constexpr (D == 3) fixed = get_coordinate_axis(require(v, "axis", path), dot(path, "axis"));
  const int i = (fixed + 1) % 3, j = (fixed + 2) % 3; // the plane perpendicular to the axis
  typename Rigid<FT, D>::Mat a;
  for (auto& row : a)
    for (auto& x : row) x = from_rational<FT>(0);
  const int p = D == 2 ? 0 : i, q = D == 2 ? 1 : j;
  a[p][p] = c;
  a[p][q] = s;
  a[q][p] = s;
  a[q][q] = -c;
  if constexpr (D == 3) a[fixed][fixed] = from_rational<FT>(1);
  return about_center<FT, D>(a, through, path);
}

template <class FT, int D>
Rigid<FT, D> parse_reflection(const json& v, const std::string& vp) {
  expect_object(v, vp,
                "an object {\"normal\": [...], \"offset\": d} or {\"angle\": {...}, \"through\": "
                "[...]}");
  if (v.contains("angle")) return angle_reflection<FT, D>(v, vp);
  check_keys(v, vp, {"normal", "offset"});
  const auto n = get_point<FT, D>(require(v, "normal", vp), dot(vp, "normal"));
  FT d = from_rational<FT>(0);
  if (v.contains("offset")) d = get_number<FT>(v["offset"], dot(vp, "offset"));
  return guarded(dot(vp, "normal"), [&] { return Rigid<FT, D>::reflection(n, d); });
}

template <class FT, int D>
Rigid<FT, D> parse_transformation(const json& t, const std::string& path, int depth = 0) {
  if (depth > kMaxComposeDepth) fail(path, "transformations are nested too deeply");
  expect_object(t, path, "a transformation object");
  if (t.empty())
    fail(path,
         std::string("empty transformation: expected exactly one of ") + kTransformationKinds);
  if (t.contains("matrix")) {
    check_keys(t, path, {"matrix", "translation"});
    const std::string mp = dot(path, "matrix");
    const json& m = t["matrix"];
    expect_array(m, mp,
                 "a " + std::to_string(D) + "x" + std::to_string(D) + " matrix (array of rows)");
    if (m.size() != std::size_t(D))
      fail(mp, "expected " + std::to_string(D) + " rows, got " + std::to_string(m.size()));
    typename Rigid<FT, D>::Mat a;
    for (int i = 0; i < D; ++i) {
      const auto row = get_point<FT, D>(m[std::size_t(i)], at(mp, std::size_t(i)), "entries");
      for (int j = 0; j < D; ++j) a[i][j] = row[j];
    }
    core::Point<FT, D> b = core::zero_point<FT, D>();
    if (t.contains("translation")) b = get_point<FT, D>(t["translation"], dot(path, "translation"));
    return guarded(mp, [&] { return Rigid<FT, D>::from_matrix(a, b); });
  }
  if (t.size() != 1) {
    auto it = t.begin();
    const std::string k1 = it.key();
    const std::string k2 = (++it).key();
    fail(path, "a transformation has exactly one key, got " + quote_text(k1) + " and " +
                   quote_text(k2) + " (use \"compose\" to combine transformations)");
  }
  const std::string kind = t.begin().key();
  const json& v = t.begin().value();
  const std::string vp = dot(path, kind);
  if (kind == "identity") {
    if (!(v.is_object() && v.empty())) fail(vp, "expected {}, got " + v.dump());
    return Rigid<FT, D>();
  }
  if (kind == "translation") return Rigid<FT, D>::translation(get_point<FT, D>(v, vp));
  if (kind == "reflection") return parse_reflection<FT, D>(v, vp);
  if (kind == "rotation") return parse_rotation<FT, D>(v, vp);
  if (kind == "signed_permutation") {
    expect_object(v, vp, "an object {\"perm\": [...], \"sign\": [...], \"translation\": [...]}");
    check_keys(v, vp, {"perm", "sign", "translation"});
    const auto perm = get_int_array<D>(require(v, "perm", vp), dot(vp, "perm"), -1000, 1000);
    const auto sign = get_int_array<D>(require(v, "sign", vp), dot(vp, "sign"), -1000, 1000);
    core::Point<FT, D> b = core::zero_point<FT, D>();
    if (v.contains("translation")) b = get_point<FT, D>(v["translation"], dot(vp, "translation"));
    return guarded(vp, [&] { return Rigid<FT, D>::signed_permutation(perm, sign, b); });
  }
  if (kind == "compose") {
    expect_array(v, vp, "a non-empty array of transformations");
    if (v.empty()) fail(vp, "expected at least one transformation");
    Rigid<FT, D> acc;
    for (std::size_t k = 0; k < v.size(); ++k)
      acc = acc * parse_transformation<FT, D>(v[k], at(vp, k), depth + 1);
    return acc;
  }
  fail(path, "unknown transformation " + quote_text(kind) +
                 " (expected one of: " + kTransformationKinds + ")");
}

// ---------------------------------------------------------------------------------------------
// Polygons (2D geometry templates): validation and exact constrained Delaunay triangulation

template <class FT>
struct Ring {
  std::string path;                    // e.g. templates[0].polygon or templates[0].holes[1]
  std::vector<core::Point<FT, 2>> pts; // implicitly closed
  std::size_t first = 0;               // global index of pts[0]
};

template <class FT>
using KernelOf = core::ExactKernelOf<FT>;
template <class FT>
using P2 = typename KernelOf<FT>::Point_2;

template <class FT>
P2<FT> to_cgal(const core::Point<FT, 2>& p) {
  using LFT = typename KernelOf<FT>::FT;
  return P2<FT>(LFT(p[0]), LFT(p[1]));
}

template <class FT>
struct Edge {
  std::size_t ring, k; // edge from ring.pts[k] to ring.pts[(k+1) % n]
  P2<FT> a, b;
  FT xmin, xmax;
};

template <class FT>
std::string edge_name(const std::vector<Ring<FT>>& rings, const Edge<FT>& e) {
  const Ring<FT>& r = rings[e.ring];
  const std::string base = r.path.substr(r.path.rfind('.') + 1);
  return base + "[" + std::to_string(e.k) + "]-" + base + "[" +
         std::to_string((e.k + 1) % r.pts.size()) + "]";
}

/// The rings have pairwise disjoint boundaries except for consecutive edges of one ring, which
/// share their common vertex only: each ring is a simple polygon and no two rings touch.
template <class FT>
void check_simple_and_disjoint(const std::vector<Ring<FT>>& rings) {
  using K = KernelOf<FT>;
  std::vector<Edge<FT>> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& pts = rings[r].pts;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const auto& p = pts[k];
      const auto& q = pts[(k + 1) % pts.size()];
      edges.push_back({r, k, to_cgal(p), to_cgal(q), std::min(p[0], q[0]), std::max(p[0], q[0])});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const Edge<FT>& x, const Edge<FT>& y) { return x.xmin < y.xmin; });
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size() && !(edges[i].xmax < edges[j].xmin); ++j) {
      const Edge<FT>& e = edges[i];
      const Edge<FT>& f = edges[j];
      const std::size_t n = rings[e.ring].pts.size();
      const bool same_ring = e.ring == f.ring;
      const bool e_then_f = same_ring && (e.k + 1) % n == f.k;
      const bool f_then_e = same_ring && (f.k + 1) % n == e.k;
      bool bad;
      if (e_then_f || f_then_e) {
        // Consecutive edges u-v, v-w: they overlap beyond v iff u, v, w are collinear and u, w
        // lie on the same side of v.
        const P2<FT>& u = e_then_f ? e.a : f.a;
        const P2<FT>& v = e_then_f ? e.b : f.b;
        const P2<FT>& w = e_then_f ? f.b : e.b;
        bad = CGAL::collinear(u, v, w) && CGAL::angle(u, v, w) == CGAL::ACUTE;
        if (n == 3 && !bad) bad = CGAL::collinear(u, v, w);
      } else {
        bad = CGAL::do_intersect(typename K::Segment_2(e.a, e.b), typename K::Segment_2(f.a, f.b));
      }
      if (bad) {
        const Edge<FT>& later = e.ring < f.ring ? f : e;
        const Edge<FT>& earlier = e.ring < f.ring ? e : f;
        const std::string what = same_ring ? "the polygon is self-intersecting: edge "
                                           : "the boundaries of the domain touch or cross: edge ";
        fail(rings[later.ring].path,
             what + edge_name(rings, later) + " meets edge " + edge_name(rings, earlier));
      }
    }
}

struct FaceInfo {
  int nesting = -1;
  bool in_domain() const { return nesting % 2 == 1; }
};
template <class K>
using CdtOf = CGAL::Constrained_Delaunay_triangulation_2<
    K,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>,
        CGAL::Constrained_triangulation_face_base_2<
            K, CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>>>,
    CGAL::No_constraint_intersection_tag>;

/// Nesting level of every face: the number of constraint crossings on a path from the infinite
/// face. Flood-fills each level without crossing constraints; crossings seed the next level.
template <class CDT>
void mark_nesting(CDT& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().nesting = -1;
  std::deque<std::pair<typename CDT::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    auto [start, level] = seeds.front();
    seeds.pop_front();
    if (start->info().nesting != -1) continue;
    std::vector<typename CDT::Face_handle> stack{start};
    start->info().nesting = level;
    while (!stack.empty()) {
      auto f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        auto n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(typename CDT::Edge(f, i))) {
          seeds.emplace_back(n, level + 1);
        } else {
          n->info().nesting = level;
          stack.push_back(n);
        }
      }
    }
  }
}

/// Validates rings (outer polygon first, then holes) and triangulates the domain they bound
/// exactly; the triangles index the rings' vertices in order (outer, then holes). `where` names
/// the outer polygon in messages.
template <class FT>
std::vector<std::array<std::size_t, 3>> triangulate_rings(std::vector<Ring<FT>>& rings,
                                                          const std::string& where) {
  using K = KernelOf<FT>;
  using CDT = CdtOf<K>;
  // Repeated vertices (within a ring, e.g. a closing copy of the first vertex, or across rings).
  std::map<core::Point<FT, 2>, std::string, core::PointLess<FT, 2>> seen;
  std::size_t count = 0;
  for (auto& r : rings) {
    r.first = count;
    count += r.pts.size();
    for (std::size_t k = 0; k < r.pts.size(); ++k) {
      auto [it, inserted] = seen.emplace(r.pts[k], at(r.path, k));
      if (!inserted)
        fail(at(r.path, k),
             "repeated vertex (same coordinates as " + it->second +
                 "; polygons are closed implicitly, do not repeat the first vertex)");
    }
  }
  check_simple_and_disjoint(rings);
  // With disjoint simple boundaries, nesting is decided by one vertex per ring.
  std::vector<std::vector<P2<FT>>> polys;
  for (const auto& r : rings) {
    std::vector<P2<FT>> p;
    for (const auto& q : r.pts) p.push_back(to_cgal(q));
    polys.push_back(std::move(p));
  }
  for (std::size_t h = 1; h < rings.size(); ++h) {
    const P2<FT>& v = polys[h][0];
    if (CGAL::bounded_side_2(polys[0].begin(), polys[0].end(), v, K()) != CGAL::ON_BOUNDED_SIDE)
      fail(rings[h].path, "the hole is not inside the polygon");
    for (std::size_t o = 1; o < rings.size(); ++o)
      if (o != h &&
          CGAL::bounded_side_2(polys[o].begin(), polys[o].end(), v, K()) == CGAL::ON_BOUNDED_SIDE)
        fail(rings[h].path, "the hole lies inside another hole (" +
                                rings[o].path.substr(rings[o].path.rfind('.') + 1) + ")");
  }

  CDT cdt;
  std::vector<typename CDT::Vertex_handle> vh(count);
  try {
    for (const auto& r : rings)
      for (std::size_t k = 0; k < r.pts.size(); ++k) {
        vh[r.first + k] = cdt.insert(polys[std::size_t(&r - rings.data())][k]);
        vh[r.first + k]->info() = r.first + k;
      }
    for (const auto& r : rings)
      for (std::size_t k = 0; k < r.pts.size(); ++k)
        cdt.insert_constraint(vh[r.first + k], vh[r.first + (k + 1) % r.pts.size()]);
  } catch (const typename CDT::Intersection_of_constraints_exception&) {
    fail(where, "the polygon boundaries intersect");
  }
  mark_nesting(cdt);
  std::vector<std::array<std::size_t, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info().in_domain())
      out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  if (out.empty()) fail(where, "the polygon bounds no area");
  return out;
}

/// Validates outer polygon + holes and triangulates the domain they bound.
template <class FT>
core::ElementComplex<FT, 2> triangulate_polygon(const json& tj, const std::string& tpath) {
  std::vector<Ring<FT>> rings;
  auto read_ring = [&](const json& j, const std::string& path) {
    expect_array(j, path, "an array of [x, y] vertices");
    if (j.size() < 3)
      fail(path, "a polygon needs at least 3 vertices, got " + std::to_string(j.size()));
    Ring<FT> r;
    r.path = path;
    for (std::size_t k = 0; k < j.size(); ++k) r.pts.push_back(get_point<FT, 2>(j[k], at(path, k)));
    rings.push_back(std::move(r));
  };
  read_ring(tj["polygon"], dot(tpath, "polygon"));
  if (tj.contains("holes")) {
    const std::string hp = dot(tpath, "holes");
    const json& h = tj["holes"];
    expect_array(h, hp, "an array of polygons");
    for (std::size_t k = 0; k < h.size(); ++k) read_ring(h[k], at(hp, k));
  }
  const auto triangles = triangulate_rings(rings, dot(tpath, "polygon"));
  core::ElementComplex<FT, 2> m;
  for (const auto& r : rings)
    for (const auto& p : r.pts) m.points.push_back(p);
  for (const auto& t : triangles)
    m.elements.push_back(
        core::Simplex{core::VertexId(t[0]), core::VertexId(t[1]), core::VertexId(t[2])});
  return m;
}

// ---------------------------------------------------------------------------------------------
// Faces (3D geometry templates given as a PLC): validation and the carrier tetrahedralization

/// The vertices of a template, pairwise distinct (exact comparison).
template <class FT, int D>
std::vector<core::Point<FT, D>> read_vertices(const json& vj, const std::string& vp) {
  expect_array(vj, vp, "an array of vertices");
  if (vj.empty()) fail(vp, "no vertices (a template must not be empty)");
  std::vector<core::Point<FT, D>> points;
  std::map<core::Point<FT, D>, std::size_t, core::PointLess<FT, D>> seen;
  for (std::size_t k = 0; k < vj.size(); ++k) {
    points.push_back(get_point<FT, D>(vj[k], at(vp, k)));
    auto [it, inserted] = seen.emplace(points.back(), k);
    if (!inserted)
      fail(at(vp, k),
           "duplicate vertex (same coordinates as vertices[" + std::to_string(it->second) + "])");
  }
  return points;
}

/// One ring of a face: vertex indices into the template's vertices.
std::vector<std::size_t> read_index_ring(const json& j, const std::string& path, std::size_t nv) {
  expect_array(j, path, "an array of vertex indices");
  if (j.size() < 3)
    fail(path, "a polygon needs at least 3 vertices, got " + std::to_string(j.size()));
  std::vector<std::size_t> ring;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const json& v = j[k];
    if (!v.is_number_integer())
      fail(at(path, k), "a vertex index must be a JSON integer, got " + type_name(v) +
                            (v.is_number_float() ? " " + v.dump() : ""));
    if (v.is_number_unsigned() ? v.get<std::uint64_t>() >= nv : true)
      fail(at(path, k),
           "vertex index " + v.dump() + " out of range (" + std::to_string(nv) + " vertices)");
    ring.push_back(std::size_t(v.get<std::uint64_t>()));
  }
  return ring;
}

template <class FT>
core::Point<FT, 3> cross(const core::Point<FT, 3>& a, const core::Point<FT, 3>& b) {
  core::Point<FT, 3> c;
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
  return c;
}

/// One polygonal face (with holes): checked planar and simple, triangulated in its own plane.
/// The triangles index the template's vertices.
template <class FT>
std::vector<std::array<std::size_t, 3>> triangulate_face(const json& fj, const std::string& fp,
                                                         const std::vector<core::Point<FT, 3>>& x,
                                                         std::vector<bool>& used) {
  std::vector<std::vector<std::size_t>> ids;
  std::vector<std::string> paths;
  if (fj.is_array()) {
    ids.push_back(read_index_ring(fj, fp, x.size()));
    paths.push_back(fp);
  } else {
    expect_object(fj, fp,
                  "a face: an array of vertex indices or {\"polygon\": [...], \"holes\": [[...]]}");
    check_keys(fj, fp, {"polygon", "holes"});
    ids.push_back(read_index_ring(require(fj, "polygon", fp), dot(fp, "polygon"), x.size()));
    paths.push_back(dot(fp, "polygon"));
    if (fj.contains("holes")) {
      const std::string hp = dot(fp, "holes");
      expect_array(fj["holes"], hp, "an array of polygons");
      for (std::size_t k = 0; k < fj["holes"].size(); ++k) {
        ids.push_back(read_index_ring(fj["holes"][k], at(hp, k), x.size()));
        paths.push_back(at(hp, k));
      }
    }
  }
  std::map<std::size_t, std::string> seen;
  for (std::size_t r = 0; r < ids.size(); ++r)
    for (std::size_t k = 0; k < ids[r].size(); ++k) {
      auto [it, inserted] = seen.emplace(ids[r][k], at(paths[r], k));
      if (!inserted)
        fail(at(paths[r], k), "vertex " + std::to_string(ids[r][k]) +
                                  " appears twice in the face (also " + it->second +
                                  "; polygons are closed implicitly)");
      used[ids[r][k]] = true;
    }
  // The plane: the first two non-parallel edge directions from the first vertex.
  const auto& outer = ids[0];
  const core::Point<FT, 3>& p0 = x[outer[0]];
  core::Point<FT, 3> n;
  bool has_plane = false;
  for (std::size_t k = 2; k < outer.size() && !has_plane; ++k) {
    n = cross(x[outer[1]] - p0, x[outer[k]] - p0);
    has_plane = n[0] != FT(0) || n[1] != FT(0) || n[2] != FT(0);
  }
  if (!has_plane) fail(fp, "the face has zero area (its vertices are collinear)");
  for (std::size_t r = 0; r < ids.size(); ++r)
    for (std::size_t k = 0; k < ids[r].size(); ++k)
      if (core::dot(n, x[ids[r][k]] - p0) != FT(0))
        fail(at(paths[r], k), "the face is not planar: vertex " + std::to_string(ids[r][k]) +
                                  " is off the plane of its first vertices");
  // Drop a coordinate the plane is not parallel to: the projection is one-to-one on the plane,
  // so simplicity, nesting and the triangulation carry over exactly.
  const int drop = n[0] != FT(0) ? 0 : (n[1] != FT(0) ? 1 : 2);
  std::vector<Ring<FT>> rings;
  std::vector<std::size_t> global;
  for (std::size_t r = 0; r < ids.size(); ++r) {
    Ring<FT> ring;
    ring.path = paths[r];
    for (std::size_t v : ids[r]) {
      core::Point<FT, 2> q;
      for (int d = 0, e = 0; d < 3; ++d)
        if (d != drop) q[e++] = x[v][d];
      ring.pts.push_back(q);
      global.push_back(v);
    }
    rings.push_back(std::move(ring));
  }
  auto triangles = triangulate_rings(rings, fp);
  for (auto& t : triangles)
    for (auto& v : t) v = global[v];
  return triangles;
}

/// vertices + faces: a closed polyhedral surface; the carrier is tetrahedralized from it.
template <class FT>
core::ElementComplex<FT, 3> read_faces(const json& tj, const std::string& tpath) {
  const std::string vp = dot(tpath, "vertices");
  const std::string fp = dot(tpath, "faces");
  gen::TriangulatedSurface<FT> surface;
  surface.points = read_vertices<FT, 3>(require(tj, "vertices", tpath), vp);
  const json& fj = require(tj, "faces", tpath);
  expect_array(fj, fp, "an array of faces");
  if (fj.size() < 4)
    fail(fp, "a closed surface needs at least 4 faces, got " + std::to_string(fj.size()));
  std::vector<bool> used(surface.points.size(), false);
  for (std::size_t f = 0; f < fj.size(); ++f)
    for (const auto& t : triangulate_face<FT>(fj[f], at(fp, f), surface.points, used)) {
      surface.triangles.push_back(t);
      surface.face.push_back(f);
    }
  for (std::size_t k = 0; k < used.size(); ++k)
    if (!used[k]) fail(at(vp, k), "vertex is not used by any face");
  if (const auto d = gen::find_surface_defect(surface)) fail(at(fp, d->face), d->what);
  try {
    return gen::carrier_tetrahedralization(surface);
  } catch (const gen::MeshingError& e) {
    fail(fp,
         std::string("no carrier tetrahedralization without a point on the surface: ") + e.what());
  }
}

// ---------------------------------------------------------------------------------------------
// Templates

/// vertices + cells, with the shape checks of spec/input-format.md.
template <class FT, int D>
core::ElementComplex<FT, D> read_cells(const json& tj, const std::string& tpath) {
  const std::string vp = dot(tpath, "vertices");
  const std::string cp = dot(tpath, "cells");
  const json& vj = require(tj, "vertices", tpath);
  const json& cj = require(tj, "cells", tpath);
  core::ElementComplex<FT, D> m;
  m.points = read_vertices<FT, D>(vj, vp);
  expect_array(cj, cp, "an array of cells");
  if (cj.empty()) fail(cp, "no cells (a template must not be empty)");
  const std::size_t nv = m.points.size();
  std::vector<bool> used(nv, false);
  std::map<core::Simplex, std::size_t> cells;
  for (std::size_t c = 0; c < cj.size(); ++c) {
    const std::string path = at(cp, c);
    const json& cell = cj[c];
    const std::string shape =
        D == 2 ? "a triangle: 3 vertex indices" : "a tetrahedron: 4 vertex indices";
    expect_array(cell, path, shape);
    if (cell.size() != std::size_t(D + 1))
      fail(path, "a cell in " + std::to_string(D) + "D is " + shape + ", got " +
                     std::to_string(cell.size()));
    std::array<core::VertexId, 4> ids{};
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const json& v = cell[k];
      if (!v.is_number_integer())
        fail(at(path, k), "a vertex index must be a JSON integer, got " + type_name(v) +
                              (v.is_number_float() ? " " + v.dump() : ""));
      if (v.is_number_unsigned() ? v.get<std::uint64_t>() >= nv : true)
        fail(path,
             "vertex index " + v.dump() + " out of range (" + std::to_string(nv) + " vertices)");
      ids[k] = core::VertexId(v.get<std::uint64_t>());
      for (std::size_t l = 0; l < k; ++l)
        if (ids[l] == ids[k])
          fail(path, "vertex index " + std::to_string(ids[k]) + " appears twice");
      used[ids[k]] = true;
    }
    const core::Simplex s = core::Simplex::from_range(ids.data(), ids.data() + D + 1);
    if (!core::affinely_independent<FT, D>(m.coords(s)))
      fail(path, std::string("degenerate cell: its vertices are affinely dependent (zero ") +
                     (D == 2 ? "area" : "volume") + ")");
    auto [it, inserted] = cells.emplace(s, c);
    if (!inserted) fail(path, "the same cell as cells[" + std::to_string(it->second) + "]");
    m.elements.push_back(s);
  }
  for (std::size_t k = 0; k < nv; ++k)
    if (!used[k]) fail(at(vp, k), "vertex is not used by any cell");
  return m;
}

template <class FT, int D>
std::vector<core::InstanceSpec<FT, D>> read_instances(const json& tj, const std::string& tpath) {
  const std::string ip = dot(tpath, "instances");
  const json& ij = require(tj, "instances", tpath);
  expect_array(ij, ip, "an array of instances");
  if (ij.empty()) fail(ip, "no instances (every template needs at least one)");
  std::vector<core::InstanceSpec<FT, D>> out;
  for (std::size_t g = 0; g < ij.size(); ++g) {
    const std::string gp = at(ip, g);
    const json& inst = ij[g];
    expect_object(inst, gp, "an instance object {\"transformation\": ..., \"region\": ...}");
    check_keys(inst, gp, {"transformation", "region"});
    core::InstanceSpec<FT, D> spec;
    spec.transformation =
        parse_transformation<FT, D>(require(inst, "transformation", gp), dot(gp, "transformation"));
    if (inst.contains("region"))
      spec.region =
          int(get_integer(inst["region"], dot(gp, "region"), std::numeric_limits<int>::min(),
                          std::numeric_limits<int>::max()));
    out.push_back(std::move(spec));
  }
  return out;
}

template <class FT, int D>
core::TemplatedStructure<FT, D> read_structure(const json& root) {
  core::TemplatedStructure<FT, D> x;
  const json& ts = root["templates"];
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const std::string tp = at("templates", i);
    const json& tj = ts[i];
    expect_object(tj, tp, "a template object");
    check_keys(tj, tp,
               {"name", "kind", "vertices", "cells", "faces", "polygon", "holes", "instances"});
    core::Template<FT, D> t;
    t.name =
        tj.contains("name") ? get_string(tj["name"], dot(tp, "name")) : "X" + std::to_string(i + 1);
    if (tj.contains("kind")) {
      const std::string kind = get_string(tj["kind"], dot(tp, "kind"));
      if (kind == "mesh")
        t.kind = core::TemplateKind::mesh;
      else if (kind == "geometry")
        t.kind = core::TemplateKind::geometry;
      else
        fail(dot(tp, "kind"),
             "unknown kind " + quote_text(kind) + " (expected \"mesh\" or \"geometry\")");
    }
    const bool has_polygon = tj.contains("polygon");
    if (tj.contains("holes") && !has_polygon) fail(dot(tp, "holes"), "\"holes\" needs \"polygon\"");
    if (has_polygon) {
      if (D != 2)
        fail(dot(tp, "polygon"), "\"polygon\" is for 2D geometry templates only (this file is 3D)");
      if (t.kind != core::TemplateKind::geometry)
        fail(dot(tp, "polygon"),
             "\"polygon\" is for geometry templates only: add \"kind\": \"geometry\" "
             "or give a mesh template by \"vertices\" and \"cells\"");
      for (const char* k : {"vertices", "cells", "faces"})
        if (tj.contains(k))
          fail(tp,
               std::string(
                   "give either \"polygon\" or \"vertices\" and \"cells\", not both (found \"") +
                   k + "\")");
      if constexpr (D == 2) t.mesh = triangulate_polygon<FT>(tj, tp);
    } else if (tj.contains("faces")) {
      if (D != 3)
        fail(dot(tp, "faces"), "\"faces\" is for 3D geometry templates only (this file is 2D; "
                               "use \"polygon\")");
      if (t.kind != core::TemplateKind::geometry)
        fail(dot(tp, "faces"),
             "\"faces\" is for geometry templates only: add \"kind\": "
             "\"geometry\" or give a mesh template by \"vertices\" and \"cells\"");
      if (tj.contains("cells"))
        fail(tp, "give either \"faces\" or \"cells\" with the \"vertices\", not both");
      if constexpr (D == 3) t.mesh = read_faces<FT>(tj, tp);
    } else {
      if (!tj.contains("vertices") && !tj.contains("cells"))
        fail(tp, std::string("missing fields \"vertices\" and \"cells\"") +
                     (t.kind != core::TemplateKind::geometry ? ""
                      : D == 2                               ? " (or \"polygon\")"
                                                             : " (or \"vertices\" and \"faces\")"));
      t.mesh = read_cells<FT, D>(tj, tp);
    }
    t.mesh = core::face_completion(t.mesh);
    t.mesh.normalize();
    x.templates.push_back(std::move(t));
    x.instances.push_back(read_instances<FT, D>(tj, tp));
  }
  return x;
}

// ---------------------------------------------------------------------------------------------
// Writing

/// Compact one-line JSON with a space after ',' and ':'.
std::string inline_json(const ojson& j) {
  if (j.is_array()) {
    std::string s = "[";
    for (std::size_t k = 0; k < j.size(); ++k) s += (k ? ", " : "") + inline_json(j[k]);
    return s + "]";
  }
  if (j.is_object()) {
    std::string s = "{";
    bool first = true;
    for (const auto& item : j.items()) {
      s += (first ? "" : ", ") +
           ojson(item.key()).dump(-1, ' ', false, ojson::error_handler_t::replace) + ": " +
           inline_json(item.value());
      first = false;
    }
    return s + "}";
  }
  return j.dump(-1, ' ', false, ojson::error_handler_t::replace);
}

/// Pretty printing that keeps short arrays and objects (points, cells, transformations) on one
/// line.
void write_pretty(std::string& out, const ojson& j, int indent, bool force_expand = false) {
  constexpr std::size_t kWidth = 120;
  const std::string flat = inline_json(j);
  if (!j.is_structured() || j.empty() ||
      (!force_expand && flat.size() + std::size_t(indent) <= kWidth)) {
    out += flat;
    return;
  }
  const std::string pad(std::size_t(indent + 2), ' ');
  out += j.is_array() ? "[\n" : "{\n";
  std::size_t k = 0;
  for (const auto& item : j.items()) {
    out += pad;
    if (j.is_object())
      out += ojson(item.key()).dump(-1, ' ', false, ojson::error_handler_t::replace) + ": ";
    write_pretty(out, item.value(), indent + 2);
    out += ++k < j.size() ? ",\n" : "\n";
  }
  out += std::string(std::size_t(indent), ' ') + (j.is_array() ? "]" : "}");
}

std::string pretty(const ojson& j) {
  std::string out;
  write_pretty(out, j, 0, true);
  return out + "\n";
}

template <class FT, int D>
ojson point_json(const core::Point<FT, D>& p) {
  ojson a = ojson::array();
  for (int d = 0; d < D; ++d) a.push_back(number_text(p[d]));
  return a;
}

ojson simplex_json(const core::Simplex& s) {
  ojson a = ojson::array();
  for (core::VertexId v : s) a.push_back(v);
  return a;
}

template <class FT, int D>
ojson transformation_json(const Rigid<FT, D>& t) {
  ojson m = ojson::array();
  for (int i = 0; i < D; ++i) {
    ojson row = ojson::array();
    for (int j = 0; j < D; ++j) row.push_back(number_text(t.matrix()[i][j]));
    m.push_back(row);
  }
  ojson o = ojson::object();
  o["matrix"] = m;
  o["translation"] = point_json<FT, D>(t.translation_part());
  return o;
}

template <class FT, int D>
std::string structure_to_json(const core::TemplatedStructure<FT, D>& x) {
  ojson root = ojson::object();
  root["symmesh"] = kFormat;
  root["dimension"] = D;
  ojson ts = ojson::array();
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    const auto& t = x.templates[i];
    ojson tj = ojson::object();
    tj["name"] = t.name;
    tj["kind"] = t.kind == core::TemplateKind::mesh ? "mesh" : "geometry";
    ojson vs = ojson::array();
    for (const auto& p : t.mesh.points) vs.push_back(point_json<FT, D>(p));
    tj["vertices"] = vs;
    ojson cs = ojson::array();
    for (const auto& e : t.mesh.elements)
      if (e.dim() == D) cs.push_back(simplex_json(e));
    tj["cells"] = cs;
    ojson is = ojson::array();
    if (i < x.instances.size())
      for (const auto& spec : x.instances[i]) {
        ojson ij = ojson::object();
        ij["transformation"] = transformation_json<FT, D>(spec.transformation);
        ij["region"] = spec.region;
        is.push_back(ij);
      }
    tj["instances"] = is;
    ts.push_back(tj);
  }
  root["templates"] = ts;
  return pretty(root);
}

template <class FT, int D>
std::string element_complex_to_json(const core::ElementComplex<FT, D>& m) {
  ojson root = ojson::object();
  root["dimension"] = D;
  ojson vs = ojson::array();
  for (const auto& p : m.points) vs.push_back(point_json<FT, D>(p));
  root["vertices"] = vs;
  ojson es = ojson::array();
  for (const auto& e : m.elements) es.push_back(simplex_json(e));
  root["elements"] = es;
  return pretty(root);
}

} // namespace

std::string number_text(const number::Cyclotomic& x) {
  return number_text<number::Cyclotomic>(x);
}

// ---------------------------------------------------------------------------------------------
// Public API

Exact parse_exact(const std::string& text, const std::string& field) {
  return to_exact(parse_rational(text, field));
}

std::string exact_to_string(const Exact& x) {
  // Exact values are kept in canonical form (lowest terms, positive denominator).
  return rational_text(raw_mpq(CGAL::exact(x)));
}

AnyStructure parse_templated_structure(const std::string& text, const std::string& source) {
  json root;
  try {
    root = json::parse(text, DuplicateKeyGuard(source));
  } catch (const json::parse_error& e) {
    fail_malformed(source, e);
  } catch (const json::out_of_range& e) {
    // A JSON number beyond double range ("1e999"): nlohmann reports it as out_of_range, with the
    // token but no position (found by the fuzzer: it escaped as an uncaught exception).
    std::string what = e.what();
    const auto quote = what.find('\'');
    std::string token = quote == std::string::npos ? what : what.substr(quote);
    if (token.size() > 40) token = token.substr(0, 37) + "...";
    fail(source, "malformed JSON: the number " + token +
                     " is out of range (write exact numbers as strings, e.g. \"1e999\")");
  }
  try {
    expect_object(root, source, "a JSON object at the top level");
    check_keys(root, source, {"symmesh", "dimension", "templates", "description"});
    const std::string fmt = get_string(require(root, "symmesh", source), "symmesh");
    if (fmt != kFormat)
      fail("symmesh", "unsupported format " + quote_text(fmt) + " (expected \"" + kFormat + "\")");
    if (root.contains("description")) get_string(root["description"], "description");
    const int dim = int(
        get_integer(require(root, "dimension", source), "dimension", 2, 3, "the integer 2 or 3"));
    const json& ts = require(root, "templates", source);
    expect_array(ts, "templates", "an array of templates");
    if (ts.empty()) fail("templates", "no templates");
    number::CyclotomicFieldPtr field = choose_field(root);
    if (!field) {
      if (dim == 2) return read_structure<Exact, 2>(root);
      return read_structure<Exact, 3>(root);
    }
    FieldScope scope(field);
    if (dim == 2) return read_structure<Cyclotomic, 2>(root);
    return read_structure<Cyclotomic, 3>(root);
  } catch (const InputError&) {
    throw;
  } catch (const json::exception& e) {
    // Not expected (every access is type-checked first); kept so that input never escapes as
    // anything but an InputError.
    fail(source, std::string("invalid input: ") + e.what());
  } catch (const std::invalid_argument& e) {
    fail(source, std::string("invalid input: ") + e.what());
  }
}

AnyStructure read_templated_structure(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "cannot open file (it is a directory)");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open file");
  std::ostringstream buf;
  buf << in.rdbuf();
  if (in.bad()) fail(path, "cannot read file");
  return parse_templated_structure(buf.str(), path);
}

std::string to_json(const Structure2& x) {
  return structure_to_json<Exact, 2>(x);
}
std::string to_json(const Structure3& x) {
  return structure_to_json<Exact, 3>(x);
}
std::string to_json(const CyclotomicStructure2& x) {
  return structure_to_json<Cyclotomic, 2>(x);
}
std::string to_json(const CyclotomicStructure3& x) {
  return structure_to_json<Cyclotomic, 3>(x);
}

std::string complex_to_json(const core::ElementComplex<Exact, 2>& m) {
  return element_complex_to_json<Exact, 2>(m);
}
std::string complex_to_json(const core::ElementComplex<Exact, 3>& m) {
  return element_complex_to_json<Exact, 3>(m);
}

namespace {
/// The field of a K_m structure: that of its first number in a field (the reader puts every
/// number in the field; a structure built in code may hold rationals only).
template <int D>
number::CyclotomicFieldPtr field_of(const core::TemplatedStructure<Cyclotomic, D>& x) {
  for (const auto& t : x.templates)
    for (const auto& p : t.mesh.points)
      for (const auto& c : p)
        if (c.field()) return c.field();
  for (const auto& specs : x.instances)
    for (const auto& spec : specs)
      for (const auto& row : spec.transformation.matrix())
        for (const auto& a : row)
          if (a.field()) return a.field();
  return nullptr;
}
} // namespace

int field_order(const AnyStructure& x) {
  return std::visit(
      [](const auto& s) -> int {
        if constexpr (requires { field_of(s); }) {
          const auto f = field_of(s);
          return f ? f->m() : 0;
        } else {
          return 0;
        }
      },
      x);
}

std::string kernel_name(const AnyStructure& x) {
  if (std::holds_alternative<Structure2>(x) || std::holds_alternative<Structure3>(x))
    return "rational (CGAL Epeck, exact)";
  const int m = field_order(x);
  if (m == 0) return "K_m (exact real cyclotomic field; all numbers rational)";
  return "K_" + std::to_string(m) + " = Q(cos 2pi/" + std::to_string(m) +
         ") (exact real cyclotomic field)";
}

} // namespace symmesh::io
