// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_STRUCTURALLY_FLAT_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_STRUCTURALLY_FLAT_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <random>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Per tetrahedron: 1 if the constraints flatten it whatever the free variables y are (three corners
// on one singular line after a jog of the curve), i.e. det J_t = 0 on the whole affine space
// x = P y + x0. Tested at one random y: det J_t is a polynomial in y, which vanishes at a random point
// only if it is zero. Neither the stiffening nor the untangling can repair these tetrahedra, so they
// count among the failures of neither.
inline std::vector<char> structurally_flat_tetrahedra(const Map_geometry& geometry,
                                                      const Eigen::SparseMatrix<double, Eigen::RowMajor>& P,
                                                      const Eigen::VectorXd& x0)
{
  const std::size_t nt = geometry.volumes.size();
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd y_random(P.cols());
  for(Eigen::Index j = 0; j < P.cols(); ++j) y_random[j] = uniform(rng);
  const Eigen::VectorXd x_random = P * y_random + x0;
  std::vector<char> flat(nt, 0);
  for(std::size_t t = 0; t < nt; ++t) {
    Eigen::Matrix<double, 3, 4> U;
    for(int c = 0; c < 4; ++c) U.col(c) = x_random.segment<3>(Eigen::Index(12 * t + 3 * c));
    const double scale = (U.col(1) - U.col(0)).norm() * (U.col(2) - U.col(0)).norm() * (U.col(3) - U.col(0)).norm();
    flat[t] = std::abs((U * geometry.gradients[t].transpose()).determinant()) * geometry.volumes[t] * 6 <= 1e-12 * scale;
  }
  return flat;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_STRUCTURALLY_FLAT_H
