// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_STIFFENING_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_STIFFENING_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fixed_variable_solver.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/reduced_system.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Distortion of tetrahedron t relative to the target s E_t^T: |sigma1/sigma3 - 1| + |log(det J / s^3)|,
// `maximum` for an inverted or flat tetrahedron (algorithms.md §4 "Validity and repair" (1)).
inline double map_distortion(const Eigen::Matrix3d& J, double s, double maximum)
{
  const double det = J.determinant();
  if(!(det > 0)) return maximum;
  const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix3d>(J).singularValues();
  return (std::min)(maximum, std::abs(sv[0] / sv[2] - 1.0) + std::abs(std::log(det / (s * s * s))));
}

// Tetrahedra with det J <= 0, those flagged in `skip` (if given) left out.
inline std::size_t count_non_positive_jacobians(const Map_geometry& geometry, const Eigen::VectorXd& x,
                                                const std::vector<char>* skip = nullptr)
{
  std::size_t n = 0;
  for(std::size_t t = 0; t < geometry.volumes.size(); ++t)
    if(!skip || !(*skip)[t]) n += !(map_jacobian(geometry, x, t).determinant() > 0);
  return n;
}

// MIQ stiffening: while some tetrahedron is inverted, raise the weight of every tetrahedron by its
// distortion (w_t += min(c dist_t, d_max)) and re-solve the continuous variables with the integers
// fixed in `solver` (numeric factorization only). Keeps the best y (fewest non-positive Jacobians
// among the tetrahedra not flagged in `flat`, which no y repairs); stops after 3 rounds without
// improvement. Returns the number of rounds run.
inline int stiffen_map(const Map_geometry& geometry, const std::vector<Eigen::Matrix3d>& frames, double s,
                       const Eigen::SparseMatrix<double, Eigen::RowMajor>& P, const Eigen::VectorXd& x0,
                       const std::vector<char>& flat, Fixed_variable_solver& solver, Eigen::VectorXd& y,
                       int maximum_rounds, double c = 1.0, double d_max = 5.0)
{
  const std::size_t nt = geometry.volumes.size();
  std::vector<double> weights(nt, 1.0);
  Eigen::VectorXd x = P * y + x0;
  std::size_t best = count_non_positive_jacobians(geometry, x, &flat);
  Eigen::VectorXd best_y = y;
  int rounds = 0, since_best = 0;
  for(; rounds < maximum_rounds && best > 0 && since_best < 3; ++rounds) {
    for(std::size_t t = 0; t < nt; ++t)
      weights[t] += (std::min)(c * map_distortion(map_jacobian(geometry, x, t), s, d_max), d_max);
    Eigen::SparseMatrix<double> H;
    Eigen::VectorXd rhs;
    assemble_reduced_system(geometry, frames, s, weights, P, x0, H, rhs);
    solver.set_system(H, rhs);
    if(!solver.solve(y)) break;
    x = P * y + x0;
    const std::size_t n = count_non_positive_jacobians(geometry, x, &flat);
    if(n < best) { best = n; best_y = y; since_best = 0; }
    else ++since_best;
  }
  y = best_y;
  return rounds;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_STIFFENING_H
