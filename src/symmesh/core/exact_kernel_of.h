/// The CGAL kernel for exact predicates on a number type of the core —
/// spec/number-type.md#kernel-choice
///
/// Epeck for the rationals; for the real cyclotomic field K_m, Cartesian over its lazy wrapper,
/// so that predicates are decided on certified intervals unless they are degenerate (as Epeck
/// does for the rationals). Only translation units that run CGAL predicates include this.
#pragma once
#include "symmesh/core/kernel.h"

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/Simple_cartesian.h>

#include <type_traits>

namespace symmesh::core {

template <class FT>
using ExactKernelOf = std::conditional_t<std::is_same_v<FT, Exact>, CGAL::Epeck,
                                         CGAL::Simple_cartesian<CGAL::Lazy_exact_nt<FT>>>;

} // namespace symmesh::core
