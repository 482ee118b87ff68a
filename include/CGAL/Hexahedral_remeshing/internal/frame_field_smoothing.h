// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_SMOOTHING_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_SMOOTHING_H

#include <CGAL/Hexahedral_remeshing/internal/frame_field_problem.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <LBFGS.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

inline Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& w)
{
  Eigen::Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

// Smoothness energy of frames, F = sum_f w_f (5/3)(3 - sum_ab P_ab^4) with P = R_i^T R_j, which is
// sum_f w_f |q(R_i) - q(R_j)|^2 exactly (design 1.3): the energy of the relaxation, measured on
// rotations. Evaluated per face in parallel, summed sequentially (deterministic).
inline double frame_field_energy(const Frame_field_problem& p, const std::vector<Eigen::Matrix3d>& frames)
{
  std::vector<double> e(p.face_tets.size());
  const std::ptrdiff_t nf = std::ptrdiff_t(p.face_tets.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
  for(std::ptrdiff_t f = 0; f < nf; ++f) {
    const Eigen::Matrix3d P = frames[p.face_tets[f][0]].transpose() * frames[p.face_tets[f][1]];
    e[f] = p.face_weight[f] * (5.0 / 3.0) * (3.0 - P.array().square().square().sum());
  }
  double sum = 0;
  for(double x : e) sum += x;
  return sum;
}

// Non-linear smoothing of Ray et al. 2016 (design 1.7), per tet, with L-BFGS (LBFGS++) on rotation
// parameters re-centred at the current frames: 3 angles (Rz Ry Rx R0) for a free tet, 1 angle about
// the alignment direction for a constrained tet, so the constraint holds exactly throughout.
class Frame_field_smoother
{
public:
  Frame_field_smoother(const Frame_field_problem& p, std::vector<Eigen::Matrix3d>& frames)
    : m_p(p), m_frames(frames), m_base(frames)
  {
    m_offset.resize(p.number_of_tets + 1);
    m_offset[0] = 0;
    for(std::size_t t = 0; t < p.number_of_tets; ++t)
      m_offset[t + 1] = m_offset[t] + (p.is_constrained(Frame_field_problem::Index(t)) ? 1 : 3);
    m_face_gradient.resize(p.face_tets.size());
  }

  std::size_t number_of_unknowns() const { return m_offset.back(); }

  // Frames for parameters x (relative to the base frames); also the derivative bases.
  void update_frames(const Eigen::VectorXd& x)
  {
    const std::ptrdiff_t nt = std::ptrdiff_t(m_p.number_of_tets);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t t = 0; t < nt; ++t) {
      const std::size_t o = m_offset[t];
      if(m_p.is_constrained(Frame_field_problem::Index(t))) {
        m_frames[t] = Eigen::AngleAxisd(x[Eigen::Index(o)], m_p.direction(Frame_field_problem::Index(t))).toRotationMatrix() * m_base[t];
      } else {
        m_frames[t] = (Eigen::AngleAxisd(x[Eigen::Index(o + 2)], Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd(x[Eigen::Index(o + 1)], Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd(x[Eigen::Index(o)], Eigen::Vector3d::UnitX())).toRotationMatrix() * m_base[t];
      }
    }
  }

  // LBFGS++ objective: energy and gradient with respect to the parameters.
  double operator()(const Eigen::VectorXd& x, Eigen::VectorXd& grad)
  {
    update_frames(x);
    ++m_evaluations;
    const std::ptrdiff_t nf = std::ptrdiff_t(m_p.face_tets.size());
    std::vector<double> e(m_p.face_tets.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t f = 0; f < nf; ++f) {
      const Eigen::Matrix3d& Ri = m_frames[m_p.face_tets[f][0]];
      const Eigen::Matrix3d& Rj = m_frames[m_p.face_tets[f][1]];
      const Eigen::Matrix3d P = Ri.transpose() * Rj;
      const double w = m_p.face_weight[f];
      e[f] = w * (5.0 / 3.0) * (3.0 - P.array().square().square().sum());
      const Eigen::Matrix3d G = (-(20.0 / 3.0) * w) * P.array().cube().matrix(); // dF/dP
      m_face_gradient[f][0] = Rj * G.transpose();                               // dF/dR_i
      m_face_gradient[f][1] = Ri * G;                                           // dF/dR_j
    }
    grad.resize(Eigen::Index(number_of_unknowns()));
    const std::ptrdiff_t nt = std::ptrdiff_t(m_p.number_of_tets);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t t = 0; t < nt; ++t) {
      Eigen::Matrix3d dR = Eigen::Matrix3d::Zero();
      for(Frame_field_problem::Index f : m_p.tet_faces[t]) {
        if(f == Frame_field_problem::none) continue;
        dR += m_face_gradient[f][m_p.face_tets[f][0] == std::size_t(t) ? 0 : 1];
      }
      const std::size_t o = m_offset[t];
      const Eigen::Matrix3d& R = m_frames[t];
      if(m_p.is_constrained(Frame_field_problem::Index(t))) {
        grad[Eigen::Index(o)] = (dR.cwiseProduct(cross_matrix(m_p.direction(Frame_field_problem::Index(t))) * R)).sum();
      } else {
        const Eigen::Matrix3d Rz = Eigen::AngleAxisd(x[Eigen::Index(o + 2)], Eigen::Vector3d::UnitZ()).toRotationMatrix();
        const Eigen::Matrix3d Ry = Eigen::AngleAxisd(x[Eigen::Index(o + 1)], Eigen::Vector3d::UnitY()).toRotationMatrix();
        const Eigen::Matrix3d Rx = Eigen::AngleAxisd(x[Eigen::Index(o)], Eigen::Vector3d::UnitX()).toRotationMatrix();
        const Eigen::Matrix3d dgamma = cross_matrix(Eigen::Vector3d::UnitZ()) * R;
        const Eigen::Matrix3d dbeta = Rz * cross_matrix(Eigen::Vector3d::UnitY()) * Ry * Rx * m_base[t];
        const Eigen::Matrix3d dalpha = Rz * Ry * cross_matrix(Eigen::Vector3d::UnitX()) * Rx * m_base[t];
        grad[Eigen::Index(o)] = dR.cwiseProduct(dalpha).sum();
        grad[Eigen::Index(o + 1)] = dR.cwiseProduct(dbeta).sum();
        grad[Eigen::Index(o + 2)] = dR.cwiseProduct(dgamma).sum();
      }
    }
    double sum = 0;
    for(double v : e) sum += v;
    if(sum < m_best_energy) { m_best_energy = sum; m_best_x = x; }
    return sum;
  }

  // Runs L-BFGS in rounds of at most `round_iterations`; after each round the rotations are absorbed
  // into the base frames (no gimbal lock, and each round starts at angle 0). Stops when a round
  // decreases the energy by less than `tolerance` relatively, or after `max_iterations` in total.
  // `on_round(energy, iterations)` is called with the energy after each round: it never increases,
  // because every accepted L-BFGS step satisfies the Armijo condition.
  double minimize(int max_iterations, double tolerance, const std::function<void(double, int)>& on_round,
                  int& iterations)
  {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(Eigen::Index(number_of_unknowns())), g;
    double energy = (*this)(x, g);
    iterations = 0;
    const int round_iterations = 200;
    while(iterations < max_iterations && energy > 0) {
      LBFGSpp::LBFGSParam<double> param;
      param.m = 7;
      param.epsilon = 1e-10;
      param.epsilon_rel = 1e-9;
      param.past = 1;
      param.delta = tolerance;
      param.max_iterations = std::min(round_iterations, max_iterations - iterations);
      // plain Armijo backtracking lets L-BFGS build non-descent directions on this non-convex
      // energy; the strong Wolfe conditions keep the curvature pairs positive
      param.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_STRONG_WOLFE;
      LBFGSpp::LBFGSSolver<double, LBFGSpp::LineSearchNocedalWright> solver(param);
      x.setZero();
      m_best_x = x;
      m_best_energy = energy;
      double fx = energy;
      int it = 0;
      try {
        it = solver.minimize(*this, x, fx);
      } catch(const std::exception&) {
        // the line search found no decrease (at the limit of the floating-point precision): x may
        // be a rejected trial point, so keep the best point evaluated in this round instead
        x = m_best_x;
        fx = m_best_energy;
        it = 0;
      }
      update_frames(x);
      m_base = m_frames;
      iterations += it;
      const double previous = energy;
      energy = fx;
      if(on_round) on_round(energy, iterations);
      if(it < param.max_iterations || previous - energy <= tolerance * previous) break;
    }
    return energy;
  }

  std::size_t evaluations() const { return m_evaluations; }

private:
  const Frame_field_problem& m_p;
  std::vector<Eigen::Matrix3d>& m_frames;
  std::vector<Eigen::Matrix3d> m_base;
  std::vector<std::size_t> m_offset;
  std::vector<std::array<Eigen::Matrix3d, 2> > m_face_gradient;
  std::size_t m_evaluations = 0;
  Eigen::VectorXd m_best_x;
  double m_best_energy = 0;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_SMOOTHING_H
