/// Colours of symmesh's pictures (instance graphs, structure SVGs, render) —
/// spec/outputs.md#render
///
/// Pictures must give the same bytes for the same input, so colours are a pure function of an
/// index or a value, never drawn at random.
#pragma once
#include <cstddef>
#include <string>

namespace symmesh::io {

/// Fill colour number k ("#rrggbb"): ten light qualitative colours (ColorBrewer Set3), then
/// golden-angle hues, so any number of templates, instances or regions gets stable, distinct
/// fills that keep black lines and text readable on them.
std::string fill_colour(std::size_t k);

/// A sequential ramp from dark blue (t = 0) through teal and green to yellow (t = 1), for
/// quality colourings; t is clamped to [0, 1].
std::string ramp_colour(double t);

} // namespace symmesh::io
