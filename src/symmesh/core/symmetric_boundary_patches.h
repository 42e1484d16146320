/// Section 6.2 (boundary patches of a reflective templated geometry) and Algorithm 6.2 (boundary
/// patch partition of a rotational slice, multi-region), 2D —
/// spec/boundary-patches.md#special-cases
///
/// A separate code path from Algorithm 4.1: it never composes template boundary mappings. It only
/// uses the symmetry: the traces of all regions (all copies of all templates) on the symmetry
/// lines (the mirror line; the first slice ray H, whose traces are rotated onto the second ray,
/// Line 13 of Algorithm 6.2), cut those lines into elements, and takes the rest of each template
/// boundary. Correction (found by comparing with Algorithm 4.1): Line 17 of Algorithm 6.2 lumps
/// the whole rest of a region slice's boundary into one element, but where two regions of the
/// same slice touch, their common boundary has other neighbours than the outer boundary; the rest
/// is therefore also cut at intra-slice region interfaces. Elements are connected (a disconnected
/// rest is several patches, as in Figure 4.10).
#pragma once
#include "symmesh/core/boundary_subdivision.h"
#include "symmesh/core/element_complex.h"
#include "symmesh/core/templated_structure.h"

#include <array>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace symmesh::core {

template <class FT>
struct SymmetryPatch {
  std::size_t template_index = 0;
  std::vector<std::array<Point<FT, 2>, 2>> segments; ///< in template coordinates
  int line = -1; ///< index of the symmetry line it lies on (-1: rest)
};

namespace detail {

template <class FT>
struct SymLine {
  Point<FT, 2> origin, dir;
  bool ray = false;
  bool contains(const Point<FT, 2>& p) const {
    const auto e = p - origin;
    if (e[0] * dir[1] - e[1] * dir[0] != 0) return false;
    return !ray || dot<FT, 2>(e, dir) >= 0;
  }
};

template <class FT>
using Seg = std::array<Point<FT, 2>, 2>;

template <class FT>
bool on_closed_segment(const Seg<FT>& s, const Point<FT, 2>& p) {
  return point_on_segment<FT, 2>(s[0], s[1], p);
}

/// Boundary edges of a template's carrier (template coordinates).
template <class FT>
std::vector<Seg<FT>> boundary_segments(const ElementComplex<FT, 2>& m) {
  std::vector<Seg<FT>> out;
  const auto b = mesh_boundary(m);
  for (const auto& e : b.elements)
    if (e.dim() == 1) out.push_back({b.points[e.v[0]], b.points[e.v[1]]});
  return out;
}

/// Boundary edges of a copy c(X).
template <class FT>
std::vector<Seg<FT>> moved(const RigidTransformation<FT, 2>& c, const ElementComplex<FT, 2>& m) {
  auto out = boundary_segments(m);
  for (auto& e : out) e = {c(e[0]), c(e[1])};
  return out;
}

/// The trace of one copy's boundary on line l: the ends of its collinear overlaps with l (joints
/// inside a straight run of boundary edges are not ends), and the points where other boundary
/// edges meet l.
template <class FT>
void trace_points(const std::vector<Seg<FT>>& boundary, const SymLine<FT>& l,
                  std::vector<Point<FT, 2>>& out) {
  const auto n = Point<FT, 2>{{-l.dir[1], l.dir[0]}};
  std::vector<std::pair<FT, FT>> runs; // parameter intervals along l
  auto param = [&](const Point<FT, 2>& p) { return dot<FT, 2>(p - l.origin, l.dir); };
  for (const auto& s : boundary) {
    const FT a = dot<FT, 2>(s[0] - l.origin, n), b = dot<FT, 2>(s[1] - l.origin, n);
    if (a == 0 && b == 0) {
      runs.emplace_back(std::min(param(s[0]), param(s[1])), std::max(param(s[0]), param(s[1])));
      continue;
    }
    if ((a > 0 && b > 0) || (a < 0 && b < 0)) continue;
    const Point<FT, 2> p = s[0] + scaled<FT, 2>(s[1] - s[0], a / (a - b));
    if (l.contains(p)) out.push_back(p);
  }
  std::sort(runs.begin(), runs.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::pair<FT, FT>> merged;
  for (const auto& r : runs)
    if (!merged.empty() && r.first <= merged.back().second)
      merged.back().second = std::max(merged.back().second, r.second);
    else
      merged.push_back(r);
  const FT dd = dot<FT, 2>(l.dir, l.dir);
  for (const auto& [lo, hi] : merged)
    for (const FT& t : {lo, hi}) {
      if (l.ray && t < 0) continue;
      out.push_back(l.origin + scaled<FT, 2>(l.dir, t / dd));
    }
  if (l.ray)
    for (const auto& [lo, hi] : merged)
      if (lo < 0 && hi > 0) out.push_back(l.origin);
}

template <class FT>
void push_unique(std::vector<Point<FT, 2>>& v, const Point<FT, 2>& p) {
  for (const auto& q : v)
    if (q == p) return;
  v.push_back(p);
}

/// Cuts template boundary edges at `cuts`, labels each piece (line index, or the set of other
/// same-slice templates whose boundary overlaps it), and merges touching pieces with equal labels
/// whose common point is not a cut.
template <class FT>
std::vector<SymmetryPatch<FT>> patches_of_template(
    std::size_t t, const std::vector<Seg<FT>>& edges, const std::vector<SymLine<FT>>& lines,
    const std::vector<std::vector<Seg<FT>>>& same_slice_others, std::vector<Point<FT, 2>> cuts) {
  // Intra-slice contacts cut the rest (the correction to Line 17). Every contact end splits an
  // edge; merging is forbidden only at line traces and at isolated point contacts (a point of
  // another template's boundary not on a common segment), since elsewhere equal labels on both
  // sides mean the same neighbours.
  std::vector<Point<FT, 2>> split = cuts;
  std::vector<Point<FT, 2>> forbid = cuts;
  for (const auto& other : same_slice_others) {
    std::vector<Seg<FT>> overlaps;
    std::vector<Point<FT, 2>> touches;
    for (const auto& f : other)
      for (const auto& e : edges) {
        std::vector<Point<FT, 2>> common;
        for (const auto& p : f)
          if (on_closed_segment(e, p)) push_unique(common, p);
        for (const auto& p : e)
          if (on_closed_segment(f, p)) push_unique(common, p);
        for (const auto& p : common) push_unique(split, p);
        if (common.size() >= 2)
          overlaps.push_back({common[0], common[1]});
        else if (common.size() == 1)
          touches.push_back(common[0]);
      }
    for (const auto& p : touches) {
      bool on_overlap = false;
      for (const auto& o : overlaps)
        if (on_closed_segment(o, p)) on_overlap = true;
      if (!on_overlap) push_unique(forbid, p);
    }
  }
  struct Piece {
    Seg<FT> s;
    int line;
    std::vector<std::size_t> label;
  };
  std::vector<Piece> pieces;
  for (const auto& e : edges) {
    std::vector<std::pair<FT, Point<FT, 2>>> on{{FT(0), e[0]},
                                                {dot<FT, 2>(e[1] - e[0], e[1] - e[0]), e[1]}};
    for (const auto& p : split)
      if (on_closed_segment(e, p) && p != e[0] && p != e[1])
        on.emplace_back(dot<FT, 2>(p - e[0], e[1] - e[0]), p);
    std::sort(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k + 1 < on.size(); ++k) {
      Piece pc{{on[k].second, on[k + 1].second}, -1, {}};
      const auto mid = scaled<FT, 2>(pc.s[0] + pc.s[1], FT(1) / FT(2));
      for (std::size_t l = 0; l < lines.size(); ++l)
        if (lines[l].contains(pc.s[0]) && lines[l].contains(pc.s[1])) pc.line = int(l);
      if (pc.line < 0)
        for (std::size_t j = 0; j < same_slice_others.size(); ++j)
          for (const auto& f : same_slice_others[j])
            if (on_closed_segment(f, pc.s[0]) && on_closed_segment(f, pc.s[1]) &&
                on_closed_segment(f, mid)) {
              pc.label.push_back(j);
              break;
            }
      pieces.push_back(pc);
    }
  }
  std::set<Point<FT, 2>, PointLess<FT, 2>> cut_set(forbid.begin(), forbid.end());
  // A shared end joins two pieces only if the point itself has their label (the symmetry line it
  // lies on and the other templates touching it): a pinch vertex of the template inside an
  // interface belongs to the interface and separates the pieces around it.
  auto point_label = [&](const Point<FT, 2>& q) {
    std::pair<int, std::vector<std::size_t>> lab{-1, {}};
    for (std::size_t l = 0; l < lines.size(); ++l)
      if (lines[l].contains(q)) lab.first = int(l);
    for (std::size_t j = 0; j < same_slice_others.size(); ++j)
      for (const auto& f : same_slice_others[j])
        if (on_closed_segment(f, q)) {
          lab.second.push_back(j);
          break;
        }
    return lab;
  };
  std::vector<std::size_t> comp(pieces.size());
  for (std::size_t k = 0; k < pieces.size(); ++k) comp[k] = k;
  auto find = [&](std::size_t k) {
    while (comp[k] != k) k = comp[k] = comp[comp[k]];
    return k;
  };
  for (std::size_t a = 0; a < pieces.size(); ++a)
    for (std::size_t b = a + 1; b < pieces.size(); ++b) {
      if (pieces[a].line != pieces[b].line || pieces[a].label != pieces[b].label) continue;
      for (const auto& p : pieces[a].s)
        for (const auto& q : pieces[b].s)
          if (p == q && !cut_set.count(p) &&
              point_label(p) == std::pair{pieces[a].line, pieces[a].label})
            comp[find(a)] = find(b);
    }
  std::map<std::size_t, std::size_t> index;
  std::vector<SymmetryPatch<FT>> out;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    auto [it, fresh] = index.emplace(find(k), out.size());
    if (fresh) out.push_back({t, {}, pieces[k].line});
    out[it->second].segments.push_back(pieces[k].s);
  }
  return out;
}

/// \pre every template has the same instance list (T_0, T_0 ∘ S_1, …): the structure seen in the
/// common frame T_0^{-1} has copies S_g of every template. Returns the S_g.
template <class FT>
std::vector<RigidTransformation<FT, 2>> common_copies(const TemplatedStructure<FT, 2>& x) {
  std::vector<RigidTransformation<FT, 2>> s;
  const auto f0 = x.instances.at(0).at(0).transformation.inverse();
  for (const auto& inst : x.instances[0]) s.push_back(f0 * inst.transformation);
  for (const auto& list : x.instances) {
    if (list.size() != s.size())
      throw std::invalid_argument("symmetric BPP: templates have different instance counts");
    for (std::size_t g = 0; g < list.size(); ++g)
      if (f0 * list[g].transformation != s[g])
        throw std::invalid_argument("symmetric BPP: templates are not instanced by one symmetry");
  }
  return s;
}

template <class FT>
std::vector<SymmetryPatch<FT>>
symmetric_patches(const TemplatedStructure<FT, 2>& x, const std::vector<SymLine<FT>>& lines,
                  const std::vector<std::vector<Point<FT, 2>>>& line_cuts) {
  std::vector<std::vector<Seg<FT>>> edges;
  for (const auto& t : x.templates) edges.push_back(boundary_segments(t.mesh));
  std::vector<Point<FT, 2>> cuts;
  for (const auto& lc : line_cuts)
    for (const auto& p : lc) push_unique(cuts, p);
  std::vector<SymmetryPatch<FT>> out;
  for (std::size_t t = 0; t < edges.size(); ++t) {
    std::vector<std::vector<Seg<FT>>> others;
    for (std::size_t j = 0; j < edges.size(); ++j)
      if (j != t) others.push_back(edges[j]);
    auto p = patches_of_template(t, edges[t], lines, others, cuts);
    out.insert(out.end(), p.begin(), p.end());
  }
  return out;
}

} // namespace detail

/// Section 6.2: X with every template instanced by (T_0, T_0 ∘ refl). In the frame T_0^{-1} the
/// mirror line is cut at the traces of all copies of all regions; each mirror piece is mapped onto
/// itself (refl fixes the line), so every patch is related only to itself when there is one
/// region. \pre as detail::common_copies, two copies, the second a reflection
template <class FT>
std::vector<SymmetryPatch<FT>> reflective_boundary_patches(const TemplatedStructure<FT, 2>& x) {
  const auto s = detail::common_copies(x);
  if (s.size() != 2 || !(s[1] * s[1]).is_identity() || s[1].determinant_of_linear_part() != FT(-1))
    throw std::invalid_argument("reflective BPP: instances are not (T, T ∘ reflection)");
  const auto& a = s[1].matrix();
  // n ∝ a non-zero column of I - A; d = b·n / 2 (refl(x) = x - 2((x·n - d)/(n·n)) n).
  Point<FT, 2> n{{FT(1) - a[0][0], -a[1][0]}};
  if (n[0] == 0 && n[1] == 0) n = Point<FT, 2>{{-a[0][1], FT(1) - a[1][1]}};
  const FT d = dot<FT, 2>(s[1].translation_part(), n) / FT(2);
  detail::SymLine<FT> mirror{scaled<FT, 2>(n, d / dot<FT, 2>(n, n)), Point<FT, 2>{{-n[1], n[0]}},
                             false};
  std::vector<Point<FT, 2>> cuts;
  for (const auto& t : x.templates)
    for (const auto& c : s) detail::trace_points<FT>(detail::moved(c, t.mesh), mirror, cuts);
  return detail::symmetric_patches<FT>(x, {mirror}, {cuts});
}

/// Algorithm 6.2 (2D): X with every template (a region slice) instanced by (T_0, T_0 ∘ rot^k),
/// k = 0..n-1, and the first slice ray H = {c + t·d1, t >= 0} (in the frame T_0^{-1}). B_H: H cut
/// at the traces of all copies of all regions (Lines 6–12); B_S = B_H ∪ rot(B_H) (Line 13); per
/// region slice the elements of B_S on its boundary plus the rest (Lines 14–17, corrected).
template <class FT>
std::vector<SymmetryPatch<FT>> rotational_boundary_patches(const TemplatedStructure<FT, 2>& x,
                                                           const Point<FT, 2>& d1) {
  const auto s = detail::common_copies(x);
  if (s.size() < 2) throw std::invalid_argument("rotational BPP: fewer than two instances");
  const auto& rot = s[1];
  for (std::size_t k = 1; k < s.size(); ++k)
    if (s[k] != rot * s[k - 1])
      throw std::invalid_argument("rotational BPP: instances are not the powers of one rotation");
  if (!(rot * s.back()).is_identity() || rot.determinant_of_linear_part() != FT(1))
    throw std::invalid_argument("rotational BPP: the rotation does not have the instance order");
  // Centre: (I - A) c = b.
  const auto& a = rot.matrix();
  const auto& b = rot.translation_part();
  const FT det = (FT(1) - a[0][0]) * (FT(1) - a[1][1]) - a[0][1] * a[1][0];
  const Point<FT, 2> c{{(b[0] * (FT(1) - a[1][1]) + a[0][1] * b[1]) / det,
                        ((FT(1) - a[0][0]) * b[1] + a[1][0] * b[0]) / det}};
  const detail::SymLine<FT> h1{c, d1, true};
  const detail::SymLine<FT> h2{c, rot(c + d1) - c, true};
  std::vector<Point<FT, 2>> b_h;
  for (const auto& t : x.templates)
    for (const auto& copy : s) detail::trace_points<FT>(detail::moved(copy, t.mesh), h1, b_h);
  std::vector<Point<FT, 2>> b_h2;
  for (const auto& p : b_h) b_h2.push_back(rot(p));
  return detail::symmetric_patches<FT>(x, {h1, h2}, {b_h, b_h2});
}

/// All templates carry the same instance list (T_{i,g} = T_{i,0} ∘ S_g with common S_g) and the S_g
/// form a group (closed under composition): a reflective, orthogonal-reflective or rotational
/// templated structure (Sections 6.2–6.4).
template <class FT, int D>
bool instanced_by_symmetry_group(const TemplatedStructure<FT, D>& x) {
  const auto& first = x.instances.at(0);
  std::vector<RigidTransformation<FT, D>> s;
  for (const auto& inst : first)
    s.push_back(first[0].transformation.inverse() * inst.transformation);
  for (const auto& list : x.instances) {
    if (list.size() != s.size()) return false;
    for (std::size_t g = 0; g < list.size(); ++g)
      if (list[0].transformation.inverse() * list[g].transformation != s[g]) return false;
  }
  for (const auto& a : s)
    for (const auto& b : s)
      if (std::find(s.begin(), s.end(), a * b) == s.end()) return false;
  return true;
}

/// Sections 6.2–6.3 in 2D and 3D: in a structure whose templates all carry the same instance list
/// (T_0 ∘ S_g), with S_g a symmetry group, no transformation functions beyond the S_g appear, so a
/// boundary point's patch is fixed by its direct neighbours: the set of copies T_{t,0}^{-1} ∘
/// T_{s,g} (s ≠ t or g ≠ 0) whose boundary contains it. Evaluated on the faces of a subdivision
/// (the caller's), returns per template and face the index of its direct-neighbour set; no mapping
/// is composed. \pre instanced_by_symmetry_group(x)
template <class FT, int D>
std::vector<std::vector<std::size_t>>
direct_neighbour_labels(const TemplatedStructure<FT, D>& x,
                        const std::vector<BoundarySubdivision<FT, D>>& sub) {
  if (!instanced_by_symmetry_group(x))
    throw std::invalid_argument("symmetric BPP: templates are not instanced by one symmetry group");
  std::vector<std::vector<std::vector<Point<FT, D>>>> facets; // per template, template frame
  for (const auto& t : x.templates) {
    const auto b = mesh_boundary(t.mesh);
    std::vector<std::vector<Point<FT, D>>> f;
    for (const auto& e : b.elements)
      if (e.dim() == D - 1) f.push_back(b.coords(e));
    facets.push_back(std::move(f));
  }
  std::map<std::vector<std::size_t>, std::size_t> ids;
  std::vector<std::vector<std::size_t>> out(x.templates.size());
  for (std::size_t t = 0; t < x.templates.size(); ++t) {
    const auto back = x.instances[t][0].transformation.inverse();
    for (std::size_t f = 0; f < sub[t].faces.size(); ++f) {
      const auto& p = sub[t].rep[f];
      std::vector<std::size_t> label;
      for (std::size_t s = 0; s < x.templates.size(); ++s)
        for (std::size_t g = 0; g < x.instances[s].size(); ++g) {
          if (s == t && g == 0) continue;
          const auto c = back * x.instances[s][g].transformation;
          for (const auto& facet : facets[s]) {
            std::vector<Point<FT, D>> moved;
            for (const auto& q : facet) moved.push_back(c(q));
            if (point_in_simplex<FT, D>(moved, p)) {
              label.push_back(s * x.instances[s].size() + g);
              break;
            }
          }
        }
      out[t].push_back(ids.emplace(label, ids.size()).first->second);
    }
  }
  return out;
}

} // namespace symmesh::core
