// Intersection partition and refinement for the default exact kernel (rationals) —
// spec/intersection-partition.md. The definitions are in intersection_partition_impl.h.
#include "symmesh/core/intersection_partition_impl.h"
#include "symmesh/core/kernel.h"

namespace symmesh::core {
SYMMESH_INSTANTIATE_INTERSECTION_PARTITION(Exact, 2)
SYMMESH_INSTANTIATE_INTERSECTION_PARTITION(Exact, 3)
} // namespace symmesh::core
