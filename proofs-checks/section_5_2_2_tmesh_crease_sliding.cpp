// Section 5.2.2 / Equation 5.1 on generated templated meshes (.tmesh): a template-boundary vertex
// on a straight crease slides along it, with every related vertex —
// spec/adaptation.md#tmesh-adaptation
//
// Claim (a generated box [0,1]×[0,1]×[0,1/2], one instance or two translated along x, so that
// the box's x = 1 and x = 0 faces are an instance interface): the middle vertex of each vertical
// box edge (z = 1/4, between two box corners) lies on a crease of the template boundary — two
// flat faces meeting in a line, not one flat patch. Slid along its edge (z = 1/4 + k/64, its
// related copies with it), the mesh is still a templated mesh, and one sweep of
// adapt::smooth_vertices moves every such vertex back to the midpoint of its crease's ends
// exactly (z = 1/4, x and y kept), leaving a valid templated mesh, certified conforming with the
// same boundary measure, the same template boundary facets and the same volume (exact).
// Dropped hypothesis (a boundary vertex moves together with every related vertex): sliding the
// middle vertices of the interface edges (x = 1) in their template only, without their copies
// (x = 0), opens the interface, and the certificate fails.
//
// Claim 2 (a generated block on a base slab, 2D and 3D: two templates instanced once whose
// interface ends in a T-junction, the block's bottom corners / edges lying in the base's flat
// top side): one or two sweeps of adapt::smooth_vertices leave a valid templated mesh, certified
// conforming with the same boundary measure and the same area / volume (exact). A vertex of the
// T-junction is a corner or crease vertex of the block but a flat vertex of the base, so its
// links are not images of each other and it stays (Equation 5.1 moves a vertex only with every
// related vertex, each to the image of the same place). Dropped hypothesis: each boundary vertex
// moved alone (adapt::detail::smooth_vertices_unlinked); the base's copy of a T-junction vertex
// slides in the base's top side while the block's stays, and the certificate fails.
//
// Claim 3 (a generated box grid, 2D and 3D, turned as a whole by a rotation that is no signed
// permutation — every template's coordinates rotated and rounded, every instance's
// transformation conjugated — so that no face of the boxes is exactly flat in the doubles and no
// edge exactly straight): boundary vertices still slide within their patch. Whenever the unturned
// grid's smoothing moves a boundary vertex, the turned grid's does too; and one to three sweeps
// leave a valid templated mesh, certified conforming with the same boundary measure, the same
// template boundary facets, and the same area / volume up to a relative 1e-12 (the rounding of
// the turned coordinates; a boundary vertex that left its face by a fraction of an edge would
// change it by far more). Dropped hypothesis (a boundary vertex moves only within its patch,
// flat up to rounding and no more): with a flatness tolerance of 2 every closed fan counts as a
// flat disk, corner and crease vertices move to their link's mean, and the area / volume changes.
#include "proofs-checks/box_inputs.h"
#include "proofs-checks/registry.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace symmesh::proofs {
namespace {

constexpr const char* kClaim = "Section_5_2_2";

using boxes::BoxInput;

BoxInput box(int instances) {
  BoxInput in;
  in.dimension = 3;
  in.size = 0.3;
  BoxInput::Box b;
  b.twice = {0, 2, 0, 2, 0, 1};
  for (int k = 0; k < instances; ++k) b.instances.push_back({{2 * k, 0, 0}, false});
  in.boxes.push_back(b);
  return in;
}

bool on_box_corner_line(const double* p) {
  return (p[0] == 0 || p[0] == 1) && (p[1] == 0 || p[1] == 1);
}

void crease_vertices_slide(int instances, int step, bool with_copies) {
  const BoxInput in = box(instances);
  const std::string text = in.description() +
                           "\n(middle vertices of the vertical edges slid to z = 1/4 + " +
                           std::to_string(step) + "/64" +
                           (with_copies ? ", copies with them)" : ", interface copies left)");
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  auto t = in.generate();
  const double boundary = adapt::certify_conformity(t).boundary_measure;
  auto& m = t.templated.templates[0].mesh;
  const auto facets = boxes::one_cell_facets(m, 3);
  std::vector<std::size_t> middle;
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    if (on_box_corner_line(m.vertex(v)) && m.vertex(v)[2] == 0.25) middle.push_back(v);
  // The line mesh of each vertical edge (length 1/2, size 0.3) has two parts: one middle vertex.
  SYMMESH_PROOF_ASSERT(middle.size() == 4, failure, no_picture);
  const double z = 0.25 + step / 64.0;
  for (std::size_t v : middle)
    if (with_copies || m.vertex(v)[0] == 1) m.vertex_coords[3 * v + 2] = z;
  SYMMESH_PROOF_ASSERT(adapt::certify_conformity(t, boundary).holds, failure, no_picture);
  const auto report = adapt::smooth_vertices(t, 1, false);
  SYMMESH_PROOF_ASSERT(report.boundary_moves >= middle.size(), failure, no_picture);
  for (std::size_t v : middle) {
    SYMMESH_PROOF_ASSERT(on_box_corner_line(m.vertex(v)), failure, no_picture);
    SYMMESH_PROOF_ASSERT(m.vertex(v)[2] == 0.25, failure, no_picture);
  }
  SYMMESH_PROOF_ASSERT(t.is_valid(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::certify_conformity(t, boundary).holds, failure, no_picture);
  SYMMESH_PROOF_ASSERT(boxes::one_cell_facets(m, 3) == facets, failure, no_picture);
  SYMMESH_PROOF_ASSERT(boxes::exact_measure(t) == in.measure(), failure, no_picture);
}

void boundary_smoothing_keeps_the_interface(const BoxInput& in, int sweeps, bool linked) {
  const std::string text = in.description() + "\n(" + std::to_string(sweeps) + " sweeps, " +
                           (linked ? "related vertices together)" : "each vertex alone)");
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  auto t = in.generate();
  const double boundary = adapt::certify_conformity(t).boundary_measure;
  SYMMESH_PROOF_ASSERT(boxes::exact_measure(t) == in.measure(), failure, no_picture);
  const auto report = linked ? adapt::smooth_vertices(t, std::size_t(sweeps), false)
                             : adapt::detail::smooth_vertices_unlinked(t, std::size_t(sweeps));
  RC_TAG(report.boundary_moves > 0 ? "boundary vertices moved" : "no boundary move");
  SYMMESH_PROOF_ASSERT(t.is_valid(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::certify_conformity(t, boundary).holds, failure, no_picture);
  SYMMESH_PROOF_ASSERT(boxes::exact_measure(t) == in.measure(), failure, no_picture);
}

std::vector<double> times(const std::vector<double>& a, const std::vector<double>& b, int d,
                          bool b_transposed = false) {
  std::vector<double> out(std::size_t(d * d), 0);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      for (int k = 0; k < d; ++k)
        out[std::size_t(i * d + j)] +=
            a[std::size_t(i * d + k)] * b[std::size_t(b_transposed ? j * d + k : k * d + j)];
  return out;
}

/// The templated mesh turned by R as a whole: coordinates R x, transformations R M R^T, R t.
void turn(mesh::TemplatedMeshCompactSvb& t, const std::vector<double>& r) {
  const int d = t.templated.point_dimension;
  const auto apply = [&](double* x) {
    double y[3] = {0, 0, 0};
    for (int i = 0; i < d; ++i)
      for (int k = 0; k < d; ++k) y[i] += r[std::size_t(i * d + k)] * x[k];
    std::copy(y, y + d, x);
  };
  for (auto& mt : t.templated.templates)
    for (std::size_t v = 0; v < mt.mesh.vertex_count(); ++v)
      apply(&mt.mesh.vertex_coords[v * std::size_t(d)]);
  for (auto& f : t.templated.transformations) {
    f.matrix = times(times(r, f.matrix, d), r, d, true);
    apply(f.translation.data());
  }
}

double relative_change(const mpq_class& before, const mpq_class& after) {
  const mpq_class change = abs(after - before) / before;
  return change.get_d();
}

void slanted_boundary_smoothing(const BoxInput& in, int degrees, int sweeps, double tolerance) {
  const std::string text = in.description() + "\n(turned by " + std::to_string(degrees) +
                           " degrees, " + std::to_string(sweeps) + " sweeps, flat to " +
                           std::to_string(tolerance) + ")";
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  const int d = in.dimension;
  auto plain = in.generate();
  auto t = plain;
  turn(t, boxes::turning_rotation(d, degrees));
  const double boundary = adapt::certify_conformity(t).boundary_measure;
  const mpq_class measure = boxes::exact_measure(t);
  std::vector<std::set<std::vector<mesh::IndexType>>> facets;
  for (const auto& mt : t.templated.templates) facets.push_back(boxes::one_cell_facets(mt.mesh, d));
  const auto unturned = adapt::smooth_vertices(plain, std::size_t(sweeps), false);
  const auto report =
      adapt::detail::smooth_vertices_with_flatness(t, std::size_t(sweeps), tolerance);
  RC_TAG(report.boundary_moves > 0 ? "boundary vertices moved" : "no boundary move");
  SYMMESH_PROOF_ASSERT(unturned.boundary_moves == 0 || report.boundary_moves > 0, failure,
                       no_picture);
  SYMMESH_PROOF_ASSERT(t.is_valid(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::certify_conformity(t, boundary).holds, failure, no_picture);
  for (std::size_t i = 0; i < facets.size(); ++i)
    SYMMESH_PROOF_ASSERT(boxes::one_cell_facets(t.templated.templates[i].mesh, d) == facets[i],
                         failure, no_picture);
  SYMMESH_PROOF_ASSERT(
      relative_change(measure, boxes::exact_measure(t)) <= 1e-12,
      [&] {
        return text + "\nrelative change of the measure " +
               std::to_string(relative_change(measure, boxes::exact_measure(t)));
      },
      no_picture);
}

rc::Gen<int> steps() {
  return rc::gen::suchThat(rc::gen::inRange(-7, 8), [](int k) { return k != 0; });
}

} // namespace

void register_section_5_2_2_tmesh(std::vector<Property>& p) {
  p.push_back(
      {kClaim, "tmesh_crease_vertex_slides_with_its_copies_3d", 3, Kind::holds,
       "Section 5.2.2 / Eq. 5.1 on a generated box (one instance or two across an "
       "interface): a template-boundary vertex on a straight crease, slid along it with "
       "its related copies, is moved back to the midpoint of the crease's ends by one "
       "smoothing sweep, and the mesh stays templated (certified, same boundary facets, "
       "same volume, exact)",
       [] {
         return rc::detail::toProperty(
             [] { crease_vertices_slide(*rc::gen::inRange(1, 3), *steps(), true); });
       },
       [] { return rc::detail::toProperty([] { crease_vertices_slide(2, *steps(), false); }); }});
  for (int d : {2, 3})
    p.push_back({kClaim, "tmesh_boundary_smoothing_keeps_a_t_junction_" + std::to_string(d) + "d",
                 d, Kind::holds,
                 "Section 5.2.2 / Eq. 5.1 on a generated block on a base slab (a T-junction where "
                 "the block's corner or crease lies in the base's flat side): smoothing moves "
                 "boundary vertices only with every related vertex, so the mesh stays templated "
                 "(certified, same measure, exact)",
                 [d] {
                   return rc::detail::toProperty([d] {
                     boundary_smoothing_keeps_the_interface(*boxes::block_on_base(d),
                                                            *rc::gen::inRange(1, 3), true);
                   });
                 },
                 [d] {
                   return rc::detail::toProperty([d] {
                     boundary_smoothing_keeps_the_interface(*boxes::block_on_base(d),
                                                            *rc::gen::inRange(1, 3), false);
                   });
                 }});
  for (int d : {2, 3})
    p.push_back(
        {kClaim, "tmesh_boundary_smoothing_on_slanted_planes_" + std::to_string(d) + "d", d,
         Kind::holds,
         "Section 5.2.2 / Eq. 5.1 on a generated box grid turned by a rotation that is no "
         "signed permutation (no face exactly flat in the doubles): boundary vertices still "
         "slide within their patch, flat up to rounding, and the mesh stays templated "
         "(certified, same boundary facets, same measure to a relative 1e-12)",
         [d] {
           return rc::detail::toProperty([d] {
             slanted_boundary_smoothing(*boxes::box_grid(d), *rc::gen::inRange(1, 90),
                                        *rc::gen::inRange(1, 4), 1e-9);
           });
         },
         [d] {
           return rc::detail::toProperty([d] {
             slanted_boundary_smoothing(*boxes::box_grid(d), *rc::gen::inRange(1, 90),
                                        *rc::gen::inRange(1, 4), 2);
           });
         }});
}

} // namespace symmesh::proofs
