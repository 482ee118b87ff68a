// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The quantized map reached from the injective seamless map by a path on which no tetrahedron ever
// folds (issue 27: the re-embedding of the integer values). The untangling of a folded map makes every
// tetrahedron positive but may wrap the map around an edge the wrong number of times: on the flange of
// make_parts.py, four valence-5 curves came out turning by one quarter turn and a regular edge beside
// each by eight (a branched map, every tetrahedron positive). Around an interior edge, the sum of the
// parameter-space dihedral angles changes only when a tetrahedron of its ring goes through zero volume,
// so a map moved from the seamless one (every edge turning as its holonomy says) without ever folding
// keeps every turn right. The integer values are reached in steps: each step moves the map along the
// linear response to the change of the integer values, is halved until no tetrahedron folds, and the
// map is then relaxed by the foldover-free energy's barrier (which never inverts a tetrahedron) where it is
// thin, which makes room for the next step. Integer values that collapse a block cannot be reached: the steps
// shrink below 1/4096 of the way and the continuation stops.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_CONTINUATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_CONTINUATION_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/check_map.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fixed_variable_solver.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fold_repair.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_assembly.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/untangle_map.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Interior edges of the map's mesh whose ring holds only positive tetrahedra (exact orientation of the
// corner scalars `x`, 12 per tetrahedron) and whose parameter-space dihedral angles sum to a number of
// quarter turns other than 3, 4 or 5: where the map is not locally injective although no tetrahedron
// folds (as check_integer_grid_map() lists them on the assembled map).
template <class Traits>
std::size_t count_branched_edges(const Tetrahedral_mesh_3<Traits>& mesh, const Eigen::VectorXd& x)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const std::vector<CGAL::Orientation> o = parameter_orientations(x);
  std::size_t branched = 0;
  for(Index e = 0; e < Index(mesh.number_of_edges()); ++e) {
    if(mesh.is_boundary_edge(e)) continue;
    const std::array<Index, 2>& ev = mesh.edge_vertices(e);
    double sum = 0;
    bool positive = true;
    for(Index t : mesh.edge_ring(e)) {
      if(o[t] != CGAL::POSITIVE) { positive = false; break; }
      const std::array<Index, 4>& tv = mesh.tetrahedron_vertices(t);
      const int a = int(std::find(tv.begin(), tv.end(), ev[0]) - tv.begin());
      const int b = int(std::find(tv.begin(), tv.end(), ev[1]) - tv.begin());
      int local = 0;
      while(!((extraction::edge_vertices[local][0] == a && extraction::edge_vertices[local][1] == b) ||
              (extraction::edge_vertices[local][0] == b && extraction::edge_vertices[local][1] == a)))
        ++local;
      std::array<Eigen::Vector3d, 4> u;
      for(int c = 0; c < 4; ++c) u[std::size_t(c)] = x.segment<3>(Eigen::Index(12 * t + 3 * c));
      sum += extraction::parameter_dihedral_angle(u, local);
    }
    if(!positive) continue;
    const long valence = std::lround(sum / 1.57079632679489661923);
    if(valence < 3 || valence > 5) ++branched;
  }
  return branched;
}

struct Map_continuation
{
  bool ran = false;           // the map folded or branched after its repair, the seamless map did neither
  bool reached = false;       // the integer values were reached without a fold
  bool kept = false;          // the map reached replaced the quantized one
  bool program_lengths = false; // the last target was the complex's program's lengths (the quantized values failed)
  int steps = 0, halvings = 0;
  double parameter = 0;       // how far along the path the map got, in [0, 1]
  std::size_t folds_before = 0, branched_before = 0; // the quantized map's
  std::size_t folds_after = 0, branched_after = 0;   // the map reached
  double seconds = 0;
};

// Whether the quantized map `y` folds or branches (the report's counts before; `ran` set if so).
template <class Traits>
Map_continuation continuation_needed(const Tetrahedral_mesh_3<Traits>& mesh, const Fold_repair_input& in, const Eigen::VectorXd& y)
{
  Map_continuation r;
  r.folds_before = count_non_positive_jacobians(in.geometry, in.P * y + in.x0, &in.flat);
  r.branched_before = r.folds_before > 0 ? 0 : count_branched_edges(mesh, in.P * y + in.x0);
  r.ran = r.folds_before > 0 || r.branched_before > 0;
  return r;
}

// One outer iteration of the foldover-free barrier on the tetrahedra of `y`'s map whose det J is below a
// tenth of the target's (s^3) and two rings around them, which makes room for the next step where the
// map is about to fold; none if no tetrahedron is that thin, all if they reach a quarter of the mesh.
template <class Traits>
void relax_near_folds(const Tetrahedral_mesh_3<Traits>& mesh, const Fold_repair_input& in, Eigen::VectorXd& y)
{
  const std::vector<char> region =
    untangling_region(mesh, in.geometry, in.P * y + in.x0, in.flat, 2, 0.1 * in.s * in.s * in.s);
  const std::size_t size = std::size_t(std::count(region.begin(), region.end(), char(1)));
  if(size == 0) return;
  const bool local = size <= region.size() / 4;
  untangle_map(in.geometry, in.frames, in.s, in.P, in.x0, in.integer_column, in.flat, y, local ? &region : nullptr, true);
}

// Moves the seamless map `seamless_y` (no fold outside `in.flat`) to the integer values of `target`
// without folding; the map reached replaces `y` if it neither folds nor branches (`r.kept`). `H`, `rhs`:
// the unstiffened system; `solver` keeps that system, with the integer variables fixed at `y`'s values.
template <class Traits>
void continue_from_seamless_map(const Tetrahedral_mesh_3<Traits>& mesh, const Fold_repair_input& in,
                                const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                                const Eigen::VectorXd& seamless_y, const Eigen::VectorXd& target, int maximum_steps,
                                Fixed_variable_solver& solver, Map_continuation& r, Eigen::VectorXd& y)
{
  typedef std::chrono::steady_clock Clock;
  const auto start = Clock::now();
  auto folds = [&](const Eigen::VectorXd& v) { return count_non_positive_jacobians(in.geometry, in.P * v + in.x0, &in.flat); };
  // the linear response of the map to the change of the integer values
  std::vector<Eigen::Index> integer;
  for(Eigen::Index j = 0; j < y.size(); ++j)
    if(in.integer_column[std::size_t(j)]) integer.push_back(j);
  solver.set_system(H, rhs);
  Eigen::VectorXd to, from;
  for(Eigen::Index j : integer) solver.fix(j, target[j]);
  const bool solved_to = solver.solve(to);
  for(Eigen::Index j : integer) solver.fix(j, seamless_y[j]);
  const bool solved_from = solver.solve(from);
  Eigen::VectorXd z = seamless_y;
  double t = 0;
  if(solved_to && solved_from) {
    const Eigen::VectorXd direction = to - from;
    double step = 0.25;
    for(int steps = 0; t < 1 && steps < maximum_steps && step > 1. / 4096;) {
      const double next = (std::min)(1., t + step);
      Eigen::VectorXd trial = z + (next - t) * direction;
      for(Eigen::Index j : integer) trial[j] = next == 1. ? target[j] : seamless_y[j] + next * (target[j] - seamless_y[j]);
      if(folds(trial) > 0) { step /= 2; ++r.halvings; continue; }
      relax_near_folds(mesh, in, trial);
      z = trial;
      t = next;
      ++steps;
      ++r.steps;
      step *= 1.5;
    }
  }
  r.parameter = t;
  r.reached = t == 1.;
  if(r.reached) {
    r.folds_after = folds(z);
    r.branched_after = r.folds_after > 0 ? 0 : count_branched_edges(mesh, in.P * z + in.x0);
    r.kept = r.folds_after == 0 && r.branched_after == 0;
    if(r.kept) y = z;
  }
  for(Eigen::Index j : integer) solver.fix(j, y[j]);
  r.seconds += std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_CONTINUATION_H
