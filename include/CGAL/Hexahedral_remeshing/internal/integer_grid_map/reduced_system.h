// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_REDUCED_SYSTEM_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_REDUCED_SYSTEM_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>

#include <Eigen/Sparse>

#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The energy in the free variables y of x = P y + x0: H = P^T A P + reg I, rhs = P^T (b - A x0).
// The tiny regularization keeps H definite when a variable (a jump that no tetrahedron sees) does not
// enter the energy; it is far below the scale of the map (relative 1e-10 of the mean diagonal).
inline void assemble_reduced_system(const Map_geometry& geometry, const std::vector<Eigen::Matrix3d>& frames, double s,
                                    const std::vector<double>& weights,
                                    const Eigen::SparseMatrix<double, Eigen::RowMajor>& P, const Eigen::VectorXd& x0,
                                    Eigen::SparseMatrix<double>& H, Eigen::VectorXd& rhs)
{
  Eigen::SparseMatrix<double> A;
  Eigen::VectorXd b;
  assemble_map_energy(geometry, frames, s, weights, A, b);
  const Eigen::SparseMatrix<double> Pc = P;
  const Eigen::SparseMatrix<double> AP = A * Pc;
  H = Eigen::SparseMatrix<double>(Pc.transpose()) * AP;
  rhs = Pc.transpose() * (b - A * x0);
  double mean = 0;
  for(Eigen::Index i = 0; i < H.rows(); ++i) mean += H.coeff(i, i);
  mean = H.rows() > 0 ? mean / double(H.rows()) : 1.0;
  Eigen::SparseMatrix<double> I(H.rows(), H.cols());
  I.setIdentity();
  H += (1e-10 * mean) * I;
  H.makeCompressed();
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_REDUCED_SYSTEM_H
