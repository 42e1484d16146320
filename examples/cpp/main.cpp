// Reads a templated geometry (a file, or a built-in object), checks it, generates its templated
// mesh and writes the structure instance as .vtu — the public API of docs/api.md in one page.
//
//   symmesh_example INPUT SIZE OUT.vtu [METHOD]
//
// INPUT is a .json file (data/...) or the name of a built-in object (symmesh example --list).
#include <symmesh/symmesh.h>

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc < 4 || argc > 5) {
    std::cerr << "usage: symmesh_example INPUT SIZE OUT.vtu [METHOD]\n";
    return 2;
  }
  const std::string input = argv[1];
  try {
    const bool file = input.size() > 5 && input.compare(input.size() - 5, 5, ".json") == 0;
    const auto structure =
        file ? symmesh::Structure::read(input) : symmesh::Structure::example(input);
    std::cout << "symmesh " << symmesh::version() << "\n"
              << "structure: " << structure.source() << ", " << structure.dimension() << "D, "
              << structure.template_count() << " templates, " << structure.instance_count()
              << " instances\n";

    const auto check = structure.check();
    std::cout << "check: templated structure " << (check.templated_structure ? "yes" : "no")
              << ", templated geometry " << (check.templated_geometry ? "yes" : "no")
              << ", regular " << (check.regularity_known ? (check.regular ? "yes" : "no") : "?")
              << ", instance graph edges " << check.instance_graph.size() << "\n";
    if (check.exit_code != 0) {
      std::cerr << "symmesh_example: " << check.message << "\n";
      return check.exit_code;
    }

    symmesh::GenerateOptions options;
    options.size = std::strtod(argv[2], nullptr);
    if (argc == 5) options.method = argv[4];
    const symmesh::Generation mesh(structure, options);
    const auto at = mesh.structure_instance();
    std::cout << "generate: method " << mesh.method() << ", cells_structure_instance "
              << mesh.cell_count() << ", cells_templates " << mesh.template_cell_count()
              << ", arrays " << at.point_count() << " points " << at.cell_count() << " cells\n";
    mesh.write(argv[3]);
    std::cout << "wrote " << argv[3] << "\n";
  } catch (const symmesh::InputError& e) {
    std::cerr << "symmesh_example: error: " << e.what() << "\n";
    return 2;
  } catch (const symmesh::CertificateError& e) {
    std::cerr << "symmesh_example: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
