// Section 5.1.1 in 3D: independent surface meshes merged by Algorithms 5.2-5.4, then Algorithm
// 5.7's template stage — spec/generation.md#merge-3d
//
// Every 2-face of every template is surface-meshed on its own (no face classes), so two faces
// that meet in the structure carry different triangulations. Which faces meet, and by which
// exact map, is read off the template boundary mappings (Def. 4.7) and the boundary subdivision
// they act on face to face; the face classes of Algorithm 4.1 are not used. The merge is exact:
// Algorithm 5.2 moves close pairs of face points to their centre when every related point can
// follow and no surface triangle turns over; Algorithms 5.4 and 5.3 are the overlay of the two
// triangulations of each interface — every crossing of their edges (line-line intersection) and
// every vertex of one in the other (vertex-in-facet) becomes a vertex of both, and each cell of
// the overlay (the intersection of two triangles, convex) is triangulated once and given to both
// faces. TetGen then fills each template with its merged surface kept.
#include "symmesh/gen/interface_merging.h"

#include "symmesh/gen/template_meshing_3d.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>

namespace symmesh::gen {
namespace {
using namespace surface3;

template <class FT>
using Tri = std::array<P3<FT>, 3>;
template <class FT>
using Triangulation = std::vector<Tri<FT>>;

/// Two 2-faces that meet: face f of template j is sent onto face g of template i by `map`
/// (template boundary mapping `letter`); (j, f) <= (i, g), each map once per face pair.
template <class FT>
struct FacePair {
  std::size_t letter = 0;
  std::size_t j = 0, f = 0, i = 0, g = 0;
  core::RigidTransformation<FT, 3> map, back;
  bool self() const { return j == i && f == g; }
};

template <class FT>
FT side(const P3<FT>& a, const P3<FT>& b, const P3<FT>& p, const P3<FT>& n) {
  return core::dot<FT, 3>(cross<FT>(b - a, p - a), n);
}

/// Twice the area of t, signed by the normal n (times |n|).
template <class FT>
FT area2(const Tri<FT>& t, const P3<FT>& n) {
  return side<FT>(t[0], t[1], t[2], n);
}

template <class FT>
Tri<FT> oriented(Tri<FT> t, const P3<FT>& n) {
  if (area2<FT>(t, n) < FT(0)) std::swap(t[1], t[2]);
  return t;
}

template <class FT>
Triangulation<FT> mapped(const Triangulation<FT>& ts, const core::RigidTransformation<FT, 3>& m,
                         const P3<FT>& n) {
  Triangulation<FT> out;
  out.reserve(ts.size());
  for (const auto& t : ts) out.push_back(oriented<FT>({m(t[0]), m(t[1]), m(t[2])}, n));
  return out;
}

/// The triangles as sets of points, in a canonical order: two triangulations are the same iff
/// their keys are.
template <class FT>
std::vector<Tri<FT>> key(Triangulation<FT> ts) {
  const core::PointLess<FT, 3> less;
  for (auto& t : ts) std::sort(t.begin(), t.end(), less);
  std::sort(ts.begin(), ts.end(), [&](const Tri<FT>& a, const Tri<FT>& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), less);
  });
  return ts;
}

/// A double box around a triangle, widened so that triangles that touch exactly have boxes
/// that overlap (the box only filters; the clipping decides exactly).
struct Box {
  std::array<double, 3> lo{}, hi{};
  bool overlaps(const Box& o) const {
    for (int d = 0; d < 3; ++d)
      if (hi[std::size_t(d)] < o.lo[std::size_t(d)] || o.hi[std::size_t(d)] < lo[std::size_t(d)])
        return false;
    return true;
  }
};

template <class FT>
Box box_of(const Tri<FT>& t) {
  Box b;
  for (int d = 0; d < 3; ++d) {
    double lo = rounded(t[0][d]), hi = lo;
    for (int k = 1; k < 3; ++k) {
      lo = std::min(lo, rounded(t[std::size_t(k)][d]));
      hi = std::max(hi, rounded(t[std::size_t(k)][d]));
    }
    const double slack = 1e-7 * (1 + std::max(std::abs(lo), std::abs(hi)));
    b.lo[std::size_t(d)] = lo - slack;
    b.hi[std::size_t(d)] = hi + slack;
  }
  return b;
}

/// a ∩ b for triangles positively oriented about n (Sutherland-Hodgman, exact): a convex
/// polygon whose vertices are corners of a or b or crossings of their edges — the vertices of
/// the overlay that lie on its boundary (Algorithms 5.3 and 5.4 find exactly these points).
template <class FT>
std::vector<P3<FT>> clip(const Tri<FT>& a, const Tri<FT>& b, const P3<FT>& n) {
  std::vector<P3<FT>> poly(a.begin(), a.end());
  for (std::size_t e = 0; e < 3 && poly.size() >= 3; ++e) {
    const auto& u = b[e];
    const auto& w = b[(e + 1) % 3];
    std::vector<P3<FT>> out;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const auto& p = poly[k];
      const auto& q = poly[(k + 1) % poly.size()];
      const FT sp = side<FT>(u, w, p, n), sq = side<FT>(u, w, q, n);
      if (sp >= FT(0)) out.push_back(p);
      if ((sp > FT(0) && sq < FT(0)) || (sp < FT(0) && sq > FT(0)))
        out.push_back(p + core::scaled<FT, 3>(q - p, sp / (sp - sq)));
    }
    std::vector<P3<FT>> unique;
    for (const auto& p : out)
      if (unique.empty() || unique.back() != p) unique.push_back(p);
    while (unique.size() > 1 && unique.front() == unique.back()) unique.pop_back();
    poly = std::move(unique);
  }
  if (poly.size() < 3) return {};
  FT twice(0);
  for (std::size_t k = 1; k + 1 < poly.size(); ++k)
    twice += side<FT>(poly[0], poly[k], poly[k + 1], n);
  if (!(twice > FT(0))) return {};
  return poly;
}

/// A triangulation of a convex polygon (positively oriented about n; vertices may lie on its
/// sides). For a face that meets itself (`canonical`), the fan from the centre of its vertices,
/// which every rigid map of the polygon onto itself preserves; otherwise ears: a strictly convex
/// vertex whose diagonal passes through no other vertex is cut off, so no triangle is flat.
template <class FT>
void triangulate_cell(std::vector<P3<FT>> poly, const P3<FT>& n, bool canonical,
                      Triangulation<FT>& out) {
  if (poly.size() == 3) {
    out.push_back({poly[0], poly[1], poly[2]});
    return;
  }
  if (canonical) {
    P3<FT> c = core::zero_point<FT, 3>();
    for (const auto& p : poly) c = c + p;
    c = core::scaled<FT, 3>(c, FT(1) / FT(int(poly.size())));
    for (std::size_t k = 0; k < poly.size(); ++k)
      out.push_back({c, poly[k], poly[(k + 1) % poly.size()]});
    return;
  }
  while (poly.size() > 3) {
    const std::size_t m = poly.size();
    bool cut = false;
    for (std::size_t k = 0; k < m && !cut; ++k) {
      const auto& prev = poly[(k + m - 1) % m];
      const auto& next = poly[(k + 1) % m];
      if (!(side<FT>(prev, poly[k], next, n) > FT(0))) continue;
      bool clear = true;
      for (std::size_t l = 0; l < m && clear; ++l)
        if (l != k && l != (k + m - 1) % m && l != (k + 1) % m &&
            side<FT>(prev, next, poly[l], n) == FT(0))
          clear = false;
      if (!clear) continue;
      out.push_back({prev, poly[k], next});
      poly.erase(poly.begin() + std::ptrdiff_t(k));
      cut = true;
    }
    if (!cut) throw std::logic_error("merge: an overlay cell has no ear");
  }
  out.push_back({poly[0], poly[1], poly[2]});
}

/// Algorithms 5.4 and 5.3 on one interface: the common refinement of a and b (two
/// triangulations of the same polygon, positively oriented about n), every overlay cell
/// triangulated once.
template <class FT>
Triangulation<FT> overlay(const Triangulation<FT>& a, const Triangulation<FT>& b, const P3<FT>& n,
                          bool canonical) {
  std::vector<Box> bb;
  for (const auto& t : b) bb.push_back(box_of<FT>(t));
  Triangulation<FT> out;
  for (const auto& ta : a) {
    const Box ba = box_of<FT>(ta);
    for (std::size_t k = 0; k < b.size(); ++k) {
      if (!ba.overlaps(bb[k])) continue;
      auto cell = clip<FT>(ta, b[k], n);
      if (!cell.empty()) triangulate_cell<FT>(std::move(cell), n, canonical, out);
    }
  }
  return out;
}

template <class FT>
FT total_area2(const Triangulation<FT>& ts, const P3<FT>& n) {
  FT s(0);
  for (const auto& t : ts) s += area2<FT>(t, n);
  return s;
}

/// A move of Algorithm 5.2: point `from` of face f of template t goes to `to`.
template <class FT>
struct Move {
  std::size_t t = 0, f = 0;
  P3<FT> from, to;
};

template <class FT>
using FaceTriangulations = std::vector<std::map<std::size_t, Triangulation<FT>>>;

/// The points of a face triangulation that are not on its boundary (not in `fixed`, the
/// template's subdivision and line-mesh points): the only ones Algorithm 5.2 moves.
template <class FT>
std::set<P3<FT>, core::PointLess<FT, 3>> free_points(const Triangulation<FT>& ts,
                                                     const SurfaceBoundary<FT>& fixed) {
  std::set<P3<FT>, core::PointLess<FT, 3>> out;
  for (const auto& t : ts)
    for (const auto& p : t)
      if (!fixed.id_of.count(p)) out.insert(p);
  return out;
}

/// Algorithm 5.2 for one close pair: p (face f of template j) and w (face g of template i) go to
/// their centre, and every point that a face pair relates to a moved point follows (Lines
/// 20-29). Nothing when the moves contradict each other, a related point is on a face boundary,
/// or a surface triangle around a moved point would not stay positively oriented (Section 5.2.2
/// on the surface; TetGen meshes the volume afterwards).
template <class FT>
std::optional<std::vector<Move<FT>>>
merge_moves(const FaceTriangulations<FT>& tri, const std::vector<SurfaceBoundary<FT>>& fixed,
            const std::vector<FacePair<FT>>& pairs, const std::vector<std::vector<P3<FT>>>& normal,
            const FacePair<FT>& pr, const P3<FT>& p, const P3<FT>& w) {
  const auto q = pr.map(p);
  P3<FT> z;
  for (int d = 0; d < 3; ++d) z[d] = (q[d] + w[d]) / FT(2);
  std::vector<Move<FT>> moves{{pr.j, pr.f, p, pr.back(z)}, {pr.i, pr.g, w, z}};
  const auto has_point = [&](std::size_t t, std::size_t f, const P3<FT>& x) {
    for (const auto& tr : tri[t].at(f))
      for (const auto& y : tr)
        if (y == x) return true;
    return false;
  };
  for (std::size_t next = 0; next < moves.size(); ++next) {
    const auto m = moves[next];
    for (const auto& o : pairs)
      for (int dir = 0; dir < 2; ++dir) {
        const bool forward = dir == 0;
        if (forward ? (o.j != m.t || o.f != m.f) : (o.i != m.t || o.g != m.f)) continue;
        const auto& r = forward ? o.map : o.back;
        const std::size_t t = forward ? o.i : o.j, f = forward ? o.g : o.f;
        const auto image = r(m.from);
        if (!has_point(t, f, image)) continue;
        const Move<FT> related{t, f, image, r(m.to)};
        bool seen = false;
        for (const auto& other : moves)
          if (other.t == related.t && other.f == related.f && other.from == related.from) {
            if (other.to != related.to) return std::nullopt;
            seen = true;
          }
        if (!seen) moves.push_back(related);
      }
  }
  for (const auto& m : moves) {
    if (fixed[m.t].id_of.count(m.from) || has_point(m.t, m.f, m.to)) return std::nullopt;
    const auto& n = normal[m.t][m.f];
    for (const auto& tr : tri[m.t].at(m.f)) {
      auto moved = tr;
      bool touched = false;
      for (auto& x : moved)
        if (x == m.from) {
          x = m.to;
          touched = true;
        }
      if (touched && !(area2<FT>(moved, n) > FT(0))) return std::nullopt;
    }
  }
  return moves;
}

/// Algorithms 5.1 and 5.2: close pairs (|map(p) − w| ≤ d_max, exactly) of free points of every
/// face pair, nearest first, merged while their moves are valid; a pass skips pairs whose points
/// moved earlier in it, and passes repeat until none merges (at most `max_passes`).
template <class FT>
void merge_close_pairs(FaceTriangulations<FT>& tri, const std::vector<SurfaceBoundary<FT>>& fixed,
                       const std::vector<FacePair<FT>>& pairs,
                       const std::vector<std::vector<P3<FT>>>& normal, const FT& dmax2,
                       GenerationResult& r) {
  constexpr int max_passes = 8;
  for (int pass = 0; pass < max_passes; ++pass) {
    struct Close {
      FT d2;
      std::size_t pair;
      P3<FT> p, w;
    };
    std::vector<Close> close;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const auto& pr = pairs[k];
      if (pr.self()) continue;
      const auto ws = free_points<FT>(tri[pr.i].at(pr.g), fixed[pr.i]);
      for (const auto& p : free_points<FT>(tri[pr.j].at(pr.f), fixed[pr.j])) {
        const auto q = pr.map(p);
        if (ws.count(q)) continue;
        for (const auto& w : ws) {
          const auto d = q - w;
          const FT d2 = core::dot<FT, 3>(d, d);
          if (d2 <= dmax2) close.push_back({d2, k, p, w});
        }
      }
    }
    const core::PointLess<FT, 3> less;
    std::sort(close.begin(), close.end(), [&](const Close& a, const Close& b) {
      if (a.d2 != b.d2) return a.d2 < b.d2;
      if (a.pair != b.pair) return a.pair < b.pair;
      if (a.p != b.p) return less(a.p, b.p);
      return less(a.w, b.w);
    });
    // Where a point of a face went earlier in this pass: a pair is taken with its points' current
    // places, so a point meets all its close partners in one pass (a TSV slice's face point has
    // one in the trunk per slice position).
    using Place = std::tuple<std::size_t, std::size_t, P3<FT>>;
    const auto place_less = [&](const Place& a, const Place& b) {
      if (std::get<0>(a) != std::get<0>(b)) return std::get<0>(a) < std::get<0>(b);
      if (std::get<1>(a) != std::get<1>(b)) return std::get<1>(a) < std::get<1>(b);
      return less(std::get<2>(a), std::get<2>(b));
    };
    std::map<Place, P3<FT>, decltype(place_less)> went(place_less);
    const auto now = [&](std::size_t t, std::size_t f, P3<FT> p) {
      for (auto it = went.find({t, f, p}); it != went.end(); it = went.find({t, f, p}))
        p = it->second;
      return p;
    };
    std::size_t merged = 0;
    for (const auto& c : close) {
      const auto& pr = pairs[c.pair];
      const auto p = now(pr.j, pr.f, c.p), w = now(pr.i, pr.g, c.w);
      const auto d = pr.map(p) - w;
      const FT d2 = core::dot<FT, 3>(d, d);
      if (d2 == FT(0) || d2 > dmax2) continue;
      const auto moves = merge_moves<FT>(tri, fixed, pairs, normal, pr, p, w);
      if (!moves) continue;
      for (const auto& m : *moves) {
        for (auto& tr : tri[m.t][m.f])
          for (auto& x : tr)
            if (x == m.from) x = m.to;
        went[{m.t, m.f, m.from}] = m.to;
      }
      r.merge_moves += moves->size();
      ++r.merge_merged;
      ++merged;
    }
    if (merged == 0) return;
  }
}

/// Face f's triangulation is a triangulation of the face: every triangle positive about n, the
/// edges used once are exactly the line-mesh segments of its closure, every other edge twice.
template <class FT>
std::optional<std::string> triangulation_defect(const core::BoundarySubdivision<FT, 3>& sd,
                                                const SurfaceBoundary<FT>& tb, std::size_t f,
                                                const std::vector<std::array<std::size_t, 3>>& ids,
                                                const std::vector<P3<FT>>& exact, const P3<FT>& n) {
  std::vector<std::size_t> boundary_ids;
  std::set<std::pair<std::size_t, std::size_t>> outline;
  for (auto s : facet_boundary(sd, tb, f, boundary_ids))
    outline.insert(std::minmax(boundary_ids[s[0]], boundary_ids[s[1]]));
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  for (const auto& c : ids) {
    if (!(area2<FT>({exact[c[0]], exact[c[1]], exact[c[2]]}, n) > FT(0)))
      return std::string("a triangle is not positively oriented");
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(c[std::size_t(k)], c[std::size_t((k + 1) % 3)])];
  }
  for (const auto& [e, count] : uses)
    if (count != (outline.count(e) ? 1 : 2))
      return "edge (" + std::to_string(e.first) + ", " + std::to_string(e.second) +
             ") is used by " + std::to_string(count) + " triangles";
  for (const auto& e : outline)
    if (!uses.count(e))
      return std::string("a line-mesh segment of its outline is no triangle edge");
  return std::nullopt;
}

template <class FT>
GenerationResult merge_3(const core::TemplatedStructure<FT, 3>& x, const GenerationOptions& o,
                         const std::vector<core::RigidTransformation<FT, 3>>& copies) {
  const bool group = !copies.empty();
  support::input_stage(x, o, "--method merge");
  const auto stage = [&](const std::string& name, std::size_t total, const std::string& unit) {
    if (o.progress) o.progress->stage(name, total, unit);
  };
  const auto say = [&](const std::string& s) {
    if (o.progress) o.progress->message(s);
  };
  // Slices of a rotation that meet only their neighbours: the interfaces of copies 0 and 1 are
  // all the interfaces up to the rotation (as in the rotational method), which spares the
  // mappings of all instance pairs; the merge itself is the same.
  const auto t0_symmetry = Clock::now();
  std::string reason;
  std::size_t rotations = group ? 0 : support::rotation_order(x, reason);
  // Decided once; a contact is found only when copy 0 is not in a slice, so rotations = 0 then
  // goes with false.
  const bool copy_zero_in_slice =
      rotations > 0 && core::slice_of_copy_zero(x, rotations).has_value();
  if (rotations > 0 && non_consecutive_contact(x, rotations, copy_zero_in_slice)) rotations = 0;
  core::TemplatedStructure<FT, 3> two_copies;
  if (rotations > 0 || group) {
    two_copies.templates = x.templates;
    for (const auto& list : x.instances)
      two_copies.instances.push_back(group ? std::vector{list[0]} : std::vector{list[0], list[1]});
  }
  const double symmetry_seconds = seconds_since(t0_symmetry);
  stage("instance overlap (Eq. 4.2)", 0, "");
  const auto overlap =
      group ? support::copy_zero_overlap(x)
            : core::find_instance_overlap_by_slices(x, rotations, copy_zero_in_slice);
  if (overlap) throw std::invalid_argument(core::overlap_message(*overlap));
  GenerationResult r;
  // The subdivision and the mappings say which faces meet; their classes are not used.
  const auto bpp = support::boundary_patch_stage(rotations > 0 || group ? two_copies : x, o,
                                                 symmetry_seconds, 0, r);
  const auto& sds = bpp.subdivisions;
  const std::size_t nt = x.templates.size();

  // Every 2-face of every template meshed on its own.
  stage("line and surface meshes (each face on its own)", nt, "templates");
  auto t0 = Clock::now();
  long f0 = minor_faults();
  const FT h = exact_from_double<FT>(o.size);
  const FT h2 = h * h;
  std::vector<SurfaceBoundary<FT>> boundaries;
  FaceTriangulations<FT> tri(nt);
  std::vector<std::vector<P3<FT>>> normal(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    boundaries.push_back(line_meshes_3<FT>(sds[t], h2, o.size, {}));
    const auto& tb = boundaries.back();
    normal[t].resize(sds[t].faces.size());
    for (std::size_t f = 0; f < sds[t].faces.size(); ++f) {
      if (sds[t].faces[f].dimension != 2) continue;
      normal[t][f] = facet_frame(sds[t], f).n;
      const auto m = mesh_facet(sds[t], tb, f, o.size, o.min_angle_deg);
      std::vector<P3<FT>> pts;
      for (std::size_t id : m.boundary_ids) pts.push_back(tb.exact[id]);
      pts.insert(pts.end(), m.interior.begin(), m.interior.end());
      auto& ts = tri[t][f];
      for (const auto& c : m.triangles)
        ts.push_back(oriented<FT>({pts[c[0]], pts[c[1]], pts[c[2]]}, normal[t][f]));
    }
    if (o.progress) o.progress->set_done(t + 1);
  }
  r.timings.line_meshes = seconds_since(t0);
  r.timings.page_faults.line_meshes = minor_faults() - f0;

  // The interfaces: one face pair per (face, image face, map on the face).
  stage("interface merging (Algorithms 5.2-5.4)", 0, "");
  t0 = Clock::now();
  f0 = minor_faults();
  std::vector<FacePair<FT>> pairs;
  std::set<std::tuple<std::size_t, std::size_t, std::size_t, std::size_t, std::vector<P3<FT>>>,
           std::function<bool(const std::tuple<std::size_t, std::size_t, std::size_t, std::size_t,
                                               std::vector<P3<FT>>>&,
                              const std::tuple<std::size_t, std::size_t, std::size_t, std::size_t,
                                               std::vector<P3<FT>>>&)>>
      seen([](const auto& a, const auto& b) {
        if (std::get<0>(a) != std::get<0>(b)) return std::get<0>(a) < std::get<0>(b);
        if (std::get<1>(a) != std::get<1>(b)) return std::get<1>(a) < std::get<1>(b);
        if (std::get<2>(a) != std::get<2>(b)) return std::get<2>(a) < std::get<2>(b);
        if (std::get<3>(a) != std::get<3>(b)) return std::get<3>(a) < std::get<3>(b);
        const core::PointLess<FT, 3> less;
        return std::lexicographical_compare(std::get<4>(a).begin(), std::get<4>(a).end(),
                                            std::get<4>(b).begin(), std::get<4>(b).end(), less);
      });
  for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
    const auto& m = bpp.mappings[l];
    if (m.whole_boundary) continue;
    const std::size_t j = m.from_template(), i = m.to_template();
    for (const auto& fg : bpp.letter_action[l]) {
      const std::size_t f = fg.first, g = fg.second;
      if (sds[j].faces[f].dimension != 2 || std::make_pair(j, f) > std::make_pair(i, g)) continue;
      std::vector<P3<FT>> images;
      bool identity = true;
      for (auto v : sds[j].faces[f].vertices) {
        images.push_back(m.map(sds[j].points[v]));
        identity = identity && images.back() == sds[j].points[v];
      }
      if ((j == i && f == g && identity) || !seen.insert({j, f, i, g, images}).second) continue;
      pairs.push_back({l, j, f, i, g, m.map, m.map.inverse()});
    }
  }
  const auto name = [&](const FacePair<FT>& p) {
    const auto& m = bpp.mappings[p.letter];
    return "the interface of instance " + std::to_string(m.from.g + 1) + " of template '" +
           x.templates[m.from.i].name + "' (face " + std::to_string(p.f) + ") and instance " +
           std::to_string(m.to.g + 1) + " of template '" + x.templates[m.to.i].name + "' (face " +
           std::to_string(p.g) + ")";
  };
  const FT dmax = h / FT(3);
  merge_close_pairs<FT>(tri, boundaries, pairs, normal, dmax * dmax, r);

  constexpr std::size_t kMaxRounds = 16;
  for (;;) {
    const FacePair<FT>* differs = nullptr;
    for (const auto& p : pairs) {
      const auto& n = normal[p.i][p.g];
      const auto a = mapped<FT>(tri[p.j][p.f], p.map, n);
      auto& b = tri[p.i][p.g];
      if (key<FT>(a) == key<FT>(b)) continue;
      differs = &p;
      if (r.merge_rounds == kMaxRounds) break;
      if (total_area2<FT>(a, n) != total_area2<FT>(b, n))
        throw MergeError("--method merge: " + name(p) + ": the faces do not cover the same area");
      auto known = free_points<FT>(b, boundaries[p.i]);
      for (const auto& q : free_points<FT>(a, boundaries[p.i])) known.insert(q);
      auto s = overlay<FT>(a, b, n, p.self());
      for (const auto& q : free_points<FT>(s, boundaries[p.i]))
        r.merge_insertions += !known.count(q);
      if (!p.self()) tri[p.j][p.f] = mapped<FT>(s, p.back, normal[p.j][p.f]);
      b = std::move(s);
    }
    if (!differs) break;
    if (r.merge_rounds == kMaxRounds)
      throw MergeError("--method merge: " + name(*differs) + " still differs after " +
                       std::to_string(kMaxRounds) +
                       " rounds of Algorithms 5.3/5.4: its maps carry the overlay to ever new "
                       "places");
    ++r.merge_rounds;
  }

  // The merged surfaces as the templates' boundary meshes: face points after the subdivision
  // and line-mesh points, face by face; a face's points are paired with its image's by their
  // exact images (facet_symmetric), since the faces were not meshed as one class.
  for (std::size_t t = 0; t < nt; ++t) {
    auto& tb = boundaries[t];
    for (const auto& [f, ts] : tri[t]) {
      tb.facet_first[f] = tb.exact.size();
      tb.facet_symmetric[f] = true;
      std::vector<std::array<std::size_t, 3>> ids;
      for (const auto& tr : ts) {
        std::array<std::size_t, 3> c{};
        for (std::size_t k = 0; k < 3; ++k) {
          auto [it, fresh] = tb.id_of.emplace(tr[k], tb.exact.size());
          if (fresh) tb.exact.push_back(tr[k]);
          c[k] = it->second;
        }
        ids.push_back(c);
      }
      tb.facet_count[f] = tb.exact.size() - tb.facet_first[f];
      if (const auto defect = triangulation_defect<FT>(sds[t], tb, f, ids, tb.exact, normal[t][f]))
        throw MergeError("--method merge: template '" + x.templates[t].name + "', face " +
                         std::to_string(f) +
                         ": the merged surface mesh is no triangulation of "
                         "the face: " +
                         *defect);
      for (const auto& c : ids) {
        tb.triangles.push_back(c);
        tb.triangle_face.push_back(f);
      }
    }
  }
  say("interface merging: " + std::to_string(pairs.size()) + " face pairs, " +
      std::to_string(r.merge_merged) + " close pairs merged (" + std::to_string(r.merge_moves) +
      " points moved, Algorithm 5.2), " + std::to_string(r.merge_insertions) +
      " overlay points inserted in " + std::to_string(r.merge_rounds) +
      " rounds (Algorithms 5.3/5.4)");

  auto candidates = support::svb_candidates<FT, 3>(
      x, bpp, [&](std::size_t l) { return mapping_pairs_3(bpp, l, boundaries); }, rotations,
      copies.size());
  std::vector<std::size_t> boundary_vertices;
  for (const auto& b : boundaries) boundary_vertices.push_back(b.exact.size());
  if (group) {
    std::vector<std::vector<P3<FT>>> points;
    for (const auto& b : boundaries) points.push_back(b.exact);
    support::copy_candidates<FT, 3>(x, points, candidates, {});
  }
  support::shared_vertex_bookkeeping<FT, 3>(x, boundary_vertices, std::move(candidates),
                                            r.templated);
  r.timings.svb = seconds_since(t0);
  r.timings.page_faults.svb = minor_faults() - f0;

  mesh_templates_3(x, bpp, boundaries, o, r);

  support::certificate_stage(o, r, [&] {
    if (o.direct_certificate) return certify_3(x, boundaries);
    if (group) return certify_copies(x, copies, bpp, boundaries);
    return certify_by_mappings(bpp, boundaries);
  });
  return r;
}
} // namespace

GenerationResult generate_merge(const core::TemplatedStructure<Exact, 3>& x,
                                const GenerationOptions& o,
                                const std::vector<core::RigidTransformation<Exact, 3>>& copies) {
  return merge_3(x, o, copies);
}
GenerationResult
generate_merge(const core::TemplatedStructure<support::LazyCyclotomic, 3>& x,
               const GenerationOptions& o,
               const std::vector<core::RigidTransformation<support::LazyCyclotomic, 3>>& copies) {
  return merge_3(x, o, copies);
}

} // namespace symmesh::gen
