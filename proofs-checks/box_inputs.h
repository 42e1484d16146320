// Generated templated meshes of boxes, for the properties of the adaptation operations that act on
// generated meshes (.tmesh: adapt/templated_mesh_adaptation.h) — spec/adaptation.md#properties
//
// The input is a templated geometry of axis-parallel boxes (rectangles in 2D) given as PLCs
// (polygons in 2D), generated as `symmesh generate` does (api::run_generation). Right angles only,
// so no acute input angle; the sides are multiples of 1/2, so the JSON and the volume are exact.
#pragma once
#include "symmesh/adapt/templated_mesh_adaptation.h"
#include "symmesh/api/generate_run.h"

#include <gmpxx.h>
#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace symmesh::proofs::boxes {

/// Box templates, each instanced by translations or by mirrors in x followed by a translation,
/// and the generation size. Coordinates are kept as twice their value (integers).
struct BoxInput {
  struct Box {
    std::vector<int> twice; ///< x0, x1, y0, y1 (, z0, z1), times two
    /// Per instance: twice its translation and whether x is mirrored first (x -> -x).
    std::vector<std::pair<std::vector<int>, bool>> instances;
  };
  int dimension = 3;
  std::vector<Box> boxes;
  double size = 1;

  static std::string half(int twice) {
    return twice % 2 ? std::to_string(twice) + "/2" : std::to_string(twice / 2);
  }
  /// The box's corner k (bit i of k: the upper side in coordinate i).
  nlohmann::json corner(const Box& b, int k) const {
    auto p = nlohmann::json::array();
    for (int i = 0; i < dimension; ++i)
      p.push_back(half(b.twice[std::size_t(2 * i + ((k >> i) & 1))]));
    return p;
  }
  nlohmann::json transformation(const std::vector<int>& shift, bool mirrored) const {
    using J = nlohmann::json;
    J t = J::array(), perm = J::array(), sign = J::array();
    for (int i = 0; i < dimension; ++i) {
      t.push_back(half(shift[std::size_t(i)]));
      perm.push_back(i);
      sign.push_back(mirrored && i == 0 ? -1 : 1);
    }
    if (!mirrored) return J{{"translation", t}};
    return J{{"signed_permutation", J{{"perm", perm}, {"sign", sign}, {"translation", t}}}};
  }
  nlohmann::json document() const {
    using J = nlohmann::json;
    J templates = J::array();
    for (std::size_t n = 0; n < boxes.size(); ++n) {
      const auto& b = boxes[n];
      J instances = J::array();
      for (const auto& [shift, mirrored] : b.instances)
        instances.push_back(J{{"transformation", transformation(shift, mirrored)}, {"region", 1}});
      J t{{"name", "box" + std::to_string(n)}, {"kind", "geometry"}, {"instances", instances}};
      if (dimension == 2) {
        t["polygon"] = J::array({corner(b, 0), corner(b, 1), corner(b, 3), corner(b, 2)});
      } else {
        J vertices = J::array();
        for (int k = 0; k < 8; ++k) vertices.push_back(corner(b, k));
        t["vertices"] = vertices;
        t["faces"] =
            J::array({J::array({0, 2, 3, 1}), J::array({4, 5, 7, 6}), J::array({0, 1, 5, 4}),
                      J::array({2, 6, 7, 3}), J::array({0, 4, 6, 2}), J::array({1, 3, 7, 5})});
      }
      templates.push_back(t);
    }
    return J{
        {"symmesh", "templated-structure/1"}, {"dimension", dimension}, {"templates", templates}};
  }
  /// The text a failing case records: the document and the size.
  std::string description() const {
    return document().dump() + "\n(size " + std::to_string(size) + ")";
  }
  /// The union's area or volume, exactly (the instances do not overlap).
  mpq_class measure() const {
    mpq_class v = 0;
    for (const auto& b : boxes) {
      mpz_class box = int(b.instances.size());
      for (int i = 0; i < dimension; ++i)
        box *= b.twice[std::size_t(2 * i + 1)] - b.twice[std::size_t(2 * i)];
      v += box;
    }
    v /= dimension == 2 ? 4 : 8;
    v.canonicalize(); // gmpxx compares representations: 16/8 != 2
    return v;
  }
  /// The generated templated mesh, its identifications expanded for the adaptation operations.
  mesh::TemplatedMeshCompactSvb generate() const {
    api::RunOptions o;
    o.size = size;
    auto t = api::run_generation(api::parse_structure_text(document().dump(), "boxes"), "boxes", o)
                 .templated;
    adapt::expand_identifications(t);
    return t;
  }
};

/// A grid of boxes with sides sides2[i] / 2, counts[i] along axis i (counts[2] ignored in 2D),
/// one template instanced by translations, or every odd column along x the mirror image of its
/// neighbour; size: half the shortest side over `divisor`.
inline BoxInput grid_of_boxes(int dimension, const std::vector<int>& sides2,
                              const std::vector<int>& counts, bool mirrored, int divisor) {
  BoxInput in;
  in.dimension = dimension;
  BoxInput::Box b;
  for (int i = 0; i < dimension; ++i) {
    b.twice.push_back(0);
    b.twice.push_back(sides2[std::size_t(i)]);
  }
  const int ny = counts[1], nz = dimension == 3 ? counts[2] : 1;
  for (int i = 0; i < counts[0]; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        // x -> (i+1)a - x maps [0,a] onto [ia, (i+1)a].
        const bool m = mirrored && i % 2;
        std::vector<int> shift{(m ? i + 1 : i) * sides2[0], j * sides2[1]};
        if (dimension == 3) shift.push_back(k * sides2[2]);
        b.instances.push_back({shift, m});
      }
  in.boxes.push_back(b);
  in.size = 0.5 * *std::min_element(sides2.begin(), sides2.begin() + dimension) / divisor;
  return in;
}

/// A grid of boxes with sides 1, 3/2 or 2: 1-3 along x, 1-2 along the other axes, at least two,
/// one template instanced by translations, or every odd column along x the mirror image of its
/// neighbour. Convex. Size: the shortest side or half of it.
inline rc::Gen<BoxInput> box_grid(int dimension) {
  return rc::gen::suchThat(
      rc::gen::apply(
          [dimension](std::vector<int> sides2, std::vector<int> counts, bool mirrored,
                      int divisor) {
            return grid_of_boxes(dimension, sides2, counts, mirrored, divisor);
          },
          rc::gen::container<std::vector<int>>(3, rc::gen::inRange(2, 5)),
          rc::gen::apply(
              [](int x, int y, int z) {
                return std::vector<int>{x, y, z};
              },
              rc::gen::inRange(1, 4), rc::gen::inRange(1, 3), rc::gen::inRange(1, 3)),
          rc::gen::arbitrary<bool>(), rc::gen::inRange(1, 3)),
      [](const BoxInput& in) { return in.boxes[0].instances.size() >= 2; });
}

/// A block on a base slab (two templates, instanced once), the block's bottom covering a corner
/// part of the base's top side: a T-junction of the boundary patches, a non-convex union; size
/// 0.7 + 0.05 size_step. Meshed independently, the cells along the partly shared side do not
/// match: made Delaunay inside each template they still leave interface facets that are not
/// template-aware locally Delaunay (in 3D). Lengths are twice their value.
inline BoxInput block_on_base_of(int dimension, int base2, int height2, int block_x2, int block_y2,
                                 int block_h2, int size_step) {
  BoxInput in;
  in.dimension = dimension;
  const std::vector<int> origin(std::size_t(dimension), 0);
  if (dimension == 2) {
    in.boxes.push_back({{0, base2, 0, height2}, {{origin, false}}});
    in.boxes.push_back({{0, block_x2, height2, height2 + block_h2}, {{origin, false}}});
  } else {
    in.boxes.push_back({{0, base2, 0, base2, 0, height2}, {{origin, false}}});
    in.boxes.push_back(
        {{0, block_x2, 0, block_y2, height2, height2 + block_h2}, {{origin, false}}});
  }
  in.size = 0.7 + 0.05 * size_step;
  return in;
}

/// block_on_base_of with base 2-3, height 1/2-1, block 1-2 by 1-2 by 1/2-3/2, size 0.7-0.8.
inline rc::Gen<BoxInput> block_on_base(int dimension) {
  return rc::gen::apply(
      [dimension](int base2, int height2, int block_x2, int block_y2, int block_h2, int size_step) {
        return block_on_base_of(dimension, base2, height2, block_x2, block_y2, block_h2, size_step);
      },
      rc::gen::inRange(4, 7), rc::gen::inRange(1, 3), rc::gen::inRange(2, 5),
      rc::gen::inRange(2, 5), rc::gen::inRange(1, 4), rc::gen::inRange(0, 3));
}

/// A rotation that is no signed permutation, row-major d × d, rounded: by `degrees` about the
/// origin (2D) or about the axis (1, 2, 3) (3D). Turning a box mesh by it leaves no face exactly
/// flat in the doubles (the slanted-plane properties of Section 5.2.1 and 5.2.2).
inline std::vector<double> turning_rotation(int d, int degrees) {
  const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a), k = 1 - c;
  if (d == 2) return {c, -s, s, c};
  const double x = 1 / std::sqrt(14.0), y = 2 * x, z = 3 * x;
  return {c + x * x * k,     x * y * k - z * s, x * z * k + y * s, y * x * k + z * s, c + y * y * k,
          y * z * k - x * s, z * x * k - y * s, z * y * k + x * s, c + z * z * k};
}

/// The facets of exactly one cell of a template mesh of dimension d — its template boundary —
/// as sorted vertex numbers.
inline std::set<std::vector<mesh::IndexType>> one_cell_facets(const mesh::Mesh& m, int d) {
  std::map<std::vector<mesh::IndexType>, int> count;
  for (std::size_t c = 0; c < m.cell_count(); ++c)
    for (int skip = 0; skip <= d; ++skip) {
      std::vector<mesh::IndexType> f;
      for (int k = 0; k <= d; ++k)
        if (k != skip) f.push_back(m.cell(c)[k]);
      std::sort(f.begin(), f.end());
      ++count[f];
    }
  std::set<std::vector<mesh::IndexType>> out;
  for (const auto& [f, n] : count)
    if (n == 1) out.insert(f);
  return out;
}

/// d! times the measure (area, volume) of the simplex with corners p[0..d], exactly: every double
/// is taken as the rational it is. Unsigned.
inline mpq_class simplex_measure_times_factorial(const std::array<const double*, 4>& p, int d) {
  std::array<std::array<mpq_class, 3>, 3> e;
  for (int k = 1; k <= d; ++k)
    for (int i = 0; i < d; ++i)
      e[std::size_t(k - 1)][std::size_t(i)] = mpq_class(p[std::size_t(k)][i]) - mpq_class(p[0][i]);
  const mpq_class det = d == 2 ? mpq_class(e[0][0] * e[1][1] - e[0][1] * e[1][0])
                               : mpq_class(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                                           e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                                           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]));
  return abs(det);
}

/// AT's area or volume from the template cells, exactly (the doubles taken as rationals; every
/// instance is a rigid copy).
inline mpq_class exact_measure(const mesh::TemplatedMeshCompactSvb& t) {
  const int d = t.templated.point_dimension;
  mpq_class total = 0;
  for (const auto& mt : t.templated.templates) {
    mpq_class sum = 0;
    for (std::size_t c = 0; c < mt.mesh.cell_count(); ++c) {
      std::array<const double*, 4> p{};
      for (int k = 0; k <= d; ++k)
        p[std::size_t(k)] = mt.mesh.vertex(std::size_t(mt.mesh.cell(c)[k]));
      sum += simplex_measure_times_factorial(p, d);
    }
    total += sum * int(mt.instance_count());
  }
  total /= d == 2 ? 2 : 6;
  return total;
}

} // namespace symmesh::proofs::boxes
