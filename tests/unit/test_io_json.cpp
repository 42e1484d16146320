// The templated-structure JSON format — spec/input-format.md
//
// Exact number parsing, the transformation forms and their semantics, polygon triangulation,
// round trips parse(to_json(x)) == x, one test per class of bad input (each error names the
// field by its JSON path), and the core::analyse verdicts of the fixtures in data/.
#include "symmesh/core/linear_algebra.h"
#include "symmesh/core/structure_report.h"
#include "symmesh/io/templated_structure_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <utility>
#include <variant>

namespace {

namespace io = symmesh::io;
namespace core = symmesh::core;
using symmesh::Exact;

std::string source_path(const std::string& rel) {
  return std::string(SYMMESH_SOURCE_DIR) + "/" + rel;
}

Exact q(long n, long d = 1) {
  return Exact(n) / Exact(d);
}

template <int D>
core::Point<Exact, D> pt(std::initializer_list<Exact> c) {
  core::Point<Exact, D> p;
  int i = 0;
  for (const auto& x : c) p[i++] = x;
  return p;
}

core::StructureReport analyse_any(const io::AnyStructure& s) {
  return std::visit([](const auto& x) { return core::analyse(x); }, s);
}

io::AnyStructure read_fixture(const std::string& rel) {
  return io::read_templated_structure(source_path(rel));
}

/// The InputError message of parsing `text` ("" and a test failure if it parses).
std::string error_of(const std::string& text) {
  try {
    io::parse_templated_structure(text);
  } catch (const io::InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "message is not one line: " << m;
    return m;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an InputError: " << e.what();
    return "";
  }
  ADD_FAILURE() << "parsed without error:\n" << text;
  return "";
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

#define EXPECT_ERROR(text, prefix, fragment)                                                       \
  do {                                                                                             \
    const std::string msg_ = error_of(text);                                                       \
    EXPECT_TRUE(starts_with(msg_, prefix))                                                         \
        << "message: " << msg_ << "\nexpected prefix: " << (prefix);                               \
    EXPECT_NE(msg_.find(fragment), std::string::npos)                                              \
        << "message: " << msg_ << "\nexpected: " << (fragment);                                    \
  } while (0)

/// A one-template document; `body` is the inside of the template object.
std::string doc(const std::string& body, int dim = 2) {
  return R"({"symmesh": "templated-structure/1", "dimension": )" + std::to_string(dim) +
         R"(, "templates": [{)" + body + "}]}";
}

const std::string kSquare =
    R"("name": "S", "vertices": [["0","0"],["1","0"],["1","1"],["0","1"]], "cells": [[0,1,2],[0,2,3]])";
const std::string kIdentity = R"("instances": [{"transformation": {"identity": {}}}])";

/// The unit square template with one instance given by the transformation `tf`.
std::string with_tf(const std::string& tf, int dim = 2) {
  if (dim == 3)
    return doc(
        R"("vertices": [["0","0","0"],["1","0","0"],["0","1","0"],["0","0","1"]], "cells": [[0,1,2,3]],
                  "instances": [{"transformation": )" +
            tf + "}]",
        3);
  return doc(kSquare + R"(, "instances": [{"transformation": )" + tf + "}]");
}

template <int D>
core::RigidTransformation<Exact, D> tf_of(const std::string& tf) {
  const auto s = io::parse_templated_structure(with_tf(tf, D));
  return std::get<core::TemplatedStructure<Exact, D>>(s).instances.at(0).at(0).transformation;
}

template <class FT, int D>
void expect_same(const core::TemplatedStructure<FT, D>& a,
                 const core::TemplatedStructure<FT, D>& b) {
  ASSERT_EQ(a.templates.size(), b.templates.size());
  ASSERT_EQ(a.instances.size(), b.instances.size());
  for (std::size_t i = 0; i < a.templates.size(); ++i) {
    EXPECT_EQ(a.templates[i].name, b.templates[i].name);
    EXPECT_EQ(a.templates[i].kind, b.templates[i].kind);
    EXPECT_TRUE(a.templates[i].mesh.points == b.templates[i].mesh.points) << "template " << i;
    EXPECT_TRUE(a.templates[i].mesh.elements == b.templates[i].mesh.elements) << "template " << i;
    ASSERT_EQ(a.instances[i].size(), b.instances[i].size());
    for (std::size_t g = 0; g < a.instances[i].size(); ++g) {
      EXPECT_TRUE(a.instances[i][g].transformation == b.instances[i][g].transformation)
          << i << "," << g;
      EXPECT_EQ(a.instances[i][g].region, b.instances[i][g].region);
    }
  }
}

void expect_round_trip(const io::AnyStructure& s) {
  std::visit(
      [](const auto& x) {
        using S = std::decay_t<decltype(x)>;
        const std::string text = io::to_json(x);
        const auto back = io::parse_templated_structure(text, "to_json output");
        const auto& y = std::get<S>(back);
        expect_same(x, y);
        EXPECT_EQ(text, io::to_json(y)); // the writer is deterministic
      },
      s);
}

// ---------------------------------------------------------------------------------------------
// Exact numbers

TEST(IoJsonExact, ParsesIntegersFractionsAndDecimalsExactly) {
  EXPECT_TRUE(io::parse_exact("-0.25", "f") == q(-1, 4));
  EXPECT_TRUE(io::parse_exact("3/5", "f") == q(3, 5));
  EXPECT_TRUE(io::parse_exact("-6/4", "f") == q(-3, 2));
  EXPECT_TRUE(io::parse_exact("1e-3", "f") == q(1, 1000));
  EXPECT_TRUE(io::parse_exact("1.5e-3", "f") == q(3, 2000));
  EXPECT_TRUE(io::parse_exact("1E2", "f") == q(100));
  EXPECT_TRUE(io::parse_exact("2.5e+1", "f") == q(25));
  EXPECT_TRUE(io::parse_exact("0.1", "f") == q(1, 10)); // not the double nearest to 0.1
  EXPECT_TRUE(io::parse_exact(".5", "f") == q(1, 2));
  EXPECT_TRUE(io::parse_exact("5.", "f") == q(5));
  EXPECT_TRUE(io::parse_exact("+2", "f") == q(2));
  EXPECT_TRUE(io::parse_exact("007", "f") == q(7)); // decimal, not octal
  EXPECT_TRUE(io::parse_exact("010/0020", "f") == q(1, 2));
  EXPECT_TRUE(io::parse_exact("-0", "f") == q(0));
  EXPECT_TRUE(io::parse_exact("123456789012345678901234567890", "f") ==
              io::parse_exact("123456789012345678901234567890/1", "f"));
  EXPECT_TRUE(io::parse_exact("1/3", "f") * Exact(3) == Exact(1));
}

TEST(IoJsonExact, RejectsNonNumbers) {
  for (const std::string bad :
       {"nan",  "NaN", "-nan", "inf",   "-inf",  "Infinity", "1/0",      "-3/000", "",
        "abc",  "1/",  "/2",   "1.2.3", "1e",    "e5",       ".",        "-",      "--1",
        "0x10", " 1",  "1 ",   "1/-2",  "1/2/3", "1.5/2",    "1e100000", "1,5",    "½"}) {
    try {
      io::parse_exact(bad, "templates[0].vertices[2][1]");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const io::InputError& e) {
      EXPECT_TRUE(starts_with(e.what(), "templates[0].vertices[2][1]: ")) << e.what();
    }
  }
  try {
    io::parse_exact("nan", "x");
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("NaN"), std::string::npos) << e.what();
  }
  try {
    io::parse_exact("1/0", "x");
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("zero denominator"), std::string::npos) << e.what();
  }
}

TEST(IoJsonExact, PrintsLowestTerms) {
  EXPECT_EQ(io::exact_to_string(io::parse_exact("-0.25", "f")), "-1/4");
  EXPECT_EQ(io::exact_to_string(io::parse_exact("6/4", "f")), "3/2");
  EXPECT_EQ(io::exact_to_string(io::parse_exact("1.5e-3", "f")), "3/2000");
  EXPECT_EQ(io::exact_to_string(io::parse_exact("1e3", "f")), "1000");
  EXPECT_EQ(io::exact_to_string(io::parse_exact("-0", "f")), "0");
  EXPECT_EQ(io::exact_to_string(Exact(2) / Exact(6) + Exact(1) / Exact(6)), "1/2");
  EXPECT_EQ(io::exact_to_string(Exact(-7)), "-7");
  for (const std::string s : {"0", "-1/4", "3/5", "12345678901234567890123/7"})
    EXPECT_EQ(io::exact_to_string(io::parse_exact(s, "f")), s);
}

TEST(IoJsonExact, JsonIntegersAreExactAndFloatsAreRejected) {
  const auto s = io::parse_templated_structure(
      doc(R"("vertices": [[0, 0], [3, 0], [0, "1/3"]], "cells": [[0, 1, 2]], )" + kIdentity));
  const auto& x = std::get<io::Structure2>(s);
  EXPECT_TRUE(x.templates[0].mesh.points[1][0] == q(3));
  EXPECT_ERROR(doc(R"("vertices": [[0, 0], [0.5, 0], [0, 1]], "cells": [[0, 1, 2]], )" + kIdentity),
               "templates[0].vertices[1][0]: ", "as strings");
}

// ---------------------------------------------------------------------------------------------
// Transformations

TEST(IoJsonTransformations, Semantics2D) {
  using P = core::Point<Exact, 2>;
  auto img = [](const std::string& tf, P p) { return tf_of<2>(tf)(p); };
  EXPECT_TRUE(tf_of<2>(R"({"identity": {}})").is_identity());
  EXPECT_TRUE(img(R"({"translation": ["1/2", -3]})", pt<2>({1, 1})) == pt<2>({q(3, 2), -2}));
  // refl_{n,d}(x) = x - 2((x·n - d)/(n·n)) n, n not unit
  EXPECT_TRUE(img(R"({"reflection": {"normal": ["1", "1"], "offset": "0"}})", pt<2>({1, 0})) ==
              pt<2>({0, -1}));
  EXPECT_TRUE(img(R"({"reflection": {"normal": ["2", "2"], "offset": "2"}})", pt<2>({0, 0})) ==
              pt<2>({1, 1}));
  EXPECT_TRUE(img(R"({"reflection": {"normal": [1, 0]}})", pt<2>({3, 5})) == pt<2>({-3, 5}));
  EXPECT_TRUE(img(R"({"rotation": {"cos": "3/5", "sin": "4/5", "center": [1, 1]}})",
                  pt<2>({2, 1})) == pt<2>({q(8, 5), q(9, 5)}));
  EXPECT_TRUE(img(R"({"rotation": {"order": 4, "k": 1}})", pt<2>({1, 0})) == pt<2>({0, 1}));
  EXPECT_TRUE(img(R"({"rotation": {"order": 8, "k": 2}})", pt<2>({1, 0})) == pt<2>({0, 1}));
  EXPECT_TRUE(img(R"({"rotation": {"order": 8, "k": 4}})", pt<2>({1, 0})) == pt<2>({-1, 0}));
  EXPECT_TRUE(img(R"({"rotation": {"order": 4, "k": -1}})", pt<2>({1, 0})) == pt<2>({0, -1}));
  EXPECT_TRUE(img(R"({"rotation": {"order": 2, "k": 1, "center": [1, 0]}})", pt<2>({0, 0})) ==
              pt<2>({2, 0}));
  EXPECT_TRUE(tf_of<2>(R"({"rotation": {"order": 3, "k": 0}})").is_identity());
  // row i of A has sign[i] in column perm[i]: (x, y) -> (-y + 3, x + 1)
  EXPECT_TRUE(
      img(R"({"signed_permutation": {"perm": [1, 0], "sign": [-1, 1], "translation": [3, 1]}})",
          pt<2>({1, 0})) == pt<2>({3, 2}));
  // compose [T1, T2] = T1 ∘ T2: the last is applied first
  EXPECT_TRUE(img(R"({"compose": [{"translation": [1, 0]}, {"rotation": {"order": 4, "k": 1}}]})",
                  pt<2>({1, 0})) == pt<2>({1, 1}));
  EXPECT_TRUE(img(R"({"compose": [{"rotation": {"order": 4, "k": 1}}, {"translation": [1, 0]}]})",
                  pt<2>({1, 0})) == pt<2>({0, 2}));
  const auto m =
      tf_of<2>(R"({"matrix": [["3/5", "-4/5"], ["4/5", "3/5"]], "translation": ["1", "2"]})");
  EXPECT_TRUE(m.matrix()[0][1] == q(-4, 5));
  EXPECT_TRUE(m.translation_part() == pt<2>({1, 2}));
  EXPECT_TRUE(tf_of<2>(R"({"matrix": [[1, 0], [0, 1]]})").is_identity());
}

TEST(IoJsonTransformations, Semantics3D) {
  const auto r = tf_of<3>(R"({"rotation": {"quaternion": [1, 0, 0, 1]}})"); // 90 degrees about z
  EXPECT_TRUE(r(pt<3>({1, 0, 0})) == pt<3>({0, 1, 0}));
  const auto c = tf_of<3>(R"({"rotation": {"quaternion": [1, 0, 0, 1], "center": [1, 0, 0]}})");
  EXPECT_TRUE(c(pt<3>({1, 0, 0})) == pt<3>({1, 0, 0}));
  const auto p = tf_of<3>(R"({"signed_permutation": {"perm": [2, 0, 1], "sign": [1, -1, 1]}})");
  EXPECT_TRUE(p(pt<3>({1, 2, 3})) == pt<3>({3, -1, 2}));
  const auto f = tf_of<3>(R"({"reflection": {"normal": [0, 0, 1], "offset": "1/2"}})");
  EXPECT_TRUE(f(pt<3>({0, 0, 0})) == pt<3>({0, 0, 1}));
}

// ---------------------------------------------------------------------------------------------
// Bad input: every class throws an InputError naming the field

TEST(IoJsonErrors, MalformedJson) {
  EXPECT_ERROR(
      "{\n  \"symmesh\": \"templated-structure/1\",\n  \"dimension\": 2\n  \"templates\": []\n}",
      "input: malformed JSON at line 4 column ", "");
  EXPECT_ERROR("", "input: malformed JSON", "");
  try {
    io::parse_templated_structure("[", "my.json");
    ADD_FAILURE();
  } catch (const io::InputError& e) {
    EXPECT_TRUE(starts_with(e.what(), "my.json: malformed JSON at line 1 column ")) << e.what();
  }
}

TEST(IoJsonErrors, NumberBeyondDoubleRangeIsAnInputError) {
  // Found by the fuzzer: nlohmann throws out_of_range (not parse_error) for such a token.
  EXPECT_ERROR(R"({"symmesh": "templated-structure/1", "dimension": 2, "x": 2e2222222222})",
               "input: ", "out of range");
}

TEST(IoJsonErrors, TopLevel) {
  EXPECT_ERROR("[1, 2]", "input: expected a JSON object", "");
  EXPECT_ERROR(R"({"dimension": 2, "templates": []})", "input: missing field \"symmesh\"", "");
  EXPECT_ERROR(R"({"symmesh": "templated-structure/2", "dimension": 2, "templates": []})",
               "symmesh: ", "unsupported format");
  EXPECT_ERROR(R"({"symmesh": "templated-structure/1", "dimension": 4, "templates": []})",
               "dimension: ", "out of range");
  EXPECT_ERROR(R"({"symmesh": "templated-structure/1", "dimension": "2", "templates": []})",
               "dimension: ", "expected the integer 2 or 3");
  EXPECT_ERROR(R"({"symmesh": "templated-structure/1", "dimension": 2, "templates": []})",
               "templates: ", "no templates");
  EXPECT_ERROR(R"({"symmesh": "templated-structure/1", "dimension": 2})",
               "input: missing field \"templates\"", "");
  EXPECT_ERROR(
      R"({"symmesh": "templated-structure/1", "dimension": 2, "templates": [], "colour": 1})",
      "input: unknown field \"colour\"", "");
  EXPECT_ERROR(
      R"({"symmesh": "templated-structure/1", "dimension": 2, "dimension": 3, "templates": []})",
      "input: duplicate field \"dimension\"", "");
}

TEST(IoJsonErrors, TemplateShape) {
  EXPECT_ERROR(doc(kSquare + R"(, "colour": "red", )" + kIdentity),
               "templates[0]: unknown field \"colour\"", "");
  EXPECT_ERROR(doc(R"("vertices": [["0","0"],["1","0"],["1","1"],["0","1"]], )" + kIdentity),
               "templates[0]: missing field \"cells\"", "");
  EXPECT_ERROR(doc(R"("cells": [[0,1,2]], )" + kIdentity),
               "templates[0]: missing field \"vertices\"", "");
  EXPECT_ERROR(doc(R"("name": "S", )" + kIdentity),
               "templates[0]: missing fields \"vertices\" and \"cells\"", "");
  EXPECT_ERROR(doc(R"("kind": "geometry", )" + kIdentity), "templates[0]: ", "\"polygon\"");
  EXPECT_ERROR(doc(kSquare), "templates[0]: missing field \"instances\"", "");
  EXPECT_ERROR(doc(kSquare + R"(, "instances": [])"), "templates[0].instances: no instances", "");
  EXPECT_ERROR(doc(kSquare + R"(, "kind": "blob", )" + kIdentity),
               "templates[0].kind: ", "unknown kind");
  EXPECT_ERROR(doc(kSquare + R"(, "name": 3, )" + kIdentity),
               "templates[0]: duplicate field \"name\"", "");
  EXPECT_ERROR(
      doc(R"("name": 3, "vertices": [[0,0],[1,0],[0,1]], "cells": [[0,1,2]], )" + kIdentity),
      "templates[0].name: ", "expected a string");
  EXPECT_ERROR(doc(R"("vertices": [], "cells": [[0,1,2]], )" + kIdentity),
               "templates[0].vertices: ", "no vertices");
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [], )" + kIdentity),
               "templates[0].cells: ", "no cells");
  // wrong coordinate count (mixed dimensions)
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0,0],[0,1]], "cells": [[0,1,2]], )" + kIdentity),
               "templates[0].vertices[1]: ", "expected 2 coordinates");
  EXPECT_ERROR(
      doc(R"("vertices": [[0,0,0],[1,0,0],[0,1,0],[0,0]], "cells": [[0,1,2,3]], )" + kIdentity, 3),
      "templates[0].vertices[3]: ", "expected 3 coordinates");
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [[0,1]], )" + kIdentity),
               "templates[0].cells[0]: ", "got 2");
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [[0,1,2,0]], )" + kIdentity),
               "templates[0].cells[0]: ", "got 4");
  // vertex indices
  EXPECT_ERROR(
      doc(R"("vertices": [[0,0],[1,0],[1,1],[0,1]], "cells": [[0,1,2],[0,2,7]], )" + kIdentity),
      "templates[0].cells[1]: vertex index 7 out of range (4 vertices)", "");
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [[0,-1,2]], )" + kIdentity),
               "templates[0].cells[0]: vertex index -1 out of range", "");
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [[0,"1",2]], )" + kIdentity),
               "templates[0].cells[0][1]: a vertex index must be a JSON integer", "");
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [[0,1.0,2]], )" + kIdentity),
               "templates[0].cells[0][1]: a vertex index must be a JSON integer", "");
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [[0,1,1]], )" + kIdentity),
               "templates[0].cells[0]: vertex index 1 appears twice", "");
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [[0,1,2],[2,1,0]], )" + kIdentity),
               "templates[0].cells[1]: the same cell as cells[0]", "");
  // degenerate cells, duplicate and unused vertices
  EXPECT_ERROR(
      doc(R"("vertices": [[0,0],[1,0],[0,1],[2,0]], "cells": [[0,1,2],[0,1,3]], )" + kIdentity),
      "templates[0].cells[1]: degenerate cell", "zero area");
  EXPECT_ERROR(
      doc(R"("vertices": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]], "cells": [[0,1,2,3]], )" + kIdentity,
          3),
      "templates[0].cells[0]: degenerate cell", "zero volume");
  EXPECT_ERROR(
      doc(R"("vertices": [[0,0],[1,0],[0,1],["2/2","0"]], "cells": [[0,1,2]], )" + kIdentity),
      "templates[0].vertices[3]: duplicate vertex (same coordinates as vertices[1])", "");
  EXPECT_ERROR(doc(R"("vertices": [[0,0],[1,0],[0,1],[5,5]], "cells": [[0,1,2]], )" + kIdentity),
               "templates[0].vertices[3]: vertex is not used by any cell", "");
  // second template, for the path
  const std::string two =
      R"({"symmesh": "templated-structure/1", "dimension": 2, "templates": [{)" + kSquare + ", " +
      kIdentity + R"(}, {"vertices": [[0,0],[1,0],["nan",1]], "cells": [[0,1,2]], )" + kIdentity +
      "}]}";
  EXPECT_ERROR(two, "templates[1].vertices[2][0]: \"nan\" is not allowed", "");
}

TEST(IoJsonErrors, DuplicateKeysAreNamedByTheirPath) {
  const std::string text =
      R"({"symmesh": "templated-structure/1", "dimension": 2, "templates": [{)" + kSquare + ", " +
      kIdentity + R"(}, {)" + kSquare + R"(, "instances": [{"transformation": {"identity": {}}},
      {"region": 2, "transformation": {"compose": [{"identity": {}}, {"reflection": {"normal": [1, 0], "normal": [0, 1]}}]}}]}]})";
  EXPECT_ERROR(
      text,
      "templates[1].instances[1].transformation.compose[1].reflection: duplicate field \"normal\"",
      "");
}

TEST(IoJsonErrors, DeeplyNestedComposeIsRejected) {
  std::string tf = R"({"identity": {}})";
  for (int k = 0; k < 150; ++k) tf = R"({"compose": [)" + tf + "]}";
  EXPECT_ERROR(with_tf(tf), "templates[0].instances[0].transformation", "nested too deeply");
}

TEST(IoJsonDefaults, NameKindAndRegion) {
  const auto s = io::parse_templated_structure(
      doc(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [[0,1,2]], )" + kIdentity));
  const auto& x = std::get<io::Structure2>(s);
  EXPECT_EQ(x.templates[0].name, "X1");
  EXPECT_EQ(x.templates[0].kind, core::TemplateKind::mesh);
  EXPECT_EQ(x.instances[0][0].region, 1);
  EXPECT_EQ(x.templates[0].mesh.elements.size(),
            7u); // face completion: 3 vertices, 3 edges, 1 triangle
}

TEST(IoJsonErrors, Instances) {
  EXPECT_ERROR(doc(kSquare + R"(, "instances": [{"region": 1}])"),
               "templates[0].instances[0]: missing field \"transformation\"", "");
  EXPECT_ERROR(
      doc(kSquare + R"(, "instances": [{"transformation": {"identity": {}}, "colour": 2}])"),
      "templates[0].instances[0]: unknown field \"colour\"", "");
  EXPECT_ERROR(
      doc(kSquare + R"(, "instances": [{"transformation": {"identity": {}}, "region": 1.5}])"),
      "templates[0].instances[0].region: ", "");
  EXPECT_ERROR(
      doc(kSquare + R"(, "instances": [{"transformation": {"identity": {}}, "region": "1"}])"),
      "templates[0].instances[0].region: ", "expected an integer");
  EXPECT_ERROR(doc(kSquare + R"(, "instances": {"transformation": {"identity": {}}})"),
               "templates[0].instances: ", "expected an array");
}

TEST(IoJsonErrors, Transformations) {
  const std::string p = "templates[0].instances[0].transformation";
  EXPECT_ERROR(with_tf(R"({"shear": {"factor": "1/2"}})"), p + ": unknown transformation \"shear\"",
               "");
  EXPECT_ERROR(with_tf("{}"), p + ": empty transformation", "");
  EXPECT_ERROR(with_tf(R"({"translation": [0, 0], "identity": {}})"), p + ": ", "exactly one key");
  EXPECT_ERROR(with_tf(R"({"translation": [0, 0], "translation": [1, 0]})"),
               p + ": duplicate field \"translation\"", "");
  EXPECT_ERROR(with_tf(R"({"identity": []})"), p + ".identity: ", "expected {}");
  EXPECT_ERROR(with_tf(R"({"translation": [0, 0, 0]})"),
               p + ".translation: ", "expected 2 coordinates");
  EXPECT_ERROR(with_tf(R"({"translation": [0, 0.5]})"), p + ".translation[1]: ", "string");
  EXPECT_ERROR(with_tf(R"({"matrix": [["1", "1"], ["0", "1"]], "translation": ["0", "0"]})"),
               p + ".matrix: matrix is not orthogonal: (A^T A)[0][1] != 0", "");
  EXPECT_ERROR(with_tf(R"({"matrix": [[0, 0], [0, 0]]})"), p + ".matrix: matrix is not orthogonal",
               "");
  EXPECT_ERROR(with_tf(R"({"matrix": [[2, 0], [0, "1/2"]]})"),
               p + ".matrix: matrix is not orthogonal", "");
  EXPECT_ERROR(with_tf(R"({"matrix": [[1, 0]]})"), p + ".matrix: ", "expected 2 rows");
  EXPECT_ERROR(with_tf(R"({"matrix": [[1, 0], [0, 1]], "scale": 2})"),
               p + ": unknown field \"scale\"", "");
  EXPECT_ERROR(with_tf(R"({"reflection": {"normal": [0, 0], "offset": 1}})"),
               p + ".reflection.normal: ", "zero vector");
  EXPECT_ERROR(with_tf(R"({"reflection": {"offset": 1}})"),
               p + ".reflection: missing field \"normal\"", "");
  EXPECT_ERROR(with_tf(R"({"rotation": {"cos": "1/2", "sin": "1/2"}})"),
               p + ".rotation: ", "cos^2 + sin^2 != 1");
  EXPECT_ERROR(with_tf(R"({"rotation": {"cos": "3/5"}})"), p + ".rotation: missing field \"sin\"",
               "");
  EXPECT_ERROR(with_tf(R"({"rotation": {"order": 2000, "k": 1}})"),
               p + ".rotation.order: ", "the largest supported");
  EXPECT_ERROR(with_tf(R"({"rotation": {"order": 0, "k": 1}})"),
               p + ".rotation.order: ", "out of range");
  EXPECT_ERROR(with_tf(R"({"rotation": {"quaternion": [1, 0, 0, 0]}})"),
               p + ".rotation.quaternion: ", "3D only");
  EXPECT_ERROR(with_tf(R"({"rotation": {"angle": 90}})"), p + ".rotation: ", "\"cos\" and \"sin\"");
  EXPECT_ERROR(with_tf(R"({"rotation": {"quaternion": [0, 0, 0, 0]}})", 3),
               p + ".rotation.quaternion: ", "quaternion is zero");
  EXPECT_ERROR(with_tf(R"({"rotation": {"cos": 1, "sin": 0}})", 3),
               p + ".rotation: ", "quaternion");
  EXPECT_ERROR(with_tf(R"({"signed_permutation": {"perm": [0, 0], "sign": [1, 1]}})"),
               p + ".signed_permutation: ", "not a permutation");
  EXPECT_ERROR(with_tf(R"({"signed_permutation": {"perm": [0, 1], "sign": [1, 2]}})"),
               p + ".signed_permutation: ", "must be 1 or -1");
  EXPECT_ERROR(with_tf(R"({"signed_permutation": {"perm": [0, 1]}})"),
               p + ".signed_permutation: missing field \"sign\"", "");
  EXPECT_ERROR(with_tf(R"({"compose": []})"), p + ".compose: ", "at least one");
  EXPECT_ERROR(with_tf(R"({"compose": [{"identity": {}}, {"shear": 1}]})"),
               p + ".compose[1]: ", "unknown transformation \"shear\"");
}

// ---------------------------------------------------------------------------------------------
// Polygons (2D geometry templates)

Exact area_of(const core::ElementComplex<Exact, 2>& m) {
  Exact a = 0;
  for (const auto& c : m.cells()) {
    const auto p = m.coords(c);
    Exact d = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
    a += d < 0 ? -d / 2 : d / 2;
  }
  return a;
}

std::string geometry(const std::string& rings) {
  return doc(R"("name": "G", "kind": "geometry", )" + rings + ", " + kIdentity);
}

TEST(IoJsonPolygon, TriangulatesPolygonWithHolesExactly) {
  const auto s = io::parse_templated_structure(geometry(
      R"("polygon": [[0,0],[4,0],[4,4],[0,4]], "holes": [[[1,1],[2,1],[2,2],[1,2]], [["5/2","1/2"],[3,"1/2"],[3,3]]])"));
  const auto& x = std::get<io::Structure2>(s);
  const auto& m = x.templates[0].mesh;
  EXPECT_EQ(x.templates[0].kind, core::TemplateKind::geometry);
  EXPECT_EQ(m.points.size(), 11u);
  EXPECT_TRUE(m.points[4] == pt<2>({1, 1})); // input order is kept
  const Exact area = area_of(m);
  EXPECT_TRUE(area == Exact(16) - Exact(1) - q(5, 8)) << io::exact_to_string(area);
  EXPECT_TRUE(core::is_mesh(m));
  const auto r = analyse_any(s);
  EXPECT_TRUE(r.well_formed) << r.error;
  EXPECT_TRUE(r.templated_geometry);
  // a straight (180 degree) vertex is kept as a vertex
  const auto t =
      io::parse_templated_structure(geometry(R"("polygon": [[0,0],[1,0],[2,0],[2,2],[0,2]])"));
  EXPECT_EQ(std::get<io::Structure2>(t).templates[0].mesh.cells().size(), 3u);
  expect_round_trip(s);
}

TEST(IoJsonPolygon, RejectsBadPolygons) {
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[2,2],[2,0],[0,2]])"),
               "templates[0].polygon: ", "self-intersecting");
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[1,0],[2,0]])"),
               "templates[0].polygon: ", "self-intersecting");
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[2,0],[2,1],[1,0],[1,2]])"),
               "templates[0].polygon: ", "self-intersecting");
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[1,0]])"),
               "templates[0].polygon: ", "at least 3 vertices");
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[1,0],[1,1],[0,0]])"),
               "templates[0].polygon[3]: ", "repeated vertex");
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[4,0],[4,4],[0,4]], "holes": [[[5,5],[6,5],[6,6]]])"),
               "templates[0].holes[0]: ", "not inside");
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[4,0],[4,4],[0,4]], "holes": [[[1,1],[5,1],[5,2]]])"),
               "templates[0].holes[0]: ", "touch or cross");
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[4,0],[4,4],[0,4]], "holes": [[[0,0],[1,1],[1,2]]])"),
               "templates[0].holes[0][0]: ", "repeated vertex");
  EXPECT_ERROR(
      geometry(
          R"("polygon": [[0,0],[9,0],[9,9],[0,9]], "holes": [[[1,1],[8,1],[8,8],[1,8]], [[2,2],[3,2],[3,3]]])"),
      "templates[0].holes[1]: ", "inside another hole");
  EXPECT_ERROR(
      geometry(
          R"("polygon": [[0,0],[4,0],[4,4],[0,4]], "holes": [[[1,1],[2,1],[2,2]], [[2,1],[3,1],[3,2]]])"),
      "templates[0].holes[1][0]: ", "repeated vertex");
  EXPECT_ERROR(doc(R"("polygon": [[0,0],[1,0],[0,1]], )" + kIdentity),
               "templates[0].polygon: ", "geometry");
  EXPECT_ERROR(doc(R"("kind": "geometry", "polygon": [[0,0,0],[1,0,0],[0,1,0]], )" + kIdentity, 3),
               "templates[0].polygon: ", "2D");
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[1,0],[0,1]], "cells": [[0,1,2]])"),
               "templates[0]: ", "not both");
  EXPECT_ERROR(geometry(R"("vertices": [[0,0],[1,0],[0,1]], "cells": [[0,1,2]], "holes": [])"),
               "templates[0].holes: ", "needs \"polygon\"");
  EXPECT_ERROR(geometry(R"("polygon": [[0,0],[1,0],["inf",1]])"),
               "templates[0].polygon[2][0]: ", "not allowed");
}

// ---------------------------------------------------------------------------------------------
// 3D geometry templates given as a PLC (vertices + polygonal faces), spec/input-format.md#plc

const std::string kCubeVertices =
    R"("vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1]])";
const std::string kCubeFaces = R"([0,3,2,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7])";

std::string solid(const std::string& vertices, const std::string& faces) {
  return doc(R"("name": "P", "kind": "geometry", )" + vertices + R"(, "faces": [)" + faces + "], " +
                 kIdentity,
             3);
}

/// Sum of |det|/6 over the tetrahedra: the exact volume of a carrier.
template <class FT>
FT volume_of(const core::ElementComplex<FT, 3>& m) {
  FT v(0);
  for (const auto& c : m.cells()) {
    const auto p = m.coords(c);
    core::Matrix<FT> a(3, std::vector<FT>(3));
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k)
        a[std::size_t(r)][std::size_t(k)] = p[std::size_t(r + 1)][k] - p[0][k];
    const FT d = core::determinant(a);
    v += (d < FT(0) ? -d : d) / FT(6);
  }
  return v;
}

TEST(IoJsonPlc, BoxWithATunnelIsTetrahedralizedExactly) {
  // Two faces with a hole; the carrier's underlying space is the solid, volume 2*2*1 - 1*1*1.
  const auto s = io::parse_templated_structure(solid(
      R"("vertices": [[0,0,0],[2,0,0],[2,2,0],[0,2,0],[0,0,1],[2,0,1],[2,2,1],[0,2,1],
        ["1/2","1/2",0],["3/2","1/2",0],["3/2","3/2",0],["1/2","3/2",0],
        ["1/2","1/2",1],["3/2","1/2",1],["3/2","3/2",1],["1/2","3/2",1]])",
      R"({"polygon": [0,1,2,3], "holes": [[8,9,10,11]]}, {"polygon": [4,5,6,7], "holes": [[12,13,14,15]]},
        [0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7],[8,9,13,12],[9,10,14,13],[10,11,15,14],[11,8,12,15])"));
  const auto& x = std::get<io::Structure3>(s);
  const auto& m = x.templates[0].mesh;
  EXPECT_EQ(x.templates[0].kind, core::TemplateKind::geometry);
  EXPECT_TRUE(m.points[9] == pt<3>({q(3, 2), q(1, 2), 0})); // input order is kept
  EXPECT_TRUE(volume_of(m) == Exact(3)) << io::exact_to_string(volume_of(m));
  EXPECT_TRUE(core::is_mesh(m));
  // The carrier boundary is the triangulated faces: 8+8 (holed faces) + 8*2 (quads) triangles.
  EXPECT_EQ(core::mesh_boundary(m).cells().size(), 32u);
  const auto r = analyse_any(s);
  EXPECT_TRUE(r.well_formed) << r.error;
  EXPECT_TRUE(r.templated_geometry);
}

TEST(IoJsonPlc, CavityIsLeftOutAndCyclotomicFacesAreExact) {
  // A cube with a closed inner shell (a cavity): the carrier has the cavity's volume removed.
  const auto c = io::parse_templated_structure(solid(
      R"("vertices": [[0,0,0],[4,0,0],[4,4,0],[0,4,0],[0,0,4],[4,0,4],[4,4,4],[0,4,4],
        [1,1,1],[2,1,1],[2,2,1],[1,2,1],[1,1,2],[2,1,2],[2,2,2],[1,2,2]])",
      R"([0,3,2,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7],
        [8,11,10,9],[12,13,14,15],[8,9,13,12],[9,10,14,13],[10,11,15,14],[11,8,12,15])"));
  EXPECT_TRUE(volume_of(std::get<io::Structure3>(c).templates[0].mesh) == Exact(63));
  // A wedge of angle 2pi/8 in K_8: its volume is sin(2pi/8)/2 exactly.
  const auto w = io::parse_templated_structure(solid(
      R"x("vertices": [[0,0,0],[1,0,0],["cos(2pi/8)","sin(2pi/8)",0],[0,0,1],[1,0,1],["cos(2pi/8)","sin(2pi/8)",1]])x",
      R"([0,2,1],[3,4,5],[0,1,4,3],[1,2,5,4],[2,0,3,5])"));
  const auto& m = std::get<io::CyclotomicStructure3>(w).templates[0].mesh;
  EXPECT_TRUE(volume_of(m) == m.points[2][1] / io::Cyclotomic(2));
}

TEST(IoJsonPlc, RejectsBadPlcsNamingTheFace) {
  EXPECT_ERROR(solid(kCubeVertices, R"([0,3,2,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6])"),
               "templates[0].faces[", "not closed");
  EXPECT_ERROR(solid(kCubeVertices, kCubeFaces + R"(, [0,1,6,7])"), "templates[0].faces[",
               "not manifold");
  EXPECT_ERROR(
      solid(
          R"("vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,"11/10"],[0,1,1]])",
          kCubeFaces),
      "templates[0].faces[1][3]: ", "not planar");
  EXPECT_ERROR(
      solid(
          R"("vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1],[2,0,0]])",
          kCubeFaces + R"(, [0,1,8])"),
      "templates[0].faces[6]: ", "zero area");
  EXPECT_ERROR(
      solid(kCubeVertices, R"([0,2,3,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7])"),
      "templates[0].faces[0]: ", "self-intersecting");
  // Two tetrahedra that cross each other in one template.
  EXPECT_ERROR(
      solid(
          R"("vertices": [[0,0,0],[2,0,0],[0,2,0],[0,0,2],["1/2","1/2","1/2"],["5/2","1/2","1/2"],["1/2","5/2","1/2"],["1/2","1/2","5/2"]])",
          R"([0,2,1],[0,1,3],[1,2,3],[0,3,2],[4,6,5],[4,5,7],[5,6,7],[4,7,6])"),
      "templates[0].faces[", "intersect");
  EXPECT_ERROR(
      solid(kCubeVertices, R"([0,3,2,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7,3])"),
      "templates[0].faces[5][4]: ", "appears twice");
  EXPECT_ERROR(
      solid(kCubeVertices, R"([0,3,2,1],[4,5,6,7],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,9])"),
      "templates[0].faces[5][3]: ", "out of range");
  EXPECT_ERROR(
      solid(
          R"("vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1],[5,5,5]])",
          kCubeFaces),
      "templates[0].vertices[8]: ", "not used by any face");
  EXPECT_ERROR(doc(kCubeVertices + R"(, "faces": [)" + kCubeFaces + "], " + kIdentity, 3),
               "templates[0].faces: ", "geometry");
  EXPECT_ERROR(doc(R"("kind": "geometry", "vertices": [[0,0],[1,0],[0,1]], "faces": [[0,1,2]], )" +
                   kIdentity),
               "templates[0].faces: ", "3D");
  EXPECT_ERROR(solid(kCubeVertices, kCubeFaces + R"(], "cells": [[0,1,2,4])"),
               "templates[0]: ", "not both");
}

// ---------------------------------------------------------------------------------------------
// Writers and round trips

TEST(IoJsonRoundTrip, FixturesAndGeneratedStructures) {
  for (const std::string f : {"data/fig_4_3_templated_mesh.json", "data/fig_4_4_nonconforming.json",
                              "data/fig_4_5_reflection.json", "data/fig_4_6_instance_graph.json",
                              "data/reflected_cube_3d.json", "data/square_geometry_2d.json",
                              "tests/data/bad/overlapping_instances.json"}) {
    SCOPED_TRACE(f);
    expect_round_trip(read_fixture(f));
  }
  // A structure built in code, with non-trivial exact transformations.
  io::Structure2 x;
  core::Template<Exact, 2> t;
  t.name = "";
  t.mesh.points = {pt<2>({0, 0}), pt<2>({q(1, 3), 0}), pt<2>({0, q(-7, 2)})};
  t.mesh.elements = {core::Simplex{0, 1, 2}};
  t.mesh = core::face_completion(t.mesh);
  x.templates.push_back(t);
  using R = core::RigidTransformation<Exact, 2>;
  x.instances.push_back(
      {{R::rotation_2d(q(3, 5), q(-4, 5), pt<2>({q(1, 7), 2})), -3},
       {R::reflection(pt<2>({3, 4}), q(1, 2)) * R::translation(pt<2>({5, q(1, 9)})), 7}});
  expect_round_trip(io::AnyStructure(x));
  io::Structure3 y;
  core::Template<Exact, 3> u;
  u.name = "tet \"quoted\"";
  u.kind = core::TemplateKind::geometry;
  u.mesh.points = {pt<3>({0, 0, 0}), pt<3>({1, 0, 0}), pt<3>({0, 1, 0}), pt<3>({0, 0, q(1, 2)})};
  u.mesh.elements = {core::Simplex{0, 1, 2, 3}};
  u.mesh = core::face_completion(u.mesh);
  y.templates.push_back(u);
  using R3 = core::RigidTransformation<Exact, 3>;
  y.instances.push_back({{R3::rotation_quaternion(1, 2, 3, 4, pt<3>({1, 1, 1})), 1}});
  expect_round_trip(io::AnyStructure(y));
}

TEST(IoJsonRoundTrip, WritesTransformationsAsExactMatrices) {
  const auto s = read_fixture("data/fig_4_3_templated_mesh.json");
  const auto j = nlohmann::json::parse(io::to_json(std::get<io::Structure2>(s)));
  EXPECT_EQ(j["symmesh"], "templated-structure/1");
  EXPECT_EQ(j["dimension"], 2);
  const auto& t12 = j["templates"][0]["instances"][1]["transformation"];
  EXPECT_EQ(t12["matrix"], nlohmann::json::parse(R"([["-1", "0"], ["0", "1"]])"));
  EXPECT_EQ(t12["translation"], nlohmann::json::parse(R"(["2", "0"])"));
  EXPECT_EQ(j["templates"][0]["cells"].size(), 3u); // only the D-cells
  EXPECT_EQ(j["templates"][0]["vertices"][2], nlohmann::json::parse(R"(["1", "1/3"])"));
}

TEST(IoJsonRoundTrip, ComplexToJson) {
  core::ElementComplex<Exact, 2> m;
  m.points = {pt<2>({0, 0}), pt<2>({q(1, 2), 0}), pt<2>({0, 1})};
  m.elements = {core::Simplex{0, 1, 2}};
  m = core::face_completion(m);
  const auto j = nlohmann::json::parse(io::complex_to_json(m));
  EXPECT_EQ(j["dimension"], 2);
  EXPECT_EQ(j["vertices"][1], nlohmann::json::parse(R"(["1/2", "0"])"));
  EXPECT_EQ(j["elements"].size(), 7u);
  EXPECT_EQ(j["elements"][6], nlohmann::json::parse("[0, 1, 2]"));
  core::ElementComplex<Exact, 3> c;
  c.points = {pt<3>({0, 0, 0}), pt<3>({1, 0, 0}), pt<3>({0, 1, 0}), pt<3>({0, 0, 1})};
  c.elements = {core::Simplex{0, 1, 2, 3}};
  c = core::face_completion(c);
  const auto k = nlohmann::json::parse(io::complex_to_json(c));
  EXPECT_EQ(k["dimension"], 3);
  EXPECT_EQ(k["elements"].size(), 15u);
}

// ---------------------------------------------------------------------------------------------
// Fixtures: the verdicts of core::analyse

/// Graph edges counted by unordered template pair; trivial self-loops separately.
std::map<std::pair<std::size_t, std::size_t>, int>
edge_multiplicities(const core::StructureReport& r, int* trivial) {
  std::map<std::pair<std::size_t, std::size_t>, int> out;
  *trivial = 0;
  for (const auto& e : r.graph_edges) {
    if (e.edge.trivial) {
      ++*trivial;
      continue;
    }
    ++out[{std::min(e.template_a, e.template_b), std::max(e.template_a, e.template_b)}];
  }
  return out;
}

TEST(IoJsonFixtures, Fig43TemplatedMesh) {
  const auto r = analyse_any(read_fixture("data/fig_4_3_templated_mesh.json"));
  ASSERT_TRUE(r.well_formed) << r.error;
  EXPECT_EQ(r.dimension, 2);
  EXPECT_EQ(r.templates, 2u);
  EXPECT_EQ(r.instances, 5u);
  EXPECT_TRUE(r.templated_structure);
  EXPECT_TRUE(r.templated_mesh);
  EXPECT_TRUE(r.lemma42.holds) << r.lemma42.detail;
  EXPECT_TRUE(r.lemma42_agrees);
  EXPECT_EQ(r.lemma42.pairs_checked, 8u);
  EXPECT_EQ(r.graph_edges.size(), 10u); // 2 trivial loops + 8 neighbouring pairs
}

TEST(IoJsonFixtures, Fig44NonConforming) {
  const auto r = analyse_any(read_fixture("data/fig_4_4_nonconforming.json"));
  ASSERT_TRUE(r.well_formed) << r.error;
  EXPECT_TRUE(r.templated_structure);
  EXPECT_FALSE(r.templated_mesh);
  EXPECT_FALSE(r.lemma42.holds);
  EXPECT_TRUE(r.lemma42_agrees);
  EXPECT_EQ(core::to_string(r.lemma42.a), "T_{1,1}");
  EXPECT_EQ(core::to_string(r.lemma42.b), "T_{1,2}");
  EXPECT_EQ(r.lemma42.condition, 1);
  EXPECT_EQ(r.graph_edges.size(), 10u);
}

TEST(IoJsonFixtures, Fig45ReflectionSelfInterface) {
  const auto r = analyse_any(read_fixture("data/fig_4_5_reflection.json"));
  ASSERT_TRUE(r.well_formed) << r.error;
  EXPECT_TRUE(r.templated_structure);
  EXPECT_TRUE(r.templated_mesh);
  EXPECT_TRUE(r.lemma42.holds);
  ASSERT_EQ(r.graph_edges.size(), 2u);
  int trivial = 0;
  const auto m = edge_multiplicities(r, &trivial);
  EXPECT_EQ(trivial, 1);
  EXPECT_EQ((m.at({0, 0})), 1); // the template interfaces itself: T_{1,1} / T_{1,2}
}

TEST(IoJsonFixtures, Fig46InstanceGraphMultigraph) {
  const auto r = analyse_any(read_fixture("data/fig_4_6_instance_graph.json"));
  ASSERT_TRUE(r.well_formed) << r.error;
  EXPECT_TRUE(r.templated_structure);
  EXPECT_TRUE(r.templated_mesh);
  EXPECT_TRUE(r.lemma42.holds);
  EXPECT_EQ(r.graph_edges.size(), 14u); // 3 trivial loops + 11 neighbouring pairs
  int trivial = 0;
  const auto m = edge_multiplicities(r, &trivial);
  EXPECT_EQ(trivial, 3);
  const std::map<std::pair<std::size_t, std::size_t>, int> expected{
      {{0, 1}, 3}, {{0, 2}, 3}, {{1, 2}, 3}, {{1, 1}, 1}, {{2, 2}, 1}};
  EXPECT_EQ(m, expected);
}

TEST(IoJsonFixtures, ReflectedCube3D) {
  const auto s = read_fixture("data/reflected_cube_3d.json");
  ASSERT_TRUE(std::holds_alternative<io::Structure3>(s));
  EXPECT_EQ(std::get<io::Structure3>(s).templates[0].mesh.cells().size(), 6u);
  const auto r = analyse_any(s);
  ASSERT_TRUE(r.well_formed) << r.error;
  EXPECT_EQ(r.dimension, 3);
  EXPECT_TRUE(r.templated_structure);
  EXPECT_TRUE(r.templated_mesh);
  EXPECT_TRUE(r.lemma42.holds);
  EXPECT_EQ(r.graph_edges.size(), 2u);
  EXPECT_EQ(r.structure_instance_vertices, 12u);
  EXPECT_EQ(r.structure_instance_cells, 12u);
}

TEST(IoJsonFixtures, SquareGeometryFromPolygon) {
  const auto s = read_fixture("data/square_geometry_2d.json");
  const auto& x = std::get<io::Structure2>(s);
  EXPECT_EQ(x.templates[0].kind, core::TemplateKind::geometry);
  EXPECT_EQ(x.templates[0].mesh.cells().size(), 4u); // a hexagon: 4 triangles
  const Exact area = area_of(x.templates[0].mesh);
  EXPECT_TRUE(area == Exact(3));
  const auto r = analyse_any(s);
  ASSERT_TRUE(r.well_formed) << r.error;
  EXPECT_FALSE(r.mesh_templates);
  EXPECT_TRUE(r.templated_structure);
  EXPECT_TRUE(r.templated_geometry);
  EXPECT_FALSE(r.templated_mesh);
  EXPECT_EQ(r.graph_edges.size(), 7u); // 1 trivial loop + all 6 pairs meet (at least at the origin)
}

TEST(IoJsonFixtures, OverlappingInstancesAreNotATemplatedStructure) {
  const auto r = analyse_any(read_fixture("tests/data/bad/overlapping_instances.json"));
  EXPECT_TRUE(r.well_formed) << r.error;
  EXPECT_FALSE(r.templated_structure);
  ASSERT_TRUE(r.overlap.has_value());
  EXPECT_EQ(core::to_string(r.overlap->a), "T_{1,1}");
  EXPECT_EQ(core::to_string(r.overlap->b), "T_{1,2}");
}

TEST(IoJsonFixtures, BadFilesThrowInputErrorsNamingTheField) {
  const std::map<std::string, std::string> expected{
      {"malformed.json", "malformed JSON at line 4 column 13: syntax error"},
      {"nonorthogonal_matrix.json", "templates[0].instances[1].transformation.matrix: matrix is "
                                    "not orthogonal: (A^T A)[0][1] != 0"},
      {"nan.json", "templates[0].vertices[2][0]: \"nan\" is not allowed"},
      {"missing_field.json", "templates[0]: missing field \"cells\""},
      {"unknown_transformation.json",
       "templates[0].instances[1].transformation: unknown transformation \"shear\""},
  };
  for (const auto& [file, prefix] : expected) {
    SCOPED_TRACE(file);
    const std::string path = source_path("tests/data/bad/" + file);
    try {
      io::read_templated_structure(path);
      ADD_FAILURE() << "no error";
    } catch (const io::InputError& e) {
      const std::string m = e.what();
      const std::string full = file == "malformed.json" ? path + ": " + prefix : prefix;
      EXPECT_TRUE(starts_with(m, full)) << m;
    }
  }
}

TEST(IoJsonFixtures, UnreadableFile) {
  const std::string path = source_path("tests/data/bad/does_not_exist.json");
  try {
    io::read_templated_structure(path);
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot open file");
  }
  try {
    io::read_templated_structure(source_path("tests/data/bad"));
    ADD_FAILURE() << "no error";
  } catch (const io::InputError& e) {
    EXPECT_TRUE(starts_with(e.what(), source_path("tests/data/bad") + ": cannot open file"))
        << e.what();
  }
}

} // namespace
