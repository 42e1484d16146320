// Surface meshes of a face class carried by index (gen/surface_meshes_3d.h,
// spec/generation.md#surface-meshes): boundary_point_images, from the letters' face actions
// composed along the class's BFS tree, must name for every vertex and line-mesh point on the
// first face's closure the point of the member's template that the class composition C_g sends
// it to — the point the exact lookup by value found before. Checked exactly on hand-made
// structures whose mappings reverse edges (quarter-turn slices, a turned neighbour).
#include <gtest/gtest.h>

#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/kernel.h"
#include "symmesh/gen/surface_meshes_3d.h"
#include "symmesh/io/templated_structure_json.h"

#include <string>

using namespace symmesh;
using symmesh::Exact;

namespace {

core::TemplatedStructure<Exact, 3> parse3(const std::string& json) {
  return std::get<core::TemplatedStructure<Exact, 3>>(io::parse_templated_structure(json));
}

/// Every class member's boundary point ids, compared with C_g of the first face's points.
void expect_ids_are_images(const core::TemplatedStructure<Exact, 3>& x, double h) {
  const auto bpp = core::boundary_patch_partition(x);
  const auto classes = gen::surface3::face_classes(bpp);
  const Exact hh = gen::support::exact_from_double<Exact>(h);
  std::vector<gen::surface3::SurfaceBoundary<Exact>> boundaries;
  for (const auto& sd : bpp.subdivisions)
    boundaries.push_back(gen::surface3::line_meshes_3<Exact>(sd, hh * hh, h, {}, true));
  std::size_t checked = 0, members = 0;
  for (const auto& c : classes) {
    const auto [t, f] = c.first;
    for (const auto& g : c.members) {
      ++members;
      const auto image = gen::surface3::boundary_point_images(
          bpp.subdivisions[t], boundaries[t], bpp.subdivisions[g.t], boundaries[g.t], f,
          c.closure_image.at(g));
      const auto& map = c.comp.at(g);
      for (const auto& [from, to] : image) {
        ASSERT_LT(to, boundaries[g.t].exact.size());
        EXPECT_TRUE(map(boundaries[t].exact[from]) == boundaries[g.t].exact[to])
            << "class of face " << f << " of template " << t << ", member face " << g.f
            << " of template " << g.t << ": point " << from << " -> " << to;
        ++checked;
      }
    }
  }
  EXPECT_GT(members, classes.size()); // some class has a member other than its first face
  EXPECT_GT(checked, 0u);
}

} // namespace

// Four quarter-turn slices about the z axis: each slice plane is mapped onto the next copy's
// other slice plane, so the edges along the axis and the outer edges are traversed both ways.
TEST(SurfaceMeshPointIds, QuarterTurnSlicesMapLinePointsByIndex) {
  expect_ids_are_images(
      parse3(R"({"symmesh": "templated-structure/1", "dimension": 3, "templates": [
    {"kind": "geometry",
     "vertices": [["0","0","0"],["1","-1","0"],["1","1","0"],["0","0","1"],["1","-1","1"],["1","1","1"]],
     "cells": [[0,1,2,3],[1,2,3,4],[2,3,4,5]],
     "instances": [
       {"transformation": {"identity": {}}},
       {"transformation": {"signed_permutation": {"perm": [1,0,2], "sign": [-1,1,1]}}},
       {"transformation": {"signed_permutation": {"perm": [0,1,2], "sign": [-1,-1,1]}}},
       {"transformation": {"signed_permutation": {"perm": [1,0,2], "sign": [1,-1,1]}}}]}]})"),
      0.3);
}

// A cube next to its copy turned by a quarter about the x axis and moved by 1 along x: the face
// x = 1 is mapped onto the face x = 0, its edges turned, so line points are renumbered.
TEST(SurfaceMeshPointIds, TurnedNeighbourMapsLinePointsByIndex) {
  expect_ids_are_images(
      parse3(R"({"symmesh": "templated-structure/1", "dimension": 3, "templates": [
    {"kind": "geometry",
     "vertices": [["0","0","0"],["1","0","0"],["1","1","0"],["0","1","0"],
                  ["0","0","1"],["1","0","1"],["1","1","1"],["0","1","1"]],
     "cells": [[0,1,3,4],[1,2,3,6],[1,4,5,6],[3,4,6,7],[1,3,4,6]],
     "instances": [{"transformation": {"identity": {}}},
                   {"transformation": {"signed_permutation": {"perm": [0,2,1], "sign": [1,-1,1],
                                                              "translation": ["1","1","0"]}}}]}]})"),
      0.3);
}
