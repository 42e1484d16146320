/// Lemma 4.2 (interface conformity) as a checker, and the direct check "AT(X) is conforming" —
/// spec/lemmas.md#lemma-4-2
///
/// For every pair of distinct neighbouring instances (a, b):
///  (i)  us(interf(Γ, T_a, T_b)) = interf_geo(Γ, T_a, T_b). With inst_a, inst_b conforming,
///       this fails exactly when some element of inst_a and a different element of inst_b have
///       meeting relative interiors (spec/lemmas.md#lemma-4-2-condition-i);
///  (ii) T_a(IP_{a,b}) = T_b(IP_{b,a}), IP_{a,b} = bnd(X_i) restricted to T_a^{-1}(interf_geo):
///       the transformed template boundary elements contained in us(inst_b), found with the
///       exact containment test simplex_covered_by (boundary elements have dimension <= 2).
/// Pairs (a, a) are trivial. When all pairs pass, AT(Γ) is conforming (the lemma); the
/// converse also holds, so the verdict must equal the direct check.
#pragma once
#include "symmesh/core/templated_structure.h"

#include <string>

namespace symmesh::core {

struct Lemma42Verdict {
  bool holds = true;
  std::size_t pairs_checked = 0;
  InstanceId a, b;   ///< the failing neighbouring pair (when !holds)
  int condition = 0; ///< 1 for (i), 2 for (ii)
  std::string detail;
};

template <class FT, int D>
bool condition_i_holds(const StructureInstance<FT, D>& si, std::size_t a, std::size_t b,
                       std::string* detail) {
  const auto& m = si.at.mesh;
  for (const auto& s : si.instance_elements[a]) {
    const auto sp = m.coords(s);
    const auto sb = box_of<FT, D>(sp);
    if (!sb.overlaps(si.instance_box[b])) continue;
    for (const auto& t : si.instance_elements[b]) {
      if (s == t) continue;
      const auto tp = m.coords(t);
      if (!sb.overlaps(box_of<FT, D>(tp))) continue;
      if (relative_interiors_meet<FT, D>(sp, tp)) {
        if (detail)
          *detail = "a " + std::to_string(s.dim()) + "-element of one instance and a different " +
                    std::to_string(t.dim()) + "-element of the other overlap";
        return false;
      }
    }
  }
  return true;
}

/// T_a(IP_{a,b}) in global element ids.
template <class FT, int D>
std::vector<Simplex> transformed_interface_part(const TemplatedStructure<FT, D>& x,
                                                const StructureInstance<FT, D>& si, std::size_t a,
                                                std::size_t b) {
  const auto id = si.ids[a];
  const auto bnd = mesh_boundary(x.templates[id.i].mesh);
  const auto other = si.instance_complex(b);
  std::vector<Simplex> out;
  for (const auto& e : bnd.elements) {
    std::array<VertexId, 4> g{};
    for (int k = 0; k < e.n; ++k) g[k] = si.vertex_map[a][e.v[k]];
    const Simplex s = Simplex::from_range(g.data(), g.data() + e.n);
    const auto sp = si.at.mesh.coords(s);
    if (!box_of<FT, D>(sp).overlaps(si.instance_box[b])) continue;
    if (simplex_covered_by<FT, D>(sp, other)) out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

template <class FT, int D>
bool condition_ii_holds(const TemplatedStructure<FT, D>& x, const StructureInstance<FT, D>& si,
                        std::size_t a, std::size_t b, std::string* detail) {
  const auto ip_a = transformed_interface_part(x, si, a, b);
  const auto ip_b = transformed_interface_part(x, si, b, a);
  if (ip_a == ip_b) return true;
  if (detail)
    *detail = "the interface boundary elements differ: " + std::to_string(ip_a.size()) +
              " from one template, " + std::to_string(ip_b.size()) + " from the other";
  return false;
}

/// \pre x is a templated structure (Eq. 4.2) with mesh templates
template <class FT, int D>
Lemma42Verdict check_interface_conformity(const TemplatedStructure<FT, D>& x,
                                          const StructureInstance<FT, D>& si) {
  Lemma42Verdict v;
  for (auto [a, b] : neighbouring_instances(si)) {
    ++v.pairs_checked;
    std::string detail;
    int failed = 0;
    if (!condition_i_holds(si, a, b, &detail))
      failed = 1;
    else if (!condition_ii_holds(x, si, a, b, &detail))
      failed = 2;
    if (failed && v.holds) {
      v.holds = false;
      v.a = si.ids[a];
      v.b = si.ids[b];
      v.condition = failed;
      v.detail = detail;
    }
  }
  return v;
}

/// Definition 4.4 directly: AT(X) is conforming.
template <class FT, int D>
bool structure_instance_conforming(const StructureInstance<FT, D>& si) {
  return !find_nonconformity(si.at.mesh).has_value();
}

} // namespace symmesh::core
