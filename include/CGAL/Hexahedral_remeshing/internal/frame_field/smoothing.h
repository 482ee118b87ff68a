// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_SMOOTHING_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_SMOOTHING_H

#include <CGAL/Hexahedral_remeshing/internal/frame_field/aggregation_multigrid.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/conjugate_gradients.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/preconditioned_lbfgs.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/problem.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <LBFGS.h>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

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
// the alignment direction for a constrained tet, none for a fixed tet, so the constraints hold
// exactly throughout.
// Plain L-BFGS needs more iterations the longer the mesh is (the energy is Dirichlet-like); on
// meshes where the frame-field solves use the multigrid (see Frame_field_preconditioner), its
// initial inverse Hessian is that multigrid's V-cycle (linear and symmetric, as L-BFGS needs) on the
// rotation Laplacian instead (preconditioned_lbfgs()):
// between two equal frames, small rotations omega_s, omega_t give the face the energy
// (20/3) w_f |omega_s - omega_t|^2, the same about every axis by the cube's symmetry, so near a
// smooth field the Hessian in these angles is about (40/3) times that Laplacian; the scale is left
// to the L-BFGS pairs.
class Frame_field_smoother
{
public:
  Frame_field_smoother(const Frame_field_problem& p, std::vector<Eigen::Matrix3d>& frames)
    : m_p(p), m_frames(frames), m_base(frames)
  {
    m_offset.resize(p.number_of_tets + 1);
    m_offset[0] = 0;
    for(std::size_t t = 0; t < p.number_of_tets; ++t)
      m_offset[t + 1] = m_offset[t] + (p.is_fixed(Frame_field_problem::Index(t)) ? 0 :
                                       p.is_constrained(Frame_field_problem::Index(t)) ? 1 : 3);
    m_face_energy.resize(p.face_tets.size());
    m_face_torque.resize(p.face_tets.size());
  }

  std::size_t number_of_unknowns() const { return m_offset.back(); }

  // Multigrid of apply_rotation_laplacian() (unknowns as the smoother's).
  Aggregation_multigrid make_preconditioner() const
  {
    const std::size_t nt = m_p.number_of_tets;
    Multigrid_fine_system fine;
    fine.number_of_tets = nt;
    fine.face_tets = &m_p.face_tets;
    fine.face_weight = &m_p.face_weight;
    fine.tet_faces = &m_p.tet_faces;
    fine.offset = m_offset;
    fine.embedding.assign(nt, 0);
    for(std::size_t t = 0; t < nt; ++t) {
      const Frame_field_problem::Index ti = Frame_field_problem::Index(t);
      if(m_p.is_fixed(ti)) continue;
      if(m_p.is_constrained(ti)) {
        fine.embedding[t] = fine.embeddings.size();
        const Eigen::Vector3d& d = m_p.direction(ti);
        fine.embeddings.insert(fine.embeddings.end(), {d.x(), d.y(), d.z(), 0., 0., 0., 0., 0., 0.});
      } else {
        fine.embedding[t] = Multigrid_fine_system::leading_identity;
      }
    }
    fine.mu = 1e-8;
    fine.apply = [this](const Eigen::VectorXd& x, Eigen::VectorXd& y) { apply_rotation_laplacian(x, y); };
    return Aggregation_multigrid(std::move(fine), Multigrid_cycle::V);
  }

  // y = L x for the rotation Laplacian sum_f w_f |omega_s - omega_t|^2 + mu sum_t |omega_t|^2 (mu =
  // 1e-8: definite without any constraint) in the smoother's unknowns: omega_t = x_t for a free
  // tet, x_t d_t for a constrained one, 0 for a fixed one. Two passes: the world rotation vectors
  // first, so that the pass over the faces reads 3 doubles per neighbour and nothing else.
  void apply_rotation_laplacian(const Eigen::VectorXd& x, Eigen::VectorXd& y) const
  {
    typedef Frame_field_problem::Index Index;
    const std::ptrdiff_t nt = std::ptrdiff_t(m_p.number_of_tets);
    m_omega.resize(std::size_t(nt));
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t ti = 0; ti < nt; ++ti) {
      const Index t = Index(ti);
      const Eigen::Index o = Eigen::Index(m_offset[t]);
      m_omega[t] = m_p.is_fixed(t) ? Eigen::Vector3d::Zero() :
                   m_p.is_constrained(t) ? Eigen::Vector3d(x[o] * m_p.direction(t)) : Eigen::Vector3d(x.segment<3>(o));
    }
    y.resize(x.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t ti = 0; ti < nt; ++ti) {
      const Index t = Index(ti);
      if(m_offset[t + 1] == m_offset[t]) continue;
      const Eigen::Vector3d& w_t = m_omega[t];
      Eigen::Vector3d r = 1e-8 * w_t;
      for(Index f : m_p.tet_faces[t]) {
        if(f == Frame_field_problem::none) continue;
        const auto& ft = m_p.face_tets[f];
        r += m_p.face_weight[f] * (w_t - m_omega[ft[0] == t ? ft[1] : ft[0]]);
      }
      const Eigen::Index o = Eigen::Index(m_offset[t]);
      if(m_p.is_constrained(t)) y[o] = r.dot(m_p.direction(t));
      else y.segment<3>(o) = r;
    }
  }

  // Frames for parameters x (relative to the base frames).
  void update_frames(const Eigen::VectorXd& x)
  {
    const std::ptrdiff_t nt = std::ptrdiff_t(m_p.number_of_tets);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t t = 0; t < nt; ++t) {
      const std::size_t o = m_offset[t];
      if(m_p.is_fixed(Frame_field_problem::Index(t))) {
        m_frames[t] = m_base[t];
      } else if(m_p.is_constrained(Frame_field_problem::Index(t))) {
        m_frames[t] = Eigen::AngleAxisd(x[Eigen::Index(o)], m_p.direction(Frame_field_problem::Index(t))).toRotationMatrix() * m_base[t];
      } else {
        // Rz(gamma) Ry(beta) Rx(alpha), written out
        const double ca = std::cos(x[Eigen::Index(o)]), sa = std::sin(x[Eigen::Index(o)]);
        const double cb = std::cos(x[Eigen::Index(o + 1)]), sb = std::sin(x[Eigen::Index(o + 1)]);
        const double cg = std::cos(x[Eigen::Index(o + 2)]), sg = std::sin(x[Eigen::Index(o + 2)]);
        Eigen::Matrix3d R;
        R << cg * cb, cg * sb * sa - sg * ca, cg * sb * ca + sg * sa,
             sg * cb, sg * sb * sa + cg * ca, sg * sb * ca - cg * sa,
             -sb, cb * sa, cb * ca;
        m_frames[t] = R * m_base[t];
      }
    }
  }

  // LBFGS++ objective: energy and gradient with respect to the parameters.
  // Every parameter rotates its frame about a world axis w (left multiplication), and
  // <dF/dR, [w]x R>_F = w . tau with tau the axial vector of S - S^T, S = (dF/dR) R^T. Per face,
  // with P = R_i^T R_j and G = dF/dP, S_j gets K = R_i G R_j^T and S_i gets K^T, so a face only
  // contributes +/- axial(K - K^T) to its two tets.
  double operator()(const Eigen::VectorXd& x, Eigen::VectorXd& grad)
  {
    update_frames(x);
    ++m_evaluations;
    const std::ptrdiff_t nf = std::ptrdiff_t(m_p.face_tets.size());
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t f = 0; f < nf; ++f) {
      const Eigen::Matrix3d& Ri = m_frames[m_p.face_tets[f][0]];
      const Eigen::Matrix3d& Rj = m_frames[m_p.face_tets[f][1]];
      const Eigen::Matrix3d P = Ri.transpose() * Rj;
      const double w = m_p.face_weight[f];
      const Eigen::Array33d P2 = P.array().square();
      m_face_energy[f] = w * (5.0 / 3.0) * (3.0 - P2.square().sum());
      const Eigen::Matrix3d G = (-(20.0 / 3.0) * w) * (P2 * P.array()).matrix(); // dF/dP
      const Eigen::Matrix3d K = Ri * G * Rj.transpose();
      m_face_torque[f] = Eigen::Vector3d(K(2, 1) - K(1, 2), K(0, 2) - K(2, 0), K(1, 0) - K(0, 1));
    }
    grad.resize(Eigen::Index(number_of_unknowns()));
    const std::ptrdiff_t nt = std::ptrdiff_t(m_p.number_of_tets);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t t = 0; t < nt; ++t) {
      Eigen::Vector3d tau = Eigen::Vector3d::Zero();
      for(Frame_field_problem::Index f : m_p.tet_faces[t]) {
        if(f == Frame_field_problem::none) continue;
        if(m_p.face_tets[f][0] == std::size_t(t)) tau -= m_face_torque[f];
        else tau += m_face_torque[f];
      }
      const std::size_t o = m_offset[t];
      if(m_p.is_fixed(Frame_field_problem::Index(t))) continue;
      if(m_p.is_constrained(Frame_field_problem::Index(t))) {
        grad[Eigen::Index(o)] = tau.dot(m_p.direction(Frame_field_problem::Index(t)));
      } else {
        // axes of the three parameter rotations: Rz Ry e_x, Rz e_y, e_z
        const double cb = std::cos(x[Eigen::Index(o + 1)]), sb = std::sin(x[Eigen::Index(o + 1)]);
        const double cg = std::cos(x[Eigen::Index(o + 2)]), sg = std::sin(x[Eigen::Index(o + 2)]);
        grad[Eigen::Index(o)] = tau.dot(Eigen::Vector3d(cg * cb, sg * cb, -sb));
        grad[Eigen::Index(o + 1)] = tau.dot(Eigen::Vector3d(-sg, cg, 0.));
        grad[Eigen::Index(o + 2)] = tau.z();
      }
    }
    double sum = 0;
    for(double v : m_face_energy) sum += v;
    if(sum < m_best_energy) { m_best_energy = sum; m_best_x = x; }
    return sum;
  }

  // Runs L-BFGS in rounds of at most `round_iterations`; after each round the rotations are absorbed
  // into the base frames (no gimbal lock, and each round starts at angle 0). Stops when a round
  // decreases the energy by less than `tolerance` relatively, or after `max_iterations` in total.
  // `on_round(energy, iterations)` is called with the energy after each round: it never increases,
  // because every accepted L-BFGS step satisfies the Armijo condition. `preconditioner`: plain
  // L-BFGS (JACOBI) or the multigrid-preconditioned one (MULTIGRID); AUTOMATIC as the other solves.
  double minimize(int max_iterations, double tolerance, const std::function<void(double, int)>& on_round,
                  int& iterations,
                  Frame_field_preconditioner preconditioner = Frame_field_preconditioner::AUTOMATIC)
  {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(Eigen::Index(number_of_unknowns())), g;
    double energy = (*this)(x, g);
    std::unique_ptr<Aggregation_multigrid> multigrid;
    if(use_multigrid(preconditioner, m_p.number_of_tets) && number_of_unknowns() > 0)
      multigrid.reset(new Aggregation_multigrid(make_preconditioner()));
    iterations = 0;
    const int round_iterations = 200;
    while(iterations < max_iterations && energy > 0) {
      LBFGSpp::LBFGSParam<double> param;
      param.m = 7;
      param.epsilon = 1e-10;
      param.epsilon_rel = 1e-9;
      // the preconditioned steps decrease the energy less evenly: over one iteration, the test
      // stopped B0 at 376.342 where plain L-BFGS reaches 376.330 (over three: 376.329)
      param.past = multigrid ? 3 : 1;
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
        if(multigrid)
          it = preconditioned_lbfgs(*this, *multigrid, x, fx, param);
        else it = solver.minimize(*this, x, fx);
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
  std::vector<double> m_face_energy;
  std::vector<Eigen::Vector3d> m_face_torque;
  mutable std::vector<Eigen::Vector3d> m_omega; // work of apply_rotation_laplacian()
  std::size_t m_evaluations = 0;
  Eigen::VectorXd m_best_x;
  double m_best_energy = 0;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_SMOOTHING_H
