// Lemma 4.3 (Boundary patch relation is an equivalence relation) — spec/lemmas.md#lemma-4-3
//
// ~_X is the transitive completion of R_X: "some template boundary mapping sends patch A onto
// patch B" (Def 4.8). Reflexive because the trivial mapping 𝕋_{T,T} = I applies to every patch,
// symmetric because the mappings are closed under inverses, transitive by construction. The
// properties check each of the three on the computed relation, and that the union-find classes
// equal the BFS components of the patch graph (two independent closures). Dropping the
// transitive completion (R_X alone) loses transitivity on the indirect-neighbour chain of
// Figure 4.7 (the counterexample property, and the holds property's dropped variant, which runs
// the same conclusion with R_X in place of ~_X).
#include "proofs-checks/bpp_generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/boundary_patch_partition.h"

#include <deque>
#include <set>

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "Lemma_4_3";

template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kLemma, s);
}
using gen::picture;

template <int D>
using Bpp = core::BoundaryPatchPartition<Exact, D>;

template <int D>
bool reflexive(const Bpp<D>& b) {
  std::vector<bool> self(b.patches.size(), false);
  for (const auto& a : b.arrows)
    if (a.from == a.to && b.mappings[a.letter].whole_boundary) self[a.from] = true;
  return std::find(self.begin(), self.end(), false) == self.end();
}

template <int D>
bool symmetric(const Bpp<D>& b) {
  std::set<std::tuple<std::size_t, std::size_t, std::size_t>> arrows;
  for (const auto& a : b.arrows) arrows.emplace(a.from, a.to, a.letter);
  for (const auto& a : b.arrows)
    if (!arrows.count({a.to, a.from, b.mappings[a.letter].inverse})) return false;
  return true;
}

/// Classes of the union-find closure equal the connected components of the patch graph found by
/// breadth-first search.
template <int D>
bool classes_are_bfs_components(const Bpp<D>& b) {
  const std::size_t n = b.patches.size();
  std::vector<std::vector<std::size_t>> adj(n);
  for (const auto& a : b.arrows) {
    adj[a.from].push_back(a.to);
    adj[a.to].push_back(a.from);
  }
  std::vector<std::size_t> comp(n, n);
  std::size_t count = 0;
  for (std::size_t s = 0; s < n; ++s) {
    if (comp[s] != n) continue;
    std::deque<std::size_t> q{s};
    comp[s] = count;
    while (!q.empty()) {
      const auto p = q.front();
      q.pop_front();
      for (auto r : adj[p])
        if (comp[r] == n) comp[r] = count, q.push_back(r);
    }
    ++count;
  }
  if (count != b.classes.size()) return false;
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t r = 0; r < n; ++r)
      if ((comp[p] == comp[r]) != (b.patches[p].relation_class == b.patches[r].relation_class))
        return false;
  return true;
}

using Relation = std::set<std::pair<std::size_t, std::size_t>>;

/// R_X: one mapping, no completion.
template <int D>
Relation one_step_relation(const Bpp<D>& b) {
  Relation r;
  for (const auto& a : b.arrows) r.emplace(a.from, a.to);
  return r;
}

/// ~_X as computed: two patches are related iff they are in one class.
template <int D>
Relation class_relation(const Bpp<D>& b) {
  Relation r;
  for (std::size_t p = 0; p < b.patches.size(); ++p)
    for (std::size_t q = 0; q < b.patches.size(); ++q)
      if (b.patches[p].relation_class == b.patches[q].relation_class) r.emplace(p, q);
  return r;
}

bool transitive(const Relation& r) {
  for (const auto& [p, q] : r)
    for (auto it = r.lower_bound({q, 0}); it != r.end() && it->first == q; ++it)
      if (!r.count({p, it->second})) return false;
  return true;
}

/// The relation `related(b)` is an equivalence relation on the patches: reflexive (identity arrow
/// on every patch), symmetric (inverse arrow for every arrow), transitive, and its classes are the
/// BFS components of the patch graph.
template <int D, class RelationOf>
void equivalence_conclusion(const GeneratedStructure<D>& s, RelationOf related) {
  const auto b = core::boundary_patch_partition(s.x);
  std::ostringstream why;
  SYMMESH_PROOF_ASSERT(b.is_valid(&why), record(s), picture(s));
  RC_TAG(b.regular() ? "regular" : "irregular");
  SYMMESH_PROOF_ASSERT(reflexive<D>(b), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(symmetric<D>(b), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(transitive(related(b)), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(classes_are_bfs_components<D>(b), record(s), picture(s));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back({kLemma, "equivalence_relation" + d, D, Kind::holds,
               "Lemma 4.3: on templated structures (reflections, grids, split templates, Figure "
               "4.4/4.7/4.11 families, rotational slices) the boundary patch relation is reflexive "
               "(identity arrow on every patch), symmetric (inverse arrow for every arrow) and "
               "its union-find classes are the BFS components of the patch graph",
               [] {
                 return rc::detail::toProperty(
                     [] { equivalence_conclusion<D>(*bpp_structure<D>(), class_relation<D>); });
               },
               [] {
                 return rc::detail::toProperty([] {
                   equivalence_conclusion<D>(*indirect_chain_structure<D>(true),
                                             one_step_relation<D>);
                 });
               }});
  p.push_back({kLemma,
               "relation_without_transitive_completion" + d,
               D,
               Kind::counterexample,
               "Lemma 4.3 without the transitive completion: on the chain of Figure 4.7, R_X "
               "relates X1's face to X2's and X2's to X3's, but no single mapping joins X1 and X3",
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *indirect_chain_structure<D>(true);
                   const auto b = core::boundary_patch_partition(s.x);
                   SYMMESH_PROOF_ASSERT(!transitive(one_step_relation<D>(b)), record(s),
                                        picture(s));
                   SYMMESH_PROOF_ASSERT(classes_are_bfs_components<D>(b), record(s), picture(s));
                 });
               },
               {}});
}

} // namespace

void register_lemma_4_3(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
