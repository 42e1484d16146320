/// The input of the conventional baseline (Section 7.1), for both dimensions —
/// spec/generation.md#conventional
///
/// Per region, the union of its instances (AT restricted to the region, exact, merged by exact
/// point equality) as one geometry template instanced once by the identity, so that region
/// boundaries stay mesh edges (2D) or mesh faces (3D) and the same pipeline and mesher with the
/// same parameters mesh the whole geometry. Internal to gen/.
#pragma once
#include "symmesh/core/templated_structure.h"

#include <map>
#include <stdexcept>
#include <string>

namespace symmesh::gen::support {

/// \pre x obeys Eq. 4.2 (checked: throws std::invalid_argument naming the overlapping pair)
template <class FT, int D>
core::TemplatedStructure<FT, D> as_region_templates(const core::TemplatedStructure<FT, D>& x) {
  if (const auto overlap = core::find_instance_overlap(x))
    throw std::invalid_argument(core::overlap_message(*overlap));
  std::map<int, core::TemplatedStructure<FT, D>> by_region;
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    for (const auto& inst : x.instances[i]) {
      auto& part = by_region[inst.region];
      std::size_t k = 0;
      while (k < part.templates.size() && part.templates[k].name != x.templates[i].name) ++k;
      if (k == part.templates.size()) {
        part.templates.push_back(x.templates[i]);
        part.instances.emplace_back();
      }
      part.instances[k].push_back(inst);
    }
  core::TemplatedStructure<FT, D> whole;
  for (const auto& [region, part] : by_region) {
    const auto si = core::apply_template(part);
    whole.templates.push_back(
        {"region " + std::to_string(region), core::TemplateKind::geometry, si.at.mesh});
    core::InstanceSpec<FT, D> spec;
    spec.region = region;
    whole.instances.push_back({spec});
  }
  return whole;
}

} // namespace symmesh::gen::support
