/// RapidCheck generators of templated structures for the boundary patch partition
/// (Section 4.3, Lemmas 4.3 and 4.4, Definition 4.9) — spec/traceability.md#generators
///
/// Families with interesting patch structure beyond the tiers of generators.h: a box touching a
/// half-turned copy of itself (Figure 4.11, irregular), a box touching a shifted translate
/// (partial contact, not a templated mesh), the indirect-neighbour chain of Figure 4.7, and
/// order-4 rotational slices, one- and two-region (Figures 6.7, 6.8).
#pragma once
#include "proofs-checks/generators.h"

namespace symmesh::proofs::gen {

/// Figure 4.11: a box mesh T and its half turn about an axis in its face x_0 = 1; the contact is
/// mapped onto itself reversed, so the instance graph is irregular.
template <int D>
rc::Gen<GeneratedStructure<D>> self_contact_structure();

/// A box mesh and its translate by e_0 + t e_1 (0 < t < 1): the contact is part of a face, so the
/// patch boundary cuts a template boundary element — a templated structure, not a templated mesh.
template <int D>
rc::Gen<GeneratedStructure<D>> shifted_translation_structure();

/// Figure 4.7: templates X1, X2 (two instances), X3 in a chain X1 | X2 ... X2 | X3 so that X1 and
/// X3 are indirect neighbours; box sizes and offsets vary, so contacts can be partial (aligned:
/// equal heights, full-face contacts, so X1's face ~ X2's face ~ X3's face always).
template <int D>
rc::Gen<GeneratedStructure<D>> indirect_chain_structure(bool aligned = false);

/// Figures 6.7 / 6.8: a 90° slice about the origin (2D) or the z axis (3D), instanced by the four
/// rotations; optionally split radially into two region templates.
template <int D>
rc::Gen<GeneratedStructure<D>> rotational_slice_structure();

/// All of the above and templated_structure() (reflections, grids, split templates, Figure 4.4).
template <int D>
rc::Gen<GeneratedStructure<D>> bpp_structure();

/// Templated meshes only (valid_templated_mesh() and the rotational slices).
template <int D>
rc::Gen<GeneratedStructure<D>> bpp_templated_mesh();

/// A random rational rigid motion (quarter turns, an integer quaternion in 3D, a reflection in a
/// rational hyperplane, a small translation), for metamorphic properties.
template <int D>
rc::Gen<Described<Motion<D>>> bpp_motion();

} // namespace symmesh::proofs::gen
