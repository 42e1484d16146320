// Output files appear whole or not at all, alone or as a group — spec/outputs.md#atomic-files.
#include "symmesh/io/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {
namespace fs = std::filesystem;

struct AtomicFile : ::testing::Test {
  fs::path dir;
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("symmesh-atomic-" +
           std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  std::size_t files() const {
    return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
  }
  static std::string read(const std::string& p) {
    std::ifstream is(p);
    std::stringstream s;
    s << is.rdbuf();
    return s.str();
  }
};

TEST_F(AtomicFile, AFileAloneIsRenamedWhenComplete) {
  symmesh::io::write_file_atomically(path("a.txt"), "alpha");
  EXPECT_EQ(read(path("a.txt")), "alpha");
  EXPECT_EQ(files(), 1u);
}

TEST_F(AtomicFile, AFailingBodyLeavesNoFile) {
  EXPECT_THROW(symmesh::io::write_atomically(
                   path("a.txt"), [](std::ostream&) { throw std::runtime_error("midway"); }),
               std::runtime_error);
  EXPECT_EQ(files(), 0u) << "the .part file was not removed";
}

TEST_F(AtomicFile, AGroupPublishesNothingBeforeCommit) {
  symmesh::io::OutputGroup g;
  symmesh::io::write_file_atomically(path("a.txt"), "alpha");
  symmesh::io::write_file_atomically(path("b.txt"), "beta");
  EXPECT_FALSE(fs::exists(path("a.txt")));
  EXPECT_TRUE(fs::exists(path("a.txt.part")));
  g.commit();
  EXPECT_EQ(read(path("a.txt")), "alpha");
  EXPECT_EQ(read(path("b.txt")), "beta");
  EXPECT_EQ(files(), 2u);
}

TEST_F(AtomicFile, AFailureInAGroupLeavesNoneOfItsFiles) {
  try {
    symmesh::io::OutputGroup g;
    symmesh::io::write_file_atomically(path("a.txt"), "alpha");
    symmesh::io::write_file_atomically(path("missing/b.txt"), "beta"); // throws: no directory
    g.commit();
    FAIL() << "writing into a missing directory did not throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing/b.txt: cannot write"), std::string::npos);
  }
  EXPECT_EQ(files(), 0u) << "a.txt or a.txt.part was left behind";
}

TEST_F(AtomicFile, AnInnerGroupPublishesIntoTheOuterOne) {
  {
    symmesh::io::OutputGroup outer;
    {
      symmesh::io::OutputGroup inner;
      symmesh::io::write_file_atomically(path("a.txt"), "alpha");
      inner.commit();
    }
    EXPECT_FALSE(fs::exists(path("a.txt"))) << "the inner commit published before the outer";
  } // the outer group is not committed
  EXPECT_EQ(files(), 0u);
  symmesh::io::write_file_atomically(path("c.txt"), "gamma"); // no group is left active
  EXPECT_TRUE(fs::exists(path("c.txt")));
}

} // namespace
