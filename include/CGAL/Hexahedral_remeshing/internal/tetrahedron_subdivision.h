// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// One round of red refinement of a tetrahedral soup (refine_tetrahedral_soup()): the midpoint of each
// edge is made once, so that the children of two tetrahedra sharing a face share their faces too.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_TETRAHEDRON_SUBDIVISION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_TETRAHEDRON_SUBDIVISION_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <utility>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Point>
class Tetrahedron_subdivision
{
public:
  typedef std::array<std::size_t, 4> Tet;

  Tetrahedron_subdivision(const Tetrahedral_soup_3<Point>& in, Tetrahedral_soup_3<Point>& out) : m_in(in), m_out(out) {}

  void run()
  {
    m_out = Tetrahedral_soup_3<Point>();
    m_out.points = m_in.points;
    m_out.corners = m_in.corners;
    m_out.patch_names = m_in.patch_names;
    m_out.source = m_in.source;
    for(std::size_t t = 0; t < m_in.tetrahedra.size(); ++t)
      split_tetrahedron(m_in.tetrahedra[t], t < m_in.tetrahedron_lines.size() ? m_in.tetrahedron_lines[t] : 0);
    for(std::size_t i = 0; i < m_in.triangles.size(); ++i)
      split_triangle(m_in.triangles[i], i < m_in.triangle_patches.size() ? m_in.triangle_patches[i] : -1);
    for(std::size_t i = 0; i < m_in.feature_edges.size(); ++i) {
      const auto& e = m_in.feature_edges[i];
      const std::size_t m = midpoint(e[0], e[1]);
      const int curve = i < m_in.feature_edge_curves.size() ? m_in.feature_edge_curves[i] : -1;
      m_out.feature_edges.push_back({e[0], m});
      m_out.feature_edges.push_back({m, e[1]});
      m_out.feature_edge_curves.push_back(curve);
      m_out.feature_edge_curves.push_back(curve);
    }
  }

private:
  // Index of the midpoint of edge (a, b), created on first use. Out-of-range indices are kept as they
  // are (the build reports them with their source line).
  std::size_t midpoint(std::size_t a, std::size_t b)
  {
    const std::size_t n = m_in.points.size();
    if(a >= n || b >= n) return (std::max)(a, b);
    const std::pair<std::size_t, std::size_t> key((std::min)(a, b), (std::max)(a, b));
    auto it = m_midpoints.find(key);
    if(it != m_midpoints.end()) return it->second;
    const Point& p = m_in.points[a];
    const Point& q = m_in.points[b];
    m_out.points.push_back(Point((p.x() + q.x()) / 2, (p.y() + q.y()) / 2, (p.z() + q.z()) / 2));
    m_midpoints.emplace(key, m_out.points.size() - 1);
    return m_out.points.size() - 1;
  }

  double squared_distance(std::size_t a, std::size_t b) const
  {
    const Point& p = m_out.points[a];
    const Point& q = m_out.points[b];
    const double dx = p.x() - q.x(), dy = p.y() - q.y(), dz = p.z() - q.z();
    return dx * dx + dy * dy + dz * dz;
  }

  void push(const Tet& t, std::size_t line)
  {
    m_out.tetrahedra.push_back(t);
    m_out.tetrahedron_lines.push_back(line);
  }

  // The four corner tetrahedra keep the parent's orientation; the inner octahedron is cut along its
  // shortest diagonal (a, b) into four tetrahedra (a, b, r_i+1, r_i) around it, r the ring of
  // midpoints about the diagonal, in an order that keeps the orientation too.
  void split_tetrahedron(const Tet& t, std::size_t line)
  {
    const std::size_t m01 = midpoint(t[0], t[1]), m02 = midpoint(t[0], t[2]), m03 = midpoint(t[0], t[3]);
    const std::size_t m12 = midpoint(t[1], t[2]), m13 = midpoint(t[1], t[3]), m23 = midpoint(t[2], t[3]);
    push({t[0], m01, m02, m03}, line);
    push({m01, t[1], m12, m13}, line);
    push({m02, m12, t[2], m23}, line);
    push({m03, m13, m23, t[3]}, line);
    const std::array<std::array<std::size_t, 6>, 3> cuts = {{{m01, m23, m02, m12, m13, m03},
                                                           {m02, m13, m01, m03, m23, m12},
                                                           {m03, m12, m01, m13, m23, m02}}};
    std::size_t best = 0;
    for(std::size_t k = 1; k < 3; ++k)
      if(squared_distance(cuts[k][0], cuts[k][1]) < squared_distance(cuts[best][0], cuts[best][1])) best = k;
    const auto& c = cuts[best];
    for(int i = 0; i < 4; ++i) push({c[0], c[1], c[2 + (i + 1) % 4], c[2 + i]}, line);
  }

  void split_triangle(const std::array<std::size_t, 3>& f, int patch)
  {
    const std::size_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
    for(const auto& child : {std::array<std::size_t, 3>{f[0], ab, ca}, std::array<std::size_t, 3>{ab, f[1], bc},
                             std::array<std::size_t, 3>{ca, bc, f[2]}, std::array<std::size_t, 3>{ab, bc, ca}}) {
      m_out.triangles.push_back(child);
      m_out.triangle_patches.push_back(patch);
    }
  }

  const Tetrahedral_soup_3<Point>& m_in;
  Tetrahedral_soup_3<Point>& m_out;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> m_midpoints;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_TETRAHEDRON_SUBDIVISION_H
