/// Default exact kernel of the core — spec/definitions.md#exactness
///
/// The core is generic in its number type `FT` (an exact ordered field: comparisons and
/// equality decide exactly). The default is the field type of CGAL's `Epeck`, rational
/// numbers with lazy evaluation. Only translation units that instantiate the core include this.
#pragma once
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

namespace symmesh {
using DefaultKernel = CGAL::Epeck;
using Exact = DefaultKernel::FT;
} // namespace symmesh
