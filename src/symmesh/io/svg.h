/// SVG pictures of 2D structures (counterexamples, fixtures) — spec/outputs.md#svg
#pragma once
#include "symmesh/core/kernel.h"
#include "symmesh/core/templated_structure.h"

#include <string>

namespace symmesh::io {

/// The structure instance: every instance's cells filled in its own colour, edges drawn,
/// instance labels T_{i,g} at the centroids.
std::string structure_svg(const core::TemplatedStructure<Exact, 2>& x);

/// A plain 2D element complex.
std::string complex_svg(const core::ElementComplex<Exact, 2>& m);

/// `s` with the XML-special characters & < > " replaced by their entities, for text and
/// attribute values of SVG and of Graphviz's HTML-like labels.
std::string xml_escape(const std::string& s);

} // namespace symmesh::io
