// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNTANGLING_FOLDOVER_FREE_ENERGY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNTANGLING_FOLDOVER_FREE_ENERGY_H

#include <Eigen/Dense>

#include <cmath>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The regularized barrier of Garanzha, Kaporin, Kudryavtseva, Protais, Ray, Sokolov 2021,
// "Foldover-free maps in 50 lines of code" (ACM TOG 40(4)): chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2.
// For D <= 0 the textbook form cancels catastrophically (D + |D| with |D| >> eps); the conjugate form
// eps^2 / (2 (sqrt(eps^2 + D^2) - D)) is the same number without the cancellation.
inline double foldover_free_chi(double D, double eps)
{
  const double r = std::sqrt(eps * eps + D * D);
  if(D > 0) return 0.5 * (D + r);
  return 0.5 * eps * eps / (r - D);
}

// d chi / dD, in (0, 1).
inline double foldover_free_chi_derivative(double D, double eps)
{
  return 0.5 + 0.5 * D / std::sqrt(eps * eps + D * D);
}

// d det(K) / dK, the cofactor matrix (columns: k1 x k2, k2 x k0, k0 x k1), defined also for singular K.
inline Eigen::Matrix3d foldover_free_cofactor(const Eigen::Matrix3d& K)
{
  Eigen::Matrix3d C;
  C.col(0) = K.col(1).cross(K.col(2));
  C.col(1) = K.col(2).cross(K.col(0));
  C.col(2) = K.col(0).cross(K.col(1));
  return C;
}

// Energy of one element with Jacobian-like matrix K (K = I is the ideal element):
//   f = (1 - theta) tr(K^T K) / chi(det K, eps)^{2/3} + theta (det^2 K + 1) / chi(det K, eps).
// The first term measures the shape (scale invariant: minimal for similarities), the second the
// volume (minimal for det = 1); both tend to +infinity as det K -> 0+ when eps -> 0.
// If `dK` is given, receives df/dK.
inline double foldover_free_element_energy(const Eigen::Matrix3d& K, double eps, double theta,
                                           Eigen::Matrix3d* dK = nullptr)
{
  const Eigen::Matrix3d C = foldover_free_cofactor(K);
  const double det = K.col(0).dot(C.col(0));
  const double c1 = foldover_free_chi(det, eps);
  const double c2 = std::cbrt(c1 * c1);
  const double trace = K.squaredNorm();
  const double f = trace / c2;
  const double g = (1. + det * det) / c1;
  if(dK != nullptr) {
    const double c3 = foldover_free_chi_derivative(det, eps);
    // d f / dK = 2K / chi^{2/3} - (2/3) f chi'/chi cof(K); d g / dK = (2 det - g chi') / chi cof(K)
    *dK = (1. - theta) * (2. / c2) * K
          + ((1. - theta) * (-2. * f * c3 / (3. * c1)) + theta * (2. * det - g * c3) / c1) * C;
  }
  return (1. - theta) * f + theta * g;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNTANGLING_FOLDOVER_FREE_ENERGY_H
