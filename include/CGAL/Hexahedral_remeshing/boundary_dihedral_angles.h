// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_DIHEDRAL_ANGLES_H
#define CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_DIHEDRAL_ANGLES_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/ambiguous_dihedral_class.h>

#include <array>
#include <cmath>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// The points `(p, q, a, b)` of boundary edge `e` in the order the traits' `Dihedral_class_3`
/// expects: `(p, q, a)` is the first boundary triangle of `e` and `p -> q` its half-edge along `e`
/// (the paper's `e_ij`), `(q, p, b)` the second boundary triangle.
/// \pre `mesh.is_boundary_edge(e)`
template <class Traits>
std::array<typename Traits::Point_3, 4>
boundary_edge_points(const Tetrahedral_mesh_3<Traits>& mesh, typename Tetrahedral_mesh_3<Traits>::Index e)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const std::array<Index, 2>& ev = mesh.edge_vertices(e);
  const std::array<Index, 2>& bt = mesh.edge_boundary_triangles(e);
  auto third = [&](Index b) {
    for(Index v : mesh.boundary_triangle_vertices(b)) if(v != ev[0] && v != ev[1]) return v;
    return ev[0];
  };
  // the first triangle holds the half-edge v1 -> v0 (see Tetrahedral_mesh_3)
  return {mesh.point(ev[1]), mesh.point(ev[0]), mesh.point(third(bt[0])), mesh.point(third(bt[1]))};
}

/// \ingroup PkgHexahedralRemeshingRef
/// Exact class `round(2 phi / pi)` (0 to 4, ties at odd multiples of pi/4 rounded up) of the
/// interior dihedral angle `phi` at boundary edge `e`, decided with the traits' exact predicate.
/// \pre `mesh.is_boundary_edge(e)`
template <class Traits>
int boundary_edge_dihedral_class(const Tetrahedral_mesh_3<Traits>& mesh, typename Tetrahedral_mesh_3<Traits>::Index e,
                                 const Traits& traits = Traits())
{
  const auto p = boundary_edge_points(mesh, e);
  return traits.dihedral_class_3_object()(p[0], p[1], p[2], p[3]);
}

/// \ingroup PkgHexahedralRemeshingRef
/// Interior dihedral angle `phi` in radians, in [0, 2 pi), at boundary edge `e`, from the paper's
/// formula `phi = pi - atan2(<n_i x n_j, e/|e|>, <n_i, n_j>)` with unit outward normals (floating
/// point: use `boundary_edge_dihedral_class()` for decisions).
/// \pre `mesh.is_boundary_edge(e)`
template <class Traits>
double boundary_edge_dihedral_angle(const Tetrahedral_mesh_3<Traits>& mesh, typename Tetrahedral_mesh_3<Traits>::Index e)
{
  const auto p = boundary_edge_points(mesh, e);
  const auto ed = p[1] - p[0];
  auto ni = CGAL::cross_product(ed, p[2] - p[0]);
  auto nj = CGAL::cross_product(p[0] - p[1], p[3] - p[1]);
  const double li = std::sqrt(CGAL::to_double(ni.squared_length()));
  const double lj = std::sqrt(CGAL::to_double(nj.squared_length()));
  const double le = std::sqrt(CGAL::to_double(ed.squared_length()));
  const double s = CGAL::to_double(CGAL::cross_product(ni, nj) * ed) / (li * lj * le);
  const double c = CGAL::to_double(ni * nj) / (li * lj);
  double phi = CGAL_PI - std::atan2(s, c);
  if(phi >= 2 * CGAL_PI) phi -= 2 * CGAL_PI;
  return phi;
}

namespace internal {

// The points of `boundary_edge_points()` as the 12 doubles of internal/dihedral_class.h.
template <class Traits>
std::array<double, 12> boundary_edge_coordinates(const Tetrahedral_mesh_3<Traits>& mesh,
                                                 typename Tetrahedral_mesh_3<Traits>::Index e)
{
  const auto p = boundary_edge_points(mesh, e);
  std::array<double, 12> xyz;
  for(int i = 0; i < 4; ++i)
    for(int c = 0; c < 3; ++c) xyz[std::size_t(3 * i + c)] = CGAL::to_double(p[std::size_t(i)][c]);
  return xyz;
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// The class `round(2 phi / pi)` of `boundary_edge_dihedral_class()` with the angles within
/// pi/8192 (0.022 degrees) below an odd multiple of pi/4 rounded up like the exact ties: the class
/// the valence heuristics other than `GEOMETRIC` start from.
/// A CAD angle of 45, 135, 225 or 315 degrees (a 45-degree chamfer, the toe of a gusset) meshed
/// with rounded coordinates lands on either side of the exact tie edge by edge; this class gives
/// the whole curve the valence of the tie. Decided exactly for the coordinates converted to
/// `double` (exact for the default kernel): an interval filter, then exact rational arithmetic
/// against MPFR enclosures of the (irrational) threshold, as for the `AMBIGUOUS` heuristic.
/// \pre `mesh.is_boundary_edge(e)`
template <class Traits>
int boundary_edge_near_tie_class(const Tetrahedral_mesh_3<Traits>& mesh, typename Tetrahedral_mesh_3<Traits>::Index e)
{
  return internal::near_tie_dihedral_class_exact(internal::boundary_edge_coordinates(mesh, e));
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_DIHEDRAL_ANGLES_H
