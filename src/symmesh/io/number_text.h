/// Exact text of a number as the templated-structure reader accepts it back (spec/input-format.md
/// #numbers): "n" or "n/d" for a rational, "K<m>[a_0, ...]" for an element of K_m.
#pragma once
#include "symmesh/number/cyclotomic.h"

#include <string>

namespace symmesh::io {

std::string number_text(const number::Cyclotomic& x);

} // namespace symmesh::io
