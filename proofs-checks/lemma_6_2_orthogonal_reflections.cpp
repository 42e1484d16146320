// Lemma 6.2 (Combination of reflective symmetries) — spec/lemmas.md#lemma-6-2
//
// A set A with reflective symmetries across pairwise orthogonal hyperplanes H_{n1,d1}, H_{n2,d2}:
// A^{+,n1,d1} = {x ∈ A | n1·x >= d1} has the reflective symmetry refl_{n2,d2}. With Algorithm 6.4,
// the 2^k compositions of the reflections instance a template in the positive orthant into a
// templated mesh. Here A = us(AT(Γ)) for such a Γ (so A has the k symmetries), and sets are
// compared exactly as sets of cells (each cell a set of points).
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/interface_conformity.h"

#include <set>

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_6_2";

template <int D>
auto record(const OrthogonalReflections<D>& o) {
  return [&o] { return structure_record<D>(kLemma, o.s.recipe, o.s.x); };
}
template <int D>
auto picture(const OrthogonalReflections<D>& o) {
  return [&o] { return structure_picture<D>(o.s.x); };
}

template <int D>
struct CellLess {
  bool operator()(const PointSet<D>& a, const PointSet<D>& b) const {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                        core::PointLess<Exact, D>());
  }
};
template <int D>
using CellSet = std::set<PointSet<D>, CellLess<D>>;

template <int D>
PointSet<D> sorted(PointSet<D> c) {
  std::sort(c.begin(), c.end(), core::PointLess<Exact, D>());
  return c;
}

/// The cells of AT lying in {n·x >= d} (a cell never crosses a symmetry hyperplane here, so
/// its centroid decides).
template <int D>
CellSet<D> positive_part(const Complex<D>& m, const Point<D>& n, const Exact& d) {
  CellSet<D> out;
  for (const auto& c : m.cells()) {
    const auto p = m.coords(c);
    Exact s = 0;
    for (const auto& q : p) s += core::dot<Exact, D>(n, q) - d;
    if (s >= 0) out.insert(sorted<D>(p));
  }
  return out;
}

template <int D>
CellSet<D> image(const CellSet<D>& cells, const Motion<D>& t) {
  CellSet<D> out;
  for (const auto& c : cells) {
    PointSet<D> q;
    for (const auto& p : c) q.push_back(t(p));
    out.insert(sorted<D>(q));
  }
  return out;
}

template <int D>
CellSet<D> all_cells(const Complex<D>& m) {
  CellSet<D> out;
  for (const auto& c : m.cells()) out.insert(sorted<D>(m.coords(c)));
  return out;
}

/// A has every reflective symmetry refl_{n_j,d_j}.
template <int D>
bool symmetric(const OrthogonalReflections<D>& o, const Complex<D>& at) {
  const auto a = all_cells<D>(at);
  for (std::size_t j = 0; j < o.normals.size(); ++j)
    if (image<D>(a, Motion<D>::reflection(o.normals[j], o.offsets[j])) != a) return false;
  return true;
}

/// The lemma for every ordered pair (j1, j2): refl_{j2}(A^{+,j1}) = A^{+,j1}.
template <int D>
bool half_keeps_symmetry(const OrthogonalReflections<D>& o, const Complex<D>& at) {
  for (std::size_t j1 = 0; j1 < o.normals.size(); ++j1)
    for (std::size_t j2 = 0; j2 < o.normals.size(); ++j2) {
      if (j1 == j2) continue;
      const auto half = positive_part<D>(at, o.normals[j1], o.offsets[j1]);
      if (image<D>(half, Motion<D>::reflection(o.normals[j2], o.offsets[j2])) != half) return false;
    }
  return true;
}

template <int D>
bool pairwise_orthogonal(const OrthogonalReflections<D>& o) {
  for (std::size_t a = 0; a < o.normals.size(); ++a)
    for (std::size_t b = a + 1; b < o.normals.size(); ++b)
      if (core::dot<Exact, D>(o.normals[a], o.normals[b]) != 0) return false;
  return true;
}

template <int D>
void orthogonal(const OrthogonalReflections<D>& o, bool check_hypotheses) {
  const auto si = core::apply_template(o.s.x);
  if (check_hypotheses) {
    SYMMESH_PROOF_ASSERT(pairwise_orthogonal<D>(o), record(o), picture(o));
    SYMMESH_PROOF_ASSERT(symmetric<D>(o, si.at.mesh), record(o), picture(o));
    // Algorithm 6.4: the 2^k instances form a templated structure (their conformity is
    // asserted by Lemma_4_2.sufficiency, whose valid tier contains this family)
    SYMMESH_PROOF_ASSERT(!core::find_instance_overlap(o.s.x).has_value(), record(o), picture(o));
  }
  SYMMESH_PROOF_ASSERT(half_keeps_symmetry<D>(o, si.at.mesh), record(o), picture(o));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma, "orthogonal_reflections" + d, D, Kind::holds,
       "Lemma 6.2 with Algorithm 6.4: a template in the positive orthant of k = 2..D pairwise "
       "orthogonal rational hyperplanes, instanced by the 2^k reflection compositions, is a "
       "templated structure; A = us(AT) has the k symmetries and each half A^{+,n_i,d_i} keeps "
       "every other symmetry refl_{n_j,d_j}",
       [] {
         return rc::detail::toProperty([] { orthogonal<D>(*orthogonal_reflections<D>(), true); });
       },
       [] {
         return rc::detail::toProperty(
             [] { orthogonal<D>(*non_orthogonal_reflections<D>(), false); });
       }});
  p.push_back({kLemma,
               "non_orthogonal_hyperplanes" + d,
               D,
               Kind::counterexample,
               "Lemma 6.2 without orthogonality (two rational symmetries at 45 degrees, the square "
               "group of a wedge template): A has both symmetries but A^{+,n1,d1} does not keep "
               "refl_{n2,d2}",
               [] {
                 return rc::detail::toProperty([] {
                   const auto o = *non_orthogonal_reflections<D>();
                   const auto at = core::apply_template(o.s.x).at.mesh;
                   SYMMESH_PROOF_ASSERT(!pairwise_orthogonal<D>(o), record<D>(o), picture<D>(o));
                   SYMMESH_PROOF_ASSERT(symmetric<D>(o, at), record<D>(o), picture<D>(o));
                   SYMMESH_PROOF_ASSERT(!half_keeps_symmetry<D>(o, at), record<D>(o),
                                        picture<D>(o));
                 });
               },
               {}});
}

} // namespace

void register_lemma_6_2(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
