// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_EXTRACTION_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_EXTRACTION_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/check_map.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/map_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/transitions.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// What an integer-grid map looks like, measured from its parameters alone (`check_integer_grid_map()`).
/// Faces are given as sorted vertex triples; deviations are in parameter units (hex edges).
struct Integer_grid_map_check
{
  /// Number of tetrahedra.
  std::size_t tetrahedra = 0;
  /// Number of interior faces (shared by two tetrahedra).
  std::size_t interior_faces = 0;
  /// Number of boundary faces.
  std::size_t boundary_faces = 0;
  /// Tetrahedra whose parameter points are negatively oriented (exact `orientation`).
  std::size_t inverted_tetrahedra = 0;
  /// Tetrahedra whose parameter points are coplanar (exact `orientation`).
  std::size_t degenerate_tetrahedra = 0;
  /// Tetrahedra whose positions (model space) are negatively oriented (exact `orientation`): the map
  /// folds the model there even if the parameters are fine.
  std::size_t inverted_positions = 0;
  /// Tetrahedra whose positions are coplanar.
  std::size_t degenerate_positions = 0;
  /// Largest misfit, over the interior faces, of the face edge vectors of one chart and the best
  /// rotation of the 24-group applied to the other chart's.
  double max_rotation_deviation = 0.;
  /// Face of `max_rotation_deviation`.
  std::array<std::uint32_t, 3> worst_rotation_face{};
  /// Largest distance of a transition's translation to an integer vector (includes the rotation misfit).
  double max_jump_deviation = 0.;
  /// Face of `max_jump_deviation`.
  std::array<std::uint32_t, 3> worst_jump_face{};
  /// Largest distance of a boundary face to the nearest integer coordinate plane.
  double max_boundary_deviation = 0.;
  /// Face of `max_boundary_deviation`.
  std::array<std::uint32_t, 3> worst_boundary_face{};
  /// Interior faces whose parameters do not determine the rotation (collinear or coincident).
  std::size_t ambiguous_transitions = 0;
  /// Interior edges by valence: (sum of the parameter-space dihedral angles of the incident tetrahedra,
  /// negative for inverted ones, 0 for degenerate ones) / (pi/2), rounded; 4 is regular.
  std::map<int, std::size_t> interior_edge_valences;
  /// Boundary edges by valence (same sum): 2 flat, 1 convex feature, 3 concave feature.
  std::map<int, std::size_t> boundary_edge_valences;
  /// Largest distance of an edge's angle sum / (pi/2) to an integer (edges at degenerate tetrahedra excluded).
  double max_valence_deviation = 0.;
  /// Edges incident to a degenerate tetrahedron (their valence is not reliable).
  std::size_t edges_at_degenerate_tetrahedra = 0;

  /// True when the transitions and the boundary planes are integer within `tolerance`.
  bool is_integer_grid(double tolerance = 1e-3) const
  {
    return max_rotation_deviation <= tolerance && max_jump_deviation <= tolerance && max_boundary_deviation <= tolerance;
  }
  /// True when no tetrahedron is inverted or degenerate in parameter space.
  bool is_locally_injective() const { return inverted_tetrahedra == 0 && degenerate_tetrahedra == 0; }
  /// Number of interior edges whose valence is not 4.
  std::size_t singular_interior_edges() const
  {
    std::size_t n = 0;
    for(const auto& kv : interior_edge_valences) n += kv.first != 4 ? kv.second : 0;
    return n;
  }
};

/// \ingroup PkgHexahedralRemeshingRef
/// Checks an integer-grid map from its parameters alone, independently of how it was produced:
/// transitions recovered per interior face (faces matched by sorted vertex triples; the rotation of
/// the 24-group best mapping one chart's face edge vectors onto the other's, the translation
/// `round(u_i - R u_j)`; `map.transitions` when given), boundary faces against integer planes,
/// inverted and degenerate tetrahedra by the exact orientation of their parameter points (and of their
/// positions), and the
/// valence of every edge from its parameter-space dihedral-angle sum (HexEx's singularity test,
/// Lyon, Bommes, Kobbelt 2016). Runs in O(#tetrahedra log #tetrahedra).
/// \throws Input_error if the tetrahedra are not a manifold (a face shared by more than two) or a
///         vertex id is out of range.
inline Integer_grid_map_check check_integer_grid_map(const Integer_grid_map& map)
{
  namespace ex = internal::extraction;
  Integer_grid_map_check check;
  ex::Map_topology topo;
  ex::build_map_topology(map, topo);
  ex::Face_transitions tr;
  ex::compute_face_transitions(map, topo, tr);
  const std::size_t nt = map.tetrahedra.size();
  check.tetrahedra = nt;
  check.interior_faces = topo.interior_faces;
  check.boundary_faces = topo.boundary_faces;
  check.max_rotation_deviation = tr.max_rotation_deviation;
  check.max_jump_deviation = tr.max_jump_deviation;
  check.ambiguous_transitions = tr.ambiguous;
  if(tr.worst_rotation_tet != ex::no_tetrahedron)
    check.worst_rotation_face = ex::sorted_face(map, tr.worst_rotation_tet, tr.worst_rotation_face);
  if(tr.worst_jump_tet != ex::no_tetrahedron)
    check.worst_jump_face = ex::sorted_face(map, tr.worst_jump_tet, tr.worst_jump_face);

  std::vector<double> angle_sum(topo.edges.size(), 0.);
  std::vector<char> at_degenerate(topo.edges.size(), 0);
  for(std::uint32_t t = 0; t < nt; ++t) {
    const CGAL::Orientation o = ex::parameter_orientation(map.parameters[t]);
    if(o == CGAL::NEGATIVE) ++check.inverted_tetrahedra;
    if(o == CGAL::COPLANAR) ++check.degenerate_tetrahedra;
    const auto& tet = map.tetrahedra[t];
    const CGAL::Orientation og = CGAL::orientation(map.points[tet[0]], map.points[tet[1]], map.points[tet[2]], map.points[tet[3]]);
    if(og == CGAL::NEGATIVE) ++check.inverted_positions;
    if(og == CGAL::COPLANAR) ++check.degenerate_positions;
    for(int e = 0; e < 6; ++e) {
      const std::uint32_t id = topo.tetrahedron_edges[t][e];
      if(o == CGAL::COPLANAR) { at_degenerate[id] = 1; continue; }
      const double a = ex::parameter_dihedral_angle(map.parameters[t], e);
      angle_sum[id] += o == CGAL::NEGATIVE ? -a : a;
    }
    for(int f = 0; f < 4; ++f) {
      if(topo.neighbor[t][f] != ex::no_tetrahedron) continue;
      int axis;
      double value, deviation;
      ex::boundary_plane(map, t, f, axis, value, deviation);
      if(deviation > check.max_boundary_deviation) {
        check.max_boundary_deviation = deviation;
        check.worst_boundary_face = ex::sorted_face(map, t, f);
      }
    }
  }
  const double quarter = 1.57079632679489661923;
  for(std::size_t e = 0; e < topo.edges.size(); ++e) {
    const double v = angle_sum[e] / quarter;
    const int valence = int(std::lround(v));
    if(at_degenerate[e]) ++check.edges_at_degenerate_tetrahedra;
    else check.max_valence_deviation = (std::max)(check.max_valence_deviation, std::abs(v - valence));
    if(topo.edge_on_boundary[e]) ++check.boundary_edge_valences[valence];
    else ++check.interior_edge_valences[valence];
  }
  return check;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_EXTRACTION_H
