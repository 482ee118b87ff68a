// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNION_FIND_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNION_FIND_H

#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Plain union-find on 0..n-1 with path halving; the smaller root wins so that results are
// independent of the order of the unions (deterministic component numbering).
class Union_find
{
public:
  explicit Union_find(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), std::uint32_t(0)); }
  std::uint32_t find(std::uint32_t x)
  {
    while(m_parent[x] != x) { m_parent[x] = m_parent[m_parent[x]]; x = m_parent[x]; }
    return x;
  }
  bool unite(std::uint32_t a, std::uint32_t b)
  {
    a = find(a); b = find(b);
    if(a == b) return false;
    if(a < b) m_parent[b] = a; else m_parent[a] = b;
    return true;
  }
  // Component number of every element, numbered by first appearance.
  std::vector<std::uint32_t> labels(std::size_t& number_of_labels)
  {
    std::vector<std::uint32_t> label(m_parent.size(), std::uint32_t(-1)), out(m_parent.size());
    number_of_labels = 0;
    for(std::size_t i = 0; i < m_parent.size(); ++i) {
      std::uint32_t r = find(std::uint32_t(i));
      if(label[r] == std::uint32_t(-1)) label[r] = std::uint32_t(number_of_labels++);
      out[i] = label[r];
    }
    return out;
  }
private:
  std::vector<std::uint32_t> m_parent;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNION_FIND_H
