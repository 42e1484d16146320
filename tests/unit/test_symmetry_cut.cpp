// The cut of a whole symmetric object into its fundamental piece (spec/generation.md#cut):
// Algorithm 6.2's slice with Algorithm 6.3's first ray, Algorithms 6.1/6.4 (one or two orthogonal
// mirrors) and 6.5 (mirror + rotation). Areas are compared exactly: |group| · area(pieces) =
// area(object), per region; rings are checked vertex by vertex; bad symmetries are refused.
#include "symmesh/gen/symmetry_cut.h"
#include "symmesh/io/examples.h"
#include "symmesh/io/templated_structure_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <variant>

namespace {

namespace gen = symmesh::gen;
namespace io = symmesh::io;
namespace core = symmesh::core;
using symmesh::number::Cyclotomic;
using Structure = core::TemplatedStructure<Cyclotomic, 2>;

Structure as_cyclotomic(const io::AnyStructure& x) {
  if (const auto* c = std::get_if<io::CyclotomicStructure2>(&x)) return *c;
  return core::convert_numbers<Cyclotomic>(
      std::get<io::Structure2>(x),
      [](const symmesh::Exact& v) { return Cyclotomic(mpq_class(io::exact_to_string(v))); });
}
Structure example(const std::string& name) {
  return as_cyclotomic(io::parse_templated_structure(io::example_document(name).dump()));
}
Structure parse(const std::string& text) {
  return as_cyclotomic(io::parse_templated_structure(text));
}

Cyclotomic twice_area(const std::vector<gen::CutPoint>& ring) {
  Cyclotomic s(0);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const auto& a = ring[i];
    const auto& b = ring[(i + 1) % ring.size()];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return s;
}
/// Twice the area per region, of the cut's pieces (holes subtract: they run clockwise).
std::map<int, Cyclotomic> piece_areas(const gen::CutResult& r) {
  std::map<int, Cyclotomic> out;
  for (const auto& p : r.pieces) {
    Cyclotomic a = twice_area(p.outer);
    for (const auto& h : p.holes) a += twice_area(h);
    out.try_emplace(p.region, Cyclotomic(0));
    out[p.region] += a;
  }
  return out;
}
/// Twice the area per region of the object AT(X), from its carrier triangles.
std::map<int, Cyclotomic> object_areas(const Structure& x) {
  std::map<int, Cyclotomic> out;
  for (const auto& id : x.instance_ids()) {
    const auto inst = core::instance(x, id);
    const int region = x.instances[id.i][id.g].region;
    out.try_emplace(region, Cyclotomic(0));
    for (const auto& c : inst.cells()) {
      std::vector<gen::CutPoint> tri;
      for (auto v : c) tri.push_back({inst.points[v][0], inst.points[v][1]});
      out[region] += abs(twice_area(tri));
    }
  }
  return out;
}
/// |group| · area(pieces) = area(object), per region, exactly.
void expect_areas_add_up(const Structure& x, const gen::CutResult& r) {
  const auto whole = object_areas(x);
  const auto cut = piece_areas(r);
  ASSERT_EQ(whole.size(), cut.size());
  for (const auto& [region, a] : whole)
    EXPECT_TRUE(cut.at(region) * Cyclotomic(int(r.group.size())) == a) << "region " << region;
}

gen::CutPoint pt(int x, int y) {
  return {Cyclotomic(x), Cyclotomic(y)};
}

std::string polygon_doc(const std::string& templates) {
  return R"({"symmesh": "templated-structure/1", "dimension": 2, "templates": [)" + templates +
         "]}";
}
const std::string identity_instance = R"("instances": [{"transformation": {"identity": {}}}])";

TEST(SymmetryCut, Algorithm63CutsTheNgonThroughEdgeMidpoints) {
  const auto x = example("ngon-8");
  const auto r = gen::cut_to_fundamental_piece(x, {8, {}, {}});
  ASSERT_EQ(r.pieces.size(), 1u);
  EXPECT_EQ(r.group.size(), 8u);
  EXPECT_EQ(r.start_kind, "foot");
  EXPECT_NEAR(r.start_angle_deg, 22.5, 1e-9);
  EXPECT_NEAR(r.smallest_new_angle_deg, 90, 1e-9);
  // Through a vertex (the x-axis), the 135° corner is halved.
  EXPECT_NEAR(r.smallest_new_angle_at_x_axis_deg, 67.5, 1e-9);
  // Centre, edge midpoint, vertex, edge midpoint.
  EXPECT_EQ(r.pieces[0].outer.size(), 4u);
  expect_areas_add_up(x, r);
}

TEST(SymmetryCut, GivenFirstRayIsKept) {
  const auto x = example("ngon-8");
  const auto r = gen::cut_to_fundamental_piece(x, {8, {}, pt(1, 0)});
  EXPECT_EQ(r.start_kind, "given");
  EXPECT_NEAR(r.smallest_new_angle_deg, 67.5, 1e-9);
  ASSERT_EQ(r.pieces.size(), 1u);
  EXPECT_EQ(r.pieces[0].outer.size(), 3u); // the slice triangle
  expect_areas_add_up(x, r);
}

TEST(SymmetryCut, Algorithm63AvoidsTheGearFlank) {
  const auto x = example("gear");
  const auto r = gen::cut_to_fundamental_piece(x, {12, {}, {}});
  EXPECT_NEAR(r.start_angle_deg, 7.5, 1e-9); // the middle of a tooth
  EXPECT_NEAR(r.smallest_new_angle_deg, 90, 1e-9);
  EXPECT_LT(r.smallest_new_angle_at_x_axis_deg, 31); // the x-axis crosses a flank
  EXPECT_GT(r.smallest_new_angle_at_x_axis_deg, 30);
  ASSERT_EQ(r.pieces.size(), 1u);
  EXPECT_TRUE(r.pieces[0].holes.empty()); // the bore is cut open
  expect_areas_add_up(x, r);
}

TEST(SymmetryCut, HolesInsideTheSliceStayHoles) {
  // [-2, 2]^2 with a square hole of side 1/2 around (±1, ±1): each quarter keeps one hole.
  std::string holes;
  for (const auto& [sx, sy] :
       std::vector<std::pair<int, int>>{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) {
    const auto c = [](int s, const char* d) { return std::string(s > 0 ? "" : "-") + d; };
    holes += std::string(holes.empty() ? "" : ", ") + "[[\"" + c(sx, "3/4") + "\", \"" +
             c(sy, "3/4") + "\"], [\"" + c(sx, "5/4") + "\", \"" + c(sy, "3/4") + "\"], [\"" +
             c(sx, "5/4") + "\", \"" + c(sy, "5/4") + "\"], [\"" + c(sx, "3/4") + "\", \"" +
             c(sy, "5/4") + "\"]]";
  }
  const auto x = parse(polygon_doc(
      R"({"kind": "geometry", "polygon": [["-2", "-2"], ["2", "-2"], ["2", "2"], ["-2", "2"]],
      "holes": [)" +
      holes + "], " + identity_instance + "}"));
  const auto r = gen::cut_to_fundamental_piece(x, {4, {}, pt(1, 0)});
  ASSERT_EQ(r.pieces.size(), 1u);
  ASSERT_EQ(r.pieces[0].holes.size(), 1u);
  EXPECT_EQ(r.pieces[0].holes[0].size(), 4u);
  EXPECT_LT(twice_area(r.pieces[0].holes[0]).sign(), 0); // clockwise
  expect_areas_add_up(x, r);
}

TEST(SymmetryCut, OneMirrorHalvesEveryRegionOfTheMosfet) {
  const auto x = example("mosfet"); // its AT is the whole device
  const auto r = gen::cut_to_fundamental_piece(x, {0, {pt(1, 0)}, {}});
  EXPECT_EQ(r.group.size(), 2u);
  EXPECT_EQ(r.pieces.size(), 4u);
  EXPECT_EQ(piece_areas(r).size(), 4u);
  expect_areas_add_up(x, r);
  EXPECT_TRUE(r.field == nullptr); // rational in, rational out
}

TEST(SymmetryCut, TwoOrthogonalMirrorsGiveTheQuadrant) {
  const auto x = parse(polygon_doc(
      R"({"kind": "geometry", "polygon": [["-2", "-1"], ["2", "-1"], ["2", "1"], ["-2", "1"]], )" +
      identity_instance + "}"));
  const auto r = gen::cut_to_fundamental_piece(x, {0, {pt(1, 0), pt(0, 1)}, {}});
  EXPECT_EQ(r.group.size(), 4u);
  ASSERT_EQ(r.pieces.size(), 1u);
  const std::vector<gen::CutPoint> quadrant{pt(0, 0), pt(2, 0), pt(2, 1), pt(0, 1)};
  ASSERT_EQ(r.pieces[0].outer.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    for (int d = 0; d < 2; ++d) EXPECT_TRUE(r.pieces[0].outer[i][d] == quadrant[i][d]) << i;
  EXPECT_THROW(gen::cut_to_fundamental_piece(x, {0, {pt(1, 0), pt(1, 1)}, {}}), gen::CutError);
}

TEST(SymmetryCut, MirrorAndRotationGiveTheHalfSliceOfAlgorithm65) {
  const auto x = example("star");
  const auto r = gen::cut_to_fundamental_piece(x, {5, {pt(0, 1)}, {}});
  EXPECT_EQ(r.group.size(), 10u);
  ASSERT_EQ(r.pieces.size(), 1u);
  EXPECT_EQ(r.pieces[0].outer.size(), 3u); // centre, tip, inner vertex
  expect_areas_add_up(x, r);
}

TEST(SymmetryCut, CarriersWithTJunctionsAreOneRegion) {
  // [-1, 0] x [-1, 1] next to two unit squares: (0, 0) is a T-junction of the carriers.
  const auto rect = [](const char* x0, const char* y0, const char* x1, const char* y1) {
    return std::string(R"({"kind": "geometry", "polygon": [[")") + x0 + "\", \"" + y0 + "\"], [\"" +
           x1 + "\", \"" + y0 + "\"], [\"" + x1 + "\", \"" + y1 + "\"], [\"" + x0 + "\", \"" + y1 +
           "\"]], " + identity_instance + "}";
  };
  const auto x = parse(polygon_doc(rect("-1", "-1", "0", "1") + ", " + rect("0", "-1", "1", "0") +
                                   ", " + rect("0", "0", "1", "1")));
  const auto r = gen::cut_to_fundamental_piece(x, {4, {}, pt(1, 0)});
  ASSERT_EQ(r.pieces.size(), 1u);
  EXPECT_EQ(r.pieces[0].outer.size(), 4u);
  expect_areas_add_up(x, r);
}

TEST(SymmetryCut, HalfTurnAndThirdTurn) {
  // n = 2: the slice is a half-plane; n = 3 on an equilateral triangle about the origin (K_12).
  const auto rect = parse(polygon_doc(
      R"({"kind": "geometry", "polygon": [["-2", "-1"], ["2", "-1"], ["2", "1"], ["-2", "1"]], )" +
      identity_instance + "}"));
  const auto r2 = gen::cut_to_fundamental_piece(rect, {2, {}, {}});
  EXPECT_EQ(r2.group.size(), 2u);
  ASSERT_EQ(r2.pieces.size(), 1u);
  expect_areas_add_up(rect, r2);
  const auto tri = parse(polygon_doc(
      R"J({"kind": "geometry", "polygon": [["cos(2pi*3/12)", "sin(2pi*3/12)"],
      ["cos(2pi*7/12)", "sin(2pi*7/12)"], ["cos(2pi*11/12)", "sin(2pi*11/12)"]], )J" +
      identity_instance + "}"));
  const auto r3 = gen::cut_to_fundamental_piece(tri, {3, {}, {}});
  EXPECT_EQ(r3.group.size(), 3u);
  ASSERT_EQ(r3.pieces.size(), 1u);
  EXPECT_NEAR(r3.smallest_new_angle_deg, 90, 1e-9); // through the middle of a side
  expect_areas_add_up(tri, r3);
}

TEST(SymmetryCut, InputFieldIsEmbeddedIntoTheCutsField) {
  // The octagon is read in K_8; Algorithm 6.5 with order 8 needs rot(pi/8), i.e. K_16, so every
  // coordinate is carried over from K_8 into K_16.
  const auto x = example("ngon-8");
  const auto r = gen::cut_to_fundamental_piece(x, {8, {pt(0, 1)}, {}});
  ASSERT_TRUE(r.field != nullptr);
  EXPECT_EQ(r.field->m(), 16);
  EXPECT_EQ(r.group.size(), 16u);
  ASSERT_EQ(r.pieces.size(), 1u);
  EXPECT_EQ(r.pieces[0].outer.size(), 3u); // centre, vertex, edge midpoint
  // The object's area is in K_8 and the piece's in K_16 (no mixed arithmetic): compared as
  // certified intervals, which for these small numbers are a few ulps wide.
  const auto whole = object_areas(x).at(1).to_interval();
  const auto cut = (piece_areas(r).at(1) * Cyclotomic(16)).to_interval();
  EXPECT_NEAR(cut.first, whole.first, 1e-12);
  EXPECT_NEAR(cut.second, whole.second, 1e-12);
}

TEST(SymmetryCut, ObjectWithoutTheSymmetryIsRefused) {
  const auto x = example("star");
  try {
    gen::cut_to_fundamental_piece(x, {4, {}, {}});
    FAIL() << "a star has no rotational symmetry of order 4";
  } catch (const gen::CutError& e) {
    EXPECT_NE(std::string(e.what()).find("region 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(gen::cut_to_fundamental_piece(x, {0, {pt(1, 1)}, {}}), gen::CutError);
  EXPECT_THROW(gen::cut_to_fundamental_piece(x, {1, {}, {}}), gen::CutError);
  EXPECT_THROW(gen::cut_to_fundamental_piece(x, {0, {}, {}}), gen::CutError);
  EXPECT_THROW(gen::cut_to_fundamental_piece(x, {5, {}, pt(0, 0)}), gen::CutError);
  EXPECT_THROW(gen::cut_to_fundamental_piece(x, {999983, {}, {}}), gen::CutError);
}

TEST(SymmetryCut, SmallestNewAngleOfOneEdge) {
  // The edge x = 1, the object on its left (x < 1).
  const std::vector<std::array<double, 4>> edge{{1, -1, 1, 1}};
  EXPECT_NEAR(gen::smallest_new_angle_deg(edge, 0), 90, 1e-12);
  EXPECT_NEAR(gen::smallest_new_angle_deg(edge, M_PI / 8), 67.5, 1e-9);
  EXPECT_NEAR(gen::smallest_new_angle_deg(edge, M_PI), 90, 1e-12); // the ray misses the edge
  // Through the edge's first vertex (1, -1): from the edge (up) counter-clockwise to the ray's
  // line (at -45°, i.e. 135°) is 45°.
  EXPECT_NEAR(gen::smallest_new_angle_deg(edge, -M_PI / 4), 45, 1e-9);
}

} // namespace
