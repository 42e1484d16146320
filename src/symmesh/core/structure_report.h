/// What `symmesh check` decides about a templated structure — spec/definitions.md#check-verdicts
///
/// Classification along Definitions 4.3 and 4.4: well-formed input, templated structure (Eq. 4.2),
/// templated mesh (AT conforming, decided directly) or templated geometry, the Lemma 4.2
/// checker's verdict (which must agree with the direct decision), the instance graph, and its
/// regularity (Def 4.9) with the boundary patch counts of Algorithm 4.1.
#pragma once
#include "symmesh/core/boundary_patch_partition.h"
#include "symmesh/core/instance_graph.h"
#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/kernel.h"
#include "symmesh/number/cyclotomic.h"

#include <optional>
#include <sstream>
#include <type_traits>
#include <string>
#include <vector>

namespace symmesh::core {

using symmesh::Exact;

struct GraphEdgeSummary {
  std::size_t template_a, template_b;
  InterfaceEdge edge;
};

/// Boundary patches of one template (Algorithm 4.1): facet patches (dimension D-1) and the
/// lower-dimensional ones (points, and segments in 3D).
struct PatchCounts {
  std::size_t facet_patches = 0, lower_dimensional_patches = 0;
};

/// Exact text of a number: "n" or "n/d" in lowest terms for rationals, "K<m>[a_0, ...]" (the
/// coefficients in the basis of spec/number-type.md) for elements of K_m. Reports hold text so
/// that they do not depend on the kernel the structure was analysed in.
template <class T>
struct IsLazyExact : std::false_type {};
template <class ET>
struct IsLazyExact<CGAL::Lazy_exact_nt<ET>> : std::true_type {};

template <class FT>
std::string exact_text(const FT& x) {
  std::ostringstream os;
  if constexpr (IsLazyExact<FT>::value)
    os << CGAL::exact(x);
  else
    os << x;
  return os.str();
}

/// An irregularity witness (Def 4.9) reduced to what a report prints. Compositions are lists of
/// mapping names, first applied first (an empty list is the identity). The symmetry
/// F1^{-1} ∘ F2 is kept as exact text (exact_text).
struct IrregularitySummary {
  std::size_t patch = 0, target = 0; ///< indices into the partition's patch list
  std::vector<std::string> f1, f2;
  std::vector<std::vector<std::string>> symmetry_matrix;
  std::vector<std::string> symmetry_translation;
};

template <class FT, int D>
IrregularitySummary summarise_irregularity(const BoundaryPatchPartition<FT, D>& bpp) {
  const auto& w = *bpp.irregularity;
  IrregularitySummary s;
  s.patch = w.patch;
  s.target = w.target;
  for (std::size_t l : w.f1.letters) s.f1.push_back(bpp.mappings[l].name());
  for (std::size_t l : w.f2.letters) s.f2.push_back(bpp.mappings[l].name());
  for (int i = 0; i < D; ++i) {
    s.symmetry_matrix.emplace_back();
    for (int j = 0; j < D; ++j)
      s.symmetry_matrix.back().push_back(exact_text(w.symmetry.matrix()[i][j]));
    s.symmetry_translation.push_back(exact_text(w.symmetry.translation_part()[i]));
  }
  return s;
}

struct StructureReport {
  int dimension = 0;
  /// The exact kernel the structure was read in (set by the reader, io::kernel_name): empty for
  /// the default rationals; field_m is m of K_m, 0 for rationals.
  std::string kernel;
  int field_m = 0;
  std::size_t templates = 0, instances = 0;
  bool mesh_templates = true;
  bool well_formed = false;
  std::string error; ///< why it is not well-formed or not a templated structure
  bool templated_structure = false;
  std::optional<OverlapWitness> overlap;
  bool at_conforming = false;
  bool templated_mesh = false;
  bool templated_geometry = false;
  Lemma42Verdict lemma42;
  bool lemma42_agrees = true;
  std::vector<std::string> template_names;
  std::vector<GraphEdgeSummary> graph_edges;
  std::size_t structure_instance_vertices = 0, structure_instance_cells = 0;
  /// Boundary patch partition (set for templated structures): computed unless 𝔗_X exceeded the
  /// default guard, which is reported in bpp_error rather than failing the whole check.
  bool bpp_computed = false;
  std::string bpp_error;
  bool regular = false; ///< Def 4.9, when bpp_computed
  std::optional<IrregularitySummary> irregularity;
  std::vector<PatchCounts> patches_per_template;
};

/// The composition guard of `check`, below BppOptions' default: the partition refinement is
/// quadratic in the length of a chain of composed images (a glide by 1/10000 already takes
/// about 40 s), and check must stay quick on any input. The 32-template, 200-instance
/// performance fixture needs about 4000; `symmesh bpp --max-compositions` goes further.
inline constexpr std::size_t kCheckMaxCompositions = 10000;

namespace detail {
/// Fills the regularity verdict and the patch counts of `r` from Algorithm 4.1.
/// \pre x.is_well_formed(), which `analyse`, its only caller, has just decided: the partition
/// does not decide it again (for a PLC template that would be a second exact conformity check of
/// its carrier, about half of the analysis of a small PLC structure).
template <class FT, int D>
void summarise_boundary_patches(const TemplatedStructure<FT, D>& x, StructureReport& r) {
  BppOptions options;
  options.max_compositions = kCheckMaxCompositions;
  options.well_formed_checked = true;
  try {
    const auto bpp = boundary_patch_partition(x, options);
    r.bpp_computed = true;
    r.regular = bpp.regular();
    if (!r.regular) r.irregularity = summarise_irregularity(bpp);
    for (std::size_t t = 0; t < x.templates.size(); ++t) {
      PatchCounts c;
      for (std::size_t p : bpp.bndpart(t))
        (bpp.patches[p].dimension == D - 1 ? c.facet_patches : c.lower_dimensional_patches)++;
      r.patches_per_template.push_back(c);
    }
  } catch (const CompositionLimitExceeded& e) {
    r.bpp_error = e.what();
  }
}
} // namespace detail

template <class FT, int D>
StructureReport analyse(const TemplatedStructure<FT, D>& x) {
  StructureReport r;
  r.dimension = D;
  r.templates = x.templates.size();
  for (const auto& t : x.templates) r.template_names.push_back(t.name);
  r.instances = x.instance_ids().size();
  r.mesh_templates = x.all_of_kind(TemplateKind::mesh);
  std::ostringstream why;
  r.well_formed = x.is_well_formed(&why);
  if (!r.well_formed) {
    r.error = why.str();
    return r;
  }
  r.overlap = find_instance_overlap(x);
  r.templated_structure = !r.overlap.has_value();
  if (!r.templated_structure) {
    r.error = overlap_message(*r.overlap);
    return r;
  }
  const auto si = apply_template(x);
  r.structure_instance_vertices = si.at.mesh.points.size();
  r.structure_instance_cells = si.at.cell_region.size();
  const auto g = instance_graph(x, si);
  for (auto [e, end] = boost::edges(g); e != end; ++e)
    r.graph_edges.push_back({boost::source(*e, g), boost::target(*e, g), g[*e]});
  detail::summarise_boundary_patches(x, r);
  if (r.mesh_templates) {
    r.at_conforming = structure_instance_conforming(si);
    r.lemma42 = check_interface_conformity(x, si);
    r.lemma42_agrees = r.lemma42.holds == r.at_conforming;
    r.templated_mesh = r.at_conforming;
  } else {
    r.templated_geometry = true; // Definition 4.4: AT of geometry templates is a geometry
    r.at_conforming = true;
  }
  return r;
}

// Instantiated once, in instantiate.cpp for the default exact kernel.
extern template StructureReport analyse<Exact, 2>(const TemplatedStructure<Exact, 2>&);
extern template StructureReport analyse<Exact, 3>(const TemplatedStructure<Exact, 3>&);

/// The analysis of a structure over K_m (spec/number-type.md#core-over-k-m). It runs on
/// CGAL::Lazy_exact_nt<Cyclotomic>, as Epeck does over the rationals: certified interval
/// approximations decide most signs, and exact field arithmetic is done only where they do not
/// (degenerate, i.e. zero, signs). Defined in lazy_cyclotomic_instantiations.cpp.
StructureReport analyse(const TemplatedStructure<number::Cyclotomic, 2>& x);
StructureReport analyse(const TemplatedStructure<number::Cyclotomic, 3>& x);

} // namespace symmesh::core
