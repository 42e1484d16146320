/// Templated-structure building blocks of the proofs-checks generators (internal): templates from
/// complexes, region splits, the reflective (Lemmas 6.1, 6.2) and translation families, encroached
/// facets (Lemma 4.5) and single simplices — spec/traceability.md#lemma-to-proofs-checks
#pragma once
#include "proofs-checks/generator_support.h"

namespace symmesh::proofs::gen::detail {

// ----- templated structures --------------------------------------------------------------------

template <int D>
core::Template<Exact, D> make_template(const Complex<D>& mesh, const std::string& name) {
  core::Template<Exact, D> t;
  t.name = name;
  t.kind = core::TemplateKind::mesh;
  t.mesh = mesh;
  return t;
}

template <int D>
Structure<D> single_template(const Complex<D>& mesh, const std::vector<Motion<D>>& tfs,
                             const std::vector<int>& regions) {
  Structure<D> x;
  x.templates.push_back(make_template<D>(mesh, "X1"));
  x.instances.emplace_back();
  for (std::size_t g = 0; g < tfs.size(); ++g)
    x.instances[0].push_back(core::InstanceSpec<Exact, D>{tfs[g], regions[g]});
  return x;
}

inline std::vector<int> random_regions(std::size_t n) {
  std::vector<int> r;
  const bool same = chance(50);
  for (std::size_t i = 0; i < n; ++i) r.push_back(same ? 1 : pick(1, 2));
  return r;
}

/// Splits template 0 into 2-3 templates by the side of each cell centroid with respect to
/// random hyperplanes (Figure 4.3's multi-template shape); all keep the same instances.
template <int D>
GeneratedStructure<D> split_template(GeneratedStructure<D> s) {
  const auto& base = s.x.templates[0].mesh;
  const auto cells = base.cells();
  if (cells.size() < 2) return s;
  const auto m = small_vector<D>(-2, 2);
  std::vector<Exact> key;
  for (const auto& c : cells) key.push_back(core::dot<Exact, D>(m, centroid<D>(base.coords(c))));
  auto sorted = key;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  if (sorted.size() < 2) return s;
  const int parts = sorted.size() >= 3 && chance(40) ? 3 : 2;
  std::vector<Exact> cuts;
  const int first = pick(1, int(sorted.size()) - parts + 1);
  cuts.push_back(sorted[first]);
  if (parts == 3) cuts.push_back(sorted[pick(first + 1, int(sorted.size()) - 1)]);
  std::vector<std::vector<Cell>> groups(parts);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    int g = 0;
    while (g < int(cuts.size()) && !(key[k] < cuts[g])) ++g;
    groups[g].push_back(Cell(cells[k].begin(), cells[k].end()));
  }
  const auto inst = s.x.instances[0];
  const bool own_regions = chance(50);
  Structure<D> x;
  for (int g = 0; g < parts; ++g) {
    if (groups[g].empty()) continue;
    x.templates.push_back(make_template<D>(complex_from_cells<D>(base.points, groups[g]),
                                           "X1" + std::string(1, char('a' + g))));
    auto list = inst;
    if (own_regions)
      for (auto& spec : list) spec.region = g + 1;
    x.instances.push_back(list);
  }
  for (std::size_t i = 1; i < s.x.templates.size(); ++i) {
    x.templates.push_back(s.x.templates[i]);
    x.instances.push_back(s.x.instances[i]);
  }
  s.x = x;
  s.recipe += "; split into " + std::to_string(parts) + " templates by m=" + text<D>(m);
  return s;
}

// ----- reflective families (Lemma 6.1, 6.2) ----------------------------------------------------

/// Template points in frame coordinates c_0 >= 0: several exactly on c_0 = 0, only one, none,
/// or the corners of a frame box (then the template and AT are convex).
template <int D>
struct HalfSpacePoints {
  PointSet<D> pts;
  std::vector<bool> on_hull;
  std::string mode;
};

template <int D>
HalfSpacePoints<D> half_space_points(const Frame<D>& f, int size, int orthant_axes, bool convex) {
  HalfSpacePoints<D> out;
  std::vector<Coords<D>> cs;
  std::vector<bool> hull;
  auto add = [&](const Coords<D>& c, bool h) {
    cs.push_back(c);
    hull.push_back(h);
  };
  std::array<int, D> extent;
  for (int j = 0; j < D; ++j) extent[j] = pick(2, 3);
  auto lo = [&](int j) { return j < orthant_axes ? 0 : -extent[j]; };
  if (convex && D == 2) {
    // a frame box in the orthant: AT (the box and its mirror images) is a box again
    out.mode = "box";
    for (int mask = 0; mask < (1 << D); ++mask) {
      Coords<D> c;
      for (int j = 0; j < D; ++j) c[j] = (mask >> j) & 1 ? Exact(extent[j]) : Exact(lo(j));
      add(c, true);
    }
    const int on_sides = pick(0, 1 + size / 40);
    for (int k = 0; k < on_sides; ++k) {
      Coords<D> c;
      const int j = pick(0, D - 1);
      for (int i = 0; i < D; ++i) c[i] = i == j ? Exact(lo(i)) : inner_value(lo(i), extent[i]);
      add(c, true);
    }
    const int interior = pick(0, std::min(2, size / 30));
    for (int k = 0; k < interior; ++k) {
      Coords<D> c;
      for (int i = 0; i < D; ++i) c[i] = inner_value(lo(i), extent[i]);
      add(c, false);
    }
  } else if (convex) {
    // the orthant corner simplex: its images under the reflections form a convex cross-polytope
    out.mode = "corner simplex";
    Coords<D> o{};
    for (int j = 0; j < D; ++j) o[j] = 0;
    add(o, true);
    for (int j = 0; j < D; ++j) {
      Coords<D> c = o;
      c[j] = extent[j];
      add(c, true);
    }
    if (size > 30 && chance(40)) {
      Coords<D> c;
      for (int j = 0; j < D; ++j) c[j] = rational(extent[j], 4);
      add(c, false);
    }
  } else {
    const int mode = pick(0, 9);
    const int on_plane =
        mode < 7 ? D + (D == 2 ? pick(0, 2) : pick(0, size / 60)) : (mode < 9 ? 1 : 0);
    out.mode = on_plane == 0 ? "none on H" : (on_plane == 1 ? "one on H" : "several on H");
    for (int k = 0; k < on_plane; ++k) {
      Coords<D> c;
      for (int i = 0; i < D; ++i) c[i] = i == 0 ? Exact(0) : grid_value(lo(i), extent[i]);
      for (int i = 1; i < orthant_axes; ++i) // further orthant hyperplanes get points too
        if (chance(40)) c[i] = 0;
      add(c, true);
    }
    // off H (c_0 > 0 unless several points are on H anyway)
    const int off = (on_plane >= D ? 1 : D + 1 - on_plane) +
                    pick(0, D == 2 ? std::min(3, size / 25) : size / 50);
    for (int k = 0; k < off; ++k) {
      Coords<D> c;
      for (int i = 0; i < D; ++i) c[i] = grid_value(lo(i), extent[i]);
      if (c[0] == 0 && on_plane < D) c[0] = 1;
      bool h = c[0] == 0;
      for (int i = 1; i < orthant_axes; ++i) h = h || c[i] == 0;
      add(c, h);
    }
  }
  // dedupe, keeping each point's hull flag (hull points keep weight 0: never hidden)
  std::set<Point<D>, core::PointLess<Exact, D>> seen;
  for (std::size_t k = 0; k < cs.size(); ++k) {
    const auto p = f.at(cs[k]);
    if (!seen.insert(p).second) continue;
    out.pts.push_back(p);
    out.on_hull.push_back(hull[k]);
  }
  return out;
}

/// All 2^k compositions of the reflections, in the order of Algorithm 6.4.
template <int D>
std::vector<Motion<D>> reflection_group(const std::vector<Motion<D>>& refl) {
  std::vector<Motion<D>> t{Motion<D>(), refl[0]};
  for (std::size_t i = 1; i < refl.size(); ++i) {
    const std::size_t n = t.size();
    for (std::size_t k = 0; k < n; ++k) t.push_back(t[k] * refl[i]);
  }
  return t;
}

template <int D>
rc::Gen<OrthogonalReflections<D>> reflections_impl(int min_k, int max_k, bool force_box) {
  return rc::gen::withSize([=](int size) {
    return rc::gen::exec([=] {
      for (int attempt = 0;; ++attempt) {
        const auto f = random_frame<D>();
        const int k = pick(min_k, max_k);
        // convex ones are full-dimensional; in 3D, 8 instances only of the corner simplex
        const bool box = force_box || attempt >= 5 || chance(35) || (D == 3 && k == 3);
        const auto hp = half_space_points<D>(f, size, k, box);
        if (!full_dimensional<D>(hp.pts)) continue;
        const auto [cells, how] = some_triangulation<D>(hp.pts, hp.on_hull);
        if (cells.empty()) continue;
        OrthogonalReflections<D> o;
        std::vector<Motion<D>> refl;
        for (int j = 0; j < k; ++j) {
          refl.push_back(f.reflection(j, 0));
          o.normals.push_back(f.axis[j]);
          o.offsets.push_back(f.offset(j, 0));
        }
        const auto tfs = reflection_group<D>(refl);
        const auto mesh = complex_from_cells<D>(hp.pts, cells);
        o.s.x = single_template<D>(mesh, tfs, random_regions(tfs.size()));
        o.s.tier = Tier::valid_templated_mesh;
        o.s.convex = box;
        o.s.recipe = std::to_string(k) + " orthogonal reflection(s) in " + f.text + ", " + hp.mode +
                     ", " + how + " of " + points_text<D>(hp.pts);
        return o;
      }
    });
  });
}

// ----- translation families --------------------------------------------------------------------

/// Values strictly inside (0, extent) for the subdivision of a box side.
inline std::vector<Exact> side_values(int extent, int max_count) {
  std::vector<Exact> v;
  const int n = pick(0, max_count);
  for (int k = 0; k < n; ++k) v.push_back(inner_value(0, extent));
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

/// A different subdivision: add a value that is not yet there, or drop one.
inline std::vector<Exact> different_side_values(std::vector<Exact> v, int extent) {
  if (!v.empty() && chance(30)) {
    v.erase(v.begin() + pick(0, int(v.size()) - 1));
    return v;
  }
  Exact x = inner_value(0, extent) + (chance(50) ? rational(1, 4) : Exact(0));
  if (!(x < Exact(extent))) x = rational(extent, 2);
  while (std::find(v.begin(), v.end(), x) != v.end()) x = (x + extent) / 2; // stays in (0, extent)
  v.push_back(x);
  std::sort(v.begin(), v.end());
  return v;
}

inline std::string values_text(const std::vector<Exact>& v) {
  std::string s = "{";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + text(v[i]);
  return s + "}";
}

/// Translations k_j * extent_j * axis_j over a small grid with at least two instances.
template <int D>
std::pair<std::vector<Motion<D>>, std::string> grid_translations(const Frame<D>& f,
                                                                 const std::array<int, D>& ext,
                                                                 int max_instances, int only_axis) {
  std::array<int, D> n;
  int total = 1;
  for (int j = 0; j < D; ++j) {
    n[j] = only_axis < 0 || only_axis == j ? pick(1, 3) : 1;
    if (total * n[j] > max_instances) n[j] = std::max(1, max_instances / total);
    total *= n[j];
  }
  if (total < 2) {
    const int j = only_axis < 0 ? 0 : only_axis;
    total = total / n[j] * 2;
    n[j] = 2;
  }
  std::vector<Motion<D>> t;
  for (int idx = 0; idx < total; ++idx) {
    int r = idx;
    Point<D> v = core::zero_point<Exact, D>();
    for (int j = 0; j < D; ++j) {
      v = v + core::scaled<Exact, D>(f.axis[j], Exact((r % n[j]) * ext[j]));
      r /= n[j];
    }
    t.push_back(Motion<D>::translation(v));
  }
  std::string s = "grid ";
  for (int j = 0; j < D; ++j) s += (j ? "x" : "") + std::to_string(n[j]);
  return {t, s};
}

/// 2D box template [0,W]x[0,H]: side subdivisions `left`, `right` (x = 0, W), `bottom`, `top`,
/// interior points, Delaunay or regular triangulation (boundary points keep weight 0).
inline Complex<2> box_template_2d(const Frame<2>& f, const std::array<int, 2>& e,
                                  const std::vector<Exact>& left, const std::vector<Exact>& right,
                                  const std::vector<Exact>& bottom, const std::vector<Exact>& top,
                                  int interior, bool delaunay_only, std::string* how) {
  PointSet<2> pts;
  std::vector<bool> hull;
  auto add = [&](const Exact& a, const Exact& b, bool h) {
    pts.push_back(f.at({a, b}));
    hull.push_back(h);
  };
  add(0, 0, true);
  add(e[0], 0, true);
  add(0, e[1], true);
  add(e[0], e[1], true);
  for (const auto& y : left) add(0, y, true);
  for (const auto& y : right) add(e[0], y, true);
  for (const auto& x : bottom) add(x, 0, true);
  for (const auto& x : top) add(x, e[1], true);
  for (int k = 0; k < interior; ++k) add(inner_value(0, e[0]), inner_value(0, e[1]), false);
  auto u = dedupe<2>(pts);
  std::vector<bool> uh;
  for (const auto& p : u) uh.push_back(hull[std::find(pts.begin(), pts.end(), p) - pts.begin()]);
  if (delaunay_only) {
    *how = "delaunay";
    return complex_from_cells<2>(u, delaunay_cells<2>(u));
  }
  auto [cells, h] = some_triangulation<2>(u, uh);
  *how = h;
  return complex_from_cells<2>(u, cells);
}

/// 3D box template [0,e0]x[0,e1]x[0,e2] triangulated without extra points:
///  - Kuhn (Freudenthal) subdivision, 6 tetrahedra around the main diagonal: opposite faces carry
///    translated diagonals, so every grid translation is conforming;
///  - the 5-tetrahedron subdivision (a central tetrahedron on alternate corners): opposite faces
///    carry crossing diagonals, so a translated copy meets it non-conformingly (Figure 4.4 in 3D).
inline Complex<3> cube_template(const Frame<3>& f, const std::array<int, 3>& e, bool kuhn) {
  PointSet<3> pts;
  for (int mask = 0; mask < 8; ++mask) {
    Coords<3> c;
    for (int j = 0; j < 3; ++j) c[j] = (mask >> j) & 1 ? Exact(e[j]) : Exact(0);
    pts.push_back(f.at(c));
  }
  std::vector<Cell> cells;
  if (kuhn) {
    int perm[3] = {0, 1, 2};
    do {
      Cell c{0};
      int mask = 0;
      for (int k = 0; k < 3; ++k) {
        mask |= 1 << perm[k];
        c.push_back(VertexId(mask));
      }
      cells.push_back(c);
    } while (std::next_permutation(perm, perm + 3));
  } else {
    // central tetrahedron 0, 3, 5, 6 (alternate corners) and the four corners cut off
    cells = {{0, 3, 5, 6}, {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}};
  }
  return complex_from_cells<3>(pts, cells);
}

template <int D>
rc::Gen<GeneratedStructure<D>> translation_impl(bool conforming, bool delaunay_only);

template <>
inline rc::Gen<GeneratedStructure<2>> translation_impl<2>(bool conforming, bool delaunay_only) {
  return rc::gen::withSize([=](int size) {
    return rc::gen::exec([=] {
      const auto f = random_frame<2>();
      const std::array<int, 2> e{pick(2, 4), pick(2, 4)};
      const int max_side = 1 + size / 50;
      const auto left = side_values(e[1], max_side);
      const auto bottom = side_values(e[0], max_side);
      const auto right = conforming ? left : different_side_values(left, e[1]);
      const auto top = bottom;
      std::string how;
      const int interior = pick(0, std::min(3, size / 30));
      const auto mesh =
          box_template_2d(f, e, left, right, bottom, top, interior, delaunay_only, &how);
      const auto [tfs, grid] =
          grid_translations<2>(f, e, conforming ? 2 + size / 50 : 3, conforming ? -1 : 0);
      GeneratedStructure<2> s;
      s.x = single_template<2>(mesh, tfs, random_regions(tfs.size()));
      s.tier = conforming ? Tier::valid_templated_mesh : Tier::templated_structure;
      s.convex = true;
      s.recipe = std::string(conforming ? "translation " : "figure 4.4 translation ") + grid +
                 " of box " + std::to_string(e[0]) + "x" + std::to_string(e[1]) + " in " + f.text +
                 ", left " + values_text(left) + " right " + values_text(right) + " bottom/top " +
                 values_text(bottom) + ", " + how + " with " + std::to_string(interior) +
                 " interior";
      return s;
    });
  });
}

/// Triangular prism over (0,0), (e0,0), (0,e1) extruded along axis 2 by e2, in 3 tetrahedra;
/// its top face is the translated bottom face, so stacking along axis 2 is conforming.
inline Complex<3> prism_template(const Frame<3>& f, const std::array<int, 3>& e) {
  PointSet<3> pts;
  for (int z = 0; z < 2; ++z) {
    const Exact h = z ? Exact(e[2]) : Exact(0);
    pts.push_back(f.at({Exact(0), Exact(0), h}));
    pts.push_back(f.at({Exact(e[0]), Exact(0), h}));
    pts.push_back(f.at({Exact(0), Exact(e[1]), h}));
  }
  return complex_from_cells<3>(pts, {{0, 1, 2, 5}, {0, 1, 4, 5}, {0, 3, 4, 5}});
}

/// Square pyramid (base square in c_2 = 0 split by one diagonal, apex above) in 2 tetrahedra.
inline Complex<3> pyramid_template(const Frame<3>& f, int e, int h) {
  const PointSet<3> pts = {
      f.at({Exact(0), Exact(0), Exact(0)}), f.at({Exact(e), Exact(0), Exact(0)}),
      f.at({Exact(0), Exact(e), Exact(0)}), f.at({Exact(e), Exact(e), Exact(0)}),
      f.at({rational(e, 2), rational(e, 2), Exact(h)})};
  return complex_from_cells<3>(pts, {{0, 1, 3, 4}, {0, 3, 2, 4}});
}

template <>
inline rc::Gen<GeneratedStructure<3>> translation_impl<3>(bool conforming, bool /*delaunay_only*/) {
  return rc::gen::withSize([=](int size) {
    return rc::gen::exec([=] {
      const auto f = random_frame<3>();
      const std::array<int, 3> e{pick(1, 3), pick(1, 3), pick(1, 3)};
      GeneratedStructure<3> s;
      s.tier = conforming ? Tier::valid_templated_mesh : Tier::templated_structure;
      std::ostringstream os;
      if (conforming && (size < 60 || chance(60))) {
        // a stack of prisms along axis 2 (2 or 3 instances)
        const int n = size < 50 ? 2 : pick(2, 3);
        std::vector<Motion<3>> tfs;
        for (int k = 0; k < n; ++k) tfs.push_back(f.translation(2, Exact(k * e[2])));
        s.x = single_template<3>(prism_template(f, e), tfs, random_regions(tfs.size()));
        s.convex = true;
        os << "translation stack of " << n << " prisms " << e[0] << "x" << e[1] << "x" << e[2]
           << " in " << f.text;
      } else if (!conforming && chance(50)) {
        // Figure 4.4 in 3D by a half turn: the pyramid turned about an axis in its base plane
        // parallel to a side meets itself with the other base diagonal
        const int h = pick(1, 2);
        const auto mesh = pyramid_template(f, e[0], h);
        const auto c = f.at({rational(e[0], 2), rational(e[0], 2), Exact(0)});
        const auto& u = f.axis[0]; // half turn about the line c + t u: quaternion (0, u)
        const auto turn = Motion<3>::rotation_quaternion(0, u[0], u[1], u[2], c);
        s.x = single_template<3>(mesh, {Motion<3>(), turn}, random_regions(2));
        s.convex = true;
        os << "figure 4.4 (half turn) of a square pyramid " << e[0] << "/" << h << " in " << f.text;
      } else {
        const auto mesh = cube_template(f, e, conforming);
        const int axis = conforming ? -1 : pick(0, 2);
        const auto [tfs, grid] = grid_translations<3>(f, e, 2, axis);
        s.x = single_template<3>(mesh, tfs, random_regions(tfs.size()));
        s.convex = true;
        os << (conforming ? "translation " : "figure 4.4 translation ") << grid << " of "
           << (conforming ? "Kuhn" : "5-tetrahedron") << " box " << e[0] << "x" << e[1] << "x"
           << e[2] << " in " << f.text;
      }
      s.recipe = os.str();
      return s;
    });
  });
}

/// Overlapping instances (Eq. 4.2 violated): a box template translated by less than its width.
template <int D>
rc::Gen<GeneratedStructure<D>> overlapping_translation() {
  return rc::gen::exec([] {
    auto s = *translation_impl<D>(true, false);
    auto& list = s.x.instances[0];
    const auto box = core::box_of<Exact, D>(s.x.templates[0].mesh.points);
    Point<D> shift = core::zero_point<Exact, D>();
    shift[0] = (box.hi[0] - box.lo[0]) * rational(1, pick(2, 3));
    list.resize(1);
    list.push_back({list[0].transformation * Motion<D>::translation(shift), pick(1, 2)});
    s.tier = Tier::any;
    s.convex = false;
    s.recipe += "; overlapping: second instance shifted by " + text<D>(shift);
    return s;
  });
}

// ----- encroachment (Lemma 4.5 generator) -------------------------------------------------------

/// Circumcentre of a facet within its own affine hull (midpoint of an edge, circumcentre of a
/// triangle in 3D), exactly.
template <int D>
Point<D> facet_circumcenter(const PointSet<D>& v) {
  if (v.size() == 2) return core::scaled<Exact, D>(v[0] + v[1], rational(1, 2));
  const auto b = v[1] - v[0], c = v[2] - v[0];
  const Exact bb = core::dot<Exact, D>(b, b), cc = core::dot<Exact, D>(c, c),
              bc = core::dot<Exact, D>(b, c);
  const Exact det = bb * cc - bc * bc;
  const Exact alpha = (bb * cc - cc * bc) / (2 * det), beta = (cc * bb - bb * bc) / (2 * det);
  return v[0] + core::scaled<Exact, D>(b, alpha) + core::scaled<Exact, D>(c, beta);
}

/// Vertices strictly inside the diametral ball of an interface facet: a template boundary facet
/// whose image under some instance coincides with the image of a boundary facet under another
/// instance. Such an apex keeps the facet from being locally Delaunay in AT (the mirrored /
/// translated neighbour cell is on the other side); other boundary facets have one co-face cell.
template <int D>
std::vector<Point<D>> encroaching_apexes(const Complex<D>& m, const std::vector<Motion<D>>& tfs) {
  std::map<Simplex, int> count;
  const auto cells = m.cells();
  for (const auto& c : cells)
    for (const auto& f : core::facets(c)) ++count[f];
  // images of the boundary facets under every instance, as sorted point tuples
  using Key = std::vector<Point<D>>;
  auto key = [&](const Simplex& f, const Motion<D>& t) {
    Key k;
    for (VertexId v : f) k.push_back(t(m.points[v]));
    std::sort(k.begin(), k.end(), core::PointLess<Exact, D>());
    return k;
  };
  auto less = [](const Key& a, const Key& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                        core::PointLess<Exact, D>());
  };
  std::map<Key, int, decltype(less)> images(less);
  for (const auto& [f, n] : count)
    if (n == 1)
      for (const auto& t : tfs) ++images[key(f, t)];
  std::vector<Point<D>> out;
  for (const auto& c : cells)
    for (const auto& f : core::facets(c)) {
      if (count[f] != 1) continue;
      bool interface = false;
      for (const auto& t : tfs) interface = interface || images[key(f, t)] > 1;
      if (!interface) continue;
      const auto fv = m.coords(f);
      const auto cc = facet_circumcenter<D>(fv);
      const Exact r2 = core::dot<Exact, D>(fv[0] - cc, fv[0] - cc);
      for (VertexId v : c)
        if (!f.has_vertex(v)) {
          const auto d = m.points[v] - cc;
          if (core::dot<Exact, D>(d, d) < r2) out.push_back(m.points[v]);
        }
    }
  return out;
}

/// Delaunay triangulation of `pts` with encroaching removable points dropped until no interface
/// facet is encroached; fails (empty) if a non-removable point encroaches.
template <int D>
Complex<D> unencroached_delaunay(PointSet<D> pts, const std::vector<bool>& removable_in,
                                 const std::vector<Motion<D>>& tfs) {
  std::vector<bool> removable = removable_in;
  for (int round = 0; round < 12; ++round) {
    const auto mesh = complex_from_cells<D>(pts, delaunay_cells<D>(pts), false);
    const auto bad = encroaching_apexes<D>(mesh, tfs);
    if (bad.empty()) return complex_from_cells<D>(pts, delaunay_cells<D>(pts));
    PointSet<D> keep;
    std::vector<bool> keep_removable;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const bool encroaches = std::find(bad.begin(), bad.end(), pts[i]) != bad.end();
      if (encroaches && !removable[i]) return {};
      if (!encroaches) {
        keep.push_back(pts[i]);
        keep_removable.push_back(removable[i]);
      }
    }
    pts = keep;
    removable = keep_removable;
  }
  return {};
}

// ----- a simplex with vertices -------------------------------------------------------------------

template <int D>
PointSet<D> random_simplex(int k) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    PointSet<D> s;
    for (int i = 0; i <= k; ++i) {
      Coords<D> c;
      for (int d = 0; d < D; ++d) c[d] = grid_value(0, 4);
      s.push_back(make_point<D>(c));
    }
    if (dedupe<D>(s).size() == s.size() && core::affinely_independent<Exact, D>(s)) return s;
  }
  PointSet<D> s; // the corner simplex, should the picks keep coinciding
  for (int i = 0; i <= k; ++i) {
    Coords<D> c;
    for (int d = 0; d < D; ++d) c[d] = i == d + 1 ? 2 : 0;
    s.push_back(make_point<D>(c));
  }
  return s;
}

/// A big simplex on the side m·(x - c) >= 0 whose facet lies in the hyperplane through c.
template <int D>
PointSet<D> half_space_simplex(const Point<D>& c, const Point<D>& m);

template <>
inline PointSet<2> half_space_simplex<2>(const Point<2>& c, const Point<2>& m) {
  const Point<2> t = make_point<2>({-m[1], m[0]});
  return {c + core::scaled<Exact, 2>(t, 40), c - core::scaled<Exact, 2>(t, 40),
          c + core::scaled<Exact, 2>(m, 40)};
}

template <>
inline PointSet<3> half_space_simplex<3>(const Point<3>& c, const Point<3>& m) {
  int k = 0;
  for (int d = 1; d < 3; ++d)
    if (CGAL::abs(m[d]) < CGAL::abs(m[k])) k = d;
  Coords<3> e{};
  for (int d = 0; d < 3; ++d) e[d] = d == k ? 1 : 0;
  const auto u = cross(m, make_point<3>(e));
  const auto w = cross(m, u);
  return {c + core::scaled<Exact, 3>(u, 80),
          c - core::scaled<Exact, 3>(u, 40) + core::scaled<Exact, 3>(w, 70),
          c - core::scaled<Exact, 3>(u, 40) - core::scaled<Exact, 3>(w, 70),
          c + core::scaled<Exact, 3>(m, 80)};
}

/// A normal m whose hyperplane through c = centroid(e) separates two vertices of e strictly.
template <int D>
Point<D> cutting_normal(const PointSet<D>& e) {
  const auto c = centroid<D>(e);
  for (int attempt = 0; attempt < 30; ++attempt) {
    const auto m = small_vector<D>(-2, 2);
    bool pos = false, neg = false;
    for (const auto& v : e) {
      const Exact s = core::dot<Exact, D>(m, v - c);
      pos = pos || s > 0;
      neg = neg || s < 0;
    }
    if (pos && neg) return m;
  }
  return e[1] - e[0]; // always separates e[0] from e[1]
}

template <int D>
Complex<D> delaunay_of(const PointSet<D>& pts) {
  return complex_from_cells<D>(pts, delaunay_cells<D>(pts));
}

} // namespace symmesh::proofs::gen::detail
