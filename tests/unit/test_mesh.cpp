// The mesh data structures (spec/mesh-data-structures.md): byte counts from the arrays against
// Eq. 2.11/2.12, and the compact SVB against Listing 4.2 and the structure instance.
#include <gtest/gtest.h>

#include "symmesh/gen/templated_triangle_mesh.h"
#include "symmesh/io/templated_mesh_file.h"
#include "symmesh/io/templated_structure_json.h"
#include "symmesh/mesh/quality.h"
#include "symmesh/mesh/templated_mesh.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <variant>

using namespace symmesh;

namespace {
mesh::Mesh unit_square() {
  mesh::Mesh m;
  const double p[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& q : p) m.add_vertex(q);
  const mesh::IndexType a[3] = {0, 1, 2}, b[3] = {0, 2, 3};
  m.add_cell(mesh::ElementType::triangle, a);
  m.add_cell(mesh::ElementType::triangle, b);
  return m;
}
} // namespace

TEST(MeshBytes, MeshMatchesEq211AndMrMeshNeedsTheSwappedConstant) {
  const mesh::Mesh m = unit_square();
  ASSERT_TRUE(m.is_valid());
  // 8n per vertex; per cell 1 type byte + 3 indices + 1 offset; plus the leading offset.
  EXPECT_EQ(m.bytes(), 4u * 8 * 2 + 2u * (1 + 12 + 4) + 4);
  EXPECT_LE(m.bytes(), mesh::eq_2_11_bound(4, 2, 2, 3));
  mesh::MrMesh mr{m, {1, 1}};
  ASSERT_TRUE(mr.is_valid());
  EXPECT_EQ(mr.bytes(), 4u * 8 * 2 + 2u * (7 + 4 * 3) + 4);
  // Eq. 2.12 as printed (5 + 4k) is below the MRMESH bytes: its 5 and Eq. 2.11's 7 are swapped.
  EXPECT_GT(mr.bytes(), mesh::eq_2_12_bound(4, 2, 2, 3));
  EXPECT_LE(mr.bytes(), mesh::eq_2_11_bound(4, 2, 2, 3) + 4);
}

TEST(MeshBytes, InvalidOffsetsAreReported) {
  mesh::Mesh m = unit_square();
  m.cell_vertex_index_offsets[1] = 2;
  std::ostringstream why;
  EXPECT_FALSE(m.is_valid(&why));
  EXPECT_NE(why.str().find("vertex count"), std::string::npos);
}

TEST(CompactSvb, OctagonSlicesAgreeWithListing42AndTheStructureInstance) {
  const auto x = std::get<io::CyclotomicStructure2>(
      io::read_templated_structure(std::string(SYMMESH_SOURCE_DIR) + "/data/ngon_slice_8.json"));
  gen::GenerationOptions o;
  o.size = 0.1;
  o.min_angle_deg = 25;
  const auto r = gen::generate_triangle_mesh(x, gen::Method::bpp, o);
  ASSERT_TRUE(r.lemma_4_2_holds) << r.lemma_4_2_failure;
  std::ostringstream why;
  ASSERT_TRUE(r.templated.is_valid(&why)) << why.str();
  // The 8 slice-to-slice pairs suffice; the 20 pairs meeting only at the centre are implied.
  EXPECT_EQ(r.templated.identifications.size(), 8u);
  const auto& t = r.templated.templated.templates.at(0);
  const auto si = mesh::assemble_structure_instance(r.templated);
  const auto svb = mesh::to_listing_4_2(r.templated);
  ASSERT_TRUE(svb.is_valid(&why)) << why.str();
  EXPECT_EQ(si.mesh.mesh.cell_count(), 8 * t.mesh.cell_count());
  // Each side of the slice has s interior line points plus its outer corner; the centre is one.
  std::size_t shared = 0;
  for (const auto& inst : svb.templates[0].instances)
    shared += inst.local_to_global_vertex_mapping.size();
  const std::size_t per_instance = shared / 8;
  EXPECT_EQ(shared % 8, 0u);
  // 8 sides shared by two slices each (interior points + outer corner), plus the centre.
  EXPECT_EQ(svb.global_vertex_count(), 8 * (per_instance - 1) / 2 + 1);
  EXPECT_EQ(si.mesh.mesh.vertex_count(),
            8 * t.mesh.vertex_count() - 8 * (per_instance - 1) / 2 - 7);
  // Compact: far below Listing 4.2's pairs for the same identifications.
  EXPECT_LT(r.templated.bytes(), svb.bytes());
}

TEST(Quality, RightIsoscelesTrianglesHave45DegreesAndRatioOneOverRootTwo) {
  const auto q = mesh::triangle_quality(unit_square(), 50);
  EXPECT_EQ(q.triangles, 2u);
  EXPECT_NEAR(q.min_angle_deg, 45, 1e-12);
  // R = hypotenuse/2 = sqrt(2)/2, shortest edge 1.
  EXPECT_NEAR(q.max_radius_edge_ratio, std::sqrt(2.0) / 2, 1e-12);
  EXPECT_EQ(q.histogram[9], 2u); // [45, 50)
  EXPECT_EQ(q.below_bound, 2u);
  EXPECT_EQ(mesh::triangle_quality(unit_square(), 45).below_bound, 0u);
}

TEST(TemplatedMeshFile, RoundTripIsExactAndBadFilesNameTheField) {
  const auto x = std::get<io::Structure2>(io::read_templated_structure(
      std::string(SYMMESH_SOURCE_DIR) + "/data/fig_6_7_rotational_slice.json"));
  gen::GenerationOptions o;
  o.size = 0.3;
  const auto r = gen::generate_triangle_mesh(x, gen::Method::bpp, o);
  const std::string path = testing::TempDir() + "/round_trip.tmesh";
  io::write_tmesh(r.templated, path);
  const auto back = io::read_tmesh(path);
  const auto& a = r.templated.templated.templates.at(0).mesh;
  const auto& b = back.templated.templates.at(0).mesh;
  EXPECT_EQ(a.vertex_coords, b.vertex_coords); // bit-identical doubles
  EXPECT_EQ(a.cell_vertex_indices, b.cell_vertex_indices);
  EXPECT_EQ(back.identifications.size(), r.templated.identifications.size());
  EXPECT_EQ(back.bytes(), r.templated.bytes());
  EXPECT_EQ(back.templated.transformations.at(1).matrix,
            r.templated.templated.transformations.at(1).matrix);
  // A cell index out of range is refused with the field's path.
  std::ifstream is(path);
  std::string text((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
  const auto at = text.find("\"cells\":[[");
  ASSERT_NE(at, std::string::npos);
  text.replace(at + 10, 1, "999999");
  const std::string bad = testing::TempDir() + "/bad.tmesh";
  std::ofstream(bad) << text;
  try {
    io::read_tmesh(bad);
    ADD_FAILURE() << "accepted an out-of-range cell index";
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("templates[0].cells[0]"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
  std::remove(bad.c_str());
}

TEST(Quality, RegularAndCornerTetrahedraHaveTheirKnownDihedralAnglesAndRatios) {
  mesh::Mesh m;
  m.point_dimension = 3;
  // Regular: every dihedral angle arccos(1/3), R/l = sqrt(6)/4.
  const double r[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (const auto& p : r) m.add_vertex(p);
  const mesh::IndexType a[4] = {0, 1, 2, 3};
  m.add_cell(mesh::ElementType::tetrahedron, a);
  auto q = mesh::tetrahedron_quality(m, 60);
  const double regular = std::acos(1.0 / 3) * 180 / M_PI;
  EXPECT_NEAR(q.min_dihedral_deg, regular, 1e-9);
  EXPECT_NEAR(q.max_dihedral_deg, regular, 1e-9);
  EXPECT_NEAR(q.max_radius_edge_ratio, std::sqrt(6.0) / 4, 1e-12);
  EXPECT_EQ(q.histogram[14], 1u); // [70, 75)
  EXPECT_EQ(q.below_bound, 0u);
  // The corner tetrahedron: 90° at the three axis edges, arccos(1/sqrt 3) at the others; its
  // circumcentre is (1/2, 1/2, 1/2), so R/l = (sqrt 3 / 2) / 1.
  mesh::Mesh c;
  c.point_dimension = 3;
  const double k[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& p : k) c.add_vertex(p);
  c.add_cell(mesh::ElementType::tetrahedron, a);
  q = mesh::tetrahedron_quality(c, 60);
  EXPECT_NEAR(q.max_dihedral_deg, 90, 1e-9);
  EXPECT_NEAR(q.min_dihedral_deg, std::acos(1 / std::sqrt(3.0)) * 180 / M_PI, 1e-9);
  EXPECT_NEAR(q.max_radius_edge_ratio, std::sqrt(3.0) / 2, 1e-12);
  EXPECT_EQ(q.below_bound, 1u);
  // A templated mesh of the corner tetrahedron instanced 3 times counts it 3 times.
  mesh::TemplatedMesh t;
  t.point_dimension = 3;
  t.templates.push_back({c, {0, 0, 0}, {1, 1, 1}});
  t.transformations.push_back({{1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}});
  const auto tq = mesh::tetrahedron_quality(t, 60);
  EXPECT_EQ(tq.tetrahedra, 3u);
  EXPECT_EQ(tq.below_bound, 3u);
  EXPECT_NEAR(tq.min_dihedral_deg, q.min_dihedral_deg, 0);
}
