// AT(X) is a multi-region mesh ⇔ AT(X) is conforming (the remark after Definition 4.4) —
// spec/lemmas.md#at-multi-region-equivalence
//
// For a templated structure with mesh templates, AT(X) is finite, face-complete and without
// dangling elements automatically (a union of meshes) and every cell carries its instance's
// region, so the multi-region-mesh validity (MultiRegionMesh::is_valid: Definition 2.4 plus a
// region per cell) must coincide with conformity. Dropping "templates are meshes" (templates
// reduced to their cells) breaks it: AT stays conforming but is no mesh.
#include "proofs-checks/generators.h"
#include "proofs-checks/registry.h"
#include "symmesh/core/interface_conformity.h"

namespace symmesh::proofs {
namespace {

using namespace gen;

constexpr const char* kLemma = "AT_multi_region_equivalence";

/// Failure records of this lemma's generated structures (see generators.h).
template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kLemma, s);
}
using gen::picture;

/// Conformity is decided independently of the multi-region-mesh test, which calls the global
/// find_nonconformity on AT: by the instance-pair checker of Lemma 4.2 (conditions on instance
/// interfaces only, spec/lemmas.md#lemma-4-2), whose agreement with AT's conformity the Lemma 4.2
/// properties establish for templated structures with mesh templates.
template <int D>
void equivalence(const GeneratedStructure<D>& s) {
  const auto si = core::apply_template(s.x);
  const bool conforming = core::check_interface_conformity(s.x, si).holds;
  RC_TAG(conforming ? "conforming" : "not conforming");
  SYMMESH_PROOF_ASSERT(si.at.is_valid() == conforming, record(s), picture(s));
}

template <int D>
void add(std::vector<Property>& p) {
  const std::string d = dim_suffix(D);
  p.push_back(
      {kLemma, "multi_region_mesh_iff_conforming" + d, D, Kind::holds,
       "Definition 4.4 remark: for templated structures with mesh templates (conforming "
       "and Figure 4.4-like), AT(X) is a valid multi-region mesh iff AT(X) is conforming",
       [] { return rc::detail::toProperty([] { equivalence<D>(*templated_structure<D>()); }); },
       [] {
         return rc::detail::toProperty([] { equivalence<D>(*non_mesh_template_structure<D>()); });
       }});
  p.push_back(
      {kLemma,
       "templates_not_meshes" + d,
       D,
       Kind::counterexample,
       "Without 'templates are meshes' (templates reduced to their cells, not face-complete): "
       "AT is conforming but not a multi-region mesh",
       [] {
         return rc::detail::toProperty([] {
           const auto s = *non_mesh_template_structure<D>();
           const auto si = core::apply_template(s.x);
           SYMMESH_PROOF_ASSERT(core::check_interface_conformity(s.x, si).holds &&
                                    core::structure_instance_conforming(si) && !si.at.is_valid(),
                                record<D>(s), picture<D>(s));
         });
       },
       {}});
}

} // namespace

void register_at_multi_region_equivalence(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
