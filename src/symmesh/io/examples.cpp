// Built-in 2D and 3D templated geometries (spec/examples.md).
#include "symmesh/io/examples.h"

#include <array>
#include <functional>
#include <map>
#include <stdexcept>

namespace symmesh::io {
namespace {
using J = nlohmann::ordered_json;

J point(const std::string& x, const std::string& y) {
  return J::array({x, y});
}
J identity() {
  return J{{"identity", J::object()}};
}
J translation(const std::string& x, const std::string& y) {
  return J{{"translation", point(x, y)}};
}
J rotation(int order, int k) {
  return J{{"rotation", J{{"order", order}, {"k", k}}}};
}
J compose(const J& outer, const J& inner) {
  return J{{"compose", J::array({outer, inner})}};
}
/// Reflection in the line through the origin orthogonal to (nx, ny).
J reflection(const std::string& nx, const std::string& ny) {
  return J{{"reflection", J{{"normal", point(nx, ny)}}}};
}
J instance(const J& transformation, int region = 1) {
  return J{{"transformation", transformation}, {"region", region}};
}
J geometry(const std::string& name, const J& polygon, const J& instances) {
  return J{{"name", name}, {"kind", "geometry"}, {"polygon", polygon}, {"instances", instances}};
}
J document(const std::string& description, const J& templates) {
  return J{{"symmesh", "templated-structure/1"},
           {"dimension", 2},
           {"description", description},
           {"templates", templates}};
}
std::string cos_of(int k, int n) {
  return "cos(2pi*" + std::to_string(k) + "/" + std::to_string(n) + ")";
}
std::string sin_of(int k, int n) {
  return "sin(2pi*" + std::to_string(k) + "/" + std::to_string(n) + ")";
}
std::string scaled(const std::string& factor, const std::string& x) {
  return factor + "*" + x;
}

// ------------------------------------------------------------------------------ n-gons

J ngon_slices(int n) {
  J inst = J::array();
  for (int k = 0; k < n; ++k) inst.push_back(instance(rotation(n, k)));
  const J slice = J::array({point("0", "0"), point("1", "0"), point(cos_of(1, n), sin_of(1, n))});
  return document("Regular " + std::to_string(n) +
                      "-gon of circumradius 1 as one slice template (the triangle between the "
                      "rays at 0 and 2pi/" +
                      std::to_string(n) + ") instanced by the " + std::to_string(n) +
                      " rotations by 2pi*k/" + std::to_string(n) + ".",
                  J::array({geometry("slice", slice, inst)}));
}

J ngon_sao(int n) {
  J centre = J::array();
  for (int k = 0; k < n; ++k)
    centre.push_back(point(scaled("1/2", cos_of(k, n)), scaled("1/2", sin_of(k, n))));
  const J ring = J::array({point("1/2", "0"), point("1", "0"), point(cos_of(1, n), sin_of(1, n)),
                           point(scaled("1/2", cos_of(1, n)), scaled("1/2", sin_of(1, n)))});
  J inst = J::array();
  for (int k = 0; k < n; ++k) inst.push_back(instance(rotation(n, k)));
  return document(
      "Regular " + std::to_string(n) +
          "-gon of circumradius 1 split by the small-angle optimisation (Section 6.3.2): a centre "
          "n-gon of circumradius 1/2 instanced once, and a ring slice instanced by the n "
          "rotations.",
      J::array({geometry("centre", centre, J::array({instance(identity())})),
                geometry("ring_slice", ring, inst)}));
}

J ngon_whole(int n) {
  J poly = J::array();
  for (int k = 0; k < n; ++k) poly.push_back(point(cos_of(k, n), sin_of(k, n)));
  return document("Regular " + std::to_string(n) + "-gon of circumradius 1 (vertices at 2pi*k/" +
                      std::to_string(n) +
                      ") as one template with one instance: the whole object, for `symmesh cut "
                      "--rotation " +
                      std::to_string(n) + "`.",
                  J::array({geometry("ngon", poly, J::array({instance(identity())}))}));
}

// ------------------------------------------------------------------------------ gear

/// A 12-tooth gear as one whole polygon with a bore, angles in steps of 2pi/96 (3.75 degrees):
/// tooth k has tip corners at steps 8k+1 and 8k+3 (radius 1) and root corners at 8k+5 and
/// 8k+7 (radius 4/5), i.e. a flank from step -1 to step 1; the bore is a 12-gon of radius 3/10
/// with corners at steps 8k+6. The x-axis crosses that flank at about 30 degrees: the cut that
/// Algorithm 6.3 avoids (it cuts through the middle of a tooth, at 90 degrees).
J gear() {
  const auto at = [](const std::string& r, int step) {
    return point(r + "*" + cos_of(step, 96), r + "*" + sin_of(step, 96));
  };
  J outline = J::array(), bore = J::array();
  for (int k = 0; k < 12; ++k) {
    outline.push_back(at("1", 8 * k + 1));
    outline.push_back(at("1", 8 * k + 3));
    outline.push_back(at("4/5", 8 * k + 5));
    outline.push_back(at("4/5", 8 * k + 7));
    bore.push_back(at("3/10", 8 * k + 6));
  }
  const J g{{"name", "gear"},
            {"kind", "geometry"},
            {"polygon", outline},
            {"holes", J::array({bore})},
            {"instances", J::array({instance(identity())})}};
  return document("A 12-tooth gear with a 12-gon bore as one template with one instance (the "
                  "whole object, rotational symmetry of order 12, exact in K_96), for `symmesh "
                  "cut --rotation 12`.",
                  J::array({g}));
}

// ------------------------------------------------------------------------------ star

/// Inner vertex of the {5/2} star at angle 2pi*j/10 (j odd), radius cos(2pi/5)/cos(2pi/10).
J star_inner(int j) {
  const std::string r = "cos(2pi*1/5)/cos(2pi*1/10)";
  return point(r + "*" + cos_of(j, 10), r + "*" + sin_of(j, 10));
}

J star_plain() {
  J poly = J::array();
  for (int k = 0; k < 5; ++k) {
    poly.push_back(point(cos_of(k, 5), sin_of(k, 5)));
    poly.push_back(star_inner(2 * k + 1));
  }
  return document("The five-pointed star {5/2} (tips on the unit circle) as one template with "
                  "one instance: no symmetry used.",
                  J::array({geometry("star", poly, J::array({instance(identity())}))}));
}

J star_rotational() {
  const J point_piece = J::array({point("0", "0"), star_inner(9), point("1", "0"), star_inner(1)});
  J inst = J::array();
  for (int k = 0; k < 5; ++k) inst.push_back(instance(rotation(5, k)));
  return document("The five-pointed star {5/2} as one point template (centre, inner vertex, tip, "
                  "inner vertex) instanced by the 5 rotations by 2pi*k/5.",
                  J::array({geometry("point", point_piece, inst)}));
}

J star_reflective_rotational() {
  const J half = J::array({point("0", "0"), point("1", "0"), star_inner(1)});
  J inst = J::array();
  for (int k = 0; k < 5; ++k) {
    inst.push_back(instance(rotation(5, k)));
    inst.push_back(instance(compose(rotation(5, k), reflection("0", "1"))));
  }
  return document("The five-pointed star {5/2} in the form of Algorithm 6.5: one half-slice "
                  "template (centre, tip, inner vertex) instanced by rot(2pi*k/5) and "
                  "rot(2pi*k/5) o refl(x-axis), k = 0..4.",
                  J::array({geometry("half_slice", half, inst)}));
}

// ------------------------------------------------------------------------------ mirrored

J mirrored_pair(int region) {
  return J::array({instance(identity(), region), instance(reflection("1", "0"), region)});
}

J mosfet() {
  return document(
      "A MOSFET-like device mirrored in the line x = 0: the right half is a substrate "
      "(region 1), a drain well (region 2), a gate oxide (region 3) and a gate (region 4); each "
      "piece is a template instanced by the identity and the reflection x -> -x.",
      J::array({geometry("substrate",
                         J::array({point("0", "0"), point("3", "0"), point("3", "3/2"),
                                   point("1", "3/2"), point("1", "2"), point("0", "2")}),
                         mirrored_pair(1)),
                geometry("well",
                         J::array({point("1", "3/2"), point("3", "3/2"), point("3", "2"),
                                   point("1", "2")}),
                         mirrored_pair(2)),
                geometry("oxide",
                         J::array({point("0", "2"), point("6/5", "2"), point("6/5", "21/10"),
                                   point("0", "21/10")}),
                         mirrored_pair(3)),
                geometry("gate",
                         J::array({point("0", "21/10"), point("1", "21/10"), point("1", "13/5"),
                                   point("0", "13/5")}),
                         mirrored_pair(4))}));
}

J aircraft() {
  const J half =
      J::array({point("0", "-3"), point("8/5", "-16/5"), point("8/5", "-14/5"),
                point("2/5", "-11/5"), point("1/2", "3/5"), point("9/2", "1/5"),
                point("9/2", "3/5"), point("3/5", "11/5"), point("2/5", "9/2"), point("0", "6")});
  return document("An aircraft-like outline mirrored in the line x = 0 (sharp wing tips, tail "
                  "and nose): the right half instanced by the identity and x -> -x.",
                  J::array({geometry("half", half, mirrored_pair(1))}));
}

// ------------------------------------------------------------------------------ bridge

J bridge() {
  // Warren truss of unit beams: bottom nodes (i, 0), i = 0..8; top nodes (i + 1/2, sin 60°).
  // Connectors: hexagons of apothem 1/10 with flat sides facing 0°, 60°, ...; beams: the
  // rectangle [1/10, 9/10] x [-1/20, 1/20] along +x, whose ends lie on the hexagons' sides.
  J hexagon = J::array();
  const std::string r = "1/10/" + cos_of(1, 12);
  for (int k = 0; k < 6; ++k)
    hexagon.push_back(point(r + "*" + cos_of(2 * k + 1, 12), r + "*" + sin_of(2 * k + 1, 12)));
  const J beam = J::array({point("1/10", "-1/20"), point("9/10", "-1/20"), point("9/10", "1/20"),
                           point("1/10", "1/20")});
  const std::string h = sin_of(1, 6);
  const auto bottom = [](int i) { return std::to_string(i); };
  const auto top = [](int i) { return std::to_string(2 * i + 1) + "/2"; };
  J beams = J::array(), connectors = J::array();
  for (int i = 0; i < 8; ++i) { // bottom chord, along 0°
    beams.push_back(instance(translation(bottom(i), "0")));
  }
  for (int i = 0; i < 7; ++i) // top chord, from the right end node, turned by 180°
    beams.push_back(instance(compose(translation(top(i + 1), h), rotation(6, 3))));
  for (int i = 0; i < 8; ++i) { // diagonals at 60° and 120°
    beams.push_back(instance(compose(translation(bottom(i), "0"), rotation(6, 1))));
    beams.push_back(instance(compose(translation(bottom(i + 1), "0"), rotation(6, 2))));
  }
  for (int i = 0; i <= 8; ++i) connectors.push_back(instance(translation(bottom(i), "0"), 2));
  for (int i = 0; i < 8; ++i) connectors.push_back(instance(translation(top(i), h), 2));
  return document(
      "A Warren-truss bridge beam (Section 7.4): 31 beams (region 1) and 17 hexagonal "
      "connectors (region 2) as two templates, instanced by translations and "
      "rotations by 60, 120 and 180 degrees. Exact in K_12.",
      J::array({geometry("beam", beam, beams), geometry("connector", hexagon, connectors)}));
}

// ------------------------------------------------------------------------------ 3D: open TSV

/// The carrier of a trapezoid prism with bottom vertices 0..3 (0, 1 on one cut face, 2, 3 on the
/// other; 0, 2 inner, 1, 3 outer) and top vertices 4..7 above them: the two triangle prisms over
/// (0, 1, 3) and (0, 2, 3), 3 tetrahedra each, every vertical quad split from its lower-index
/// bottom to its higher-index top vertex.
J trapezoid_prism_cells() {
  J cells = J::array();
  for (const auto& tri : {std::array<int, 3>{0, 1, 3}, std::array<int, 3>{0, 2, 3}}) {
    const int a = tri[0], b = tri[1], c = tri[2]; // increasing
    cells.push_back(J::array({a, b, c, c + 4}));
    cells.push_back(J::array({a, b, b + 4, c + 4}));
    cells.push_back(J::array({a, a + 4, b + 4, c + 4}));
  }
  return cells;
}

/// The slice of an open through-silicon via (Sections 6.3, 7.3): an n-gon prism of silicon with a
/// coaxial open via lined by two layers, cut into n slices (the wedge between the half-planes at
/// angle 0 and 2pi/n through the z axis). Each layer of the slice is one template (its own
/// region), the trapezoid prism between radii r_in and r_out (circumradii of the n-gons), height
/// 2, carried by 6 tetrahedra (the two triangle prisms of the trapezoid, 3 tetrahedra each, every
/// vertical quad split from its lower-index bottom to its higher-index top vertex); all instanced
/// by the n rotations about the z axis. The via itself is empty.
J tsv_slice_template(const std::string& name, const std::string& r_in, const std::string& r_out,
                     int n, int region) {
  const auto at = [&](const std::string& r, int k, const std::string& z) {
    return J::array({r + "*" + cos_of(k, n), r + "*" + sin_of(k, n), z});
  };
  // 0..3 bottom (r_in at angle 0, r_out at 0, r_in at 2pi/n, r_out at 2pi/n), 4..7 the same on
  // top: the two slice faces then get the same diagonal up to the rotation (inner bottom to
  // outer top), and every radial face the same as its neighbour layer's (angle 0 bottom to
  // angle 2pi/n top), so the carriers of all instances conform (the conventional baseline needs
  // the union of a region's instances to be a mesh).
  J vertices = J::array({at(r_in, 0, "0"), at(r_out, 0, "0"), at(r_in, 1, "0"), at(r_out, 1, "0"),
                         at(r_in, 0, "2"), at(r_out, 0, "2"), at(r_in, 1, "2"), at(r_out, 1, "2")});
  const J cells = trapezoid_prism_cells();
  J inst = J::array();
  for (int k = 0; k < n; ++k) {
    const J row0 = J::array({cos_of(k, n), "-" + sin_of(k, n), "0"});
    const J row1 = J::array({sin_of(k, n), cos_of(k, n), "0"});
    const J row2 = J::array({"0", "0", "1"});
    inst.push_back(
        instance(k == 0 ? identity() : J{{"matrix", J::array({row0, row1, row2})}}, region));
  }
  return J{{"name", name},
           {"kind", "geometry"},
           {"vertices", vertices},
           {"cells", cells},
           {"instances", inst}};
}

J tsv(int n) {
  J d{{"symmesh", "templated-structure/1"},
      {"dimension", 3},
      {"description",
       "Open TSV, n = " + std::to_string(n) + ": a regular " + std::to_string(n) +
           "-gon prism of silicon (circumradius 1, height 2) with a coaxial open via of "
           "circumradius 1/5 lined by an oxide layer (to 1/4) and a metal layer (to 3/10), as "
           "three slice templates (one per region: oxide 1, metal 2, silicon 3) instanced by the " +
           std::to_string(n) + " rotations about the z axis. Exact in K_" + std::to_string(n) +
           "."},
      {"templates", J::array({tsv_slice_template("oxide", "1/5", "1/4", n, 1),
                              tsv_slice_template("metal", "1/4", "3/10", n, 2),
                              tsv_slice_template("silicon", "3/10", "1", n, 3)})}};
  return d;
}

/// The half-slice of the open TSV of tsv(n) (Algorithm 6.5, Section 6.4.2): the TSV is mirror
/// symmetric in the plane y = 0 and in its rotations by pi/n, so the wedge between angle 0 (n-gon
/// vertices) and pi/n (midpoints of the n-gon sides) reconstructs it under rot(2pi*k/n) and
/// rot(2pi*k/n) o refl(y = 0), k = 0..n-1. Each layer is the trapezoid prism between the n-gons of
/// circumradii r_in and r_out (vertices 0..3 bottom: r_in and r_out at angle 0, then at the side
/// midpoints; 4..7 the same on top), carried by 6 tetrahedra with tsv_slice_template's diagonals
/// (lower-index bottom to higher-index top), so neighbouring layers' carriers conform; its two cut
/// faces lie in mirror planes, which fix them pointwise, so the copies' carriers conform too.
/// Unlike the slice's two cut faces, which the rotation relates point for point (their meshes are
/// mirror images, which makes TetGen's input cospherical in sixes), the half-slice's cut faces are
/// meshed on their own.
J tsv_half_slice_template(const std::string& name, const std::string& r_in,
                          const std::string& r_out, int n, int region) {
  const std::string mx = "(1+" + cos_of(1, n) + ")/2", my = sin_of(1, n) + "/2";
  const auto vertex = [&](const std::string& r, bool midpoint, const std::string& z) {
    return midpoint ? J::array({r + "*" + mx, r + "*" + my, z}) : J::array({r, "0", z});
  };
  J vertices = J::array();
  for (const std::string z : {"0", "2"})
    for (bool midpoint : {false, true})
      for (const std::string& r : {r_in, r_out}) vertices.push_back(vertex(r, midpoint, z));
  const J cells = trapezoid_prism_cells();
  const J mirror{{"reflection", J{{"normal", J::array({"0", "1", "0"})}}}};
  J inst = J::array();
  for (int k = 0; k < n; ++k) {
    const J rot{{"rotation", J{{"order", n}, {"k", k}, {"axis", "z"}}}};
    inst.push_back(instance(k == 0 ? identity() : rot, region));
    inst.push_back(instance(k == 0 ? mirror : compose(rot, mirror), region));
  }
  return J{{"name", name},
           {"kind", "geometry"},
           {"vertices", vertices},
           {"cells", cells},
           {"instances", inst}};
}

J tsv_half(int n) {
  return J{{"symmesh", "templated-structure/1"},
           {"dimension", 3},
           {"description",
            "The open TSV of tsv-" + std::to_string(n) +
                " in the form of Algorithm 6.5: three half-slice templates (oxide 1, metal 2, "
                "silicon 3), the wedge between angle 0 and pi/" +
                std::to_string(n) + ", each instanced by the " + std::to_string(2 * n) +
                " copies rot(2pi*k/" + std::to_string(n) + ") and rot(2pi*k/" + std::to_string(n) +
                ") o refl(y = 0). Exact in K_" + std::to_string(n) + "."},
           {"templates", J::array({tsv_half_slice_template("oxide", "1/5", "1/4", n, 1),
                                   tsv_half_slice_template("metal", "1/4", "3/10", n, 2),
                                   tsv_half_slice_template("silicon", "3/10", "1", n, 3)})}};
}

/// The whole open TSV of tsv(n), unsliced, for `symmesh cut --rotation n` in 3D: each layer is
/// one template instanced once, the n-gon annulus prism between circumradii r_in and r_out
/// (height 2) given by its faces (a PLC: top and bottom are n-gons with an n-gon hole, the walls
/// are quadrilaterals).
J annulus_prism(const std::string& name, const std::string& r_in, const std::string& r_out, int n,
                int region) {
  // Vertex (ring, k): ring 0 inner bottom, 1 outer bottom, 2 inner top, 3 outer top.
  J vertices = J::array();
  for (int ring = 0; ring < 4; ++ring)
    for (int k = 0; k < n; ++k) {
      const std::string& r = ring % 2 == 0 ? r_in : r_out;
      vertices.push_back(
          J::array({r + "*" + cos_of(k, n), r + "*" + sin_of(k, n), ring < 2 ? "0" : "2"}));
    }
  const auto v = [n](int ring, int k) { return ring * n + (k % n); };
  J inner_bottom = J::array(), outer_bottom = J::array(), inner_top = J::array(),
    outer_top = J::array();
  for (int k = 0; k < n; ++k) {
    inner_bottom.push_back(v(0, k));
    outer_bottom.push_back(v(1, k));
    inner_top.push_back(v(2, k));
    outer_top.push_back(v(3, k));
  }
  J faces = J::array({J{{"polygon", outer_bottom}, {"holes", J::array({inner_bottom})}},
                      J{{"polygon", outer_top}, {"holes", J::array({inner_top})}}});
  for (int k = 0; k < n; ++k) {
    faces.push_back(J::array({v(0, k), v(0, k + 1), v(2, k + 1), v(2, k)}));
    faces.push_back(J::array({v(1, k), v(1, k + 1), v(3, k + 1), v(3, k)}));
  }
  return J{{"name", name},
           {"kind", "geometry"},
           {"vertices", vertices},
           {"faces", faces},
           {"instances", J::array({instance(identity(), region)})}};
}

J tsv_whole(int n) {
  return J{{"symmesh", "templated-structure/1"},
           {"dimension", 3},
           {"description", "The open TSV of tsv-" + std::to_string(n) +
                               ", whole: oxide (region 1), metal (2) and silicon (3) as three "
                               "n-gon annulus prisms given by their faces, each instanced once; "
                               "input for symmesh cut --rotation " +
                               std::to_string(n) + ". Exact in K_" + std::to_string(n) + "."},
           {"templates", J::array({annulus_prism("oxide", "1/5", "1/4", n, 1),
                                   annulus_prism("metal", "1/4", "3/10", n, 2),
                                   annulus_prism("silicon", "3/10", "1", n, 3)})}};
}

// ------------------------------------------------------------------------------ 3D: FinFET

/// An axis-parallel box [x0,x1] x [y0,y1] x [z0,z1] as a geometry template (carrier: the 6
/// tetrahedra around the diagonal from the first to the last corner).
J box(const std::string& name, const std::array<std::string, 6>& b, const J& instances) {
  J vertices = J::array();
  for (int k = 0; k < 8; ++k)
    vertices.push_back(J::array({b[std::size_t(k & 1)], b[std::size_t(2 + ((k >> 1) & 1))],
                                 b[std::size_t(4 + ((k >> 2) & 1))]}));
  const J cells =
      J::array({J::array({0, 1, 3, 7}), J::array({0, 1, 5, 7}), J::array({0, 2, 3, 7}),
                J::array({0, 2, 6, 7}), J::array({0, 4, 5, 7}), J::array({0, 4, 6, 7})});
  return J{{"name", name},
           {"kind", "geometry"},
           {"vertices", vertices},
           {"cells", cells},
           {"instances", instances}};
}

/// A FinFET-like device with two orthogonal mirror planes (x = 0 across the fin, y = 0 along
/// it): the quarter x, y >= 0 as six boxes — substrate (region 1), fin (2), gate oxide on the
/// fin's side and top (3), gate on the side and across the top (4) — each instanced by the four
/// copies I, refl(x = 0), refl(y = 0) and their composition (Algorithm 6.4). Rational.
J finfet() {
  const auto refl = [](const std::string& nx, const std::string& ny) {
    return J{{"reflection", J{{"normal", J::array({nx, ny, "0"})}, {"offset", "0"}}}};
  };
  const auto copies = [&](int region) {
    return J::array({instance(identity(), region), instance(refl("1", "0"), region),
                     instance(refl("0", "1"), region),
                     instance(compose(refl("1", "0"), refl("0", "1")), region)});
  };
  J d{{"symmesh", "templated-structure/1"},
      {"dimension", 3},
      {"description",
       "FinFET-like device, two mirror planes x = 0 and y = 0: substrate [-2,2]x[-3/2,3/2]x[0,1] "
       "(region 1), fin [-1/5,1/5]x[-3/2,3/2]x[1,8/5] (2), gate oxide 1/10 thick on the fin's "
       "sides and top for |y| <= 1/2 (3), gate [-1,1]x[-1/2,1/2] around it up to z = 2 (4); the "
       "quarter x, y >= 0 as six boxes, each instanced by the four mirror copies. Volume 14.48."},
      {"templates",
       J::array({box("substrate", {"0", "2", "0", "3/2", "0", "1"}, copies(1)),
                 box("fin", {"0", "1/5", "0", "3/2", "1", "8/5"}, copies(2)),
                 box("oxide_side", {"1/5", "3/10", "0", "1/2", "1", "17/10"}, copies(3)),
                 box("oxide_top", {"0", "1/5", "0", "1/2", "8/5", "17/10"}, copies(3)),
                 box("gate_side", {"3/10", "1", "0", "1/2", "1", "17/10"}, copies(4)),
                 box("gate_top", {"0", "1", "0", "1/2", "17/10", "2"}, copies(4))})}};
  return d;
}

// ------------------------------------------------------------------------------ 3D: smoke case

/// The 3D analogue of Figure 6.5, given as a PLC: the half cube [0,1] x [-1/2,1/2] x [0,1] and
/// its mirror image in x = 0 (one mirror, Algorithm 6.1's case), so the whole is [-1,1] x
/// [-1/2,1/2] x [0,1]. The smallest 3D object: a smoke case for every 3D generator.
J cube_halves() {
  J vertices = J::array();
  for (int k = 0; k < 8; ++k)
    vertices.push_back(
        J::array({(k & 1) ? "1" : "0", (k & 2) ? "1/2" : "-1/2", (k & 4) ? "1" : "0"}));
  const J faces =
      J::array({J::array({0, 2, 3, 1}), J::array({4, 5, 7, 6}), J::array({0, 1, 5, 4}),
                J::array({2, 6, 7, 3}), J::array({0, 4, 6, 2}), J::array({1, 3, 7, 5})});
  const J mirror = J{{"reflection", J{{"normal", J::array({"1", "0", "0"})}, {"offset", "0"}}}};
  return J{{"symmesh", "templated-structure/1"},
           {"dimension", 3},
           {"description",
            "Cube halves: the half box [0,1]x[-1/2,1/2]x[0,1] given by its six faces "
            "(a PLC) and its mirror image in the plane x = 0. Volume 2, surface 10."},
           {"templates",
            J::array({J{{"name", "half"},
                        {"kind", "geometry"},
                        {"vertices", vertices},
                        {"faces", faces},
                        {"instances", J::array({instance(identity()), instance(mirror)})}}})}};
}

// ------------------------------------------------------------------------------ 3D: multi-TSV

/// Four open 8-TSVs in a silicon trunk (Section 7.4, Figure 7.11): the trunk is the block
/// [-3,3] x [-3,3] x [0,2] with four 8-gon prism holes of circumradius 1 centred at (+-3/2,
/// +-3/2), given as a PLC whose top and bottom faces are polygons with four holes; it is
/// instanced once (region 4). Each hole holds the three slice templates of tsv(8), instanced by
/// the 8 rotations about the hole's axis, i.e. 32 copies each. The hole walls are given as
/// triangles with the slice carriers' diagonals, so the two sides of each wall agree.
J multi_tsv() {
  const int n = 8;
  const std::array<std::array<std::string, 2>, 4> centres{
      {{"-3/2", "-3/2"}, {"3/2", "-3/2"}, {"-3/2", "3/2"}, {"3/2", "3/2"}}};
  J tsv_doc = tsv(n);
  J templates = J::array();
  for (auto& t : tsv_doc["templates"]) {
    const int region = t["instances"][0]["region"].get<int>();
    J inst = J::array();
    for (const auto& c : centres)
      for (int k = 0; k < n; ++k) {
        const J rows =
            J::array({J::array({cos_of(k, n), "-" + sin_of(k, n), "0"}),
                      J::array({sin_of(k, n), cos_of(k, n), "0"}), J::array({"0", "0", "1"})});
        inst.push_back(
            instance(J{{"matrix", rows}, {"translation", J::array({c[0], c[1], "0"})}}, region));
      }
    t["instances"] = inst;
    templates.push_back(t);
  }
  // The trunk: 8 block corners (bottom 0..3, top 4..7), then per hole h the bottom ring
  // 8 + 16h + k and the top ring 8 + 16h + 8 + k (k = 0..7, counter-clockwise from angle 0).
  J vertices = J::array();
  for (const char* z : {"0", "2"})
    for (const auto& xy : std::array<std::array<const char*, 2>, 4>{
             {{"-3", "-3"}, {"3", "-3"}, {"3", "3"}, {"-3", "3"}}})
      vertices.push_back(J::array({xy[0], xy[1], z}));
  for (const auto& c : centres)
    for (const char* z : {"0", "2"})
      for (int k = 0; k < n; ++k)
        vertices.push_back(J::array({c[0] + "+" + cos_of(k, n), c[1] + "+" + sin_of(k, n), z}));
  const auto ring = [&](int h, int top) {
    J r = J::array();
    for (int k = 0; k < n; ++k) r.push_back(8 + 2 * n * h + n * top + k);
    return r;
  };
  J bottom_holes = J::array(), top_holes = J::array();
  for (int h = 0; h < 4; ++h) {
    bottom_holes.push_back(ring(h, 0));
    top_holes.push_back(ring(h, 1));
  }
  J faces = J::array({J{{"polygon", J::array({0, 3, 2, 1})}, {"holes", bottom_holes}},
                      J{{"polygon", J::array({4, 5, 6, 7})}, {"holes", top_holes}},
                      J::array({0, 1, 5, 4}), J::array({1, 2, 6, 5}), J::array({2, 3, 7, 6}),
                      J::array({3, 0, 4, 7})});
  for (int h = 0; h < 4; ++h)
    for (int k = 0; k < n; ++k) {
      // The silicon slice's outer quad is split from the bottom at angle k to the top at k+1.
      const int b0 = 8 + 2 * n * h + k, b1 = 8 + 2 * n * h + (k + 1) % n;
      faces.push_back(J::array({b0, b1, b1 + n}));
      faces.push_back(J::array({b0, b1 + n, b0 + n}));
    }
  templates.push_back(J{{"name", "trunk"},
                        {"kind", "geometry"},
                        {"vertices", vertices},
                        {"faces", faces},
                        {"instances", J::array({instance(identity(), 4)})}});
  return J{{"symmesh", "templated-structure/1"},
           {"dimension", 3},
           {"description",
            "Multi-TSV (Section 7.4): four open 8-TSVs (the slices of tsv-8: oxide 1, metal 2, "
            "silicon 3, each x 32 = 8 rotations x 4 centres (+-3/2, +-3/2)) in a silicon trunk "
            "[-3,3]^2 x [0,2] with four 8-gon holes (region 4, given by its faces, instanced "
            "once). Exact in K_8."},
           {"templates", templates}};
}

struct Entry {
  std::string summary;
  std::function<J()> make;
};

const std::vector<std::pair<std::string, Entry>>& registry() {
  static const std::vector<std::pair<std::string, Entry>> r = [] {
    std::vector<std::pair<std::string, Entry>> v;
    for (int n : {5, 8, 16, 32, 64, 128}) {
      v.push_back(
          {"ngon-slice-" + std::to_string(n),
           {"regular " + std::to_string(n) + "-gon, one slice, " + std::to_string(n) + " rotations",
            [n] { return ngon_slices(n); }}});
      v.push_back({"ngon-sao-" + std::to_string(n),
                   {"regular " + std::to_string(n) + "-gon, centre + ring slice (Section 6.3.2)",
                    [n] { return ngon_sao(n); }}});
    }
    for (int n : {8, 32, 128})
      v.push_back({"ngon-" + std::to_string(n),
                   {"regular " + std::to_string(n) + "-gon, whole (for cut --rotation)",
                    [n] { return ngon_whole(n); }}});
    for (int n : {8, 16, 32, 64, 128})
      v.push_back(
          {"tsv-" + std::to_string(n),
           {"3D open TSV, " + std::to_string(n) + "-gon prism, via lined by 2 layers, 3 regions, " +
                std::to_string(n) + " slices",
            [n] { return tsv(n); }}});
    for (int n : {8, 16, 32, 64, 128})
      v.push_back({"tsv-half-" + std::to_string(n),
                   {"3D open TSV, " + std::to_string(n) + "-gon prism, 3 regions, " +
                        std::to_string(2 * n) + " half-slices (Algorithm 6.5)",
                    [n] { return tsv_half(n); }}});
    v.push_back({"tsv-whole-8",
                 {"3D open 8-TSV, whole (3 annulus prisms as PLCs, for cut --rotation 8)",
                  [] { return tsv_whole(8); }}});
    v.push_back(
        {"finfet",
         {"3D FinFET-like device, 4 regions, two mirror planes (6 box templates x 4)", finfet}});
    v.push_back(
        {"multi-tsv",
         {"3D four open 8-TSVs in a trunk instanced once, 4 regions (Section 7.4)", multi_tsv}});
    v.push_back(
        {"cube-halves", {"3D half box and its mirror image (PLC input), smoke case", cube_halves}});
    v.push_back({"gear", {"12-tooth gear with a bore, whole (for cut --rotation 12)", gear}});
    v.push_back({"mosfet", {"MOSFET-like device, 4 regions, one mirror axis", mosfet}});
    v.push_back({"aircraft", {"aircraft-like outline, one mirror axis, sharp angles", aircraft}});
    v.push_back({"bridge", {"Warren truss: 31 beams, 17 connectors, 60/120/180 degrees", bridge}});
    v.push_back({"star", {"five-pointed star, one template, no symmetry", star_plain}});
    v.push_back({"star-rotational", {"five-pointed star, 5 rotated points", star_rotational}});
    v.push_back(
        {"star-reflective-rotational",
         {"five-pointed star, 10 half-slices (Algorithm 6.5)", star_reflective_rotational}});
    return v;
  }();
  return r;
}
} // namespace

std::vector<ExampleInfo> example_list() {
  std::vector<ExampleInfo> out;
  for (const auto& [name, e] : registry())
    out.push_back({name, e.summary, e.summary.rfind("3D ", 0) == 0 ? 3 : 2});
  return out;
}

nlohmann::ordered_json example_document(const std::string& name) {
  for (const auto& [n, e] : registry())
    if (n == name) return e.make();
  std::string known;
  for (const auto& [n, e] : registry()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown example '" + name + "' (known: " + known + ")");
}

} // namespace symmesh::io
