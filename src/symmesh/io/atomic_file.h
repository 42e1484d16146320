/// Output files appear whole or not at all (the bad-input rule: no partial output file) —
/// spec/outputs.md#atomic-files
///
/// The text goes to PATH.part, which is renamed onto PATH only after every byte was written; on
/// any failure the .part file is removed and std::runtime_error names PATH.
#pragma once
#include <functional>
#include <ostream>
#include <string>

namespace symmesh::io {

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& body);
void write_file_atomically(const std::string& path, const std::string& text);

} // namespace symmesh::io
