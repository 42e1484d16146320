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

} // namespace

void register_technique_5_8(std::vector<Property>& p) {
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
