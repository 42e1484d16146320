// Explicit instantiation of the core's heavy entry points for the default exact kernel, so that
// the CGAL exact number type and LP solver are compiled once.
#include "symmesh/core/structure_report.h"

namespace symmesh::core {
template StructureReport analyse<Exact, 2>(const TemplatedStructure<Exact, 2>&);
template StructureReport analyse<Exact, 3>(const TemplatedStructure<Exact, 3>&);
} // namespace symmesh::core
