// `symmesh check` over K_m (spec/number-type.md#core-over-k-m): the analysis runs on
// CGAL::Lazy_exact_nt<Cyclotomic>. Each value keeps a certified interval enclosure (from
// Cyclotomic::to_interval) and the expression that made it; a sign or comparison is decided on
// the interval when it excludes zero, and only otherwise by evaluating the expression exactly in
// K_m. The decision is exact either way, so the report is the one of the plain Cyclotomic core;
// only the cost differs (the 128-gon's rotations need products of dense degree-32 elements).
#include "symmesh/number/cyclotomic_cgal.h"

#include "symmesh/core/boundary_patch_partition_impl.h"
#include "symmesh/core/intersection_partition_impl.h"
#include "symmesh/core/structure_report.h"

#include <CGAL/Lazy_exact_nt.h>

namespace symmesh::core {
using number::Cyclotomic;
using LazyCyclotomic = CGAL::Lazy_exact_nt<Cyclotomic>;
SYMMESH_INSTANTIATE_INTERSECTION_PARTITION(LazyCyclotomic, 2)
SYMMESH_INSTANTIATE_INTERSECTION_PARTITION(LazyCyclotomic, 3)
SYMMESH_BPP_INSTANTIATE(LazyCyclotomic, 2)
SYMMESH_BPP_INSTANTIATE(LazyCyclotomic, 3)

namespace {
template <int D>
StructureReport analyse_lazily(const TemplatedStructure<Cyclotomic, D>& x) {
  const auto lazy =
      convert_numbers<LazyCyclotomic>(x, [](const Cyclotomic& v) { return LazyCyclotomic(v); });
  return analyse(lazy);
}
} // namespace

StructureReport analyse(const TemplatedStructure<Cyclotomic, 2>& x) {
  return analyse_lazily(x);
}
StructureReport analyse(const TemplatedStructure<Cyclotomic, 3>& x) {
  return analyse_lazily(x);
}
} // namespace symmesh::core
