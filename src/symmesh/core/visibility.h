/// Definition 2.22 (Visibility) — spec/definitions.md#def-2-22
///
/// Two points x, y are visible to each other if the segment simplex(x, y) respects the PLC P,
/// i.e. every element of P (vertex, k-cell) meets it in a union of its faces {x}, {y}, [x, y].
/// `visible` decides exactly that.
///
/// Def 2.23 asks whether a vertex v is visible from *some* point of the relative interior of a
/// simplex σ. Computable form (spec/definitions.md#visibility-from-a-simplex): when relint σ lies
/// inside a D-cell of P and meets no lower-dimensional element of P (true for the cells of a mesh
/// that respects and geometry-conforms to P, and for its facets not included in a facet of P),
/// x ∈ relint σ sees v iff the half-open segment [x, v) misses every lower-dimensional element
/// ("blocker") of P. The points that a blocker b hides from v form its shadow
///   shadow_v(b) = { v + λ(y − v) : y ∈ b \ {v}, λ >= 1 },
/// a convex polyhedron (closed up to the point v). So v is visible from relint σ iff the
/// relatively open set relint σ is not covered by the finitely many closed polyhedra cl
/// shadow_v(b). That is decided exactly by branching on the complements of their half-spaces (open
/// half-spaces) and asking an exact LP whether each branch keeps a point of relint σ.
#pragma once
#include "symmesh/core/delaunay.h"
#include "symmesh/core/plc.h"
#include "symmesh/core/respect.h"

#include <stdexcept>
#include <vector>

namespace symmesh::core {

/// E respects the element p of P given by its carrier subcomplex k_p (Def 2.9): every face f of E
/// lies in us(k_p) or has a relative interior disjoint from it.
/// \pre k_p is face-complete and conforming (a subcomplex of the PLC's carrier)
template <class FT, int D>
bool respects_plc_element(const std::vector<Point<FT, D>>& e, const ElementComplex<FT, D>& k_p) {
  if (k_p.elements.empty()) return true;
  const int kd = k_p.cell_dimension();
  std::vector<Point<FT, D>> corners;
  for (const auto& s : k_p.elements)
    if (s.n == 1) corners.push_back(k_p.points[s.v[0]]);
  if (!box_of<FT, D>(e).overlaps(box_of<FT, D>(corners))) return true; // E ∩ p = ∅
  return respects_by_faces<FT, D>(
      e,
      [&](const auto& f) { return int(f.size()) - 1 <= kd && simplex_covered_by<FT, D>(f, k_p); },
      [&](const auto& f) {
        const auto fbox = box_of<FT, D>(f);
        for (const auto& g : k_p.elements) {
          const auto gp = k_p.coords(g);
          if (!fbox.overlaps(box_of<FT, D>(gp))) continue;
          if (relative_interiors_meet<FT, D>(f, gp)) return true;
        }
        return false;
      });
}

/// E respects every element of P: every vertex and every k-cell.
template <class FT, int D>
bool respects_plc(const std::vector<Point<FT, D>>& e, const Plc<FT, D>& p) {
  for (VertexId v : p.vertices) {
    ElementComplex<FT, D> vertex;
    vertex.points = p.carrier.points;
    vertex.elements = {Simplex{v}};
    if (!respects_plc_element<FT, D>(e, vertex)) return false;
  }
  for (std::size_t c = 0; c < p.cells.size(); ++c)
    if (!respects_plc_element<FT, D>(e, p.cell_complex(c))) return false;
  return true;
}

/// Def 2.22: x and y (x != y) are visible to each other iff simplex(x, y) respects P.
template <class FT, int D>
bool visible(const Plc<FT, D>& p, const Point<FT, D>& x, const Point<FT, D>& y) {
  if (x == y) throw std::invalid_argument("visible: x == y is no line simplex");
  return respects_plc<FT, D>({x, y}, p);
}

/// The blockers of P: its vertices and the carrier pieces of all cells of dimension < D, as
/// point tuples (their union is the union of all lower-dimensional elements of P).
template <class FT, int D>
std::vector<std::vector<Point<FT, D>>> visibility_blockers(const Plc<FT, D>& p) {
  std::vector<std::vector<Point<FT, D>>> out;
  for (VertexId v : p.vertices) out.push_back({p.carrier.points[v]});
  for (const auto& c : p.cells)
    if (c.dimension < D)
      for (const auto& s : c.pieces) out.push_back(p.carrier.coords(s));
  return out;
}

namespace detail {

/// A closed convex polyhedron given by generators: apex + Σ α_j u_j with linearly independent
/// u_j, α_j >= 0, and Σ α_j >= 1 (`at_least_one`) or Σ α_j <= 1 (`at_most_one`) if set.
template <class FT, int D>
struct GeneratedPolyhedron {
  Point<FT, D> apex;
  std::vector<Point<FT, D>> u;
  bool at_least_one = false, at_most_one = false;
};

/// Rows a·x >= b (and a·x == b) describing a GeneratedPolyhedron in x ∈ R^D. The u_j are
/// completed to a basis by unit vectors; (α, γ) = A^{-1}(x − apex), and x lies in the flat iff
/// γ = 0.
template <class FT, int D>
std::vector<LinearRow<FT>> halfspace_rows(const GeneratedPolyhedron<FT, D>& g) {
  std::vector<Point<FT, D>> basis = g.u;
  for (int i = 0; i < D && int(basis.size()) < D; ++i) {
    Point<FT, D> e = zero_point<FT, D>();
    e[i] = 1;
    auto trial = basis;
    trial.push_back(e);
    Matrix<FT> m;
    for (const auto& b : trial) m.push_back(std::vector<FT>(b.begin(), b.end()));
    if (rank(m) == trial.size()) basis = trial;
  }
  // inverse rows: solve A^T r_i = e_i, where A has the basis vectors as columns
  Matrix<FT> at;
  for (const auto& b : basis) at.push_back(std::vector<FT>(b.begin(), b.end()));
  std::vector<std::vector<FT>> inv_rows;
  for (int i = 0; i < D; ++i) {
    // row i of A^{-1}: r with r·basis_j = δ_ij
    Matrix<FT> sys = at;
    std::vector<FT> rhs(D, FT(0));
    rhs[i] = 1;
    auto r = solve_unique(sys, rhs);
    if (!r) throw std::logic_error("halfspace_rows: generators are not independent");
    inv_rows.push_back(*r);
  }
  auto row_of = [&](const std::vector<FT>& r, const FT& scale) {
    LinearRow<FT> row;
    row.a.resize(D);
    FT c = 0;
    for (int d = 0; d < D; ++d) {
      row.a[d] = scale * r[d];
      c += scale * r[d] * g.apex[d];
    }
    row.b = c; // scale * r·(x − apex) >= 0  ⇔  scale * r·x >= scale * r·apex
    return row;
  };
  std::vector<LinearRow<FT>> rows;
  const std::size_t k = g.u.size();
  for (std::size_t j = 0; j < k; ++j) rows.push_back(row_of(inv_rows[j], FT(1)));
  if (g.at_least_one || g.at_most_one) {
    std::vector<FT> sum(D, FT(0));
    for (std::size_t j = 0; j < k; ++j)
      for (int d = 0; d < D; ++d) sum[d] += inv_rows[j][d];
    LinearRow<FT> row = row_of(sum, g.at_least_one ? FT(1) : FT(-1));
    row.b += g.at_least_one ? FT(1) : FT(-1); // Σα >= 1  or  −Σα >= −1
    rows.push_back(row);
  }
  for (std::size_t j = k; j < std::size_t(D); ++j) {
    LinearRow<FT> row = row_of(inv_rows[j], FT(1));
    row.equal = true;
    rows.push_back(row);
  }
  return rows;
}

template <class FT, int D>
bool independent(const std::vector<Point<FT, D>>& u) {
  if (u.empty()) return true;
  Matrix<FT> m;
  for (const auto& b : u) m.push_back(std::vector<FT>(b.begin(), b.end()));
  return rank(m) == u.size();
}

/// Closed polyhedra whose union is cl shadow_v(b) ∪ b.
template <class FT, int D>
void shadow_pieces(const std::vector<Point<FT, D>>& b, const Point<FT, D>& v,
                   std::vector<GeneratedPolyhedron<FT, D>>& out) {
  // b itself (a simplex: apex b_0, edges to the others, Σα <= 1)
  {
    GeneratedPolyhedron<FT, D> g{b[0], {}, false, true};
    for (std::size_t j = 1; j < b.size(); ++j) g.u.push_back(b[j] - b[0]);
    out.push_back(g);
  }
  for (std::size_t j = 0; j < b.size(); ++j)
    if (b[j] == v) { // v is a vertex of b: the shadow is the cone at v over b
      GeneratedPolyhedron<FT, D> g{v, {}, false, false};
      for (std::size_t i = 0; i < b.size(); ++i)
        if (i != j) g.u.push_back(b[i] - v);
      if (!g.u.empty()) out.push_back(g);
      return;
    }
  std::vector<Point<FT, D>> u;
  for (const auto& y : b) u.push_back(y - v);
  if (independent<FT, D>(u)) { // v ∉ aff(b)
    out.push_back(GeneratedPolyhedron<FT, D>{v, u, true, false});
    return;
  }
  if (b.size() == 1) return; // v == b handled above; cannot happen
  if (point_in_simplex<FT, D>(b, v)) {
    // v inside b but no vertex: b = ∪ conv(v, f) over the facets f of b with v ∉ aff(f)
    for (std::size_t skip = 0; skip < b.size(); ++skip) {
      std::vector<Point<FT, D>> f;
      for (std::size_t i = 0; i < b.size(); ++i)
        if (i != skip) f.push_back(b[i]);
      std::vector<Point<FT, D>> fu;
      for (const auto& y : f) fu.push_back(y - v);
      if (!independent<FT, D>(fu)) continue;
      out.push_back(GeneratedPolyhedron<FT, D>{v, fu, false, false});
    }
    return;
  }
  // v ∈ aff(b) \ b: shadow_v(b) = b ∪ ⋃ shadow_v(facets of b)
  for (std::size_t skip = 0; skip < b.size(); ++skip) {
    std::vector<Point<FT, D>> f;
    for (std::size_t i = 0; i < b.size(); ++i)
      if (i != skip) f.push_back(b[i]);
    shadow_pieces<FT, D>(f, v, out);
  }
}

/// Rows over the barycentric parameters μ_1..μ_k of σ (x = s_0 + Σ μ_i (s_i − s_0)).
template <class FT, int D>
LinearRow<FT> to_simplex_parameters(const LinearRow<FT>& r, const std::vector<Point<FT, D>>& s) {
  LinearRow<FT> out;
  out.equal = r.equal;
  const std::size_t k = s.size() - 1;
  out.a.resize(k);
  FT at0 = 0;
  for (int d = 0; d < D; ++d) at0 += r.a[d] * s[0][d];
  for (std::size_t i = 1; i <= k; ++i) {
    FT c = 0;
    for (int d = 0; d < D; ++d) c += r.a[d] * (s[i][d] - s[0][d]);
    out.a[i - 1] = c;
  }
  out.b = r.b - at0;
  return out;
}

template <class FT>
bool strictly_feasible(const std::vector<LinearRow<FT>>& rows, int m) {
  return feasibility<FT>(rows, m).strictly_feasible;
}

/// Is some point of the open region `region` (strict rows) outside every polyhedron from
/// `polys[i..]` (each a list of rows h >= 0)?
template <class FT>
bool uncovered(const std::vector<LinearRow<FT>>& region,
               const std::vector<std::vector<LinearRow<FT>>>& polys, std::size_t i, int m) {
  for (; i < polys.size(); ++i) {
    auto with = region;
    with.insert(with.end(), polys[i].begin(), polys[i].end());
    if (strictly_feasible<FT>(with, m)) break; // polys[i] has interior points in the region
  }
  if (i == polys.size()) return true;
  for (const auto& h : polys[i]) {
    LinearRow<FT> out = h; // the open complement h < 0, i.e. −h > 0
    for (auto& a : out.a) a = -a;
    out.b = -out.b;
    auto branch = region;
    branch.push_back(out);
    if (strictly_feasible<FT>(branch, m) && uncovered<FT>(branch, polys, i + 1, m)) return true;
  }
  return false;
}

} // namespace detail

/// v is visible from some point of the relative interior of the simplex σ: some x ∈ relint σ
/// has [x, v) disjoint from every blocker (spec/definitions.md#visibility-from-a-simplex).
/// \pre σ is a non-degenerate k-simplex, k >= 1, and v is no vertex of σ
template <class FT, int D>
bool visible_from_relative_interior(const std::vector<Point<FT, D>>& sigma, const Point<FT, D>& v,
                                    const std::vector<std::vector<Point<FT, D>>>& blockers) {
  if (sigma.size() < 2 || !affinely_independent<FT, D>(sigma))
    throw std::invalid_argument("visible_from_relative_interior: degenerate simplex");
  for (const auto& s : sigma)
    if (s == v) throw std::invalid_argument("visible_from_relative_interior: v is a vertex of σ");
  const int m = int(sigma.size()) - 1;
  // relint σ: μ_i > 0 and 1 − Σ μ_i > 0
  std::vector<LinearRow<FT>> region;
  for (int i = 0; i < m; ++i) {
    LinearRow<FT> r;
    r.a.assign(m, FT(0));
    r.a[i] = 1;
    r.b = 0;
    region.push_back(r);
  }
  {
    LinearRow<FT> r;
    r.a.assign(m, FT(-1));
    r.b = -1;
    region.push_back(r);
  }
  const auto sbox = box_of<FT, D>(sigma);
  std::vector<std::vector<LinearRow<FT>>> polys;
  for (const auto& b : blockers) {
    std::vector<detail::GeneratedPolyhedron<FT, D>> pieces;
    detail::shadow_pieces<FT, D>(b, v, pieces);
    for (const auto& g : pieces) {
      // cheap exact filter: a bounded piece whose box misses σ's box is irrelevant
      if (g.at_most_one) {
        std::vector<Point<FT, D>> corners{g.apex};
        for (const auto& u : g.u) corners.push_back(g.apex + u);
        if (!box_of<FT, D>(corners).overlaps(sbox)) continue;
      }
      std::vector<LinearRow<FT>> rows;
      bool lower_dimensional = false;
      for (const auto& r : detail::halfspace_rows<FT, D>(g)) {
        auto q = detail::to_simplex_parameters<FT, D>(r, sigma);
        if (q.equal) {
          bool zero = q.b == 0;
          for (const auto& a : q.a) zero = zero && a == 0;
          if (!zero) lower_dimensional = true; // meets aff σ in a nowhere dense set
          continue;
        }
        rows.push_back(q);
      }
      if (!lower_dimensional) polys.push_back(rows);
    }
  }
  return detail::uncovered<FT>(region, polys, 0, m);
}

} // namespace symmesh::core
