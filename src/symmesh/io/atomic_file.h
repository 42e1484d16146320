/// Output files appear whole or not at all (the bad-input rule: no partial output file) —
/// spec/outputs.md#atomic-files
///
/// The text goes to PATH.part, which is renamed onto PATH only after every byte was written; on
/// any failure the .part file is removed and std::runtime_error names PATH. A command writing
/// several files (generate -o and --templated, adapt -o, --vtu and --report) publishes them as one
/// OutputGroup, so that a failure of the last one does not leave the first ones behind.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace symmesh::io {

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& body);
void write_file_atomically(const std::string& path, const std::string& text);

/// While a group is alive on this thread, write_atomically leaves each complete file as PATH.part
/// and records it; commit() renames them all. A group destroyed uncommitted (an exception between
/// two outputs) removes every PATH.part it recorded, so the command leaves none of its files.
/// Groups nest: an inner group publishes into the outer one.
class OutputGroup {
public:
  OutputGroup();
  ~OutputGroup();
  OutputGroup(const OutputGroup&) = delete;
  OutputGroup& operator=(const OutputGroup&) = delete;
  /// Renames every recorded PATH.part onto PATH. Throws std::runtime_error naming the first PATH
  /// that cannot be renamed, after removing the .part files not yet renamed.
  void commit();

private:
  friend void write_atomically(const std::string&, const std::function<void(std::ostream&)>&);
  std::vector<std::string> paths_;
  OutputGroup* outer_;
  bool committed_ = false;
};

} // namespace symmesh::io
