/// Reading templated-structure JSON, part 3 (internal): rigid transformations — matrices,
/// translations, symbolic rotations (2D, and 3D about an axis of rational length), reflections and
/// compositions, each checked exactly — spec/input-format.md#transformations
#pragma once
#include "symmesh/io/structure_json/numbers.h"

#include "symmesh/core/rigid_transformation.h"

namespace symmesh::io::structure_json {

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
inline std::pair<long long, long long> get_angle(const json& v, const std::string& path) {
  const long long n =
      get_integer(require(v, "order", path), dot(path, "order"), 1, 1000000, "a positive integer");
  long long k = 1;
  if (v.contains("k")) k = get_integer(v["k"], dot(path, "k"), -1000000000, 1000000000);
  return {k, n};
}

/// "x", "y" or "z": the index of a coordinate axis.
inline int get_coordinate_axis(const json& j, const std::string& path) {
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
  if constexpr (D == 2) {
    return guarded(path, [&] { return Rigid<FT, D>::rotation_2d(c, s, center); });
  } else {
    const auto u = get_unit_axis<FT>(require(r, "axis", path), dot(path, "axis"));
    return guarded(path, [&] { return Rigid<FT, D>::rotation_about_axis(c, s, u, center); });
  }
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

} // namespace symmesh::io::structure_json
