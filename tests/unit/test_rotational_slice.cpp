// Definitions 6.1–6.3 about a general centre and (3D) a general axis, Eq. 6.10–6.17 —
// spec/definitions.md#def-6-3: a quarter-turn slice about the axis v = (1, 2, 2) through
// c = (1, 0, 2) (an exact rational rotation), its half-plane normals, the prism it cuts from a
// square prism around the axis, the symmetries of that prism, and Eq. 6.17's reconstruction —
// each also where it must fail (a missing copy, a piece outside the slice, a shifted mirror).
#include <gtest/gtest.h>

#include "exact_fixtures.h"

#include "symmesh/core/kernel.h"
#include "symmesh/core/rotational_slice.h"

#include <map>
#include <sstream>

using namespace symmesh::core;
using symmesh::Exact;
using namespace symmesh::test;

namespace {

template <int D>
using P = Point<Exact, D>;
template <int D>
using T = RigidTransformation<Exact, D>;

/// rot_{c,v,90°} for v = (1, 2, 2): A = [û]× + ûûᵀ with û = v/3.
T<3> quarter_turn() {
  const Exact n = 9;
  typename T<3>::Mat a{{{Exact(1) / n, Exact(-4) / n, Exact(8) / n},
                        {Exact(8) / n, Exact(4) / n, Exact(1) / n},
                        {Exact(-4) / n, Exact(7) / n, Exact(4) / n}}};
  const auto c = p3(1, 0, 2);
  const auto ac = T<3>::from_matrix(a, p3(0, 0, 0))(c);
  return T<3>::from_matrix(a, c - ac);
}

RotationalSlice<Exact, 3> slice3() {
  return {p3(1, 0, 2), p3(1, 2, 2), p3(2, -1, 0), quarter_turn()};
}

/// The union of the given copies of a complex, vertices with equal coordinates merged.
template <int D>
ElementComplex<Exact, D> union_of(const std::vector<ElementComplex<Exact, D>>& parts) {
  ElementComplex<Exact, D> out;
  auto less = [](const P<D>& a, const P<D>& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
  };
  std::map<P<D>, VertexId, decltype(less)> id(less);
  for (const auto& part : parts)
    for (const auto& e : part.elements) {
      std::vector<VertexId> v;
      for (VertexId x : e) {
        const auto [it, added] = id.emplace(part.points[x], VertexId(out.points.size()));
        if (added) out.points.push_back(part.points[x]);
        v.push_back(it->second);
      }
      out.elements.push_back(Simplex::from_range(v.data(), v.data() + v.size()));
    }
  out.normalize();
  return out;
}

template <int D>
ElementComplex<Exact, D> moved(ElementComplex<Exact, D> e, const T<D>& t) {
  for (auto& p : e.points) p = t(p);
  return e;
}

/// The prism over the triangle (c, c + u, c + A u) along v, as three tetrahedra.
ElementComplex<Exact, 3> piece3() {
  const auto s = slice3();
  const auto au = s.rotation(s.center + s.start) - s.center;
  ElementComplex<Exact, 3> e;
  e.points = {s.center, s.center + s.start, s.center + au};
  for (int i = 0; i < 3; ++i) e.points.push_back(e.points[std::size_t(i)] + s.axis);
  e.elements = {Simplex{0, 1, 2, 3}, Simplex{1, 2, 3, 4}, Simplex{2, 3, 4, 5}};
  return face_completion(e);
}

template <int D>
std::vector<ElementComplex<Exact, D>> copies(const ElementComplex<Exact, D>& piece, const T<D>& r,
                                             int n) {
  std::vector<ElementComplex<Exact, D>> out;
  T<D> power;
  for (int k = 0; k < n; ++k, power = r * power) out.push_back(moved(piece, power));
  return out;
}

} // namespace

TEST(RotationalSlice, NormalsAndMembershipAboutAGeneralAxisEq613To615) {
  const auto s = slice3();
  std::ostringstream why;
  ASSERT_TRUE(s.is_valid(&why)) << why.str();
  // A u = (2, 4, -5)/3: n_1 points towards it and n_2 = 3u back towards the start.
  EXPECT_EQ(s.n1(), p3(2, 4, -5));
  EXPECT_EQ(s.n2(), p3(6, -3, 0));
  const auto au = s.rotation(s.center + s.start) - s.center;
  const Exact q = Exact(1) / 4;
  EXPECT_TRUE(
      s.contains(s.center + scaled<Exact, 3>(s.start + au, q) + scaled<Exact, 3>(s.axis, 7)));
  EXPECT_FALSE(s.contains(s.center + scaled<Exact, 3>(au - s.start, q)));
  EXPECT_TRUE(s.contains(s.center + s.axis)); // the axis belongs to every slice
  // Three quarter turns span 270 degrees: two half-planes no longer describe that slice.
  auto wide = s;
  wide.rotation = s.rotation * s.rotation * s.rotation;
  EXPECT_FALSE(wide.is_valid());
  auto tilted = s;
  tilted.start = p3(1, 0, 0); // not perpendicular to v
  EXPECT_FALSE(tilted.is_valid());
}

TEST(RotationalSlice, PrismAroundTheAxisIsSymmetricAndRebuiltFromItsSliceEq617) {
  const auto s = slice3();
  const auto piece = piece3();
  const auto prism = union_of<3>(copies(piece, s.rotation, 4));
  ASSERT_TRUE(is_mesh(prism));
  EXPECT_TRUE(has_symmetry(prism, s.rotation)); // Def 6.2, order 4
  // Def 6.1: the mirror through the axis and u, and the mid-height mirror ⟂ v.
  EXPECT_TRUE(has_symmetry(prism, T<3>::reflection(p3(2, 4, -5), Exact(-8))));
  EXPECT_TRUE(has_symmetry(prism, T<3>::reflection(p3(1, 2, 2), Exact(19) / 2)));
  EXPECT_FALSE(has_symmetry(prism, T<3>::reflection(p3(1, 2, 2), Exact(11) / 2)));
  std::ostringstream why;
  EXPECT_TRUE(reconstructs_by_rotation(prism, piece, s, 4, &why)) << why.str();
  // Three copies only: not symmetric, and the fourth copy leaves it.
  auto three = copies(piece, s.rotation, 3);
  const auto partial = union_of<3>(three);
  EXPECT_FALSE(has_symmetry(partial, s.rotation));
  why.str("");
  EXPECT_FALSE(reconstructs_by_rotation(partial, piece, s, 4, &why));
  EXPECT_NE(why.str().find("leaves b"), std::string::npos) << why.str();
  // The second copy is no piece of the first slice; two turns are no rotation of order 2.
  why.str("");
  EXPECT_FALSE(reconstructs_by_rotation(prism, three[1], s, 4, &why));
  EXPECT_NE(why.str().find("leaves the slice"), std::string::npos) << why.str();
  why.str("");
  EXPECT_FALSE(reconstructs_by_rotation(prism, piece, s, 2, &why));
  EXPECT_NE(why.str().find("identity"), std::string::npos) << why.str();
}

TEST(RotationalSlice, QuarterTurnInThePlaneEq610To612And616) {
  const auto c = p2(1, 1);
  const RotationalSlice<Exact, 2> s{c, p2(0, 0), p2(1, 0), T<2>::rotation_2d(0, 1, c)};
  ASSERT_TRUE(s.is_valid());
  EXPECT_EQ(s.n1(), p2(0, 1));
  EXPECT_EQ(s.n2(), p2(1, 0));
  ElementComplex<Exact, 2> piece;
  piece.points = {c, c + p2(1, 0), c + p2(0, 1)};
  piece.elements = {Simplex{0, 1, 2}};
  piece = face_completion(piece);
  const auto diamond = union_of<2>(copies(piece, s.rotation, 4));
  EXPECT_TRUE(has_symmetry(diamond, s.rotation));
  EXPECT_TRUE(reconstructs_by_rotation(diamond, piece, s, 4));
  EXPECT_FALSE(has_symmetry(diamond, T<2>::rotation_2d(0, 1, p2(0, 0))));
}
