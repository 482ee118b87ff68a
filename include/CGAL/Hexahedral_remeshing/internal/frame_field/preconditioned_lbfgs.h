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
  // Memory, the limit at a million tetrahedra: 3 m + 4 vectors. The newest pair is built in the slot
  // of the one it evicts (s starts as the previous x, y as the previous gradient, Py as the previous
  // P g), and the first loop of the recursion needs s_i^T q only, q = g - sum_{j > i} alpha_j y_j,
  // which the dot products s_i^T y_j of the stored pairs give without forming q.
  const Eigen::Index n = x.size();
  const int m = (std::max)(1, param.m);
  struct Pair { Eigen::VectorXd s, y, Py; double rho = 0; };
  std::vector<Pair> pairs(static_cast<std::size_t>(m));
  std::vector<std::size_t> order;            // slots of the stored pairs, oldest first
  Eigen::MatrixXd sy(m, m);                  // sy(i, j) = s_i^T y_j by slot
  std::vector<double> alpha(static_cast<std::size_t>(m)), history;
  Eigen::VectorXd grad(n), Pg(n), direction(n);
  fx = f(x, grad);
  history.push_back(fx);
  if(grad.norm() <= param.epsilon || grad.norm() <= param.epsilon_rel * x.norm()) return 1;
  precondition(grad, Pg);
  direction = -Pg;
  double step = 1.0 / direction.norm();
  for(int k = 1;; ++k) {
    std::size_t slot = 0;
    if(int(order.size()) == m) {
      slot = order.front();
      order.erase(order.begin());
    } else {
      std::vector<bool> used(std::size_t(m), false);
      for(std::size_t i : order) used[i] = true;
      while(used[slot]) ++slot;
    }
    Pair& p = pairs[slot];
    p.s = x;
    p.y = grad;
    p.Py = Pg;
    LBFGSpp::LineSearchNocedalWright<double>::LineSearch(f, fx, x, grad, step, direction, p.s, param);
    const double gnorm = grad.norm();
    if(gnorm <= param.epsilon || gnorm <= param.epsilon_rel * x.norm()) return k;
    if(param.past > 0 && k >= param.past) {
      const double f_past = history[std::size_t(k - param.past)];
      if(std::abs(f_past - fx) <= param.delta * (std::max)((std::max)(std::abs(fx), std::abs(f_past)), 1.0)) return k;
    }
    history.push_back(fx);
    if(param.max_iterations != 0 && k >= param.max_iterations) return k;
    precondition(grad, Pg);
    p.s = x - p.s;
    p.y = grad - p.y;
    p.Py = Pg - p.Py;
    const double s_y = p.s.dot(p.y);
    // the strong Wolfe conditions give s^T y > 0; a pair at the limit of the precision is dropped
    if(s_y > 1e-16 * p.y.squaredNorm()) {
      p.rho = 1.0 / s_y;
      for(std::size_t i : order) {
        sy(Eigen::Index(i), Eigen::Index(slot)) = pairs[i].s.dot(p.y);
        sy(Eigen::Index(slot), Eigen::Index(i)) = p.s.dot(pairs[i].y);
      }
      sy(Eigen::Index(slot), Eigen::Index(slot)) = s_y;
      order.push_back(slot);
    }
    // two-loop recursion (Alg. 7.4) with H0 = gamma P; direction holds P q, then H g
    direction = Pg;
    for(std::size_t a = order.size(); a-- > 0;) {
      const std::size_t i = order[a];
      double s_q = pairs[i].s.dot(grad);
      for(std::size_t b = a + 1; b < order.size(); ++b) s_q -= alpha[order[b]] * sy(Eigen::Index(i), Eigen::Index(order[b]));
      alpha[i] = pairs[i].rho * s_q;
      direction -= alpha[i] * pairs[i].Py;
    }
    if(!order.empty()) {
      const Pair& newest = pairs[order.back()];
      const double yPy = newest.y.dot(newest.Py);
      if(yPy > 0) direction *= 1.0 / (newest.rho * yPy);
    }
    for(std::size_t i : order) {
      const double beta = pairs[i].rho * pairs[i].y.dot(direction);
      direction += (alpha[i] - beta) * pairs[i].s;
    }
    direction = -direction;
    step = 1.0;
  }
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PRECONDITIONED_LBFGS_H
