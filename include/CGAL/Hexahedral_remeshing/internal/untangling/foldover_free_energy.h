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

// The energy of an element from det K and tr(K^T K), and the two coefficients of its derivative:
// df/dK = a K + b cof(K). Shared by the textbook and the fused evaluation, which so compute the same bits.
struct Foldover_free_scalars
{
  double energy, a, b;
};

inline Foldover_free_scalars foldover_free_scalars(double det, double trace, double eps, double theta)
{
  const double c1 = foldover_free_chi(det, eps);
  const double c2 = std::cbrt(c1 * c1);
  const double f = trace / c2;
  const double g = (1. + det * det) / c1;
  const double c3 = foldover_free_chi_derivative(det, eps);
  // d f / dK = 2K / chi^{2/3} - (2/3) f chi'/chi cof(K); d g / dK = (2 det - g chi') / chi cof(K)
  return {(1. - theta) * f + theta * g, (1. - theta) * (2. / c2),
          (1. - theta) * (-2. * f * c3 / (3. * c1)) + theta * (2. * det - g * c3) / c1};
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
  const Foldover_free_scalars s = foldover_free_scalars(K.col(0).dot(C.col(0)), K.squaredNorm(), eps, theta);
  if(dK != nullptr) *dK = s.a * K + s.b * C;
  return s.energy;
}

// The foldover-free untangling's work on one tetrahedron (foldover_free_map.h), fused and unrolled:
// returns w f(K) for K = D M, D the corner differences (c_1 - c_0, c_2 - c_0, c_3 - c_0) as columns, and
// writes d(w f)/dc into g (12 values, the layout of c: 3 coordinates per corner). It computes what
// foldover_free_element_energy() computes on Eigen's 3x3 products, in the same order of operations, so
// that maps keep their bits: Eigen 3.4 (SSE2) sums rows 0 and 1 of a product as (a0 b0 + a1 b1) + a2 b2
// (two rows per packet) and row 2 as a0 b0 + (a1 b1 + a2 b2), and a squared norm of 9 values in two
// interleaved pairs. Through Eigen's out-of-line 3x3 products and temporaries an element cost 102 ns,
// fused 78 ns (random elements, one thread); on the flange of make_parts.py the seamless map's
// untanglings take about 5% less time.
inline double foldover_free_fused_element(const double* c, const Eigen::Matrix3d& Me, double w, double eps, double theta,
                                          double* g)
{
  const double* M = Me.data(); // column-major
  const auto head = [](double a0, double a1, double a2, double b0, double b1, double b2) { return (a0 * b0 + a1 * b1) + a2 * b2; };
  const auto tail = [](double a0, double a1, double a2, double b0, double b1, double b2) { return a0 * b0 + (a1 * b1 + a2 * b2); };
  const double d[9] = {c[3] - c[0], c[4] - c[1], c[5] - c[2], c[6] - c[0], c[7] - c[1], c[8] - c[2], c[9] - c[0], c[10] - c[1], c[11] - c[2]};
  double K[9];
  for(int j = 0; j < 3; ++j) {
    const double* m = M + 3 * j;
    K[3 * j] = head(d[0], d[3], d[6], m[0], m[1], m[2]);
    K[3 * j + 1] = head(d[1], d[4], d[7], m[0], m[1], m[2]);
    K[3 * j + 2] = tail(d[2], d[5], d[8], m[0], m[1], m[2]);
  }
  const double *k0 = K, *k1 = K + 3, *k2 = K + 6;
  const double C[9] = {k1[1] * k2[2] - k1[2] * k2[1], k1[2] * k2[0] - k1[0] * k2[2], k1[0] * k2[1] - k1[1] * k2[0],
                       k2[1] * k0[2] - k2[2] * k0[1], k2[2] * k0[0] - k2[0] * k0[2], k2[0] * k0[1] - k2[1] * k0[0],
                       k0[1] * k1[2] - k0[2] * k1[1], k0[2] * k1[0] - k0[0] * k1[2], k0[0] * k1[1] - k0[1] * k1[0]};
  const double det = head(k0[0], k0[1], k0[2], C[0], C[1], C[2]);
  const double trace = ((K[0] * K[0] + K[2] * K[2]) + (K[4] * K[4] + K[6] * K[6])) +
                       ((K[1] * K[1] + K[3] * K[3]) + (K[5] * K[5] + K[7] * K[7])) + K[8] * K[8];
  const Foldover_free_scalars s = foldover_free_scalars(det, trace, eps, theta);
  double W[9]; // w df/dK
  for(int i = 0; i < 9; ++i) W[i] = w * (s.a * K[i] + s.b * C[i]);
  // K = D M: d/dD = W M^T; corners 1..3 get its columns, corner 0 minus their sum
  for(int k = 0; k < 3; ++k) {
    const double m0 = M[k], m1 = M[3 + k], m2 = M[6 + k];
    g[3 * (k + 1)] = head(W[0], W[3], W[6], m0, m1, m2);
    g[3 * (k + 1) + 1] = head(W[1], W[4], W[7], m0, m1, m2);
    g[3 * (k + 1) + 2] = tail(W[2], W[5], W[8], m0, m1, m2);
  }
  for(int r = 0; r < 3; ++r) g[r] = -(g[3 + r] + g[6 + r] + g[9 + r]);
  return w * s.energy;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNTANGLING_FOLDOVER_FREE_ENERGY_H
