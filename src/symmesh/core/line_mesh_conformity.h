/// Lemma 4.2 on uniform line meshes, decided face by face — spec/lemmas.md#lemma-4-2-line-meshes
///
/// The generator's boundary complexes (Section 5.1.2 step iii) are line meshes of a special kind:
/// every face [a, b] of a template's boundary subdivision is split into N equal parts, with the
/// vertices a + (k/N)(b − a), k = 0..N. A rigid motion T is affine, so T sends that line mesh onto
/// the uniform N-split of [T(a), T(b)]. Condition (i) of Lemma 4.2 on AT of such boundary
/// complexes can therefore be decided per pair of transformed faces from their ends and their N:
///  - the same segment (ends equal as sets) with the same N: the two line meshes are equal;
///  - one common end and otherwise apart (not collinear, or collinear on opposite sides): the
///    faces, hence their line meshes, meet only in that common vertex;
///  - disjoint closed segments: nothing meets;
///  - anything else (overlap, a touch inside a face, a crossing, the same segment with another N)
///    is decided element by element on the two line meshes.
/// That makes the certificate cost the number of faces, not the number of line-mesh points.
#pragma once
#include "symmesh/core/interface_conformity.h"

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

namespace symmesh::core {

/// One template's boundary as faces split into equal parts (the line mesh of Algorithm 5.6).
template <class FT>
struct UniformLineMesh {
  struct Face {
    VertexId a = 0, b = 0;
    std::size_t parts = 1; ///< N >= 1
  };
  std::vector<Point<FT, 2>> points; ///< the face ends
  std::vector<Face> faces;

  /// Ends in range and distinct, N >= 1.
  bool is_valid(std::ostream* why = nullptr) const {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const auto& e = faces[f];
      const auto bad = [&](const char* what) {
        if (why) *why << "face " << f << ": " << what;
        return false;
      };
      if (e.a >= points.size() || e.b >= points.size()) return bad("end out of range");
      if (points[e.a] == points[e.b]) return bad("ends are equal");
      if (e.parts == 0) return bad("zero parts");
    }
    return true;
  }
};

/// Vertex k of the uniform N-split of [a, b]: a + (k/N)(b − a), exactly.
template <class FT>
Point<FT, 2> line_mesh_point(const Point<FT, 2>& a, const Point<FT, 2>& b, std::size_t k,
                             std::size_t n) {
  if (k == 0) return a;
  if (k == n) return b;
  const FT t = FT(int(k)) / FT(int(n));
  Point<FT, 2> p;
  for (int d = 0; d < 2; ++d) p[d] = a[d] + (b[d] - a[d]) * t;
  return p;
}

/// The line mesh of one face with the given (transformed) ends: its N + 1 points and its
/// vertices and segments in local ids.
template <class FT>
ElementComplex<FT, 2> face_line_mesh(const Point<FT, 2>& a, const Point<FT, 2>& b,
                                     std::size_t parts) {
  ElementComplex<FT, 2> c;
  for (std::size_t k = 0; k <= parts; ++k) {
    c.points.push_back(line_mesh_point<FT>(a, b, k, parts));
    c.elements.push_back(Simplex{VertexId(k)});
    if (k > 0) c.elements.push_back(Simplex{VertexId(k - 1), VertexId(k)});
  }
  c.normalize();
  return c;
}

/// A templated structure whose templates are uniform line meshes.
template <class FT>
struct LineMeshStructure {
  std::vector<UniformLineMesh<FT>> templates;
  std::vector<std::vector<InstanceSpec<FT, 2>>> instances;
};

/// The same structure with every template's line mesh written out as a complex (the faces'
/// line meshes merged by exact point equality, as AT merges instances), for the direct check
/// and the tests.
template <class FT>
TemplatedStructure<FT, 2> materialize(const LineMeshStructure<FT>& x) {
  TemplatedStructure<FT, 2> out;
  out.instances = x.instances;
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    const auto& t = x.templates[i];
    TemplatedStructure<FT, 2> faces;
    for (const auto& f : t.faces) {
      faces.templates.push_back(
          {"face", TemplateKind::mesh, face_line_mesh<FT>(t.points[f.a], t.points[f.b], f.parts)});
      faces.instances.push_back({InstanceSpec<FT, 2>{}});
    }
    Template<FT, 2> m{"line mesh " + std::to_string(i + 1), TemplateKind::mesh, {}};
    if (!faces.templates.empty()) m.mesh = apply_template(faces).at.mesh;
    m.mesh.normalize();
    out.templates.push_back(std::move(m));
  }
  return out;
}

namespace detail {

/// A transformed face in the sweep: its instance, its ends (exact) and N.
template <class FT>
struct SweptFace {
  std::size_t instance = 0;
  Point<FT, 2> a, b;
  std::size_t parts = 1;
  EnclosingBox<FT, 2> box;
};

/// Closed segments [p, q] and [r, s] certainly do not meet (exact signs).
template <class FT>
bool segments_apart(const Point<FT, 2>& p, const Point<FT, 2>& q, const Point<FT, 2>& r,
                    const Point<FT, 2>& s) {
  const int o1 = orientation_sign<FT>(p, q, r), o2 = orientation_sign<FT>(p, q, s);
  if (o1 * o2 > 0) return true;
  const int o3 = orientation_sign<FT>(r, s, p), o4 = orientation_sign<FT>(r, s, q);
  if (o3 * o4 > 0) return true;
  return false; // crossing, touching or collinear: left to the element check
}

/// How two transformed faces of different instances meet, from their ends and N alone: true when
/// their line meshes certainly conform, nullopt when they have to be compared element by element.
/// Ends are compared by exact equality (interval-filtered: only equal ends cost exact work).
template <class FT>
std::optional<bool> faces_decide(const SweptFace<FT>& p, const SweptFace<FT>& q) {
  const bool aa = p.a == q.a, ab = p.a == q.b, ba = p.b == q.a, bb = p.b == q.b;
  if ((aa && bb) || (ab && ba))
    return p.parts == q.parts ? std::optional<bool>(true) : std::nullopt;
  if (aa || ab || ba || bb) {
    const auto& o = (aa || ab) ? p.a : p.b;
    const auto& u = (aa || ab) ? p.b : p.a;
    const auto& w = (aa || ba) ? q.b : q.a;
    if (orientation_sign<FT>(o, u, w) != 0) return true;
    if (dot<FT, 2>(u - o, w - o) < 0) return true;
    return std::nullopt;
  }
  if (segments_apart<FT>(p.a, p.b, q.a, q.b)) return true;
  return std::nullopt;
}

/// Condition (i) between the line meshes of two transformed faces, element by element: the two
/// line meshes as a structure of two instances, through apply_template (exact point
/// identification) and the condition (i) sweep.
template <class FT>
bool line_meshes_conflict(const SweptFace<FT>& p, const SweptFace<FT>& q) {
  TemplatedStructure<FT, 2> two;
  for (const auto* f : {&p, &q}) {
    two.templates.push_back({"face", TemplateKind::mesh, face_line_mesh<FT>(f->a, f->b, f->parts)});
    two.instances.push_back({InstanceSpec<FT, 2>{}});
  }
  return !condition_i_failures(apply_template(two)).empty();
}

} // namespace detail

/// Lemma 4.2 (condition (i); (ii) is vacuous on boundary complexes, spec/lemmas.md#lemma-4-2-
/// boundary) for AT of uniform line meshes, face pair by face pair
/// (spec/lemmas.md#lemma-4-2-line-meshes). `rotation_copies` = n > 0: only the pairs of a copy 0
/// and a copy k <= n/2 are decided (spec/lemmas.md#lemma-4-2-rotational). The verdict equals the
/// direct check of AT(materialize(x)).
/// \pre every template is valid and its own line mesh is conforming (its faces meet only in
/// common ends); with rotation_copies = n > 0, every template has the n instances
/// T_{i,k} = R^k ∘ T_{i,0} for one rotation R of order n (checked by the caller)
template <class FT>
Lemma42Verdict check_line_mesh_conformity(const LineMeshStructure<FT>& x,
                                          std::size_t rotation_copies = 0) {
  using IBox = EnclosingBox<FT, 2>;
  std::vector<InstanceId> ids;
  for (std::size_t i = 0; i < x.instances.size(); ++i)
    for (std::size_t g = 0; g < x.instances[i].size(); ++g) ids.push_back({i, g});
  const auto copy0 = [&](std::size_t a) { return rotation_copies == 0 || ids[a].g == 0; };
  // Up to the rotation, a pair is decided when one side is a copy 0 and the other a copy
  // k <= n/2: R^{-k} turns ((i,0), (j,k)) into ((j,0), (i,n-k)) (lemma-4-2-rotational).
  const auto near_half = [&](std::size_t a) {
    return rotation_copies == 0 || 2 * ids[a].g <= rotation_copies;
  };
  const auto decided = [&](std::size_t a, std::size_t b) {
    return rotation_copies == 0 || (copy0(a) && near_half(b)) || (copy0(b) && near_half(a));
  };
  // Transformed face ends per instance, and the copies 0 boxes that the other copies must meet.
  std::vector<std::vector<Point<FT, 2>>> moved(ids.size());
  std::vector<IBox> copy0_boxes;
  for (std::size_t a = 0; a < ids.size(); ++a) {
    const auto& t = x.instances[ids[a].i][ids[a].g].transformation;
    const auto& tm = x.templates[ids[a].i];
    for (const auto& p : tm.points) moved[a].push_back(t(p));
    if (rotation_copies > 0 && copy0(a)) {
      std::vector<VertexId> all(moved[a].size());
      for (std::size_t v = 0; v < all.size(); ++v) all[v] = VertexId(v);
      copy0_boxes.push_back(IBox::of(moved[a], all));
    }
  }
  std::vector<detail::SweptFace<FT>> items;
  for (std::size_t a = 0; a < ids.size(); ++a)
    for (const auto& f : x.templates[ids[a].i].faces) {
      const std::array<VertexId, 2> ends{f.a, f.b};
      const auto box = IBox::of(moved[a], ends);
      if (!copy0(a) &&
          (!near_half(a) || std::none_of(copy0_boxes.begin(), copy0_boxes.end(),
                                         [&](const IBox& c) { return box.may_meet(c); })))
        continue;
      items.push_back({a, moved[a][f.a], moved[a][f.b], f.parts, box});
    }
  std::stable_sort(items.begin(), items.end(),
                   [](const auto& p, const auto& q) { return p.box.lo[0] < q.box.lo[0]; });
  Lemma42Verdict v;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t s = 0; s < items.size(); ++s) {
    const auto& p = items[s];
    for (std::size_t r = s + 1; r < items.size() && !(p.box.hi[0] < items[r].box.lo[0]); ++r) {
      const auto& q = items[r];
      if (p.instance == q.instance || !decided(p.instance, q.instance) || !p.box.may_meet(q.box, 1))
        continue;
      pairs.emplace_back(std::minmax(p.instance, q.instance));
      if (!v.holds) continue;
      const auto quick = detail::faces_decide<FT>(p, q);
      if (quick ? *quick : !detail::line_meshes_conflict<FT>(p, q)) continue;
      v.holds = false;
      v.a = ids[std::min(p.instance, q.instance)];
      v.b = ids[std::max(p.instance, q.instance)];
      v.condition = 1;
      v.detail = "the line meshes of two of their boundary faces (split into " +
                 std::to_string(p.parts) + " and " + std::to_string(q.parts) +
                 " parts) do not conform";
    }
  }
  std::sort(pairs.begin(), pairs.end());
  v.pairs_checked = std::size_t(std::unique(pairs.begin(), pairs.end()) - pairs.begin());
  return v;
}

} // namespace symmesh::core
