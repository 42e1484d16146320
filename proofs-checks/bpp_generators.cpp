// Generators of templated structures for the boundary patch partition — see bpp_generators.h.
#include "proofs-checks/bpp_generators.h"

#include <sstream>

namespace symmesh::proofs::gen {
namespace {

int choose(int lo, int hi) { // inclusive
  return *rc::gen::inRange(lo, hi + 1);
}

template <int D>
Point<D> pt(std::array<Exact, D> c) {
  Point<D> p;
  for (int i = 0; i < D; ++i) p[i] = c[i];
  return p;
}

template <int D>
Complex<D> complex_of(std::vector<Point<D>> pts, std::vector<core::Simplex> cells) {
  Complex<D> m;
  m.points = std::move(pts);
  m.elements = std::move(cells);
  return core::face_completion(m);
}

/// The box [0,w] x [0,h] (x [0,l]): two triangles, or the six Kuhn tetrahedra.
template <int D>
Complex<D> box_mesh(const Exact& w, const Exact& h, const Exact& l) {
  if constexpr (D == 2) {
    return complex_of<2>({pt<2>({0, 0}), pt<2>({w, 0}), pt<2>({w, h}), pt<2>({0, h})},
                         {{0, 1, 2}, {0, 2, 3}});
  } else {
    std::vector<Point<3>> p;
    for (int v = 0; v < 8; ++v)
      p.push_back(pt<3>({v & 1 ? w : Exact(0), v & 2 ? h : Exact(0), v & 4 ? l : Exact(0)}));
    return complex_of<3>(
        p, {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}});
  }
}

template <int D>
Motion<D> translation(const Exact& x, const Exact& y) {
  Point<D> b = core::zero_point<Exact, D>();
  b[0] = x;
  b[1] = y;
  return Motion<D>::translation(b);
}

/// Rotation by k·90° about the origin (2D) or the z axis (3D), as a signed permutation.
template <int D>
Motion<D> quarter_turn(int k, const Exact& cx = 0, const Exact& cy = 0) {
  std::array<int, D> perm{}, sign{};
  for (int i = 0; i < D; ++i) {
    perm[i] = i;
    sign[i] = 1;
  }
  switch (k % 4) {
  case 1:
    perm[0] = 1, perm[1] = 0, sign[0] = -1;
    break;
  case 2:
    sign[0] = sign[1] = -1;
    break;
  case 3:
    perm[0] = 1, perm[1] = 0, sign[1] = -1;
    break;
  default:
    break;
  }
  const auto r = Motion<D>::signed_permutation(perm, sign, core::zero_point<Exact, D>());
  // About (cx, cy): x -> R(x - c) + c.
  return translation<D>(cx, cy) * r * translation<D>(-cx, -cy);
}

template <int D>
void add_template(Structure<D>& x, const std::string& name, Complex<D> m,
                  std::vector<Motion<D>> motions, int region = 1) {
  x.templates.push_back({name, core::TemplateKind::mesh, std::move(m)});
  std::vector<core::InstanceSpec<Exact, D>> inst;
  for (auto& t : motions) inst.push_back({t, region});
  x.instances.push_back(std::move(inst));
}

template <int D>
std::string dims(const Exact& w, const Exact& h) {
  return text(w) + "x" + text(h) + (D == 3 ? "x1" : "");
}

/// The 90° slice (0,0), (a,-a), [(a+1, 0)], (a,a) as a mesh (prism in 3D).
template <int D>
Complex<D> slice_mesh(int a, bool kite, int inner = 0) {
  std::vector<Point<2>> s;
  if (inner == 0)
    s = {pt<2>({0, 0}), pt<2>({a, -a}), pt<2>({a, a})};
  else
    s = {pt<2>({inner, -inner}), pt<2>({a, -a}), pt<2>({a, a}), pt<2>({inner, inner})};
  std::vector<core::Simplex> tri = inner == 0 ? std::vector<core::Simplex>{{0, 1, 2}}
                                              : std::vector<core::Simplex>{{0, 1, 2}, {0, 2, 3}};
  if (kite && inner == 0) {
    s.push_back(pt<2>({a + 1, 0}));
    tri = {{0, 1, 3}, {0, 3, 2}};
  }
  if constexpr (D == 2) {
    return complex_of<2>(s, tri);
  } else {
    // Prism over a single triangle: three tetrahedra (the slice is one triangle in 3D).
    std::vector<Point<3>> p;
    for (int z = 0; z < 2; ++z)
      for (int k = 0; k < 3; ++k) p.push_back(pt<3>({s[k][0], s[k][1], Exact(z)}));
    return complex_of<3>(p, {{0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 5}});
  }
}

} // namespace

template <int D>
rc::Gen<GeneratedStructure<D>> self_contact_structure() {
  return rc::gen::exec([] {
    const Exact w = choose(1, 3), h = choose(1, 3);
    const Exact t = h * Exact(choose(1, 3)) / 4;
    std::array<int, D> perm{}, sign{};
    for (int i = 0; i < D; ++i) perm[i] = i, sign[i] = i < 2 ? -1 : 1;
    Point<D> b = core::zero_point<Exact, D>();
    b[0] = 2 * w;
    b[1] = 2 * t;
    GeneratedStructure<D> s;
    add_template<D>(s.x, "box", box_mesh<D>(w, h, 1),
                    {Motion<D>(), Motion<D>::signed_permutation(perm, sign, b)});
    s.recipe = "box " + dims<D>(w, h) + " and its half turn about x=" + text(w) + ", y=" + text(t) +
               " (Figure 4.11)";
    s.tier = Tier::templated_structure;
    return s;
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> shifted_translation_structure() {
  return rc::gen::exec([] {
    const Exact w = choose(1, 3), h = choose(1, 3);
    const Exact t = h * Exact(choose(1, 3)) / 4;
    GeneratedStructure<D> s;
    add_template<D>(s.x, "box", box_mesh<D>(w, h, 1), {Motion<D>(), translation<D>(w, t)});
    s.recipe = "box " + dims<D>(w, h) + " and its translate by (" + text(w) + ", " + text(t) + ")";
    s.tier = Tier::templated_structure;
    return s;
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> indirect_chain_structure(bool aligned) {
  return rc::gen::exec([aligned] {
    const int h1 = choose(1, 3), h2 = aligned ? h1 : choose(1, 3), h3 = aligned ? h1 : choose(1, 3);
    const int s1 = aligned ? 0 : choose(0, h1 - 1), s3 = aligned ? 0 : choose(1 - h3, h2 - 1);
    GeneratedStructure<D> s;
    add_template<D>(s.x, "X1", box_mesh<D>(1, h1, 1), {Motion<D>()});
    add_template<D>(s.x, "X2", box_mesh<D>(1, h2, 1),
                    {translation<D>(1, s1), translation<D>(10, 0)});
    add_template<D>(s.x, "X3", box_mesh<D>(1, h3, 1), {translation<D>(9, s3)});
    std::ostringstream r;
    r << "Figure 4.7 chain: X1 (height " << h1 << ") | X2 at y=" << s1 << " (height " << h2
      << "); X3 (height " << h3 << ") at y=" << s3 << " | second X2";
    s.recipe = r.str();
    s.tier = Tier::templated_structure;
    return s;
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> rotational_slice_structure() {
  return rc::gen::exec([] {
    const int a = choose(2, 4);
    const bool two_regions = D == 2 && *rc::gen::arbitrary<bool>();
    const bool kite = !two_regions && D == 2 && *rc::gen::arbitrary<bool>();
    std::vector<Motion<D>> rot;
    for (int k = 0; k < 4; ++k) rot.push_back(quarter_turn<D>(k));
    GeneratedStructure<D> s;
    s.tier = Tier::valid_templated_mesh;
    if (two_regions) {
      const int b = choose(1, a - 1);
      add_template<D>(s.x, "inner", slice_mesh<D>(b, false), rot, 1);
      add_template<D>(s.x, "outer", slice_mesh<D>(a, false, b), rot, 2);
      s.recipe = "order-4 rotational slice of radius " + std::to_string(a) +
                 ", two regions split at " + std::to_string(b) + " (Figure 6.8)";
    } else {
      add_template<D>(s.x, "slice", slice_mesh<D>(a, kite), rot);
      s.recipe = std::string("order-4 rotational ") + (kite ? "kite " : "") + "slice of radius " +
                 std::to_string(a) + " (Figure 6.7)";
    }
    return s;
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> bpp_structure() {
  return rc::gen::exec([] {
    switch (choose(0, 6)) {
    case 0:
      return *self_contact_structure<D>();
    case 1:
      return *shifted_translation_structure<D>();
    case 2:
      return *indirect_chain_structure<D>();
    case 3:
      return *rotational_slice_structure<D>();
    default:
      return *templated_structure<D>();
    }
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> bpp_templated_mesh() {
  return rc::gen::exec([] {
    if (choose(0, 3) == 0) return *rotational_slice_structure<D>();
    return *valid_templated_mesh<D>();
  });
}

template <int D>
rc::Gen<Described<Motion<D>>> bpp_motion() {
  return rc::gen::exec([] {
    Described<Motion<D>> m{quarter_turn<D>(choose(0, 3)), ""};
    m.recipe = "quarter turns";
    if constexpr (D == 3) {
      const int w = choose(0, 2), a = choose(-1, 1), b = choose(-1, 1), c = choose(0, 2);
      if (w || a || b || c) {
        m.value =
            Motion<3>::rotation_quaternion(w, a, b, c, core::zero_point<Exact, 3>()) * m.value;
        m.recipe += "; quaternion (" + std::to_string(w) + "," + std::to_string(a) + "," +
                    std::to_string(b) + "," + std::to_string(c) + ")";
      }
    }
    if (*rc::gen::arbitrary<bool>()) {
      Point<D> n = core::zero_point<Exact, D>();
      for (int i = 0; i < D; ++i) n[i] = choose(-2, 2);
      if (n == core::zero_point<Exact, D>()) n[0] = 1;
      const Exact off = Exact(choose(-4, 4)) / 2;
      m.value = Motion<D>::reflection(n, off) * m.value;
      m.recipe += "; reflection n=" + text<D>(n) + " d=" + text(off);
    }
    Point<D> t = core::zero_point<Exact, D>();
    for (int i = 0; i < D; ++i) t[i] = Exact(choose(-6, 6)) / 3;
    m.value = Motion<D>::translation(t) * m.value;
    m.recipe += "; translation " + text<D>(t);
    return m;
  });
}

#define SYMMESH_BPP_GEN(D)                                                                         \
  template rc::Gen<GeneratedStructure<D>> self_contact_structure<D>();                             \
  template rc::Gen<GeneratedStructure<D>> shifted_translation_structure<D>();                      \
  template rc::Gen<GeneratedStructure<D>> indirect_chain_structure<D>(bool);                       \
  template rc::Gen<GeneratedStructure<D>> rotational_slice_structure<D>();                         \
  template rc::Gen<GeneratedStructure<D>> bpp_structure<D>();                                      \
  template rc::Gen<GeneratedStructure<D>> bpp_templated_mesh<D>();                                 \
  template rc::Gen<Described<Motion<D>>> bpp_motion<D>();
SYMMESH_BPP_GEN(2)
SYMMESH_BPP_GEN(3)

} // namespace symmesh::proofs::gen
