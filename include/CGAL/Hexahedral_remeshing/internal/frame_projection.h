// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_PROJECTION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_PROJECTION_H

#include <CGAL/Hexahedral_remeshing/internal/spherical_harmonics.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Projection of a 9-vector onto the set of valid frames {q(R), R in SO(3)} (design 1.6): the rotation R
// maximizing <q/|q|, q(R)>, i.e. the closest frame.  The set is a 3-manifold, so the nearest point is
// found by Gauss-Newton on SO(3) from a few seeds: the tangent space at a = q(R) is spanned by
// Lx a, Ly a, Lz a (left rotations), so each step solves a 3x3 normal system.

// Gauss-Newton from R (in/out) towards the unit vector q; returns <q, q(R)> at the final R.
// Far from the manifold plain Gauss-Newton can overshoot, so a step longer than 1e-3 rad is halved until
// ||q - q(R)|| decreases (at most 20 times; the iteration stops if none does).  Shorter steps are taken as
// they are: there Gauss-Newton is contractive, and comparing residuals would only measure rounding noise.
// Stops when |omega| < tolerance or after max_iterations.
inline double refine_frame(const Vector9& q, Eigen::Matrix3d& R, int max_iterations = 50, double tolerance = 1e-12)
{
  const Matrix9& Lx = sh_generator_x();
  const Matrix9& Ly = sh_generator_y();
  const Matrix9& Lz = sh_generator_z();
  auto rotate = [](const Eigen::Vector3d& omega, const Eigen::Matrix3d& M) {
    const double angle = omega.norm();
    if(angle == 0.)
      return M;
    return Eigen::Matrix3d(Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix() * M);
  };

  Vector9 a = frame_to_sh(R);
  double residual = (q - a).squaredNorm();
  for(int it = 0; it < max_iterations; ++it) {
    Eigen::Matrix<double, 9, 3> J;
    J.col(0) = Lx * a;
    J.col(1) = Ly * a;
    J.col(2) = Lz * a;
    // Normal equations (J^T J) omega = J^T (q - a).  J^T J = (20/3) I at every frame: it is so at q_ref
    // (the L_k q_ref are orthogonal, of squared norm 20/3), and q(R E) = D(R) q(E) with D orthogonal and
    // D(R) L_k D(R)^T = sum_l R_lk L_l carries this to any frame, so no 3x3 solve is needed.  (Checked in
    // the tests.)
    const Eigen::Vector3d omega = (3. / 20.) * (J.transpose() * (q - a));
    const double length = omega.norm();
    if(length < 1e-3) {
      R = rotate(omega, R);
      a = frame_to_sh(R);
      residual = (q - a).squaredNorm();
      if(length < tolerance)
        break;
      continue;
    }
    bool accepted = false;
    double step = 1.;
    for(int halving = 0; halving < 20 && !accepted; ++halving, step *= 0.5) {
      const Eigen::Matrix3d trial = rotate(step * omega, R);
      const Vector9 trial_a = frame_to_sh(trial);
      const double trial_residual = (q - trial_a).squaredNorm();
      if(trial_residual < residual) {
        R = trial;
        a = trial_a;
        residual = trial_residual;
        accepted = true;
      }
    }
    if(!accepted)
      break;
  }
  return q.dot(a);
}

// Closest frame to q.  Seeds: I, Rx(pi/4), Ry(pi/4), Rz(pi/4), Rz(pi/4)Rx(pi/4) (they cover the distinct
// basins of <q, q(R)>; geogram and mouette use the same five) plus the optional already-projected
// neighbour frame.  Every seed is refined and the best final dot is kept: a seed that starts best can end
// in a worse local maximum.  Ties keep the earliest seed, so the result is deterministic.
// If |q| < 1e-6 the direction is meaningless: the hint (or identity) is returned unchanged.
inline Eigen::Matrix3d project_to_frame(const Vector9& q, const Eigen::Matrix3d* neighbour_hint = nullptr)
{
  const double norm = q.norm();
  if(norm < 1e-6)
    return neighbour_hint != nullptr ? *neighbour_hint : Eigen::Matrix3d::Identity();
  const Vector9 qn = q / norm;

  const double quarter_pi = 0.25 * sh_detail::pi;
  const Eigen::Matrix3d Rx = Eigen::AngleAxisd(quarter_pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d Ry = Eigen::AngleAxisd(quarter_pi, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d Rz = Eigen::AngleAxisd(quarter_pi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  std::array<Eigen::Matrix3d, 6> seeds = {Eigen::Matrix3d::Identity(), Rx, Ry, Rz, Eigen::Matrix3d(Rz * Rx),
                                          Eigen::Matrix3d::Identity()};
  int seed_count = 5;
  if(neighbour_hint != nullptr)
    seeds[seed_count++] = *neighbour_hint;

  Eigen::Matrix3d best = Eigen::Matrix3d::Identity();
  double best_dot = -2.; // dots of unit vectors are >= -1
  for(int s = 0; s < seed_count; ++s) {
    Eigen::Matrix3d R = seeds[s];
    const double dot = refine_frame(qn, R);
    if(dot > best_dot) {
      best_dot = dot;
      best = R;
    }
  }
  return best;
}

// Faster variant for the initialization of a frame field, where the projection only seeds L-BFGS:
// the seeds are ranked by their starting dot and only the `refined` best ones are refined, to a
// looser tolerance. Deterministic (ties keep the earliest seed).
inline Eigen::Matrix3d project_to_frame_fast(const Vector9& q, int refined = 2, double tolerance = 1e-9)
{
  const double norm = q.norm();
  if(norm < 1e-6)
    return Eigen::Matrix3d::Identity();
  const Vector9 qn = q / norm;
  const double quarter_pi = 0.25 * sh_detail::pi;
  const Eigen::Matrix3d Rx = Eigen::AngleAxisd(quarter_pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d Ry = Eigen::AngleAxisd(quarter_pi, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Matrix3d Rz = Eigen::AngleAxisd(quarter_pi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const std::array<Eigen::Matrix3d, 5> seeds = {Eigen::Matrix3d::Identity(), Rx, Ry, Rz, Eigen::Matrix3d(Rz * Rx)};
  std::array<std::pair<double, int>, 5> ranked;
  for(int s = 0; s < 5; ++s) ranked[std::size_t(s)] = {-qn.dot(frame_to_sh(seeds[std::size_t(s)])), s};
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const std::pair<double, int>& a, const std::pair<double, int>& b) { return a.first < b.first; });
  Eigen::Matrix3d best = Eigen::Matrix3d::Identity();
  double best_dot = -2.;
  for(int k = 0; k < refined && k < 5; ++k) {
    Eigen::Matrix3d R = seeds[std::size_t(ranked[std::size_t(k)].second)];
    const double dot = refine_frame(qn, R, 50, tolerance);
    if(dot > best_dot) {
      best_dot = dot;
      best = R;
    }
  }
  return best;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_PROJECTION_H
