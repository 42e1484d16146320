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
// Claim (3D, on generated templated meshes): on grids of boxes (translated or mirrored) and on a
// block on a base slab (two templates, a T-junction), right-angled and convex or not, generated
// as `symmesh generate` does, Technique 5.8 in 3D ends within 64 rounds with a certified
// templated mesh of the same volume (exact) whose AT has every interior triangle locally
// Delaunay, decided by exact in-sphere signs with no allowance (see exact_delaunay_verdict for the
// coordinates). Dropped (Lines 6-18, no boundary insertions: the
// templates are only re-tetrahedralized): on the block on its base, interface triangles are not
// locally Delaunay.
// Claim (3D, acute creases, spec/adaptation.md#tmesh-adaptation): on a triangular prism
// template with a 3°-44° crease between its two legs (second leg 0.3-1.5 long, the first 1),
// alone or mirrored across its first leg (y = 0, exact), after 0-2 rounds of uniform refinement,
// Technique 5.8 in 3D with crease mirroring ends within 32 rounds with a certified templated mesh
// of the same boundary area whose AT has every interior triangle locally Delaunay by exact
// in-sphere signs, up to ties by rounding (|D| / L^5 <= 1e-9: a leg triangle and its mirror
// image are cospherical in the reals, and mirror points across a slanted bisector are rounded).
// Dropped (no mirror points: bisection and shells around the crease vertices only): at 3°-10° the
// legs keep encroaching on each other and the refinement cap or the round cap ends it
// (AdaptationLimit).
#include "proofs-checks/adaptation_support.h"
#include "proofs-checks/acute_prism.h"
#include "proofs-checks/box_inputs.h"
#include "proofs-checks/exact_delaunay_verdict.h"
#include "proofs-checks/registry.h"
#include "symmesh/adapt/make_delaunay.h"
#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/core/delaunay.h"
#include "symmesh/mesh/structure_instance.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

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

// ------------------------------------------------------------------ Technique 5.8 in 3D (.tmesh)
//
// Technique 5.8 in 3D works on generated templated meshes (adapt::make_delaunay on the compact
// SVB, with TetGen re-tetrahedralizing each template), not on the exact core, so its property
// generates the input as `symmesh generate` does and decides the conclusion with exact signs on
// the result's doubles (taken as rationals): every interior triangle of AT, found from the SVB's
// numbering, is tested both ways — the apex of one cell not strictly inside the circumsphere of
// the other. With every interior triangle locally Delaunay, AT is a constrained Delaunay
// tetrahedralization of its domain, Delaunay where the domain is convex (the grids).

using boxes::BoxInput;

void delaunay_after_technique_5_8_3d(const BoxInput& g, bool boundary_insertions) {
  const std::string text = g.description();
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  auto t = g.generate();
  const double boundary = adapt::certify_conformity(t).boundary_measure;
  try {
    // Dropped (Lines 6-18): no round of boundary insertions, the templates are only
    // re-tetrahedralized; the limit it then reports is the expected outcome.
    const auto report = adapt::make_delaunay(t, boundary_insertions ? 64 : 0);
    RC_TAG(report.rounds > 0 ? "boundary points inserted" : "templates only");
  } catch (const adapt::AdaptationLimit&) {
    SYMMESH_PROOF_ASSERT(!boundary_insertions, failure, no_picture);
  }
  SYMMESH_PROOF_ASSERT(t.is_valid(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::certify_conformity(t, boundary).holds, failure, no_picture);
  const auto verdict = exact_delaunay_verdict(t);
  SYMMESH_PROOF_ASSERT(verdict.overfull == 0, failure, no_picture);
  SYMMESH_PROOF_ASSERT(verdict.volume == g.measure(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(
      verdict.not_locally_delaunay == 0,
      [&] {
        return text + "\n(" + std::to_string(verdict.not_locally_delaunay) + " of " +
               std::to_string(verdict.interior) + " interior triangles of AT not locally Delaunay)";
      },
      no_picture);
}

rc::Gen<AcutePrism> acute_prism_in(int lowest, int highest) {
  return rc::gen::apply(
      [](int degrees, int leg_tenths, bool mirrored, int refinements) {
        return AcutePrism{degrees, leg_tenths / 10.0, mirrored, refinements};
      },
      rc::gen::inRange(lowest, highest + 1), rc::gen::inRange(3, 16), rc::gen::arbitrary<bool>(),
      rc::gen::inRange(0, 3));
}

void delaunay_at_acute_crease(const AcutePrism& g, bool crease_mirrors) {
  std::string text = g.description();
  const auto failure = [&] { return text; };
  const auto no_picture = [] { return std::string(); };
  auto t = g.build();
  const double boundary = adapt::certify_conformity(t).boundary_measure;
  bool ended = true;
  try {
    const auto report = adapt::make_delaunay(t, 32, nullptr, crease_mirrors);
    RC_TAG(report.crease_mirror_points > 0 ? "mirror points inserted" : "no mirror points");
  } catch (const std::runtime_error& e) { // AdaptationLimit, or TetGen's MeshingError
    ended = false;
    text += std::string("\n") + e.what();
  }
  SYMMESH_PROOF_ASSERT(ended, failure, no_picture);
  SYMMESH_PROOF_ASSERT(t.is_valid(), failure, no_picture);
  SYMMESH_PROOF_ASSERT(adapt::certify_conformity(t, boundary).holds, failure, no_picture);
  const auto verdict = exact_delaunay_verdict(t);
  SYMMESH_PROOF_ASSERT(verdict.overfull == 0, failure, no_picture);
  // Mirror points across a slanted bisector are rounded, so a leg triangle and its mirror image
  // are cospherical only up to rounding: such ties count (|D| / L^5 <= 1e-9), as in the library.
  RC_TAG(verdict.not_locally_delaunay ? "ties up to rounding" : "no ties");
  SYMMESH_PROOF_ASSERT(
      verdict.beyond_rounding == 0,
      [&] {
        return text + "\n(" + std::to_string(verdict.beyond_rounding) + " of " +
               std::to_string(verdict.interior) +
               " interior triangles of AT not locally Delaunay beyond rounding)";
      },
      no_picture);
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
  p.push_back({kClaim, "structure_instance_is_delaunay_3d", 3, Kind::holds,
               "Technique 5.8 in 3D (adapt::make_delaunay on a generated templated mesh): on "
               "grids of boxes, translated or mirrored, and on a block on a base slab (right "
               "angles), it ends within 64 rounds with a certified templated mesh of the same "
               "volume (exact) whose AT has every interior triangle locally Delaunay (exact "
               "in-sphere signs, no allowance)",
               [] {
                 return rc::detail::toProperty([] {
                   delaunay_after_technique_5_8_3d(
                       *rc::gen::oneOf(boxes::box_grid(3), boxes::block_on_base(3)), true);
                 });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { delaunay_after_technique_5_8_3d(*boxes::block_on_base(3), false); });
               }});
  p.push_back({kClaim, "crease_mirroring_ends_ping_pong_3d", 3, Kind::holds,
               "Technique 5.8 in 3D with crease mirroring: on a triangular prism with a "
               "3-44 degree crease between its legs (alone or mirrored across a leg, refined "
               "0-2 times) it ends within 32 rounds with a certified templated mesh whose AT has "
               "every interior triangle locally Delaunay (exact signs; ties up to rounding, "
               "|D|/L^5 <= 1e-9, allowed)",
               [] {
                 return rc::detail::toProperty(
                     [] { delaunay_at_acute_crease(*acute_prism_in(3, 44), true); });
               },
               [] {
                 return rc::detail::toProperty(
                     [] { delaunay_at_acute_crease(*acute_prism_in(3, 10), false); });
               }});
}

} // namespace symmesh::proofs
