// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_FIELD_DIAGNOSTICS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_FIELD_DIAGNOSTICS_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>

#include <cmath>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Traits>
Eigen::Vector3d vertex_point(const Tetrahedral_mesh_3<Traits>& mesh, typename Tetrahedral_mesh_3<Traits>::Index v)
{
  const auto& p = mesh.point(v);
  return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// What the map reports of the field it follows (`Result`: Integer_grid_map_result): its non-meshable
// locations (improper edges, dangling ends, zippers), the faces where the frames' closest matching is
// not the kept one, and its jogs (singular edges more than 45 degrees off their holonomy axis), which
// are returned.
template <class Traits, class Result>
std::vector<typename Tetrahedral_mesh_3<Traits>::Index>
diagnose_field(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames, const Matchings& matchings,
               const Singularity_graph& singularities, Result& r)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  typedef typename std::decay_t<decltype(r.defects)>::value_type Defect;
  auto point = [&](Index v) { return vertex_point(mesh, v); };
  for(Index e = 0; e < mesh.number_of_edges(); ++e)
    if(singularities.edge_valence[e] == 0) {
      const auto& ev = mesh.edge_vertices(e);
      r.defects.push_back({Defect::IMPROPER_EDGE, e, 0.5 * (point(ev[0]) + point(ev[1]))});
    }
  for(Index v : singularities.dangling_vertices) r.defects.push_back({Defect::DANGLING_END, v, point(v)});
  for(Index v : singularities.zipper_vertices) r.defects.push_back({Defect::ZIPPER, v, point(v)});
  for(Index f = 0; f < mesh.number_of_faces(); ++f) {
    if(mesh.is_boundary_face(f)) continue;
    const auto& ft = mesh.face_tetrahedra(f);
    if(closest_matching(frames[ft[0]], frames[ft[1]]).index != matchings.face_matching[f]) ++r.disagreeing_faces;
  }
  std::vector<Index> jog_edges;
  for(Index e = 0; e < mesh.number_of_edges(); ++e) {
    if(singularities.edge_valence[e] != 3 && singularities.edge_valence[e] != 5) continue;
    const auto& ev = mesh.edge_vertices(e);
    const Eigen::Vector3d d = (point(ev[1]) - point(ev[0])).normalized();
    const Eigen::Vector3d axis = frames[mesh.edge_ring(e)[0]] * octahedral_group().axis(singularities.edge_holonomy[e]);
    if(std::abs(axis.dot(d)) < std::sqrt(0.5)) jog_edges.push_back(e);
  }
  r.jogs = jog_edges.size();
  return jog_edges;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_FIELD_DIAGNOSTICS_H
