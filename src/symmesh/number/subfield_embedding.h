/// K_{m'} ⊂ K_m for m' | m (spec/number-type.md#kernel-choice): the generator 2cos(2π/m') of
/// K_{m'} is 2cos(2π(m/m')/m) in K_m, so an element Σ a_i (2cos 2π/m')^i is evaluated there by
/// Horner's rule. Used by the reader (a "K<m'>[...]" literal in a document read in K_m) and by
/// the symmetry cut (the input's field inside the cut's field).
#pragma once
#include "symmesh/number/cyclotomic.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::number {

/// \pre from_m >= 1 divides into.m(); `coefficients` are in the basis of K_{from_m}
inline Cyclotomic embed_subfield_element(const CyclotomicField& into, int from_m,
                                         const std::vector<mpq_class>& coefficients) {
  if (from_m < 1 || into.m() % from_m != 0)
    throw std::invalid_argument("K_" + std::to_string(from_m) + " is not a subfield of K_" +
                                std::to_string(into.m()));
  const Cyclotomic c = into.two_cos_2pi_over_m(long(into.m() / from_m));
  Cyclotomic v = into.zero();
  for (std::size_t i = coefficients.size(); i-- > 0;) v = v * c + into.element({coefficients[i]});
  return v;
}

} // namespace symmesh::number
