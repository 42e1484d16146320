// libFuzzer harness: Technique 5.8 in 3D (adapt::make_delaunay on a generated templated mesh,
// spec/adaptation.md#technique-5-8) on random templated geometries of boxes, after random
// bisections and smoothing sweeps. fuzz_adapt leaves Technique 5.8 to its 2D seeds (in 3D every
// round re-tetrahedralizes the templates with TetGen, too slow for that harness's budget); this
// harness is about it alone.
//
// Bytes 0-5 choose the geometry as the 3D Technique 5.8 properties do
// (proofs-checks/technique_5_8_make_delaunay.cpp, box_inputs.h, acute_prism.h): with bit 2 of
// byte 0 clear, a grid of boxes, one template instanced by translations or with every odd column
// mirrored in x, or a block on a base slab (two templates, a T-junction of the boundary patches,
// not convex), right angles only; with it set, a triangular prism with an acute crease of 1-59
// degrees between its legs (second leg 0.3-1.5), alone or mirrored across its first leg, refined
// 0-2 times — the input of Technique 5.8's crease mirroring. Every further 3 bytes are one
// operation before Technique 5.8: a bisection of one template edge (with its related edges) or
// smoothing sweeps (boundary vertices too, moved with their related copies); inputs that grow a
// mesh past 400 template cells stop there. Then Technique 5.8 runs with its round cap of 32.
//
// After every operation: the compact SVB is valid, the conformity certificate holds with AT's
// boundary area unchanged, and AT's volume is exactly the boxes' (the doubles taken as
// rationals; a prism's within 1e-12 of it: its slanted leg is rounded). After Technique 5.8:
// also every interior triangle of AT is locally Delaunay by exact in-sphere signs with no
// allowance for boxes (every instance matrix is a signed permutation, so the library resolves
// every tie), up to ties by rounding (|D| / L^5 <= 1e-9) for prisms (mirror points across a
// slanted bisector are rounded), and no triangle lies in three cells (exact_delaunay_verdict).
// AdaptationLimit (the round cap, or a facet Technique 5.8 cannot make locally Delaunay: its
// documented clear error) is a refusal, not a finding; any other exception, a failed check, a
// crash or a hang is a finding.
#include "proofs-checks/acute_prism.h"
#include "proofs-checks/box_inputs.h"
#include "proofs-checks/exact_delaunay_verdict.h"
#include "symmesh/api/generate_run.h"
#include "symmesh/adapt/templated_mesh_adaptation.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {
using symmesh::mesh::TemplatedMeshCompactSvb;
using symmesh::proofs::boxes::BoxInput;

/// The geometry from bytes 0-5, in the ranges of the property's generators (box_grid,
/// block_on_base).
BoxInput geometry_of(const std::uint8_t* b) {
  namespace boxes = symmesh::proofs::boxes;
  if (b[0] & 1)
    return boxes::block_on_base_of(3, 4 + b[1] % 3, 1 + b[2] % 2, 2 + b[3] % 3, 2 + b[4] % 3,
                                   1 + b[5] % 3, b[0] / 2 % 3);
  std::vector<int> counts{1 + b[4] % 3, 1 + b[4] / 3 % 2, 1 + b[4] / 6 % 2};
  if (counts[0] * counts[1] * counts[2] == 1) counts[0] = 2; // at least two instances
  return boxes::grid_of_boxes(3, {2 + b[1] % 3, 2 + b[2] % 3, 2 + b[3] % 3}, counts, b[0] & 2,
                              1 + b[5] % 2);
}

struct Seed {
  TemplatedMeshCompactSvb mesh;
  double boundary = 0;
  mpq_class volume;
  bool exact = true; ///< boxes: the volume and the Delaunay verdict are exact
};

/// The prism from bytes 1-4 (byte 0 has bit 2 set).
Seed prism_of(const std::uint8_t* b) {
  const symmesh::proofs::AcutePrism p{1 + b[1] % 59, (3 + b[2] % 13) / 10.0, bool(b[3] & 1),
                                      b[4] % 3};
  Seed s;
  s.mesh = p.build();
  s.boundary = symmesh::adapt::certify_conformity(s.mesh).boundary_measure;
  s.volume = symmesh::proofs::boxes::exact_measure(s.mesh);
  s.exact = false;
  return s;
}

/// The generated mesh of a geometry, made once: generation (TetGen under the sanitizers) costs as
/// much as the rest of an input, and the bytes allow a few thousand geometries only. Null when
/// generation refuses the geometry: generation is fuzz_generate's subject, not this harness's.
/// (The first campaign saw the carrier tetrahedralization's forked TetGen process die on a block
/// on a base that the same binary meshes when the input is run alone: spec/adaptation.md.)
const Seed* seed_of(const BoxInput& in) {
  static std::map<std::string, Seed> made;
  const auto key = in.description();
  const auto it = made.find(key);
  if (it != made.end()) return &it->second;
  Seed s;
  try {
    s.mesh = in.generate();
  } catch (const symmesh::api::Refusal&) {
    return nullptr;
  }
  s.boundary = symmesh::adapt::certify_conformity(s.mesh).boundary_measure;
  s.volume = in.measure();
  if (made.size() >= 256) made.clear(); // bounded memory over a long campaign
  return &made.emplace(key, std::move(s)).first->second;
}

void check(const TemplatedMeshCompactSvb& t, const Seed& s) {
  if (!t.is_valid()) __builtin_trap();
  if (!symmesh::adapt::certify_conformity(t, s.boundary).holds) __builtin_trap();
  const mpq_class v = symmesh::proofs::boxes::exact_measure(t);
  if (s.exact ? v != s.volume
              : std::abs(mpq_class(v - s.volume).get_d()) > 1e-12 * s.volume.get_d())
    __builtin_trap();
}

std::size_t template_cells(const TemplatedMeshCompactSvb& t) {
  std::size_t cells = 0;
  for (const auto& mt : t.templated.templates) cells += mt.mesh.cell_count();
  return cells;
}

/// One operation before Technique 5.8, from three bytes.
void apply(TemplatedMeshCompactSvb& t, const std::uint8_t* op) {
  namespace adapt = symmesh::adapt;
  const auto& templates = t.templated.templates;
  if (op[0] % 2 == 0) { // bisect one edge of one cell
    const std::size_t ti = op[1] % templates.size();
    const auto& m = templates[ti].mesh;
    const std::size_t c = (std::size_t(op[2]) * 2654435761u) % m.cell_count();
    const int k = op[1] / 16 % 4, l = (k + 1 + op[1] / 64 % 3) % 4;
    const auto a = m.cell(c)[k], b = m.cell(c)[l];
    adapt::bisect_edges(t, {{ti, std::min(a, b), std::max(a, b)}});
  } else {
    adapt::smooth_vertices(t, 1 + op[1] % 2, op[2] & 1);
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 6 || size > 6 + 3 * 6) return 0; // at most six operations: each input stays fast
  Seed prism;
  const bool is_prism = data[0] & 4;
  if (is_prism) prism = prism_of(data);
  const auto* seed = is_prism ? &prism : seed_of(geometry_of(data));
  if (!seed) return 0;
  const auto& s = *seed;
  auto t = s.mesh;
  for (std::size_t i = 6; i + 3 <= size && template_cells(t) <= 400; i += 3) {
    apply(t, data + i);
    check(t, s);
  }
  try {
    symmesh::adapt::make_delaunay(t, 32);
  } catch (const symmesh::adapt::AdaptationLimit&) {
    return 0; // the documented refusal
  }
  check(t, s);
  const auto verdict = symmesh::proofs::exact_delaunay_verdict(t);
  if (verdict.overfull != 0 || (s.exact ? verdict.not_locally_delaunay : verdict.beyond_rounding))
    __builtin_trap();
  if (s.exact && verdict.volume != s.volume) __builtin_trap();
  return 0;
}
