// Boundary patch partition (Algorithm 4.1, Definitions 4.7-4.9) for the default exact kernel
// (rationals) — spec/boundary-patches.md. The definitions are in boundary_patch_partition_impl.h.
#include "symmesh/core/boundary_patch_partition_impl.h"
#include "symmesh/core/kernel.h"

namespace symmesh::core {
SYMMESH_BPP_INSTANTIATE(Exact, 2)
SYMMESH_BPP_INSTANTIATE(Exact, 3)
} // namespace symmesh::core
