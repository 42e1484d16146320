// Definition 4.7 mappings, the closed boundary subdivision, Algorithm 4.1, Definitions 4.8 and
// 4.9 and the valid vertex movement of Section 5.2.2 — spec/boundary-patches.md
//
// CGAL is used here only: exact segment/triangle intersections for the mapping domains and, in
// 3D, constrained triangulations of each boundary triangle with its cuts. The public headers
// stay free of CGAL.
//
// Definitions only, included by the translation units that instantiate them for one number
// type each (boundary_patch_partition.cpp: rationals; cyclotomic_instantiations.cpp: K_m).
//
// Part 3 (after template_boundary_mapping_impl.h and boundary_subdivision_impl.h): the face
// automaton, Moore refinement, patches, the relation, regularity, the enumeration of 𝔗_X and the
// valid vertex movement.
#pragma once
#include "symmesh/core/boundary_subdivision_impl.h"

namespace symmesh::core {
namespace {

// ---------------------------------------------------------------------------------------------
// Face automaton, Moore refinement, patches, relation, regularity.

template <class FT, int D>
using FaceKey = std::pair<int, std::vector<VertexId>>;

template <class FT, int D>
std::vector<std::map<FaceKey<FT, D>, std::size_t>>
face_keys(const std::vector<BoundarySubdivision<FT, D>>& sub) {
  std::vector<std::map<FaceKey<FT, D>, std::size_t>> out(sub.size());
  for (std::size_t t = 0; t < sub.size(); ++t)
    for (std::size_t f = 0; f < sub[t].faces.size(); ++f) {
      const auto& face = sub[t].faces[f];
      if (!out[t].emplace(FaceKey<FT, D>{face.dimension, face.vertices}, f).second)
        throw std::logic_error("boundary subdivision: two faces with the same vertices");
    }
  return out;
}

} // namespace

template <class FT, int D>
BoundaryPatchPartition<FT, D> boundary_patch_partition(const TemplatedStructure<FT, D>& x,
                                                       const BppOptions& options) {
  BoundaryPatchPartition<FT, D> r;
  r.mappings = template_boundary_mappings(x, !options.well_formed_checked, options.on_progress);
  const std::size_t nt = x.templates.size();
  const auto ix = index_mappings<FT, D>(r.mappings, nt);
  if constexpr (D == 2)
    r.subdivisions = close_subdivisions_2d<FT>(x, r.mappings, ix, options);
  else
    r.subdivisions = close_subdivisions_3d<FT>(x, r.mappings, ix, options);
  const auto keys = face_keys<FT, D>(r.subdivisions);

  // Global state numbering and transitions δ(s, letter).
  std::vector<std::size_t> offset(nt + 1, 0);
  for (std::size_t t = 0; t < nt; ++t) offset[t + 1] = offset[t] + r.subdivisions[t].faces.size();
  const std::size_t ns = offset[nt];
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> delta(ns);
  r.letter_action.resize(r.mappings.size());
  for (std::size_t m = 0; m < r.mappings.size(); ++m) {
    const auto& mp = r.mappings[m];
    const std::size_t s = mp.from_template(), d = mp.to_template();
    const auto& src = r.subdivisions[s];
    const auto& dst = r.subdivisions[d];
    for (std::size_t f = 0; f < src.faces.size(); ++f) {
      if (!applies<FT, D>(mp, ix.box[m], src.rep[f])) continue;
      std::size_t g = f;
      if (!mp.whole_boundary) {
        std::vector<VertexId> img;
        for (VertexId v : src.faces[f].vertices)
          img.push_back(vertex_id(dst, apply_mapping<FT, D>(r.mappings, m, src.points[v])));
        std::sort(img.begin(), img.end());
        auto it = keys[d].find({src.faces[f].dimension, img});
        if (it == keys[d].end())
          throw std::logic_error(
              "boundary subdivision: a mapping does not send a face onto a face");
        g = it->second;
      }
      delta[offset[s] + f].emplace_back(m, offset[d] + g);
      r.letter_action[m].emplace_back(f, g);
    }
  }

  // Partition refinement to classes of equal languages (= equal Algorithm 4.1 signatures):
  // Moore's algorithm, but each round re-examines only states whose successors changed block, so
  // a long chain of faces (one split per round) costs O(n) rather than O(n^2).
  std::vector<std::size_t> block(ns);
  {
    std::vector<std::vector<std::size_t>> pred(ns);
    for (std::size_t s = 0; s < ns; ++s)
      for (const auto& [m, g] : delta[s]) pred[g].push_back(s);
    std::map<std::vector<std::size_t>, std::size_t> ids;
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t s = offset[t]; s < offset[t + 1]; ++s) {
        std::vector<std::size_t> key{t};
        for (const auto& [m, g] : delta[s]) key.push_back(m);
        block[s] = ids.emplace(key, ids.size()).first->second;
      }
    // Rounds use the block ids of the round's start (moves are applied at its end). In a block,
    // members not marked dirty share their successor blocks (nothing they point to moved since
    // the block was last checked), so the dirty members with another key split off; if all are
    // dirty, the largest group keeps the id. A block with one key is never renamed, so every
    // round splits a block or ends the loop.
    std::vector<std::vector<std::size_t>> members(ids.size());
    std::vector<std::size_t> pos(ns);
    for (std::size_t s = 0; s < ns; ++s) {
      pos[s] = members[block[s]].size();
      members[block[s]].push_back(s);
    }
    auto key_of = [&](std::size_t s) {
      std::vector<std::size_t> k;
      for (const auto& [m, g] : delta[s]) k.push_back(block[g]);
      return k;
    };
    std::vector<std::size_t> dirty(ns);
    for (std::size_t s = 0; s < ns; ++s) dirty[s] = s;
    std::vector<char> is_dirty(ns, 1);
    while (!dirty.empty()) {
      std::map<std::size_t, std::vector<std::size_t>> by_block;
      for (std::size_t s : dirty) by_block[block[s]].push_back(s);
      std::vector<std::pair<std::size_t, std::size_t>> moves;
      for (auto& [b, ds] : by_block) {
        std::optional<std::vector<std::size_t>> stay;
        if (ds.size() < members[b].size())
          for (std::size_t m : members[b])
            if (!is_dirty[m]) {
              stay = key_of(m);
              break;
            }
        std::map<std::vector<std::size_t>, std::vector<std::size_t>> groups;
        for (std::size_t s : ds) groups[key_of(s)].push_back(s);
        if (!stay) {
          stay = groups.begin()->first;
          for (const auto& [k, g] : groups)
            if (g.size() > groups[*stay].size()) stay = k;
        }
        for (const auto& [k, g] : groups) {
          if (k == *stay) continue;
          const std::size_t nb = members.size();
          members.emplace_back();
          for (std::size_t s : g) moves.emplace_back(s, nb);
        }
      }
      for (std::size_t s : dirty) is_dirty[s] = 0;
      dirty.clear();
      for (const auto& [s, nb] : moves) {
        auto& from = members[block[s]];
        pos[from.back()] = pos[s];
        from[pos[s]] = from.back();
        from.pop_back();
        pos[s] = members[nb].size();
        members[nb].push_back(s);
        block[s] = nb;
      }
      for (const auto& [s, nb] : moves)
        for (std::size_t q : pred[s])
          if (!is_dirty[q]) {
            is_dirty[q] = 1;
            dirty.push_back(q);
          }
    }
    // Dense, deterministic class numbers (first occurrence order).
    std::map<std::size_t, std::size_t> dense;
    for (std::size_t s = 0; s < ns; ++s)
      block[s] = dense.emplace(block[s], dense.size()).first->second;
  }

  // Patches: connected unions of faces of one class (incidence through closures).
  r.face_class.resize(nt);
  r.face_patch.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& sub = r.subdivisions[t];
    const std::size_t n = sub.faces.size();
    std::vector<std::size_t> rank(n), parent(n);
    boost::disjoint_sets<std::size_t*, std::size_t*> ds(rank.data(), parent.data());
    for (std::size_t f = 0; f < n; ++f) ds.make_set(f);
    r.face_class[t].resize(n);
    for (std::size_t f = 0; f < n; ++f) {
      r.face_class[t][f] = block[offset[t] + f];
      for (std::size_t g : sub.faces[f].closure)
        if (block[offset[t] + g] == block[offset[t] + f]) ds.union_set(f, g);
    }
    std::map<std::size_t, std::size_t> patch_of_root;
    r.face_patch[t].resize(n);
    for (std::size_t f = 0; f < n; ++f) {
      const std::size_t root = ds.find_set(f);
      auto [it, fresh] = patch_of_root.emplace(root, r.patches.size());
      if (fresh) {
        BoundaryPatch p;
        p.template_index = t;
        p.dimension = -1;
        r.patches.push_back(p);
      }
      auto& p = r.patches[it->second];
      p.faces.push_back(f);
      if (sub.faces[f].dimension > p.dimension) {
        p.dimension = sub.faces[f].dimension;
        p.representative = f;
      }
      r.face_patch[t][f] = it->second;
    }
  }

  // Patch graph and the relation (Def 4.8) by union-find.
  const std::size_t np = r.patches.size();
  std::vector<std::size_t> prank(np), pparent(np);
  boost::disjoint_sets<std::size_t*, std::size_t*> pds(prank.data(), pparent.data());
  for (std::size_t p = 0; p < np; ++p) pds.make_set(p);
  std::vector<std::vector<std::size_t>> out_arrows(np);
  for (std::size_t p = 0; p < np; ++p) {
    const auto& patch = r.patches[p];
    for (const auto& [m, g] : delta[offset[patch.template_index] + patch.representative]) {
      std::size_t gt = 0;
      while (offset[gt + 1] <= g) ++gt;
      const std::size_t q = r.face_patch[gt][g - offset[gt]];
      out_arrows[p].push_back(r.arrows.size());
      r.arrows.push_back({p, q, m});
      pds.union_set(p, q);
    }
  }
  {
    std::map<std::size_t, std::size_t> class_of_root;
    for (std::size_t p = 0; p < np; ++p) {
      auto [it, fresh] = class_of_root.emplace(pds.find_set(p), r.classes.size());
      if (fresh) r.classes.emplace_back();
      r.classes[it->second].push_back(p);
      r.patches[p].relation_class = it->second;
    }
  }

  // BFS per class with composition potentials; an inconsistent arrow witnesses irregularity
  // (Eq. 4.13). Two rigid maps agree on a patch iff they agree on an affine basis of its vertices,
  // and every mapping sends subdivision vertices to subdivision vertices, so a potential is kept
  // as the vertex ids of the basis images, read off the automaton on vertex faces: no products
  // of exact maps (the words are read off the BFS tree when needed).
  auto vertex_step = [&](std::size_t t, VertexId v, std::size_t letter) {
    const auto& out = delta[offset[t] + v];
    const auto it =
        std::lower_bound(out.begin(), out.end(), std::make_pair(letter, std::size_t(0)));
    if (it == out.end() || it->first != letter)
      throw std::logic_error("boundary subdivision: a mapping applies to a patch but not to a "
                             "vertex of its closure");
    return VertexId(it->second - offset[r.mappings[letter].to_template()]);
  };
  r.tree_parent.assign(np, std::nullopt);
  std::vector<std::optional<std::vector<VertexId>>> pot(np);
  for (const auto& cls : r.classes) {
    const std::size_t root = cls.front();
    const auto& rs = r.subdivisions[r.patches[root].template_index];
    std::vector<VertexId> ids; // in lexicographic point order, as the subdivision numbers them
    for (std::size_t f : r.patches[root].faces)
      for (VertexId v : rs.faces[f].vertices) ids.push_back(v);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<VertexId> basis;
    PointVec<FT, D> basis_points;
    for (VertexId v : ids) {
      if (int(basis.size()) == D + 1) break;
      basis_points.push_back(rs.points[v]);
      if (affinely_independent<FT, D>(basis_points))
        basis.push_back(v);
      else
        basis_points.pop_back();
    }
    pot[root] = basis;
    std::deque<std::size_t> queue{root};
    while (!queue.empty()) {
      const std::size_t p = queue.front();
      queue.pop_front();
      for (std::size_t ai : out_arrows[p]) {
        const auto& a = r.arrows[ai];
        std::vector<VertexId> c;
        for (VertexId v : *pot[p])
          c.push_back(vertex_step(r.patches[p].template_index, v, a.letter));
        if (!pot[a.to]) {
          pot[a.to] = std::move(c);
          r.tree_parent[a.to] = a;
          queue.push_back(a.to);
        } else if (!r.irregularity && *pot[a.to] != c) {
          IrregularityWitness<FT, D> w;
          w.patch = root;
          w.target = a.to;
          w.f1 = r.composition_between(root, a.to);
          auto f2 = r.composition_between(root, p).letters;
          f2.push_back(a.letter);
          w.f2 = compose<FT, D>(r.mappings, f2);
          w.symmetry = w.f1.map.inverse() * w.f2.map;
          r.irregularity = w;
        }
      }
    }
  }
  return r;
}

template <class FT, int D>
std::vector<std::size_t> BoundaryPatchPartition<FT, D>::bndpart(std::size_t t) const {
  std::vector<std::size_t> out;
  for (std::size_t p = 0; p < patches.size(); ++p)
    if (patches[p].template_index == t) out.push_back(p);
  return out;
}

template <class FT, int D>
std::size_t BoundaryPatchPartition<FT, D>::patch_count(std::size_t t, int dim) const {
  std::size_t n = 0;
  for (const auto& p : patches)
    if (p.template_index == t && p.dimension == dim) ++n;
  return n;
}

template <class FT, int D>
Composition<FT, D> BoundaryPatchPartition<FT, D>::composition_between(std::size_t a,
                                                                      std::size_t b) const {
  if (patches.at(a).relation_class != patches.at(b).relation_class)
    throw std::invalid_argument("composition_between: patches are not related");
  auto path = [&](std::size_t p) {
    std::vector<std::size_t> letters;
    while (tree_parent[p]) {
      letters.push_back(tree_parent[p]->letter);
      p = tree_parent[p]->from;
    }
    std::reverse(letters.begin(), letters.end());
    return letters;
  };
  const auto pa = path(a), pb = path(b);
  std::vector<std::size_t> letters;
  for (auto it = pa.rbegin(); it != pa.rend(); ++it) letters.push_back(mappings[*it].inverse);
  letters.insert(letters.end(), pb.begin(), pb.end());
  return compose<FT, D>(mappings, letters);
}

template <class FT, int D>
std::optional<FaceRef> BoundaryPatchPartition<FT, D>::step(FaceRef face, std::size_t letter) const {
  const auto& m = mappings.at(letter);
  if (m.from_template() != face.t) return std::nullopt;
  const auto& src = subdivisions[face.t];
  if (!m.in_domain(src.rep.at(face.f))) return std::nullopt;
  if (m.whole_boundary) return face;
  const auto& dst = subdivisions[m.to_template()];
  std::vector<VertexId> img;
  for (VertexId v : src.faces[face.f].vertices) img.push_back(vertex_id(dst, m.map(src.points[v])));
  std::sort(img.begin(), img.end());
  for (std::size_t g = 0; g < dst.faces.size(); ++g)
    if (dst.faces[g].dimension == src.faces[face.f].dimension && dst.faces[g].vertices == img)
      return FaceRef{m.to_template(), g};
  throw std::logic_error("boundary subdivision: a mapping does not send a face onto a face");
}

template <class FT, int D>
std::optional<std::size_t> BoundaryPatchPartition<FT, D>::locate(std::size_t t,
                                                                 const Point<FT, D>& x) const {
  const auto& s = subdivisions.at(t);
  auto it = std::lower_bound(s.points.begin(), s.points.end(), x, PointLess<FT, D>());
  if (it != s.points.end() && *it == x) return std::size_t(it - s.points.begin());
  for (int dim = 1; dim < D; ++dim)
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      if (s.faces[f].dimension != dim) continue;
      for (const auto& piece : s.faces[f].pieces) {
        PointVec<FT, D> c;
        for (VertexId v : piece) c.push_back(s.points[v]);
        if (dim == 1 ? point_on_segment<FT, D>(c[0], c[1], x) : point_in_simplex<FT, D>(c, x))
          return f;
      }
    }
  return std::nullopt;
}

template <class FT, int D>
std::vector<std::vector<Point<FT, D>>>
BoundaryPatchPartition<FT, D>::patch_simplices(std::size_t p) const {
  const auto& patch = patches.at(p);
  const auto& s = subdivisions[patch.template_index];
  std::vector<std::vector<Point<FT, D>>> out;
  for (std::size_t f : patch.faces)
    for (const auto& piece : s.faces[f].pieces) {
      std::vector<Point<FT, D>> c;
      for (VertexId v : piece) c.push_back(s.points[v]);
      out.push_back(std::move(c));
    }
  return out;
}

template <class FT, int D>
bool BoundarySubdivision<FT, D>::is_valid(std::ostream* why) const {
  auto fail = [&](const std::string& m) {
    if (why) *why << m;
    return false;
  };
  if (!std::is_sorted(points.begin(), points.end(), PointLess<FT, D>()))
    return fail("subdivision vertices are not in lexicographic order");
  if (faces.size() != rep.size()) return fail("a face has no representative point");
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    if (f < points.size() &&
        (face.dimension != 0 || face.vertices != std::vector<VertexId>{VertexId(f)}))
      return fail("face " + std::to_string(f) + " should be vertex " + std::to_string(f));
    if (face.dimension < 0 || face.dimension >= D) return fail("face dimension out of range");
    for (std::size_t g : face.closure)
      if (g >= faces.size() || faces[g].dimension >= face.dimension)
        return fail("face " + std::to_string(f) + " has an invalid closure face");
    for (VertexId v : face.vertices)
      if (v >= points.size()) return fail("face vertex out of range");
  }
  return true;
}

template <class FT, int D>
bool BoundaryPatchPartition<FT, D>::is_valid(std::ostream* why) const {
  auto fail = [&](const std::string& m) {
    if (why) *why << m;
    return false;
  };
  for (const auto& s : subdivisions)
    if (!s.is_valid(why)) return false;
  std::vector<std::set<std::size_t>> covered(subdivisions.size());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const auto& patch = patches[p];
    if (patch.faces.empty()) return fail("empty patch " + std::to_string(p));
    for (std::size_t f : patch.faces) {
      if (!covered[patch.template_index].insert(f).second)
        return fail("a face lies in two patches");
      if (face_patch[patch.template_index][f] != p) return fail("face_patch disagrees");
    }
    if (std::find(classes.at(patch.relation_class).begin(), classes[patch.relation_class].end(),
                  p) == classes[patch.relation_class].end())
      return fail("patch missing from its relation class");
  }
  for (std::size_t t = 0; t < subdivisions.size(); ++t)
    if (covered[t].size() != subdivisions[t].faces.size())
      return fail("template " + std::to_string(t + 1) + ": patches do not cover the boundary");
  for (const auto& a : arrows)
    if (patches.at(a.from).relation_class != patches.at(a.to).relation_class)
      return fail("an arrow joins two relation classes");
  return true;
}

// ---------------------------------------------------------------------------------------------
// 𝔗_X enumeration and the brute-force regularity verdict.

template <class FT, int D>
std::vector<RestrictedComposition<FT, D>>
enumerate_compositions(const BoundaryPatchPartition<FT, D>& bpp, std::size_t limit) {
  struct State {
    RestrictedComposition<FT, D> rc;
    std::vector<FaceRef> image; ///< image face of each domain face
  };
  std::vector<State> all;
  std::set<std::tuple<std::size_t, std::size_t, std::vector<std::size_t>, std::vector<VertexId>>>
      seen;
  auto admit = [&](State st) {
    if (st.rc.domain.empty()) return;
    std::vector<VertexId> imgs;
    const auto& src = bpp.subdivisions[st.rc.from_template];
    const auto& dst = bpp.subdivisions[st.rc.to_template];
    std::set<VertexId> dv;
    for (std::size_t f : st.rc.domain)
      for (VertexId v : src.faces[f].vertices) dv.insert(v);
    for (VertexId v : dv) imgs.push_back(vertex_id(dst, st.rc.composition.map(src.points[v])));
    if (!seen.emplace(st.rc.from_template, st.rc.to_template, st.rc.domain, imgs).second) return;
    if (all.size() >= limit) {
      std::ostringstream m;
      m << "𝔗_X has more than " << limit << " distinct compositions; raise the limit to go on";
      throw CompositionLimitExceeded(m.str());
    }
    all.push_back(std::move(st));
  };
  for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
    const auto& m = bpp.mappings[l];
    State st;
    st.rc.composition = compose<FT, D>(bpp.mappings, {l});
    st.rc.from_template = m.from_template();
    st.rc.to_template = m.to_template();
    for (std::size_t f = 0; f < bpp.subdivisions[m.from_template()].faces.size(); ++f)
      if (auto g = bpp.step({m.from_template(), f}, l)) {
        st.rc.domain.push_back(f);
        st.image.push_back(*g);
      }
    admit(std::move(st));
  }
  for (std::size_t k = 0; k < all.size(); ++k)
    for (std::size_t l = 0; l < bpp.mappings.size(); ++l) {
      if (bpp.mappings[l].from_template() != all[k].rc.to_template) continue;
      State st;
      st.rc.composition = all[k].rc.composition;
      st.rc.composition.letters.push_back(l);
      st.rc.composition.map = bpp.mappings[l].map * st.rc.composition.map;
      st.rc.from_template = all[k].rc.from_template;
      st.rc.to_template = bpp.mappings[l].to_template();
      for (std::size_t q = 0; q < all[k].rc.domain.size(); ++q)
        if (auto g = bpp.step(all[k].image[q], l)) {
          st.rc.domain.push_back(all[k].rc.domain[q]);
          st.image.push_back(*g);
        }
      admit(std::move(st));
    }
  std::vector<RestrictedComposition<FT, D>> out;
  for (auto& s : all) out.push_back(std::move(s.rc));
  return out;
}

template <class FT, int D>
bool regular_by_enumeration(const BoundaryPatchPartition<FT, D>& bpp,
                            const std::vector<RestrictedComposition<FT, D>>& all) {
  for (std::size_t p = 0; p < bpp.patches.size(); ++p) {
    const auto& patch = bpp.patches[p];
    const auto& src = bpp.subdivisions[patch.template_index];
    PointVec<FT, D> verts;
    for (std::size_t f : patch.faces)
      for (VertexId v : src.faces[f].vertices) verts.push_back(src.points[v]);
    std::map<std::size_t, const RigidTransformation<FT, D>*> by_target;
    for (const auto& c : all) {
      if (c.from_template != patch.template_index) continue;
      if (!std::binary_search(c.domain.begin(), c.domain.end(), patch.representative)) continue;
      // Image patch of the representative face under c.
      FaceRef f{patch.template_index, patch.representative};
      for (std::size_t l : c.composition.letters) f = *bpp.step(f, l);
      const std::size_t target = bpp.face_patch[f.t][f.f];
      auto [it, fresh] = by_target.emplace(target, &c.composition.map);
      if (fresh) continue;
      for (const auto& v : verts)
        if ((*it->second)(v) != c.composition.map(v)) return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// Section 5.2.2.

template <class FT, int D>
VertexMovement<FT, D> valid_vertex_movement(const BoundaryPatchPartition<FT, D>& bpp, std::size_t t,
                                            const Point<FT, D>& x) {
  const auto face = bpp.locate(t, x);
  if (!face)
    throw std::invalid_argument("valid_vertex_movement: the point is not on the boundary of "
                                "template " +
                                std::to_string(t + 1));
  const auto& s = bpp.subdivisions[t];
  auto closed = [&](std::size_t p) {
    std::set<std::size_t> c;
    for (std::size_t f : bpp.patches[p].faces) {
      c.insert(f);
      c.insert(s.faces[f].closure.begin(), s.faces[f].closure.end());
    }
    return c;
  };
  VertexMovement<FT, D> mv;
  std::optional<std::set<std::size_t>> meet;
  for (std::size_t p : bpp.bndpart(t)) {
    const auto c = closed(p);
    if (!c.count(*face)) continue;
    mv.patches.push_back(p);
    if (!meet) {
      meet = c;
      continue;
    }
    std::set<std::size_t> both;
    std::set_intersection(meet->begin(), meet->end(), c.begin(), c.end(),
                          std::inserter(both, both.end()));
    meet = std::move(both);
  }
  mv.dimension = 0;
  for (std::size_t f : *meet) {
    mv.dimension = std::max(mv.dimension, s.faces[f].dimension);
    for (const auto& piece : s.faces[f].pieces) {
      std::vector<Point<FT, D>> c;
      for (VertexId v : piece) c.push_back(s.points[v]);
      mv.allowed.push_back(std::move(c));
    }
  }
  mv.can_move = bpp.regular() && mv.dimension > 0;
  return mv;
}

#define SYMMESH_BPP_INSTANTIATE(FT, D)                                                             \
  template std::vector<TemplateBoundaryMapping<FT, D>> template_boundary_mappings<FT, D>(          \
      const TemplatedStructure<FT, D>&, bool,                                                      \
      const std::function<void(std::size_t, std::size_t)>&,                                        \
      const std::function<bool(InstanceId, InstanceId)>&);                                         \
  template BoundaryPatchPartition<FT, D> boundary_patch_partition<FT, D>(                          \
      const TemplatedStructure<FT, D>&, const BppOptions&);                                        \
  template struct BoundaryPatchPartition<FT, D>;                                                   \
  template struct BoundarySubdivision<FT, D>;                                                      \
  template std::vector<RestrictedComposition<FT, D>> enumerate_compositions<FT, D>(                \
      const BoundaryPatchPartition<FT, D>&, std::size_t);                                          \
  template bool regular_by_enumeration<FT, D>(const BoundaryPatchPartition<FT, D>&,                \
                                              const std::vector<RestrictedComposition<FT, D>>&);   \
  template VertexMovement<FT, D> valid_vertex_movement<FT, D>(                                     \
      const BoundaryPatchPartition<FT, D>&, std::size_t, const Point<FT, D>&);

} // namespace symmesh::core
