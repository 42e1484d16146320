/// Definition A.17 (k-simplex) and A.9 (facets and faces of a simplex) —
/// spec/definitions.md#def-a-17
///
/// A simplex is stored combinatorially as the sorted tuple of its vertex indices into a point
/// array. Two simplices over the same point array are the same set exactly when their tuples
/// are equal, provided no two indices carry equal coordinates (checked by `is_valid`).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <vector>

namespace symmesh::core {

using VertexId = std::uint32_t;

struct Simplex {
  std::array<VertexId, 4> v{};
  std::uint8_t n = 0; ///< number of vertices = dimension + 1

  Simplex() = default;
  Simplex(std::initializer_list<VertexId> ids) {
    /// \pre 1 <= ids.size() <= 4 and the ids are pairwise distinct
    if (ids.size() == 0 || ids.size() > 4)
      throw std::invalid_argument("simplex needs 1..4 vertices");
    for (VertexId id : ids) v[n++] = id;
    normalize();
  }
  static Simplex from_range(const VertexId* b, const VertexId* e) {
    Simplex s;
    if (e - b <= 0 || e - b > 4) throw std::invalid_argument("simplex needs 1..4 vertices");
    for (; b != e; ++b) s.v[s.n++] = *b;
    s.normalize();
    return s;
  }
  int dim() const { return int(n) - 1; }
  const VertexId* begin() const { return v.data(); }
  const VertexId* end() const { return v.data() + n; }
  bool has_vertex(VertexId id) const { return std::find(begin(), end(), id) != end(); }
  bool is_face_of(const Simplex& s) const {
    return std::includes(s.begin(), s.end(), begin(), end());
  }
  friend bool operator==(const Simplex& a, const Simplex& b) {
    return a.n == b.n && std::equal(a.begin(), a.end(), b.begin());
  }
  friend bool operator!=(const Simplex& a, const Simplex& b) { return !(a == b); }
  friend bool operator<(const Simplex& a, const Simplex& b) {
    if (a.n != b.n) return a.n < b.n;
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
  }

private:
  void normalize() {
    std::sort(v.begin(), v.begin() + n);
    if (std::adjacent_find(v.begin(), v.begin() + n) != v.begin() + n)
      throw std::invalid_argument("simplex has a repeated vertex");
  }
};

/// facets(S), Eq. A.16: the simplices on all (k)-subsets of the k+1 vertices.
inline std::vector<Simplex> facets(const Simplex& s) {
  std::vector<Simplex> out;
  if (s.n <= 1) return out;
  for (int skip = 0; skip < s.n; ++skip) {
    Simplex f;
    for (int i = 0; i < s.n; ++i)
      if (i != skip) f.v[f.n++] = s.v[i];
    out.push_back(f);
  }
  return out;
}

/// faces(S), Eq. A.6: every non-empty vertex subset, S included.
inline std::vector<Simplex> faces(const Simplex& s) {
  std::vector<Simplex> out;
  const unsigned full = (1u << s.n);
  for (unsigned mask = 1; mask < full; ++mask) {
    Simplex f;
    for (int i = 0; i < s.n; ++i)
      if (mask & (1u << i)) f.v[f.n++] = s.v[i];
    out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

} // namespace symmesh::core
