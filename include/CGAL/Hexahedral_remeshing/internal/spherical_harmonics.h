// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SPHERICAL_HARMONICS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SPHERICAL_HARMONICS_H

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Frames as L4 real spherical harmonics (design 1.1-1.4).  A frame E (a rotation whose columns are the
// axes) is represented by the 9 coefficients q(E) of the band-4 part of f_E(x) = sum_i (E e_i . x)^4.
// q is invariant under the 24 symmetries of the cube (q(E g) = q(E)), which is what makes a smooth frame
// field a plain vector-field problem.  Rotating the frame acts linearly: q(R E) = D(R) q(E), D(R) being
// a 9x9 orthogonal matrix (Wigner matrix of band 4) and R -> D(R) a group homomorphism.

using Vector9 = Eigen::Matrix<double, 9, 1>;
using Matrix9 = Eigen::Matrix<double, 9, 9>;
using Matrix9x2 = Eigen::Matrix<double, 9, 2>;

namespace sh_detail {

constexpr double pi = 3.14159265358979323846;

// exp(A) by scaling and squaring of a Taylor series.  Only used once per constant (Dx(pi/2)), so plain
// and dependency-free beats Eigen's unsupported module; for the antisymmetric A used here it is accurate
// to a few ulps (checked against unsupported/Eigen/MatrixFunctions in the tests).
inline Matrix9 matrix_exponential(const Matrix9& A)
{
  const double norm = A.cwiseAbs().colwise().sum().maxCoeff(); // 1-norm
  int squarings = 0;
  double scale = 1.;
  while(norm * scale > 0.25) {
    scale *= 0.5;
    ++squarings;
  }
  const Matrix9 B = scale * A;
  // ||B|| <= 1/4: the terms B^k/k! fall below 1e-17 relative well before k = 20.
  Matrix9 result = Matrix9::Identity();
  Matrix9 term = Matrix9::Identity();
  for(int k = 1; k <= 20; ++k) {
    term = (term * B) / double(k);
    result += term;
  }
  for(int i = 0; i < squarings; ++i)
    result = (result * result).eval();
  return result;
}

inline Eigen::Matrix3d rotation_z(double t) { return Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }
inline Eigen::Matrix3d rotation_y(double t) { return Eigen::AngleAxisd(t, Eigen::Vector3d::UnitY()).toRotationMatrix(); }

// Fills the antisymmetric generator from its upper entries.
inline void set_antisymmetric(Matrix9& L, int r, int c, double value)
{
  L(r, c) = value;
  L(c, r) = -value;
}

} // namespace sh_detail

// Real L4 spherical harmonics Y_0..Y_8 (orders m = -4..4) at the unit vector x (not normalized here:
// callers pass frame axes, which are unit vectors).
inline Vector9 sh_basis(const Eigen::Vector3d& p)
{
  using sh_detail::pi;
  const double x = p.x(), y = p.y(), z = p.z();
  const double x2 = x * x, y2 = y * y, z2 = z * z;
  Vector9 Y;
  Y[0] = 0.75 * std::sqrt(35. / pi) * x * y * (x2 - y2);
  Y[1] = 0.75 * std::sqrt(35. / (2. * pi)) * y * z * (3. * x2 - y2);
  Y[2] = 0.75 * std::sqrt(5. / pi) * x * y * (7. * z2 - 1.);
  Y[3] = 0.75 * std::sqrt(5. / (2. * pi)) * y * z * (7. * z2 - 3.);
  Y[4] = (3. / 16.) * std::sqrt(1. / pi) * (35. * z2 * z2 - 30. * z2 + 3.);
  Y[5] = 0.75 * std::sqrt(5. / (2. * pi)) * x * z * (7. * z2 - 3.);
  Y[6] = (3. / 8.) * std::sqrt(5. / pi) * (x2 - y2) * (7. * z2 - 1.);
  Y[7] = 0.75 * std::sqrt(35. / (2. * pi)) * x * z * (x2 - 3. * y2);
  Y[8] = (3. / 16.) * std::sqrt(35. / pi) * (x2 * x2 - 6. * x2 * y2 + y2 * y2);
  return Y;
}

// q of the identity frame: sqrt(7/12) e4 + sqrt(5/12) e8 (unit norm).
inline Vector9 reference_sh_frame()
{
  Vector9 q = Vector9::Zero();
  q[4] = std::sqrt(7. / 12.);
  q[8] = std::sqrt(5. / 12.);
  return q;
}

// Closed form q(E) = normalize(Y(E e_1) + Y(E e_2) + Y(E e_3)) (addition theorem): no Euler angles and
// q(I) = reference_sh_frame() up to rounding.
inline Vector9 frame_to_sh(const Eigen::Matrix3d& E)
{
  const Vector9 s = sh_basis(E.col(0)) + sh_basis(E.col(1)) + sh_basis(E.col(2));
  return s.normalized();
}

// Infinitesimal generators: q(Rot_axis(t) E) = exp(t L_axis) q(E) (world rotation by +t).
inline const Matrix9& sh_generator_x()
{
  static const Matrix9 L = [] {
    Matrix9 M = Matrix9::Zero();
    const double s2 = std::sqrt(2.), s72 = std::sqrt(3.5), s10 = std::sqrt(10.), t2 = 3. / std::sqrt(2.);
    sh_detail::set_antisymmetric(M, 0, 7, -s2);
    sh_detail::set_antisymmetric(M, 1, 6, -s72);
    sh_detail::set_antisymmetric(M, 1, 8, -s2);
    sh_detail::set_antisymmetric(M, 2, 5, -t2);
    sh_detail::set_antisymmetric(M, 2, 7, -s72);
    sh_detail::set_antisymmetric(M, 3, 4, -s10);
    sh_detail::set_antisymmetric(M, 3, 6, -t2);
    return M;
  }();
  return L;
}

inline const Matrix9& sh_generator_y()
{
  static const Matrix9 L = [] {
    Matrix9 M = Matrix9::Zero();
    const double s2 = std::sqrt(2.), s72 = std::sqrt(3.5), s10 = std::sqrt(10.), t2 = 3. / std::sqrt(2.);
    sh_detail::set_antisymmetric(M, 0, 1, s2);
    sh_detail::set_antisymmetric(M, 1, 2, s72);
    sh_detail::set_antisymmetric(M, 2, 3, t2);
    sh_detail::set_antisymmetric(M, 4, 5, -s10);
    sh_detail::set_antisymmetric(M, 5, 6, -t2);
    sh_detail::set_antisymmetric(M, 6, 7, -s72);
    sh_detail::set_antisymmetric(M, 7, 8, -s2);
    return M;
  }();
  return L;
}

inline const Matrix9& sh_generator_z()
{
  static const Matrix9 L = [] {
    Matrix9 M = Matrix9::Zero();
    for(int i = 0; i < 4; ++i)
      sh_detail::set_antisymmetric(M, i, 8 - i, double(4 - i));
    return M;
  }();
  return L;
}

// Dz(t) = exp(t Lz) in closed form: each pair (q_i, q_{8-i}) of order m = 4 - i turns by the angle m t.
inline Matrix9 sh_rotation_z(double t)
{
  Matrix9 D = Matrix9::Zero();
  D(4, 4) = 1.;
  for(int i = 0; i < 4; ++i) {
    const double m = 4 - i;
    const double c = std::cos(m * t), s = std::sin(m * t);
    D(i, i) = c;
    D(i, 8 - i) = s;
    D(8 - i, i) = -s;
    D(8 - i, 8 - i) = c;
  }
  return D;
}

// Dx(pi/2) = exp(pi/2 Lx): the only non-diagonal factor needed for arbitrary rotations (ZYZ, below).
// Computed once, thread-safe function-local static.
inline const Matrix9& sh_rotation_x_half_pi()
{
  static const Matrix9 D = sh_detail::matrix_exponential((0.5 * sh_detail::pi) * sh_generator_x());
  return D;
}

// D(R) with q(R E) = D(R) q(E), through R = Rz(alpha) Ry(beta) Rz(gamma) and
// D = Dz(alpha) Dx(-pi/2) Dz(beta) Dx(pi/2) Dz(gamma), since Ry(beta) = Rx(-pi/2) Rz(beta) Rx(pi/2).
// Gimbal lock (sin beta ~ 0) makes alpha ill-defined; gamma is therefore not read from R but taken from
// the residual Rz(gamma) = Ry(beta)^T Rz(alpha)^T R, which is a z-rotation up to rounding whatever alpha
// came out, so the product is exact to rounding for every R.
inline Matrix9 sh_rotation(const Eigen::Matrix3d& R)
{
  const double beta = std::atan2(std::hypot(R(0, 2), R(1, 2)), R(2, 2));
  const double alpha = std::atan2(R(1, 2), R(0, 2));
  const Eigen::Matrix3d G = sh_detail::rotation_y(beta).transpose() * sh_detail::rotation_z(alpha).transpose() * R;
  const double gamma = std::atan2(G(1, 0), G(0, 0));
  const Matrix9& X = sh_rotation_x_half_pi();
  return sh_rotation_z(alpha) * X.transpose() * sh_rotation_z(beta) * X * sh_rotation_z(gamma);
}

// A rotation R with R e_z = v (v need not be unit).  Minimal rotation (axis e_z x v) when v.z >= -1/2;
// near -e_z that formula divides by 1 + v.z ~ 0, so there the minimal rotation from -e_z to v is composed
// with Rx(pi) (which maps e_z to -e_z).  Any such R is valid for the frame family below.
inline Eigen::Matrix3d minimal_rotation_to(const Eigen::Vector3d& v)
{
  const Eigen::Vector3d u = v.normalized();
  // Rodrigues for the rotation taking unit a to unit b: I + [k]x + [k]x^2 / (1 + a.b), k = a x b.
  auto rodrigues = [](const Eigen::Vector3d& k, double c) {
    Eigen::Matrix3d K;
    K << 0., -k.z(), k.y(),
         k.z(), 0., -k.x(),
         -k.y(), k.x(), 0.;
    return Eigen::Matrix3d(Eigen::Matrix3d::Identity() + K + (K * K) / (1. + c));
  };
  if(u.z() >= -0.5)
    return rodrigues(Eigen::Vector3d(-u.y(), u.x(), 0.), u.z()); // e_z x u
  const Eigen::Matrix3d Rx_pi = Eigen::Vector3d(1., -1., -1.).asDiagonal();
  return rodrigues(Eigen::Vector3d(u.y(), -u.x(), 0.), -u.z()) * Rx_pi; // (-e_z) x u
}

// Frames with an axis along v (design 1.4): q(theta) = offset + sqrt(5/12) basis (sin 4theta, cos 4theta)
// for E = R_v Rz(theta), R_v = minimal_rotation_to(v).  In the convex relaxation (a, b) = coefficients on
// basis are free, which keeps the problem linear while the e4 part (offset) prevents q = 0.
struct Sh_frame_family
{
  Matrix9x2 basis; // D(R_v) [e0 e8]
  Vector9 offset;  // D(R_v) sqrt(7/12) e4
};

inline Sh_frame_family sh_frame_family(const Eigen::Vector3d& v)
{
  const Matrix9 D = sh_rotation(minimal_rotation_to(v));
  Sh_frame_family family;
  family.basis.col(0) = D.col(0);
  family.basis.col(1) = D.col(8);
  family.offset = std::sqrt(7. / 12.) * D.col(4);
  return family;
}

// Closed-form projection of the relaxed (a, b) back onto the family: theta = atan2(a, b) / 4,
// E = R_v Rz(theta); E e_z = v exactly (to rounding) whatever (a, b).
inline Eigen::Matrix3d frame_from_family(const Eigen::Vector3d& v, double a, double b)
{
  const double theta = 0.25 * std::atan2(a, b);
  return minimal_rotation_to(v) * sh_detail::rotation_z(theta);
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SPHERICAL_HARMONICS_H
