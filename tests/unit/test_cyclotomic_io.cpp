// Symbolic numbers and the kernel choice of the input format (spec/input-format.md#numbers,
// spec/number-type.md#kernel-choice): a document is read in the rationals when its orders are
// 1, 2, 4 and in K_m for the smallest m = lcm(4, orders) otherwise; expressions, K literals,
// symbolic rotations (2D, 3D axes) and angle reflections are exact; writing K_m structures
// round-trips; and the equal-copies regression of compare.
#include "symmesh/io/templated_structure_json.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <gtest/gtest.h>

#include <string>
#include <variant>

namespace {

namespace io = symmesh::io;
namespace core = symmesh::core;
using symmesh::number::Cyclotomic;
using symmesh::number::CyclotomicField;

/// A one-template 2D geometry with the given third polygon vertex and transformation.
std::string doc2(const std::string& x, const std::string& y, const std::string& transformation) {
  return R"({"symmesh": "templated-structure/1", "dimension": 2, "templates": [{"kind": "geometry",
    "polygon": [["0", "0"], ["1", "0"], [")" +
         x + R"(", ")" + y + R"("]], "instances": [{"transformation": )" + transformation + "}]}]}";
}

std::string doc3(const std::string& transformation) {
  return R"({"symmesh": "templated-structure/1", "dimension": 3, "templates": [{"vertices":
    [["0","0","0"], ["1","0","0"], ["0","1","0"], ["0","0","1"]], "cells": [[0, 1, 2, 3]],
    "instances": [{"transformation": )" +
         transformation + "}]}]}";
}

std::string error_of(const std::string& text) {
  try {
    io::parse_templated_structure(text);
  } catch (const io::InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "parsed without error:\n" << text;
  return "";
}

TEST(CyclotomicIo, RationalKernelForOrdersOneTwoFour) {
  const auto x = io::parse_templated_structure(doc2("0", "1", R"({"rotation": {"order": 4}})"));
  EXPECT_TRUE(std::holds_alternative<io::Structure2>(x));
  EXPECT_EQ(io::field_order(x), 0);
  // cos(2pi*1/4) = 0 is rational too.
  EXPECT_TRUE(std::holds_alternative<io::Structure2>(
      io::parse_templated_structure(doc2("cos(2pi*1/4)", "1", R"({"identity": {}})"))));
}

TEST(CyclotomicIo, SmallestFieldFromAllOrders) {
  // order 5 in a rotation, 6 in a number: m = lcm(4, 5, 6) = 60.
  const auto x = io::parse_templated_structure(
      doc2("cos(2pi*1/6)", "1", R"({"rotation": {"order": 5, "k": 2}})"));
  ASSERT_TRUE(std::holds_alternative<io::CyclotomicStructure2>(x));
  EXPECT_EQ(io::field_order(x), 60);
  EXPECT_NE(io::kernel_name(x).find("K_60"), std::string::npos);
  // k/n in lowest terms: 2pi*2/8 has order 4, rational.
  EXPECT_EQ(io::field_order(io::parse_templated_structure(
                doc2("0", "1", R"({"rotation": {"order": 8, "k": 2}})"))),
            0);
}

TEST(CyclotomicIo, ExpressionsAreExact) {
  const auto x = std::get<io::CyclotomicStructure2>(
      io::parse_templated_structure(doc2("cos(2pi*1/5)/cos(2pi*1/10)*sin(2pi*1/10)",
                                         "-(1/2 + sin(2pi*3/20))*2", R"({"identity": {}})")));
  const auto f = CyclotomicField::get(20);
  const auto& p = x.templates[0].mesh.points;
  bool found = false;
  for (const auto& v : p)
    if (v[0] == f->cos_2pi(1, 5) / f->cos_2pi(1, 10) * f->sin_2pi(1, 10)) {
      found = true;
      EXPECT_EQ(v[1], -(Cyclotomic(mpq_class(1, 2)) + f->sin_2pi(3, 20)) * Cyclotomic(2));
    }
  EXPECT_TRUE(found);
}

TEST(CyclotomicIo, FieldLiteralEmbedsIntoLargerField) {
  // K8[0, 1/2] = cos(2pi/8) read in K_40 (order 5 elsewhere) equals cos(2pi*5/40).
  const auto x = std::get<io::CyclotomicStructure2>(
      io::parse_templated_structure(doc2("K8[0, 1/2]", "1", R"({"rotation": {"order": 5}})")));
  const auto f = CyclotomicField::get(40);
  bool found = false;
  for (const auto& v : x.templates[0].mesh.points) found = found || v[0] == f->cos_2pi(1, 8);
  EXPECT_TRUE(found);
}

TEST(CyclotomicIo, RoundTripThroughJson) {
  const auto x = std::get<io::CyclotomicStructure2>(io::read_templated_structure(
      std::string(SYMMESH_SOURCE_DIR) + "/data/star_5_half_slices.json"));
  const auto y = std::get<io::CyclotomicStructure2>(io::parse_templated_structure(io::to_json(x)));
  ASSERT_EQ(x.instances[0].size(), y.instances[0].size());
  for (std::size_t g = 0; g < x.instances[0].size(); ++g)
    EXPECT_EQ(x.instances[0][g].transformation, y.instances[0][g].transformation) << g;
  EXPECT_EQ(x.templates[0].mesh.points, y.templates[0].mesh.points);
  EXPECT_EQ(io::to_json(x), io::to_json(y)); // deterministic text
}

TEST(CyclotomicIo, SymbolicRotationsAndReflections) {
  // 2D: rot(2pi/8)^8 = I built from the document's own transformation.
  const auto x = std::get<io::CyclotomicStructure2>(
      io::parse_templated_structure(doc2("0", "1", R"({"rotation": {"order": 8}})")));
  auto r = x.instances[0][0].transformation, acc = r;
  for (int k = 1; k < 8; ++k) acc = acc * r;
  EXPECT_TRUE(acc.is_identity());
  // A reflection through the line at angle pi/8 is an involution with det -1.
  const auto y = std::get<io::CyclotomicStructure2>(io::parse_templated_structure(
      doc2("0", "1", R"({"reflection": {"angle": {"order": 8, "k": 1}, "through": ["1", "2"]}})")));
  const auto& s = y.instances[0][0].transformation;
  EXPECT_TRUE((s * s).is_identity());
  EXPECT_EQ(s.determinant_of_linear_part(), Cyclotomic(-1));
  // 3D: order-16 rotation about z and about the rational-length axis [1, 2, 2].
  for (const char* axis : {R"("z")", R"(["1", "2", "2"])"}) {
    const auto z = std::get<io::CyclotomicStructure3>(io::parse_templated_structure(
        doc3(std::string(R"({"rotation": {"order": 16, "axis": )") + axis + "}}")));
    auto t = z.instances[0][0].transformation, p = t;
    for (int k = 1; k < 16; ++k) p = p * t;
    EXPECT_TRUE(p.is_identity()) << axis;
    EXPECT_FALSE(t.is_identity()) << axis;
  }
}

TEST(CyclotomicIo, BadSymbolicInputNamesTheField) {
  EXPECT_NE(error_of(doc3(R"({"rotation": {"order": 8, "axis": ["1", "1", "0"]}})"))
                .find("templates[0].instances[0].transformation.rotation.axis: the axis has "
                      "irrational length"),
            std::string::npos);
  EXPECT_NE(error_of(doc2("cos(2pi*1/0)", "1", R"({"identity": {}})")).find("out of range"),
            std::string::npos);
  EXPECT_NE(error_of(doc2("((((cos(2pi/8)", "1", R"({"identity": {}})")).find("expected ')'"),
            std::string::npos);
  EXPECT_NE(error_of(doc2(std::string(200, '(') + "1" + std::string(200, ')'), "1",
                          R"({"identity": {}})"))
                .find("nested too deeply"),
            std::string::npos);
  EXPECT_NE(error_of(doc2("0", "1", R"({"rotation": {"order": 1500, "k": 1}})")).find("1024"),
            std::string::npos);
}

TEST(CyclotomicIo, CompareOfEqualCopiesIsZero) {
  // Regression: copies share coefficient storage, and a filter once counted them twice.
  const auto x = CyclotomicField::get(5)->element({0, 1});
  const Cyclotomic y = x;
  EXPECT_EQ(compare(x, x), 0);
  EXPECT_EQ(compare(x, y), 0);
  EXPECT_EQ(Cyclotomic(mpq_class(2, 2)), Cyclotomic(1)); // kept in lowest terms
}

} // namespace
