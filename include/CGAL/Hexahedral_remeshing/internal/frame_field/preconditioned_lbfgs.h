// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PRECONDITIONED_LBFGS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PRECONDITIONED_LBFGS_H

#include <CGAL/Hexahedral_remeshing/internal/frame_field/parallel_vector_operations.h>

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
  struct Pair { Eigen::VectorXd s, y, Py; double rho = 0, yPy = 0; };
  std::vector<Pair> pairs(static_cast<std::size_t>(m));
  std::vector<std::size_t> order;            // slots of the stored pairs, oldest first
  Eigen::MatrixXd sy(m, m);                  // sy(i, j) = s_i^T y_j by slot
  std::vector<double> alpha(static_cast<std::size_t>(m)), c(static_cast<std::size_t>(m)), history, dots, dots_s;
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
    const double gnorm = std::sqrt(parallel_dot(grad, grad));
    if(gnorm <= param.epsilon || gnorm <= param.epsilon_rel * std::sqrt(parallel_dot(x, x))) return k;
    if(param.past > 0 && k >= param.past) {
      const double f_past = history[std::size_t(k - param.past)];
      if(std::abs(f_past - fx) <= param.delta * (std::max)((std::max)(std::abs(fx), std::abs(f_past)), 1.0)) return k;
    }
    history.push_back(fx);
    if(param.max_iterations != 0 && k >= param.max_iterations) return k;
    precondition(grad, Pg);
    // The new pair, the dot products of its y and s with the stored pairs, and s_i^T g for the first
    // loop of the recursion. Large vectors: one pass over the blocks, whose per-block sums, added in
    // block order, are those of the separate passes below (bitwise the same, a fifth less memory traffic).
    const std::size_t stored = order.size();
    std::vector<double> s_g; // s_i^T g: the stored pairs oldest first, then the new one
    if(use_parallel_vector_operations(n)) {
      std::vector<double> all;
      parallel_block_sums(n, 3 * stored + 4, [&](Eigen::Index b, Eigen::Index size, double* out) {
        auto ps = p.s.segment(b, size), py = p.y.segment(b, size), pPy = p.Py.segment(b, size);
        const auto g = grad.segment(b, size);
        ps = x.segment(b, size) - ps;
        py = g - py;
        pPy = Pg.segment(b, size) - pPy;
        out[0] = py.dot(ps);
        out[1] = py.dot(py);
        out[2] = py.dot(pPy);
        for(std::size_t a = 0; a < stored; ++a) {
          const Pair& q = pairs[order[a]];
          out[3 + a] = py.dot(q.s.segment(b, size));
          out[3 + stored + a] = ps.dot(q.y.segment(b, size));
          out[3 + 2 * stored + a] = g.dot(q.s.segment(b, size));
        }
        out[3 + 3 * stored] = g.dot(ps);
      }, all);
      dots.assign(all.begin(), all.begin() + std::ptrdiff_t(3 + stored));
      dots_s.assign(all.begin() + std::ptrdiff_t(3 + stored), all.begin() + std::ptrdiff_t(3 + 2 * stored));
      s_g.assign(all.begin() + std::ptrdiff_t(3 + 2 * stored), all.end());
    } else {
      p.s = x - p.s;
      p.y = grad - p.y;
      p.Py = Pg - p.Py;
      std::vector<const Eigen::VectorXd*> with_y = {&p.s, &p.y, &p.Py}, with_s;
      for(std::size_t i : order) { with_y.push_back(&pairs[i].s); with_s.push_back(&pairs[i].y); }
      parallel_dots(p.y, with_y, dots);
      parallel_dots(p.s, with_s, dots_s);
    }
    const double s_y = dots[0], y_y = dots[1], y_Py = dots[2];
    // the strong Wolfe conditions give s^T y > 0; a pair at the limit of the precision is dropped
    const bool accepted = s_y > 1e-16 * y_y;
    if(accepted) {
      p.rho = 1.0 / s_y;
      p.yPy = y_Py;
      for(std::size_t a = 0; a < stored; ++a) {
        sy(Eigen::Index(order[a]), Eigen::Index(slot)) = dots[3 + a];
        sy(Eigen::Index(slot), Eigen::Index(order[a])) = dots_s[a];
      }
      sy(Eigen::Index(slot), Eigen::Index(slot)) = s_y;
      order.push_back(slot);
    }
    // two-loop recursion (Alg. 7.4) with H0 = gamma P. First loop: alpha_i from s_i^T g and the
    // stored s_i^T y_j; direction = gamma (P g - sum_i alpha_i P y_i).
    std::vector<const Eigen::VectorXd*> vs, vy, vPy;
    for(std::size_t i : order) { vs.push_back(&pairs[i].s); vy.push_back(&pairs[i].y); vPy.push_back(&pairs[i].Py); }
    if(s_g.empty()) parallel_dots(grad, vs, dots);
    else {
      if(!accepted) s_g.pop_back();
      dots.swap(s_g);
    }
    for(std::size_t a = order.size(); a-- > 0;) {
      const std::size_t i = order[a];
      double s_q = dots[a];
      for(std::size_t b = a + 1; b < order.size(); ++b) s_q -= alpha[order[b]] * sy(Eigen::Index(i), Eigen::Index(order[b]));
      alpha[i] = pairs[i].rho * s_q;
    }
    double gamma = 1;
    if(!order.empty()) {
      const Pair& newest = pairs[order.back()];
      if(newest.yPy > 0) gamma = 1.0 / (newest.rho * newest.yPy);
    }
    for_each_segment(n, [&](Eigen::Index b, Eigen::Index size) {
      auto d = direction.segment(b, size);
      d = Pg.segment(b, size);
      for(std::size_t a = 0; a < order.size(); ++a) d -= alpha[order[a]] * vPy[a]->segment(b, size);
      d *= gamma;
    });
    // Second loop: beta_i = rho_i y_i^T (r0 + sum_{j < i} c_j s_j), c_j = alpha_j - beta_j, from
    // y_i^T r0 and the stored s_j^T y_i; then direction = -(r0 + sum_i c_i s_i) in one pass.
    parallel_dots(direction, vy, dots);
    for(std::size_t a = 0; a < order.size(); ++a) {
      const std::size_t i = order[a];
      double y_r = dots[a];
      for(std::size_t b = 0; b < a; ++b) y_r += c[b] * sy(Eigen::Index(order[b]), Eigen::Index(i));
      c[a] = alpha[i] - pairs[i].rho * y_r;
    }
    for_each_segment(n, [&](Eigen::Index b, Eigen::Index size) {
      auto d = direction.segment(b, size);
      for(std::size_t a = 0; a < order.size(); ++a) d += c[a] * vs[a]->segment(b, size);
      d = -d;
    });
    step = 1.0;
  }
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PRECONDITIONED_LBFGS_H
