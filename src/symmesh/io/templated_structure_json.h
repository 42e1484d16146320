/// The templated-structure JSON format (reader and writer) — spec/input-format.md
///
/// Exact numbers are strings ("3/5", "-0.25", "2") or JSON integers; a JSON number with a
/// fraction or exponent is rejected, because it would not be exact. Every error is an InputError
/// whose one-line message names the offending field by its JSON path.
#pragma once
#include "symmesh/core/kernel.h"
#include "symmesh/core/templated_structure.h"

#include <stdexcept>
#include <string>
#include <variant>

namespace symmesh::io {

using symmesh::Exact;

/// Bad input: exit code 2, one line, names the field or element.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Structure2 = core::TemplatedStructure<Exact, 2>;
using Structure3 = core::TemplatedStructure<Exact, 3>;
using AnyStructure = std::variant<Structure2, Structure3>;

/// Parses an exact rational: "n", "n/d", decimal "-0.25", "1e-3" (all exact). `field` names it.
Exact parse_exact(const std::string& text, const std::string& field);

/// Canonical text of an exact number: "n" or "n/d" in lowest terms.
std::string exact_to_string(const Exact& x);

/// Reads and validates the shape of a templated structure (not yet Eq. 4.2: that is `check`).
AnyStructure parse_templated_structure(const std::string& text,
                                       const std::string& source = "input");
AnyStructure read_templated_structure(const std::string& path);

/// Writes a structure in the same format (transformations as exact matrix + translation).
std::string to_json(const Structure2& x);
std::string to_json(const Structure3& x);

/// A plain element complex (vertices + elements) as JSON, for counterexamples of Chapter 2.
std::string complex_to_json(const core::ElementComplex<Exact, 2>& m);
std::string complex_to_json(const core::ElementComplex<Exact, 3>& m);

} // namespace symmesh::io
