/// Reading templated-structure JSON, part 1 (internal to io/templated_structure_json.cpp): one-line
/// errors naming the JSON path, exact rational numbers, the duplicate-key guard and typed field
/// access — spec/input-format.md
#pragma once
#include "symmesh/io/templated_structure_json.h"

#include <gmp.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace symmesh::io::structure_json {

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
inline std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t' || c == '\f' || c == '\v') c = ' ';
  return s;
}

[[noreturn]] inline void fail(const std::string& path, const std::string& message) {
  throw InputError(one_line(path + ": " + message));
}

/// A user string quoted for an error message, shortened if long.
inline std::string quote_text(const std::string& s) {
  constexpr std::size_t kMax = 40;
  if (s.size() <= kMax) return "\"" + s + "\"";
  return "\"" + s.substr(0, kMax) + "...\"";
}

inline std::string type_name(const json& j) {
  if (j.is_number_float()) return "a non-integer number";
  if (j.is_number()) return "an integer";
  return std::string(j.is_array() || j.is_object() ? "an " : "a ") + j.type_name();
}

inline std::string at(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}
inline std::string dot(const std::string& path, const std::string& key) {
  return path + "." + key;
}

// ---------------------------------------------------------------------------------------------
// Exact numbers

inline bool all_digits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

/// Strips leading zeros (keeps one digit).
inline std::string strip_zeros(const std::string& digits) {
  const auto nz = digits.find_first_not_of('0');
  return nz == std::string::npos ? "0" : digits.substr(nz);
}

/// ±num/den from decimal digit strings (den != 0), reduced to lowest terms.
inline mpq_class make_rational(bool negative, const std::string& num, const std::string& den) {
  mpq_class q;
  const std::string text = (negative ? "-" : "") + strip_zeros(num) + "/" + strip_zeros(den);
  if (mpq_set_str(q.get_mpq_t(), text.c_str(), 10) != 0)
    throw std::logic_error("make_rational: GMP rejected " + text);
  mpq_canonicalize(q.get_mpq_t());
  return q;
}

/// "n" or "n/d" of a canonical rational (mpq_get_str omits a denominator 1).
inline std::string rational_text(mpq_srcptr q) {
  std::string out(mpz_sizeinbase(mpq_numref(q), 10) + mpz_sizeinbase(mpq_denref(q), 10) + 3, '\0');
  mpq_get_str(out.data(), 10, q);
  out.resize(std::char_traits<char>::length(out.c_str()));
  return out;
}

inline std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// "n", "n/d" or a decimal, exactly (spec/input-format.md#numbers).
inline mpq_class parse_rational(const std::string& text, const std::string& field) {
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
inline void check_keys(const json& obj, const std::string& path,
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

inline const json& require(const json& obj, const char* key, const std::string& path) {
  auto it = obj.find(key);
  if (it == obj.end()) fail(path, std::string("missing field \"") + key + "\"");
  return *it;
}

inline void expect_object(const json& j, const std::string& path,
                          const std::string& what = "an object") {
  if (!j.is_object()) fail(path, "expected " + what + ", got " + type_name(j));
}

inline void expect_array(const json& j, const std::string& path,
                         const std::string& what = "an array") {
  if (!j.is_array()) fail(path, "expected " + what + ", got " + type_name(j));
}

inline std::string get_string(const json& j, const std::string& path) {
  if (!j.is_string()) fail(path, "expected a string, got " + type_name(j));
  return j.get<std::string>();
}

inline long long get_integer(const json& j, const std::string& path, long long lo, long long hi,
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

} // namespace symmesh::io::structure_json
