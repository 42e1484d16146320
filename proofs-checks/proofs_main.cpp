// GoogleTest entry point of the proofs-checks: one test per registered property.
#include <gtest/gtest.h>

#include "proofs-checks/registry.h"

#include <iostream>

namespace {
class PropertyTest : public testing::Test {
public:
  explicit PropertyTest(const symmesh::proofs::Property* p) : p_(p) {}
  void TestBody() override {
    symmesh::proofs::RunOptions o;
    o.counterexample_dir = "counterexamples";
    const auto out = symmesh::proofs::run(*p_, o);
    std::cout << p_->lemma << "." << p_->name << ": " << out.cases << " cases, seed " << out.seed
              << (out.passed ? ", passed" : ", FAILED") << "\n";
    EXPECT_TRUE(out.passed) << p_->statement << "\n"
                            << out.message << "\ncounterexample: " << out.counterexample_path;
  }

private:
  const symmesh::proofs::Property* p_;
};
} // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  for (const auto& p : symmesh::proofs::all_properties()) {
    const std::string suite = p.lemma;
    const std::string name = p.name;
    testing::RegisterTest(suite.c_str(), name.c_str(), nullptr, nullptr, __FILE__, __LINE__,
                          [&p]() -> testing::Test* { return new PropertyTest(&p); });
  }
  return RUN_ALL_TESTS();
}
