// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_GREEDY_DIRECTION_OPTIMIZATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_GREEDY_DIRECTION_OPTIMIZATION_H

#include <CGAL/Hexahedral_remeshing/internal/cube_direction_search.h>
#include <CGAL/Hexahedral_remeshing/internal/direction_constraints_energy.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

struct Greedy_direction_statistics
{
  std::size_t iterations = 0;    // accepted updates v_i <- u_i
  std::size_t queue_pops = 0;
  std::size_t searches = 0;      // runs of Algorithm 2
  std::size_t evaluations = 0;   // E_i evaluations inside Algorithm 2
  bool converged = true;         // the queue emptied (false: stopped by the pop limit)
};

// Algorithm 1 of Desobry et al. (Sec. 4.2): v starts at the normals; a FIFO queue holds every
// boundary triangle once, in index order; a popped triangle i gets the direction u_i of Algorithm 2
// if E_i(u) < E_i(v), and then its three neighbours enter the queue unless they are in it already.
//
// Early exit: a popped triangle whose E_i(v) is at most `tolerance` is not searched (on planar
// regions and on edges whose normals already meet their valence exactly, E_i(n) is 0 up to
// rounding).  This cannot hide a larger deviation elsewhere: every term of E_i that involves a
// neighbour j (the dihedral deviation across the edge ij) is also a term of E_j, so a triangle with
// a deviation above the tolerance is searched itself.
//
// Termination: an accepted update lowers E_i strictly and raises a neighbour's E_j at most to the
// new E_i (the only term of E_j that depends on v_i is the shared dihedral deviation), so the list
// of the energies sorted decreasingly decreases lexicographically; the directions are taken from a
// finite set (the normals and the points of the search cubes).  `maximum_pops` (0: none) is a
// safety net reported through `converged`.
inline Greedy_direction_statistics
greedy_direction_optimization(const Boundary_direction_energy& energy, std::vector<Eigen::Vector3d>& v,
                              int refinements, double tolerance, std::size_t maximum_pops)
{
  typedef std::uint32_t Index;
  Greedy_direction_statistics stats;
  const std::size_t nf = energy.number_of_faces();
  // FIFO ring buffer: a triangle is at most once in the queue, so nf slots suffice.
  std::vector<Index> ring(nf);
  std::vector<char> in_queue(nf, 1);
  for(std::size_t i = 0; i < nf; ++i) ring[i] = Index(i);
  std::size_t head = 0, size = nf;
  while(size > 0) {
    if(maximum_pops > 0 && stats.queue_pops >= maximum_pops) { stats.converged = false; break; }
    const Index i = ring[head];
    head = (head + 1 == nf) ? 0 : head + 1;
    --size;
    in_queue[i] = 0;
    ++stats.queue_pops;
    const double current = energy.face_energy(i, v);
    if(current <= tolerance) continue;
    ++stats.searches;
    const Cube_direction_search_result best = cube_direction_search(energy, i, v, refinements);
    stats.evaluations += best.evaluations;
    if(!(best.energy < current)) continue;
    v[i] = best.direction;
    ++stats.iterations;
    for(const auto& h : energy.half_edges(i)) {
      const Index j = h.neighbor;
      if(in_queue[j]) continue;
      in_queue[j] = 1;
      std::size_t tail = head + size;
      if(tail >= nf) tail -= nf;
      ring[tail] = j;
      ++size;
    }
  }
  return stats;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_GREEDY_DIRECTION_OPTIMIZATION_H
