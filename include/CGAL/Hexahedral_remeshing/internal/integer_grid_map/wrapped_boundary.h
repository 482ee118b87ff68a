// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Boundary vertices around which a map wraps the boundary surface: the boundary analogue of a branched
// interior edge. Every boundary triangle lies on a coordinate plane of its tetrahedron's chart; at a
// boundary vertex of a hex mesh the parameter angles of its boundary triangles (each counted negative
// where its tetrahedron is inverted) sum to a positive number of quarter turns, 3, 4 or 5 on a smooth
// part of the surface (the surface's quad layout has valence 3, 4 or 5 there). A sum of 0 or less means
// the map folds the surface over itself at the vertex; on a smooth part of the surface, 1, 2 or 6 and
// more mean its triangles are wound around the vertex the wrong number of times (measured: the plate
// with a boss of make_parts.py, whose field has the right graph, has four valence-5 curve ends on the
// plate's top face, two wound to 1 quarter turn in the energy's minimizer). The untangling moves the
// triangles continuously, and a winding changes only through a degenerate triangle: measured on the 42
// shared models, it unwound the minimizer's wraps of three maps (HexMe s09c, s13c, s15c: 1, 4 and 9
// vertices), and left 3 to 283 on 23 of the 26 whose seamless map folds.
// A diagnostic in floating point (angles, not decisions): the sum is rounded to quarter turns, a sum
// farther than a tenth of a quarter turn from one is not counted (a flat triangle makes it ambiguous).
// Two singular curves ending at one smooth boundary vertex would give 2 or 6 quarter turns, a valid
// configuration that this count lists as well (the public map rockerarm_q of ../shared/data/igm has two
// smooth vertices at 2): the count says where to look, it does not make a map invalid.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_WRAPPED_BOUNDARY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_WRAPPED_BOUNDARY_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

inline double corner_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const double na = a.norm(), nb = b.norm();
  if(!(na > 0) || !(nb > 0)) return 0;
  return std::acos(std::clamp(a.dot(b) / (na * nb), -1., 1.));
}

// The boundary vertices around which the map `x` (12 corner values per tetrahedron, `P y + x0`) wraps
// the boundary surface (see the file's comment), in increasing order.
template <class Traits>
std::vector<std::uint32_t> wrapped_boundary_vertices(const Tetrahedral_mesh_3<Traits>& mesh, const Eigen::VectorXd& x)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const double pi = 3.14159265358979323846, quarter = pi / 2;
  std::vector<double> parameter_sum(mesh.number_of_vertices(), 0.), space_sum(mesh.number_of_vertices(), 0.);
  auto point = [&](Index v) {
    const auto& p = mesh.point(v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  for(std::size_t t = 0; t < mesh.number_of_tetrahedra(); ++t) {
    const auto& tv = mesh.tetrahedron_vertices(Index(t));
    Eigen::Vector3d u[4], p[4];
    for(int c = 0; c < 4; ++c) {
      u[c] = x.segment<3>(Eigen::Index(12 * t + 3 * c));
      p[c] = point(tv[c]);
    }
    Eigen::Matrix3d du, dp;
    for(int c = 0; c < 3; ++c) {
      du.col(c) = u[c + 1] - u[0];
      dp.col(c) = p[c + 1] - p[0];
    }
    const double sign = du.determinant() * dp.determinant() > 0 ? 1. : du.determinant() * dp.determinant() < 0 ? -1. : 0.;
    for(int i = 0; i < 4; ++i) {
      if(mesh.tetrahedron_neighbor(Index(t), i) != Tetrahedral_mesh_3<Traits>::null_index) continue;
      // face i is opposite corner i
      for(int k = 1; k < 4; ++k) {
        const int c = (i + k) % 4, a = (i + k % 3 + 1) % 4, b = (i + (k + 1) % 3 + 1) % 4;
        parameter_sum[tv[c]] += sign * corner_angle(u[a] - u[c], u[b] - u[c]);
        space_sum[tv[c]] += corner_angle(p[a] - p[c], p[b] - p[c]);
      }
    }
  }
  std::vector<std::uint32_t> wrapped;
  for(std::uint32_t v = 0; v < mesh.number_of_vertices(); ++v) {
    if(!mesh.is_boundary_vertex(Index(v))) continue;
    const double q = parameter_sum[v] / quarter;
    const double turns = std::round(q);
    if(std::abs(q - turns) > 0.1) continue;
    const bool smooth = std::abs(space_sum[v] - 2 * pi) < pi / 18; // within 10 degrees of a plane
    if(turns <= 0 || (smooth && (turns < 3 || turns > 5))) wrapped.push_back(v);
  }
  return wrapped;
}

// How many of `tetrahedra` have a corner in `vertices` (sorted).
template <class Traits>
std::size_t count_tetrahedra_at(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<std::uint32_t>& tetrahedra,
                                const std::vector<std::uint32_t>& vertices)
{
  std::size_t n = 0;
  for(std::uint32_t t : tetrahedra) {
    const auto& tv = mesh.tetrahedron_vertices(typename Tetrahedral_mesh_3<Traits>::Index(t));
    n += std::any_of(tv.begin(), tv.end(), [&](auto v) { return std::binary_search(vertices.begin(), vertices.end(), std::uint32_t(v)); }) ? 1 : 0;
  }
  return n;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_WRAPPED_BOUNDARY_H
