// Every written cell is positively oriented (spec/outputs.md#orientation): the structure instance
// streamed from the templated mesh, for every built-in 2D object and every method that applies,
// and each writer's file read back by a small reader of its own format.
#include <gtest/gtest.h>

#include "symmesh/gen/templated_triangle_mesh.h"
#include "symmesh/io/examples.h"
#include "symmesh/io/mesh_writers.h"
#include "symmesh/io/templated_structure_json.h"
#include "symmesh/mesh/structure_instance.h"

#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

using namespace symmesh;

namespace {

/// A triangle mesh as read back from a file: points (x, y) and cells (0-based).
struct ReadBack {
  std::vector<std::array<double, 2>> points;
  std::vector<std::array<std::int64_t, 3>> cells;
};

double twice_signed_area(const ReadBack& m, const std::array<std::int64_t, 3>& c) {
  const auto& a = m.points[std::size_t(c[0])];
  const auto& b = m.points[std::size_t(c[1])];
  const auto& d = m.points[std::size_t(c[2])];
  return (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
}

/// Cells with non-positive signed area, and the signed area in all.
std::pair<std::size_t, double> orientation(const ReadBack& m) {
  std::size_t bad = 0;
  double sum = 0;
  for (const auto& c : m.cells) {
    const double a = twice_signed_area(m, c);
    if (!(a > 0)) ++bad;
    sum += a / 2;
  }
  return {bad, sum};
}

/// AT as the view gives it, with the view's orientation or the template's vertex order.
ReadBack from_view(const mesh::StructureInstance& at, bool template_order = false) {
  ReadBack m;
  at.for_each_vertex([&](const double* x) { m.points.push_back({x[0], x[1]}); });
  at.for_each_instance([&](const mesh::StructureInstance::Instance& in) {
    const auto& t = in.mesh_template->mesh;
    for (std::size_t c = 0; c < t.cell_count(); ++c) {
      const auto v = mesh::oriented_cell(t, c, template_order ? false : in.reverses);
      m.cells.push_back({(*in.global)[std::size_t(v[0])], (*in.global)[std::size_t(v[1])],
                         (*in.global)[std::size_t(v[2])]});
    }
  });
  return m;
}

using AnyStructure2 = std::variant<io::Structure2, io::CyclotomicStructure2>;

AnyStructure2 example(const std::string& name) {
  auto x = io::parse_templated_structure(io::example_document(name).dump(), name);
  if (auto* s = std::get_if<io::Structure2>(&x)) return *s;
  return std::get<io::CyclotomicStructure2>(x);
}

gen::GenerationResult generate(const AnyStructure2& x, gen::Method method, double cells) {
  return std::visit(
      [&](const auto& s) {
        gen::GenerationOptions o;
        o.size = std::sqrt(gen::estimate_cells(s, 1.0).measure / (0.2 * cells));
        o.min_angle_deg = 20;
        return gen::generate_triangle_mesh(s, method, o);
      },
      x);
}

double area_of(const AnyStructure2& x) {
  return std::visit([](const auto& s) { return gen::estimate_cells(s, 1.0).measure; }, x);
}

std::string slurp(const std::string& path) {
  std::ifstream is(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
}

template <class T>
T take(const std::string& s, std::size_t& at) {
  T v;
  std::memcpy(&v, s.data() + at, sizeof(T));
  at += sizeof(T);
  return v;
}

/// The arrays of a binary .vtu in file order, as raw bytes (raw or zlib-compressed blocks).
std::vector<std::string> vtu_appended_arrays(const std::string& file) {
  const bool zlib = file.find("vtkZLibDataCompressor") != std::string::npos;
  std::size_t at = file.find("<AppendedData encoding=\"raw\">");
  at = file.find('_', at) + 1;
  std::vector<std::string> arrays;
  for (int a = 0; a < 7; ++a) {
    std::string bytes;
    if (!zlib) {
      const auto n = take<std::uint64_t>(file, at);
      bytes = file.substr(at, n);
      at += n;
    } else {
      const auto blocks = take<std::uint64_t>(file, at);
      const auto block = take<std::uint64_t>(file, at);
      const auto last = take<std::uint64_t>(file, at);
      std::vector<std::uint64_t> sizes;
      for (std::uint64_t b = 0; b < blocks; ++b) sizes.push_back(take<std::uint64_t>(file, at));
      for (std::uint64_t b = 0; b < blocks; ++b) {
        std::string out(b + 1 == blocks ? last : block, '\0');
        uLongf n = uLongf(out.size());
        EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(out.data()), &n,
                             reinterpret_cast<const Bytef*>(file.data() + at), uLong(sizes[b])),
                  Z_OK);
        bytes += out.substr(0, n);
        at += sizes[b];
      }
    }
    arrays.push_back(bytes);
  }
  return arrays;
}

ReadBack read_vtu(const std::string& path) {
  const std::string file = slurp(path);
  ReadBack m;
  if (file.find("format=\"ascii\"") != std::string::npos) {
    const auto numbers = [&](const std::string& marker) {
      std::size_t at = file.find('>', file.find(marker)) + 1;
      std::istringstream is(file.substr(at, file.find('<', at) - at));
      std::vector<double> v;
      for (double x; is >> x;) v.push_back(x);
      return v;
    };
    const auto p = numbers("NumberOfComponents=\"3\"");
    for (std::size_t k = 0; k + 2 < p.size(); k += 3) m.points.push_back({p[k], p[k + 1]});
    const auto c = numbers("Name=\"connectivity\"");
    for (std::size_t k = 0; k + 2 < c.size(); k += 3)
      m.cells.push_back({std::int64_t(c[k]), std::int64_t(c[k + 1]), std::int64_t(c[k + 2])});
    return m;
  }
  const auto arrays = vtu_appended_arrays(file);
  for (std::size_t at = 0; at + 24 <= arrays[0].size(); at += 24) {
    std::size_t k = at;
    const double x = take<double>(arrays[0], k), y = take<double>(arrays[0], k);
    m.points.push_back({x, y});
  }
  for (std::size_t at = 0; at + 12 <= arrays[1].size();) {
    std::array<std::int64_t, 3> c{};
    for (auto& v : c) v = take<std::int32_t>(arrays[1], at);
    m.cells.push_back(c);
  }
  return m;
}

/// MSH 4.1, one node block with tags 1..n, element blocks of 3-node triangles.
ReadBack read_msh(const std::string& path) {
  const std::string file = slurp(path);
  const bool binary = file.compare(file.find("$MeshFormat") + 12, 7, "4.1 1 8") == 0;
  ReadBack m;
  std::size_t at = file.find('\n', file.find("$Nodes")) + 1;
  if (!binary) {
    std::istringstream is(file.substr(at));
    std::size_t blocks, n, lo, hi, dim, tag, param, count;
    is >> blocks >> n >> lo >> hi >> dim >> tag >> param >> count;
    for (std::size_t k = 0; k < count; ++k) is >> tag;
    for (std::size_t k = 0; k < count; ++k) {
      double x, y, z;
      is >> x >> y >> z;
      m.points.push_back({x, y});
    }
    at = file.find('\n', file.find("$Elements")) + 1;
    std::istringstream es(file.substr(at));
    std::size_t eblocks, ne;
    es >> eblocks >> ne >> lo >> hi;
    for (std::size_t b = 0; b < eblocks; ++b) {
      std::size_t type;
      es >> dim >> tag >> type >> count;
      for (std::size_t k = 0; k < count; ++k) {
        std::array<std::int64_t, 3> c{};
        es >> tag >> c[0] >> c[1] >> c[2];
        for (auto& v : c) --v;
        m.cells.push_back(c);
      }
    }
    return m;
  }
  take<std::uint64_t>(file, at); // blocks
  take<std::uint64_t>(file, at); // nodes
  take<std::uint64_t>(file, at);
  take<std::uint64_t>(file, at);
  take<std::int32_t>(file, at);
  take<std::int32_t>(file, at);
  take<std::int32_t>(file, at);
  const auto count = take<std::uint64_t>(file, at);
  at += count * 8; // tags
  for (std::uint64_t k = 0; k < count; ++k) {
    const double x = take<double>(file, at), y = take<double>(file, at);
    take<double>(file, at);
    m.points.push_back({x, y});
  }
  at = file.find('\n', file.find("$Elements")) + 1;
  const auto blocks = take<std::uint64_t>(file, at);
  at += 24;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    at += 12;
    const auto n = take<std::uint64_t>(file, at);
    for (std::uint64_t k = 0; k < n; ++k) {
      take<std::uint64_t>(file, at);
      std::array<std::int64_t, 3> c{};
      for (auto& v : c) v = std::int64_t(take<std::uint64_t>(file, at)) - 1;
      m.cells.push_back(c);
    }
  }
  return m;
}

ReadBack read_medit(const std::string& path) {
  std::istringstream is(slurp(path));
  ReadBack m;
  std::string word;
  std::size_t n = 0;
  while (is >> word) {
    if (word == "Vertices") {
      is >> n;
      for (std::size_t k = 0; k < n; ++k) {
        double x, y;
        int ref;
        is >> x >> y >> ref;
        m.points.push_back({x, y});
      }
    } else if (word == "Triangles") {
      is >> n;
      for (std::size_t k = 0; k < n; ++k) {
        std::array<std::int64_t, 3> c{};
        int ref;
        is >> c[0] >> c[1] >> c[2] >> ref;
        for (auto& v : c) --v;
        m.cells.push_back(c);
      }
    }
  }
  return m;
}

} // namespace

// The built-in catalogue, each object with the method `auto` picks (rotational, reflective,
// combined or bpp), with bpp, the conventional baseline and Gmsh: no cell of AT is negative.
TEST(Orientation, EveryCellOfEveryBuiltInObjectIsPositiveForEveryMethod) {
  std::size_t objects = 0, reflected_objects = 0;
  for (const auto& e : io::example_list()) {
    if (e.dimension != 2) continue; // 3D: test_templated_tetrahedral_mesh.cpp, test_generate_3d.sh
    const auto x = example(e.name);
    const double area = area_of(x);
    for (auto method :
         {gen::Method::automatic, gen::Method::bpp, gen::Method::conventional, gen::Method::gmsh}) {
      SCOPED_TRACE(e.name + " / method " + std::to_string(int(method)));
      const auto r = generate(x, method, 1500);
      ASSERT_TRUE(r.lemma_4_2_holds) << r.lemma_4_2_failure;
      const mesh::StructureInstance at(r.templated);
      const auto m = from_view(at);
      ASSERT_EQ(m.cells.size(), at.cell_count());
      const auto [bad, signed_area] = orientation(m);
      EXPECT_EQ(bad, 0u) << r.method;
      EXPECT_NEAR(signed_area, area, 1e-9 * area) << r.method;
      // The templates themselves are positive (the generators orient them).
      for (const auto& t : r.templated.templated.templates) {
        const mesh::TemplatedMeshCompactSvb one{
            {2, {{t.mesh, {0}, {1}}}, {{{1, 0, 0, 1}, {0, 0}}}}, {}, {}};
        EXPECT_EQ(orientation(from_view(mesh::StructureInstance(one))).first, 0u);
      }
      if (method == gen::Method::automatic) {
        ++objects;
        bool reflected = false;
        at.for_each_instance([&](const auto& in) { reflected = reflected || in.reverses; });
        if (reflected) {
          ++reflected_objects;
          // The check can fail: in the template's vertex order the reflected copies are negative.
          EXPECT_GT(orientation(from_view(at, true)).first, 0u) << r.method;
        }
      }
    }
  }
  EXPECT_GE(objects, 18u);
  // MOSFET, aircraft, the reflective-rotational star and the reflected star slices at least.
  EXPECT_GE(reflected_objects, 3u);
}

// Each writer, binary and text, on the reflective MOSFET (half its instances are mirrored): the
// file read back has the view's vertices and cells, all positive, and the object's area.
TEST(Orientation, EveryWriterWritesPositiveCells) {
  const auto x = example("mosfet");
  const auto r = generate(x, gen::Method::reflective, 3000);
  ASSERT_EQ(r.method, "reflective");
  const mesh::StructureInstance at(r.templated);
  const double area = area_of(x);
  struct Case {
    std::string file;
    io::MeshFileOptions options;
    ReadBack (*read)(const std::string&);
  };
  io::MeshFileOptions ascii, zlib;
  ascii.ascii = true;
  zlib.compress = true;
  const std::vector<Case> cases{{"o.vtu", {}, read_vtu},          {"o_ascii.vtu", ascii, read_vtu},
                                {"o_zlib.vtu", zlib, read_vtu},   {"o.msh", {}, read_msh},
                                {"o_ascii.msh", ascii, read_msh}, {"o.mesh", {}, read_medit}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    const std::string path = testing::TempDir() + "/" + c.file;
    io::write_mesh_file(at, path, c.options);
    const auto m = c.read(path);
    EXPECT_EQ(m.points.size(), at.vertex_count());
    ASSERT_EQ(m.cells.size(), at.cell_count());
    const auto [bad, signed_area] = orientation(m);
    EXPECT_EQ(bad, 0u);
    EXPECT_NEAR(signed_area, area, 1e-9 * area);
    // Same input, same bytes.
    const std::string again = testing::TempDir() + "/again_" + c.file;
    io::write_mesh_file(at, again, c.options);
    EXPECT_EQ(slurp(path), slurp(again));
    std::remove(path.c_str());
    std::remove(again.c_str());
  }
}

// The streamed AT is the materialised one (assemble_structure_instance), vertex for vertex.
TEST(StructureInstanceView, AgreesWithTheAssembledMesh) {
  const auto r = generate(example("star-reflective-rotational"), gen::Method::combined, 800);
  const mesh::StructureInstance at(r.templated);
  const auto si = mesh::assemble_structure_instance(r.templated);
  ASSERT_EQ(si.mesh.mesh.vertex_count(), at.vertex_count());
  ASSERT_EQ(si.mesh.mesh.cell_count(), at.cell_count());
  std::vector<double> coords;
  at.for_each_vertex([&](const double* x) { coords.insert(coords.end(), x, x + 2); });
  EXPECT_EQ(coords, si.mesh.mesh.vertex_coords);
  std::vector<mesh::IndexType> cells;
  at.for_each_cell([&](const auto&, std::size_t, const std::array<mesh::IndexType, 4>& v) {
    cells.insert(cells.end(), v.begin(), v.begin() + 3);
  });
  EXPECT_EQ(cells, si.mesh.mesh.cell_vertex_indices);
  // Its own memory is the interface numbering, far below AT's.
  EXPECT_LT(at.bytes() * 4, si.mesh.bytes());
}
