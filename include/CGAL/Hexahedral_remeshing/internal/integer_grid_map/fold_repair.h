// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_FOLD_REPAIR_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_FOLD_REPAIR_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fixed_variable_solver.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/stiffening.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/untangle_map.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

struct Fold_repair_report
{
  int stiffening_rounds = 0;
  bool untangling_ran = false;
  double stiffening_seconds = 0, untangling_seconds = 0;
};

// The map's equations and what the repair may move (the integer variables are fixed in `solver`).
struct Fold_repair_input
{
  const Map_geometry& geometry;
  const std::vector<Eigen::Matrix3d>& frames;
  double s;
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& P;
  const Eigen::VectorXd& x0;
  const std::vector<char>& integer_column;
  const std::vector<char>& flat;  // structurally flat tetrahedra: no y repairs them
};

// The local untangling of the folds of `y` (the continuous variables of the tetrahedra within `rings`
// rings of them move), if those rings hold at most a quarter of the tetrahedra; `y` is replaced only if
// the untangling leaves fewer inverted tetrahedra, after at most `outer_iterations` updates of the
// barrier. Returns false if the rings were too large.
template <class Traits>
bool untangle_folds_locally(const Tetrahedral_mesh_3<Traits>& mesh, const Fold_repair_input& in, int rings, bool& ran, Eigen::VectorXd& y,
                            int outer_iterations = 50)
{
  const std::vector<char> region = untangling_region(mesh, in.geometry, in.P * y + in.x0, in.flat, rings);
  if(std::size_t(std::count(region.begin(), region.end(), char(1))) > in.geometry.volumes.size() / 4) return false;
  ran = untangle_map(in.geometry, in.frames, in.s, in.P, in.x0, in.integer_column, in.flat, y, &region, false, outer_iterations).ran || ran;
  return true;
}

// Repair of the folds of the quantized map `y`, the integer values held. First the local untangling
// (the tets within `rings` rings of the folds): it repairs most maps alone, and the stiffening, a
// numeric factorization per round over the whole mesh, rarely changes the count (B0: 2 inverted
// before and after 3 rounds, 4.5 s of its 7.4 s map). If folds remain: stiffening from the quantized
// map, then the local untangling again and the global one if folds still remain (from the stiffened
// map: from the partly untangled one, s12c's hex mesh came out invalid). Folds whose rings hold more
// than a quarter of the tets go to the global untangling directly (and without `local_first`, which
// says the local untangling of `y` was tried already). `visitor` sees the stages "untangling" and
// "stiffening".
template <class Traits, class Visitor>
Fold_repair_report repair_folds(const Tetrahedral_mesh_3<Traits>& mesh, const Fold_repair_input& in, Fixed_variable_solver& solver,
                                bool untangle, int maximum_stiffening, int rings, Visitor& visitor, Eigen::VectorXd& y,
                                bool local_first = true)
{
  typedef std::chrono::steady_clock Clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  Fold_repair_report r;
  auto folds = [&](const Eigen::VectorXd& v) { return count_non_positive_jacobians(in.geometry, in.P * v + in.x0, &in.flat); };
  auto untangle_everywhere = [&](Eigen::VectorXd& v, const std::vector<char>* region) {
    r.untangling_ran = untangle_map(in.geometry, in.frames, in.s, in.P, in.x0, in.integer_column, in.flat, v, region).ran || r.untangling_ran;
  };
  auto untangle_locally = [&](Eigen::VectorXd& v) { return untangle_folds_locally(mesh, in, rings, r.untangling_ran, v); };
  if(folds(y) == 0) return r;
  if(untangle && local_first) {
    visitor.start_stage("untangling");
    const auto t = Clock::now();
    Eigen::VectorXd z = y;
    const bool repaired = untangle_locally(z) && folds(z) == 0;
    if(repaired) y = z;
    r.untangling_seconds += seconds_since(t);
    visitor.end_stage("untangling", seconds_since(t));
    if(repaired) return r;
  }
  visitor.start_stage("stiffening");
  auto t = Clock::now();
  r.stiffening_rounds = stiffen_map(in.geometry, in.frames, in.s, in.P, in.x0, in.flat, solver, y, maximum_stiffening);
  r.stiffening_seconds = seconds_since(t);
  visitor.end_stage("stiffening", r.stiffening_seconds);
  if(!untangle || folds(y) == 0) return r;
  visitor.start_stage("untangling");
  t = Clock::now();
  const Eigen::VectorXd stiffened = y;
  if(!untangle_locally(y) || folds(y) > 0) {
    y = stiffened;
    untangle_everywhere(y, nullptr);
  }
  r.untangling_seconds += seconds_since(t);
  visitor.end_stage("untangling", seconds_since(t));
  return r;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_FOLD_REPAIR_H
