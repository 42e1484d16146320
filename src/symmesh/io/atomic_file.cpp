// Output files appear whole or not at all — spec/outputs.md#atomic-files
#include "symmesh/io/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace symmesh::io {
namespace {
thread_local OutputGroup* current_group = nullptr;

void remove_part(const std::string& path) {
  std::error_code ec;
  std::filesystem::remove(path + ".part", ec);
}
} // namespace

OutputGroup::OutputGroup() : outer_(current_group) {
  current_group = this;
}

OutputGroup::~OutputGroup() {
  current_group = outer_;
  if (!committed_)
    for (const auto& p : paths_) remove_part(p);
}

void OutputGroup::commit() {
  current_group = outer_;
  committed_ = true;
  if (outer_) {
    outer_->paths_.insert(outer_->paths_.end(), paths_.begin(), paths_.end());
    return;
  }
  for (std::size_t k = 0; k < paths_.size(); ++k) {
    std::error_code ec;
    std::filesystem::rename(paths_[k] + ".part", paths_[k], ec);
    if (ec) {
      for (std::size_t j = k; j < paths_.size(); ++j) remove_part(paths_[j]);
      throw std::runtime_error(paths_[k] + ": cannot write (rename failed)");
    }
  }
}

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& body) {
  namespace fs = std::filesystem;
  const std::string tmp = path + ".part";
  const auto give_up = [&](const std::string& why) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw std::runtime_error(path + ": cannot write" + why);
  };
  {
    std::ofstream os(tmp, std::ios::binary);
    if (!os) give_up("");
    try {
      body(os);
    } catch (...) { // a writer's own error (e.g. a size limit): no .part is left either
      os.close();
      remove_part(path);
      throw;
    }
    os.flush();
    if (!os) give_up("");
  }
  if (current_group) {
    current_group->paths_.push_back(path);
    return;
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) give_up(" (rename failed)");
}

void write_file_atomically(const std::string& path, const std::string& text) {
  write_atomically(path, [&](std::ostream& os) { os << text; });
}

} // namespace symmesh::io
