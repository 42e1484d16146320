// Explicit instantiation of the core's heavy entry points for the real cyclotomic field K_m
// (spec/number-type.md#kernel-choice): the boundary patch partition and the intersection
// partition, used by `symmesh bpp` and the K_m properties. The analysis of `symmesh check` runs
// on the lazy wrapper (lazy_cyclotomic_instantiations.cpp). A separate translation unit from the
// rational ones so that the kernels compile in parallel.
#include "symmesh/number/cyclotomic_cgal.h"

#include "symmesh/core/boundary_patch_partition_impl.h"
#include "symmesh/core/intersection_partition_impl.h"

namespace symmesh::core {
using number::Cyclotomic;
SYMMESH_INSTANTIATE_INTERSECTION_PARTITION(Cyclotomic, 2)
SYMMESH_INSTANTIATE_INTERSECTION_PARTITION(Cyclotomic, 3)
SYMMESH_BPP_INSTANTIATE(Cyclotomic, 2)
SYMMESH_BPP_INSTANTIATE(Cyclotomic, 3)
} // namespace symmesh::core
