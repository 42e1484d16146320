/// The templated CSR matrix (TCSR, Listing 7.1), Algorithm 7.1 (TCSR → CSR) and Algorithm 7.2
/// (matrix-vector product) — spec/fem.md#tcsr
///
/// A templated mesh stores each template once; so does its system matrix. The P1 stiffness
/// matrix of a template is assembled once, with coefficient 1 (a rigid motion does not change
/// it), and an instance contributes κ_region · P_iᵀ K_t P_i, where P_i maps the template's
/// vertices to the global unknowns. Listing 7.1 stores P_i as a full local-to-global map per
/// instance. Here a template's rows are ordered boundary vertices first; an instance's interior
/// vertices belong to it alone, so the global numbering gives them one consecutive range and
/// only the boundary rows are looked up: the map of an instance costs O(template boundary), not
/// O(template). Dirichlet unknowns are eliminated symmetrically (rows and columns replaced by the
/// identity); they are marked in the boundary maps as −1 − g, so the constrained product needs no
/// extra memory.
#pragma once
#include "symmesh/fem/csr_matrix.h"
#include "symmesh/mesh/templated_mesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <vector>

namespace symmesh::fem {

/// One template's matrix: rows [0, boundary) are its boundary vertices (in vertex order), rows
/// [boundary, vertices) its interior vertices (in vertex order). Only what the product needs is
/// kept (the boundary facets and loads are recomputed from the mesh where boundary conditions
/// need them), so that a template costs about its share of the conventional matrix.
struct TemplateMatrix {
  std::size_t vertices = 0, boundary = 0;
  std::vector<GlobalIndex> row_of; ///< template vertex -> row
  CsrMatrix stiffness;             ///< rows and columns in row order, coefficient 1
  /// The P1 mass matrix's values on the stiffness pattern (empty: no reaction term anywhere).
  std::vector<double> mass;

  /// row -> template vertex (the inverse of row_of).
  std::vector<GlobalIndex> vertex_of() const;
  std::size_t bytes() const {
    return stiffness.bytes() + mass.size() * sizeof(double) + row_of.size() * sizeof(GlobalIndex);
  }
};

/// One instance: its template, coefficient, the global id of its first interior row and the
/// global ids of its boundary rows (−1 − g: g is a Dirichlet unknown). The boundary ids are kept
/// as runs (rows r … r + n − 1 ↦ first + δ·(r' − r), δ = ±1) when that is smaller than the list:
/// an instance numbers its new boundary unknowns consecutively along its template's line meshes,
/// so a slice of an n-gon needs a handful of runs, not one id per boundary vertex.
struct InstanceMap {
  struct Run {
    std::uint32_t row = 0, length = 0;
    GlobalIndex first = 0;
    std::int32_t delta = 1;
  };
  std::uint32_t template_index = 0;
  double coefficient = 1; ///< κ of its region: the instance adds κ K_t + σ M_t
  double reaction = 0;    ///< σ of its region (0 unless a reaction term is given)
  GlobalIndex interior_first = 0;
  std::size_t boundary_rows = 0;

  /// Stores the boundary ids (one per boundary row) as runs or as a list, whichever is smaller.
  void set_boundary(const std::vector<GlobalIndex>& ids);
  /// Boundary id of row r (encoded: negative for Dirichlet). \pre r < boundary_rows
  GlobalIndex boundary(std::size_t r) const;
  /// All boundary ids, expanded, into `out` (resized).
  void boundary_ids(std::vector<GlobalIndex>& out) const;
  std::vector<GlobalIndex> boundary_ids() const {
    std::vector<GlobalIndex> out;
    boundary_ids(out);
    return out;
  }
  std::size_t bytes() const {
    return sizeof(std::uint32_t) + 2 * sizeof(double) + sizeof(GlobalIndex) + sizeof(std::size_t) +
           list_.size() * sizeof(GlobalIndex) + runs_.size() * sizeof(Run);
  }
  bool uses_runs() const { return !runs_.empty(); }

private:
  std::vector<GlobalIndex> list_;
  std::vector<Run> runs_;
};

struct TemplatedCsr {
  int dimension = 2;
  std::size_t unknowns = 0;
  std::vector<TemplateMatrix> templates;
  std::vector<InstanceMap> instances; ///< global instance order (template-major)
  std::vector<GlobalIndex> dirichlet; ///< sorted

  /// Global unknown of template vertex `vertex` of instance `instance`.
  GlobalIndex global(std::size_t instance, std::size_t vertex) const;
  bool is_dirichlet_row(std::size_t instance, std::size_t row) const {
    const auto& in = instances[instance];
    return row < in.boundary_rows && in.boundary(row) < 0;
  }
  /// Algorithm 7.2: y = A x over the instances (constrained: the Dirichlet rows and columns are
  /// the identity). \pre x, y have `unknowns` entries
  void multiply(const double* x, double* y, bool constrained = true) const;
  /// The diagonal without forming the CSR matrix (for Jacobi).
  std::vector<double> diagonal(bool constrained = true) const;
  /// Algorithm 7.1: the same operator as a CSR matrix.
  CsrMatrix to_csr(bool constrained = true) const;
  /// Marks these unknowns as Dirichlet unknowns (replacing earlier marks).
  void set_dirichlet(std::vector<GlobalIndex> nodes);

  std::size_t bytes() const;
  bool is_valid(std::ostream* why = nullptr) const;
};

/// The boundary facets of a simplex mesh (facets in exactly one cell; D vertex ids each, sorted,
/// the third id −1 in 2D). Throws std::invalid_argument for a facet in more than two cells.
std::vector<std::array<GlobalIndex, 3>> template_boundary_facets(const mesh::Mesh& m, int dim);

/// Algorithm 7.2 over any list of instances in any index space of `unknowns` entries (the whole
/// system, or one MPI rank's owned and ghost unknowns): y = Σ κ_i P_iᵀ K_t P_i x, and with
/// `constrained` the Dirichlet rows and columns (negative boundary ids) as the identity on the
/// listed `dirichlet` unknowns.
void multiply_instances(const std::vector<TemplateMatrix>& templates,
                        const std::vector<InstanceMap>& instances, std::size_t unknowns,
                        const std::vector<GlobalIndex>& dirichlet, const double* x, double* y,
                        bool constrained);

/// Adds the diagonals κ_i (K_t)_rr + σ_i (M_t)_rr of the listed instances into d (in their index
/// space), leaving out the Dirichlet rows (negative boundary ids) when `skip_dirichlet`, without
/// forming the matrix: the Jacobi preconditioner of the TCSR and of its PETSc MATSHELL.
void add_diagonal_instances(const std::vector<TemplateMatrix>& templates,
                            const std::vector<InstanceMap>& instances, bool skip_dirichlet,
                            double* d);

/// Assembles the TCSR of a templated mesh (triangles in 2D, tetrahedra in 3D): every template's
/// stiffness once, the global numbering from the compact SVB (union-find over the instances'
/// boundary rows; each instance's interior rows numbered consecutively after its new boundary
/// unknowns), each instance's coefficient coefficient(region).
/// With `reaction` (σ per region, −div(κ∇u) + σu = f), every template's P1 mass matrix is
/// assembled too, on the same pattern.
/// \pre t.is_valid(); every coefficient positive and finite, every reaction ≥ 0 and finite (else
/// std::invalid_argument naming the region)
TemplatedCsr
assemble_templated_csr(const mesh::TemplatedMeshCompactSvb& t,
                       const std::function<double(mesh::RegionIdType)>& coefficient,
                       const std::function<double(mesh::RegionIdType)>& reaction = nullptr);

/// Where the direct assembly takes a cell's vertex coordinates from (spec/fem.md#tcsr).
enum class CellCoordinates {
  /// AT's vertices as written (double): each the rounded image of one instance's template vertex.
  structure_instance,
  /// Each cell's vertices as its own instance's transformation of the template's, evaluated in
  /// long double: AT's cells without the rounding of AT's coordinates, which moves a vertex by
  /// up to ε|x| and so changes an element matrix by about ε|x|/h times its shape factor.
  extended_per_cell,
};

/// The CSR matrix assembled directly on the structure instance (every cell of AT from its own
/// transformed coordinates, times its region's coefficient), numbered like `numbering` (the
/// TCSR's global ids), unconstrained: the reference Algorithm 7.1 must reproduce.
CsrMatrix
assemble_structure_instance_csr(const mesh::TemplatedMeshCompactSvb& t,
                                const std::function<double(mesh::RegionIdType)>& coefficient,
                                const std::function<double(mesh::RegionIdType)>& reaction,
                                const TemplatedCsr& numbering,
                                CellCoordinates coordinates = CellCoordinates::structure_instance);

/// Replaces rows and columns of the sorted Dirichlet unknowns by the identity.
CsrMatrix constrain(const CsrMatrix& a, const std::vector<GlobalIndex>& dirichlet);

} // namespace symmesh::fem
