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
  /// Number of vertices, including the ones added by preprocessing.
  std::size_t vertices = 0;
  /// Number of vertices of the input.
  std::size_t input_vertices = 0;
  /// Number of tetrahedra (after preprocessing).
  std::size_t tetrahedra = 0;
  /// Number of faces (triangles of the tetrahedra, each counted once).
  std::size_t faces = 0;
  /// Number of edges.
  std::size_t edges = 0;
  /// Number of boundary triangles.
  std::size_t boundary_triangles = 0;
  /// Number of boundary edges.
  std::size_t boundary_edges = 0;
  /// Number of boundary vertices.
  std::size_t boundary_vertices = 0;
  /// Number of connected components of the mesh (through faces).
  std::size_t components = 0;
  /// Number of connected components of the boundary surface.
  std::size_t boundary_components = 0;
  /// Euler characteristic `V - E + F` of the boundary surface.
  long boundary_euler_characteristic = 0;
  /// Sum of the genera of the boundary components, from `chi = 2 c - 2 g`.
  long boundary_genus = 0;
  /// Number of tetrahedra split 1-to-4 by preprocessing.
  std::size_t split_tetrahedra = 0;
  /// Number of inverted input tetrahedra that were re-oriented.
  std::size_t reoriented_tetrahedra = 0;
  /// Number of edges tagged with a feature curve by the input.
  std::size_t feature_edges = 0;
  /// Number of distinct feature curve ids of the input.
  std::size_t feature_curves = 0;
  /// Number of distinct surface patch ids of the input.
  std::size_t surface_patches = 0;
  /// Number of corner vertices of the input.
  std::size_t corners = 0;
  /// Number of boundary edges per exact class `round(2 phi / pi)`, 0 to 4.
  std::array<std::size_t, 5> dihedral_class_histogram{{0, 0, 0, 0, 0}};
  /// Smallest boundary dihedral angle, in degrees (0 without boundary edge).
  double min_dihedral_angle_degrees = 0;
  /// Largest boundary dihedral angle, in degrees (0 without boundary edge).
  double max_dihedral_angle_degrees = 0;
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
