// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_PROJECT_TO_ROTATIONS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_PROJECT_TO_ROTATIONS_H

#include <CGAL/Hexahedral_remeshing/internal/realignment/realignment_system.h>

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Axial index of the local axis of E aligned with direction d and its sign: E^T d ~ sign e_k.
inline int aligned_axis(const Eigen::Matrix3d& E, const Eigen::Vector3d& d, double& sign)
{
  const Eigen::Vector3d c = E.transpose() * d;
  int k = 0;
  c.cwiseAbs().maxCoeff(&k);
  sign = c[k] >= 0 ? 1.0 : -1.0;
  return k;
}

// R = the rotation closest to E (polar decomposition by SVD, kept right-handed).
inline void closest_rotation(const Eigen::Matrix3d& E, Eigen::Matrix3d& R)
{
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(E, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  R = svd.matrixU() * D * svd.matrixV().transpose();
}

// R = the rotation closest to E with its axis k exactly on s n: a 2D Procrustes of the two other
// columns inside the tangent plane (basis B, right-handed about n), keeping the frame right-handed.
inline void closest_constrained_rotation(const Eigen::Matrix3d& E, const Eigen::Matrix<double, 3, 2>& B,
                                         const Eigen::Vector3d& n, int k, double s, Eigen::Matrix3d& R)
{
  const int a = (k + 1) % 3, c = (k + 2) % 3;
  Eigen::Matrix2d M;
  M.col(0) = B.transpose() * E.col(a);
  M.col(1) = B.transpose() * E.col(c);
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix2d Q = svd.matrixU() * svd.matrixV().transpose();
  // columns (a, c, k) must be right-handed: col_a x col_c = col_k = s n, i.e. det(Q) = s
  // (B is right-handed about n: B.col(0) x B.col(1) = n)
  if(Q.determinant() * s < 0) {
    Eigen::Matrix2d Dm = Eigen::Matrix2d::Identity();
    Dm(1, 1) = -1;
    Q = svd.matrixU() * Dm * svd.matrixV().transpose();
  }
  R.col(k) = s * n;
  R.col(a) = B * Q.col(0);
  R.col(c) = B * Q.col(1);
}

// Projects the solved matrices E (per solver tet) to rotations into `frames` (per mesh tet; in:
// the old frames, whose axis along the direction decides which axis goes onto the normal). The
// errors are maxima, the same in any order: constraint_error, the largest violation of
// n_i^T E' = v_i^T E before the projection; alignment_error, the largest |1 - |R^T n_i|_inf| after.
template <class Traits>
void project_to_rotations(const Realignment_system<Traits>& system, const std::vector<Eigen::Matrix3d>& E,
                          const std::vector<Eigen::Vector3d>& normals, const std::vector<Eigen::Vector3d>& directions,
                          std::vector<Eigen::Matrix3d>& frames, double& constraint_error, double& alignment_error)
{
  double c_error = 0, a_error = 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) reduction(max : c_error, a_error)
#endif
  for(std::ptrdiff_t ti = 0; ti < std::ptrdiff_t(system.nt); ++ti) {
    const std::size_t t = std::size_t(ti);
    Eigen::Matrix3d& frame = frames[system.mesh_tet(t)];
    if(!system.is_constrained(t)) {
      closest_rotation(E[t], frame);
      continue;
    }
    const auto bt = system.constraint[t];
    const Eigen::Vector3d& nrm = normals[bt];
    double s = 1;
    const int k = aligned_axis(frame, directions[bt].normalized(), s);
    c_error = (std::max)(c_error, (nrm.transpose() * E[t] - directions[bt].normalized().transpose() * frame).cwiseAbs().maxCoeff());
    Eigen::Matrix3d R;
    closest_constrained_rotation(E[t], system.T[t], nrm, k, s, R);
    frame = R;
    const Eigen::Vector3d check = R.transpose() * nrm;
    a_error = (std::max)(a_error, std::abs(1.0 - check.cwiseAbs().maxCoeff()));
  }
  constraint_error = (std::max)(constraint_error, c_error);
  alignment_error = (std::max)(alignment_error, a_error);
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_PROJECT_TO_ROTATIONS_H
