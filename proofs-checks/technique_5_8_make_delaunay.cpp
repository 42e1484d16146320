// Technique 5.8 (make a templated mesh Delaunay, Section 5.2.5) — spec/adaptation.md#technique-5-8
//
// Claim: on planar templated meshes whose structure instance is convex and has no acute angle
// (translation grids of boxes with subdivided sides, after 1-3 random interior insertions and
// sometimes a random insertion on an interface, so that templates and interfaces are seldom
// Delaunay), Technique 5.8 ends within its round cap with a
// templated mesh whose structure instance is Delaunay — decided directly by empty circumballs
// of AT's cells, exactly (core::is_delaunay_mesh) — and covers the same area.
// Dropped hypothesis (Lines 6-18, the boundary insertions): making only the templates Delaunay
// leaves the mirrored flat triangles' interface facet encroached, and AT is not Delaunay.
// Claim (protection balls, Line 9 and Figure 5.17): on a triangle template with an acute corner
// (5.7°-42°) reflected across both legs, Technique 5.8 with protection balls ends within its
// round cap and every interior edge of AT is locally Delaunay (AT is then a constrained Delaunay
// triangulation of its non-convex domain). Dropped (points at midpoints, no protection balls):
// the legs' pieces keep encroaching on each other and the cap is hit (ping-pong encroachment).
#include "proofs-checks/adaptation_support.h"
#include "proofs-checks/registry.h"
#include "symmesh/adapt/make_delaunay.h"
#include "symmesh/core/delaunay.h"

namespace symmesh::proofs {
namespace {

using namespace gen;
using namespace adaptation;

constexpr const char* kClaim = "Technique_5_8";

auto record(const GeneratedStructure<2>& s) {
  return structure_failure_record<2>(kClaim, s);
}
using gen::picture;

/// Twice the area of AT (sum of |det| over every instance's cells), exactly.
Exact doubled_area(const Structure<2>& x) {
  Exact sum(0);
  for (const auto& cell : adapt::structure_instance_cells(x)) {
    const Exact a = core::signed_volume_times_factorial<Exact, 2>(cell);
    sum += a < 0 ? -a : a;
  }
  return sum;
}

void delaunay_after_technique_5_8(const GeneratedStructure<2>& s, bool boundary_insertions) {
  RC_PRE(s.convex);
  // The dropped variant keeps its input: the encroached interface must reach AT unchanged.
  const auto x = boundary_insertions ? with_random_insertions<2>(s.x) : s.x;
  Structure<2> y = x;
  if (boundary_insertions) {
    const auto report = adapt::make_delaunay(y);
    RC_TAG(report.inserted > 0 ? "boundary points inserted" : "templates flipped only");
  } else {
    for (std::size_t i = 0; i < y.templates.size(); ++i) adapt::make_template_delaunay(y, i);
  }
  SYMMESH_PROOF_ASSERT(is_templated_mesh<2>(y), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(doubled_area(y) == doubled_area(x), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(core::is_delaunay_mesh(core::apply_template(y).at.mesh), record(s),
                       picture(s));
}

void ends_with_protection_balls(const GeneratedStructure<2>& s, bool protection_balls) {
  Structure<2> y = s.x;
  bool ended = true;
  try {
    const auto report = adapt::make_delaunay(y, 32, protection_balls);
    RC_TAG(std::to_string(report.rounds) + " rounds");
  } catch (const std::runtime_error&) {
    ended = false;
  }
  SYMMESH_PROOF_ASSERT(ended, record(s), picture(s));
  SYMMESH_PROOF_ASSERT(is_templated_mesh<2>(y), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(doubled_area(y) == doubled_area(s.x), record(s), picture(s));
  const auto at = core::apply_template(y).at.mesh;
  for (const auto& e : at.elements_of_dimension(1))
    if (adapt::co_cells(at, e).size() == 2)
      SYMMESH_PROOF_ASSERT(core::is_locally_delaunay_in(at, e), record(s), picture(s));
}

} // namespace

void register_technique_5_8(std::vector<Property>& p) {
  p.push_back(
      {kClaim, "protection_balls_end_ping_pong_2d", 2, Kind::holds,
       "Technique 5.8 with protection balls: on a triangle template with an acute "
       "corner reflected across both legs it ends within 32 rounds, and every interior "
       "edge of AT is locally Delaunay (exact)",
       [] {
         return rc::detail::toProperty([] { ends_with_protection_balls(*acute_wedge(), true); });
       },
       [] {
         return rc::detail::toProperty([] { ends_with_protection_balls(*acute_wedge(), false); });
       }});
  p.push_back({kClaim, "structure_instance_is_delaunay_2d", 2, Kind::holds,
               "Technique 5.8: on convex, right-angled planar templated meshes (translation "
               "grids of boxes) it ends with a templated mesh of the same area "
               "whose AT is Delaunay (empty circumballs, exact)",
               [] {
                 return rc::detail::toProperty(
                     [] { delaunay_after_technique_5_8(*translation_grid<2>(), true); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { delaunay_after_technique_5_8(*encroached_reflection<2>(), false); });
               }});
}

} // namespace symmesh::proofs
