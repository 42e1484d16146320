/// Exact linear programs for the core's geometric predicates — spec/definitions.md#exactness
///
/// Intersections of relative interiors of simplices (conformity, Def A.13), respect (Def 2.9) and
/// empty circumballs (Def 2.21) are all linear feasibility questions. They are decided with
/// CGAL's exact LP solver over the exact type behind FT, so no tolerance enters any verdict.
#pragma once
#include "symmesh/core/point.h"

#include <CGAL/Lazy_exact_nt.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <optional>
#include <vector>

namespace symmesh::core {

/// The exact number type the LP solver runs on: the lazy number's exact value, or FT itself.
template <class FT>
struct ExactOf {
  using type = FT;
  static const FT& get(const FT& x) { return x; }
  static FT back(const type& e) { return e; }
};
template <class ET>
struct ExactOf<CGAL::Lazy_exact_nt<ET>> {
  using type = ET;
  static ET get(const CGAL::Lazy_exact_nt<ET>& x) { return CGAL::exact(x); }
  static CGAL::Lazy_exact_nt<ET> back(const ET& e) { return CGAL::Lazy_exact_nt<ET>(e); }
};

/// One convex set of a common-point query: conv(points), its relative interior if `strict`.
template <class FT, int D>
struct ConvexGroup {
  std::vector<Point<FT, D>> points;
  bool strict = false;
};

template <class FT, int D>
struct CommonPoint {
  bool closed_meet = false; ///< the closed convex hulls have a common point
  bool strict_meet = false; ///< ... and one lies in the relative interior of every strict group
  Point<FT, D> witness{};   ///< such a point (valid when closed_meet)
};

/// Decides whether the convex hulls of the groups share a point, and whether one lies in the
/// relative interior of every group marked strict. Variables: barycentric weights λ_{g,i} >= 0 of
/// each group (summing to 1), all groups' combinations equal, and a slack t <= λ_{g,i} on strict
/// groups; maximizing t decides strictness (t* > 0 iff a relative-interior point exists).
/// \pre every group is non-empty
template <class FT, int D>
CommonPoint<FT, D> common_point(const std::vector<ConvexGroup<FT, D>>& groups) {
  using ET = typename ExactOf<FT>::type;
  using Program = CGAL::Quadratic_program<ET>;
  Program lp(CGAL::EQUAL, true, ET(0), false, ET(0));
  int var = 0;
  std::vector<int> first(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g) {
    first[g] = var;
    var += int(groups[g].points.size());
  }
  const int t = var;
  bool any_strict = false;
  int row = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (std::size_t i = 0; i < groups[g].points.size(); ++i)
      lp.set_a(first[g] + int(i), row, ET(1));
    lp.set_b(row, ET(1));
    ++row;
  }
  for (std::size_t g = 1; g < groups.size(); ++g) {
    for (int d = 0; d < D; ++d) {
      for (std::size_t i = 0; i < groups[0].points.size(); ++i)
        lp.set_a(first[0] + int(i), row, ExactOf<FT>::get(groups[0].points[i][d]));
      for (std::size_t i = 0; i < groups[g].points.size(); ++i)
        lp.set_a(first[g] + int(i), row, -ExactOf<FT>::get(groups[g].points[i][d]));
      lp.set_b(row, ET(0));
      ++row;
    }
  }
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (!groups[g].strict) continue;
    any_strict = true;
    for (std::size_t i = 0; i < groups[g].points.size(); ++i) {
      lp.set_a(t, row, ET(1));
      lp.set_a(first[g] + int(i), row, ET(-1));
      lp.set_r(row, CGAL::SMALLER);
      lp.set_b(row, ET(0));
      ++row;
    }
  }
  lp.set_u(t, true, ET(1));
  lp.set_c(t, ET(-1));
  const auto sol = CGAL::solve_linear_program(lp, ET());
  CommonPoint<FT, D> out;
  if (sol.is_infeasible()) return out;
  out.closed_meet = true;
  const auto obj = sol.objective_value();
  out.strict_meet = !any_strict || obj.numerator() * obj.denominator() < ET(0);
  auto it = sol.variable_values_begin();
  std::vector<FT> lambda;
  for (int i = 0; i < var; ++i, ++it)
    lambda.push_back(ExactOf<FT>::back(it->numerator()) / ExactOf<FT>::back(it->denominator()));
  out.witness = zero_point<FT, D>();
  for (std::size_t i = 0; i < groups[0].points.size(); ++i)
    out.witness = out.witness + scaled<FT, D>(groups[0].points[i], lambda[first[0] + int(i)]);
  return out;
}

/// Half-space system over free variables y ∈ R^m:
///   rows with `equal` hold with equality: a·y == b; the others a·y >= b (+ slack t if strict).
template <class FT>
struct LinearRow {
  std::vector<FT> a;
  FT b;
  bool equal = false;
};

struct FeasibilityResult {
  bool feasible = false;          ///< all rows hold with >=
  bool strictly_feasible = false; ///< all inequality rows hold with > at some point
};

/// Decides feasibility and strict feasibility of an inequality system over free variables.
template <class FT>
FeasibilityResult feasibility(const std::vector<LinearRow<FT>>& rows, int m) {
  using ET = typename ExactOf<FT>::type;
  using Program = CGAL::Quadratic_program<ET>;
  Program lp(CGAL::LARGER, false, ET(0), false, ET(0));
  const int t = m;
  bool any_ineq = false;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (int j = 0; j < m; ++j) lp.set_a(j, int(r), ExactOf<FT>::get(rows[r].a[j]));
    lp.set_b(int(r), ExactOf<FT>::get(rows[r].b));
    if (rows[r].equal) {
      lp.set_r(int(r), CGAL::EQUAL);
    } else {
      any_ineq = true;
      lp.set_a(t, int(r), ET(-1));
    }
  }
  lp.set_l(t, true, ET(0));
  lp.set_u(t, true, ET(1));
  lp.set_c(t, ET(-1));
  const auto sol = CGAL::solve_linear_program(lp, ET());
  FeasibilityResult out;
  if (sol.is_infeasible()) return out;
  out.feasible = true;
  const auto obj = sol.objective_value();
  out.strictly_feasible = !any_ineq || obj.numerator() * obj.denominator() < ET(0);
  return out;
}

} // namespace symmesh::core
