// libFuzzer harness: random sequences of template cloning, merging and splitting (Section 5.2.1
// on a generated templated mesh, adapt/tmesh_template_cloning.h; `symmesh adapt --clone K
// --split-where EXPR --merge-identical`), mixed with edge bisections that make templates differ.
// The first byte picks one of four small generated meshes (2D n-gon slices, a reflective-rotational
// star, the cube halves and the 8-TSV in 3D); every further 2 bytes are one operation:
//   - clone the template of an instance: must succeed when that template has two or more
//     instances and throw std::invalid_argument otherwise (the documented precondition);
//   - merge two templates: must succeed when they are distinct and identical, and throw
//     std::invalid_argument otherwise;
//   - merge every identical template, or (one in four) every template congruent up to 1e-9 of
//     its diameter (`--merge-congruent --congruence-tolerance 1e-9`: exact motions first, then
//     up to rounding, which may move AT's points of the merged instances by rounding, so AT is
//     then compared by the certificate only);
//   - split a template along a pseudo-random cell subset: must succeed when the subset is
//     non-empty and proper, and throw std::invalid_argument otherwise;
//   - bisect one template edge (with its related edges): the templates cloned before now differ.
// After each operation the compact SVB is valid and the structure instance conforms (the
// certificate, with the seed's boundary measure). Cloning, merging and splitting must leave AT
// exactly as it was: the same number of AT vertices (the identifications survive), and the same
// cells, as a multiset of (region, the written coordinates of the cell's vertices), compared bit
// for bit — the transformations and template coordinates are not changed, so no rounding may enter.
// Any other exception, a failed check, a crash or a hang is a finding.
#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/adapt/tmesh_template_cloning.h"
#include "symmesh/api/generate_run.h"
#include "symmesh/io/examples.h"
#include "symmesh/mesh/structure_instance.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace {
using symmesh::mesh::IndexType;
using symmesh::mesh::TemplatedMeshCompactSvb;

struct Seed {
  TemplatedMeshCompactSvb mesh;
  double boundary = 0;
};

const std::vector<Seed>& seeds() {
  static const std::vector<Seed> all = [] {
    const std::array<std::pair<const char*, double>, 4> objects{
        {{"ngon-slice-5", 0.4},
         {"star-reflective-rotational", 0.4},
         {"cube-halves", 0.8},
         {"tsv-8", 0.8}}};
    std::vector<Seed> out;
    for (const auto& [name, size] : objects) {
      symmesh::api::RunOptions o;
      o.size = size;
      o.min_angle = 20;
      const auto x =
          symmesh::api::parse_structure_text(symmesh::io::example_document(name).dump(), name);
      Seed s;
      s.mesh = symmesh::api::run_generation(x, name, o).templated;
      s.boundary = symmesh::adapt::certify_conformity(s.mesh).boundary_measure;
      out.push_back(std::move(s));
    }
    return out;
  }();
  return all;
}

/// One cell of AT as the writers see it: its region and its vertices' written coordinates.
using AtCell = std::pair<long long, std::array<std::array<double, 3>, 4>>;

/// AT by coordinates: the number of AT vertices and the sorted multiset of its cells (each with
/// its vertices sorted), independent of the instance numbering that cloning changes.
struct AtByCoordinates {
  std::size_t vertices = 0;
  std::vector<AtCell> cells;
  bool operator==(const AtByCoordinates& o) const {
    return vertices == o.vertices && cells == o.cells;
  }
};

AtByCoordinates at_of(const TemplatedMeshCompactSvb& t) {
  const symmesh::mesh::StructureInstance view(t);
  const int d = view.dimension();
  AtByCoordinates a;
  a.vertices = view.vertex_count();
  view.for_each_cell([&](const symmesh::mesh::StructureInstance::Instance& in, std::size_t c,
                         const std::array<IndexType, 4>&) {
    const auto& m = in.mesh_template->mesh;
    AtCell cell{(long long)in.region, {}};
    const int n = symmesh::mesh::vertex_count(m.cell_types[c]);
    for (int k = 0; k < n; ++k) {
      double image[3] = {0, 0, 0};
      in.transformation->apply(&m.vertex_coords[std::size_t(m.cell(c)[k]) * std::size_t(d)], image);
      cell.second[std::size_t(k)] = {image[0], image[1], image[2]};
    }
    std::sort(cell.second.begin(), cell.second.end());
    a.cells.push_back(cell);
  });
  std::sort(a.cells.begin(), a.cells.end());
  return a;
}

void check(const TemplatedMeshCompactSvb& t, const Seed& s) {
  if (!t.is_valid()) __builtin_trap();
  if (!symmesh::adapt::certify_conformity(t, s.boundary).holds) __builtin_trap();
}

/// Runs `op`, which must throw std::invalid_argument exactly when `allowed` is false.
template <class F>
void expect_refusal_unless(bool allowed, F&& op) {
  bool refused = false;
  try {
    op();
  } catch (const std::invalid_argument&) {
    refused = true;
  }
  if (refused == allowed) __builtin_trap();
}

/// One operation from two bytes; returns whether it must keep AT exactly.
bool apply(TemplatedMeshCompactSvb& t, const std::uint8_t* op) {
  namespace adapt = symmesh::adapt;
  const auto& templates = t.templated.templates;
  switch (op[0] % 5) {
  case 0: { // clone the template of one instance
    const std::size_t instance = op[1] % t.templated.instance_count();
    std::size_t first = 0, ti = 0;
    while (instance >= first + templates[ti].instance_count())
      first += templates[ti++].instance_count();
    expect_refusal_unless(templates[ti].instance_count() >= 2,
                          [&] { adapt::clone_template(t, instance); });
    return true;
  }
  case 1: { // merge two templates
    const std::size_t i = op[1] % 16 % templates.size(), j = op[1] / 16 % templates.size();
    expect_refusal_unless(i != j && adapt::identical_templates(t, i, j),
                          [&] { adapt::merge_templates(t, i, j); });
    return true;
  }
  case 2:
    if (op[1] % 4 == 3) {
      adapt::merge_congruent_templates(t, 1e-9);
      return false;
    }
    adapt::merge_identical_templates(t);
    return true;
  case 3: { // split a template along about one in k of its cells, k = 2..7
    const std::size_t ti = op[1] % templates.size(), k = 2 + op[0] / 5 % 6;
    const std::size_t cells = templates[ti].mesh.cell_count();
    std::vector<std::size_t> part;
    for (std::size_t c = 0; c < cells; ++c)
      if ((((c + op[1]) * 2654435761u) >> 13) % k == 0) part.push_back(c);
    expect_refusal_unless(!part.empty() && part.size() < cells,
                          [&] { adapt::split_template(t, ti, part); });
    return true;
  }
  default: { // bisect one edge of one cell, with its related edges
    adapt::expand_identifications(t);
    const std::size_t ti = op[1] % templates.size();
    const auto& m = templates[ti].mesh;
    const std::size_t c = (std::size_t(op[1] / 8) * 2654435761u) % m.cell_count();
    const int arity = t.templated.point_dimension + 1;
    const int k = op[0] / 4 % arity, l = (k + 1 + op[0] / 16 % (arity - 1)) % arity;
    const IndexType a = m.cell(c)[k], b = m.cell(c)[l];
    adapt::bisect_edges(t, {{ti, std::min(a, b), std::max(a, b)}});
    return false;
  }
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 41) return 0; // at most 20 operations: each input stays fast
  const auto& s = seeds()[data[0] % seeds().size()];
  auto t = s.mesh;
  auto before = at_of(t);
  for (std::size_t i = 1; i + 2 <= size; i += 2) {
    std::size_t cells = 0;
    for (const auto& mt : t.templated.templates) cells += mt.mesh.cell_count();
    if (cells > 400) break; // bisections grow the templates; keep every input's cost bounded
    const bool keeps_at = apply(t, data + i);
    check(t, s);
    auto after = at_of(t);
    if (keeps_at && !(after == before)) __builtin_trap();
    before = std::move(after);
  }
  return 0;
}
