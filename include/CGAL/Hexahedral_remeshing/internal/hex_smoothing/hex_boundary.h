// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_HEX_BOUNDARY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_HEX_BOUNDARY_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/reference_projector.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Boundary quads of a hex mesh: the faces that belong to a single hexahedron, oriented outward.
inline std::vector<std::array<std::uint32_t, 4> > hex_boundary_quads(const Hexahedral_mesh_3& mesh)
{
  std::map<std::array<std::uint32_t, 4>, std::pair<int, std::array<std::uint32_t, 4> > > faces;
  for(const auto& h : mesh.hexahedra)
    for(const auto& f : hex_faces()) {
      std::array<std::uint32_t, 4> q{ {h[f[0]], h[f[1]], h[f[2]], h[f[3]]} };
      std::array<std::uint32_t, 4> key = q;
      std::sort(key.begin(), key.end());
      auto it = faces.emplace(key, std::make_pair(0, q)).first;
      ++it->second.first;
    }
  std::vector<std::array<std::uint32_t, 4> > quads;
  for(const auto& f : faces)
    if(f.second.first == 1) quads.push_back(f.second.second);
  return quads;
}

// Symmetric distance between the boundary of the hex mesh (bilinear quads, sampled at vertices, edge
// midpoints and centres) and the reference surface (sampled at its vertices, edge midpoints and
// triangle centroids, measured to the quads split into 4 triangles around their centre). An
// approximation from below of the Hausdorff distance, deterministic. -1 if either side is empty.
inline double hex_boundary_hausdorff_distance(const std::vector<Hexahedral_mesh_3::Point_3>& points,
                                              const std::vector<std::array<std::uint32_t, 4> >& quads,
                                              const Reference_projector& reference)
{
  typedef Reference_projector::K K;
  typedef K::Point_3 Point_3;
  typedef K::Triangle_3 Triangle_3;
  if(quads.empty() || !reference.has_surface()) return -1;
  double d = 0;
  std::vector<Triangle_3> hex_triangles;
  for(const auto& q : quads) {
    const Point_3 c = CGAL::centroid(points[q[0]], points[q[1]], points[q[2]], points[q[3]]);
    d = (std::max)(d, reference.distance_to_surface(c));
    for(int i = 0; i < 4; ++i) {
      const Point_3& a = points[q[i]];
      const Point_3& b = points[q[(i + 1) % 4]];
      d = (std::max)(d, reference.distance_to_surface(a));
      d = (std::max)(d, reference.distance_to_surface(CGAL::midpoint(a, b)));
      const Triangle_3 t(a, b, c);
      if(!t.is_degenerate()) hex_triangles.push_back(t);
    }
  }
  if(hex_triangles.empty()) return d;
  typedef std::vector<Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > tree(hex_triangles.begin(), hex_triangles.end());
  tree.accelerate_distance_queries();
  auto dist = [&tree](const Point_3& p) { return std::sqrt(tree.squared_distance(p)); };
  for(const Triangle_3& t : reference.triangles()) {
    d = (std::max)(d, dist(CGAL::centroid(t[0], t[1], t[2])));
    for(int i = 0; i < 3; ++i) {
      d = (std::max)(d, dist(t[i]));
      d = (std::max)(d, dist(CGAL::midpoint(t[i], t[(i + 1) % 3])));
    }
  }
  return d;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_HEX_BOUNDARY_H
