// Explicit instantiation of the core's heavy entry points for the real cyclotomic field K_m
// (spec/number-type.md#kernel-choice): the boundary patch partition, the intersection partition
// and the whole analysis of `symmesh check`. A separate translation unit from the rational ones
// so that the two kernels compile in parallel.
#include "symmesh/number/cyclotomic_cgal.h"

#include "symmesh/core/boundary_patch_partition_impl.h"
#include "symmesh/core/intersection_partition_impl.h"
#include "symmesh/core/structure_report.h"

namespace symmesh::core {
using number::Cyclotomic;
SYMMESH_INSTANTIATE_INTERSECTION_PARTITION(Cyclotomic, 2)
SYMMESH_INSTANTIATE_INTERSECTION_PARTITION(Cyclotomic, 3)
SYMMESH_BPP_INSTANTIATE(Cyclotomic, 2)
SYMMESH_BPP_INSTANTIATE(Cyclotomic, 3)
template StructureReport analyse<Cyclotomic, 2>(const TemplatedStructure<Cyclotomic, 2>&);
template StructureReport analyse<Cyclotomic, 3>(const TemplatedStructure<Cyclotomic, 3>&);
} // namespace symmesh::core
