// Section 5.2.1 on a generated templated mesh: merging templates congruent by an exact motion —
// spec/adaptation.md#tmesh-cloning
//
// The doubles of both templates are taken as the rationals they are, so "R(X_j) = X_i" is decided
// without a tolerance: R is solved from one cell of each, over the rationals, and must be
// orthogonal and send every vertex of j exactly onto a vertex of i, and cells onto cells. Motions
// whose images of doubles are doubles (translations by representable amounts, mirrors, signed
// permutations, Pythagorean rotations on suitable points) are found; a rotation by 2π/n with
// rounded images is not, and is refused like any non-congruent pair — unless a tolerance is
// given: then a pair the exact search refuses is searched again up to that fraction of i's
// diameter (find_congruence_to_rounding), the motion made orthonormal before it is composed.
#include "symmesh/adapt/tmesh_template_cloning.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstddef>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace symmesh::adapt {
namespace {

using mesh::IndexType;
using mesh::TemplatedMeshCompactSvb;
using Q = mpq_class;

/// x -> A x + b over the rationals; A row-major, d × d.
struct ExactAffine {
  int d = 3;
  std::vector<Q> a, b;

  Q at(int r, int c) const { return a[std::size_t(r * d + c)]; }
  std::vector<Q> operator()(const double* x) const {
    std::vector<Q> y(b);
    for (int r = 0; r < d; ++r)
      for (int c = 0; c < d; ++c) y[std::size_t(r)] += at(r, c) * Q(x[c]);
    return y;
  }
  bool is_orthogonal() const {
    for (int r = 0; r < d; ++r)
      for (int c = 0; c < d; ++c) {
        Q s = 0;
        for (int k = 0; k < d; ++k) s += at(k, r) * at(k, c);
        if (s != (r == c ? 1 : 0)) return false;
      }
    return true;
  }
  bool is_identity() const {
    for (int r = 0; r < d; ++r) {
      if (b[std::size_t(r)] != 0) return false;
      for (int c = 0; c < d; ++c)
        if (at(r, c) != (r == c ? 1 : 0)) return false;
    }
    return true;
  }
};

/// The affine map with q_k = A p_k + b for the d + 1 corners of a simplex, over the rationals;
/// nullopt when the p_k are affinely dependent.
std::optional<ExactAffine> affine_from_corners(const std::vector<const double*>& p,
                                               const std::vector<const double*>& q, int d) {
  // Solve A P = R, P and R with columns p_k − p_0 and q_k − q_0: rows of A from P^T A^T = R^T.
  std::vector<std::vector<Q>> m(std::size_t(d), std::vector<Q>(std::size_t(2 * d)));
  for (int k = 0; k < d; ++k)
    for (int c = 0; c < d; ++c) {
      m[std::size_t(k)][std::size_t(c)] = Q(p[std::size_t(k + 1)][c]) - Q(p[0][c]);
      m[std::size_t(k)][std::size_t(d + c)] = Q(q[std::size_t(k + 1)][c]) - Q(q[0][c]);
    }
  for (int col = 0; col < d; ++col) { // Gauss–Jordan, exact
    int pivot = col;
    while (pivot < d && m[std::size_t(pivot)][std::size_t(col)] == 0) ++pivot;
    if (pivot == d) return std::nullopt;
    std::swap(m[std::size_t(col)], m[std::size_t(pivot)]);
    const Q inv = 1 / m[std::size_t(col)][std::size_t(col)];
    for (auto& v : m[std::size_t(col)]) v *= inv;
    for (int r = 0; r < d; ++r) {
      if (r == col || m[std::size_t(r)][std::size_t(col)] == 0) continue;
      const Q f = m[std::size_t(r)][std::size_t(col)];
      for (int c = 0; c < 2 * d; ++c)
        m[std::size_t(r)][std::size_t(c)] -= f * m[std::size_t(col)][std::size_t(c)];
    }
  }
  ExactAffine f;
  f.d = d;
  f.a.assign(std::size_t(d * d), 0);
  for (int r = 0; r < d; ++r) // row r of A = column r of the solved A^T
    for (int c = 0; c < d; ++c) f.a[std::size_t(r * d + c)] = m[std::size_t(c)][std::size_t(d + r)];
  f.b.assign(std::size_t(d), 0);
  for (int r = 0; r < d; ++r) {
    f.b[std::size_t(r)] = Q(q[0][r]);
    for (int c = 0; c < d; ++c) f.b[std::size_t(r)] -= f.at(r, c) * Q(p[0][c]);
  }
  return f;
}

/// The double nearest to q (ties to even), decided exactly.
double nearest_double(const Q& q) {
  const double t = q.get_d(); // truncated towards zero
  const double up = std::nextafter(t, q > 0 ? INFINITY : -INFINITY);
  const Q dt = abs(q - Q(t)), du = abs(q - Q(up));
  if (dt != du) return dt < du ? t : up;
  std::int64_t bits;
  static_assert(sizeof(bits) == sizeof(t));
  std::memcpy(&bits, &t, sizeof(t));
  return bits % 2 == 0 ? t : up;
}

using Key = std::array<double, 3>;
Key key_of(const double* x, int d) {
  Key k{0, 0, 0};
  for (int c = 0; c < d; ++c) k[std::size_t(c)] = x[c];
  return k;
}

/// Sorted squared edge lengths of a cell in doubles: only a filter on the candidate cells (equal
/// up to a relative 1e-9 for congruent cells, whose exact lengths are equal); the decision is
/// the exact check after it.
std::vector<double> edge_lengths(const mesh::Mesh& m, std::size_t c, int d) {
  std::vector<double> out;
  for (int u = 0; u <= d; ++u)
    for (int v = u + 1; v <= d; ++v) {
      double s = 0;
      for (int k = 0; k < d; ++k) {
        const double e =
            m.vertex(std::size_t(m.cell(c)[u]))[k] - m.vertex(std::size_t(m.cell(c)[v]))[k];
        s += e * e;
      }
      out.push_back(s);
    }
  std::sort(out.begin(), out.end());
  return out;
}

bool similar(const std::vector<double>& x, const std::vector<double>& y, double relative) {
  for (std::size_t k = 0; k < x.size(); ++k)
    if (std::abs(x[k] - y[k]) > relative * std::max(x[k], y[k])) return false;
  return true;
}

std::vector<IndexType> sorted_cell(const mesh::Mesh& m, std::size_t c, int d,
                                   const std::vector<IndexType>* rename = nullptr) {
  std::vector<IndexType> v(m.cell(c), m.cell(c) + d + 1);
  if (rename)
    for (auto& x : v) x = (*rename)[std::size_t(x)];
  std::sort(v.begin(), v.end());
  return v;
}

/// With f as R: every vertex of `from` goes exactly onto a vertex of `onto` (one each), and the
/// cells of `from` onto the cells of `onto`. Returns the vertex map.
std::optional<std::vector<IndexType>> vertex_map(const ExactAffine& f, const mesh::Mesh& from,
                                                 const mesh::Mesh& onto,
                                                 const std::map<Key, IndexType>& where,
                                                 const std::set<std::vector<IndexType>>& cells) {
  const int d = from.point_dimension;
  std::vector<IndexType> image(from.vertex_count());
  std::vector<char> hit(onto.vertex_count(), 0);
  for (std::size_t v = 0; v < from.vertex_count(); ++v) {
    const auto y = f(from.vertex(v));
    Key k{0, 0, 0};
    for (int c = 0; c < d; ++c) {
      k[std::size_t(c)] = y[std::size_t(c)].get_d();
      if (Q(k[std::size_t(c)]) != y[std::size_t(c)]) return std::nullopt; // not a double
    }
    const auto it = where.find(k);
    if (it == where.end() || hit[std::size_t(it->second)]) return std::nullopt;
    hit[std::size_t(it->second)] = 1;
    image[v] = it->second;
  }
  for (std::size_t c = 0; c < from.cell_count(); ++c)
    if (!cells.count(sorted_cell(from, c, d, &image))) return std::nullopt;
  return image;
}

bool simplicial(const mesh::Mesh& m) {
  const auto want =
      m.point_dimension == 2 ? mesh::ElementType::triangle : mesh::ElementType::tetrahedron;
  return std::all_of(m.cell_types.begin(), m.cell_types.end(),
                     [&](mesh::ElementType t) { return t == want; });
}

/// R and the vertex map it makes.
struct Found {
  ExactAffine motion;
  std::vector<IndexType> vertex;
};

/// A grid of i's vertices with cells of 4·eps, so that the vertices within eps of a point lie in
/// the 3^d cells around it; the nearest one within eps, if any.
struct RoundedLookup {
  const mesh::Mesh& onto;
  double eps, cell;
  std::map<std::array<std::int64_t, 3>, std::vector<IndexType>> grid;

  RoundedLookup(const mesh::Mesh& m, double eps_) : onto(m), eps(eps_), cell(4 * eps_) {
    for (std::size_t v = 0; v < m.vertex_count(); ++v)
      grid[key(m.vertex(v))].push_back(IndexType(v));
  }
  std::array<std::int64_t, 3> key(const double* x) const {
    std::array<std::int64_t, 3> k{0, 0, 0};
    for (int c = 0; c < onto.point_dimension; ++c)
      k[std::size_t(c)] = std::int64_t(std::floor(x[c] / cell));
    return k;
  }
  std::optional<IndexType> near(const double* x) const {
    const int d = onto.point_dimension;
    const auto k0 = key(x);
    std::optional<IndexType> best;
    double best2 = eps * eps;
    for (int n = 0; n < (d == 2 ? 9 : 27); ++n) {
      auto k = k0;
      for (int c = 0, m = n; c < d; ++c, m /= 3) k[std::size_t(c)] += m % 3 - 1;
      const auto it = grid.find(k);
      if (it == grid.end()) continue;
      for (IndexType v : it->second) {
        double l2 = 0;
        for (int c = 0; c < d; ++c)
          l2 += (onto.vertex(std::size_t(v))[c] - x[c]) * (onto.vertex(std::size_t(v))[c] - x[c]);
        if (l2 <= best2) best2 = l2, best = v;
      }
    }
    return best;
  }
};

/// The rational affine map as doubles, its columns made orthonormal by Gram–Schmidt (the
/// orientation kept) and b fitted to the corners' centroids: R up to rounding, rigid.
ExactAffine orthonormal(const ExactAffine& f, const std::vector<const double*>& p,
                        const std::vector<const double*>& q) {
  const int d = f.d;
  std::vector<std::array<double, 3>> col(static_cast<std::size_t>(d));
  for (int c = 0; c < d; ++c)
    for (int r = 0; r < d; ++r) col[std::size_t(c)][std::size_t(r)] = f.at(r, c).get_d();
  for (int c = 0; c < d; ++c) {
    auto& u = col[std::size_t(c)];
    for (int k = 0; k < c; ++k) {
      double dot = 0;
      for (int r = 0; r < d; ++r) dot += u[std::size_t(r)] * col[std::size_t(k)][std::size_t(r)];
      for (int r = 0; r < d; ++r) u[std::size_t(r)] -= dot * col[std::size_t(k)][std::size_t(r)];
    }
    double len = 0;
    for (int r = 0; r < d; ++r) len += u[std::size_t(r)] * u[std::size_t(r)];
    for (int r = 0; r < d; ++r) u[std::size_t(r)] /= std::sqrt(len);
  }
  ExactAffine g;
  g.d = d;
  g.a.assign(std::size_t(d * d), 0);
  for (int r = 0; r < d; ++r)
    for (int c = 0; c < d; ++c) g.a[std::size_t(r * d + c)] = col[std::size_t(c)][std::size_t(r)];
  g.b.assign(std::size_t(d), 0);
  for (int r = 0; r < d; ++r) {
    double b = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      b += q[k][r];
      for (int c = 0; c < d; ++c) b -= col[std::size_t(c)][std::size_t(r)] * p[k][c];
    }
    g.b[std::size_t(r)] = b / double(p.size());
  }
  return g;
}

/// Whether A^T A = I within `slack` in every entry (in doubles).
bool nearly_orthogonal(const ExactAffine& f, double slack) {
  for (int r = 0; r < f.d; ++r)
    for (int c = 0; c < f.d; ++c) {
      double s = 0;
      for (int k = 0; k < f.d; ++k) s += f.at(k, r).get_d() * f.at(k, c).get_d();
      if (std::abs(s - (r == c ? 1 : 0)) > slack) return false;
    }
  return true;
}

double diameter(const mesh::Mesh& m) {
  const int d = m.point_dimension;
  std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t v = 0; v < m.vertex_count(); ++v)
    for (int c = 0; c < d; ++c) {
      lo[std::size_t(c)] = std::min(lo[std::size_t(c)], m.vertex(v)[c]);
      hi[std::size_t(c)] = std::max(hi[std::size_t(c)], m.vertex(v)[c]);
    }
  double l2 = 0;
  for (int c = 0; c < d; ++c)
    l2 += (hi[std::size_t(c)] - lo[std::size_t(c)]) * (hi[std::size_t(c)] - lo[std::size_t(c)]);
  return std::sqrt(l2);
}

/// Any congruence sends j's first cell onto some cell of i, corner to corner: calls
/// `attempt(f, p, q)` with the affine map f (over the rationals) from j's first cell's corners p
/// onto each cell of i whose sorted edge lengths match to `relative`, corners q in every order;
/// returns the first result that holds a value.
template <class Attempt>
std::optional<Found> over_corner_matches(const mesh::Mesh& onto, const mesh::Mesh& from,
                                         double relative, Attempt&& attempt) {
  const int d = from.point_dimension;
  std::vector<const double*> p;
  for (int k = 0; k <= d; ++k) p.push_back(from.vertex(std::size_t(from.cell(0)[k])));
  const auto lengths = edge_lengths(from, 0, d);
  for (std::size_t c = 0; c < onto.cell_count(); ++c) {
    if (!similar(lengths, edge_lengths(onto, c, d), relative)) continue;
    std::vector<int> order(std::size_t(d + 1));
    std::iota(order.begin(), order.end(), 0);
    do {
      std::vector<const double*> q;
      for (int k : order) q.push_back(onto.vertex(std::size_t(onto.cell(c)[k])));
      if (const auto f = affine_from_corners(p, q, d))
        if (auto found = attempt(*f, p, q)) return found;
    } while (std::next_permutation(order.begin(), order.end()));
  }
  return std::nullopt;
}

/// R with R(X_j) = X_i up to `tolerance` times i's diameter: solved from j's first cell and a
/// cell of i as in the exact search, nearly orthogonal (1e-6: a copy scaled by more than the
/// tolerance is refused by the vertices), made orthonormal, and accepted when it sends every
/// vertex of j within that distance of a distinct vertex of i and every cell onto a cell.
std::optional<Found> find_congruence_to_rounding(const mesh::Mesh& onto, const mesh::Mesh& from,
                                                 const std::set<std::vector<IndexType>>& cells,
                                                 double tolerance) {
  const int d = from.point_dimension;
  const RoundedLookup lookup(onto, tolerance * diameter(onto));
  if (!(lookup.eps > 0)) return std::nullopt;
  const auto attempt = [&](const ExactAffine& f, const std::vector<const double*>& p,
                           const std::vector<const double*>& q) -> std::optional<Found> {
    if (!nearly_orthogonal(f, 1e-6)) return std::nullopt;
    const auto r = orthonormal(f, p, q);
    std::vector<IndexType> image(from.vertex_count());
    std::vector<char> hit(onto.vertex_count(), 0);
    for (std::size_t v = 0; v < from.vertex_count(); ++v) {
      double y[3] = {0, 0, 0};
      for (int row = 0; row < d; ++row) {
        y[row] = r.b[std::size_t(row)].get_d();
        for (int col = 0; col < d; ++col) y[row] += r.at(row, col).get_d() * from.vertex(v)[col];
      }
      const auto w = lookup.near(y);
      if (!w || hit[std::size_t(*w)]) return std::nullopt;
      hit[std::size_t(*w)] = 1;
      image[v] = *w;
    }
    for (std::size_t k = 0; k < from.cell_count(); ++k)
      if (!cells.count(sorted_cell(from, k, d, &image))) return std::nullopt;
    return Found{r, image};
  };
  return over_corner_matches(onto, from, std::max(1e-9, 16 * tolerance), attempt);
}

std::optional<Found> find_congruence(const TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j,
                                     double tolerance) {
  const auto &onto = t.templated.templates.at(i).mesh, &from = t.templated.templates.at(j).mesh;
  const int d = from.point_dimension;
  if (onto.point_dimension != d || onto.vertex_count() != from.vertex_count() ||
      onto.cell_count() != from.cell_count() || from.cell_count() == 0 || !simplicial(from) ||
      !simplicial(onto))
    return std::nullopt;
  std::map<Key, IndexType> where;
  for (std::size_t v = 0; v < onto.vertex_count(); ++v)
    if (!where.emplace(key_of(onto.vertex(v), d), IndexType(v)).second) return std::nullopt;
  std::set<std::vector<IndexType>> cells;
  for (std::size_t c = 0; c < onto.cell_count(); ++c) cells.insert(sorted_cell(onto, c, d));
  if (cells.size() != onto.cell_count()) return std::nullopt;
  const auto exact =
      over_corner_matches(onto, from, 1e-9,
                          [&](const ExactAffine& f, const std::vector<const double*>&,
                              const std::vector<const double*>&) -> std::optional<Found> {
                            if (!f.is_orthogonal()) return std::nullopt;
                            if (auto image = vertex_map(f, from, onto, where, cells))
                              return Found{f, *image};
                            return std::nullopt;
                          });
  if (exact || !(tolerance > 0)) return exact;
  return find_congruence_to_rounding(onto, from, cells, tolerance);
}

/// T ∘ R^{-1} with R(x) = A x + b orthogonal: y -> M A^T y + (t − M A^T b), over the rationals
/// from the doubles, rounded once per entry.
mesh::Transformation after_inverse(const mesh::Transformation& tf, const ExactAffine& r, int d) {
  std::vector<Q> ma(std::size_t(d * d), 0); // M A^T
  for (int row = 0; row < d; ++row)
    for (int col = 0; col < d; ++col)
      for (int k = 0; k < d; ++k)
        ma[std::size_t(row * d + col)] += Q(tf.matrix[std::size_t(row * d + k)]) * r.at(col, k);
  mesh::Transformation out;
  for (const auto& x : ma) out.matrix.push_back(nearest_double(x));
  for (int row = 0; row < d; ++row) {
    Q s = Q(tf.translation[std::size_t(row)]);
    for (int k = 0; k < d; ++k) s -= ma[std::size_t(row * d + k)] * r.b[std::size_t(k)];
    out.translation.push_back(nearest_double(s));
  }
  return out;
}

/// Template j's instances join i with T ∘ R^{-1}, its tables renumbered by the vertex map.
void merge_by(TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j, const Found& r) {
  const int d = t.templated.point_dimension;
  auto& from = t.templated.templates[j];
  if (!r.motion.is_identity()) {
    // Each transformation j's instances use gets one composed copy, appended.
    std::map<IndexType, IndexType> composed;
    for (auto& k : from.transformation_indices) {
      const auto [it, fresh] = composed.emplace(k, IndexType(t.templated.transformations.size()));
      if (fresh)
        t.templated.transformations.push_back(
            after_inverse(t.templated.transformations[std::size_t(k)], r.motion, d));
      k = it->second;
    }
  }
  for (auto& table : t.tables) {
    if (std::size_t(table.from_template) == j)
      for (auto& pair : table.pairs) pair.first = r.vertex[std::size_t(pair.first)];
    if (std::size_t(table.to_template) == j)
      for (auto& pair : table.pairs) pair.second = r.vertex[std::size_t(pair.second)];
  }
  from.mesh = t.templated.templates[i].mesh;
  detail::merge_templates_unchecked(t, i, j);
}

} // namespace

std::optional<TemplateCongruence> template_congruence(const TemplatedMeshCompactSvb& t,
                                                      std::size_t i, std::size_t j,
                                                      double tolerance) {
  const auto r = find_congruence(t, i, j, tolerance);
  if (!r) return std::nullopt;
  return TemplateCongruence{r->vertex, r->motion.is_identity()};
}

void merge_congruent_templates(TemplatedMeshCompactSvb& t, std::size_t i, std::size_t j,
                               double tolerance) {
  const auto nt = t.templated.templates.size();
  if (i == j || i >= nt || j >= nt)
    throw std::invalid_argument("merge_congruent_templates: needs two distinct templates below " +
                                std::to_string(nt) + ", got " + std::to_string(i) + " and " +
                                std::to_string(j));
  std::ostringstream why;
  if (!t.is_valid(&why))
    throw std::invalid_argument("merge_congruent_templates: the templated mesh is not valid: " +
                                why.str());
  const auto r = find_congruence(t, i, j, tolerance);
  if (!r)
    throw std::invalid_argument(
        "merge_congruent_templates: templates " + std::to_string(i) + " and " + std::to_string(j) +
        (tolerance > 0
             ? " are not congruent up to " + std::to_string(tolerance) + " of the diameter"
             : " are not congruent by an exact motion"));
  merge_by(t, i, j, *r);
}

std::size_t merge_congruent_templates(TemplatedMeshCompactSvb& t, double tolerance) {
  std::ostringstream why;
  if (!t.is_valid(&why))
    throw std::invalid_argument("merge_congruent_templates: the templated mesh is not valid: " +
                                why.str());
  std::size_t merged = 0;
  for (std::size_t j = 1; j < t.templated.templates.size();) {
    std::optional<Found> r;
    std::size_t i = 0;
    while (i < j && !(r = find_congruence(t, i, j, tolerance))) ++i;
    if (!r) {
      ++j;
      continue;
    }
    merge_by(t, i, j, *r);
    ++merged;
  }
  return merged;
}

} // namespace symmesh::adapt
