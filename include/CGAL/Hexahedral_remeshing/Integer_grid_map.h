// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTEGER_GRID_MAP_H
#define CGAL_HEXAHEDRAL_REMESHING_INTEGER_GRID_MAP_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Transition of an integer-grid map across one interior face shared by tetrahedra `t0` and `t1`:
/// on the face, the parameters of the two charts satisfy `u_t0 = R u_t1 + translation`, with `R` the
/// element `rotation` (0..23) of `internal::Octahedral_group` and an integer translation
/// (algorithms.md §4: `R = g_ij^T`).
struct Integer_grid_map_transition
{
  /// The two tetrahedra sharing the face.
  std::array<std::uint32_t, 2> tetrahedra{};
  /// The rotation of the 24-group mapping `t1`'s chart to `t0`'s chart.
  int rotation = 0;
  /// The integer translation.
  Eigen::Vector3i translation = Eigen::Vector3i::Zero();
};

/// \ingroup PkgHexahedralRemeshingRef
/// A per-tetrahedron map `u_t : t -> R^3`, affine on every tetrahedron, given by the parameters of the
/// four corners of each tetrahedron in that tetrahedron's own chart (libHexEx's `.hexex` model).
/// An integer-grid map jumps across faces only by a transition (`Integer_grid_map_transition`),
/// puts the boundary on integer planes and the singular and feature curves on integer lines; its
/// integer cells are the hexahedra (Lyon, Bommes, Kobbelt 2016, "HexEx").
///
/// Shapes: `points.size()` vertices; `tetrahedra.size() == parameters.size()` tetrahedra. Positions
/// are in model units; parameters in hex edges (1 = one hex edge).
struct Integer_grid_map
{
  /// Point type of the positions.
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point_3;
  /// Vertex positions.
  std::vector<Point_3> points;
  /// Tetrahedra as 4 vertex indices.
  std::vector<std::array<std::uint32_t, 4> > tetrahedra;
  /// Per tetrahedron, the parameters `(u, v, w)` of its corners, in the order of `tetrahedra[t]`.
  std::vector<std::array<Eigen::Vector3d, 4> > parameters;
  /// Transitions of the interior faces when the producer knows them (`compute_integer_grid_map()`);
  /// empty when they must be recovered from the parameters (a map read from a file).
  std::vector<Integer_grid_map_transition> transitions;
  /// Name of the source (file name) for error messages; empty for in-memory maps.
  std::string source;

  /// Number of tetrahedra.
  std::size_t number_of_tetrahedra() const { return tetrahedra.size(); }
};

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTEGER_GRID_MAP_H
