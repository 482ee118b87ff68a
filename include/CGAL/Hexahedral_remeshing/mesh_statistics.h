// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_MESH_STATISTICS_H
#define CGAL_HEXAHEDRAL_REMESHING_MESH_STATISTICS_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Statistics of a `Tetrahedral_mesh_3`, as printed by `hexmesh info`.
struct Mesh_statistics
{
  std::size_t vertices = 0, input_vertices = 0, tetrahedra = 0, faces = 0, edges = 0;
  std::size_t boundary_triangles = 0, boundary_edges = 0, boundary_vertices = 0;
  std::size_t components = 0, boundary_components = 0;
  long boundary_euler_characteristic = 0;
  /// Sum of the genera of the boundary components, from `chi = 2 c - 2 g`.
  long boundary_genus = 0;
  std::size_t split_tetrahedra = 0, reoriented_tetrahedra = 0;
  std::size_t feature_edges = 0, feature_curves = 0, surface_patches = 0, corners = 0;
  /// Number of boundary edges per exact class `round(2 phi / pi)`, 0 to 4.
  std::array<std::size_t, 5> dihedral_class_histogram{{0, 0, 0, 0, 0}};
  /// Extreme boundary dihedral angles, in degrees.
  double min_dihedral_angle_degrees = 0, max_dihedral_angle_degrees = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Computes the statistics of `mesh`; dihedral classes are exact (see `boundary_edge_dihedral_class()`).
template <class Traits>
Mesh_statistics compute_mesh_statistics(const Tetrahedral_mesh_3<Traits>& mesh, const Traits& traits = Traits())
{
  Mesh_statistics s;
  s.vertices = mesh.number_of_vertices();
  s.input_vertices = mesh.number_of_input_vertices();
  s.tetrahedra = mesh.number_of_tetrahedra();
  s.faces = mesh.number_of_faces();
  s.edges = mesh.number_of_edges();
  s.boundary_triangles = mesh.number_of_boundary_triangles();
  s.boundary_edges = mesh.boundary_edges().size();
  for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v) s.boundary_vertices += mesh.is_boundary_vertex(typename Tetrahedral_mesh_3<Traits>::Index(v));
  s.components = mesh.number_of_components();
  s.boundary_components = mesh.number_of_boundary_components();
  s.boundary_euler_characteristic = mesh.boundary_euler_characteristic();
  s.boundary_genus = (2 * long(s.boundary_components) - s.boundary_euler_characteristic) / 2;
  s.split_tetrahedra = mesh.number_of_split_tetrahedra();
  s.reoriented_tetrahedra = mesh.number_of_reoriented_tetrahedra();
  s.feature_edges = mesh.number_of_feature_edges();
  s.feature_curves = mesh.number_of_feature_curves();
  s.surface_patches = mesh.number_of_surface_patches();
  s.corners = mesh.corners().size();
  double lo = 1e300, hi = -1e300;
  for(auto e : mesh.boundary_edges()) {
    ++s.dihedral_class_histogram[std::size_t(boundary_edge_dihedral_class(mesh, e, traits))];
    const double a = boundary_edge_dihedral_angle(mesh, e) * 180.0 / CGAL_PI;
    lo = (std::min)(lo, a);
    hi = (std::max)(hi, a);
  }
  if(!mesh.boundary_edges().empty()) { s.min_dihedral_angle_degrees = lo; s.max_dihedral_angle_degrees = hi; }
  return s;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_MESH_STATISTICS_H
