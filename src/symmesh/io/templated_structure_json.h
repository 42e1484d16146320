/// The templated-structure JSON format (reader and writer) — spec/input-format.md
///
/// Exact numbers are strings ("3/5", "-0.25", "2", "cos(2pi*1/8)", "K8[0, 1/2]") or JSON
/// integers; a JSON number with a fraction or exponent is rejected, because it would not be
/// exact. A document is read in the rational kernel when that suffices, otherwise in the real
/// cyclotomic field K_m for the smallest m that holds all its rotations (spec/number-type.md#
/// kernel-choice). Every error is an InputError whose one-line message names the offending field
/// by its JSON path.
#pragma once
#include "symmesh/core/kernel.h"
#include "symmesh/core/templated_structure.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <stdexcept>
#include <string>
#include <variant>

namespace symmesh::io {

using symmesh::Exact;

/// Bad input: exit code 2, one line, names the field or element.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using number::Cyclotomic;

using Structure2 = core::TemplatedStructure<Exact, 2>;
using Structure3 = core::TemplatedStructure<Exact, 3>;
using CyclotomicStructure2 = core::TemplatedStructure<Cyclotomic, 2>;
using CyclotomicStructure3 = core::TemplatedStructure<Cyclotomic, 3>;
/// A structure in the kernel its document needs: rationals, or K_m.
using AnyStructure =
    std::variant<Structure2, Structure3, CyclotomicStructure2, CyclotomicStructure3>;

/// Parses an exact rational: "n", "n/d", decimal "-0.25", "1e-3" (all exact). `field` names it.
Exact parse_exact(const std::string& text, const std::string& field);

/// Canonical text of an exact number: "n" or "n/d" in lowest terms.
std::string exact_to_string(const Exact& x);

/// Reads and validates the shape of a templated structure (not yet Eq. 4.2: that is `check`).
AnyStructure parse_templated_structure(const std::string& text,
                                       const std::string& source = "input");
AnyStructure read_templated_structure(const std::string& path);

/// "rational (CGAL Epeck, exact)" or "K_<m> = Q(cos 2pi/<m>) (...)": the kernel `x` is held in.
std::string kernel_name(const AnyStructure& x);
/// m of the field K_m of `x`, 0 for the rational kernel.
int field_order(const AnyStructure& x);

/// Writes a structure in the same format (transformations as exact matrix + translation; K_m
/// numbers as "K<m>[a_0, ...]" unless rational).
std::string to_json(const Structure2& x);
std::string to_json(const Structure3& x);
std::string to_json(const CyclotomicStructure2& x);
std::string to_json(const CyclotomicStructure3& x);

/// A plain element complex (vertices + elements) as JSON, for counterexamples of Chapter 2.
std::string complex_to_json(const core::ElementComplex<Exact, 2>& m);
std::string complex_to_json(const core::ElementComplex<Exact, 3>& m);

} // namespace symmesh::io
