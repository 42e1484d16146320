// The cut of a whole symmetric object into its fundamental piece (spec/generation.md#cut).
#include "symmesh/gen/symmetry_cut.h"
#include "symmesh/gen/cut_support.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace symmesh::gen {
namespace {

using number::Cyclotomic;
using number::CyclotomicField;
using number::CyclotomicFieldPtr;
using P = CutPoint;

constexpr double kPi = 3.14159265358979323846;
using cut_support::compare_coefficients;
using cut_support::cos_sin;
using cut_support::embed;
using cut_support::field_for;
using cut_support::kMaxFieldOrder;

// ----- exact arithmetic on points -------------------------------------------------------------

P sub(const P& a, const P& b) {
  return {a[0] - b[0], a[1] - b[1]};
}
P add(const P& a, const P& b) {
  return {a[0] + b[0], a[1] + b[1]};
}
P scale(const P& a, const Cyclotomic& s) {
  return {a[0] * s, a[1] * s};
}
Cyclotomic cross(const P& a, const P& b) {
  return a[0] * b[1] - a[1] * b[0];
}
Cyclotomic dot(const P& a, const P& b) {
  return a[0] * b[0] + a[1] * b[1];
}

/// A total order on exact points for maps (not a geometric order).
struct KeyLess {
  bool operator()(const P& a, const P& b) const {
    if (const int c = compare_coefficients(a[0], b[0]); c != 0) return c < 0;
    return compare_coefficients(a[1], b[1]) < 0;
  }
};
struct PairLess {
  bool operator()(const std::pair<P, P>& a, const std::pair<P, P>& b) const {
    const KeyLess l;
    if (l(a.first, b.first)) return true;
    if (l(b.first, a.first)) return false;
    return l(a.second, b.second);
  }
};
/// Geometric (x, then y) order, for a deterministic start of every ring.
bool geometric_less(const P& a, const P& b) {
  if (const int c = compare(a[0], b[0]); c != 0) return c < 0;
  return compare(a[1], b[1]) < 0;
}

std::string show(const P& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p[0].to_double() << ", " << p[1].to_double() << ")";
  return s.str();
}

// ----- the symmetry group ---------------------------------------------------------------------

struct Group {
  CyclotomicFieldPtr field;
  int n = 0; ///< rotation order (0: none)
  std::vector<P> mirrors;

  P rotate(const P& p, int k) const {
    if (n == 0 || k % n == 0) return p;
    const auto [c, s] = cos_sin(k, n, field);
    return {c * p[0] - s * p[1], s * p[0] + c * p[1]};
  }
  P reflect(const P& p, std::size_t j) const {
    const P& m = mirrors[j];
    return sub(p, scale(m, Cyclotomic(2) * dot(m, p) / dot(m, m)));
  }
  P apply(const GroupElement& g, const P& p) const {
    P q = p;
    for (std::size_t j = 0; j < mirrors.size(); ++j)
      if (g.mirror_bits & (1u << j)) q = reflect(q, j);
    return rotate(q, g.k);
  }
  static bool preserves_orientation(const GroupElement& g) {
    return std::popcount(g.mirror_bits) % 2 == 0;
  }
};

// ----- boundaries of unions of polygons -------------------------------------------------------

/// Directed edge between point indices; the interior of its polygon lies on its left.
using Edge = std::pair<std::size_t, std::size_t>;

struct PointTable {
  std::vector<P> points;
  std::map<P, std::size_t, KeyLess> index;
  std::size_t id(const P& p) {
    auto [it, fresh] = index.emplace(p, points.size());
    if (fresh) points.push_back(p);
    return it->second;
  }
};

/// The boundary edges of the union of non-overlapping counter-clockwise polygons: every edge is
/// first cut at the polygons' vertices that lie inside it (T-junctions between carriers), then
/// an edge is on the boundary iff its reverse is not an edge. Throws when two polygons overlap.
std::vector<Edge> union_boundary(const std::vector<std::vector<P>>& polygons, PointTable& t) {
  std::vector<Edge> edges;
  for (const auto& poly : polygons)
    for (std::size_t i = 0; i < poly.size(); ++i)
      edges.push_back({t.id(poly[i]), t.id(poly[(i + 1) % poly.size()])});
  // Certified boxes of the points: the exact collinearity test runs only on candidates.
  std::vector<std::pair<double, double>> bx, by;
  for (const auto& p : t.points) {
    bx.push_back(p[0].to_interval());
    by.push_back(p[1].to_interval());
  }
  std::vector<std::size_t> by_x(t.points.size());
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](auto a, auto b) { return bx[a].first < bx[b].first; });
  std::vector<double> lo_x;
  double widest = 0; // the widest x interval: a point meets [x0, x1] only if lo >= x0 - widest
  for (auto v : by_x) {
    lo_x.push_back(bx[v].first);
    widest = std::max(widest, bx[v].second - bx[v].first);
  }

  std::vector<Edge> split;
  for (const auto& [a, b] : edges) {
    const P& pa = t.points[a];
    const P d = sub(t.points[b], pa);
    const Cyclotomic dd = dot(d, d);
    const double x0 = std::min(bx[a].first, bx[b].first), x1 = std::max(bx[a].second, bx[b].second);
    const double y0 = std::min(by[a].first, by[b].first), y1 = std::max(by[a].second, by[b].second);
    std::vector<std::pair<Cyclotomic, std::size_t>> inner;
    for (auto it =
             std::lower_bound(lo_x.begin(), lo_x.end(), std::nextafter(x0 - widest, -HUGE_VAL));
         it != lo_x.end() && *it <= x1; ++it) {
      const std::size_t v = by_x[std::size_t(it - lo_x.begin())];
      if (v == a || v == b || bx[v].second < x0 || by[v].second < y0 || by[v].first > y1) continue;
      const P w = sub(t.points[v], pa);
      if (!cross(d, w).is_zero()) continue;
      const Cyclotomic s = dot(w, d);
      if (s.sign() > 0 && s < dd) inner.push_back({s, v});
    }
    std::sort(inner.begin(), inner.end(),
              [](const auto& u, const auto& v) { return u.first < v.first; });
    std::size_t from = a;
    for (const auto& [s, v] : inner) {
      split.push_back({from, v});
      from = v;
    }
    split.push_back({from, b});
  }
  std::map<Edge, int> count;
  for (const auto& e : split) ++count[e];
  std::vector<Edge> out;
  for (const auto& [e, c] : count) {
    if (c > 1)
      throw CutError("two pieces of the object overlap along " + show(t.points[e.first]) + "-" +
                     show(t.points[e.second]) + " (Eq. 4.2)");
    if (!count.count({e.second, e.first})) out.push_back(e);
  }
  return out;
}

/// The maximal straight boundary segments: consecutive collinear boundary edges are merged at
/// vertices with one incoming and one outgoing boundary edge.
std::vector<std::pair<P, P>> maximal_segments(const std::vector<Edge>& boundary,
                                              const PointTable& t) {
  std::map<std::size_t, std::vector<std::size_t>> out, in;
  for (const auto& [a, b] : boundary) {
    out[a].push_back(b);
    in[b].push_back(a);
  }
  const auto passes = [&](std::size_t v) {
    if (out[v].size() != 1 || in[v].size() != 1) return false;
    const P u = sub(t.points[v], t.points[in[v][0]]);
    const P w = sub(t.points[out[v][0]], t.points[v]);
    return cross(u, w).is_zero() && dot(u, w).sign() > 0;
  };
  std::vector<std::pair<P, P>> segments;
  for (const auto& [a, b0] : boundary) {
    if (passes(a)) continue;
    std::size_t b = b0;
    while (passes(b)) b = out[b][0];
    segments.push_back({t.points[a], t.points[b]});
  }
  return segments;
}

// ----- the object -----------------------------------------------------------------------------

struct Object {
  std::map<int, std::vector<std::vector<P>>> triangles; ///< per region, counter-clockwise
};

Object whole_object(const core::TemplatedStructure<Cyclotomic, 2>& x, const CyclotomicFieldPtr& F) {
  Object o;
  for (const auto& id : x.instance_ids()) {
    const auto inst = core::instance(x, id);
    const int region = x.instances[id.i][id.g].region;
    for (const auto& c : inst.cells()) {
      std::vector<P> tri;
      for (auto v : c) tri.push_back({embed(inst.points[v][0], F), embed(inst.points[v][1], F)});
      const Cyclotomic o2 = cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]));
      if (o2.is_zero()) continue; // a degenerate carrier cell covers no area
      if (o2.sign() < 0) std::swap(tri[1], tri[2]);
      o.triangles[region].push_back(std::move(tri));
    }
  }
  return o;
}

std::string element_name(const Group& g, const GroupElement& e) {
  std::string s;
  if (e.k != 0) s = "the rotation by 2pi*" + std::to_string(e.k) + "/" + std::to_string(g.n);
  for (std::size_t j = 0; j < g.mirrors.size(); ++j)
    if (e.mirror_bits & (1u << j))
      s += (s.empty() ? "" : " o ") + std::string("the reflection in the line orthogonal to ") +
           show(g.mirrors[j]);
  return s;
}

/// The object has the symmetry: every generator maps each region's maximal boundary segments
/// onto themselves (a bounded region is determined by its boundary, so that suffices).
void verify_symmetry(const Group& g, const std::map<int, std::vector<std::pair<P, P>>>& segs) {
  std::vector<GroupElement> generators;
  if (g.n >= 2) generators.push_back({1, 0});
  for (std::size_t j = 0; j < g.mirrors.size(); ++j) generators.push_back({0, 1u << j});
  for (const auto& [region, list] : segs) {
    const std::set<std::pair<P, P>, PairLess> have(list.begin(), list.end());
    for (const auto& e : generators)
      for (const auto& [a, b] : list) {
        const P ga = g.apply(e, a), gb = g.apply(e, b);
        const auto image = Group::preserves_orientation(e) ? std::pair{ga, gb} : std::pair{gb, ga};
        if (!have.count(image))
          throw CutError("the object does not have the symmetry: " + element_name(g, e) +
                         " maps the boundary segment " + show(a) + "-" + show(b) + " of region " +
                         std::to_string(region) + " onto no boundary segment of that region");
      }
  }
}

// ----- Algorithm 6.3 --------------------------------------------------------------------------

struct Candidate {
  double sigma = 0; ///< the ray's angle, radians
  int rank = 0;     ///< 0 foot, 1 vertex, 2 balance: exact kinds first on ties
  P exact;          ///< the exact direction (foot, vertex), set for rank < 2
  double value = 0; ///< smallest new angle, degrees
};

double reduce(double a, double period) {
  double r = std::fmod(a, period);
  if (r < 0) r += period;
  if (r >= period) r -= period;
  return r;
}

/// Algorithm 6.3 (2D): candidate rays are the directions of the object's vertices, of the feet
/// of the perpendiculars from the origin (where the angle with one edge peaks at 90°), and of
/// the rays where two edges' angles are equal (where a rising and a falling piece cross); the
/// objective is piecewise linear between them, so its maximum is at one of them.
std::vector<Candidate> ranked_starts(const std::vector<std::pair<P, P>>& segments, int n) {
  const double alpha = 2 * kPi / n;
  std::vector<std::array<double, 4>> seg;
  std::vector<std::pair<P, P>> exact;
  for (const auto& [a, b] : segments) {
    if (cross(a, b).is_zero()) continue; // radial, or through the origin: no new angle
    seg.push_back({a[0].to_double(), a[1].to_double(), b[0].to_double(), b[1].to_double()});
    exact.push_back({a, b});
  }
  std::vector<Candidate> cands;
  std::vector<double> foot_angle(seg.size()), lo(seg.size()), width(seg.size());
  for (std::size_t i = 0; i < seg.size(); ++i) {
    const auto& [a, b] = exact[i];
    const auto& s = seg[i];
    const double ta = std::atan2(s[1], s[0]), tb = std::atan2(s[3], s[2]);
    // The span of rays through the segment, counter-clockwise from lo, narrower than π.
    const bool ccw = cross(a, b).sign() > 0;
    lo[i] = reduce(ccw ? ta : tb, 2 * kPi);
    width[i] = reduce(ccw ? tb - ta : ta - tb, 2 * kPi);
    cands.push_back({ta, 1, a, 0});
    cands.push_back({tb, 1, b, 0});
    const P d = sub(b, a);
    const Cyclotomic t = -dot(a, d) / dot(d, d);
    const P foot = add(a, scale(d, t));
    foot_angle[i] = std::atan2(foot[1].to_double(), foot[0].to_double());
    if (t.sign() >= 0 && t <= Cyclotomic(1)) cands.push_back({foot_angle[i], 0, foot, 0});
  }
  const auto spans_overlap = [&](std::size_t i, std::size_t j) {
    const double d = reduce(lo[j] - lo[i], 2 * kPi);
    return d <= width[i] || reduce(lo[i] - lo[j], 2 * kPi) <= width[j];
  };
  // Balancing rays are looked for in the first sector [0, α] only (the others are its turned
  // copies), which keeps the pairs to the segments there.
  const auto in_first_sector = [&](std::size_t i) {
    return lo[i] <= alpha || lo[i] + width[i] >= 2 * kPi;
  };
  std::vector<std::size_t> sector;
  for (std::size_t i = 0; i < seg.size(); ++i)
    if (in_first_sector(i)) sector.push_back(i);
  for (std::size_t a = 0; a < sector.size(); ++a)
    for (std::size_t b = a + 1; b < sector.size(); ++b)
      if (const std::size_t i = sector[a], j = sector[b]; spans_overlap(i, j)) {
        const double mid = (foot_angle[i] + foot_angle[j]) / 2;
        cands.push_back({mid, 2, {}, 0});
        cands.push_back({mid + kPi, 2, {}, 0});
      }
  // Symmetric copies of a candidate have the same value: keep one per angle modulo α.
  for (auto& c : cands) c.sigma = reduce(c.sigma, alpha);
  std::sort(cands.begin(), cands.end(), [](const Candidate& u, const Candidate& v) {
    return u.sigma != v.sigma ? u.sigma < v.sigma : u.rank < v.rank;
  });
  // One candidate per ray (angles within rounding are one ray), of the most exact kind.
  std::vector<Candidate> unique;
  for (const auto& c : cands)
    if (unique.empty() || std::abs(c.sigma - unique.back().sigma) > 1e-12)
      unique.push_back(c);
    else if (c.rank < unique.back().rank)
      unique.back() = c;
  for (auto& c : unique) c.value = smallest_new_angle_deg(seg, c.sigma);
  // Best first; ties (within rounding of the double objective) keep the exact kinds, then the
  // smallest σ (the sort is stable and `unique` is ordered by σ).
  const double tie = 1e-9;
  std::stable_sort(unique.begin(), unique.end(), [&](const Candidate& u, const Candidate& v) {
    if (std::abs(u.value - v.value) > tie) return u.value > v.value;
    return u.rank < v.rank;
  });
  if (unique.empty()) unique.push_back({0, 1, {Cyclotomic(1), Cyclotomic(0)}, 90}); // the x-axis
  for (auto& c : unique)
    if (c.rank == 2) {
      // A rational direction within 2^-30 of the balancing ray.
      const double scale_bits = 1073741824.0;
      c.exact = {Cyclotomic(mpq_class(long(std::lround(std::cos(c.sigma) * scale_bits)))),
                 Cyclotomic(mpq_class(long(std::lround(std::sin(c.sigma) * scale_bits))))};
    }
  return unique;
}

// ----- clipping and rings ---------------------------------------------------------------------

/// Sutherland–Hodgman against h·x >= 0, exact; the result may be degenerate (zero area).
std::vector<P> clip(const std::vector<P>& poly, const P& h) {
  std::vector<P> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const P& cur = poly[i];
    const P& nxt = poly[(i + 1) % poly.size()];
    const Cyclotomic sc = dot(h, cur), sn = dot(h, nxt);
    const int c = sc.sign(), n = sn.sign();
    if (c >= 0) out.push_back(cur);
    if ((c > 0 && n < 0) || (c < 0 && n > 0))
      out.push_back(add(cur, scale(sub(nxt, cur), sc / (sc - sn))));
  }
  return out;
}

Cyclotomic twice_area(const std::vector<P>& ring) {
  Cyclotomic s(0);
  for (std::size_t i = 0; i < ring.size(); ++i) s += cross(ring[i], ring[(i + 1) % ring.size()]);
  return s;
}

/// Strictly inside (the point is on no ring edge: rings do not touch).
bool inside(const P& p, const std::vector<P>& ring) {
  bool in = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const P& a = ring[i];
    const P& b = ring[(i + 1) % ring.size()];
    if ((a[1] > p[1]) == (b[1] > p[1])) continue;
    // x of the edge at height p.y, compared with p.x without dividing.
    const Cyclotomic lhs = (p[0] - a[0]) * (b[1] - a[1]);
    const Cyclotomic rhs = (b[0] - a[0]) * (p[1] - a[1]);
    if ((b[1] > a[1]) ? lhs < rhs : lhs > rhs) in = !in;
  }
  return in;
}

/// The pieces of one region: its clipped carrier triangles' boundary traced into rings; vertices
/// the cut added in the middle of a straight boundary run are dropped (kept: the region's own
/// boundary vertices and every corner).
std::vector<CutPiece> trace_pieces(int region, const std::vector<std::vector<P>>& clipped,
                                   const std::set<P, KeyLess>& keep) {
  PointTable t;
  const auto boundary = union_boundary(clipped, t);
  std::map<std::size_t, std::vector<std::size_t>> out;
  for (const auto& [a, b] : boundary) out[a].push_back(b);
  for (const auto& [v, next] : out)
    if (next.size() > 1)
      throw CutError("the cut piece of region " + std::to_string(region) + " touches itself at " +
                     show(t.points[v]) + "; such a piece is not a polygon with holes");
  std::set<std::size_t> used;
  std::vector<std::vector<P>> rings;
  for (const auto& [a, b] : boundary) {
    if (used.count(a)) continue;
    std::vector<P> ring;
    for (std::size_t v = a; !used.count(v); v = out[v][0]) {
      used.insert(v);
      ring.push_back(t.points[v]);
    }
    std::vector<P> kept;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const P& u = ring[(i + ring.size() - 1) % ring.size()];
      const P& v = ring[i];
      const P& w = ring[(i + 1) % ring.size()];
      const bool straight = cross(sub(v, u), sub(w, v)).is_zero();
      if (!straight || keep.count(v)) kept.push_back(v);
    }
    std::rotate(kept.begin(), std::min_element(kept.begin(), kept.end(), geometric_less),
                kept.end());
    rings.push_back(std::move(kept));
  }
  std::vector<CutPiece> pieces;
  std::vector<Cyclotomic> area;
  std::vector<std::vector<P>> holes;
  for (auto& r : rings) {
    const Cyclotomic a2 = twice_area(r);
    if (a2.sign() > 0) {
      pieces.push_back({region, std::move(r), {}});
      area.push_back(a2);
    } else {
      holes.push_back(std::move(r));
    }
  }
  for (auto& h : holes) {
    std::size_t best = pieces.size();
    for (std::size_t i = 0; i < pieces.size(); ++i)
      if (inside(h[0], pieces[i].outer) && (best == pieces.size() || area[i] < area[best]))
        best = i;
    if (best == pieces.size())
      throw CutError("internal error: a hole of the cut piece of region " + std::to_string(region) +
                     " lies in no outer ring");
    pieces[best].holes.push_back(std::move(h));
  }
  std::sort(pieces.begin(), pieces.end(), [](const CutPiece& u, const CutPiece& v) {
    return geometric_less(u.outer[0], v.outer[0]);
  });
  return pieces;
}

} // namespace

namespace {
/// The angle (degrees, in [0, 360)) turned counter-clockwise from direction a to direction b.
double ccw_deg(double ax, double ay, double bx, double by) {
  double t = std::atan2(ax * by - ay * bx, ax * bx + ay * by) * 180 / kPi;
  return t < 0 ? t + 360 : t;
}
} // namespace

double smallest_new_angle_deg(const std::vector<std::array<double, 4>>& segments, double sigma) {
  const double ux = std::cos(sigma), uy = std::sin(sigma);
  double smallest = 90;
  for (const auto& s : segments) {
    const double dx = s[2] - s[0], dy = s[3] - s[1];
    const double den = ux * dy - uy * dx; // cross(u, d)
    if (den == 0) continue;
    const double t = (s[0] * uy - s[1] * ux) / den; // where the ray's line meets the segment
    const double r = (s[0] * dy - s[1] * dx) / den; // distance along the ray
    const double at_end = 1e-9;
    if (t < -at_end || t > 1 + at_end || r <= 0) continue;
    double angle;
    if (t <= at_end) {
      // Through the segment's first vertex: the region lies counter-clockwise of the edge, so
      // the new angle there is from the edge counter-clockwise to the ray's line.
      const double a = ccw_deg(dx, dy, ux, uy);
      angle = std::min(a, a >= 180 ? a - 180 : a + 180);
    } else if (t >= 1 - at_end) {
      // Through its last vertex: clockwise from the reversed edge to the ray's line.
      const double a = ccw_deg(ux, uy, -dx, -dy);
      angle = std::min(a, a >= 180 ? a - 180 : a + 180);
    } else {
      // Through its inside: the two angles θ and 180° − θ both lie in the object (the second
      // in the neighbouring slice, i.e. at this slice's other ray).
      const double c = std::abs(ux * dx + uy * dy) / std::hypot(dx, dy);
      angle = std::acos(std::min(1.0, c)) * 180 / kPi;
    }
    smallest = std::min(smallest, angle);
  }
  return smallest;
}

CutResult cut_to_fundamental_piece(const core::TemplatedStructure<Cyclotomic, 2>& x,
                                   const SymmetrySpec& spec) {
  cut_support::check_spec(spec, x, 2, "at most two (orthogonal) mirrors", "ray");
  const int n = spec.rotation_order;

  Group g;
  g.field = field_for(x, spec);
  g.n = n;
  for (const auto& mv : spec.mirrors) {
    const P m{embed(mv[0], g.field), embed(mv[1], g.field)};
    if (m[0].is_zero() && m[1].is_zero()) throw CutError("--mirror: the normal is the zero vector");
    g.mirrors.push_back(m);
  }
  if (g.mirrors.size() == 2 && !dot(g.mirrors[0], g.mirrors[1]).is_zero())
    throw CutError("--mirror: the two mirrors are not orthogonal (Algorithm 6.4 needs them so)");

  const Object whole = whole_object(x, g.field);
  std::map<int, std::vector<std::pair<P, P>>> segments;
  std::map<int, std::set<P, KeyLess>> boundary_vertices;
  std::vector<std::pair<P, P>> all_segments;
  for (const auto& [region, tris] : whole.triangles) {
    PointTable t;
    const auto b = union_boundary(tris, t);
    for (const auto& [u, v] : b) boundary_vertices[region].insert(t.points[u]);
    segments[region] = maximal_segments(b, t);
    all_segments.insert(all_segments.end(), segments[region].begin(), segments[region].end());
  }
  verify_symmetry(g, segments);

  CutResult r;
  r.field = g.field;
  r.rotation_order = n;
  r.mirrors = g.mirrors;
  // Clips every carrier triangle by the cone {x : h·x >= 0 for every h} and traces the pieces.
  const auto cut_by = [&](const std::vector<P>& half_planes) {
    std::vector<CutPiece> out;
    for (const auto& [region, tris] : whole.triangles) {
      std::vector<std::vector<P>> clipped;
      for (const auto& tri : tris) {
        std::vector<P> piece = tri;
        for (const auto& h : half_planes) piece = clip(piece, h);
        if (piece.size() >= 3 && twice_area(piece).sign() > 0) clipped.push_back(std::move(piece));
      }
      if (clipped.empty()) continue;
      auto pieces = trace_pieces(region, clipped, boundary_vertices[region]);
      out.insert(out.end(), pieces.begin(), pieces.end());
    }
    if (out.empty()) throw CutError("the cut leaves nothing of the object");
    return out;
  };

  if (n >= 2 && g.mirrors.empty()) {
    std::vector<std::array<double, 4>> seg_d;
    for (const auto& [a, b] : all_segments)
      if (!cross(a, b).is_zero())
        seg_d.push_back({a[0].to_double(), a[1].to_double(), b[0].to_double(), b[1].to_double()});
    std::vector<Candidate> starts;
    if (spec.start) {
      starts.push_back(
          {0, -1, {embed((*spec.start)[0], g.field), embed((*spec.start)[1], g.field)}, 0});
      if (starts[0].exact[0].is_zero() && starts[0].exact[1].is_zero())
        throw CutError("--start: the direction is the zero vector");
    } else {
      starts = ranked_starts(all_segments, n);
    }
    for (int k = 0; k < n; ++k) r.group.push_back({k, 0});
    // A ray of Algorithm 6.3 may run through a reflex vertex so that the piece touches itself
    // there; then the next-ranked ray is taken (a given --start is not replaced).
    const std::size_t tries = std::min<std::size_t>(starts.size(), 16);
    std::optional<CutError> first_error; // the best ray's, reported if no ray works
    for (std::size_t t = 0;; ++t) {
      const Candidate& c = starts[t];
      P d0{embed(c.exact[0], g.field), embed(c.exact[1], g.field)};
      // The symmetric copy of the ray in [0, 2π/n), so that the piece is the slice next to the
      // positive x-axis (exactly the same piece up to the rotation).
      const double sigma0 = std::atan2(d0[1].to_double(), d0[0].to_double());
      const int turns = int(std::floor(reduce(sigma0, 2 * kPi) / (2 * kPi / n)));
      d0 = g.rotate(d0, n - turns % n);
      const P d1 = g.rotate(d0, 1);
      std::vector<P> half_planes{{-d0[1], d0[0]}};        // cross(d0, x) >= 0
      if (n >= 3) half_planes.push_back({d1[1], -d1[0]}); // cross(x, d1) >= 0
      try {
        r.pieces = cut_by(half_planes);
      } catch (const CutError& e) {
        if (!first_error) first_error = e;
        if (t + 1 >= tries) throw *first_error;
        continue;
      }
      r.start_direction = d0;
      r.start_kind = c.rank < 0    ? "given"
                     : c.rank == 0 ? "foot"
                     : c.rank == 1 ? "vertex"
                                   : "balance";
      const double sigma = std::atan2(d0[1].to_double(), d0[0].to_double());
      r.start_angle_deg = reduce(sigma, 2 * kPi / n) * 180 / kPi;
      r.smallest_new_angle_deg = smallest_new_angle_deg(seg_d, sigma);
      r.smallest_new_angle_at_x_axis_deg = smallest_new_angle_deg(seg_d, 0);
      break;
    }
  } else if (n >= 2) {
    // Algorithm 6.5: between the mirror line and the mirror line turned by π/n.
    const P& m = g.mirrors[0];
    const auto [c, s] = cos_sin(1, 2 * n, g.field);
    for (int k = 0; k < n; ++k) {
      r.group.push_back({k, 0});
      r.group.push_back({k, 1});
    }
    r.pieces = cut_by({m, {-(c * m[0] - s * m[1]), -(s * m[0] + c * m[1])}});
  } else {
    for (unsigned bits = 0; bits < (1u << g.mirrors.size()); ++bits) r.group.push_back({0, bits});
    r.pieces = cut_by(g.mirrors);
  }
  return r;
}

} // namespace symmesh::gen
