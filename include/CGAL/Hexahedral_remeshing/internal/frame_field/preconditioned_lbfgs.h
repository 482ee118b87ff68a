// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PRECONDITIONED_LBFGS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PRECONDITIONED_LBFGS_H

#include <Eigen/Dense>
#include <LBFGS.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <deque>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// L-BFGS whose initial inverse Hessian is gamma P instead of gamma I (Nocedal and Wright, Numerical
// Optimization, 2nd ed., Alg. 7.4 with H0 = gamma P, gamma = s^T y / y^T P y of the newest pair).
// Plain L-BFGS on a Dirichlet-like energy needs more iterations the longer the mesh's dual graph
// is; with P an (approximate) inverse of the energy's Hessian they hardly grow.
// P is applied once per iteration although the recursion needs P q for a q built from the gradient
// and the pairs: P is linear, so P q = P g - sum_i alpha_i P y_i with P y_i = P g_{i+1} - P g_i kept
// beside each pair (one vector more per pair).
// Same line search (LBFGS++'s strong Wolfe, Nocedal-Wright), parameters and stopping tests as
// LBFGSpp::LBFGSSolver::minimize(); throws what that line search throws. f(x, grad) returns the value
// and fills the gradient; precondition(v, Pv) applies a symmetric positive definite P.
// Returns the number of iterations.
template <class Function, class Precondition>
int preconditioned_lbfgs(Function& f, const Precondition& precondition, Eigen::VectorXd& x, double& fx,
                         const LBFGSpp::LBFGSParam<double>& param)
{
  const Eigen::Index n = x.size();
  Eigen::VectorXd grad(n), grad_previous(n), x_previous(n), direction(n), Pg(n), Pg_previous(n), z(n), q(n);
  struct Pair { Eigen::VectorXd s, y, Py; double rho; };
  std::deque<Pair> pairs;
  std::vector<double> alpha, history;
  fx = f(x, grad);
  history.push_back(fx);
  if(grad.norm() <= param.epsilon || grad.norm() <= param.epsilon_rel * x.norm()) return 1;
  precondition(grad, Pg);
  direction = -Pg;
  double step = 1.0 / direction.norm();
  for(int k = 1;; ++k) {
    x_previous = x;
    grad_previous = grad;
    std::swap(Pg, Pg_previous);
    LBFGSpp::LineSearchNocedalWright<double>::LineSearch(f, fx, x, grad, step, direction, x_previous, param);
    const double gnorm = grad.norm();
    if(gnorm <= param.epsilon || gnorm <= param.epsilon_rel * x.norm()) return k;
    if(param.past > 0 && k >= param.past) {
      const double f_past = history[std::size_t(k - param.past)];
      if(std::abs(f_past - fx) <= param.delta * (std::max)((std::max)(std::abs(fx), std::abs(f_past)), 1.0)) return k;
    }
    history.push_back(fx);
    if(param.max_iterations != 0 && k >= param.max_iterations) return k;
    precondition(grad, Pg);
    Pair p{x - x_previous, grad - grad_previous, Pg - Pg_previous, 0.0};
    const double sy = p.s.dot(p.y);
    // the strong Wolfe conditions give s^T y > 0; a pair at the limit of the precision is dropped
    if(sy > 1e-16 * p.y.squaredNorm()) {
      p.rho = 1.0 / sy;
      pairs.push_back(std::move(p));
      if(int(pairs.size()) > param.m) pairs.pop_front();
    }
    q = grad;
    z = Pg;
    alpha.assign(pairs.size(), 0.0);
    for(std::size_t i = pairs.size(); i-- > 0;) {
      alpha[i] = pairs[i].rho * pairs[i].s.dot(q);
      q -= alpha[i] * pairs[i].y;
      z -= alpha[i] * pairs[i].Py;
    }
    if(!pairs.empty()) {
      const double yPy = pairs.back().y.dot(pairs.back().Py);
      if(yPy > 0) z *= 1.0 / (pairs.back().rho * yPy);
    }
    for(std::size_t i = 0; i < pairs.size(); ++i) {
      const double beta = pairs[i].rho * pairs[i].y.dot(z);
      z += (alpha[i] - beta) * pairs[i].s;
    }
    direction = -z;
    step = 1.0;
  }
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PRECONDITIONED_LBFGS_H
