// Replays saved fuzz inputs through a harness without libFuzzer (`make test`, ctest label fuzz):
// every file given, or every file in a directory given, is fed to LLVMFuzzerTestOneInput once.
// An exception escaping the harness is a finding: it is named with its input and the exit code
// is 1. A crash or a sanitizer report ends the process as it would under libFuzzer.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {
std::vector<std::filesystem::path> inputs(int argc, char** argv) {
  std::vector<std::filesystem::path> out;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path p(argv[i]);
    if (std::filesystem::is_directory(p)) {
      for (const auto& e : std::filesystem::directory_iterator(p))
        if (e.is_regular_file()) out.push_back(e.path());
    } else {
      out.push_back(p);
    }
  }
  std::sort(out.begin(), out.end()); // a fixed order: replays are reproducible
  return out;
}
} // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: " << argv[0] << " INPUT_OR_DIRECTORY...\n";
    return 2;
  }
  const auto files = inputs(argc, argv);
  if (files.empty()) {
    std::cerr << "replay: no inputs\n";
    return 2;
  }
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) {
      std::cerr << "replay: " << f.string() << ": cannot open file\n";
      return 2;
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    try {
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    } catch (const std::exception& e) {
      std::cerr << "replay: " << f.string() << ": exception escaped the harness: " << e.what()
                << "\n";
      return 1;
    }
  }
  std::cout << "replay: " << files.size() << " inputs, no finding\n";
  return 0;
}
