/// Exact helpers shared by the 2D and 3D cuts of whole symmetric objects
/// (spec/generation.md#cut): embedding a number into the cut's field K_m, cos/sin of 2πk/n in
/// it. Internal to gen/.
#pragma once
#include "symmesh/core/templated_structure.h"
#include "symmesh/gen/symmetry_cut.h"
#include "symmesh/number/cyclotomic.h"
#include "symmesh/number/subfield_embedding.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

namespace symmesh::gen::cut_support {

using number::Cyclotomic;
using number::CyclotomicFieldPtr;

/// The largest field K_m the cut builds (the templated-structure reader's limit as well).
constexpr long kMaxFieldOrder = 1024;

/// v as an element of F (null: v must be rational). \pre v's field divides F.
inline Cyclotomic embed(const Cyclotomic& v, const CyclotomicFieldPtr& F) {
  if (v.is_rational()) return F ? F->element({v.rational_value()}) : Cyclotomic(v.rational_value());
  if (!F || F->m() % v.field()->m() != 0)
    throw CutError("internal error: a number of K_" + std::to_string(v.field()->m()) +
                   " does not embed into the cut's field");
  if (F->same_field(*v.field())) return v;
  return number::embed_subfield_element(*F, v.field()->m(), v.coefficients());
}

/// cos and sin of 2πk/n: rational for quarter turns, else in F (\pre n | F's m and 4 | m).
inline std::pair<Cyclotomic, Cyclotomic> cos_sin(int k, int n, const CyclotomicFieldPtr& F) {
  const int q = ((4 * k) % (4 * n) + 4 * n) % (4 * n); // the angle in quarter turns times n
  if (q % n == 0) {
    static const int c[] = {1, 0, -1, 0}, s[] = {0, 1, 0, -1};
    return {Cyclotomic(c[q / n]), Cyclotomic(s[q / n])};
  }
  return {F->cos_2pi(k, n), F->sin_2pi(k, n)};
}

/// Coefficients compared with zero padding: equal values have equal keys in one field, whether
/// an element is held in rational mode or as a field element.
inline int compare_coefficients(const Cyclotomic& a, const Cyclotomic& b) {
  const auto& x = a.coefficients();
  const auto& y = b.coefficients();
  static const mpq_class zero(0);
  for (std::size_t i = 0; i < std::max(x.size(), y.size()); ++i) {
    const mpq_class& u = i < x.size() ? x[i] : zero;
    const mpq_class& v = i < y.size() ? y[i] : zero;
    if (const int c = cmp(u, v); c != 0) return c;
  }
  return 0;
}

/// The field K_m of a cut (m = lcm(4, the input's fields, n, and 2n for Algorithm 6.5); null when
/// everything is rational): coordinates, transformations, mirrors and start direction.
template <int D, class Spec>
CyclotomicFieldPtr field_for(const core::TemplatedStructure<Cyclotomic, D>& x, const Spec& spec) {
  long m = 1;
  const auto take = [&](const Cyclotomic& v) {
    if (!v.is_rational_mode()) m = std::lcm(m, long(v.field()->m()));
  };
  for (const auto& t : x.templates)
    for (const auto& p : t.mesh.points)
      for (int i = 0; i < D; ++i) take(p[i]);
  for (const auto& list : x.instances)
    for (const auto& s : list)
      for (int i = 0; i < D; ++i) {
        take(s.transformation.translation_part()[i]);
        for (int j = 0; j < D; ++j) take(s.transformation.matrix()[i][j]);
      }
  for (const auto& mv : spec.mirrors)
    for (const auto& v : mv) take(v);
  if (spec.start)
    for (const auto& v : *spec.start) take(v);
  // Quarter turns are rational; other rotations (by 2π/n, and π/n for Algorithm 6.5) need K_m.
  const auto order = [&](long k) {
    if (4 % k != 0) m = std::lcm(m, k);
  };
  if (spec.rotation_order >= 2) order(spec.rotation_order);
  if (spec.rotation_order >= 2 && !spec.mirrors.empty()) order(2L * spec.rotation_order);
  if (m == 1) return nullptr;
  m = std::lcm(m, 4L);
  if (m > kMaxFieldOrder)
    throw CutError("the symmetry needs the field K_m with m = " + std::to_string(m) + " > " +
                   std::to_string(kMaxFieldOrder) + ", the largest supported");
  return number::CyclotomicField::get(int(m));
}

/// The checks every cut makes of its symmetry spec and input (2D and 3D alike); `max_mirrors`,
/// `mirrors_text` ("at most two (orthogonal) mirrors") and `start_text` ("ray", "half-plane")
/// are what differs.
template <int D, class Spec>
void check_spec(const Spec& spec, const core::TemplatedStructure<Cyclotomic, D>& x,
                std::size_t max_mirrors, const std::string& mirrors_text,
                const std::string& start_text) {
  const int n = spec.rotation_order;
  if (n == 1 || n < 0) throw CutError("--rotation: the order must be at least 2");
  if (n > kMaxFieldOrder)
    throw CutError("--rotation: the order must be at most " + std::to_string(kMaxFieldOrder));
  if (spec.mirrors.size() > max_mirrors) throw CutError("--mirror: " + mirrors_text);
  if (n == 0 && spec.mirrors.empty()) throw CutError("give a rotation order or a mirror to cut by");
  if (n >= 2 && spec.mirrors.size() > 1)
    throw CutError("--mirror: with a rotation, give one mirror (Algorithm 6.5)");
  if (spec.start && (n == 0 || !spec.mirrors.empty()))
    throw CutError("--start: the starting " + start_text + " is for a rotation without mirror");
  if (!x.all_of_kind(core::TemplateKind::geometry))
    throw CutError("the input must be a templated geometry (kind \"geometry\")");
}

} // namespace symmesh::gen::cut_support
