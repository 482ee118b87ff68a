// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_BOUNDARY_PROPAGATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_BOUNDARY_PROPAGATION_H

#include <CGAL/Hexahedral_remeshing/internal/frame_field/problem.h>

#include <Eigen/Dense>

#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// `Frame_field_initialization::BOUNDARY_PROPAGATION` (see there why): every free tet takes the frame of
// its nearest constrained (or fixed) tet, nearest along the dual graph with the centroid distances as
// lengths (multi-source Dijkstra; ties go to the first tet popped, so the result is deterministic).
// `centroids` are in the problem's tet order; `frames` holds the relaxation's projection on entry (its
// boundary frames are the sources) and the propagated field on exit. A component of free tets with no
// constrained tet keeps its frames.
inline void propagate_boundary_frames(const Frame_field_problem& p, const std::vector<Eigen::Vector3d>& centroids,
                                      std::vector<Eigen::Matrix3d>& frames)
{
  typedef Frame_field_problem::Index Index;
  const std::size_t nt = p.number_of_tets;
  std::vector<double> distance(nt, std::numeric_limits<double>::infinity());
  std::vector<Index> source(nt, Frame_field_problem::none);
  typedef std::pair<double, Index> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  for(std::size_t t = 0; t < nt; ++t) {
    if(!p.is_constrained(Index(t)) && !p.is_fixed(Index(t))) continue;
    distance[t] = 0;
    source[t] = Index(t);
    queue.push(Entry(0., Index(t)));
  }
  while(!queue.empty()) {
    const Entry e = queue.top();
    queue.pop();
    const Index t = e.second;
    if(e.first > distance[t]) continue;
    for(Index f : p.tet_faces[t]) {
      if(f == Frame_field_problem::none) continue;
      const Index u = p.face_tets[f][0] == t ? p.face_tets[f][1] : p.face_tets[f][0];
      const double d = distance[t] + (centroids[t] - centroids[u]).norm();
      if(d >= distance[u]) continue;
      distance[u] = d;
      source[u] = source[t];
      queue.push(Entry(d, u));
    }
  }
  for(std::size_t t = 0; t < nt; ++t)
    if(source[t] != Frame_field_problem::none && source[t] != Index(t)) frames[t] = frames[source[t]];
}

// Centroids of the tetrahedra in the problem's order (`mesh_tet`).
template <class Traits>
std::vector<Eigen::Vector3d> tetrahedron_centroids(const Tetrahedral_mesh_3<Traits>& mesh, const Frame_field_problem& p)
{
  std::vector<Eigen::Vector3d> centroids(p.number_of_tets);
  for(std::size_t i = 0; i < p.number_of_tets; ++i) {
    const auto& tv = mesh.tetrahedron_vertices(typename Tetrahedral_mesh_3<Traits>::Index(p.mesh_tet.empty() ? i : p.mesh_tet[i]));
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for(int k = 0; k < 4; ++k) {
      const auto& q = mesh.point(tv[k]);
      c += Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()));
    }
    centroids[i] = c / 4;
  }
  return centroids;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_BOUNDARY_PROPAGATION_H
