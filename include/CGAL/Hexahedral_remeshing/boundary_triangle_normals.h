// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_TRIANGLE_NORMALS_H
#define CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_TRIANGLE_NORMALS_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// The unit outward normals `n_i` of the boundary triangles, indexed by boundary triangle. As the
/// directions of `compute_frame_field()` they give the classic normal-aligned frame field.
template <class Traits>
std::vector<Eigen::Vector3d> boundary_triangle_unit_normals(const Tetrahedral_mesh_3<Traits>& mesh)
{
  std::vector<Eigen::Vector3d> n(mesh.number_of_boundary_triangles());
  for(std::size_t i = 0; i < n.size(); ++i) {
    const auto v = mesh.boundary_triangle_normal(typename Tetrahedral_mesh_3<Traits>::Index(i));
    n[i] = Eigen::Vector3d(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
    n[i] /= n[i].norm();
  }
  return n;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_TRIANGLE_NORMALS_H
