/// Rigid transformations with exact coefficients — spec/definitions.md#rigid-transformations
///
/// Definition 4.1 restricts instance transformations to rigid ones (rotations, translations,
/// reflections and their compositions, Section 4.1). x -> A x + b with A exactly orthogonal.
/// Every constructor checks orthogonality exactly and throws `std::invalid_argument` otherwise.
#pragma once
#include "symmesh/core/linear_algebra.h"
#include "symmesh/core/point.h"

#include <array>
#include <sstream>
#include <stdexcept>
#include <string>

namespace symmesh::core {

template <class FT, int D>
class RigidTransformation {
public:
  using Mat = std::array<std::array<FT, D>, D>;
  using Vec = Point<FT, D>;

  /// The identity I.
  RigidTransformation() {
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) a_[i][j] = FT(i == j ? 1 : 0);
    b_ = zero_point<FT, D>();
  }

  /// \pre A^T A = I exactly (so det A = ±1); otherwise throws std::invalid_argument.
  static RigidTransformation from_matrix(const Mat& a, const Vec& b) {
    RigidTransformation t;
    t.a_ = a;
    t.b_ = b;
    std::string why;
    if (!t.is_valid(&why)) throw std::invalid_argument(why);
    return t;
  }

  static RigidTransformation translation(const Vec& b) {
    RigidTransformation t;
    t.b_ = b;
    return t;
  }

  /// refl_{n,d}(x) = x - 2((x·n - d)/(n·n)) n (Eq. 6.1 with a not necessarily unit, rational n).
  /// \pre n != 0
  static RigidTransformation reflection(const Vec& n, const FT& d) {
    const FT nn = dot<FT, D>(n, n);
    if (nn == 0) throw std::invalid_argument("reflection normal is the zero vector");
    RigidTransformation t;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) t.a_[i][j] = FT(i == j ? 1 : 0) - FT(2) * n[i] * n[j] / nn;
    for (int i = 0; i < D; ++i) t.b_[i] = FT(2) * d * n[i] / nn;
    return t;
  }

  /// Signed permutation: row i of A has sign[i] in column perm[i].
  /// \pre perm is a permutation of 0..D-1 and sign[i] ∈ {-1, 1}
  static RigidTransformation signed_permutation(const std::array<int, D>& perm,
                                                const std::array<int, D>& sign, const Vec& b) {
    Mat a;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) a[i][j] = FT(0);
    std::array<bool, D> used{};
    for (int i = 0; i < D; ++i) {
      if (perm[i] < 0 || perm[i] >= D || used[perm[i]])
        throw std::invalid_argument("signed permutation: 'perm' is not a permutation");
      if (sign[i] != 1 && sign[i] != -1)
        throw std::invalid_argument("signed permutation: 'sign' entries must be 1 or -1");
      used[perm[i]] = true;
      a[i][perm[i]] = FT(sign[i]);
    }
    return from_matrix(a, b);
  }

  /// 2D rotation with rational cosine c and sine s about `center`.
  /// \pre D == 2 and c^2 + s^2 == 1 exactly (a Pythagorean angle)
  static RigidTransformation rotation_2d(const FT& c, const FT& s,
                                         const Vec& center) requires(D == 2) {
    if (c * c + s * s != FT(1))
      throw std::invalid_argument("rotation: cos^2 + sin^2 != 1 (not a rational rotation)");
    Mat a;
    a[0][0] = c;
    a[0][1] = -s;
    a[1][0] = s;
    a[1][1] = c;
    return about_center(a, center);
  }

  /// 3D rotation by the angle with cosine c and sine s about the line through `center` along the
  /// unit vector u (Rodrigues: R = cI + s[u]x + (1 - c) u uᵀ). For |u| = 1 and c² + s² = 1 this R
  /// is orthogonal with det 1, so those two equations are the whole check — in K_256 they cost 2
  /// products where is_valid's AᵀA costs 27 (reading a 128-TSV's 768 rotations).
  /// \pre D == 3, u·u == 1 and c² + s² == 1 exactly
  static RigidTransformation rotation_about_axis(const FT& c, const FT& s, const Vec& u,
                                                 const Vec& center) requires(D == 3) {
    if (u[0] * u[0] + u[1] * u[1] + u[2] * u[2] != FT(1))
      throw std::invalid_argument("rotation: the axis is not a unit vector");
    if (c * c + s * s != FT(1)) throw std::invalid_argument("rotation: cos^2 + sin^2 != 1");
    const FT t = FT(1) - c;
    Mat a = {{{c + t * u[0] * u[0], t * u[0] * u[1] - s * u[2], t * u[0] * u[2] + s * u[1]},
              {t * u[1] * u[0] + s * u[2], c + t * u[1] * u[1], t * u[1] * u[2] - s * u[0]},
              {t * u[2] * u[0] - s * u[1], t * u[2] * u[1] + s * u[0], c + t * u[2] * u[2]}}};
    return about_center(a, center);
  }

  /// 3D rotation from an integer (or rational) quaternion q = (w, x, y, z) != 0 about `center`.
  /// R = (1/|q|^2) * (Cayley/Euler-Rodrigues matrix), exactly orthogonal for every q != 0.
  static RigidTransformation rotation_quaternion(const FT& w, const FT& x, const FT& y, const FT& z,
                                                 const Vec& center) requires(D == 3) {
    const FT q = w * w + x * x + y * y + z * z;
    if (q == 0) throw std::invalid_argument("rotation: quaternion is zero");
    Mat a;
    a[0][0] = (w * w + x * x - y * y - z * z) / q;
    a[0][1] = FT(2) * (x * y - w * z) / q;
    a[0][2] = FT(2) * (x * z + w * y) / q;
    a[1][0] = FT(2) * (x * y + w * z) / q;
    a[1][1] = (w * w - x * x + y * y - z * z) / q;
    a[1][2] = FT(2) * (y * z - w * x) / q;
    a[2][0] = FT(2) * (x * z - w * y) / q;
    a[2][1] = FT(2) * (y * z + w * x) / q;
    a[2][2] = (w * w - x * x - y * y + z * z) / q;
    return about_center(a, center);
  }

  Vec operator()(const Vec& p) const {
    Vec r;
    for (int i = 0; i < D; ++i) {
      FT s = b_[i];
      for (int j = 0; j < D; ++j) s += a_[i][j] * p[j];
      r[i] = s;
    }
    return r;
  }

  /// A·u: the linear part applied to a vector (the image of a direction).
  Vec linear(const Vec& u) const {
    Vec r;
    for (int i = 0; i < D; ++i) {
      FT s = a_[i][0] * u[0];
      for (int j = 1; j < D; ++j) s += a_[i][j] * u[j];
      r[i] = s;
    }
    return r;
  }

  /// (this ∘ other)(x) = this(other(x)).
  RigidTransformation operator*(const RigidTransformation& o) const {
    RigidTransformation t;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) {
        FT s = 0;
        for (int k = 0; k < D; ++k) s += a_[i][k] * o.a_[k][j];
        t.a_[i][j] = s;
      }
    t.b_ = (*this)(o.b_);
    return t;
  }

  /// Inverse of a rigid map: x -> A^T (x - b).
  RigidTransformation inverse() const {
    RigidTransformation t;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) t.a_[i][j] = a_[j][i];
    for (int i = 0; i < D; ++i) {
      FT s = 0;
      for (int j = 0; j < D; ++j) s -= a_[j][i] * b_[j];
      t.b_[i] = s;
    }
    return t;
  }

  friend bool operator==(const RigidTransformation& l, const RigidTransformation& r) {
    return l.a_ == r.a_ && l.b_ == r.b_;
  }
  friend bool operator!=(const RigidTransformation& l, const RigidTransformation& r) {
    return !(l == r);
  }

  bool is_identity() const { return *this == RigidTransformation(); }
  const Mat& matrix() const { return a_; }
  const Vec& translation_part() const { return b_; }

  /// The same motion over another number type, entry by entry.
  /// \pre `to` is an exact field embedding (e.g. a lazy wrapper of FT), so A^T A = I still holds
  /// and is not re-checked.
  template <class To, class F>
  RigidTransformation<To, D> convert_numbers(F&& to) const {
    RigidTransformation<To, D> t;
    for (int i = 0; i < D; ++i) {
      for (int j = 0; j < D; ++j) t.a_[i][j] = to(a_[i][j]);
      t.b_[i] = to(b_[i]);
    }
    return t;
  }

  /// det A, which is +1 for proper and -1 for improper (orientation-reversing) motions.
  FT determinant_of_linear_part() const {
    Matrix<FT> m(D, std::vector<FT>(D));
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) m[i][j] = a_[i][j];
    return determinant(m);
  }

  /// Exact orthogonality A^T A = I. Writes the first violated entry to `why`.
  bool is_valid(std::string* why = nullptr) const {
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) {
        FT s = 0;
        for (int k = 0; k < D; ++k) s += a_[k][i] * a_[k][j];
        if (s != FT(i == j ? 1 : 0)) {
          if (why) {
            std::ostringstream os;
            os << "matrix is not orthogonal: (A^T A)[" << i << "][" << j << "] != " << (i == j);
            *why = os.str();
          }
          return false;
        }
      }
    return true;
  }

private:
  template <class, int>
  friend class RigidTransformation;

  static RigidTransformation about_center(const Mat& a, const Vec& c) {
    RigidTransformation t;
    t.a_ = a;
    // x -> A (x - c) + c
    for (int i = 0; i < D; ++i) {
      FT s = c[i];
      for (int j = 0; j < D; ++j) s -= a[i][j] * c[j];
      t.b_[i] = s;
    }
    return t;
  }

  Mat a_;
  Vec b_;
};

} // namespace symmesh::core
