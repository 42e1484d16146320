// The public C++ API (symmesh.h, docs/api.md) over the library layers: the same reader, checker,
// generation run and writers as the CLI.
#include "symmesh/symmesh.h"

#include "symmesh/api/generate_run.h"
#include "symmesh/core/structure_report.h"
#include "symmesh/io/examples.h"
#include "symmesh/io/mesh_writers.h"
#include "symmesh/io/report_json.h"
#include "symmesh/io/templated_mesh_file.h"
#include "symmesh/mesh/structure_instance.h"

#include <array>
#include <chrono>
#include <iostream>
#include <variant>

#ifndef SYMMESH_VERSION
#error "SYMMESH_VERSION is set by CMake (the project version)"
#endif

namespace symmesh {

// The public header keeps its own literal so that it includes nothing of the library.
static_assert(GenerateOptions{}.tetgen_dihedral == mesh::kDihedralBoundDeg);

std::string version() {
  return SYMMESH_VERSION;
}

struct Structure::Impl {
  io::AnyStructure x;
  std::string source;
};

struct Generation::Impl {
  gen::GenerationResult r;
  std::string report;
  std::size_t cells = 0, points = 0, template_cells = 0;
};

namespace {

/// Runs f and turns a Refusal into the API's exception of the same exit code.
template <class F>
auto translating_refusals(F&& f) {
  try {
    return f();
  } catch (const api::Refusal& e) {
    if (e.exit_code() == api::kNegative) throw CertificateError(e.what());
    throw InputError(e.what());
  }
}

template <class FT, int D>
int dimension_of(const core::TemplatedStructure<FT, D>&) {
  return D;
}

/// Template coordinates padded to x, y, z.
void append_points(const mesh::Mesh& m, std::vector<double>& points) {
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const double* x = m.vertex(v);
    for (int k = 0; k < 3; ++k) points.push_back(k < m.point_dimension ? x[k] : 0.0);
  }
}

/// \pre every cell of `t` is a simplex of its dimension (what the generators make)
void require_simplices(const mesh::TemplatedMeshCompactSvb& t) {
  const auto want = t.templated.point_dimension == 3 ? mesh::ElementType::tetrahedron
                                                     : mesh::ElementType::triangle;
  for (const auto& tm : t.templated.templates)
    for (const auto type : tm.mesh.cell_types)
      if (type != want) throw std::logic_error("symmesh: a generated template has mixed cells");
}

} // namespace

Structure Structure::read(const std::string& path) {
  return translating_refusals([&] {
    return Structure(std::make_shared<const Impl>(Impl{api::read_structure_file(path), path}));
  });
}

Structure Structure::parse(const std::string& json_text, const std::string& source) {
  return translating_refusals([&] {
    return Structure(
        std::make_shared<const Impl>(Impl{api::parse_structure_text(json_text, source), source}));
  });
}

Structure Structure::example(const std::string& name) {
  std::string text;
  try {
    text = io::example_document(name).dump();
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("example: ") + e.what());
  }
  return parse(text, name);
}

std::vector<std::string> Structure::example_names() {
  std::vector<std::string> out;
  for (const auto& e : io::example_list()) out.push_back(e.name);
  return out;
}

int Structure::dimension() const {
  return std::visit([](const auto& s) { return dimension_of(s); }, impl_->x);
}

std::size_t Structure::template_count() const {
  return std::visit([](const auto& s) { return s.templates.size(); }, impl_->x);
}

std::size_t Structure::instance_count() const {
  return std::visit([](const auto& s) { return s.instance_ids().size(); }, impl_->x);
}

std::vector<std::string> Structure::template_names() const {
  return std::visit(
      [](const auto& s) {
        std::vector<std::string> out;
        for (const auto& t : s.templates) out.push_back(t.name);
        return out;
      },
      impl_->x);
}

const std::string& Structure::source() const {
  return impl_->source;
}

std::string Structure::kernel() const {
  return io::kernel_name(impl_->x);
}

CheckResult Structure::check() const {
  core::StructureReport r = std::visit([](const auto& s) { return core::analyse(s); }, impl_->x);
  r.kernel = io::kernel_name(impl_->x);
  r.field_m = io::field_order(impl_->x);
  if (!r.well_formed) throw InputError(impl_->source + ": " + r.error);
  CheckResult c;
  c.templated_structure = r.templated_structure;
  c.templated_mesh = r.templated_mesh;
  c.templated_geometry = r.templated_geometry;
  c.lemma_4_2_checked = r.templated_structure && r.mesh_templates;
  c.lemma_4_2_holds = c.lemma_4_2_checked && r.lemma42.holds;
  if (c.lemma_4_2_checked && !r.lemma42.holds) {
    c.lemma_4_2_failing_pair = core::to_string(r.lemma42.a) + ", " + core::to_string(r.lemma42.b);
    c.lemma_4_2_condition = r.lemma42.condition;
  }
  c.regularity_known = r.bpp_computed;
  c.regular = r.bpp_computed && r.regular;
  for (const auto& e : r.graph_edges)
    c.instance_graph.push_back(
        {e.edge.a.i, e.edge.a.g, e.edge.b.i, e.edge.b.g, e.edge.trivial, e.edge.label()});
  c.json = io::report_to_json(r);
  // The verdicts and messages of `symmesh check` (apps/cmd_check.cpp).
  if (!r.templated_structure) {
    c.exit_code = api::kBadInput;
    c.message = impl_->source + ": not a templated structure: " + r.error;
  } else if (r.mesh_templates && !r.templated_mesh) {
    c.exit_code = api::kNegative;
    c.message = impl_->source + " is a templated structure but not a templated mesh (Lemma 4.2 " +
                "fails for " + c.lemma_4_2_failing_pair + ")";
  }
  return c;
}

Generation::Generation(const Structure& structure, const GenerateOptions& options) {
  api::RunOptions o;
  o.method = options.method;
  o.size = options.size;
  o.min_angle = options.min_angle;
  o.max_cells = options.max_cells;
  o.repair_outliers = options.repair_outliers;
  o.tetgen_dihedral = options.tetgen_dihedral;
  std::unique_ptr<mesh::Progress> progress;
  if (options.progress) progress = std::make_unique<mesh::Progress>("symmesh generate", std::cerr);
  o.progress = progress.get();
  const auto start = std::chrono::steady_clock::now();
  auto impl = std::make_shared<Impl>();
  impl->r = translating_refusals([&] {
    api::check_method(o);
    api::check_numbers(o);
    return api::run_generation(structure.impl_->x, structure.source(), o);
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.reset();
  o.progress = nullptr;
  require_simplices(impl->r.templated);
  const mesh::StructureInstance at(impl->r.templated);
  impl->cells = at.cell_count();
  impl->points = at.vertex_count();
  for (const auto& t : impl->r.templated.templated.templates)
    impl->template_cells += t.mesh.cell_count();
  impl->report = api::generation_report(impl->r, o, seconds, 0).dump(2);
  impl_ = std::move(impl);
}

Generation generate(const Structure& structure, const GenerateOptions& options) {
  return Generation(structure, options);
}

const std::string& Generation::method() const {
  return impl_->r.method;
}
int Generation::dimension() const {
  return impl_->r.templated.templated.point_dimension;
}
std::size_t Generation::cell_count() const {
  return impl_->cells;
}
std::size_t Generation::point_count() const {
  return impl_->points;
}
std::size_t Generation::template_cell_count() const {
  return impl_->template_cells;
}
std::size_t Generation::template_count() const {
  return impl_->r.templated.templated.templates.size();
}
std::size_t Generation::instance_count() const {
  return impl_->r.templated.templated.instance_count();
}
const std::string& Generation::report_json() const {
  return impl_->report;
}

Mesh Generation::structure_instance() const {
  const mesh::StructureInstance at(impl_->r.templated);
  Mesh m;
  m.dimension = at.dimension();
  const int d = at.dimension(), k = d + 1;
  m.points.reserve(at.vertex_count() * 3);
  at.for_each_vertex([&](const double* x) {
    for (int c = 0; c < 3; ++c) m.points.push_back(c < d ? x[c] : 0.0);
  });
  m.cells.reserve(at.cell_count() * std::size_t(k));
  for (auto* a : {&m.region, &m.template_number, &m.instance_number}) a->reserve(at.cell_count());
  at.for_each_cell([&](const mesh::StructureInstance::Instance& in, std::size_t,
                       const std::array<mesh::IndexType, 4>& v) {
    m.cells.insert(m.cells.end(), v.begin(), v.begin() + k);
    m.region.push_back(std::int32_t(in.region));
    m.template_number.push_back(std::int32_t(in.template_index) + 1);
    m.instance_number.push_back(std::int32_t(in.index) + 1);
  });
  return m;
}

TemplatedMesh Generation::templated_mesh() const {
  const auto& t = impl_->r.templated.templated;
  TemplatedMesh out;
  out.dimension = t.point_dimension;
  for (std::size_t i = 0; i < t.templates.size(); ++i) {
    const auto& tm = t.templates[i];
    Mesh m;
    m.dimension = t.point_dimension;
    append_points(tm.mesh, m.points);
    m.cells = tm.mesh.cell_vertex_indices;
    m.region.assign(tm.mesh.cell_count(), -1);
    m.template_number.assign(tm.mesh.cell_count(), std::int32_t(i) + 1);
    m.instance_number.assign(tm.mesh.cell_count(), -1);
    out.templates.push_back(std::move(m));
    for (std::size_t g = 0; g < tm.instance_count(); ++g) {
      const auto& f = t.transformations[std::size_t(tm.transformation_indices[g])];
      out.instances.push_back({i, std::int32_t(tm.region_ids[g]), f.matrix, f.translation});
    }
  }
  return out;
}

void Generation::write(const std::string& path, const WriteOptions& options) const {
  const mesh::StructureInstance at(impl_->r.templated);
  io::MeshFileOptions w;
  w.ascii = options.ascii;
  w.compress = options.compress;
  try {
    io::write_mesh_file(at, path, w);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

void Generation::write_templated(const std::string& path) const {
  io::write_tmesh(impl_->r.templated, path);
}

} // namespace symmesh
