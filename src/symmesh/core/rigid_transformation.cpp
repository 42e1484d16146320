// Compile-time checks that the transformation templates instantiate for the default kernel.
#include "symmesh/core/kernel.h"
#include "symmesh/core/rigid_transformation.h"

namespace symmesh::core {
template class RigidTransformation<Exact, 2>;
template class RigidTransformation<Exact, 3>;
} // namespace symmesh::core
