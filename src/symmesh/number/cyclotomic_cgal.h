// CGAL number-type traits for symmesh::number::Cyclotomic (spec/number-type.md): K_m is an exact
// ordered field, so it is a CGAL FieldNumberType and RealEmbeddable type. Sign and comparison use
// the type's certified sign(); To_double/To_interval are its output-only conversions. With this
// header, CGAL::Simple_cartesian<Cyclotomic>, CGAL::Cartesian<Cyclotomic> and CGAL's QP solver
// with ET = Cyclotomic compile, and the core's ExactOf<Cyclotomic> is Cyclotomic itself (the
// primary template of symmesh/core/exact_lp.h).
#pragma once

#include "symmesh/number/cyclotomic.h"

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Coercion_traits.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Real_embeddable_traits.h>
#include <CGAL/number_type_basic.h>

#include <utility>

namespace CGAL {

template <>
class Algebraic_structure_traits<symmesh::number::Cyclotomic>
    : public Algebraic_structure_traits_base<symmesh::number::Cyclotomic, Field_tag> {
public:
  using Type = symmesh::number::Cyclotomic;
  using Is_exact = Tag_true;
  using Is_numerical_sensitive = Tag_false;

  class Is_zero : public CGAL::cpp98::unary_function<Type, bool> {
  public:
    bool operator()(const Type& x) const { return x.is_zero(); }
  };

  class Is_one : public CGAL::cpp98::unary_function<Type, bool> {
  public:
    bool operator()(const Type& x) const { return x == Type(1); }
  };

  class Square : public CGAL::cpp98::unary_function<Type, Type> {
  public:
    Type operator()(const Type& x) const { return x * x; }
  };

  /// Exact division; in a field every non-zero element divides every element.
  class Integral_division : public CGAL::cpp98::binary_function<Type, Type, Type> {
  public:
    Type operator()(const Type& x, const Type& y) const { return x / y; }
    CGAL_IMPLICIT_INTEROPERABLE_BINARY_OPERATOR(Type)
  };

  class Inverse : public CGAL::cpp98::unary_function<Type, Type> {
  public:
    Type operator()(const Type& x) const { return x.inverse(); }
  };

  class Divides : public CGAL::cpp98::binary_function<Type, Type, bool> {
  public:
    bool operator()(const Type& x, const Type& y) const { return !x.is_zero() || y.is_zero(); }
    bool operator()(const Type& x, const Type& y, Type& q) const {
      if (x.is_zero()) {
        q = Type(0);
        return y.is_zero();
      }
      q = y / x;
      return true;
    }
    CGAL_IMPLICIT_INTEROPERABLE_BINARY_OPERATOR_WITH_RT(Type, bool)
  };

  /// The canonical representation is already reduced (coefficients in lowest terms).
  class Simplify : public CGAL::cpp98::unary_function<Type&, void> {
  public:
    void operator()(Type&) const {}
  };
};

template <>
class Real_embeddable_traits<symmesh::number::Cyclotomic>
    : public INTERN_RET::Real_embeddable_traits_base<symmesh::number::Cyclotomic, Tag_true> {
public:
  using Type = symmesh::number::Cyclotomic;

  class Is_zero : public CGAL::cpp98::unary_function<Type, bool> {
  public:
    bool operator()(const Type& x) const { return x.is_zero(); }
  };

  class Sgn : public CGAL::cpp98::unary_function<Type, ::CGAL::Sign> {
  public:
    ::CGAL::Sign operator()(const Type& x) const { return ::CGAL::Sign(x.sign()); }
  };

  class Is_positive : public CGAL::cpp98::unary_function<Type, bool> {
  public:
    bool operator()(const Type& x) const { return x.sign() > 0; }
  };

  class Is_negative : public CGAL::cpp98::unary_function<Type, bool> {
  public:
    bool operator()(const Type& x) const { return x.sign() < 0; }
  };

  class Abs : public CGAL::cpp98::unary_function<Type, Type> {
  public:
    Type operator()(const Type& x) const { return x.sign() < 0 ? -x : x; }
  };

  class Compare : public CGAL::cpp98::binary_function<Type, Type, Comparison_result> {
  public:
    Comparison_result operator()(const Type& x, const Type& y) const {
      return Comparison_result(compare(x, y));
    }
    CGAL_IMPLICIT_INTEROPERABLE_BINARY_OPERATOR_WITH_RT(Type, Comparison_result)
  };

  class Is_finite : public CGAL::cpp98::unary_function<Type, bool> {
  public:
    bool operator()(const Type&) const { return true; }
  };

  /// Output only (and CGAL's filtered QP pricing, which re-checks every decision exactly).
  class To_double : public CGAL::cpp98::unary_function<Type, double> {
  public:
    double operator()(const Type& x) const { return x.to_double(); }
  };

  class To_interval : public CGAL::cpp98::unary_function<Type, std::pair<double, double>> {
  public:
    std::pair<double, double> operator()(const Type& x) const { return x.to_interval(); }
  };
};

// Mixed arithmetic with built-in integers and GMP numbers promotes to Cyclotomic.
CGAL_DEFINE_COERCION_TRAITS_FROM_TO(short, symmesh::number::Cyclotomic)
CGAL_DEFINE_COERCION_TRAITS_FROM_TO(int, symmesh::number::Cyclotomic)
CGAL_DEFINE_COERCION_TRAITS_FROM_TO(long, symmesh::number::Cyclotomic)

} // namespace CGAL
