// The outlier repair after TetGen (spec/generation.md#outlier-repair): a flip that helps is
// made unless its facet is an input triangle, a point TetGen added moves or is taken out (its
// star tetrahedralized anew, within the volume bound) and a surface point never is, and on
// generated templated meshes the repair only improves the worst measures and keeps the mesh
// certified and conforming.
#include <gtest/gtest.h>

#include "symmesh/gen/outlier_repair.h"
#include "symmesh/gen/templated_tetrahedral_mesh.h"
#include "symmesh/io/examples.h"
#include "symmesh/io/templated_structure_json.h"
#include "symmesh/mesh/quality.h"
#include "symmesh/mesh/templated_mesh.h"
#include "at_summary.h"

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

using namespace symmesh;
using gen::SurfaceInput;
using gen::TetrahedralMeshOutput;

namespace {

double signed_volume(const TetrahedralMeshOutput& m, const std::array<std::size_t, 4>& c) {
  return test::signed_volume(m.points[c[0]].data(), m.points[c[1]].data(), m.points[c[2]].data(),
                             m.points[c[3]].data());
}

/// Puts a hand-made tetrahedron in positive order, as TetGen's output is.
std::array<std::size_t, 4> positive(const TetrahedralMeshOutput& m, std::array<std::size_t, 4> c) {
  if (signed_volume(m, c) < 0) std::swap(c[2], c[3]);
  return c;
}

/// Two tetrahedra abcd (flat: d is 0.1 above triangle abc) and abce (e is 1 below it), and the
/// bipyramid's six hull triangles; with `facet`, abc is an input triangle too (a facet inside
/// the domain, as a region interface or a template's kept surface is).
void bipyramid(SurfaceInput& s, TetrahedralMeshOutput& m, bool facet) {
  const double h = std::sqrt(3.0) / 2;
  s.points = {{1, 0, 0}, {-0.5, h, 0}, {-0.5, -h, 0}, {0, 0, 0.1}, {0, 0, -1}};
  s.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {0, 1, 4}, {1, 2, 4}, {2, 0, 4}};
  if (facet) s.triangles.push_back({0, 1, 2});
  m.points = s.points;
  m.tetrahedra = {positive(m, {0, 1, 2, 3}), positive(m, {0, 1, 2, 4})};
  m.region = {0, 0};
}

TEST(OutlierRepair, FlipsAFlatPairIntoThreeGoodTetrahedra) {
  SurfaceInput s;
  TetrahedralMeshOutput m;
  bipyramid(s, m, false);
  const double volume = signed_volume(m, m.tetrahedra[0]) + signed_volume(m, m.tetrahedra[1]);
  const auto r = gen::repair_outliers(s, m, gen::OutlierBounds{});
  EXPECT_EQ(r.outliers_before, 1u); // abcd: radius-edge 5.0, smallest dihedral 11.3 degrees
  EXPECT_EQ(r.outliers_after, 0u);
  EXPECT_EQ(r.flips, 1u);
  ASSERT_EQ(m.tetrahedra.size(), 3u);
  double after = 0;
  for (const auto& c : m.tetrahedra) {
    EXPECT_GT(signed_volume(m, c), 0);
    after += signed_volume(m, c);
    const auto q = mesh::tetrahedron_shape(m.points[c[0]].data(), m.points[c[1]].data(),
                                           m.points[c[2]].data(), m.points[c[3]].data());
    EXPECT_LT(q.radius_edge_ratio, 1.414);
    EXPECT_GT(q.min_dihedral_deg, 10);
  }
  EXPECT_NEAR(after, volume, 1e-12);
  EXPECT_FALSE(gen::boundary_mismatch(s, m).has_value());
  EXPECT_EQ(m.region, std::vector<int>(3, 0));
}

// The dropped hypothesis: the same flip across an input triangle would remove it from the mesh,
// so the repair must leave the pair as it is.
TEST(OutlierRepair, NeverFlipsAnInputTriangle) {
  SurfaceInput s;
  TetrahedralMeshOutput m;
  bipyramid(s, m, true);
  const auto before = m.tetrahedra;
  const auto r = gen::repair_outliers(s, m, gen::OutlierBounds{});
  EXPECT_EQ(r.outliers_before, 1u);
  EXPECT_EQ(r.outliers_after, 1u);
  EXPECT_EQ(r.flips + r.moves, 0u);
  EXPECT_EQ(m.tetrahedra, before);
  EXPECT_FALSE(gen::boundary_mismatch(s, m).has_value());
}

/// The unit cube's corners and 12 hull triangles, and a point TetGen would have added at
/// (0.5, 0.5, 0.02), joined to every hull triangle: the two cells on the bottom face are flat.
void cube_with_low_centre(SurfaceInput& s, TetrahedralMeshOutput& m) {
  for (int k = 0; k < 8; ++k)
    s.points.push_back({double(k & 1), double(k >> 1 & 1), double(k >> 2)});
  const std::size_t quads[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  m.points = s.points;
  m.points.push_back({0.5, 0.5, 0.02});
  for (const auto& t : s.triangles) {
    m.tetrahedra.push_back(positive(m, {t[0], t[1], t[2], 8}));
    m.region.push_back(0);
  }
}

/// The cells tile the unit cube: positive, volume 1, the surface kept.
void expect_cube_tiled(const SurfaceInput& s, const TetrahedralMeshOutput& m) {
  double volume = 0;
  for (const auto& c : m.tetrahedra) {
    EXPECT_GT(signed_volume(m, c), 0);
    volume += signed_volume(m, c);
  }
  EXPECT_NEAR(volume, 1, 1e-12);
  EXPECT_FALSE(gen::boundary_mismatch(s, m).has_value());
}

TEST(OutlierRepair, RemovesAnAddedPointWhoseStarHasABetterTetrahedralization) {
  SurfaceInput s;
  TetrahedralMeshOutput m;
  cube_with_low_centre(s, m);
  const auto r = gen::repair_outliers(s, m, gen::OutlierBounds{});
  EXPECT_EQ(r.removals, 1u);
  EXPECT_EQ(r.outliers_after, 0u);
  ASSERT_EQ(m.points.size(), 8u); // the point taken out is gone, the surface points stay
  for (std::size_t v = 0; v < 8; ++v) EXPECT_EQ(m.points[v], s.points[v]);
  EXPECT_LE(m.tetrahedra.size(), 6u); // the cube on its corners: five or six cells
  expect_cube_tiled(s, m);
}

TEST(OutlierRepair, NeverRemovesASurfacePoint) {
  // Dropped hypothesis: the low centre is an input point (as a template's surface point is).
  SurfaceInput s;
  TetrahedralMeshOutput m;
  cube_with_low_centre(s, m);
  s.points.push_back(m.points[8]);
  const auto r = gen::repair_outliers(s, m, gen::OutlierBounds{});
  EXPECT_EQ(r.removals + r.moves, 0u);
  ASSERT_EQ(m.points.size(), 9u);
  EXPECT_EQ(m.points[8], s.points[8]);
}

TEST(OutlierRepair, MovesAnAddedPointButNeverASurfacePoint) {
  // A volume bound below the cube's cells on its corners (at least 1/6) rules the removal out.
  SurfaceInput s;
  TetrahedralMeshOutput m;
  cube_with_low_centre(s, m);
  gen::OutlierBounds bounds;
  bounds.max_volume = 0.15;
  const auto r = gen::repair_outliers(s, m, bounds);
  EXPECT_EQ(r.removals, 0u);
  EXPECT_GE(r.outliers_before, 2u);
  EXPECT_LT(r.outliers_after, r.outliers_before);
  EXPECT_GE(r.moves, 1u);
  ASSERT_EQ(m.points.size(), 9u);
  for (std::size_t v = 0; v < 8; ++v) EXPECT_EQ(m.points[v], s.points[v]);
  EXPECT_GT(m.points[8][2], 0.02);
  expect_cube_tiled(s, m);
}

TEST(OutlierRepair, RefusesBadBoundsAndAForeignMesh) {
  SurfaceInput s;
  TetrahedralMeshOutput m;
  bipyramid(s, m, false);
  gen::OutlierBounds b;
  b.radius_edge = 0.5;
  EXPECT_THROW(gen::repair_outliers(s, m, b), std::invalid_argument);
  b = gen::OutlierBounds{};
  b.max_volume = 0;
  EXPECT_THROW(gen::repair_outliers(s, m, b), std::invalid_argument);
  m.region.pop_back();
  EXPECT_THROW(gen::repair_outliers(s, m, gen::OutlierBounds{}), std::invalid_argument);
}

/// The repair only makes the worst measures better, and the result is still a certified templated
/// mesh whose structure instance (assembled from the SVB) is conforming, positive and has the
/// same volume and boundary area: the templates' surfaces are TetGen's (the certificate alone
/// would not show it, it checks the exact surface meshes).
template <class Structure>
void only_gets_better(const Structure& x, double size, const char* name) {
  gen::GenerationOptions o;
  o.size = size;
  o.repair_outliers = false;
  const auto plain = gen::generate_tetrahedral_mesh(x, gen::Method::automatic, o);
  o.repair_outliers = true;
  const auto repaired = gen::generate_tetrahedral_mesh(x, gen::Method::automatic, o);
  ASSERT_TRUE(repaired.lemma_4_2_holds) << name << ": " << repaired.lemma_4_2_failure;
  std::ostringstream why;
  EXPECT_TRUE(repaired.templated.is_valid(&why)) << name << ": " << why.str();
  EXPECT_GT(repaired.outliers_before, 0u) << name;
  EXPECT_LT(repaired.outliers_after, repaired.outliers_before) << name;
  EXPECT_GT(repaired.repair_flips + repaired.repair_moves, 0u) << name;
  const auto q0 = mesh::tetrahedron_quality(plain.templated.templated, 10);
  const auto q1 = mesh::tetrahedron_quality(repaired.templated.templated, 10);
  EXPECT_GE(q1.min_dihedral_deg, q0.min_dihedral_deg) << name;
  EXPECT_LE(q1.max_radius_edge_ratio, q0.max_radius_edge_ratio) << name;
  EXPECT_LT(q1.below_bound, q0.below_bound) << name;
  const auto& t0 = plain.templated.templated.templates;
  const auto& t1 = repaired.templated.templated.templates;
  ASSERT_EQ(t0.size(), t1.size());
  for (std::size_t i = 0; i < t0.size(); ++i)
    EXPECT_EQ(t0[i].mesh.vertex_count(), t1[i].mesh.vertex_count()) << name; // none added
  EXPECT_EQ(plain.templated.tables.size(), repaired.templated.tables.size());
  const auto a0 = test::summarise(plain.templated), a1 = test::summarise(repaired.templated);
  EXPECT_EQ(a1.non_positive, 0u) << name;
  EXPECT_EQ(a1.faces_in_more_than_two, 0u) << name;
  EXPECT_NEAR(a1.volume, a0.volume, 1e-9 * a0.volume) << name;
  // A lost or added surface triangle, or an interface that no longer meets, changes the area.
  EXPECT_NEAR(a1.boundary_area, a0.boundary_area, 1e-9 * a0.boundary_area) << name;
}

TEST(OutlierRepair, GeneratedMeshesOnlyGetBetter) {
  only_gets_better(std::get<io::CyclotomicStructure3>(
                       io::parse_templated_structure(io::example_document("tsv-8").dump())),
                   0.1, "tsv-8");
  only_gets_better(std::get<io::Structure3>(
                       io::parse_templated_structure(io::example_document("finfet").dump())),
                   0.15, "finfet");
}

} // namespace
