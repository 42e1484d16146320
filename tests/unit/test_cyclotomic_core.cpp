// The exact core over the real cyclotomic field K_m (symmesh::number::Cyclotomic with its CGAL
// traits): regular n-gon fans of triangles whose rotations by 2πk/n are exact in K_n.
#include <gtest/gtest.h>

#include "symmesh/core/exact_lp.h"
#include "symmesh/core/instance_graph.h"
#include "symmesh/core/interface_conformity.h"
#include "symmesh/core/templated_structure.h"
#include "symmesh/number/cyclotomic_cgal.h"

#include <CGAL/Simple_cartesian.h>

#include <stdexcept>
#include <type_traits>

using namespace symmesh::core;
using symmesh::number::Cyclotomic;
using symmesh::number::CyclotomicField;
using symmesh::number::CyclotomicFieldPtr;
using KP = Point<Cyclotomic, 2>;
using KT = RigidTransformation<Cyclotomic, 2>;

static_assert(std::is_same_v<ExactOf<Cyclotomic>::type, Cyclotomic>);
static_assert(std::is_same_v<CGAL::Algebraic_structure_traits<Cyclotomic>::Algebraic_category,
                             CGAL::Field_tag>);
static_assert(CGAL::Algebraic_structure_traits<Cyclotomic>::Is_exact::value);
static_assert(!CGAL::Algebraic_structure_traits<Cyclotomic>::Is_numerical_sensitive::value);
static_assert(CGAL::Real_embeddable_traits<Cyclotomic>::Is_real_embeddable::value);

namespace {

/// Rotation by 2πk/n about the origin, exact in `f` (n | m, 4 | m).
KT rotation(const CyclotomicFieldPtr& f, long k, long n) {
  const Cyclotomic c = f->cos_2pi(k, n), s = f->sin_2pi(k, n);
  KT::Mat a;
  a[0][0] = c;
  a[0][1] = -s;
  a[1][0] = s;
  a[1][1] = c;
  return KT::from_matrix(a, KP{{Cyclotomic(0), Cyclotomic(0)}});
}

/// One triangular slice (0,0), (1,0), (cos 2π/n, sin 2π/n) with n instances rotated by 2πk/n.
TemplatedStructure<Cyclotomic, 2> fan(const CyclotomicFieldPtr& f, long n) {
  ElementComplex<Cyclotomic, 2> m;
  m.points = {KP{{Cyclotomic(0), Cyclotomic(0)}}, KP{{Cyclotomic(1), Cyclotomic(0)}},
              KP{{f->cos_2pi(1, n), f->sin_2pi(1, n)}}};
  m.elements = {Simplex{0, 1, 2}};
  m = face_completion(m);
  TemplatedStructure<Cyclotomic, 2> x;
  x.templates.push_back({"slice", TemplateKind::mesh, std::move(m)});
  std::vector<InstanceSpec<Cyclotomic, 2>> inst;
  for (long k = 0; k < n; ++k) inst.push_back({rotation(f, k, n), 1});
  x.instances.push_back(inst);
  return x;
}

/// Runs the core on the n-gon fan and checks every verdict.
void check_fan(int m, long n) {
  const auto f = CyclotomicField::get(m);
  const auto x = fan(f, n);
  std::ostringstream why;
  ASSERT_TRUE(x.is_well_formed(&why)) << why.str();
  EXPECT_FALSE(find_instance_overlap(x).has_value());

  const auto si = apply_template(x);
  // The centre, and the n rim vertices, each shared exactly by two neighbouring slices.
  EXPECT_EQ(si.at.mesh.points.size(), std::size_t(n + 1));
  EXPECT_EQ(si.at.cell_region.size(), std::size_t(n));
  EXPECT_TRUE(is_mesh(si.at.mesh));
  EXPECT_TRUE(structure_instance_conforming(si));
  const auto lemma = check_interface_conformity(x, si);
  EXPECT_TRUE(lemma.holds) << lemma.detail;

  // Every two slices meet (at least at the centre): C(n, 2) edges plus the trivial self-loop.
  EXPECT_EQ(neighbouring_instances(si).size(), std::size_t(n * (n - 1) / 2));
  const auto g = instance_graph(x, si);
  EXPECT_EQ(boost::num_vertices(g), 1u);
  EXPECT_EQ(boost::num_edges(g), std::size_t(n * (n - 1) / 2 + 1));

  // The rotations form the cyclic group C_n exactly.
  const auto r = rotation(f, 1, n);
  KT p;
  for (long k = 0; k < n; ++k) {
    EXPECT_EQ(p, x.instances[0][k].transformation);
    EXPECT_EQ(p.determinant_of_linear_part(), Cyclotomic(1));
    p = r * p;
  }
  EXPECT_TRUE(p.is_identity());
}

} // namespace

TEST(CyclotomicCgal, TraitsUseCertifiedSignAndExactDivision) {
  const auto f = CyclotomicField::get(8);
  const Cyclotomic c = f->cos_2pi(1, 8); // √2/2
  EXPECT_EQ(CGAL::sign(c - Cyclotomic(mpq_class(7, 10))), CGAL::POSITIVE);
  EXPECT_EQ(CGAL::sign(c - Cyclotomic(mpq_class(71, 100))), CGAL::NEGATIVE);
  EXPECT_EQ(CGAL::compare(c * c, Cyclotomic(mpq_class(1, 2))), CGAL::EQUAL);
  EXPECT_EQ(CGAL::abs(-c), c);
  EXPECT_TRUE(CGAL::is_zero(c * c - Cyclotomic(mpq_class(1, 2))));
  EXPECT_TRUE(CGAL::is_one(c / c));
  EXPECT_EQ(CGAL::square(c), c * c);
  EXPECT_EQ(CGAL::integral_division(Cyclotomic(1), c), c + c);
  EXPECT_EQ(CGAL::inverse(c), c + c);
  EXPECT_TRUE(CGAL::divides(c, Cyclotomic(3)));
  const auto iv = CGAL::to_interval(c);
  EXPECT_LE(iv.first, 0.70710678118654757);
  EXPECT_GE(iv.second, 0.70710678118654746);
}

TEST(CyclotomicCgal, CartesianKernelPredicatesAreExact) {
  using K = CGAL::Simple_cartesian<Cyclotomic>;
  const auto f = CyclotomicField::get(16);
  const K::Point_2 o(Cyclotomic(0), Cyclotomic(0));
  const K::Point_2 a(f->cos_2pi(1, 16), f->sin_2pi(1, 16));
  const K::Point_2 b(f->cos_2pi(9, 16), f->sin_2pi(9, 16)); // -a
  const K::Point_2 c(f->cos_2pi(2, 16), f->sin_2pi(2, 16));
  EXPECT_EQ(CGAL::orientation(a, o, b), CGAL::COLLINEAR);
  EXPECT_EQ(CGAL::orientation(o, a, c), CGAL::LEFT_TURN);
  EXPECT_EQ(CGAL::compare_distance_to_point(o, a, c), CGAL::EQUAL);
}

TEST(CyclotomicCgal, ExactLpOverK8) {
  const auto f = CyclotomicField::get(8);
  const Cyclotomic c = f->cos_2pi(1, 8);
  // Two triangles of the octagon fan: slices 0 and 1 meet along an edge, not in their interiors.
  const KP o{{Cyclotomic(0), Cyclotomic(0)}}, e{{Cyclotomic(1), Cyclotomic(0)}}, d{{c, c}};
  const KP u{{Cyclotomic(0), Cyclotomic(1)}};
  std::vector<ConvexGroup<Cyclotomic, 2>> closed{{{o, e, d}, false}, {{o, d, u}, false}};
  EXPECT_TRUE(common_point(closed).closed_meet);
  std::vector<ConvexGroup<Cyclotomic, 2>> open{{{o, e, d}, true}, {{o, d, u}, true}};
  const auto r = common_point(open);
  EXPECT_TRUE(r.closed_meet);
  EXPECT_FALSE(r.strict_meet);
  // The witness lies on the shared edge y = x.
  EXPECT_EQ(r.witness[0], r.witness[1]);
}

TEST(CyclotomicCore, RotationMustBeExactlyOrthogonal) {
  const auto f = CyclotomicField::get(8);
  KT::Mat a;
  a[0][0] = f->cos_2pi(1, 8);
  a[0][1] = -f->sin_2pi(1, 8) + Cyclotomic(mpq_class(1, 1000000));
  a[1][0] = f->sin_2pi(1, 8);
  a[1][1] = f->cos_2pi(1, 8);
  EXPECT_THROW(KT::from_matrix(a, KP{{Cyclotomic(0), Cyclotomic(0)}}), std::invalid_argument);
  EXPECT_NO_THROW(rotation(f, 3, 8));
}

TEST(CyclotomicCore, OctagonFanInK8IsATemplatedMesh) {
  check_fan(8, 8);
}

TEST(CyclotomicCore, HexadecagonFanInK16IsATemplatedMesh) {
  check_fan(16, 16);
}

TEST(CyclotomicCore, OverlappingFanIsRejected) {
  // Slices of angle 2π/8 rotated by 2π/16: neighbours overlap (Eq. 4.2 violated).
  const auto f = CyclotomicField::get(16);
  auto x = fan(f, 8);
  x.instances[0] = {{rotation(f, 0, 16), 1}, {rotation(f, 1, 16), 1}};
  EXPECT_TRUE(find_instance_overlap(x).has_value());
}
