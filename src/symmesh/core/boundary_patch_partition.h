/// Algorithm 4.1 (boundary patch partition bndpart(X, T)), bndpart(X), Definition 4.8 (boundary
/// patch relation), Definition 4.9 (regular instance graph) — spec/boundary-patches.md#alg-4-1,
/// #def-4-8, #def-4-9
///
/// Algorithm 4.1 refines bnd*(T) by dom(f) and its boundary complement for every f ∈ 𝔗_X with
/// dom(f) ⊆ T. On the closed subdivision (boundary_subdivision.h) every dom(f) is a union of
/// faces, so two faces end up in the same element iff they lie in exactly the same domains,
/// i.e. iff the same words of mappings can be applied to them. Those classes are computed by
/// partition refinement (Moore's algorithm on the deterministic automaton face --f--> f(face)),
/// which needs no enumeration of 𝔗_X. A boundary patch is a connected union of faces of one
/// class (the three black pieces of Figure 4.10 are three patches); its dimension is that of its
/// largest face. Facet patches (dimension D-1) are the ones drawn in the dissertation's figures;
/// lower-dimensional patches appear where an interface is only a point or a segment.
///
/// The relation (Def 4.8) is the union-find closure of "a mapping sends patch A onto patch B".
/// Regularity is Eq. 4.13: all compositions that map a patch A onto the same patch B agree on A.
#pragma once
#include "symmesh/core/boundary_subdivision.h"
#include "symmesh/core/template_boundary_mapping.h"
#include "symmesh/core/templated_structure.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace symmesh::core {

struct BppOptions {
  /// Upper bound on subdivision vertices created by composing mappings (each one is the image
  /// of a domain vertex under a distinct composition); exceeding it throws
  /// CompositionLimitExceeded instead of running on.
  std::size_t max_compositions = 20000;
  /// The caller has checked x.is_well_formed() (an exact conformity check of every template);
  /// the BPP does not repeat it.
  bool well_formed_checked = false;
  /// Progress of the longest step, building the template boundary mappings: (candidate instance
  /// pairs decided, candidate pairs). Empty: no calls.
  std::function<void(std::size_t, std::size_t)> on_progress;
};

/// A face of some template: (template, face index in that template's subdivision).
struct FaceRef {
  std::size_t t = 0, f = 0;
  friend bool operator==(const FaceRef& a, const FaceRef& b) { return a.t == b.t && a.f == b.f; }
  friend bool operator<(const FaceRef& a, const FaceRef& b) {
    return a.t != b.t ? a.t < b.t : a.f < b.f;
  }
};

struct BoundaryPatch {
  std::size_t template_index = 0;
  int dimension = 0;              ///< largest face dimension
  std::vector<std::size_t> faces; ///< faces of the template's subdivision (sorted)
  std::size_t relation_class = 0; ///< index into BoundaryPatchPartition::classes
  std::size_t representative = 0; ///< a face of largest dimension
};

/// One edge of the patch graph: mapping `letter` sends patch `from` onto patch `to`.
struct PatchArrow {
  std::size_t from = 0, to = 0, letter = 0;
};

/// Witness of an irregular instance graph (Eq. 4.13 violated): F1 and F2 both map patch
/// `patch` onto patch `target` but differ on it, so F1^{-1} ∘ F2 is a non-trivial symmetry of
/// `patch` that every templated mesh must respect.
template <class FT, int D>
struct IrregularityWitness {
  std::size_t patch = 0, target = 0;
  Composition<FT, D> f1, f2;
  RigidTransformation<FT, D> symmetry; ///< F1^{-1} ∘ F2, maps `patch` onto itself
};

template <class FT, int D>
struct BoundaryPatchPartition {
  std::vector<TemplateBoundaryMapping<FT, D>> mappings;
  std::vector<BoundarySubdivision<FT, D>> subdivisions; ///< per template
  std::vector<std::vector<std::size_t>> face_class;     ///< language class of each face
  std::vector<std::vector<std::size_t>> face_patch;     ///< patch of each face
  std::vector<BoundaryPatch> patches;                   ///< ordered by template, then faces
  std::vector<std::vector<std::size_t>> classes;        ///< quotient set bndpart(X)/~ (sorted)
  std::vector<PatchArrow> arrows;                       ///< patch graph (one arrow per letter)
  /// The automaton's transitions by letter: letter_action[m] lists (face f of the from-template,
  /// face δ(f, m) of the to-template) for every face in the domain of mapping m, ordered by f.
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> letter_action;
  std::vector<std::optional<PatchArrow>> tree_parent; ///< BFS tree of each class (root: none)
  std::optional<IrregularityWitness<FT, D>> irregularity;

  bool regular() const { return !irregularity.has_value(); }
  /// bndpart(X, T_i), as patch indices.
  std::vector<std::size_t> bndpart(std::size_t template_index) const;
  /// Patches of dimension `dim` of template i (dim = D-1: facet patches).
  std::size_t patch_count(std::size_t template_index, int dim) const;
  /// Lemma 4.4 (i): a composition of mappings sending patch a onto patch b.
  /// \pre a and b are in the same relation class
  Composition<FT, D> composition_between(std::size_t a, std::size_t b) const;
  /// δ(face, letter) when the letter applies to the face.
  std::optional<FaceRef> step(FaceRef face, std::size_t letter) const;
  /// Face of template t containing x in its relative interior, if x ∈ bnd*(X_t).
  std::optional<std::size_t> locate(std::size_t t, const Point<FT, D>& x) const;
  /// The closed patch as simplices (coordinates).
  std::vector<std::vector<Point<FT, D>>> patch_simplices(std::size_t patch) const;

  bool is_valid(std::ostream* why = nullptr) const;
};

/// Algorithm 4.1 for every template of a templated structure (geometry or mesh templates; for a
/// mesh template the partition is that of its geometry us(X_i)), with the relation and the
/// regularity verdict. \pre x.is_well_formed() and no two instances overlap (Eq. 4.2); checked,
/// throws std::invalid_argument. Throws CompositionLimitExceeded past options.max_compositions.
template <class FT, int D>
BoundaryPatchPartition<FT, D> boundary_patch_partition(const TemplatedStructure<FT, D>& x,
                                                       const BppOptions& options = {});

/// 𝔗_X: every valid composition of mappings as a distinct restricted function — same map on
/// the same domain counts once — enumerated breadth-first over words. Finite because domains
/// are unions of subdivision faces and each face has finitely many face-to-face images; throws
/// CompositionLimitExceeded past `limit` elements.
template <class FT, int D>
struct RestrictedComposition {
  Composition<FT, D> composition;
  std::size_t from_template = 0, to_template = 0;
  std::vector<std::size_t> domain; ///< faces of the from-template (sorted)
};
template <class FT, int D>
std::vector<RestrictedComposition<FT, D>>
enumerate_compositions(const BoundaryPatchPartition<FT, D>& bpp, std::size_t limit);

/// Def 4.9 decided directly from an enumeration of 𝔗_X (for checking the fast verdict): some
/// two compositions map a patch A onto the same patch and differ on A.
template <class FT, int D>
bool regular_by_enumeration(const BoundaryPatchPartition<FT, D>& bpp,
                            const std::vector<RestrictedComposition<FT, D>>& all);

/// Section 5.2.2: where a template boundary vertex at x may move — the intersection of all closed
/// patches containing x — and whether it may move at all (not with an irregular graph, and not
/// when that intersection is the single point x, Figure 5.11).
template <class FT, int D>
struct VertexMovement {
  int dimension = 0;                              ///< of the allowed set
  std::vector<std::vector<Point<FT, D>>> allowed; ///< closed simplices covering the set
  std::vector<std::size_t> patches;               ///< the closed patches containing x
  bool can_move = false;
};
/// \pre x ∈ bnd*(X_t); throws std::invalid_argument otherwise
template <class FT, int D>
VertexMovement<FT, D> valid_vertex_movement(const BoundaryPatchPartition<FT, D>& bpp, std::size_t t,
                                            const Point<FT, D>& x);

} // namespace symmesh::core
