// The cut of a whole symmetric 3D object into its fundamental piece (spec/generation.md#cut-3d).
// The object is the union of its carriers' tetrahedra; everything is exact in K_m: clipping a
// tetrahedron by a half-space gives a convex polytope, which is split into tetrahedra at once, so
// the pieces stay carrier tetrahedralizations and volumes are sums of determinants.
#include "symmesh/gen/cut_support.h"
#include "symmesh/gen/symmetry_cut.h"

#include <algorithm>
#include <bit>
#include <map>
#include <numeric>

namespace symmesh::gen {
namespace {

using cut_support::compare_coefficients;
using cut_support::cos_sin;
using cut_support::embed;
using cut_support::field_for;
using cut_support::kMaxFieldOrder;
using number::Cyclotomic;
using number::CyclotomicField;
using number::CyclotomicFieldPtr;
using P = CutPoint3;
using Tet = std::array<P, 4>;

P sub(const P& a, const P& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
P add(const P& a, const P& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
P scale(const P& a, const Cyclotomic& s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
Cyclotomic dot(const P& a, const P& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
P cross(const P& a, const P& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
/// Six times the signed volume of (a, b, c, d).
Cyclotomic orient(const Tet& t) {
  return dot(cross(sub(t[1], t[0]), sub(t[2], t[0])), sub(t[3], t[0]));
}

struct KeyLess {
  bool operator()(const P& a, const P& b) const {
    for (int i = 0; i < 3; ++i)
      if (const int c = compare_coefficients(a[i], b[i]); c != 0) return c < 0;
    return false;
  }
};

std::string show(const P& p) {
  std::string s = "(";
  for (int i = 0; i < 3; ++i) s += (i ? ", " : "") + std::to_string(p[i].to_double());
  return s + ")";
}

/// The half-space {x : h·x >= c}.
struct HalfSpace {
  P h;
  Cyclotomic c;
};

/// t ∩ {h·x >= c} as positively oriented tetrahedra. With the vertices that stay (h·v >= c) and
/// those cut off, the polytope is the tetrahedron itself, a tetrahedron at one remaining vertex,
/// or a (possibly degenerate) triangular prism between the kept face or edge and the points where
/// the cut-off edges cross the plane; a prism is three tetrahedra. Flat tetrahedra are dropped.
std::vector<Tet> clip(const Tet& t, const HalfSpace& hs) {
  std::array<Cyclotomic, 4> s;
  std::vector<int> in, out;
  for (int k = 0; k < 4; ++k) {
    s[std::size_t(k)] = dot(hs.h, t[std::size_t(k)]) - hs.c;
    (s[std::size_t(k)].sign() >= 0 ? in : out).push_back(k);
  }
  if (out.empty()) return {t};
  if (in.empty()) return {};
  // The point where edge (a, b), a kept and b cut off, crosses the plane.
  const auto cut = [&](int a, int b) {
    const P& pa = t[std::size_t(a)];
    const Cyclotomic& sa = s[std::size_t(a)];
    return add(pa, scale(sub(t[std::size_t(b)], pa), sa / (sa - s[std::size_t(b)])));
  };
  std::vector<Tet> raw;
  // Prism between triangles (a0, a1, a2) and (b0, b1, b2), ai joined to bi, split into three
  // tetrahedra so that every quadrilateral face is cut by the diagonal from its smallest vertex
  // (KeyLess): neighbouring clipped tetrahedra then cut their common face alike and the pieces
  // stay conforming (Dompierre et al.'s rule: relabel so that the smallest vertex is a0).
  const auto prism = [&](P a0, P a1, P a2, P b0, P b1, P b2) {
    const KeyLess less;
    std::array<P*, 6> v{&a0, &a1, &a2, &b0, &b1, &b2};
    std::size_t m = 0;
    for (std::size_t k = 1; k < 6; ++k)
      if (less(*v[k], *v[m])) m = k;
    if (m >= 3) {
      std::swap(a0, b0), std::swap(a1, b1), std::swap(a2, b2);
      m -= 3;
    }
    for (; m > 0; --m) { // rotate the indices until the smallest is a0
      std::swap(a0, a1), std::swap(a1, a2);
      std::swap(b0, b1), std::swap(b1, b2);
    }
    const auto min2 = [&](const P& x, const P& y) { return less(x, y) ? x : y; };
    raw.push_back({a0, b0, b1, b2});
    if (less(min2(a1, b2), min2(a2, b1))) { // diagonal a1-b2 of the face opposite a0
      raw.push_back({a0, a1, a2, b2});
      raw.push_back({a0, a1, b1, b2});
    } else { // diagonal a2-b1
      raw.push_back({a0, a1, a2, b1});
      raw.push_back({a0, a2, b1, b2});
    }
  };
  const auto& T = t;
  if (in.size() == 1) {
    const int a = in[0];
    raw.push_back({T[std::size_t(a)], cut(a, out[0]), cut(a, out[1]), cut(a, out[2])});
  } else if (in.size() == 2) {
    const int a = in[0], b = in[1], c = out[0], d = out[1];
    prism(T[std::size_t(a)], cut(a, c), cut(a, d), T[std::size_t(b)], cut(b, c), cut(b, d));
  } else {
    const int a = in[0], b = in[1], c = in[2], d = out[0];
    prism(T[std::size_t(a)], T[std::size_t(b)], T[std::size_t(c)], cut(a, d), cut(b, d), cut(c, d));
  }
  std::vector<Tet> kept;
  for (auto& q : raw) {
    const int o = orient(q).sign();
    if (o == 0) continue;
    if (o < 0) std::swap(q[2], q[3]);
    kept.push_back(q);
  }
  return kept;
}

std::vector<Tet> clip_all(std::vector<Tet> tets, const std::vector<HalfSpace>& hs) {
  for (const auto& h : hs) {
    std::vector<Tet> next;
    for (const auto& t : tets) {
      auto c = clip(t, h);
      next.insert(next.end(), c.begin(), c.end());
    }
    tets = std::move(next);
  }
  return tets;
}

/// The four half-spaces whose intersection is the (positive) tetrahedron t.
std::vector<HalfSpace> faces_of(const Tet& t) {
  std::vector<HalfSpace> out;
  for (int k = 0; k < 4; ++k) {
    const P& a = t[std::size_t((k + 1) % 4)];
    P n = cross(sub(t[std::size_t((k + 2) % 4)], a), sub(t[std::size_t((k + 3) % 4)], a));
    if (dot(n, sub(t[std::size_t(k)], a)).sign() < 0) n = scale(n, Cyclotomic(-1));
    out.push_back({n, dot(n, a)});
  }
  return out;
}

struct Box {
  std::array<double, 3> lo, hi;
  bool overlaps(const Box& b) const {
    for (int i = 0; i < 3; ++i)
      if (hi[std::size_t(i)] < b.lo[std::size_t(i)] || b.hi[std::size_t(i)] < lo[std::size_t(i)])
        return false;
    return true;
  }
};
/// A certified enclosure (interval bounds of the exact coordinates).
Box box_of(const Tet& t) {
  Box b{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
  for (const auto& p : t)
    for (int i = 0; i < 3; ++i) {
      const auto [lo, hi] = p[std::size_t(i)].to_interval();
      b.lo[std::size_t(i)] = std::min(b.lo[std::size_t(i)], lo);
      b.hi[std::size_t(i)] = std::max(b.hi[std::size_t(i)], hi);
    }
  return b;
}

struct Group3 {
  CyclotomicFieldPtr field;
  int n = 0;
  std::vector<P> mirrors;

  P rotate(const P& p, int k) const {
    if (n == 0 || k % n == 0) return p;
    const auto [c, s] = cos_sin(k, n, field);
    return {c * p[0] - s * p[1], s * p[0] + c * p[1], p[2]};
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
  std::string name(const GroupElement& e) const {
    std::string s;
    if (e.k != 0) s = "the rotation by 2pi*" + std::to_string(e.k) + "/" + std::to_string(n);
    for (std::size_t j = 0; j < mirrors.size(); ++j)
      if (e.mirror_bits & (1u << j))
        s += (s.empty() ? "" : " o ") + std::string("the reflection in the plane orthogonal to ") +
             show(mirrors[j]);
    return s;
  }
};

/// One instance of the object: its carrier's tetrahedra in K_m, placed and positively oriented.
struct Part {
  int region = 1;
  std::string name; ///< template name and instance number
  std::vector<Tet> tets;
};

std::vector<Part> whole_object(const core::TemplatedStructure<Cyclotomic, 3>& x,
                               const CyclotomicFieldPtr& F) {
  std::vector<Part> parts;
  for (const auto& id : x.instance_ids()) {
    const auto inst = core::instance(x, id);
    Part part;
    part.region = x.instances[id.i][id.g].region;
    part.name = x.templates[id.i].name +
                (x.instances[id.i].size() > 1 ? "_" + std::to_string(id.g + 1) : std::string());
    for (const auto& c : inst.cells()) {
      Tet t;
      for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 3; ++i)
          t[std::size_t(k)][std::size_t(i)] = embed(inst.points[c.v[std::size_t(k)]][i], F);
      const int s = orient(t).sign();
      if (s == 0) continue; // a flat carrier cell covers no volume
      if (s < 0) std::swap(t[2], t[3]);
      part.tets.push_back(t);
    }
    parts.push_back(std::move(part));
  }
  return parts;
}

std::map<int, std::vector<Tet>> by_region(const std::vector<Part>& parts) {
  std::map<int, std::vector<Tet>> out;
  for (const auto& p : parts)
    out[p.region].insert(out[p.region].end(), p.tets.begin(), p.tets.end());
  return out;
}

Cyclotomic volume6(const std::vector<Tet>& tets) {
  Cyclotomic v(0);
  for (const auto& t : tets) v += orient(t);
  return v;
}

/// Every generator maps each region onto itself: g(R) ⊆ R up to measure zero, i.e.
/// Σ_{t, s ∈ R} vol(g(t) ∩ s) = vol(R) (the tetrahedra of R are interior-disjoint, Eq. 4.2), and
/// a closed polyhedral region with g(R) ⊆ R and equal volume is g(R) = R.
void verify_symmetry(const Group3& g, const std::map<int, std::vector<Tet>>& regions) {
  std::vector<GroupElement> generators;
  if (g.n >= 2) generators.push_back({1, 0});
  for (std::size_t j = 0; j < g.mirrors.size(); ++j) generators.push_back({0, 1u << j});
  for (const auto& [region, tets] : regions) {
    std::vector<Box> boxes;
    std::vector<std::vector<HalfSpace>> halves;
    for (const auto& s : tets) {
      boxes.push_back(box_of(s));
      halves.push_back(faces_of(s));
    }
    const Cyclotomic whole = volume6(tets);
    for (const auto& e : generators) {
      Cyclotomic inside(0);
      for (const auto& t : tets) {
        Tet gt;
        for (int k = 0; k < 4; ++k) gt[std::size_t(k)] = g.apply(e, t[std::size_t(k)]);
        if (orient(gt).sign() < 0) std::swap(gt[2], gt[3]);
        const Box b = box_of(gt);
        for (std::size_t s = 0; s < tets.size(); ++s)
          if (b.overlaps(boxes[s])) inside += volume6(clip_all({gt}, halves[s]));
      }
      if (!(inside - whole).is_zero())
        throw CutError("the object does not have the symmetry: " + g.name(e) + " maps region " +
                       std::to_string(region) + " onto a different set (only " +
                       std::to_string((inside / whole).to_double() * 100) +
                       " % of its volume stays in the region)");
    }
  }
}

/// The pieces: every instance's carrier clipped to the cone (one piece per instance, so that
/// each piece's carrier is conforming: an instance's carrier is, and the clipping keeps it so),
/// points shared exactly.
std::vector<CutPiece3> cut_by(const std::vector<Part>& parts, const std::vector<HalfSpace>& cone) {
  std::vector<CutPiece3> out;
  for (const auto& part : parts) {
    const auto clipped = clip_all(part.tets, cone);
    if (clipped.empty()) continue;
    CutPiece3 piece;
    piece.region = part.region;
    piece.name = part.name;
    std::map<P, std::size_t, KeyLess> index;
    for (const auto& t : clipped) {
      std::array<std::size_t, 4> ids{};
      for (int k = 0; k < 4; ++k) {
        const auto [it, fresh] = index.emplace(t[std::size_t(k)], piece.points.size());
        if (fresh) piece.points.push_back(t[std::size_t(k)]);
        ids[std::size_t(k)] = it->second;
      }
      piece.tetrahedra.push_back(ids);
    }
    out.push_back(std::move(piece));
  }
  if (out.empty()) throw CutError("the cut leaves nothing of the object");
  return out;
}

} // namespace

CutResult3 cut_to_fundamental_piece(const core::TemplatedStructure<Cyclotomic, 3>& x,
                                    const SymmetrySpec3& spec) {
  cut_support::check_spec(spec, x, 3, "at most three (orthogonal) mirror planes", "half-plane");
  const int n = spec.rotation_order;
  Group3 g;
  g.field = field_for(x, spec);
  g.n = n;
  for (const auto& mv : spec.mirrors) {
    const P m{embed(mv[0], g.field), embed(mv[1], g.field), embed(mv[2], g.field)};
    if (m[0].is_zero() && m[1].is_zero() && m[2].is_zero())
      throw CutError("--mirror: the normal is the zero vector");
    if (n >= 2 && !m[2].is_zero())
      throw CutError("--mirror: with a rotation about the z axis the mirror plane must contain "
                     "the axis (normal with z = 0)");
    g.mirrors.push_back(m);
  }
  for (std::size_t a = 0; a < g.mirrors.size(); ++a)
    for (std::size_t b = a + 1; b < g.mirrors.size(); ++b)
      if (!dot(g.mirrors[a], g.mirrors[b]).is_zero())
        throw CutError("--mirror: the mirror planes are not orthogonal (Algorithm 6.4 needs them "
                       "so)");
  const auto parts = whole_object(x, g.field);
  verify_symmetry(g, by_region(parts));

  CutResult3 r;
  r.field = g.field;
  r.rotation_order = n;
  r.mirrors = g.mirrors;
  const Cyclotomic zero(0);
  if (n >= 2 && g.mirrors.empty()) {
    P d0{Cyclotomic(1), zero, zero};
    if (spec.start) {
      d0 = {embed((*spec.start)[0], g.field), embed((*spec.start)[1], g.field), zero};
      if (d0[0].is_zero() && d0[1].is_zero())
        throw CutError("--start: the direction is the zero vector");
    }
    const P d1 = g.rotate(d0, 1);
    std::vector<HalfSpace> cone{{{-d0[1], d0[0], zero}, zero}}; // (d0 × x)_z >= 0
    if (n >= 3) cone.push_back({{d1[1], -d1[0], zero}, zero});  // (x × d1)_z >= 0
    for (int k = 0; k < n; ++k) r.group.push_back({k, 0});
    r.start_direction = d0;
    r.pieces = cut_by(parts, cone);
  } else if (n >= 2) {
    // Algorithm 6.5: between the mirror plane and the mirror plane turned by π/n about z.
    const P& m = g.mirrors[0];
    const auto [c, s] = cos_sin(1, 2 * n, g.field);
    for (int k = 0; k < n; ++k) {
      r.group.push_back({k, 0});
      r.group.push_back({k, 1});
    }
    r.pieces =
        cut_by(parts, {{m, zero}, {{-(c * m[0] - s * m[1]), -(s * m[0] + c * m[1]), zero}, zero}});
  } else {
    for (unsigned bits = 0; bits < (1u << g.mirrors.size()); ++bits) r.group.push_back({0, bits});
    std::vector<HalfSpace> cone;
    for (const auto& m : g.mirrors) cone.push_back({m, zero});
    r.pieces = cut_by(parts, cone);
  }
  return r;
}

} // namespace symmesh::gen
