// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_CHECK_MAP_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_CHECK_MAP_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/map_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/transitions.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace extraction {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Parameter_kernel;
typedef Parameter_kernel::Point_3 Parameter_point;

inline Parameter_point parameter_point(const Eigen::Vector3d& u) { return Parameter_point(u[0], u[1], u[2]); }

// Exact orientation of a tetrahedron's parameter points (Epick: exact on the double inputs).
inline CGAL::Orientation parameter_orientation(const std::array<Eigen::Vector3d, 4>& u)
{
  return CGAL::orientation(parameter_point(u[0]), parameter_point(u[1]), parameter_point(u[2]), parameter_point(u[3]));
}

// Interior dihedral angle at local edge e of a tetrahedron with the given corner parameters, in [0, pi].
inline double parameter_dihedral_angle(const std::array<Eigen::Vector3d, 4>& u, int e)
{
  const Eigen::Vector3d& a = u[edge_vertices[e][0]];
  const Eigen::Vector3d d = u[edge_vertices[e][1]] - a;
  const Eigen::Vector3d n1 = d.cross(u[edge_opposite[e][0]] - a), n2 = d.cross(u[edge_opposite[e][1]] - a);
  return std::atan2(n1.cross(n2).norm(), n1.dot(n2));
}

inline std::array<std::uint32_t, 3> sorted_face(const Integer_grid_map& map, std::uint32_t t, int f)
{
  std::array<std::uint32_t, 3> v;
  for(int k = 0; k < 3; ++k) v[k] = map.tetrahedra[t][face_vertices[f][k]];
  std::sort(v.begin(), v.end());
  return v;
}

} // namespace extraction
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_CHECK_MAP_H
