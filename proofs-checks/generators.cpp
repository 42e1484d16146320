// RapidCheck generators of the proofs-checks: triangulations and meshes (Lemmas 2.1–2.5),
// respect and geometry-conformity cases, the Delaunay counterexamples (Lemma 2.5 / 4.5) and the
// failure records (see generators.h for the tiers; building blocks in generator_support.h).
// GCC 12 false positives, silenced for the generator sources only: -Wmaybe-uninitialized inside
// CGAL's filtered weighted-point predicates and -Wrestrict in std::string concatenation (GCC bug
// 105329).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wrestrict"

#include "proofs-checks/structure_support.h"
#include "symmesh/io/svg.h"
#include "symmesh/io/templated_structure_json.h"

#include <nlohmann/json.hpp>

namespace symmesh::proofs::gen {

using namespace detail;

// =============================================================================================
// public generators
// =============================================================================================

std::string text(const Exact& x) {
  std::ostringstream os;
  os << CGAL::exact(x);
  return os.str();
}

template <int D>
std::string text(const Point<D>& p) {
  std::string s = "(";
  for (int d = 0; d < D; ++d) s += (d ? "," : "") + text(p[d]);
  return s + ")";
}

template <int D>
Complex<D> simplex_complex(const PointSet<D>& vertices) {
  Cell c;
  for (std::size_t i = 0; i < vertices.size(); ++i) c.push_back(VertexId(i));
  return complex_from_cells<D>(vertices, {c}, false);
}

template <int D>
rc::Gen<Described<Complex<D>>> delaunay_triangulation() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      const auto pts = random_point_set<D>(point_count(size, D));
      return Described<Complex<D>>{delaunay_of<D>(pts), "delaunay of " + points_text<D>(pts)};
    });
  });
}

template <int D>
rc::Gen<Described<Complex<D>>> regular_triangulation() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      const auto pts = random_point_set<D>(point_count(size, D));
      const auto w = random_weights(pts.size(), std::vector<bool>(pts.size(), false));
      const auto cells = regular_cells<D>(pts, w);
      std::string ws;
      for (int x : w) ws += std::to_string(x);
      if (cells.empty()) // cannot happen for full-dimensional points (extreme points stay)
        return Described<Complex<D>>{delaunay_of<D>(pts), "delaunay of " + points_text<D>(pts)};
      return Described<Complex<D>>{complex_from_cells<D>(pts, cells),
                                   "regular(w=" + ws + ") of " + points_text<D>(pts)};
    });
  });
}

template <int D>
rc::Gen<Described<Complex<D>>> triangulation() {
  return rc::gen::oneOf(delaunay_triangulation<D>(), regular_triangulation<D>());
}

namespace {
/// A sub-mesh of m: face completion of a random non-empty set of k-simplices of m.
template <int D>
Complex<D> random_submesh(const Complex<D>& m, int k) {
  std::vector<Cell> chosen;
  const auto all = m.elements_of_dimension(k);
  for (const auto& s : all)
    if (chance(50)) chosen.push_back(Cell(s.begin(), s.end()));
  if (chosen.empty()) chosen.push_back(Cell(all[0].begin(), all[0].end()));
  return complex_from_cells<D>(m.points, chosen);
}

/// The same complex over a reversed point array with one extra unused point, so that the pair
/// only compares equal after exact vertex identification (core::unify).
template <int D>
Complex<D> relabelled(const Complex<D>& m) {
  Complex<D> out;
  const std::size_t n = m.points.size();
  out.points.assign(m.points.rbegin(), m.points.rend());
  Point<D> extra = m.points[0];
  extra[0] += 17;
  out.points.push_back(extra);
  for (const auto& e : m.elements) {
    std::vector<VertexId> ids;
    for (VertexId v : e) ids.push_back(VertexId(n - 1 - v));
    out.elements.push_back(Simplex::from_range(ids.data(), ids.data() + ids.size()));
  }
  out.normalize();
  return out;
}
} // namespace

template <int D>
rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>> meshes_with_conforming_union() {
  return rc::gen::exec([] {
    const auto base = *triangulation<D>();
    const int k1 = chance(70) ? D : pick(1, D);
    const int k2 = chance(70) ? D : pick(1, D);
    const auto m1 = random_submesh<D>(base.value, k1);
    const auto m2 = relabelled<D>(random_submesh<D>(base.value, k2));
    return Described<std::pair<Complex<D>, Complex<D>>>{
        {m1, m2},
        "sub-meshes of dimension " + std::to_string(k1) + " and " + std::to_string(k2) +
            " (second relabelled) of " + base.recipe};
  });
}

namespace {
template <int D>
Described<std::pair<Complex<D>, Complex<D>>> figure_2_7() {
  const auto ab = random_simplex<D>(1);
  const int q = pick(2, 7);
  const Exact t = rational(pick(1, q - 1), q);
  const auto p = ab[0] + core::scaled<Exact, D>(ab[1] - ab[0], t);
  return {{simplex_complex<D>(ab), simplex_complex<D>({p})},
          "figure 2.7: line " + text<D>(ab[0]) + "-" + text<D>(ab[1]) +
              " and vertex at t=" + text(t)};
}

/// Two triangulations of one point set over the same (uncompacted) point array.
template <int D>
std::pair<Complex<D>, Complex<D>> two_triangulations(const PointSet<D>& pts, std::string* how) {
  const auto w = random_weights(pts.size(), std::vector<bool>(pts.size(), false));
  std::string ws;
  for (int x : w) ws += std::to_string(x);
  *how = "delaunay and regular(w=" + ws + ") of " + points_text<D>(pts);
  return {complex_from_cells<D>(pts, delaunay_cells<D>(pts), false),
          complex_from_cells<D>(pts, regular_cells<D>(pts, w), false)};
}
} // namespace

template <int D>
rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>> meshes_with_nonconforming_union() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      if (chance(50)) return figure_2_7<D>();
      const auto pts = random_point_set<D>(point_count(size, D) + 1);
      std::string how;
      const auto [a, b] = two_triangulations<D>(pts, &how);
      if (a.elements == b.elements || b.elements.empty()) return figure_2_7<D>();
      return Described<std::pair<Complex<D>, Complex<D>>>{{a, b}, "two triangulations: " + how};
    });
  });
}

template <int D>
rc::Gen<Described<Complex<D>>> nonconforming_complex() {
  return rc::gen::suchThat(rc::gen::withSize([](int size) {
                             return rc::gen::exec([size] {
                               const auto pts = random_point_set<D>(point_count(size, D) + 2);
                               std::string how;
                               const auto [a, b] = two_triangulations<D>(pts, &how);
                               auto u = core::set_union(a, b);
                               return Described<Complex<D>>{u, "element union of " + how};
                             });
                           }),
                           [](const Described<Complex<D>>& c) {
                             // the two triangulations differ (equal ones would give a conforming
                             // union)
                             return core::find_nonconformity(c.value).has_value();
                           });
}

template <int D>
rc::Gen<Described<Complex<D>>> non_face_complete_complex() {
  return rc::gen::exec([] {
    auto m = *triangulation<D>();
    const auto cells = m.value.cells();
    const auto& c = cells[pick(0, int(cells.size()) - 1)];
    const auto fs = core::facets(c);
    const auto f = fs[pick(0, int(fs.size()) - 1)];
    m.value.elements.erase(std::find(m.value.elements.begin(), m.value.elements.end(), f));
    m.recipe += "; one facet of a cell removed";
    return m;
  });
}

template <int D>
rc::Gen<Described<MultiRegion<D>>> multi_region_mesh() {
  return rc::gen::exec([] {
    const auto m = *triangulation<D>();
    MultiRegion<D> mr;
    mr.mesh = m.value;
    const bool by_side = chance(50);
    const auto n = small_vector<D>(-2, 2);
    const Exact d = grid_value(0, 8);
    for (const auto& c : m.value.cells())
      mr.cell_region[c] = by_side
                              ? (core::dot<Exact, D>(n, centroid<D>(m.value.coords(c))) < d ? 1 : 2)
                              : pick(1, 3);
    return Described<MultiRegion<D>>{
        mr, m.recipe + (by_side ? "; regions by side of n=" + text<D>(n) + ", d=" + text(d)
                                : "; random regions")};
  });
}

template <int D>
rc::Gen<Described<MultiRegion<D>>> nonconforming_multi_region() {
  return rc::gen::exec([] {
    const auto m = *nonconforming_complex<D>();
    MultiRegion<D> mr;
    mr.mesh = m.value;
    for (const auto& c : m.value.cells()) mr.cell_region[c] = pick(1, 3);
    const auto bad = core::find_nonconformity(m.value);
    for (auto& [c, r] : mr.cell_region)
      if (bad && (bad->a.is_face_of(c) || bad->b.is_face_of(c))) r = 1;
    return Described<MultiRegion<D>>{mr,
                                     m.recipe + "; random regions, the violating pair in region 1"};
  });
}

// ----- respect (Lemma 2.3)
// ------------------------------------------------------------------------

namespace {
/// A convex set designed to meet e in a union of faces (or to contain / avoid it), or a random one.
template <int D>
std::pair<PointSet<D>, std::string> convex_set_near(const PointSet<D>& e) {
  const auto c = centroid<D>(e);
  switch (pick(0, 4)) {
  case 0: { // contains e
    PointSet<D> a;
    for (const auto& v : e) a.push_back(c + core::scaled<Exact, D>(v - c, Exact(2)));
    if (chance(50)) a.push_back(c + small_vector<D>(-3, 3));
    return {a, "containing"};
  }
  case 1: { // far away
    PointSet<D> a;
    Point<D> shift = core::zero_point<Exact, D>();
    shift[0] = 20;
    for (const auto& v : e) a.push_back(v + shift);
    return {a, "disjoint"};
  }
  case 2:
  case 3: { // meets e exactly in a face F: point reflection of the other vertices through F
    std::vector<int> in;
    for (std::size_t i = 0; i < e.size(); ++i)
      if (chance(50)) in.push_back(int(i));
    if (in.empty()) in.push_back(0);
    PointSet<D> f;
    for (int i : in) f.push_back(e[i]);
    const auto cf = centroid<D>(f);
    PointSet<D> a = f;
    for (std::size_t i = 0; i < e.size(); ++i)
      if (std::find(in.begin(), in.end(), int(i)) == in.end())
        a.push_back(core::scaled<Exact, D>(cf, Exact(2)) - e[i]);
    return {a, "touching a " + std::to_string(in.size() - 1) + "-face"};
  }
  default: {
    PointSet<D> a;
    const int n = pick(1, D + 1);
    for (int k = 0; k < n; ++k) {
      Coords<D> q;
      for (int d = 0; d < D; ++d) q[d] = grid_value(-1, 5);
      a.push_back(make_point<D>(q));
    }
    return {a, "random"};
  }
  }
}
} // namespace

template <int D>
rc::Gen<Described<RespectCase<D>>> respect_both() {
  return rc::gen::suchThat(rc::gen::exec([] {
                             const auto e = random_simplex<D>(pick(1, D));
                             const auto [a, ka] = convex_set_near<D>(e);
                             const auto [b, kb] = convex_set_near<D>(e);
                             return Described<RespectCase<D>>{
                                 {e, a, b},
                                 "E=" + points_text<D>(e) + " A(" + ka + ")=" + points_text<D>(a) +
                                     " B(" + kb + ")=" + points_text<D>(b)};
                           }),
                           [](const Described<RespectCase<D>>& r) {
                             return core::respects<Exact, D>(r.value.e, {r.value.a}) &&
                                    core::respects<Exact, D>(r.value.e, {r.value.b});
                           });
}

template <int D>
rc::Gen<Described<RespectCase<D>>> respect_one_only() {
  return rc::gen::exec([] {
    const auto e = random_simplex<D>(pick(1, D));
    const auto c = centroid<D>(e);
    PointSet<D> a;
    for (const auto& v : e) a.push_back(c + core::scaled<Exact, D>(v - c, Exact(2)));
    const auto m = cutting_normal<D>(e);
    const auto b = half_space_simplex<D>(c, m);
    return Described<RespectCase<D>>{
        {e, a, b},
        "E=" + points_text<D>(e) + " A(containing)=" + points_text<D>(a) +
            " B(cut through centroid, m=" + text<D>(m) + ")=" + points_text<D>(b)};
  });
}

// ----- geometry conformity (Lemma 2.4)
// -------------------------------------------------------------

template <int D>
rc::Gen<Described<GeometryCase<D>>> geometry_conforming_case() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      GeometryCase<D> g;
      std::string how;
      {
        g.points = random_point_set<D>(point_count(size, D));
        const auto [a, b] = two_triangulations<D>(g.points, &how);
        const bool swap = chance(50);
        g.mesh = complex_from_cells<D>(g.points, cells_of<D>(swap ? b : a));
        g.other_mesh = complex_from_cells<D>(g.points, cells_of<D>(swap ? a : b));
        how += swap ? " (M regular)" : " (M delaunay)";
      }
      auto o = *reflections_impl<D>(1, 1, false);
      // two regions, region(G, 1) = conv(template points), region(G, 2) = its mirror image
      o.s.x.instances[0][0].region = 1;
      o.s.x.instances[0][1].region = 2;
      const auto si = core::apply_template(o.s.x);
      g.multi = si.at;
      const auto& tmpl = o.s.x.templates[0].mesh;
      PointSet<D> mirrored;
      for (const auto& p : tmpl.points) mirrored.push_back(o.s.x.instances[0][1].transformation(p));
      g.region_ids = {1, 2};
      g.region_hulls = {tmpl.points, mirrored};
      return Described<GeometryCase<D>>{g, "M, M' = " + how + "; multi-region: " + o.s.recipe};
    });
  });
}

template <int D>
rc::Gen<Described<NonConformingGeometryCase<D>>> geometry_not_conforming_case() {
  return rc::gen::exec([] {
    const auto m = *triangulation<D>();
    const auto cells = m.value.cells();
    const auto& c = cells[pick(0, int(cells.size()) - 1)];
    const auto cv = m.value.coords(c);
    const auto n = cutting_normal<D>(cv);
    NonConformingGeometryCase<D> g;
    g.mesh = m.value;
    g.points = m.value.points;
    g.cut = half_space_simplex<D>(centroid<D>(cv), n);
    return Described<NonConformingGeometryCase<D>>{
        g,
        m.recipe + "; G cut by the hyperplane through a cell centroid with normal " + text<D>(n)};
  });
}

// ----- Delaunay counterexamples (Lemma 2.5 / 4.5)
// ---------------------------------------------------

namespace {
/// A flat simplex on the positive side of x_{D-1} >= 0 with its base facet in x_{D-1} = 0.
/// Returns the vertices (base first, apex last) and the squared "margin" R0^2 - |a - c0|^2 of
/// the apex foot a inside the base circumsphere.
template <int D>
PointSet<D> flat_simplex(int L, Exact h);

template <>
PointSet<2> flat_simplex<2>(int L, Exact h) {
  return {make_point<2>({Exact(-L), Exact(0)}), make_point<2>({Exact(L), Exact(0)}),
          make_point<2>({Exact(0), h})};
}
template <>
PointSet<3> flat_simplex<3>(int L, Exact h) {
  // base on the circle of radius L about the origin, apex above (0, L/3)
  return {
      make_point<3>({Exact(-L), Exact(0), Exact(0)}), make_point<3>({Exact(L), Exact(0), Exact(0)}),
      make_point<3>({Exact(0), Exact(L), Exact(0)}), make_point<3>({Exact(0), rational(L, 3), h})};
}
/// The largest h = 1/q (q >= 3) with h^2 below the apex foot's margin (so the apex is strictly
/// inside the base facet's diametral ball: the facet is encroached).
template <int D>
Exact flat_height(int L) {
  const Exact foot2 = D == 2 ? Exact(0) : rational(L * L, 9);
  const Exact margin = Exact(L * L) - foot2;
  int q = pick(3, 6);
  while (!(rational(1, q * q) < margin)) ++q;
  return rational(1, q);
}
} // namespace

template <int D>
rc::Gen<GeneratedStructure<D>> flat_simplex_v_shape() {
  return rc::gen::exec([] {
    const int L = pick(2, 4);
    const Exact h = flat_height<D>(L);
    const auto v = flat_simplex<D>(L, h);
    // reflecting hyperplane through the vertex (L, 0, ...) tilted by slope s: normal (-s, 0.., 1)
    const Exact s = rational(1, pick(4, 9));
    Point<D> n = core::zero_point<Exact, D>();
    n[0] = -s;
    n[D - 1] = 1;
    const Exact d = core::dot<Exact, D>(n, v[1]);
    const auto mesh = simplex_complex<D>(v);
    GeneratedStructure<D> g;
    g.x = single_template<D>(mesh, {Motion<D>(), Motion<D>::reflection(n, d)}, {1, pick(1, 2)});
    g.tier = Tier::valid_templated_mesh;
    g.convex = false;
    g.recipe = "flat simplex L=" + std::to_string(L) + " h=" + text(h) +
               " reflected across the hyperplane through " + text<D>(v[1]) + " with normal " +
               text<D>(n);
    return maybe_moved<D>(g, 50);
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> encroached_reflection() {
  return rc::gen::exec([] {
    const int L = pick(2, 4);
    const Exact h = flat_height<D>(L);
    const auto v = flat_simplex<D>(L, h);
    Point<D> n = core::zero_point<Exact, D>();
    n[D - 1] = 1;
    GeneratedStructure<D> g;
    g.x = single_template<D>(simplex_complex<D>(v),
                             {Motion<D>(), Motion<D>::reflection(n, Exact(0))}, {1, pick(1, 2)});
    g.tier = Tier::valid_templated_mesh;
    g.convex = true;
    g.recipe = "flat simplex L=" + std::to_string(L) + " h=" + text(h) +
               " reflected across its base facet";
    return maybe_moved<D>(g, 50);
  });
}

/// Four tetrahedra around the axis a b = (p, 0, h), (p, 0, -k) of an octahedron over the ring
/// c0..c3 = (x0, 0, 0), (0, y1, 0), c2, (0, -y3, 0) (vertex ids 0..5). Convex: p = 0 and
/// c2 = (-x2, 0, 0); reflex: 0 < c2 = (r, 0, 0) < p < x0, so the ring's diagonal c1 c3 (x = 0)
/// leaves it and only c0 c2 may be flipped to. Instanced as is and reflected: across its face
/// (a, c0, c1) when convex (the copies share that face), across z = h when reflex (they share a).
rc::Gen<GeneratedStructure<3>> four_tetrahedra_around_an_axis(bool reflex) {
  return rc::gen::exec([reflex] {
    const Exact x0(pick(2, 4)), y1 = rational(pick(1, 6), 2), y3 = rational(pick(1, 6), 2);
    const Exact h = rational(pick(1, 6), 2), k = rational(pick(1, 6), 2);
    const Exact p = reflex ? Exact(1) : Exact(0);
    const Exact c2 = reflex ? rational(1, pick(2, 4)) : -Exact(pick(1, 4));
    const std::vector<Point<3>> pts{
        make_point<3>({p, Exact(0), h}),         make_point<3>({p, Exact(0), -k}),
        make_point<3>({x0, Exact(0), Exact(0)}), make_point<3>({Exact(0), y1, Exact(0)}),
        make_point<3>({c2, Exact(0), Exact(0)}), make_point<3>({Exact(0), -y3, Exact(0)})};
    std::vector<Cell> cells;
    for (core::VertexId j = 0; j < 4; ++j) cells.push_back({0, 1, 2 + j, 2 + (j + 1) % 4});
    const auto mesh = complex_from_cells<3>(pts, cells, false);
    Point<3> n = core::zero_point<Exact, 3>();
    Exact d(0);
    if (reflex) {
      n[2] = 1;
      d = h;
    } else {
      const auto u = pts[2] - pts[0], v = pts[3] - pts[0];
      n[0] = u[1] * v[2] - u[2] * v[1];
      n[1] = u[2] * v[0] - u[0] * v[2];
      n[2] = u[0] * v[1] - u[1] * v[0];
      d = core::dot<Exact, 3>(n, pts[0]);
    }
    GeneratedStructure<3> g;
    g.x = single_template<3>(mesh, {Motion<3>(), Motion<3>::reflection(n, d)}, {1, 1});
    g.tier = Tier::valid_templated_mesh;
    g.recipe = std::string(reflex ? "reflex" : "convex") +
               " octahedron of four tetrahedra around " + text<3>(pts[0]) + "-" + text<3>(pts[1]) +
               ", ring x0=" + text(x0) + " y1=" + text(y1) + " c2=" + text(c2) + " y3=" + text(y3);
    return g;
  });
}

rc::Gen<GeneratedStructure<2>> acute_wedge() {
  return rc::gen::exec([] {
    const Exact p = rational(pick(5, 10), 10), q = p * rational(pick(1, 9), 10);
    const std::vector<Point<2>> pts{make_point<2>({Exact(0), Exact(0)}),
                                    make_point<2>({Exact(1), Exact(0)}), make_point<2>({p, q})};
    const auto mesh = complex_from_cells<2>(pts, {{0, 1, 2}}, false);
    Point<2> along_x = core::zero_point<Exact, 2>(), along_w = core::zero_point<Exact, 2>();
    along_x[1] = 1;
    along_w[0] = -q;
    along_w[1] = p;
    GeneratedStructure<2> g;
    g.x = single_template<2>(mesh,
                             {Motion<2>(), Motion<2>::reflection(along_x, Exact(0)),
                              Motion<2>::reflection(along_w, Exact(0))},
                             {1, 1, 1});
    g.tier = Tier::valid_templated_mesh;
    g.convex = false;
    g.recipe =
        "triangle (0,0) (1,0) " + text<2>(pts[2]) + " reflected across both legs at the origin";
    return g;
  });
}

// ----- failure records ---------------------------------------------------------------------------

namespace {
/// The io layer's JSON text as a JSON value (kept as a string should it not parse).
nlohmann::json embedded(const std::string& text) {
  try {
    return nlohmann::json::parse(text);
  } catch (const std::exception&) {
    return text;
  }
}
} // namespace

template <int D>
std::string structure_record(const std::string& lemma, const std::string& recipe,
                             const Structure<D>& x) {
  // The templated-structure format itself, so that `symmesh check FILE` reads the counterexample.
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(io::to_json(x));
  j["description"] = "counterexample of " + lemma + " (" + recipe + ")";
  return j.dump(1);
}

template <int D>
std::string structure_picture(const Structure<D>& x) {
  if constexpr (D == 2)
    return io::structure_svg(x);
  else
    return std::string();
}

template <int D>
std::string complexes_record(const std::string& lemma, const std::string& recipe,
                             const std::vector<std::pair<std::string, Complex<D>>>& parts) {
  nlohmann::json j;
  j["lemma"] = lemma;
  j["recipe"] = recipe;
  for (const auto& [name, c] : parts) j["complexes"][name] = embedded(io::complex_to_json(c));
  return j.dump(1);
}

template <int D>
std::string complex_picture(const Complex<D>& c) {
  if constexpr (D == 2)
    return io::complex_svg(c);
  else
    return std::string();
}

// ----- explicit instantiations
// --------------------------------------------------------------------

#define SYMMESH_INSTANTIATE_GENERATORS(D)                                                          \
  template std::string text<D>(const Point<D>&);                                                   \
  template Complex<D> simplex_complex<D>(const PointSet<D>&);                                      \
  template std::string structure_record<D>(const std::string&, const std::string&,                 \
                                           const Structure<D>&);                                   \
  template std::string structure_picture<D>(const Structure<D>&);                                  \
  template std::string complexes_record<D>(                                                        \
      const std::string&, const std::string&,                                                      \
      const std::vector<std::pair<std::string, Complex<D>>>&);                                     \
  template std::string complex_picture<D>(const Complex<D>&);                                      \
  template rc::Gen<Described<Complex<D>>> triangulation<D>();                                      \
  template rc::Gen<Described<Complex<D>>> delaunay_triangulation<D>();                             \
  template rc::Gen<Described<Complex<D>>> regular_triangulation<D>();                              \
  template rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>>                                   \
  meshes_with_conforming_union<D>();                                                               \
  template rc::Gen<Described<std::pair<Complex<D>, Complex<D>>>>                                   \
  meshes_with_nonconforming_union<D>();                                                            \
  template rc::Gen<Described<Complex<D>>> nonconforming_complex<D>();                              \
  template rc::Gen<Described<Complex<D>>> non_face_complete_complex<D>();                          \
  template rc::Gen<Described<MultiRegion<D>>> multi_region_mesh<D>();                              \
  template rc::Gen<Described<MultiRegion<D>>> nonconforming_multi_region<D>();                     \
  template rc::Gen<Described<RespectCase<D>>> respect_both<D>();                                   \
  template rc::Gen<Described<RespectCase<D>>> respect_one_only<D>();                               \
  template rc::Gen<Described<GeometryCase<D>>> geometry_conforming_case<D>();                      \
  template rc::Gen<Described<NonConformingGeometryCase<D>>> geometry_not_conforming_case<D>();     \
  template rc::Gen<GeneratedStructure<D>> flat_simplex_v_shape<D>();                               \
  template rc::Gen<GeneratedStructure<D>> encroached_reflection<D>();

SYMMESH_INSTANTIATE_GENERATORS(2)
SYMMESH_INSTANTIATE_GENERATORS(3)

} // namespace symmesh::proofs::gen
