// Writers for the boundary patch partition. Exact coordinates are printed as exact strings in the
// JSON; the SVG and VTU round them to double for display only — nothing is decided from them.
#include "symmesh/io/bpp_output.h"
#include "symmesh/io/svg.h"

#include "symmesh/number/cyclotomic_cgal.h"

#include "symmesh/io/plot_box.h"

#include "symmesh/io/templated_structure_json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace symmesh::io {
namespace {

using ojson = nlohmann::ordered_json;

template <class FT, int D>
using Bpp = core::BoundaryPatchPartition<FT, D>;

template <class FT, int D>
ojson point_json(const core::Point<FT, D>& p) {
  ojson a = ojson::array();
  for (int d = 0; d < D; ++d) a.push_back(core::exact_text(p[d]));
  return a;
}

template <class FT, int D>
std::size_t subdivision_vertices(const Bpp<FT, D>& bpp) {
  std::size_t n = 0;
  for (const auto& s : bpp.subdivisions) n += s.points.size();
  return n;
}

template <class FT, int D>
ojson patch_json(const Bpp<FT, D>& bpp, std::size_t p) {
  const auto& patch = bpp.patches[p];
  ojson simplices = ojson::array();
  for (const auto& simplex : bpp.patch_simplices(p)) {
    ojson s = ojson::array();
    for (const auto& q : simplex) s.push_back(point_json<FT, D>(q));
    simplices.push_back(s);
  }
  ojson j;
  j["id"] = p;
  j["template"] = patch.template_index + 1;
  j["dimension"] = patch.dimension;
  j["class"] = patch.relation_class;
  j["faces"] = patch.faces.size();
  j["simplices"] = simplices;
  return j;
}

template <class FT, int D>
ojson bpp_json_impl(const core::TemplatedStructure<FT, D>& x, const Bpp<FT, D>& bpp) {
  ojson j;
  j["dimension"] = D;
  j["regular"] = bpp.regular();
  j["irregularity"] =
      bpp.regular() ? ojson(nullptr) : irregularity_json(core::summarise_irregularity(bpp));
  ojson templates = ojson::array();
  for (std::size_t t = 0; t < x.templates.size(); ++t) {
    ojson by_dim = ojson::array();
    for (int d = 0; d < D; ++d) by_dim.push_back(bpp.patch_count(t, d));
    templates.push_back({{"name", x.templates[t].name},
                         {"facet_patches", bpp.patch_count(t, D - 1)},
                         {"patches_by_dimension", by_dim}});
  }
  j["templates"] = templates;
  j["patches"] = ojson::array();
  for (std::size_t p = 0; p < bpp.patches.size(); ++p) j["patches"].push_back(patch_json(bpp, p));
  j["classes"] = bpp.classes;
  j["mappings"] = bpp.mappings.size();
  j["subdivision_vertices"] = subdivision_vertices(bpp);
  return j;
}

// ---------------------------------------------------------------------------------------------
// Drawing helpers (double only from here on).

using P = std::array<double, 2>;

template <class FT>
P to_p(const core::Point<FT, 2>& q) {
  return {CGAL::to_double(q[0]), CGAL::to_double(q[1])};
}

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", x == 0 ? 0.0 : x); // no "-0.000"
  return buf;
}

/// A fixed qualitative palette first (ColorBrewer Set1/Dark2, readable as thick lines on white),
/// then golden-angle hues, so that any number of classes gets stable, distinct colours.
std::string palette_colour(std::size_t k) {
  static const char* fixed[] = {"#e41a1c", "#377eb8", "#4daf4a", "#984ea3", "#ff7f00", "#a65628",
                                "#f781bf", "#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"};
  constexpr std::size_t n = sizeof fixed / sizeof fixed[0];
  if (k < n) return fixed[k];
  const double h = std::fmod(double(k - n) * 137.508, 360.0) / 60.0, s = 0.65, l = 0.45;
  const double c = (1 - std::fabs(2 * l - 1)) * s, x = c * (1 - std::fabs(std::fmod(h, 2.0) - 1));
  const double m = l - c / 2;
  double r = 0, g = 0, b = 0;
  if (h < 1)
    r = c, g = x;
  else if (h < 2)
    r = x, g = c;
  else if (h < 3)
    g = c, b = x;
  else if (h < 4)
    g = x, b = c;
  else if (h < 5)
    r = x, b = c;
  else
    r = c, b = x;
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(std::lround((r + m) * 255)),
                int(std::lround((g + m) * 255)), int(std::lround((b + m) * 255)));
  return buf;
}

/// Classes with one patch relate nothing to anything else: dark grey keeps the eye on the rest.
template <class FT>
std::vector<std::string> class_colours(const Bpp<FT, 2>& bpp) {
  std::vector<std::string> out;
  std::size_t shared = 0;
  for (const auto& c : bpp.classes) out.push_back(c.size() > 1 ? palette_colour(shared++) : "#555");
  return out;
}

struct Box : detail::PlotBox {
  double width() const { return span_x(); }
  double height() const { return span_y(); }
};

/// Grid of equal panels, one per template, all drawn at the same scale.
template <class FT>
struct Layout {
  static constexpr double kBanner = 28, kTitle = 18, kMargin = 28, kPanel = 260;
  std::vector<Box> boxes;
  std::size_t cols = 1, rows = 1;
  double scale = 1, cell_w = 0, cell_h = 0;

  explicit Layout(const core::TemplatedStructure<FT, 2>& x) {
    double extent = 0, w = 0, h = 0;
    for (const auto& t : x.templates) {
      Box b;
      for (const auto& q : t.mesh.points) b.add(to_p(q));
      boxes.push_back(b);
      extent = std::max({extent, b.width(), b.height()});
      w = std::max(w, b.width());
      h = std::max(h, b.height());
    }
    scale = kPanel / std::max(extent, 1e-12);
    cols = std::min<std::size_t>(boxes.size(), 4);
    rows = (boxes.size() + cols - 1) / cols;
    cell_w = w * scale + 2 * kMargin;
    cell_h = h * scale + 2 * kMargin + kTitle;
  }
  P origin(std::size_t t) const {
    return {double(t % cols) * cell_w, kBanner + double(t / cols) * cell_h};
  }
  P map(std::size_t t, const P& p) const { // SVG's y axis points down
    const P o = origin(t);
    return {o[0] + kMargin + (p[0] - boxes[t].minx) * scale,
            o[1] + kTitle + kMargin + (boxes[t].maxy - p[1]) * scale};
  }
  double width() const { return double(cols) * cell_w + 40; } // room for the right labels
  double grid_bottom() const { return kBanner + double(rows) * cell_h; }
};

/// Where a patch's label and relation curves attach: the middle of its middle simplex, which
/// lies on the patch (a centroid of a bent polyline need not).
template <class FT>
P anchor(const Layout<FT>& lay, const Bpp<FT, 2>& bpp, std::size_t p) {
  std::vector<std::vector<core::Point<FT, 2>>> top; // the closure's points are listed too
  for (auto& s : bpp.patch_simplices(p))
    if (int(s.size()) == bpp.patches[p].dimension + 1) top.push_back(std::move(s));
  const auto& mid = top[top.size() / 2];
  P a{0, 0};
  for (const auto& q : mid) {
    const P m = lay.map(bpp.patches[p].template_index, to_p(q));
    a[0] += m[0] / double(mid.size());
    a[1] += m[1] / double(mid.size());
  }
  return a;
}

template <class FT>
void draw_panel(std::ostringstream& os, const Layout<FT>& lay,
                const core::TemplatedStructure<FT, 2>& x, std::size_t t) {
  const auto& m = x.templates[t].mesh;
  const P o = lay.origin(t);
  os << "<g id=\"template-" << t + 1 << "\">\n";
  os << "<text x=\"" << num(o[0] + Layout<FT>::kMargin) << "\" y=\""
     << num(o[1] + Layout<FT>::kTitle) << "\" font-family=\"sans-serif\" font-size=\"13\">"
     << xml_escape(x.templates[t].name) << " (template " << t + 1 << ")</text>\n";
  // Interior cells with a same-colour stroke, so no seams show between them.
  for (const auto& e : m.elements) {
    if (e.dim() != 2) continue;
    os << "<polygon fill=\"#eeeeee\" stroke=\"#eeeeee\" stroke-width=\"0.5\" points=\"";
    for (auto v : e) {
      const P p = lay.map(t, to_p(m.points[v]));
      os << num(p[0]) << "," << num(p[1]) << " ";
    }
    os << "\"/>\n";
  }
  os << "</g>\n";
}

template <class FT>
void draw_patches(std::ostringstream& os, const Layout<FT>& lay, const Bpp<FT, 2>& bpp,
                  const std::vector<std::string>& colour) {
  // Facet patches first, so that the dots of lower-dimensional patches stay visible on top.
  for (int dim : {1, 0})
    for (std::size_t p = 0; p < bpp.patches.size(); ++p) {
      const auto& patch = bpp.patches[p];
      if (patch.dimension != dim) continue;
      const std::size_t t = patch.template_index;
      os << "<g class=\"patch\" data-patch=\"" << p << "\" data-class=\"" << patch.relation_class
         << "\" data-dimension=\"" << dim << "\">";
      if (dim == 1) {
        os << "<path fill=\"none\" stroke=\"" << colour[patch.relation_class]
           << "\" stroke-width=\"5\" stroke-linecap=\"round\" d=\"";
        for (const auto& s : bpp.patch_simplices(p)) {
          if (s.size() != 2) continue; // the end points are drawn by the segments
          const P a = lay.map(t, to_p(s[0])), b = lay.map(t, to_p(s[1]));
          os << "M" << num(a[0]) << " " << num(a[1]) << " L" << num(b[0]) << " " << num(b[1])
             << " ";
        }
        os << "\"/>";
      } else {
        for (const auto& s : bpp.patch_simplices(p)) {
          const P a = lay.map(t, to_p(s[0]));
          os << "<circle cx=\"" << num(a[0]) << "\" cy=\"" << num(a[1]) << "\" r=\"5\" fill=\""
             << colour[patch.relation_class] << "\" stroke=\"white\" stroke-width=\"1.5\"/>";
        }
      }
      os << "</g>\n";
    }
}

/// One dashed curve per unordered pair of distinct patches joined by a mapping (an arrow of the
/// patch graph); the relation ~ is their transitive closure. Curved, so that a curve between two
/// patches of one straight boundary does not hide the boundary.
template <class FT>
void draw_relation(std::ostringstream& os, const Layout<FT>& lay, const Bpp<FT, 2>& bpp,
                   const std::vector<std::string>& colour) {
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  for (const auto& a : bpp.arrows)
    if (a.from != a.to) pairs.emplace(std::min(a.from, a.to), std::max(a.from, a.to));
  for (const auto& [p, q] : pairs) {
    const P a = anchor(lay, bpp, p), b = anchor(lay, bpp, q);
    const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::hypot(dx, dy);
    if (len < 1e-9) continue;
    const P c{(a[0] + b[0]) / 2 - 0.25 * dy, (a[1] + b[1]) / 2 + 0.25 * dx};
    os << "<path class=\"relation\" data-patches=\"" << p << " " << q
       << "\" fill=\"none\" stroke=\"" << colour[bpp.patches[p].relation_class]
       << "\" stroke-width=\"1.2\" stroke-dasharray=\"6,4\" d=\"M" << num(a[0]) << " " << num(a[1])
       << " Q" << num(c[0]) << " " << num(c[1]) << " " << num(b[0]) << " " << num(b[1]) << "\"/>\n";
  }
}

template <class FT>
void draw_labels(std::ostringstream& os, const Layout<FT>& lay, const Bpp<FT, 2>& bpp) {
  for (std::size_t p = 0; p < bpp.patches.size(); ++p) {
    const P a = anchor(lay, bpp, p);
    os << "<text x=\"" << num(a[0] + 6) << "\" y=\"" << num(a[1] - 6)
       << "\" font-family=\"sans-serif\" font-size=\"10\" stroke=\"white\" stroke-width=\"3\" "
          "paint-order=\"stroke\">P"
       << p << " c" << bpp.patches[p].relation_class << "</text>\n";
  }
}

/// The legend lists every class with its colour and (up to 8 of) its patches.
template <class FT>
double draw_legend(std::ostringstream& os, const Layout<FT>& lay, const Bpp<FT, 2>& bpp,
                   const std::vector<std::string>& colour) {
  constexpr double kColumn = 400, kLine = 16;
  const double top = lay.grid_bottom() + 30;
  const std::size_t cols = std::max<std::size_t>(1, std::size_t(lay.width() / kColumn));
  os << "<text x=\"10\" y=\"" << num(top + 12)
     << "\" font-family=\"sans-serif\" font-size=\"12\">Relation classes (Def 4.8); dashed: a "
        "mapping sends one patch onto the other</text>\n";
  for (std::size_t k = 0; k < bpp.classes.size(); ++k) {
    const double x = 10 + double(k % cols) * kColumn, y = top + 20 + double(k / cols) * kLine;
    os << "<line x1=\"" << num(x) << "\" y1=\"" << num(y + 8) << "\" x2=\"" << num(x + 22)
       << "\" y2=\"" << num(y + 8) << "\" stroke=\"" << colour[k]
       << "\" stroke-width=\"5\" stroke-linecap=\"round\"/>";
    os << "<text x=\"" << num(x + 30) << "\" y=\"" << num(y + 12)
       << "\" font-family=\"sans-serif\" font-size=\"11\">c" << k << ":";
    const auto& cls = bpp.classes[k];
    for (std::size_t i = 0; i < std::min<std::size_t>(cls.size(), 8); ++i) os << " P" << cls[i];
    if (cls.size() > 8) os << " … (" << cls.size() << " patches)";
    os << "</text>\n";
  }
  const std::size_t rows = (bpp.classes.size() + cols - 1) / cols;
  return top + 20 + double(rows) * kLine + 10;
}

template <class FT>
std::string banner(const Bpp<FT, 2>& bpp) {
  std::ostringstream os;
  os << "Boundary patch partition (Algorithm 4.1): " << bpp.patches.size() << " patches, "
     << bpp.classes.size() << " relation classes, instance graph ";
  if (bpp.regular())
    os << "regular (Def 4.9)";
  else
    os << "IRREGULAR (Def 4.9): two compositions map P" << bpp.irregularity->patch << " onto P"
       << bpp.irregularity->target << " and differ on it";
  return os.str();
}

// ---------------------------------------------------------------------------------------------
// VTK XML.

template <class FT, int D>
P template_x_range(const core::BoundarySubdivision<FT, D>& s) {
  P r{std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()};
  for (const auto& q : s.points) {
    r[0] = std::min(r[0], CGAL::to_double(q[0]));
    r[1] = std::max(r[1], CGAL::to_double(q[0]));
  }
  return r;
}

/// x shift of each template: boundaries side by side with a gap of a quarter of the widest one.
template <class FT, int D>
std::vector<double> x_shifts(const Bpp<FT, D>& bpp) {
  std::vector<P> range;
  double widest = 0;
  for (const auto& s : bpp.subdivisions) {
    range.push_back(template_x_range(s));
    widest = std::max(widest, range.back()[1] - range.back()[0]);
  }
  const double gap = widest > 0 ? widest / 4 : 1;
  std::vector<double> shift;
  double cursor = 0;
  for (const auto& r : range) {
    shift.push_back(cursor - r[0]);
    cursor += (r[1] - r[0]) + gap;
  }
  return shift;
}

std::string real(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x == 0 ? 0.0 : x);
  return buf;
}

void data_array(std::ostringstream& os, const char* type, const char* name,
                const std::vector<long long>& values) {
  os << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < values.size(); ++i)
    os << (i % 16 == 0 ? "          " : " ") << values[i] << (i % 16 == 15 ? "\n" : "");
  if (values.size() % 16 != 0) os << "\n";
  os << "        </DataArray>\n";
}

template <class FT, int D>
std::string bpp_vtu_impl(const Bpp<FT, D>& bpp) {
  const auto shift = x_shifts(bpp);
  std::vector<std::size_t> base{0};
  for (const auto& s : bpp.subdivisions) base.push_back(base.back() + s.points.size());
  std::vector<long long> connectivity, offsets, types, tmpl, patch, cls, dim;
  for (std::size_t p = 0; p < bpp.patches.size(); ++p) {
    const auto& pt = bpp.patches[p];
    const auto& s = bpp.subdivisions[pt.template_index];
    for (std::size_t f : pt.faces)
      for (const auto& piece : s.faces[f].pieces) {
        for (auto v : piece) connectivity.push_back((long long)(base[pt.template_index] + v));
        offsets.push_back((long long)connectivity.size());
        static constexpr int kVtkType[] = {1, 3, 5}; // VTK_VERTEX, VTK_LINE, VTK_TRIANGLE
        types.push_back(kVtkType[piece.dim()]);
        tmpl.push_back((long long)pt.template_index + 1);
        patch.push_back((long long)p);
        cls.push_back((long long)pt.relation_class);
        dim.push_back(pt.dimension);
      }
  }
  std::ostringstream os;
  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n"
     << "  <UnstructuredGrid>\n"
     << "    <Piece NumberOfPoints=\"" << base.back() << "\" NumberOfCells=\"" << types.size()
     << "\">\n"
     << "      <Points>\n"
     << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t t = 0; t < bpp.subdivisions.size(); ++t)
    for (const auto& q : bpp.subdivisions[t].points) {
      os << "          " << real(CGAL::to_double(q[0]) + shift[t]);
      for (int d = 1; d < 3; ++d) os << " " << real(d < D ? CGAL::to_double(q[d]) : 0.0);
      os << "\n";
    }
  os << "        </DataArray>\n      </Points>\n      <Cells>\n";
  data_array(os, "Int64", "connectivity", connectivity);
  data_array(os, "Int64", "offsets", offsets);
  data_array(os, "UInt8", "types", types);
  os << "      </Cells>\n      <CellData Scalars=\"class\">\n";
  data_array(os, "Int32", "template", tmpl);
  data_array(os, "Int32", "patch", patch);
  data_array(os, "Int32", "class", cls);
  data_array(os, "Int32", "dimension", dim);
  os << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return os.str();
}

} // namespace

ojson irregularity_json(const core::IrregularitySummary& w) {
  ojson matrix = ojson::array();
  for (const auto& row : w.symmetry_matrix) {
    ojson r = ojson::array();
    for (const auto& a : row) r.push_back(a);
    matrix.push_back(r);
  }
  ojson translation = ojson::array();
  for (const auto& b : w.symmetry_translation) translation.push_back(b);
  ojson j;
  j["patch"] = w.patch;
  j["target"] = w.target;
  j["f1"] = w.f1;
  j["f2"] = w.f2;
  j["symmetry"] = {{"matrix", matrix}, {"translation", translation}};
  return j;
}

namespace {
template <class FT>
std::string bpp_svg_impl(const core::TemplatedStructure<FT, 2>& x, const Bpp<FT, 2>& bpp) {
  const Layout<FT> lay(x);
  const auto colour = class_colours(bpp);
  std::ostringstream body;
  body << "<text x=\"10\" y=\"18\" font-family=\"sans-serif\" font-size=\"13\">"
       << xml_escape(banner(bpp)) << "</text>\n";
  for (std::size_t t = 0; t < x.templates.size(); ++t) draw_panel(body, lay, x, t);
  draw_patches(body, lay, bpp, colour);
  draw_relation(body, lay, bpp, colour);
  draw_labels(body, lay, bpp);
  const double height = draw_legend(body, lay, bpp, colour);
  // Wide enough for the banner too (about 7 px per character at font-size 13).
  const double width = std::max({lay.width(), 600.0, 7.0 * double(banner(bpp).size()) + 20});
  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\""
     << num(height) << "\" viewBox=\"0 0 " << num(width) << " " << num(height) << "\">\n"
     << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
     << body.str() << "</svg>\n";
  return os.str();
}

} // namespace

ojson bpp_json(const core::TemplatedStructure<Exact, 2>& x, const Bpp2& bpp) {
  return bpp_json_impl<Exact, 2>(x, bpp);
}
ojson bpp_json(const core::TemplatedStructure<Exact, 3>& x, const Bpp3& bpp) {
  return bpp_json_impl<Exact, 3>(x, bpp);
}
ojson bpp_json(const core::TemplatedStructure<Cyclotomic, 2>& x, const CyclotomicBpp2& bpp) {
  return bpp_json_impl<Cyclotomic, 2>(x, bpp);
}
ojson bpp_json(const core::TemplatedStructure<Cyclotomic, 3>& x, const CyclotomicBpp3& bpp) {
  return bpp_json_impl<Cyclotomic, 3>(x, bpp);
}

namespace {
template <class FT>
PatchOverlay patch_overlay_impl(const Bpp<FT, 2>& bpp) {
  PatchOverlay out;
  out.per_template.resize(bpp.subdivisions.size());
  out.classes = bpp.classes.size();
  const auto colour = class_colours(bpp);
  for (std::size_t p = 0; p < bpp.patches.size(); ++p) {
    const auto& patch = bpp.patches[p];
    if (patch.dimension != 1) continue;
    for (const auto& s : bpp.patch_simplices(p))
      if (s.size() == 2)
        out.per_template[patch.template_index].push_back(
            {to_p(s[0]), to_p(s[1]), patch.relation_class, colour[patch.relation_class]});
  }
  return out;
}
} // namespace

PatchOverlay patch_overlay(const Bpp2& bpp) {
  return patch_overlay_impl(bpp);
}
PatchOverlay patch_overlay(const CyclotomicBpp2& bpp) {
  return patch_overlay_impl(bpp);
}

std::string bpp_svg(const core::TemplatedStructure<Exact, 2>& x, const Bpp2& bpp) {
  return bpp_svg_impl<Exact>(x, bpp);
}
std::string bpp_svg(const core::TemplatedStructure<Cyclotomic, 2>& x, const CyclotomicBpp2& bpp) {
  return bpp_svg_impl<Cyclotomic>(x, bpp);
}

std::string bpp_vtu(const Bpp2& bpp) {
  return bpp_vtu_impl<Exact, 2>(bpp);
}
std::string bpp_vtu(const Bpp3& bpp) {
  return bpp_vtu_impl<Exact, 3>(bpp);
}
std::string bpp_vtu(const CyclotomicBpp2& bpp) {
  return bpp_vtu_impl<Cyclotomic, 2>(bpp);
}
std::string bpp_vtu(const CyclotomicBpp3& bpp) {
  return bpp_vtu_impl<Cyclotomic, 3>(bpp);
}

} // namespace symmesh::io
