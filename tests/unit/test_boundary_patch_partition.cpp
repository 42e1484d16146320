// Unit tests of Algorithm 4.1, Definitions 4.7–4.9 and Section 5.2.2 on small hand-made
// structures whose answers are worked out in the comments (spec/boundary-patches.md).
#include <gtest/gtest.h>

#include <set>

#include "symmesh/core/boundary_element_relation.h"
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/kernel.h"
#include "symmesh/core/symmetric_boundary_patches.h"
#include "symmesh/io/templated_structure_json.h"

using namespace symmesh::core;
using symmesh::Exact;

namespace {

template <int D>
TemplatedStructure<Exact, D> parse(const std::string& json) {
  return std::get<TemplatedStructure<Exact, D>>(symmesh::io::parse_templated_structure(json));
}

std::string square_with(const std::string& instances) {
  return R"({"symmesh": "templated-structure/1", "dimension": 2, "templates": [{"kind": "geometry",
    "polygon": [["0","0"],["1","0"],["1","1"],["0","1"]], "instances": [)" +
         instances + "]}]}";
}

Point<Exact, 2> p2(int x, int y, int d = 1) {
  return Point<Exact, 2>{{Exact(x) / d, Exact(y) / d}};
}

} // namespace

// Figure 6.5: a square and its mirror image in x = 0. Patches: the mirror edge x = 0 and the
// rest (one connected polyline); each related only to itself; regular (the reflection fixes the
// mirror edge pointwise).
TEST(BoundaryPatchPartition, ReflectionHasTwoPatchesAndIsRegular) {
  const auto x = parse<2>(square_with(
      R"({"transformation": {"identity": {}}}, {"transformation": {"reflection": {"normal": ["1","0"]}}})"));
  const auto b = boundary_patch_partition(x);
  std::ostringstream why;
  ASSERT_TRUE(b.is_valid(&why)) << why.str();
  EXPECT_EQ(b.patch_count(0, 1), 2u);
  EXPECT_EQ(b.patch_count(0, 0), 0u);
  EXPECT_EQ(b.classes.size(), 2u);
  EXPECT_TRUE(b.regular());
  const auto all = enumerate_compositions(b, 1000);
  EXPECT_TRUE(regular_by_enumeration(b, all));
}

// Figure 4.11: the square touches a copy of itself rotated by 180° about (1, 1/2): the right edge
// is mapped onto itself reversed, so identity and 𝕋_{T11,T12} differ on it: irregular.
TEST(BoundaryPatchPartition, FlippedSelfContactIsIrregular) {
  const auto x = parse<2>(square_with(
      R"({"transformation": {"identity": {}}}, {"transformation": {"rotation": {"order": 2, "k": 1, "center": ["1","1/2"]}}})"));
  const auto b = boundary_patch_partition(x);
  ASSERT_TRUE(b.is_valid());
  EXPECT_EQ(b.patch_count(0, 1), 2u);
  ASSERT_FALSE(b.regular());
  const auto& w = *b.irregularity;
  EXPECT_EQ(w.patch, w.target);
  EXPECT_FALSE(w.symmetry.is_identity());
  EXPECT_EQ(w.symmetry(p2(1, 0)), p2(1, 1));
  const auto all = enumerate_compositions(b, 1000);
  EXPECT_FALSE(regular_by_enumeration(b, all));
  // Section 5.2.2: no boundary vertex may move in an irregular structure.
  EXPECT_FALSE(valid_vertex_movement(b, 0, p2(2, 1, 2)).can_move);
}

// Figure 6.7: a 90° slice with four rotated instances. Facet patches H1, H2 (related) and the
// rest; the centre is a 0-dimensional patch (opposite instances meet only there).
TEST(BoundaryPatchPartition, RotationalSliceHasThreeFacetPatches) {
  const auto x = parse<2>(R"({"symmesh": "templated-structure/1", "dimension": 2, "templates": [
    {"kind": "geometry", "polygon": [["0","0"],["1","-1"],["1","1"]], "instances": [
      {"transformation": {"rotation": {"order": 4, "k": 0}}},
      {"transformation": {"rotation": {"order": 4, "k": 1}}},
      {"transformation": {"rotation": {"order": 4, "k": 2}}},
      {"transformation": {"rotation": {"order": 4, "k": 3}}}]}]})");
  const auto b = boundary_patch_partition(x);
  ASSERT_TRUE(b.is_valid());
  EXPECT_EQ(b.patch_count(0, 1), 3u);
  EXPECT_EQ(b.patch_count(0, 0), 1u);
  EXPECT_TRUE(b.regular());
  const auto h1 = b.face_patch[0][*b.locate(0, p2(1, -1, 2))];
  const auto h2 = b.face_patch[0][*b.locate(0, p2(1, 1, 2))];
  const auto rest = b.face_patch[0][*b.locate(0, p2(1, 0))];
  EXPECT_EQ(b.patches[h1].relation_class, b.patches[h2].relation_class);
  EXPECT_NE(b.patches[h1].relation_class, b.patches[rest].relation_class);
  // Lemma 4.4 (i): the witness composition maps H1 onto H2.
  const auto c = b.composition_between(h1, h2);
  EXPECT_EQ(c.map(p2(1, -1)), p2(1, 1));
  // Figure 5.11: the centre cannot move; a point inside H1 moves along H1.
  EXPECT_FALSE(valid_vertex_movement(b, 0, p2(0, 0)).can_move);
  const auto mv = valid_vertex_movement(b, 0, p2(1, -1, 2));
  EXPECT_TRUE(mv.can_move);
  EXPECT_EQ(mv.dimension, 1);
  const auto all = enumerate_compositions(b, 10000);
  EXPECT_TRUE(regular_by_enumeration(b, all));
}

// A glide reflection by a tiny offset would need ~10^5 composed images: the guard stops it.
TEST(BoundaryPatchPartition, CompositionExplosionIsStopped) {
  const auto x = parse<2>(R"({"symmesh": "templated-structure/1", "dimension": 2, "templates": [
    {"kind": "geometry", "polygon": [["0","0"],["1","0"],["0","-1"]], "instances": [
      {"transformation": {"identity": {}}},
      {"transformation": {"compose": [{"translation": ["1/100000","0"]},
                                      {"reflection": {"normal": ["0","1"]}}]}}]}]})");
  BppOptions o;
  o.max_compositions = 1000;
  EXPECT_THROW(boundary_patch_partition(x, o), CompositionLimitExceeded);
}

// 3D: the unit cube and its mirror image in x = 0: the mirror face and the rest.
TEST(BoundaryPatchPartition, MirroredCubeHalvesHaveTwoFacetPatches) {
  const auto x = parse<3>(R"({"symmesh": "templated-structure/1", "dimension": 3, "templates": [
    {"kind": "geometry",
     "vertices": [["0","0","0"],["1","0","0"],["1","1","0"],["0","1","0"],
                  ["0","0","1"],["1","0","1"],["1","1","1"],["0","1","1"]],
     "cells": [[0,1,3,4],[1,2,3,6],[1,4,5,6],[3,4,6,7],[1,3,4,6]],
     "instances": [{"transformation": {"identity": {}}},
                   {"transformation": {"reflection": {"normal": ["1","0","0"]}}}]}]})");
  const auto b = boundary_patch_partition(x);
  std::ostringstream why;
  ASSERT_TRUE(b.is_valid(&why)) << why.str();
  EXPECT_EQ(b.patch_count(0, 2), 2u);
  EXPECT_TRUE(b.regular());
}

// 3D rotational slice about the z axis: two slice planes (related), the rest, and the axis.
TEST(BoundaryPatchPartition, RotationalSlice3DHasAxisPatch) {
  const auto x = parse<3>(R"({"symmesh": "templated-structure/1", "dimension": 3, "templates": [
    {"kind": "geometry",
     "vertices": [["0","0","0"],["1","-1","0"],["1","1","0"],["0","0","1"],["1","-1","1"],["1","1","1"]],
     "cells": [[0,1,2,3],[1,2,3,4],[2,3,4,5]],
     "instances": [
       {"transformation": {"identity": {}}},
       {"transformation": {"signed_permutation": {"perm": [1,0,2], "sign": [-1,1,1]}}},
       {"transformation": {"signed_permutation": {"perm": [0,1,2], "sign": [-1,-1,1]}}},
       {"transformation": {"signed_permutation": {"perm": [1,0,2], "sign": [1,-1,1]}}}]}]})");
  const auto b = boundary_patch_partition(x);
  std::ostringstream why;
  ASSERT_TRUE(b.is_valid(&why)) << why.str();
  EXPECT_EQ(b.patch_count(0, 2), 3u);
  EXPECT_EQ(b.patch_count(0, 1), 1u);
  EXPECT_TRUE(b.regular());
}

// Section 6.2 / Algorithm 6.2 special cases on the fixtures agree with Algorithm 4.1 in the
// number of facet patches per template.
namespace {
std::vector<std::size_t> special_counts(const std::vector<SymmetryPatch<Exact>>& sp,
                                        std::size_t n) {
  std::vector<std::size_t> c(n, 0);
  for (const auto& p : sp) ++c[p.template_index];
  return c;
}
std::vector<std::size_t> general_counts(const BoundaryPatchPartition<Exact, 2>& b, std::size_t n) {
  std::vector<std::size_t> c;
  for (std::size_t t = 0; t < n; ++t) c.push_back(b.patch_count(t, 1));
  return c;
}
} // namespace

TEST(SymmetricBoundaryPatches, FixturesAgreeWithAlgorithm41) {
  const std::string dir = SYMMESH_SOURCE_DIR "/data/";
  auto load = [&](const std::string& f) {
    return std::get<TemplatedStructure<Exact, 2>>(symmesh::io::read_templated_structure(dir + f));
  };
  const auto refl = load("fig_6_5_reflection_bpp.json");
  EXPECT_EQ(special_counts(reflective_boundary_patches(refl), 1),
            general_counts(boundary_patch_partition(refl), 1));
  EXPECT_EQ(general_counts(boundary_patch_partition(refl), 1), std::vector<std::size_t>{2});
  const auto rot = load("fig_6_7_rotational_slice.json");
  EXPECT_EQ(
      special_counts(rotational_boundary_patches(rot, Point<Exact, 2>{{Exact(1), Exact(-1)}}), 1),
      std::vector<std::size_t>{3});
  const auto multi = load("fig_6_8_multiregion_rotational.json");
  EXPECT_EQ(
      special_counts(rotational_boundary_patches(multi, Point<Exact, 2>{{Exact(1), Exact(0)}}), 2),
      general_counts(boundary_patch_partition(multi), 2));
  EXPECT_EQ(general_counts(boundary_patch_partition(multi), 2), (std::vector<std::size_t>{4, 5}));
}

// The data/ fixtures with the answers stated in their descriptions.
namespace {
template <int D>
TemplatedStructure<Exact, D> fixture(const std::string& f) {
  return std::get<TemplatedStructure<Exact, D>>(
      symmesh::io::read_templated_structure(SYMMESH_SOURCE_DIR "/data/" + f));
}
template <int D>
std::vector<std::size_t> facet_counts(const BoundaryPatchPartition<Exact, D>& b) {
  std::vector<std::size_t> c;
  for (std::size_t t = 0; t < b.subdivisions.size(); ++t) c.push_back(b.patch_count(t, D - 1));
  return c;
}
} // namespace

TEST(BoundaryPatchPartition, Figure410SixAndFivePatches) {
  const auto b = boundary_patch_partition(fixture<2>("fig_4_10_partition.json"));
  ASSERT_TRUE(b.is_valid());
  EXPECT_EQ(facet_counts(b), (std::vector<std::size_t>{6, 5}));
  // green, yellow, purple pairs; 3 + 2 black singletons; one junction point of X2.
  std::size_t pairs = 0, singles = 0;
  for (const auto& c : b.classes) {
    if (b.patches[c.front()].dimension != 1) continue;
    (c.size() == 2 ? pairs : singles) += 1;
  }
  EXPECT_EQ(pairs, 3u);
  EXPECT_EQ(singles, 5u);
  EXPECT_EQ(b.patch_count(1, 0), 1u);
  EXPECT_TRUE(b.regular());
}

TEST(BoundaryPatchPartition, Figure47IndirectNeighboursAreRelated) {
  const auto x = fixture<2>("fig_4_7_indirect_neighbours.json");
  const auto b = boundary_patch_partition(x);
  EXPECT_EQ(facet_counts(b), (std::vector<std::size_t>{2, 4, 2}));
  // X1 and X3 share no instance-graph edge, yet one class holds a patch of each (and of X2).
  bool found = false;
  for (const auto& c : b.classes) {
    std::set<std::size_t> templates;
    for (std::size_t p : c) templates.insert(b.patches[p].template_index);
    if (templates == std::set<std::size_t>{0, 1, 2}) found = true;
  }
  EXPECT_TRUE(found);
  for (const auto& m : b.mappings)
    EXPECT_FALSE((m.from_template() == 0 && m.to_template() == 2) ||
                 (m.from_template() == 2 && m.to_template() == 0));
  EXPECT_TRUE(b.regular());
}

TEST(BoundaryPatchPartition, Figure411FixtureIsIrregular) {
  const auto b = boundary_patch_partition(fixture<2>("fig_4_11_irregular.json"));
  EXPECT_EQ(facet_counts(b), std::vector<std::size_t>{2});
  EXPECT_FALSE(b.regular());
}

TEST(BoundaryPatchPartition, ThreeDimensionalFixtures) {
  const auto cube = boundary_patch_partition(fixture<3>("cube_mirrored_halves_3d.json"));
  EXPECT_EQ(facet_counts(cube), std::vector<std::size_t>{2});
  EXPECT_TRUE(cube.regular());
  const auto slice = boundary_patch_partition(fixture<3>("rotational_slice_3d.json"));
  EXPECT_EQ(facet_counts(slice), std::vector<std::size_t>{3});
  EXPECT_EQ(slice.patch_count(0, 1), 1u);
  EXPECT_TRUE(slice.regular());
}

TEST(BoundaryPatchPartition, Figure68PatchesNotVisibleFromOneSlice) {
  const auto b = boundary_patch_partition(fixture<2>("fig_6_8_multiregion_rotational.json"));
  EXPECT_EQ(facet_counts(b), (std::vector<std::size_t>{4, 5}));
  EXPECT_TRUE(b.regular());
}

// Def 4.7 as listed by template_boundary_mappings: the inverse's domain holds the images of the
// domain's vertices, piece for piece and vertex for vertex (the BPP reads images off it instead
// of applying the map), and it is the pull-back to the other template (on its boundary).
template <int D>
void expect_inverse_domains_are_images(const TemplatedStructure<Exact, D>& x) {
  const auto ms = template_boundary_mappings(x);
  std::size_t checked = 0;
  for (const auto& m : ms) {
    if (m.whole_boundary) continue;
    const auto& image = ms[m.inverse].domain;
    ASSERT_EQ(image.size(), m.domain.size()) << m.name();
    for (std::size_t k = 0; k < m.domain.size(); ++k) {
      ASSERT_EQ(image[k].vertices.size(), m.domain[k].vertices.size()) << m.name();
      for (std::size_t j = 0; j < m.domain[k].vertices.size(); ++j, ++checked)
        EXPECT_EQ(m.map(m.domain[k].vertices[j]), image[k].vertices[j]) << m.name();
    }
  }
  EXPECT_GT(checked, 0u);
}

TEST(TemplateBoundaryMappings, InverseDomainListsTheImagesVertexForVertex) {
  for (const char* f : {"fig_4_10_partition.json", "fig_4_7_indirect_neighbours.json",
                        "fig_4_11_irregular.json", "fig_6_8_multiregion_rotational.json"})
    expect_inverse_domains_are_images(fixture<2>(f));
  for (const char* f : {"cube_mirrored_halves_3d.json", "rotational_slice_3d.json"})
    expect_inverse_domains_are_images(fixture<3>(f));
}

// Def 4.8 on template boundary elements of a templated mesh (Lemma 4.4 (ii)): Fig. 4.3 maps
// elements onto elements; Fig. 4.4 (not a templated mesh) does not, and names the element.
TEST(BoundaryElementRelation, TemplatedMeshVersusNonConforming) {
  const auto good = fixture<2>("fig_4_3_templated_mesh.json");
  const auto r = boundary_element_relation(good, template_boundary_mappings(good));
  EXPECT_TRUE(r.maps_onto_elements) << r.offender;
  EXPECT_EQ(r.elements.size(), 2u);
  EXPECT_LT(r.class_count, r.elements[0].size() + r.elements[1].size());
  const auto bad = fixture<2>("fig_4_4_nonconforming.json");
  const auto s = boundary_element_relation(bad, template_boundary_mappings(bad));
  EXPECT_FALSE(s.maps_onto_elements);
  EXPECT_NE(s.offender.find("is not mapped onto an element"), std::string::npos);
}
