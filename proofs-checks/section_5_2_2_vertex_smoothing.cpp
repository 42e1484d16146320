// Section 5.2.2 (vertex smoothing) — spec/adaptation.md#smoothing
//
// Claim (on generated templated meshes after 1-3 random insertions, which give them interior
// vertices): Laplacian smoothing of template-interior vertices with valid moves (every cell around
// the vertex keeps its exact orientation sign) maps a templated mesh to a templated mesh, and its
// structure instance is AT with every instance's image of each moved vertex moved to the image
// of its new place.
// Dropped hypothesis ("vertices which are not part of the boundary of a template"): moving a
// vertex of an instance interface facet to its neighbours' centroid, in its template only,
// opens the interface — AT is no longer conforming (Lemma 4.2 fails).
#include "proofs-checks/adaptation_support.h"
#include "proofs-checks/registry.h"
#include "symmesh/adapt/vertex_smoothing.h"

#include <map>

namespace symmesh::proofs {
namespace {

using namespace gen;
using namespace adaptation;

constexpr const char* kClaim = "Section_5_2_2";

template <int D>
auto record(const GeneratedStructure<D>& s) {
  return structure_failure_record<D>(kClaim, s);
}
using gen::picture;

/// AT(x)'s cells with every point T(p) replaced by T(q) wherever y moved template vertex p to q.
template <int D>
adapt::CellSet<Exact, D> moved_structure_instance(const Structure<D>& x, const Structure<D>& y) {
  std::map<Point<D>, Point<D>, core::PointLess<Exact, D>> move;
  for (const auto id : x.instance_ids()) {
    const auto& a = x.templates[id.i].mesh.points;
    const auto& b = y.templates[id.i].mesh.points;
    for (std::size_t v = 0; v < a.size(); ++v)
      if (a[v] != b[v]) move.emplace(x.tf(id)(a[v]), x.tf(id)(b[v]));
  }
  adapt::CellSet<Exact, D> out;
  for (auto cell : adapt::structure_instance_cells(x)) {
    for (auto& p : cell)
      if (const auto it = move.find(p); it != move.end()) p = it->second;
    out.insert(adapt::sorted_points<Exact, D>(std::move(cell)));
  }
  return out;
}

template <int D>
void smoothing_keeps_a_templated_mesh(const GeneratedStructure<D>& s) {
  const auto x = with_random_insertions<D>(s.x);
  Structure<D> y = x;
  const auto moves = adapt::smooth_interior_vertices(y, 2);
  RC_TAG(moves > 0 ? "vertices moved" : "no valid move");
  SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(y), record(s), picture(s));
  SYMMESH_PROOF_ASSERT(adapt::structure_instance_cells(y) == moved_structure_instance<D>(x, y),
                       record(s), picture(s));
}

/// Moves one vertex of a random interface facet to its neighbours' centroid, ignoring the
/// interface. \pre x has an interface facet
template <int D>
Structure<D> move_interface_vertex(const Structure<D>& x) {
  const auto facets = interface_facets<D>(x);
  RC_PRE(!facets.empty());
  const auto [i, f] = facets[std::size_t(*rc::gen::inRange<int>(0, int(facets.size())))];
  const auto v = f.v[std::size_t(*rc::gen::inRange<int>(0, int(f.n)))];
  Structure<D> y = x;
  y.templates[i].mesh.points[v] = adapt::neighbour_centroid(x.templates[i].mesh, v);
  return y;
}

template <int D>
void add(std::vector<Property>& p) {
  p.push_back({kClaim, "interior_smoothing_moves_every_instance" + dim_suffix(D), D, Kind::holds,
               "Section 5.2.2: two sweeps of Laplacian smoothing of template-interior vertices "
               "(valid moves only) give a templated mesh whose AT is the input's with every "
               "instance image of a moved vertex moved likewise",
               [] {
                 return rc::detail::toProperty(
                     [] { smoothing_keeps_a_templated_mesh<D>(*valid_templated_mesh<D>()); });
               },
               [] {
                 return rc::detail::toProperty([] {
                   const auto s = *valid_templated_mesh<D>();
                   SYMMESH_PROOF_ASSERT(is_templated_mesh<D>(move_interface_vertex<D>(s.x)),
                                        record(s), picture(s));
                 });
               }});
}

} // namespace

void register_section_5_2_2(std::vector<Property>& p) {
  add<2>(p);
  add<3>(p);
}

} // namespace symmesh::proofs
