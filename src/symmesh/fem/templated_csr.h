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
/// [boundary, vertices) its interior vertices (in vertex order).
struct TemplateMatrix {
  std::size_t vertices = 0, boundary = 0;
  std::vector<GlobalIndex> row_of;         ///< template vertex -> row
  std::vector<GlobalIndex> vertex_of;      ///< row -> template vertex
  CsrMatrix stiffness;                     ///< rows and columns in row order, coefficient 1
  std::vector<std::int64_t> interior_from; ///< per row: first entry whose column is interior
  std::vector<double> lumped_load;         ///< per row: ∫ φ_row = Σ |T| / (D + 1)
  /// The template's boundary facets (D row ids each; a triangle in 3D, an edge in 2D).
  std::vector<std::array<GlobalIndex, 3>> boundary_facets;

  std::size_t bytes() const;
};

/// One instance: its template, coefficient, the global id of its first interior row and the
/// global ids of its boundary rows (−1 − g: g is a Dirichlet unknown).
struct InstanceMap {
  std::uint32_t template_index = 0;
  double coefficient = 1;
  GlobalIndex interior_first = 0;
  std::vector<GlobalIndex> boundary_global;

  std::size_t bytes() const {
    return sizeof(std::uint32_t) + sizeof(double) + sizeof(GlobalIndex) +
           boundary_global.size() * sizeof(GlobalIndex);
  }
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
    return row < in.boundary_global.size() && in.boundary_global[row] < 0;
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

/// Algorithm 7.2 over any list of instances in any index space of `unknowns` entries (the whole
/// system, or one MPI rank's owned and ghost unknowns): y = Σ κ_i P_iᵀ K_t P_i x, and with
/// `constrained` the Dirichlet rows and columns (negative boundary ids) as the identity on the
/// listed `dirichlet` unknowns.
void multiply_instances(const std::vector<TemplateMatrix>& templates,
                        const std::vector<InstanceMap>& instances, std::size_t unknowns,
                        const std::vector<GlobalIndex>& dirichlet, const double* x, double* y,
                        bool constrained);

/// Assembles the TCSR of a templated mesh (triangles in 2D, tetrahedra in 3D): every template's
/// stiffness once, the global numbering from the compact SVB (union-find over the instances'
/// boundary rows; each instance's interior rows numbered consecutively after its new boundary
/// unknowns), each instance's coefficient coefficient(region).
/// \pre t.is_valid(); every coefficient positive and finite (else std::invalid_argument naming
/// the region)
TemplatedCsr assemble_templated_csr(const mesh::TemplatedMeshCompactSvb& t,
                                    const std::function<double(mesh::RegionIdType)>& coefficient);

/// The CSR matrix assembled directly on the structure instance (every cell of AT from its own
/// transformed coordinates, times its region's coefficient), numbered like `numbering` (the
/// TCSR's global ids), unconstrained: the reference Algorithm 7.1 must reproduce.
CsrMatrix
assemble_structure_instance_csr(const mesh::TemplatedMeshCompactSvb& t,
                                const std::function<double(mesh::RegionIdType)>& coefficient,
                                const TemplatedCsr& numbering);

/// Replaces rows and columns of the sorted Dirichlet unknowns by the identity.
CsrMatrix constrain(const CsrMatrix& a, const std::vector<GlobalIndex>& dirichlet);

} // namespace symmesh::fem
