/// Definition A.3 (n-ball, open n-ball, n-half-ball), Eq. A.2–A.4 — spec/definitions.md#def-a-1
///
/// The radius is carried as its square so that a ball whose radius is irrational (a circumball,
/// Def 2.14) stays exact; membership compares squared distances. Eq. A.4 prints the half-ball as
/// {y : ‖y − x‖ ≤ r ∧ y_n ≥ 0}, which is a half-ball about x only when x_n = 0 (its one use, the
/// unit half-ball ℋ^n of Def A.6, has x = 0); the code cuts at y_n ≥ x_n, which agrees there
/// (spec/traceability.md, slips).
#pragma once
#include "symmesh/core/point.h"

#include <ostream>

namespace symmesh::core {

enum class BallKind { closed, open, half };

template <class FT, int D>
struct Ball {
  Point<FT, D> center;
  FT squared_radius = FT(1);
  BallKind kind = BallKind::closed;

  /// r > 0.
  bool is_valid(std::ostream* why = nullptr) const {
    if (squared_radius > FT(0)) return true;
    if (why) *why << "a ball needs a positive radius";
    return false;
  }

  /// y in the ball (Eq. A.2 closed, A.3 open, A.4 half).
  bool contains(const Point<FT, D>& y) const {
    const auto d = y - center;
    const FT dd = dot<FT, D>(d, d);
    switch (kind) {
    case BallKind::open:
      return dd < squared_radius;
    case BallKind::half:
      return dd <= squared_radius && y[D - 1] >= center[D - 1];
    case BallKind::closed:
      break;
    }
    return dd <= squared_radius;
  }
};

/// The unit ball 𝔅^n, 𝔅^n open or ℋ^n about the origin.
template <class FT, int D>
Ball<FT, D> unit_ball(BallKind kind = BallKind::closed) {
  return {zero_point<FT, D>(), FT(1), kind};
}

} // namespace symmesh::core
