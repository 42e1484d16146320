// RapidCheck generators of templated structures for the proofs-checks: reflective, orthogonal-
// reflective and translation families, Delaunay templated meshes and the tiers valid_templated_mesh
// ⊂ templated_structure ⊂ any_structure (see generators.h).
// GCC 12 false positives, silenced for the generator sources only: -Wmaybe-uninitialized inside
// CGAL's filtered weighted-point predicates and -Wrestrict in std::string concatenation (GCC bug
// 105329).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wrestrict"

#include "proofs-checks/structure_support.h"

namespace symmesh::proofs::gen {

using namespace detail;

// ----- structures
// ------------------------------------------------------------------------------------

template <int D>
rc::Gen<GeneratedStructure<D>> reflective_structure() {
  return rc::gen::exec([] {
    auto o = *reflections_impl<D>(1, 1, false);
    o.s.recipe = "reflective: " + o.s.recipe;
    return maybe_moved<D>(o.s, 40);
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> crossing_reflective_structure() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      const auto f = random_frame<D>();
      // No point lies on H (c_0 != 0) but some lie on either side: the hull crosses H, so some
      // cell meets H, and as no vertex is on H that cell has vertices strictly on both sides
      // (its interior meets H and overlaps its own mirror image).
      std::vector<Coords<D>> cs;
      const int n = point_count(size, D) + 1;
      for (int k = 0; k < n; ++k) {
        Coords<D> c;
        for (int i = 0; i < D; ++i) c[i] = grid_value(i == 0 ? -2 : -3, 3);
        if (c[0] == 0) c[0] = rational(1, 2);
        cs.push_back(c);
      }
      Coords<D> below{}, above{};
      for (int i = 0; i < D; ++i) below[i] = above[i] = 0;
      below[0] = -1;
      above[0] = 2;
      cs.push_back(below);
      cs.push_back(above);
      for (int i = 1; i < D; ++i) { // keep the point set full-dimensional
        Coords<D> e = above;
        e[i] = 2;
        cs.push_back(e);
      }
      PointSet<D> pts;
      for (const auto& c : cs) pts.push_back(f.at(c));
      pts = dedupe<D>(pts);
      GeneratedStructure<D> g;
      g.x = single_template<D>(delaunay_of<D>(pts), {Motion<D>(), f.reflection(0, 0)},
                               {1, pick(1, 2)});
      g.tier = Tier::any;
      g.recipe = "template crossing H: delaunay of " + points_text<D>(pts) + " in " + f.text;
      return maybe_moved<D>(g, 30);
    });
  });
}

template <int D>
rc::Gen<OrthogonalReflections<D>> orthogonal_reflections() {
  return rc::gen::exec([] {
    auto o = *reflections_impl<D>(2, D, false);
    if (chance(40)) {
      const auto g = random_motion<D>();
      const bool conj = chance(50);
      o.s = moved<D>(o.s, g, conj);
      // the symmetry hyperplanes of AT move with g: n' = A n, d' = d + n'·b
      for (std::size_t j = 0; j < o.normals.size(); ++j) {
        Point<D> n2;
        const auto& a = g.value.matrix();
        for (int r = 0; r < D; ++r) {
          n2[r] = 0;
          for (int k = 0; k < D; ++k) n2[r] += a[r][k] * o.normals[j][k];
        }
        o.offsets[j] = o.offsets[j] + core::dot<Exact, D>(n2, g.value.translation_part());
        o.normals[j] = n2;
      }
    }
    return o;
  });
}

template <int D>
rc::Gen<OrthogonalReflections<D>> non_orthogonal_reflections() {
  return rc::gen::withSize([](int size) {
    return rc::gen::exec([size] {
      // axes a0 ⟂ a1 of equal length (a rotation by a Pythagorean angle), a2 = e_z in 3D
      const int p = pick(1, 3), q = pick(0, 2);
      std::array<Point<D>, D> axis;
      Point<D> o = core::zero_point<Exact, D>();
      for (int d = 0; d < D; ++d) o[d] = pick(-2, 2);
      axis[0] = core::zero_point<Exact, D>();
      axis[1] = core::zero_point<Exact, D>();
      axis[0][0] = p;
      axis[0][1] = q;
      axis[1][0] = -q;
      axis[1][1] = p;
      if constexpr (D == 3) {
        axis[2] = core::zero_point<Exact, D>();
        axis[2][2] = 1;
      }
      auto at = [&](const Coords<D>& c) {
        Point<D> x = o;
        for (int j = 0; j < D; ++j) x = x + core::scaled<Exact, D>(axis[j], c[j]);
        return x;
      };
      // template in the wedge 0 <= c1 <= c0 <= B (x 0 <= c2 <= Z)
      const int B = pick(2, 4), Z = pick(1, 2);
      std::vector<Coords<D>> cs;
      auto add = [&](const Exact& c0, const Exact& c1) {
        Coords<D> c{};
        c[0] = c0;
        c[1] = c1;
        if constexpr (D == 3) {
          cs.push_back(c);
          c[2] = Z;
        }
        cs.push_back(c);
      };
      add(0, 0);
      add(B, 0);
      add(B, B);
      const int extra = pick(0, 1 + size / 30);
      for (int k = 0; k < extra; ++k) {
        const Exact c0 = grid_value(1, B), c1 = grid_value(0, B);
        add(c0, c1 < c0 ? c1 : c0);
      }
      PointSet<D> pts;
      for (const auto& c : cs) pts.push_back(at(c));
      pts = dedupe<D>(pts);
      const auto mesh = delaunay_of<D>(pts);
      // the 8 signed permutations of (c0, c1) as world motions A S A^T / |a0|^2
      const Exact l2 = Exact(p * p + q * q);
      std::vector<Motion<D>> tfs;
      for (int perm = 0; perm < 2; ++perm)
        for (int sg = 0; sg < 4; ++sg) {
          typename Motion<D>::Mat s{};
          for (int r = 0; r < D; ++r)
            for (int k = 0; k < D; ++k) s[r][k] = 0;
          const int i0 = perm ? 1 : 0, i1 = perm ? 0 : 1;
          s[0][i0] = (sg & 1) ? -1 : 1;
          s[1][i1] = (sg & 2) ? -1 : 1;
          if constexpr (D == 3) s[2][2] = 1;
          typename Motion<D>::Mat m{};
          for (int r = 0; r < D; ++r)
            for (int k = 0; k < D; ++k) {
              Exact sum = 0;
              for (int i = 0; i < D; ++i)
                for (int j = 0; j < D; ++j) // c_j = (x - o)·a_j / |a_j|^2
                  sum += axis[i][r] * s[i][j] * axis[j][k] / (j < 2 ? l2 : Exact(1));
              m[r][k] = sum;
            }
          // x -> o + M (x - o)
          Point<D> b = o;
          for (int r = 0; r < D; ++r)
            for (int k = 0; k < D; ++k) b[r] -= m[r][k] * o[k];
          tfs.push_back(Motion<D>::from_matrix(m, b));
        }
      OrthogonalReflections<D> out;
      out.s.x = single_template<D>(mesh, tfs, std::vector<int>(tfs.size(), 1));
      out.s.tier = Tier::valid_templated_mesh;
      out.s.convex = true;
      out.normals = {axis[0], axis[0] - axis[1]};
      out.offsets = {core::dot<Exact, D>(axis[0], o), core::dot<Exact, D>(axis[0] - axis[1], o)};
      out.s.recipe =
          "square group (reflections at 45 degrees) of the wedge template, a0=" + text<D>(axis[0]) +
          " origin " + text<D>(o) + ", B=" + std::to_string(B) + ", " + points_text<D>(pts);
      return out;
    });
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> translation_grid() {
  return translation_impl<D>(true, false);
}

template <int D>
rc::Gen<GeneratedStructure<D>> figure_4_4_structure() {
  return translation_impl<D>(false, false);
}

template <int D>
rc::Gen<GeneratedStructure<D>> delaunay_templated_mesh() {
  return rc::gen::suchThat(rc::gen::withSize([](int size) {
                             return rc::gen::exec([size] {
                               GeneratedStructure<D> s;
                               const bool translate = D == 2 && chance(30);
                               if (translate) {
                                 s = *translation_impl<D>(true, true);
                               } else {
                                 s = (*reflections_impl<D>(1, D == 3 && size < 50 ? 2 : D, true)).s;
                               }
                               // re-triangulate the template: Delaunay with no encroached boundary
                               // facet
                               auto& tm = s.x.templates[0].mesh;
                               const auto bnd = core::mesh_boundary(tm);
                               std::set<VertexId> on_boundary;
                               for (const auto& e : bnd.elements)
                                 for (VertexId v : e) on_boundary.insert(v);
                               std::vector<bool> removable;
                               for (std::size_t i = 0; i < tm.points.size(); ++i)
                                 removable.push_back(!on_boundary.count(VertexId(i)));
                               std::vector<Motion<D>> tfs;
                               for (const auto& spec : s.x.instances[0])
                                 tfs.push_back(spec.transformation);
                               tm = unencroached_delaunay<D>(tm.points, removable, tfs);
                               s.recipe = "delaunay-repaired " + s.recipe;
                               s.convex = true;
                               if (!tm.elements.empty() && chance(30)) s = split_template<D>(s);
                               return maybe_moved<D>(s, 40);
                             });
                           }),
                           [](const GeneratedStructure<D>& s) {
                             for (const auto& t : s.x.templates)
                               if (t.mesh.elements.empty()) return false;
                             return true;
                           });
}

namespace {
/// Number of cells of AT(x): the exact LPs of the conformity checks grow quadratically with it.
template <int D>
std::size_t at_cells(const Structure<D>& x) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < x.templates.size(); ++i)
    n += x.templates[i].mesh.cells().size() * x.instances[i].size();
  return n;
}
/// Keeps the structure instance small (so that 300 cases stay fast): a few redraws, then accept.
template <int D>
constexpr std::size_t kMaxAtCells = D == 2 ? 36 : 10;
} // namespace

template <int D>
rc::Gen<GeneratedStructure<D>> valid_templated_mesh() {
  return rc::gen::exec([] {
    GeneratedStructure<D> s;
    for (int attempt = 0; attempt < 4; ++attempt) {
      switch (pick(0, 5)) {
      case 0:
      case 1:
        s = (*reflections_impl<D>(1, 1, false)).s;
        break;
      case 2:
        s = (*reflections_impl<D>(2, 2, false)).s;
        break; // 8 instances only in Lemma 6.2
      case 3:
      case 4:
        s = *translation_impl<D>(true, false);
        break;
      default:
        s = *delaunay_templated_mesh<D>();
        break;
      }
      if (at_cells<D>(s.x) <= kMaxAtCells<D>) break;
    }
    if (chance(35)) s = split_template<D>(s);
    return maybe_moved<D>(s, 40);
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> templated_structure() {
  return rc::gen::exec([] {
    if (chance(55)) return *valid_templated_mesh<D>();
    auto s = *figure_4_4_structure<D>();
    if (chance(30)) s = split_template<D>(s);
    return maybe_moved<D>(s, 40);
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> any_structure() {
  return rc::gen::exec([] {
    switch (pick(0, 4)) {
    case 0:
      return *crossing_reflective_structure<D>();
    case 1:
      return maybe_moved<D>(*overlapping_translation<D>(), 40);
    default:
      return *templated_structure<D>();
    }
  });
}

template <int D>
rc::Gen<GeneratedStructure<D>> non_mesh_template_structure() {
  return rc::gen::exec([] {
    auto s = *valid_templated_mesh<D>();
    for (auto& t : s.x.templates) t.mesh.elements = t.mesh.cells();
    s.tier = Tier::any;
    s.recipe += "; templates reduced to their cells (not face-complete)";
    return s;
  });
}

// ----- explicit instantiations
// --------------------------------------------------------------------

#define SYMMESH_INSTANTIATE_STRUCTURE_GENERATORS(D)                                                \
  template rc::Gen<GeneratedStructure<D>> reflective_structure<D>();                               \
  template rc::Gen<GeneratedStructure<D>> crossing_reflective_structure<D>();                      \
  template rc::Gen<OrthogonalReflections<D>> orthogonal_reflections<D>();                          \
  template rc::Gen<OrthogonalReflections<D>> non_orthogonal_reflections<D>();                      \
  template rc::Gen<GeneratedStructure<D>> translation_grid<D>();                                   \
  template rc::Gen<GeneratedStructure<D>> figure_4_4_structure<D>();                               \
  template rc::Gen<GeneratedStructure<D>> delaunay_templated_mesh<D>();                            \
  template rc::Gen<GeneratedStructure<D>> valid_templated_mesh<D>();                               \
  template rc::Gen<GeneratedStructure<D>> templated_structure<D>();                                \
  template rc::Gen<GeneratedStructure<D>> any_structure<D>();                                      \
  template rc::Gen<GeneratedStructure<D>> non_mesh_template_structure<D>();

SYMMESH_INSTANTIATE_STRUCTURE_GENERATORS(2)
SYMMESH_INSTANTIATE_STRUCTURE_GENERATORS(3)

} // namespace symmesh::proofs::gen
