/// Error-free transformations of doubles (spec/number-type.md#core-over-k-m): exact only when each
/// operation is rounded on its own, so the targets using them compile with -ffp-contract=off.
#pragma once

namespace symmesh::number {

/// s + t = a + b exactly, s = a + b rounded (Knuth's TwoSum).
inline void two_sum(double a, double b, double& s, double& t) {
  s = a + b;
  const double bb = s - a;
  t = (a - (s - bb)) + (b - bb);
}

} // namespace symmesh::number
