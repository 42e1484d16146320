// SVG pictures of 2D element complexes and structure instances. Coordinates are rounded to
// double here only for drawing; nothing is decided from them.
#include "symmesh/io/svg.h"

#include "symmesh/io/colour.h"
#include "symmesh/io/plot_box.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>
#include <iterator>
#include <sstream>
#include <utility>

namespace symmesh::io {
namespace {

using P = std::array<double, 2>;

struct Frame : detail::PlotBox {
  double scale() const {
    const double w = std::max(maxx - minx, 1e-12), h = std::max(maxy - miny, 1e-12);
    return 560.0 / std::max(w, h);
  }
  P map(const P& p) const { // SVG's y axis points down
    return {20 + (p[0] - minx) * scale(), 20 + (maxy - p[1]) * scale()};
  }
  double width() const { return 40 + (maxx - minx) * scale(); }
  double height() const { return 40 + (maxy - miny) * scale(); }
};

P to_p(const core::Point<Exact, 2>& q) {
  return {CGAL::to_double(q[0]), CGAL::to_double(q[1])};
}

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", x);
  return buf;
}

void draw_complex(std::ostringstream& os, const Frame& f, const core::ElementComplex<Exact, 2>& m,
                  const std::string& fill) {
  for (const auto& e : m.elements) {
    if (e.dim() == 2) {
      os << "<polygon fill=\"" << fill << "\" fill-opacity=\"0.8\" stroke=\"none\" points=\"";
      for (auto v : e) {
        const P p = f.map(to_p(m.points[v]));
        os << num(p[0]) << "," << num(p[1]) << " ";
      }
      os << "\"/>\n";
    }
  }
  for (const auto& e : m.elements) {
    if (e.dim() == 1) {
      const P a = f.map(to_p(m.points[e.v[0]])), b = f.map(to_p(m.points[e.v[1]]));
      os << "<line x1=\"" << num(a[0]) << "\" y1=\"" << num(a[1]) << "\" x2=\"" << num(b[0])
         << "\" y2=\"" << num(b[1]) << "\" stroke=\"#333\" stroke-width=\"1\"/>\n";
    } else if (e.dim() == 0) {
      const P a = f.map(to_p(m.points[e.v[0]]));
      os << "<circle cx=\"" << num(a[0]) << "\" cy=\"" << num(a[1])
         << "\" r=\"2.5\" fill=\"#000\"/>\n";
    }
  }
}

std::string header(const Frame& f) {
  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(f.width()) << "\" height=\""
     << num(f.height()) << "\" viewBox=\"0 0 " << num(f.width()) << " " << num(f.height())
     << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  return os.str();
}

} // namespace

std::string xml_escape(const std::string& s) {
  static const std::pair<char, const char*> entities[] = {
      {'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}, {'"', "&quot;"}};
  std::string out;
  for (char c : s) {
    const auto* e = std::find_if(std::begin(entities), std::end(entities),
                                 [c](const auto& entity) { return entity.first == c; });
    if (e == std::end(entities))
      out += c;
    else
      out += e->second;
  }
  return out;
}

std::string complex_svg(const core::ElementComplex<Exact, 2>& m) {
  Frame f;
  for (const auto& q : m.points) f.add(to_p(q));
  if (m.points.empty()) f.add({0, 0});
  std::ostringstream os;
  os << header(f);
  draw_complex(os, f, m, fill_colour(0));
  os << "</svg>\n";
  return os.str();
}

std::string structure_svg(const core::TemplatedStructure<Exact, 2>& x) {
  std::vector<core::ElementComplex<Exact, 2>> inst;
  std::vector<core::InstanceId> ids = x.instance_ids();
  Frame f;
  for (auto id : ids) {
    inst.push_back(core::instance(x, id));
    for (const auto& q : inst.back().points) f.add(to_p(q));
  }
  if (ids.empty()) f.add({0, 0});
  std::ostringstream os;
  os << header(f);
  for (std::size_t k = 0; k < inst.size(); ++k) draw_complex(os, f, inst[k], fill_colour(ids[k].i));
  for (std::size_t k = 0; k < inst.size(); ++k) {
    double cx = 0, cy = 0;
    for (const auto& q : inst[k].points) {
      const P p = f.map(to_p(q));
      cx += p[0];
      cy += p[1];
    }
    const double n = double(std::max<std::size_t>(1, inst[k].points.size()));
    os << "<text x=\"" << num(cx / n) << "\" y=\"" << num(cy / n)
       << "\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"middle\">"
       << core::to_string(ids[k]) << "</text>\n";
  }
  os << "</svg>\n";
  return os.str();
}

} // namespace symmesh::io
