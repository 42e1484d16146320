// The extension module symmesh._symmesh: the public C++ API (symmesh.h) with numpy arrays; the
// package python/symmesh/__init__.py builds meshio meshes and dicts on top — docs/api.md#python
#include "symmesh/symmesh.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace py = pybind11;

namespace {

/// A copy of `v` as a numpy array of shape (v.size() / columns, columns).
template <class T>
py::array_t<T> table(const std::vector<T>& v, std::size_t columns) {
  const auto rows = py::ssize_t(columns ? v.size() / columns : 0);
  py::array_t<T> a(std::vector<py::ssize_t>{rows, py::ssize_t(columns)});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

template <class T>
py::array_t<T> column(const std::vector<T>& v) {
  return py::array_t<T>(py::ssize_t(v.size()), v.data());
}

py::dict mesh_dict(const symmesh::Mesh& m) {
  py::dict d;
  d["dimension"] = m.dimension;
  d["points"] = table(m.points, 3);
  d["cells"] = table(m.cells, std::size_t(m.dimension + 1));
  d["region"] = column(m.region);
  d["template"] = column(m.template_number);
  d["instance"] = column(m.instance_number);
  return d;
}

py::dict check_dict(const symmesh::CheckResult& c) {
  py::list edges;
  for (const auto& e : c.instance_graph) {
    py::dict attrs;
    attrs["label"] = e.label;
    attrs["trivial"] = e.trivial;
    attrs["instance_a"] = py::make_tuple(e.template_a, e.instance_a);
    attrs["instance_b"] = py::make_tuple(e.template_b, e.instance_b);
    edges.append(py::make_tuple(e.template_a, e.template_b, attrs));
  }
  py::dict d;
  d["report"] = c.json;
  d["exit_code"] = c.exit_code;
  d["message"] = c.message;
  d["edges"] = edges;
  return d;
}

} // namespace

PYBIND11_MODULE(_symmesh, m) {
  m.doc() = "symmesh's C++ API (symmesh.h); use the package symmesh, not this module";
  m.attr("__version__") = symmesh::version();
  // Same names and messages as the CLI's refusals; InputError is a ValueError.
  py::register_exception<symmesh::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<symmesh::CertificateError>(m, "CertificateError", PyExc_RuntimeError);

  py::class_<symmesh::Structure>(m, "Structure")
      .def_static("read", &symmesh::Structure::read, py::arg("path"))
      .def_static("parse", &symmesh::Structure::parse, py::arg("text"), py::arg("source") = "input")
      .def_static("example", &symmesh::Structure::example, py::arg("name"))
      .def_static("example_names", &symmesh::Structure::example_names)
      .def_property_readonly("dimension", &symmesh::Structure::dimension)
      .def_property_readonly("template_count", &symmesh::Structure::template_count)
      .def_property_readonly("instance_count", &symmesh::Structure::instance_count)
      .def_property_readonly("template_names", &symmesh::Structure::template_names)
      .def_property_readonly("source", &symmesh::Structure::source)
      .def_property_readonly("kernel", &symmesh::Structure::kernel)
      .def("check", [](const symmesh::Structure& s) {
        // The analysis is exact and may take a while; other Python threads may run meanwhile.
        symmesh::CheckResult c;
        {
          py::gil_scoped_release release;
          c = s.check();
        }
        return check_dict(c);
      });

  py::class_<symmesh::Generation>(m, "Generation")
      .def(py::init([](const symmesh::Structure& s, double size, double min_angle,
                       const std::string& method, double max_cells, bool progress, bool repair) {
             symmesh::GenerateOptions o;
             o.size = size;
             o.min_angle = min_angle;
             o.method = method;
             o.max_cells = max_cells;
             o.progress = progress;
             o.repair_outliers = repair;
             py::gil_scoped_release release;
             return symmesh::Generation(s, o);
           }),
           py::arg("structure"), py::arg("size"), py::arg("min_angle"), py::arg("method"),
           py::arg("max_cells"), py::arg("progress"), py::arg("repair") = true)
      .def_property_readonly("method", &symmesh::Generation::method)
      .def_property_readonly("dimension", &symmesh::Generation::dimension)
      .def_property_readonly("cell_count", &symmesh::Generation::cell_count)
      .def_property_readonly("point_count", &symmesh::Generation::point_count)
      .def_property_readonly("template_cell_count", &symmesh::Generation::template_cell_count)
      .def_property_readonly("report_json", &symmesh::Generation::report_json)
      .def("structure_instance",
           [](const symmesh::Generation& g) { return mesh_dict(g.structure_instance()); })
      .def("templated_mesh",
           [](const symmesh::Generation& g) {
             const auto t = g.templated_mesh();
             py::list templates, instances;
             for (const auto& tm : t.templates) templates.append(mesh_dict(tm));
             const auto d = std::size_t(t.dimension);
             for (const auto& in : t.instances) {
               py::dict i;
               i["template"] = in.template_index;
               i["region"] = in.region;
               i["matrix"] = table(in.matrix, d);
               i["translation"] = column(in.translation);
               instances.append(i);
             }
             py::dict out;
             out["dimension"] = t.dimension;
             out["templates"] = templates;
             out["instances"] = instances;
             return out;
           })
      .def(
          "write",
          [](const symmesh::Generation& g, const std::string& path, bool ascii, bool compress) {
            symmesh::WriteOptions o;
            o.ascii = ascii;
            o.compress = compress;
            g.write(path, o);
          },
          py::arg("path"), py::arg("ascii") = false, py::arg("compress") = false)
      .def("write_templated", &symmesh::Generation::write_templated, py::arg("path"));
}
