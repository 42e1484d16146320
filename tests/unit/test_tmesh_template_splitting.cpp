// Section 5.2.1 template splitting on a generated templated mesh (.tmesh) —
// spec/adaptation.md#tmesh-cloning: the preconditions of split_template and split_where, and the
// edge cases a random property rarely reaches (a template without instances, an invalid mesh).
// The property that splitting keeps AT is Section_5_2_1.tmesh_split_keeps_the_structure_instance.
#include <gtest/gtest.h>

#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/adapt/tmesh_template_cloning.h"

#include <sstream>
#include <stdexcept>
#include <string>

using namespace symmesh;

namespace {

/// The unit square as two triangles: cell 0 = (0,0) (1,0) (1,1), centroid x = 2/3; cell 1 =
/// (0,0) (1,1) (0,1), centroid x = 1/3. The cut between them is the diagonal, vertices 0 and 2.
mesh::MeshTemplate unit_square(std::size_t instances) {
  mesh::MeshTemplate t;
  t.mesh.point_dimension = 2;
  for (const double p : {0., 0., 1., 0., 1., 1., 0., 1.}) t.mesh.vertex_coords.push_back(p);
  const mesh::IndexType a[] = {0, 1, 2}, b[] = {0, 2, 3};
  t.mesh.add_cell(mesh::ElementType::triangle, a);
  t.mesh.add_cell(mesh::ElementType::triangle, b);
  for (std::size_t k = 0; k < instances; ++k) {
    t.transformation_indices.push_back(mesh::IndexType(k));
    t.region_ids.push_back(1);
  }
  return t;
}

/// Template 0 instanced twice (translations by 0 and by (1, 0), identified along x = 1 by one
/// table), and, with `spare`, template 1 = the same square without instances.
mesh::TemplatedMeshCompactSvb two_squares(bool spare) {
  mesh::TemplatedMeshCompactSvb t;
  t.templated.point_dimension = 2;
  t.templated.templates.push_back(unit_square(2));
  if (spare) t.templated.templates.push_back(unit_square(0));
  for (const double dx : {0., 1.}) t.templated.transformations.push_back({{1, 0, 0, 1}, {dx, 0}});
  // Instance 0's right side (vertices 1, 2) is instance 1's left side (vertices 0, 3).
  t.tables.push_back({0, 0, {{1, 0}, {2, 3}}});
  t.identifications.push_back({0, 1, 0});
  return t;
}

TEST(TmeshTemplateSplitting, IdentifiesEachInstancesTwoPartsAlongTheCut) {
  auto t = two_squares(false);
  ASSERT_TRUE(t.is_valid());
  EXPECT_EQ(adapt::split_template(t, 0, {1}), 1u);
  std::ostringstream why;
  EXPECT_TRUE(t.is_valid(&why)) << why.str();
  ASSERT_EQ(t.templated.templates.size(), 2u);
  EXPECT_EQ(t.templated.templates[0].mesh.cell_count(), 1u);
  EXPECT_EQ(t.templated.templates[1].mesh.cell_count(), 1u);
  EXPECT_EQ(t.templated.instance_count(), 4u);
  // The cut table (new part -> old part, the diagonal) is used once per instance of template 0.
  std::size_t cut_uses = 0;
  for (const auto& id : t.identifications) {
    const auto& table = t.tables[std::size_t(id.table)];
    if (table.from_template == 1 && table.to_template == 0 && table.pairs.size() == 2) ++cut_uses;
  }
  EXPECT_EQ(cut_uses, 2u);
}

TEST(TmeshTemplateSplitting, TemplateWithoutInstancesGetsNoCutTable) {
  auto t = two_squares(true);
  ASSERT_TRUE(t.is_valid());
  const auto tables = t.tables.size();
  const auto identifications = t.identifications.size();
  EXPECT_EQ(adapt::split_template(t, 1, {0}), 2u);
  EXPECT_TRUE(t.is_valid());
  EXPECT_EQ(t.tables.size(), tables);
  EXPECT_EQ(t.identifications.size(), identifications);
  EXPECT_EQ(t.templated.templates[2].instance_count(), 0u);
  EXPECT_EQ(t.templated.instance_count(), 2u);
}

TEST(TmeshTemplateSplitting, RefusesAPartThatIsNotANonEmptyProperSubset) {
  for (const auto& part : {std::vector<std::size_t>{}, std::vector<std::size_t>{0, 1},
                           std::vector<std::size_t>{1, 1, 0}, std::vector<std::size_t>{2}}) {
    auto t = two_squares(false);
    const auto before = t.tables.size();
    EXPECT_THROW(adapt::split_template(t, 0, part), std::invalid_argument);
    EXPECT_EQ(t.templated.templates.size(), 1u);
    EXPECT_EQ(t.tables.size(), before);
  }
  auto t = two_squares(false);
  EXPECT_THROW(adapt::split_template(t, 1, {0}), std::invalid_argument);
}

TEST(TmeshTemplateSplitting, SplitWhereTakesTheCellsThatSatisfyThePredicate) {
  auto t = two_squares(false);
  const auto splits = adapt::split_where(t, adapt::parse_template_cell_predicate("x < 0.5"));
  ASSERT_EQ(splits.size(), 1u);
  EXPECT_EQ(splits[0].template_index, 0u);
  EXPECT_EQ(splits[0].new_template, 1u);
  EXPECT_EQ(splits[0].cells, 1u);
  // The cell with centroid x = 1/3 moved: the new template holds (0,0) (1,1) (0,1).
  const auto& moved = t.templated.templates[1].mesh;
  ASSERT_EQ(moved.vertex_count(), 3u);
  EXPECT_EQ(moved.vertex(std::size_t(moved.cell(0)[2]))[1], 1.0);
  // A predicate that every cell or no cell satisfies splits nothing.
  auto u = two_squares(false);
  EXPECT_TRUE(adapt::split_where(u, adapt::parse_template_cell_predicate("x < 2")).empty());
  EXPECT_TRUE(adapt::split_where(u, adapt::parse_template_cell_predicate("x > 2")).empty());
  EXPECT_EQ(u.templated.templates.size(), 1u);
}

TEST(TmeshTemplateSplitting, SplitWhereRefusesAnInvalidMeshBeforeReadingIt) {
  auto t = two_squares(false);
  t.templated.templates[0].mesh.cell_vertex_indices[4] = 99; // cell 1 names no vertex 99
  try {
    adapt::split_where(t, adapt::parse_template_cell_predicate("x < 0.5"));
    FAIL() << "an invalid mesh was split";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not valid"), std::string::npos) << e.what();
  }
  EXPECT_EQ(t.templated.templates.size(), 1u);
}

TEST(TmeshTemplateSplitting, SplitWherePredicateRefusesInstanceNames) {
  EXPECT_THROW(adapt::parse_template_cell_predicate("region == 1"), std::invalid_argument);
  EXPECT_THROW(adapt::parse_template_cell_predicate("instance < 3"), std::invalid_argument);
  EXPECT_NO_THROW(adapt::parse_template_cell_predicate("template == 0 and y >= 0.25"));
}

} // namespace
