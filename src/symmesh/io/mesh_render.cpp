// Pictures of templated meshes — spec/outputs.md#render. Coordinates are doubles (a generated
// mesh is not exact); interfaces come from the compact SVB's vertex numbering, not from distances.
#include "symmesh/io/mesh_render.h"

#include "symmesh/io/atomic_file.h"
#include "symmesh/io/colour.h"
#include "symmesh/io/mesh_writers.h"
#include "symmesh/io/plot_box.h"
#include "symmesh/mesh/structure_instance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include <spawn.h>
#include <sys/wait.h>

extern char** environ;

namespace symmesh::io {
namespace {

using mesh::IndexType;
using V3 = std::array<double, 3>;

/// One cell of AT with what the colourings need.
struct AtCell {
  std::size_t instance = 0, templ = 0;
  int region = 0;
  std::array<IndexType, 4> v{};
  int nv = 0;
  double quality = 0; ///< smallest angle in degrees (2D)
};

/// AT as flat arrays: coordinates (z = 0 in 2D) and cells.
struct At {
  int dim = 2;
  std::vector<V3> x;
  std::vector<AtCell> cells;
  std::vector<std::size_t> instances_per_template;
  std::vector<std::pair<std::size_t, std::size_t>> instance_id; ///< (template, g) per instance
};

double angle_deg(const V3& p, const V3& q, const V3& r) { // at p, between q - p and r - p
  const double ax = q[0] - p[0], ay = q[1] - p[1], bx = r[0] - p[0], by = r[1] - p[1];
  return std::atan2(std::fabs(ax * by - ay * bx), ax * bx + ay * by) * 180.0 / M_PI;
}

/// Smallest angle of each template triangle: rigid maps keep angles, so AT's cells take their
/// template cell's value.
std::vector<double> smallest_angles(const mesh::Mesh& m) {
  std::vector<double> out(m.cell_count(), 0);
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    if (mesh::vertex_count(m.cell_types[c]) != 3) continue;
    V3 p[3]{};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 2; ++d) p[k][std::size_t(d)] = m.vertex(std::size_t(m.cell(c)[k]))[d];
    out[c] = std::min(
        {angle_deg(p[0], p[1], p[2]), angle_deg(p[1], p[2], p[0]), angle_deg(p[2], p[0], p[1])});
  }
  return out;
}

At collect(const mesh::TemplatedMeshCompactSvb& t) {
  const mesh::StructureInstance view(t);
  At at;
  at.dim = view.dimension();
  at.x.reserve(view.vertex_count());
  view.for_each_vertex([&](const double* p) {
    V3 q{};
    for (int d = 0; d < at.dim; ++d) q[std::size_t(d)] = p[d];
    at.x.push_back(q);
  });
  std::vector<std::vector<double>> quality;
  for (const auto& tm : t.templated.templates) {
    at.instances_per_template.push_back(tm.instance_count());
    for (std::size_t g = 0; g < tm.instance_count(); ++g)
      at.instance_id.emplace_back(at.instances_per_template.size() - 1, g);
    quality.push_back(at.dim == 2 ? smallest_angles(tm.mesh) : std::vector<double>{});
  }
  at.cells.reserve(view.cell_count());
  view.for_each_cell([&](const mesh::StructureInstance::Instance& in, std::size_t c,
                         const std::array<IndexType, 4>& v) {
    AtCell cell{in.index, in.template_index, int(in.region), v, 0, 0};
    cell.nv = mesh::vertex_count(in.mesh_template->mesh.cell_types[c]);
    if (at.dim == 2) cell.quality = quality[in.template_index][c];
    at.cells.push_back(cell);
  });
  return at;
}

/// The largest angle the quality scale shows: the equilateral triangle's.
constexpr double kBestAngle = 60;

std::string cell_colour(const AtCell& c, CellColour colour) {
  switch (colour) {
  case CellColour::instance:
    return fill_colour(c.instance);
  case CellColour::template_:
    return fill_colour(c.templ);
  case CellColour::region:
    return fill_colour(std::size_t(c.region));
  case CellColour::quality:
    return ramp_colour(c.quality / kBestAngle);
  }
  return "#000000";
}

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return std::string(buf) == "-0.00" ? "0.00" : buf;
}

/// Screen placement: the longer side of the drawing gets `width` pixels.
struct Frame {
  detail::PlotBox box;
  double scale = 1, margin = 20;
  std::array<double, 2> map(double x, double y) const {
    return {margin + (x - box.minx) * scale, margin + (box.maxy - y) * scale};
  }
  double width() const { return 2 * margin + box.span_x() * scale; }
  double height() const { return 2 * margin + box.span_y() * scale; }
};

Frame fit(const std::vector<std::array<double, 2>>& pts, double width) {
  Frame f;
  for (const auto& p : pts) f.box.add(p);
  if (pts.empty()) f.box.add({0, 0});
  const double span = std::max({f.box.span_x(), f.box.span_y(), 1e-300});
  f.scale = (width - 2 * f.margin) / span;
  return f;
}

// --- legend -------------------------------------------------------------------------------

struct LegendEntry {
  std::string colour, text;
};

constexpr double kLegendColumn = 180, kLegendRow = 22;
/// Instance colourings list their instances only up to here; beyond, one line says how many.
constexpr std::size_t kMaxInstanceEntries = 40;

std::vector<LegendEntry> legend_entries(const At& at, CellColour colour) {
  std::vector<LegendEntry> out;
  if (colour == CellColour::template_)
    for (std::size_t i = 0; i < at.instances_per_template.size(); ++i)
      out.push_back({fill_colour(i), "template " + std::to_string(i + 1) + " (" +
                                         std::to_string(at.instances_per_template[i]) + "x)"});
  if (colour == CellColour::region) {
    std::set<int> regions;
    for (const auto& c : at.cells) regions.insert(c.region);
    for (int r : regions)
      out.push_back({fill_colour(std::size_t(r)), "region " + std::to_string(r)});
  }
  if (colour == CellColour::instance && at.instance_id.size() <= kMaxInstanceEntries)
    for (std::size_t k = 0; k < at.instance_id.size(); ++k)
      out.push_back({fill_colour(k), "T_{" + std::to_string(at.instance_id[k].first + 1) + "," +
                                         std::to_string(at.instance_id[k].second + 1) + "}"});
  return out;
}

std::size_t legend_columns(double width) {
  return std::max<std::size_t>(1, std::size_t((width - 40) / kLegendColumn));
}

double legend_height(const At& at, CellColour colour, double width) {
  const double caption = 2 * kLegendRow;
  if (colour == CellColour::quality) return caption + 60;
  const std::size_t n = legend_entries(at, colour).size(), cols = legend_columns(width);
  return caption + double((n + cols - 1) / cols) * kLegendRow + 10;
}

std::string text(double x, double y, const std::string& s, const char* anchor = "start") {
  return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + anchor + "\">" + s +
         "</text>\n";
}

void quality_bar(std::ostringstream& os, double top, double min_angle) {
  const double x0 = 20, w = 360, h = 16;
  os << "<g class=\"colour-bar\">\n";
  for (int k = 0; k < 60; ++k)
    os << "<rect x=\"" << num(x0 + w * k / 60) << "\" y=\"" << num(top) << "\" width=\""
       << num(w / 60 + 0.5) << "\" height=\"" << num(h) << "\" fill=\""
       << ramp_colour((k + 0.5) / 60) << "\"/>\n";
  for (int a = 0; a <= 60; a += 10)
    os << text(x0 + w * a / kBestAngle, top + h + 14, std::to_string(a) + "&#176;", "middle");
  os << text(x0 + w + 14, top + 13, "smallest angle (min " + num(min_angle) + "&#176;)");
  os << "</g>\n";
}

void legend(std::ostringstream& os, const At& at, CellColour colour, double top, double width,
            const std::string& caption) {
  os << "<g class=\"legend\" font-family=\"sans-serif\" font-size=\"13\">\n";
  os << text(20, top + 16, caption);
  top += 2 * kLegendRow;
  if (colour == CellColour::quality) {
    double lo = kBestAngle;
    for (const auto& c : at.cells) lo = std::min(lo, c.quality);
    quality_bar(os, top - 14, at.cells.empty() ? 0 : lo);
  } else if (colour == CellColour::instance && at.instance_id.size() > kMaxInstanceEntries) {
    os << text(20, top, std::to_string(at.instance_id.size()) + " instances, one colour each");
  }
  const auto entries = legend_entries(at, colour);
  const std::size_t cols = legend_columns(width);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const double x = 20 + double(k % cols) * kLegendColumn, y = top + double(k / cols) * kLegendRow;
    os << "<rect x=\"" << num(x) << "\" y=\"" << num(y - 12)
       << "\" width=\"16\" height=\"14\" fill=\"" << entries[k].colour
       << "\" stroke=\"#333\" stroke-width=\"0.5\"/>\n"
       << text(x + 22, y, entries[k].text);
  }
  os << "</g>\n";
}

std::string svg_open(double w, double h) {
  std::ostringstream os;
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(std::ceil(w)) << "\" height=\""
     << num(std::ceil(h)) << "\" viewBox=\"0 0 " << num(std::ceil(w)) << " " << num(std::ceil(h))
     << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  return os.str();
}

const char* colour_name(CellColour c) {
  switch (c) {
  case CellColour::instance:
    return "instance";
  case CellColour::template_:
    return "template";
  case CellColour::region:
    return "region";
  case CellColour::quality:
    return "quality";
  }
  return "";
}

std::string caption(const At& at, const std::string& what, CellColour colour) {
  return std::to_string(at.x.size()) + " vertices, " + std::to_string(at.cells.size()) +
         " cells, " + std::to_string(at.instance_id.size()) + " instances of " +
         std::to_string(at.instances_per_template.size()) + " templates; " + what +
         "; colour: " + colour_name(colour);
}

// --- 2D -------------------------------------------------------------------------------------

/// An edge of AT seen from one of its cells.
struct EdgeUse {
  IndexType a, b;
  std::size_t instance;
  bool operator<(const EdgeUse& o) const {
    return std::tie(a, b, instance) < std::tie(o.a, o.b, o.instance);
  }
};

/// AT's boundary edges (one cell) and instance interface edges (cells of two instances).
void classify_edges(const At& at, std::vector<EdgeUse>& boundary,
                    std::vector<EdgeUse>& interfaces) {
  std::vector<EdgeUse> uses;
  uses.reserve(at.cells.size() * 3);
  for (const auto& c : at.cells)
    for (int k = 0; k < c.nv; ++k) {
      IndexType a = c.v[std::size_t(k)], b = c.v[std::size_t((k + 1) % c.nv)];
      uses.push_back({std::min(a, b), std::max(a, b), c.instance});
    }
  std::sort(uses.begin(), uses.end());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
    if (j - i == 1)
      boundary.push_back(uses[i]);
    else if (uses[j - 1].instance != uses[i].instance)
      interfaces.push_back(uses[i]);
    i = j;
  }
}

void edge_path(std::ostringstream& os, const Frame& f, const At& at,
               const std::vector<EdgeUse>& edges, const char* cls, const char* stroke,
               double width) {
  os << "<path class=\"" << cls << "\" fill=\"none\" stroke=\"" << stroke << "\" stroke-width=\""
     << num(width) << "\" stroke-linecap=\"round\" d=\"";
  for (const auto& e : edges) {
    const auto p = f.map(at.x[std::size_t(e.a)][0], at.x[std::size_t(e.a)][1]);
    const auto q = f.map(at.x[std::size_t(e.b)][0], at.x[std::size_t(e.b)][1]);
    os << "M" << num(p[0]) << " " << num(p[1]) << "L" << num(q[0]) << " " << num(q[1]);
  }
  os << "\"/>\n";
}

/// Every template's patch segments carried into each of its instances, one path per class.
void patch_paths(std::ostringstream& os, const Frame& f, const mesh::TemplatedMesh& t,
                 const PatchOverlay& overlay) {
  std::map<std::size_t, std::pair<std::string, std::string>> by_class; // class -> (colour, d)
  for (std::size_t i = 0; i < t.templates.size(); ++i)
    for (const auto ti : t.templates[i].transformation_indices) {
      const auto& tr = t.transformations[std::size_t(ti)];
      for (const auto& seg : overlay.per_template[i]) {
        double a[2], b[2];
        tr.apply(seg.a.data(), a);
        tr.apply(seg.b.data(), b);
        const auto p = f.map(a[0], a[1]), q = f.map(b[0], b[1]);
        auto& [colour, d] = by_class[seg.relation_class];
        colour = seg.colour;
        d += "M" + num(p[0]) + " " + num(p[1]) + "L" + num(q[0]) + " " + num(q[1]);
      }
    }
  for (const auto& [cls, cd] : by_class)
    os << "<path class=\"patches\" data-class=\"" << cls << "\" fill=\"none\" stroke=\"" << cd.first
       << "\" stroke-width=\"3.2\" stroke-linecap=\"round\" d=\"" << cd.second << "\"/>\n";
}

std::string svg_2d(const At& at, const mesh::TemplatedMesh& t, const MeshRenderOptions& o) {
  std::vector<std::array<double, 2>> pts;
  for (const auto& p : at.x) pts.push_back({p[0], p[1]});
  const Frame f = fit(pts, o.width);
  const double w = std::max(f.width(), 420.0);
  std::ostringstream os;
  os << svg_open(w, f.height() + legend_height(at, o.colour, w));
  os << "<g class=\"cells\" stroke=\"#444\" stroke-width=\"0.3\" stroke-linejoin=\"round\">\n";
  for (const auto& c : at.cells) {
    os << "<polygon fill=\"" << cell_colour(c, o.colour) << "\" points=\"";
    for (int k = 0; k < c.nv; ++k) {
      const auto& p = at.x[std::size_t(c.v[std::size_t(k)])];
      const auto q = f.map(p[0], p[1]);
      os << (k ? " " : "") << num(q[0]) << "," << num(q[1]);
    }
    os << "\"/>\n";
  }
  os << "</g>\n";
  std::vector<EdgeUse> boundary, interfaces;
  classify_edges(at, boundary, interfaces);
  edge_path(os, f, at, interfaces, "interfaces", "#d7301f", 1.6);
  edge_path(os, f, at, boundary, "boundary", "#000000", 2.4);
  std::string what = "red: instance interfaces, black: boundary";
  if (o.patches) {
    patch_paths(os, f, t, *o.patches);
    what = "thick: boundary patches, a colour per relation class (" +
           std::to_string(o.patches->classes) + ")";
  }
  legend(os, at, o.colour, f.height(), w, caption(at, what, o.colour));
  os << "</svg>\n";
  return os.str();
}

// --- 3D -------------------------------------------------------------------------------------

V3 sub(const V3& a, const V3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V3 unit(const V3& a) {
  const double n = std::sqrt(dot(a, a));
  return n > 0 ? V3{a[0] / n, a[1] / n, a[2] / n} : a;
}

/// A triangle on AT's boundary, outward oriented, with the cell it bounds.
struct Face {
  std::array<IndexType, 3> v;
  std::size_t cell;
};

std::vector<Face> boundary_faces(const At& at) {
  static const int opposite_faces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::vector<std::pair<std::array<IndexType, 3>, Face>> all;
  for (std::size_t c = 0; c < at.cells.size(); ++c) {
    if (at.cells[c].nv != 4) continue;
    for (int k = 0; k < 4; ++k) {
      Face f{{}, c};
      for (int q = 0; q < 3; ++q)
        f.v[std::size_t(q)] = at.cells[c].v[std::size_t(opposite_faces[k][q])];
      // Orientation by the opposite vertex rather than by the cell's sign: robust to any order.
      const auto& x = at.x;
      const V3 n = cross(sub(x[std::size_t(f.v[1])], x[std::size_t(f.v[0])]),
                         sub(x[std::size_t(f.v[2])], x[std::size_t(f.v[0])]));
      if (dot(n, sub(x[std::size_t(at.cells[c].v[std::size_t(k)])], x[std::size_t(f.v[0])])) > 0)
        std::swap(f.v[1], f.v[2]);
      auto key = f.v;
      std::sort(key.begin(), key.end());
      all.emplace_back(key, f);
    }
  }
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first, a.second.cell) < std::tie(b.first, b.second.cell);
  });
  std::vector<Face> out;
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i;
    while (j < all.size() && all[j].first == all[i].first) ++j;
    if (j - i == 1) out.push_back(all[i].second);
    i = j;
  }
  return out;
}

/// The fixed camera: orthographic, from azimuth 35° and elevation 25° (front-right, above).
struct Camera {
  V3 right, up, towards;
  Camera() {
    const double az = 35 * M_PI / 180, el = 25 * M_PI / 180;
    towards = {std::cos(el) * std::sin(az), -std::cos(el) * std::cos(az), std::sin(el)};
    right = {std::cos(az), std::sin(az), 0};
    up = cross(towards, right);
  }
};

std::string shaded(const std::string& hex, double intensity) {
  unsigned r = 0, g = 0, b = 0;
  std::sscanf(hex.c_str(), "#%02x%02x%02x", &r, &g, &b);
  char buf[8];
  const auto s = [&](unsigned c) { return int(std::lround(std::min(255.0, c * intensity))); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", s(r), s(g), s(b));
  return buf;
}

/// A boundary triangle as the camera sees it.
struct Projected {
  double depth = 0; ///< mean distance towards the camera
  std::size_t order = 0;
  std::array<std::array<double, 2>, 3> p{};
  std::string fill;
};

/// The front-facing boundary triangles, projected and shaded, far to near.
std::vector<Projected> visible_faces(const At& at, const std::vector<Face>& faces,
                                     CellColour colour) {
  const Camera cam;
  V3 light{};
  for (std::size_t d = 0; d < 3; ++d)
    light[d] = cam.towards[d] + 0.4 * cam.up[d] + 0.3 * cam.right[d];
  light = unit(light);
  std::vector<Projected> out;
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const auto& f = faces[k];
    const auto x = [&](int q) -> const V3& { return at.x[std::size_t(f.v[std::size_t(q)])]; };
    const V3 n = unit(cross(sub(x(1), x(0)), sub(x(2), x(0))));
    if (dot(n, cam.towards) <= 0) continue; // back face: hidden on a closed surface
    Projected d;
    d.order = k;
    d.fill =
        shaded(cell_colour(at.cells[f.cell], colour), 0.35 + 0.65 * std::max(0.0, dot(n, light)));
    for (int q = 0; q < 3; ++q) {
      d.p[std::size_t(q)] = {dot(x(q), cam.right), dot(x(q), cam.up)};
      d.depth += dot(x(q), cam.towards) / 3;
    }
    out.push_back(d);
  }
  // Painter's order: far faces first; ties by face order keep the output deterministic.
  std::sort(out.begin(), out.end(), [](const Projected& a, const Projected& b) {
    return a.depth != b.depth ? a.depth < b.depth : a.order < b.order;
  });
  return out;
}

std::string svg_3d(const At& at, const MeshRenderOptions& o) {
  const auto faces = boundary_faces(at);
  const auto drawn = visible_faces(at, faces, o.colour);
  std::vector<std::array<double, 2>> pts;
  for (const auto& d : drawn) pts.insert(pts.end(), d.p.begin(), d.p.end());
  const Frame f = fit(pts, o.width);
  const double w = std::max(f.width(), 420.0);
  std::ostringstream os;
  os << svg_open(w, f.height() + legend_height(at, o.colour, w));
  os << "<g class=\"surface\" stroke=\"#000\" stroke-opacity=\"0.25\" stroke-width=\"0.3\" "
        "stroke-linejoin=\"round\">\n";
  for (const auto& d : drawn) {
    os << "<polygon fill=\"" << d.fill << "\" points=\"";
    for (int q = 0; q < 3; ++q) {
      const auto s = f.map(d.p[std::size_t(q)][0], d.p[std::size_t(q)][1]);
      os << (q ? " " : "") << num(s[0]) << "," << num(s[1]);
    }
    os << "\"/>\n";
  }
  os << "</g>\n";
  legend(os, at, o.colour, f.height(), w,
         caption(at, std::to_string(faces.size()) + " boundary triangles", o.colour));
  os << "</svg>\n";
  return os.str();
}

// --- multiblock ------------------------------------------------------------------------------

/// The templated mesh restricted to template k's instances; the other templates stay (empty), so
/// that template numbers in the block's cell data are the structure's.
mesh::TemplatedMeshCompactSvb block_of(const mesh::TemplatedMeshCompactSvb& t, std::size_t k) {
  mesh::TemplatedMeshCompactSvb b;
  b.templated.point_dimension = t.templated.point_dimension;
  b.templated.transformations = t.templated.transformations;
  std::size_t first = 0;
  for (std::size_t i = 0; i < t.templated.templates.size(); ++i) {
    if (i < k) first += t.templated.templates[i].instance_count();
    mesh::MeshTemplate m;
    m.mesh.point_dimension = t.templated.point_dimension;
    b.templated.templates.push_back(i == k ? t.templated.templates[i] : m);
  }
  const std::size_t n = t.templated.templates[k].instance_count();
  std::vector<IndexType> table_index(t.tables.size(), -1);
  for (std::size_t q = 0; q < t.tables.size(); ++q)
    if (std::size_t(t.tables[q].from_template) == k && std::size_t(t.tables[q].to_template) == k) {
      table_index[q] = IndexType(b.tables.size());
      b.tables.push_back(t.tables[q]);
    }
  const auto inside = [&](IndexType i) {
    return std::size_t(i) >= first && std::size_t(i) < first + n;
  };
  for (const auto& id : t.identifications)
    if (inside(id.from_instance) && inside(id.to_instance) &&
        table_index[std::size_t(id.table)] >= 0)
      b.identifications.push_back({IndexType(std::size_t(id.from_instance) - first),
                                   IndexType(std::size_t(id.to_instance) - first),
                                   table_index[std::size_t(id.table)]});
  return b;
}

/// The \pre of mesh_svg and write_vtm: the view and the writers index without checking.
void require_valid(const mesh::TemplatedMeshCompactSvb& t) {
  std::ostringstream why;
  if (!t.is_valid(&why)) throw std::invalid_argument("not a valid templated mesh: " + why.str());
}

} // namespace

std::string mesh_svg(const mesh::TemplatedMeshCompactSvb& t, const MeshRenderOptions& o) {
  require_valid(t);
  if (!(o.width >= 100 && o.width <= 4000))
    throw std::invalid_argument("--width must be between 100 and 4000 pixels");
  if (t.templated.point_dimension == 3 && o.colour == CellColour::quality)
    throw std::invalid_argument("--color quality (smallest angle) is 2D only; use --color "
                                "instance, template or region for a 3D mesh");
  if (o.patches && (t.templated.point_dimension != 2 ||
                    o.patches->per_template.size() != t.templated.templates.size()))
    throw std::invalid_argument("boundary patches are drawn in 2D only, one list per template");
  const At at = collect(t);
  return at.dim == 2 ? svg_2d(at, t.templated, o) : svg_3d(at, o);
}

void write_png_from_svg(const std::string& svg, const std::string& path) {
  namespace fs = std::filesystem;
  const std::string svg_part = path + ".svg.part", png_part = path + ".part";
  write_file_atomically(svg_part, svg);
  std::vector<std::string> args{"rsvg-convert", "--format=png", "--output=" + png_part, svg_part};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  int status = -1;
  const bool spawned =
      posix_spawnp(&pid, "rsvg-convert", nullptr, nullptr, argv.data(), environ) == 0;
  if (spawned) waitpid(pid, &status, 0);
  std::error_code ec;
  fs::remove(svg_part, ec);
  if (!spawned || !WIFEXITED(status) || WEXITSTATUS(status) != 0 || !fs::exists(png_part)) {
    fs::remove(png_part, ec);
    throw std::runtime_error(path + ": rsvg-convert failed" +
                             std::string(spawned ? ""
                                                 : " (not found: install librsvg2-bin, "
                                                   "scripts/install-deps.sh)"));
  }
  fs::rename(png_part, path, ec);
  if (ec) throw std::runtime_error(path + ": cannot write (rename failed)");
}

std::size_t write_vtm(const mesh::TemplatedMeshCompactSvb& t, const std::string& path) {
  require_valid(t);
  namespace fs = std::filesystem;
  const fs::path vtm(path);
  const std::string stem = vtm.stem().string();
  const fs::path dir = vtm.parent_path() / stem;
  fs::create_directories(dir);
  std::ostringstream os;
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
        "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <vtkMultiBlockDataSet>\n";
  for (std::size_t k = 0; k < t.templated.templates.size(); ++k) {
    const std::string name = stem + "_" + std::to_string(k) + ".vtu";
    const auto block = block_of(t, k);
    write_vtu(mesh::StructureInstance(block), (dir / name).string());
    os << "    <DataSet index=\"" << k << "\" name=\"template " << (k + 1) << "\" file=\"" << stem
       << "/" << name << "\"/>\n";
  }
  os << "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
  write_file_atomically(path, os.str());
  return t.templated.templates.size();
}

} // namespace symmesh::io
