// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_CUBE_DIRECTION_SEARCH_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_CUBE_DIRECTION_SEARCH_H

#include <CGAL/Hexahedral_remeshing/internal/direction_constraints_energy.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Algorithm 2 of Desobry et al. (Sec. 4.3): the direction u minimizing E_i when the directions of
// the other triangles are fixed, searched among the integer points of the surface of centred cubes.
// Stage 0: the 26 integer points of the cube of edge length 2 (max(|x|,|y|,|z|) = 1).  Refinement
// r = 1, 2, ...: the cube doubles (half edge length h = 2^r), the best point p becomes 2p, and the
// integer points of the 3x3x3 block around 2p that lie on the new cube surface (max = h) are
// tested: 2p and its 8 neighbours on a face or an edge of the cube, 2p and its 6 neighbours at a
// corner.  2p has the direction of p, so its energy is already known and the best energy never
// increases.  Candidates are visited in a fixed order (x, then y, then z, increasing) and replace
// the best only when strictly better, so the search is deterministic.
//
// Deviation from the paper's pseudo-code, which is ambiguous there: the best of each stage is kept
// from one stage to the next (the pseudo-code restarts the comparison from the current v_i at each
// stage and then falls back to the point (1, 0, 0) when nothing beats it).  Algorithm 1 compares the
// result with E_i of the current v_i.
struct Cube_direction_search_result
{
  Eigen::Vector3d direction;   // unit
  double energy = std::numeric_limits<double>::infinity();
  std::size_t evaluations = 0;
};

inline Cube_direction_search_result
cube_direction_search(const Boundary_direction_energy& energy, std::uint32_t i, const std::vector<Eigen::Vector3d>& v,
                      int refinements)
{
  Cube_direction_search_result r;
  std::array<long, 3> best{{1, 0, 0}};
  double cos_best = -1; // cos(r.energy) once r.energy < pi
  auto evaluate = [&](const std::array<long, 3>& p) {
    Eigen::Vector3d u(static_cast<double>(p[0]), static_cast<double>(p[1]), static_cast<double>(p[2]));
    u /= u.norm();
    ++r.evaluations;
    const double e = energy.face_energy_below(i, u, v, r.energy, cos_best);
    if(e < r.energy) {
      r.energy = e;
      r.direction = u;
      best = p;
      cos_best = e < CGAL_PI ? std::cos(e) : -1.0;
    }
  };
  for(long x = -1; x <= 1; ++x)
    for(long y = -1; y <= 1; ++y)
      for(long z = -1; z <= 1; ++z)
        if(x != 0 || y != 0 || z != 0) evaluate({{x, y, z}});
  if(r.energy == std::numeric_limits<double>::infinity()) { // cannot happen with finite inputs
    r.direction = Eigen::Vector3d(1, 0, 0);
    return r;
  }
  long half = 1;
  for(int refinement = 0; refinement < refinements; ++refinement) {
    half *= 2;
    const std::array<long, 3> c{{2 * best[0], 2 * best[1], 2 * best[2]}};
    best = c; // same direction, same energy
    for(long dx = -1; dx <= 1; ++dx)
      for(long dy = -1; dy <= 1; ++dy)
        for(long dz = -1; dz <= 1; ++dz) {
          if(dx == 0 && dy == 0 && dz == 0) continue;
          const std::array<long, 3> p{{c[0] + dx, c[1] + dy, c[2] + dz}};
          if((std::max)({std::labs(p[0]), std::labs(p[1]), std::labs(p[2])}) == half) evaluate(p);
        }
  }
  return r;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_CUBE_DIRECTION_SEARCH_H
