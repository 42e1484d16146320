/// The symmesh C++ API: read a templated structure, check it, generate a templated mesh and write
/// it — docs/api.md
///
/// The one public header of the installed package (`find_package(symmesh)`, target
/// `symmesh::symmesh`, the shared library libsymmesh.so). It holds standard types only: CGAL,
/// TetGen, Graphviz and nlohmann_json stay behind opaque handles inside the library, so a program
/// using it compiles in a second and needs none of their headers. Every function does what the
/// matching `symmesh` command does (the same code runs), and every refusal is an exception whose
/// what() is the one line the command prints after "symmesh: error: ".
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#define SYMMESH_API __attribute__((visibility("default")))

namespace symmesh {

/// The library's version, "MAJOR.MINOR.PATCH" (the CMake package's version).
SYMMESH_API std::string version();

/// Bad input, exit code 2 of the CLI: an unreadable or malformed document, an option out of
/// range, input a method cannot take, a mesher failure.
class SYMMESH_API InputError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

/// A generated templated mesh failed its Lemma 4.2 certificate (exit code 1 of `generate`).
class SYMMESH_API CertificateError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// One edge of the instance graph (Section 4.2): the instances T_{a} and T_{b} are neighbours,
/// or the reflexive self-loop of a template (trivial). Template and instance numbers are 0-based
/// (the CLI's text T_{i,g} is 1-based: label).
struct InstanceGraphEdge {
  std::size_t template_a = 0, instance_a = 0; ///< instance_a-th instance of template_a
  std::size_t template_b = 0, instance_b = 0;
  bool trivial = false;
  std::string label; ///< "T_{1,1} / T_{2,1}", or "I" for the self-loop
};

/// What `symmesh check` decides (spec/definitions.md#check-verdicts).
struct CheckResult {
  bool templated_structure = false; ///< Eq. 4.2 holds
  bool templated_mesh = false;      ///< mesh templates and AT conforms (Definition 4.3)
  bool templated_geometry = false;  ///< geometry templates (Definition 4.4)
  bool lemma_4_2_checked = false;   ///< mesh templates: the Lemma 4.2 checker ran
  bool lemma_4_2_holds = false;
  std::string lemma_4_2_failing_pair; ///< "T_{i,g}, T_{j,h}" when it fails
  int lemma_4_2_condition = 0;        ///< 1 for (i), 2 for (ii) when it fails
  bool regularity_known = false;      ///< Algorithm 4.1 ran within its composition guard
  bool regular = false;               ///< Definition 4.9, when regularity_known
  std::vector<InstanceGraphEdge> instance_graph;
  int exit_code = 0;   ///< what `symmesh check` exits with: 0, 1 or 2
  std::string message; ///< the CLI's error line when exit_code is 2 or 1, else empty
  std::string json;    ///< the whole report, as `symmesh check --json` prints it
};

/// A mesh as plain arrays, in the order and numbering of the .vtu writer (docs/api.md#meshes).
struct Mesh {
  int dimension = 2;               ///< 2: triangles, 3: tetrahedra
  std::vector<double> points;      ///< x, y, z per point (z = 0 in 2D)
  std::vector<std::int32_t> cells; ///< dimension + 1 point ids per cell, positively oriented
  /// Cell data as the mesh files hold it: the region id; the template and the global instance
  /// (template-major) numbered from 1 (template t is TemplatedMesh::templates[t - 1]). In a
  /// template of a TemplatedMesh, region and instance are -1.
  std::vector<std::int32_t> region, template_number, instance_number;

  std::size_t point_count() const { return points.size() / 3; }
  std::size_t cell_count() const { return cells.size() / std::size_t(dimension + 1); }
};

/// One instance of a templated mesh: x -> matrix·x + translation applied to its template.
struct Instance {
  std::size_t template_index = 0; ///< 0-based: TemplatedMesh::templates[template_index]
  std::int32_t region = 0;
  std::vector<double> matrix;      ///< dimension × dimension, row-major
  std::vector<double> translation; ///< dimension entries
};

/// A templated mesh (Listing 4.1): every template meshed once, in its own coordinates, and the
/// instances in global order (template-major: cell data instance k is instances[k - 1]).
struct TemplatedMesh {
  int dimension = 2;
  std::vector<Mesh> templates;
  std::vector<Instance> instances;
};

/// A templated structure read and validated in shape (spec/input-format.md). Copies share it.
class SYMMESH_API Structure {
public:
  /// Throw InputError with the reader's one-line message.
  static Structure read(const std::string& path);
  static Structure parse(const std::string& json_text, const std::string& source = "input");
  /// A built-in object of `symmesh example` (spec/examples.md).
  static Structure example(const std::string& name);
  static std::vector<std::string> example_names();

  int dimension() const;
  std::size_t template_count() const;
  std::size_t instance_count() const;
  std::vector<std::string> template_names() const;
  const std::string& source() const; ///< the path, or the name given to parse / example
  std::string kernel() const;        ///< the exact kernel it was read in

  /// Eq. 4.2, the Lemma 4.2 verdict, the instance graph and regularity, as `symmesh check`.
  /// Throws InputError when the structure is not well-formed (the CLI's exit 2 before any
  /// report); a structure that is not templated comes back with exit_code 2 and its message.
  CheckResult check() const;

  struct Impl;

private:
  explicit Structure(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
  std::shared_ptr<const Impl> impl_;
  friend class Generation;
};

/// The options of `symmesh generate` that shape the mesh (spec/generation.md).
struct GenerateOptions {
  double size = 0;             ///< target edge length, > 0
  double min_angle = 20;       ///< degrees, in [0, 33.8]
  std::string method = "auto"; ///< auto, bpp, rotational, reflective, combined, sao,
                               ///< conventional, gmsh
  double max_cells = 0;        ///< refuse larger estimates; 0: memory / 250 bytes per cell
  bool progress = false;       ///< progress lines on stderr, as the CLI without --quiet
  bool repair_outliers = true; ///< 3D: the outlier repair after TetGen (false: --no-repair)
  double tetgen_dihedral = 10; ///< 3D: TetGen's -q/D in degrees, [0, 70.5) (--tetgen-dihedral)
};

/// File options of `generate -o` (spec/outputs.md#mesh-files).
struct WriteOptions {
  bool ascii = false;    ///< text .vtu / .msh
  bool compress = false; ///< zlib .vtu
};

/// A generated, certified templated mesh. Copies share it.
class SYMMESH_API Generation {
public:
  /// Algorithm 5.6 (2D) or 5.7 (3D) or a baseline, then the Lemma 4.2 certificate.
  /// Throws InputError for bad options or input, CertificateError when the certificate fails.
  Generation(const Structure& structure, const GenerateOptions& options);

  const std::string& method() const; ///< the method that ran
  int dimension() const;
  std::size_t cell_count() const; ///< cells of the structure instance AT
  std::size_t point_count() const;
  std::size_t template_cell_count() const; ///< cells of the templates, each counted once
  std::size_t template_count() const;
  std::size_t instance_count() const;

  /// The structure instance AT(X) materialised, with cell data region, template, instance.
  Mesh structure_instance() const;
  TemplatedMesh templated_mesh() const;
  /// The `generate --report` JSON (docs/api.md#report; seconds_write is 0).
  const std::string& report_json() const;

  /// The structure instance as .vtu, .msh or .mesh by extension; InputError otherwise.
  void write(const std::string& path, const WriteOptions& options = {}) const;
  /// The templated mesh as .tmesh (spec/outputs.md#tmesh).
  void write_templated(const std::string& path) const;

  struct Impl;

private:
  std::shared_ptr<const Impl> impl_;
};

/// Same as Generation(structure, options).
SYMMESH_API Generation generate(const Structure& structure, const GenerateOptions& options);

} // namespace symmesh
