// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_ASSEMBLY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_ASSEMBLY_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/dof_reduction.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/field_diagnostics.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Exact orientation of every tetrahedron's corner parameters (x: 12 scalars per tetrahedron, corners
// in the mesh's vertex order; the mesh's tetrahedra are positively oriented, so NEGATIVE is inverted).
// Epick's predicate is exact on the double inputs.
inline std::vector<CGAL::Orientation> parameter_orientations(const Eigen::VectorXd& x)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;
  const std::size_t nt = std::size_t(x.size()) / 12;
  std::vector<CGAL::Orientation> o(nt);
  for(std::size_t t = 0; t < nt; ++t) {
    std::array<Point, 4> u;
    for(int c = 0; c < 4; ++c) {
      const Eigen::Index i = Eigen::Index(12 * t + 3 * c);
      u[std::size_t(c)] = Point(x[i], x[i + 1], x[i + 2]);
    }
    o[t] = CGAL::orientation(u[0], u[1], u[2], u[3]);
  }
  return o;
}

// The map handed to the extraction, from the corner scalars `x` (sanitized: every transition exact):
// points, tetrahedra and corner parameters, then the transitions of the interior faces with their
// integer `translation(f, k)` on the cut. Fills the exact orientation counts, the minimum relative
// Jacobian, the jogs with a bad tetrahedron in their ring and the largest transition violation of
// `r` (`Result`: Integer_grid_map_result).
template <class Traits, class Translation, class Result>
void assemble_map(const Tetrahedral_mesh_3<Traits>& mesh, const Matchings& matchings, const std::vector<char>& cut,
                  const Map_geometry& geometry, double s, const Eigen::VectorXd& x,
                  const std::vector<typename Tetrahedral_mesh_3<Traits>::Index>& jog_edges, const Translation& translation,
                  Integer_grid_map& map, Result& r)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const std::size_t nt = mesh.number_of_tetrahedra();
  map = Integer_grid_map();
  map.source = mesh.source();
  map.points.reserve(mesh.number_of_vertices());
  for(Index v = 0; v < mesh.number_of_vertices(); ++v) {
    const Eigen::Vector3d p = vertex_point(mesh, v);
    map.points.emplace_back(p.x(), p.y(), p.z());
  }
  map.tetrahedra.resize(nt);
  map.parameters.resize(nt);
  r.min_relative_jacobian = std::numeric_limits<double>::infinity();
  std::vector<char> bad_tet(nt, 0);
  const std::vector<CGAL::Orientation> orientation = parameter_orientations(x);
  for(Index tt = 0; tt < nt; ++tt) {
    const auto& tv = mesh.tetrahedron_vertices(tt);
    for(int c = 0; c < 4; ++c) {
      map.tetrahedra[tt][c] = tv[c];
      map.parameters[tt][c] = x.segment<3>(Eigen::Index(12 * tt + 3 * c));
    }
    const CGAL::Orientation o = orientation[tt];
    if(o == CGAL::NEGATIVE) { ++r.inverted_tetrahedra; bad_tet[tt] = 1; }
    else if(o == CGAL::COPLANAR) { ++r.degenerate_tetrahedra; bad_tet[tt] = 1; }
    r.min_relative_jacobian = (std::min)(r.min_relative_jacobian, map_jacobian(geometry, x, tt).determinant() / (s * s * s));
  }
  for(Index e : jog_edges)
    for(Index tt : mesh.edge_ring(e))
      if(bad_tet[tt]) { ++r.degenerate_jogs; break; }
  for(Index f = 0; f < mesh.number_of_faces(); ++f) {
    if(mesh.is_boundary_face(f)) continue;
    Integer_grid_map_transition tr;
    const auto& ft = mesh.face_tetrahedra(f);
    tr.tetrahedra = {{ft[0], ft[1]}};
    tr.rotation = transition_rotation(matchings, f);
    if(cut[f])
      for(int k = 0; k < 3; ++k) tr.translation[k] = translation(f, k);
    const Eigen::Matrix3d Rm = octahedral_group().matrix(tr.rotation);
    for(Index v : mesh.face_vertices(f)) {
      const Eigen::Vector3d& u0 = map.parameters[ft[0]][local_corner(mesh, ft[0], v)];
      const Eigen::Vector3d& u1 = map.parameters[ft[1]][local_corner(mesh, ft[1], v)];
      r.transition_error = (std::max)(r.transition_error, (u0 - (Rm * u1 + tr.translation.cast<double>())).cwiseAbs().maxCoeff());
    }
    map.transitions.push_back(tr);
  }
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_ASSEMBLY_H
