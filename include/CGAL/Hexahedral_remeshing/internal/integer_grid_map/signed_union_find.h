// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SIGNED_UNION_FIND_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SIGNED_UNION_FIND_H

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Union-find on scalars related by x_a = +-x_b (the seamless transitions of uncut faces are signed
// permutations, so every corner coordinate equals plus or minus a coordinate of its neighbour, as in
// evouga/CubeCover). Each element stores its sign relative to its parent. Joining two elements that
// are already in one class with the opposite sign means x = -x: the class is marked contradicted (its
// only value is 0), which happens only with a bad cut or inconsistent matchings. The smaller root wins,
// so the classes do not depend on the order of the unions.
class Signed_union_find
{
public:
  explicit Signed_union_find(std::size_t n) : m_parent(n), m_sign(n, 1), m_contradicted(n, 0)
  {
    std::iota(m_parent.begin(), m_parent.end(), std::uint32_t(0));
  }

  // (root, s) with x = s * x_root.
  std::pair<std::uint32_t, int> find(std::uint32_t x)
  {
    // two passes: find the root and the sign, then compress the path
    std::uint32_t r = x;
    int s = 1;
    while(m_parent[r] != r) { s *= m_sign[r]; r = m_parent[r]; }
    std::uint32_t y = x;
    int sy = s; // sign of y relative to the root
    while(m_parent[y] != y) {
      const std::uint32_t next = m_parent[y];
      const int snext = sy * m_sign[y]; // sign of next relative to the root
      m_parent[y] = r;
      m_sign[y] = std::int8_t(sy);
      y = next;
      sy = snext;
    }
    return {r, s};
  }

  // Imposes x_a = sign * x_b; returns false if it contradicts the previous unions.
  bool unite(std::uint32_t a, std::uint32_t b, int sign)
  {
    const auto [ra, sa] = find(a);
    const auto [rb, sb] = find(b);
    // sa x_ra = sign sb x_rb
    const int s = sa * sign * sb; // x_ra = s x_rb
    if(ra == rb) {
      if(s != 1) { m_contradicted[ra] = 1; return false; }
      return true;
    }
    const char c = char(m_contradicted[ra] | m_contradicted[rb]);
    if(ra < rb) { m_parent[rb] = ra; m_sign[rb] = std::int8_t(s); m_contradicted[ra] = c; }
    else { m_parent[ra] = rb; m_sign[ra] = std::int8_t(s); m_contradicted[rb] = c; }
    return true;
  }

  bool contradicted(std::uint32_t x) { return m_contradicted[find(x).first] != 0; }
  std::size_t size() const { return m_parent.size(); }

private:
  std::vector<std::uint32_t> m_parent;
  std::vector<std::int8_t> m_sign;
  std::vector<char> m_contradicted;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SIGNED_UNION_FIND_H
