// The templated-structure JSON format: reader and writer — spec/input-format.md
//
// Reading is in three steps: nlohmann::json parses the text (a parser callback rejects
// duplicate keys and knows their JSON path), the shape of the document is validated field by
// field (every error names the field by its JSON path), and 2D geometry templates given as a
// polygon are triangulated exactly with a constrained Delaunay triangulation. Eq. 4.2 and
// conformity are not checked here: that is core::analyse.
#include "symmesh/io/templated_structure_json.h"

#include "symmesh/core/element_complex.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <gmp.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <deque>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>
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
Rational make_rational(bool negative, const std::string& num, const std::string& den) {
  Rational q;
  const std::string text = (negative ? "-" : "") + strip_zeros(num) + "/" + strip_zeros(den);
  if (mpq_set_str(raw_mpq(q), text.c_str(), 10) != 0)
    throw std::logic_error("make_rational: GMP rejected " + text);
  mpq_canonicalize(raw_mpq(q));
  return q;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
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

Exact get_exact(const json& j, const std::string& path) {
  if (j.is_string()) return parse_exact(j.get<std::string>(), path);
  if (j.is_number_integer()) return parse_exact(j.dump(), path);
  if (j.is_number_float())
    fail(path, "the JSON number " + j.dump() +
                   " is not exact: give non-integer (and very large) numbers as strings, e.g. "
                   "\"0.25\" or \"1/4\"");
  fail(path,
       "expected an exact number (a string such as \"3/5\" or \"-0.25\", or a JSON integer), got " +
           type_name(j));
}

template <int D>
core::Point<Exact, D> get_point(const json& j, const std::string& path,
                                const char* what = "coordinates") {
  expect_array(j, path, "an array of " + std::to_string(D) + " " + what);
  if (j.size() != std::size_t(D))
    fail(path, "expected " + std::to_string(D) + " " + what + " (dimension " + std::to_string(D) +
                   "), got " + std::to_string(j.size()));
  core::Point<Exact, D> p;
  for (int d = 0; d < D; ++d) p[d] = get_exact(j[std::size_t(d)], at(path, std::size_t(d)));
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

template <int D>
using Rigid = core::RigidTransformation<Exact, D>;

/// Runs a core constructor; its std::invalid_argument becomes an InputError at `path`.
template <class F>
auto guarded(const std::string& path, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    fail(path, e.what());
  }
}

template <int D>
Rigid<D> parse_rotation(const json& r, const std::string& path) {
  expect_object(r, path);
  core::Point<Exact, D> center = core::zero_point<Exact, D>();
  if (r.contains("center")) center = get_point<D>(r["center"], dot(path, "center"));
  if constexpr (D == 3) {
    if (!r.contains("quaternion"))
      fail(path,
           "a 3D rotation is given by \"quaternion\": [w, x, y, z] (and an optional \"center\")");
    check_keys(r, path, {"quaternion", "center"});
    const std::string qp = dot(path, "quaternion");
    const json& q = r["quaternion"];
    expect_array(q, qp, "an array of 4 exact numbers [w, x, y, z]");
    if (q.size() != 4) fail(qp, "expected 4 numbers [w, x, y, z], got " + std::to_string(q.size()));
    std::array<Exact, 4> c;
    for (std::size_t k = 0; k < 4; ++k) c[k] = get_exact(q[k], at(qp, k));
    return guarded(qp,
                   [&] { return Rigid<D>::rotation_quaternion(c[0], c[1], c[2], c[3], center); });
  } else {
    if (r.contains("quaternion")) fail(dot(path, "quaternion"), "quaternion rotations are 3D only");
    if (r.contains("order")) {
      check_keys(r, path, {"order", "k", "center"});
      const long long n =
          get_integer(r["order"], dot(path, "order"), 1, 1000000000, "a positive integer");
      long long k = 1;
      if (r.contains("k")) k = get_integer(r["k"], dot(path, "k"), -1000000000, 1000000000);
      // The angle 2πk/n in lowest terms 2πk'/n'; only n' ∈ {1, 2, 4} has rational cos and sin.
      long long kk = ((k % n) + n) % n;
      const long long g = std::gcd(kk, n);
      const long long order = n / g;
      kk /= g;
      Exact c, s;
      if (order == 1) {
        c = 1, s = 0;
      } else if (order == 2) {
        c = -1, s = 0;
      } else if (order == 4) {
        c = 0, s = kk == 1 ? 1 : -1;
      } else {
        fail(dot(path, "order"), "rotation order " + std::to_string(order) +
                                     " needs the cyclotomic kernel, not available yet");
      }
      return Rigid<D>::rotation_2d(c, s, center);
    }
    if (r.contains("cos") || r.contains("sin")) {
      check_keys(r, path, {"cos", "sin", "center"});
      const Exact c = get_exact(require(r, "cos", path), dot(path, "cos"));
      const Exact s = get_exact(require(r, "sin", path), dot(path, "sin"));
      return guarded(path, [&] { return Rigid<D>::rotation_2d(c, s, center); });
    }
    fail(path, "a 2D rotation is given by \"cos\" and \"sin\" or by \"order\" and \"k\" (and an "
               "optional \"center\")");
  }
}

template <int D>
Rigid<D> parse_transformation(const json& t, const std::string& path, int depth = 0) {
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
    typename Rigid<D>::Mat a;
    for (int i = 0; i < D; ++i) {
      const auto row = get_point<D>(m[std::size_t(i)], at(mp, std::size_t(i)), "entries");
      for (int j = 0; j < D; ++j) a[i][j] = row[j];
    }
    core::Point<Exact, D> b = core::zero_point<Exact, D>();
    if (t.contains("translation")) b = get_point<D>(t["translation"], dot(path, "translation"));
    return guarded(mp, [&] { return Rigid<D>::from_matrix(a, b); });
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
    return Rigid<D>();
  }
  if (kind == "translation") return Rigid<D>::translation(get_point<D>(v, vp));
  if (kind == "reflection") {
    expect_object(v, vp, "an object {\"normal\": [...], \"offset\": d}");
    check_keys(v, vp, {"normal", "offset"});
    const auto n = get_point<D>(require(v, "normal", vp), dot(vp, "normal"));
    Exact d = 0;
    if (v.contains("offset")) d = get_exact(v["offset"], dot(vp, "offset"));
    return guarded(dot(vp, "normal"), [&] { return Rigid<D>::reflection(n, d); });
  }
  if (kind == "rotation") return parse_rotation<D>(v, vp);
  if (kind == "signed_permutation") {
    expect_object(v, vp, "an object {\"perm\": [...], \"sign\": [...], \"translation\": [...]}");
    check_keys(v, vp, {"perm", "sign", "translation"});
    const auto perm = get_int_array<D>(require(v, "perm", vp), dot(vp, "perm"), -1000, 1000);
    const auto sign = get_int_array<D>(require(v, "sign", vp), dot(vp, "sign"), -1000, 1000);
    core::Point<Exact, D> b = core::zero_point<Exact, D>();
    if (v.contains("translation")) b = get_point<D>(v["translation"], dot(vp, "translation"));
    return guarded(vp, [&] { return Rigid<D>::signed_permutation(perm, sign, b); });
  }
  if (kind == "compose") {
    expect_array(v, vp, "a non-empty array of transformations");
    if (v.empty()) fail(vp, "expected at least one transformation");
    Rigid<D> acc;
    for (std::size_t k = 0; k < v.size(); ++k)
      acc = acc * parse_transformation<D>(v[k], at(vp, k), depth + 1);
    return acc;
  }
  fail(path, "unknown transformation " + quote_text(kind) +
                 " (expected one of: " + kTransformationKinds + ")");
}

// ---------------------------------------------------------------------------------------------
// Polygons (2D geometry templates): validation and exact constrained Delaunay triangulation

struct Ring {
  std::string path;                       // e.g. templates[0].polygon or templates[0].holes[1]
  std::vector<core::Point<Exact, 2>> pts; // implicitly closed
  std::size_t first = 0;                  // global index of pts[0]
};

using K = CGAL::Epeck;
using P2 = K::Point_2;

P2 to_cgal(const core::Point<Exact, 2>& p) {
  return P2(p[0], p[1]);
}

struct Edge {
  std::size_t ring, k; // edge from ring.pts[k] to ring.pts[(k+1) % n]
  P2 a, b;
  Exact xmin, xmax;
};

std::string edge_name(const std::vector<Ring>& rings, const Edge& e) {
  const Ring& r = rings[e.ring];
  const std::string base = r.path.substr(r.path.rfind('.') + 1);
  return base + "[" + std::to_string(e.k) + "]-" + base + "[" +
         std::to_string((e.k + 1) % r.pts.size()) + "]";
}

/// The rings have pairwise disjoint boundaries except for consecutive edges of one ring, which
/// share their common vertex only: each ring is a simple polygon and no two rings touch.
void check_simple_and_disjoint(const std::vector<Ring>& rings) {
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& pts = rings[r].pts;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const auto& p = pts[k];
      const auto& q = pts[(k + 1) % pts.size()];
      edges.push_back({r, k, to_cgal(p), to_cgal(q), std::min(p[0], q[0]), std::max(p[0], q[0])});
    }
  }
  std::sort(edges.begin(), edges.end(),
            [](const Edge& x, const Edge& y) { return x.xmin < y.xmin; });
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size() && !(edges[i].xmax < edges[j].xmin); ++j) {
      const Edge& e = edges[i];
      const Edge& f = edges[j];
      const std::size_t n = rings[e.ring].pts.size();
      const bool same_ring = e.ring == f.ring;
      const bool e_then_f = same_ring && (e.k + 1) % n == f.k;
      const bool f_then_e = same_ring && (f.k + 1) % n == e.k;
      bool bad;
      if (e_then_f || f_then_e) {
        // Consecutive edges u-v, v-w: they overlap beyond v iff u, v, w are collinear and u, w
        // lie on the same side of v.
        const P2& u = e_then_f ? e.a : f.a;
        const P2& v = e_then_f ? e.b : f.b;
        const P2& w = e_then_f ? f.b : e.b;
        bad = CGAL::collinear(u, v, w) && CGAL::angle(u, v, w) == CGAL::ACUTE;
        if (n == 3 && !bad) bad = CGAL::collinear(u, v, w);
      } else {
        bad = CGAL::do_intersect(K::Segment_2(e.a, e.b), K::Segment_2(f.a, f.b));
      }
      if (bad) {
        const Edge& later = e.ring < f.ring ? f : e;
        const Edge& earlier = e.ring < f.ring ? e : f;
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
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT =
    CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;

/// Nesting level of every face: the number of constraint crossings on a path from the infinite
/// face. Flood-fills each level without crossing constraints; crossings seed the next level.
void mark_nesting(CDT& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().nesting = -1;
  std::deque<std::pair<CDT::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    auto [start, level] = seeds.front();
    seeds.pop_front();
    if (start->info().nesting != -1) continue;
    std::vector<CDT::Face_handle> stack{start};
    start->info().nesting = level;
    while (!stack.empty()) {
      auto f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        auto n = f->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained(CDT::Edge(f, i))) {
          seeds.emplace_back(n, level + 1);
        } else {
          n->info().nesting = level;
          stack.push_back(n);
        }
      }
    }
  }
}

/// Validates outer polygon + holes and triangulates the domain they bound.
core::ElementComplex<Exact, 2> triangulate_polygon(const json& tj, const std::string& tpath) {
  std::vector<Ring> rings;
  auto read_ring = [&](const json& j, const std::string& path) {
    expect_array(j, path, "an array of [x, y] vertices");
    if (j.size() < 3)
      fail(path, "a polygon needs at least 3 vertices, got " + std::to_string(j.size()));
    Ring r;
    r.path = path;
    for (std::size_t k = 0; k < j.size(); ++k) r.pts.push_back(get_point<2>(j[k], at(path, k)));
    rings.push_back(std::move(r));
  };
  read_ring(tj["polygon"], dot(tpath, "polygon"));
  if (tj.contains("holes")) {
    const std::string hp = dot(tpath, "holes");
    const json& h = tj["holes"];
    expect_array(h, hp, "an array of polygons");
    for (std::size_t k = 0; k < h.size(); ++k) read_ring(h[k], at(hp, k));
  }
  // Repeated vertices (within a ring, e.g. a closing copy of the first vertex, or across rings).
  std::map<core::Point<Exact, 2>, std::string, core::PointLess<Exact, 2>> seen;
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
  std::vector<std::vector<P2>> polys;
  for (const auto& r : rings) {
    std::vector<P2> p;
    for (const auto& q : r.pts) p.push_back(to_cgal(q));
    polys.push_back(std::move(p));
  }
  for (std::size_t h = 1; h < rings.size(); ++h) {
    const P2& v = polys[h][0];
    if (CGAL::bounded_side_2(polys[0].begin(), polys[0].end(), v, K()) != CGAL::ON_BOUNDED_SIDE)
      fail(rings[h].path, "the hole is not inside the polygon");
    for (std::size_t o = 1; o < rings.size(); ++o)
      if (o != h &&
          CGAL::bounded_side_2(polys[o].begin(), polys[o].end(), v, K()) == CGAL::ON_BOUNDED_SIDE)
        fail(rings[h].path, "the hole lies inside another hole (" +
                                rings[o].path.substr(rings[o].path.rfind('.') + 1) + ")");
  }

  CDT cdt;
  std::vector<CDT::Vertex_handle> vh(count);
  try {
    for (const auto& r : rings)
      for (std::size_t k = 0; k < r.pts.size(); ++k) {
        vh[r.first + k] = cdt.insert(polys[&r - rings.data()][k]);
        vh[r.first + k]->info() = r.first + k;
      }
    for (const auto& r : rings)
      for (std::size_t k = 0; k < r.pts.size(); ++k)
        cdt.insert_constraint(vh[r.first + k], vh[r.first + (k + 1) % r.pts.size()]);
  } catch (const CDT::Intersection_of_constraints_exception&) {
    fail(dot(tpath, "polygon"), "the polygon boundaries intersect");
  }
  mark_nesting(cdt);

  core::ElementComplex<Exact, 2> m;
  for (const auto& r : rings)
    for (const auto& p : r.pts) m.points.push_back(p);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info().in_domain())
      m.elements.push_back(core::Simplex{core::VertexId(f->vertex(0)->info()),
                                         core::VertexId(f->vertex(1)->info()),
                                         core::VertexId(f->vertex(2)->info())});
  if (m.elements.empty()) fail(dot(tpath, "polygon"), "the polygon bounds no area");
  return m;
}

// ---------------------------------------------------------------------------------------------
// Templates

/// vertices + cells, with the shape checks of spec/input-format.md.
template <int D>
core::ElementComplex<Exact, D> read_cells(const json& tj, const std::string& tpath) {
  const std::string vp = dot(tpath, "vertices");
  const std::string cp = dot(tpath, "cells");
  const json& vj = require(tj, "vertices", tpath);
  const json& cj = require(tj, "cells", tpath);
  expect_array(vj, vp, "an array of vertices");
  expect_array(cj, cp, "an array of cells");
  if (vj.empty()) fail(vp, "no vertices (a template must not be empty)");
  if (cj.empty()) fail(cp, "no cells (a template must not be empty)");
  core::ElementComplex<Exact, D> m;
  std::map<core::Point<Exact, D>, std::size_t, core::PointLess<Exact, D>> seen;
  for (std::size_t k = 0; k < vj.size(); ++k) {
    m.points.push_back(get_point<D>(vj[k], at(vp, k)));
    auto [it, inserted] = seen.emplace(m.points.back(), k);
    if (!inserted)
      fail(at(vp, k),
           "duplicate vertex (same coordinates as vertices[" + std::to_string(it->second) + "])");
  }
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
    if (!core::affinely_independent<Exact, D>(m.coords(s)))
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

template <int D>
std::vector<core::InstanceSpec<Exact, D>> read_instances(const json& tj, const std::string& tpath) {
  const std::string ip = dot(tpath, "instances");
  const json& ij = require(tj, "instances", tpath);
  expect_array(ij, ip, "an array of instances");
  if (ij.empty()) fail(ip, "no instances (every template needs at least one)");
  std::vector<core::InstanceSpec<Exact, D>> out;
  for (std::size_t g = 0; g < ij.size(); ++g) {
    const std::string gp = at(ip, g);
    const json& inst = ij[g];
    expect_object(inst, gp, "an instance object {\"transformation\": ..., \"region\": ...}");
    check_keys(inst, gp, {"transformation", "region"});
    core::InstanceSpec<Exact, D> spec;
    spec.transformation =
        parse_transformation<D>(require(inst, "transformation", gp), dot(gp, "transformation"));
    if (inst.contains("region"))
      spec.region =
          int(get_integer(inst["region"], dot(gp, "region"), std::numeric_limits<int>::min(),
                          std::numeric_limits<int>::max()));
    out.push_back(std::move(spec));
  }
  return out;
}

template <int D>
core::TemplatedStructure<Exact, D> read_structure(const json& root) {
  core::TemplatedStructure<Exact, D> x;
  const json& ts = root["templates"];
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const std::string tp = at("templates", i);
    const json& tj = ts[i];
    expect_object(tj, tp, "a template object");
    check_keys(tj, tp, {"name", "kind", "vertices", "cells", "polygon", "holes", "instances"});
    core::Template<Exact, D> t;
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
      for (const char* k : {"vertices", "cells"})
        if (tj.contains(k))
          fail(tp,
               std::string(
                   "give either \"polygon\" or \"vertices\" and \"cells\", not both (found \"") +
                   k + "\")");
      if constexpr (D == 2) t.mesh = triangulate_polygon(tj, tp);
    } else {
      if (!tj.contains("vertices") && !tj.contains("cells"))
        fail(tp, std::string("missing fields \"vertices\" and \"cells\"") +
                     (D == 2 && t.kind == core::TemplateKind::geometry ? " (or \"polygon\")" : ""));
      t.mesh = read_cells<D>(tj, tp);
    }
    t.mesh = core::face_completion(t.mesh);
    t.mesh.normalize();
    x.templates.push_back(std::move(t));
    x.instances.push_back(read_instances<D>(tj, tp));
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

template <int D>
ojson point_json(const core::Point<Exact, D>& p) {
  ojson a = ojson::array();
  for (int d = 0; d < D; ++d) a.push_back(exact_to_string(p[d]));
  return a;
}

ojson simplex_json(const core::Simplex& s) {
  ojson a = ojson::array();
  for (core::VertexId v : s) a.push_back(v);
  return a;
}

template <int D>
ojson transformation_json(const Rigid<D>& t) {
  ojson m = ojson::array();
  for (int i = 0; i < D; ++i) {
    ojson row = ojson::array();
    for (int j = 0; j < D; ++j) row.push_back(exact_to_string(t.matrix()[i][j]));
    m.push_back(row);
  }
  ojson o = ojson::object();
  o["matrix"] = m;
  o["translation"] = point_json<D>(t.translation_part());
  return o;
}

template <int D>
std::string structure_to_json(const core::TemplatedStructure<Exact, D>& x) {
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
    for (const auto& p : t.mesh.points) vs.push_back(point_json<D>(p));
    tj["vertices"] = vs;
    ojson cs = ojson::array();
    for (const auto& e : t.mesh.elements)
      if (e.dim() == D) cs.push_back(simplex_json(e));
    tj["cells"] = cs;
    ojson is = ojson::array();
    if (i < x.instances.size())
      for (const auto& spec : x.instances[i]) {
        ojson ij = ojson::object();
        ij["transformation"] = transformation_json<D>(spec.transformation);
        ij["region"] = spec.region;
        is.push_back(ij);
      }
    tj["instances"] = is;
    ts.push_back(tj);
  }
  root["templates"] = ts;
  return pretty(root);
}

template <int D>
std::string element_complex_to_json(const core::ElementComplex<Exact, D>& m) {
  ojson root = ojson::object();
  root["dimension"] = D;
  ojson vs = ojson::array();
  for (const auto& p : m.points) vs.push_back(point_json<D>(p));
  root["vertices"] = vs;
  ojson es = ojson::array();
  for (const auto& e : m.elements) es.push_back(simplex_json(e));
  root["elements"] = es;
  return pretty(root);
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Public API

Exact parse_exact(const std::string& text, const std::string& field) {
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
    return Exact(make_rational(negative, num, den));
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
      return Exact(make_rational(negative, digits + std::string(std::size_t(e10), '0'), "1"));
    return Exact(make_rational(negative, digits, "1" + std::string(std::size_t(-e10), '0')));
  }
}

std::string exact_to_string(const Exact& x) {
  // Exact values are kept in canonical form (lowest terms, positive denominator); mpq_get_str
  // prints "n" when the denominator is 1.
  const Rational& q = CGAL::exact(x);
  std::string out(mpz_sizeinbase(mpq_numref(raw_mpq(q)), 10) +
                      mpz_sizeinbase(mpq_denref(raw_mpq(q)), 10) + 3,
                  '\0');
  mpq_get_str(out.data(), 10, raw_mpq(q));
  out.resize(std::char_traits<char>::length(out.c_str()));
  return out;
}

AnyStructure parse_templated_structure(const std::string& text, const std::string& source) {
  json root;
  try {
    root = json::parse(text, DuplicateKeyGuard(source));
  } catch (const json::parse_error& e) {
    fail_malformed(source, e);
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
    if (dim == 2) return read_structure<2>(root);
    return read_structure<3>(root);
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
  return structure_to_json<2>(x);
}
std::string to_json(const Structure3& x) {
  return structure_to_json<3>(x);
}

std::string complex_to_json(const core::ElementComplex<Exact, 2>& m) {
  return element_complex_to_json<2>(m);
}
std::string complex_to_json(const core::ElementComplex<Exact, 3>& m) {
  return element_complex_to_json<3>(m);
}

} // namespace symmesh::io
