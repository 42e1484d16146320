// Output files appear whole or not at all — spec/outputs.md#atomic-files
#include "symmesh/io/atomic_file.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace symmesh::io {

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
    body(os);
    os.flush();
    if (!os) give_up("");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) give_up(" (rename failed)");
}

void write_file_atomically(const std::string& path, const std::string& text) {
  write_atomically(path, [&](std::ostream& os) { os << text; });
}

} // namespace symmesh::io
