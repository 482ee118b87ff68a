// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNTANGLING_FOLDOVER_FREE_MAP_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNTANGLING_FOLDOVER_FREE_MAP_H

// Generic foldover-free minimizer (Garanzha, Kaporin, Kudryavtseva, Protais, Ray, Sokolov 2021,
// "Foldover-free maps in 50 lines of code", ACM TOG 40(4)) on simplicial (tetrahedral) elements
// whose corner values are affine in the unknowns: x = P y + x0.
//
// Users:
// - the integer-grid map (design 4, "Validity and repair" (2)): y = free continuous DOFs, integer DOFs
//   folded into x0, P = the elimination of the seam/alignment constraints, M_e = G_t^T E_t / s;
// - the hex-mesh smoothing: y = free vertex coordinates, the 8 corner tets of each hex as elements.
//
// Shape of the problem (E elements, n unknowns):
//   P  : (12 E) x n sparse, row-major; x0 : 12 E, with x[12 e + 3 c + r] = coordinate r of corner c of e;
//   D_e = [x1 - x0, x2 - x0, x3 - x0] (3x3, edge vectors as columns), K_e = D_e M_e;
//   M_e : 3x3 with det M_e != 0 such that K_e = I for the ideal element (for a map u of a tet with
//         reference edge matrix R_e = [p1-p0, p2-p0, p3-p0]: M_e = R_e^{-1} T_e with T_e the target
//         normalization, e.g. the frame E_t / s of the integer-grid map);
//   w_e >= 0 : weight (e.g. reference volume).
// Minimized energy: sum_e w_e f(K_e) (+ an optional quadratic anchor on y), f = (1-theta) tr(K^T K)/chi(det K, eps)^{2/3}
//                                          + theta (det^2 K + 1)/chi(det K, eps),
// chi(D, eps) = (D + sqrt(eps^2 + D^2))/2, theta = 1/2 by default.
// An element is valid when det K_e > 0, i.e. when its corners have the orientation of sign(det M_e);
// the inverted counts of the result are decided with CGAL's exact orientation predicate.

#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/untangling/foldover_free_energy.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <LBFGS.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// See the file comment for the meaning of every field.
struct Foldover_free_problem
{
  Eigen::SparseMatrix<double, Eigen::RowMajor> P; // (12 E) x n
  Eigen::VectorXd x0;                              // 12 E
  std::vector<Eigen::Matrix3d> M;                  // E
  std::vector<double> w;                           // E
  // Optional quadratic anchor (a trust region for linearized constraints, e.g. vertices sliding in a
  // tangent plane): adds sum_i anchor_weight[i] (y_i - anchor[i])^2 to the energy. Empty, or both of size n.
  Eigen::VectorXd anchor_weight, anchor;

  std::size_t number_of_elements() const { return M.size(); }
};

struct Foldover_free_options
{
  // weight of the volume term against the shape term
  double theta = 0.5;
  // outer iterations (epsilon updates) and L-BFGS iterations per outer iteration
  int max_outer_iterations = 200;
  int max_inner_iterations = 1000;
  // inner stop: |grad| <= max(inner_gradient_tolerance * |grad at the start of this outer iteration|,
  // inner_absolute_gradient_tolerance * sqrt(n) / E) (gradient of the energy divided by sum_e w_e,
  // with respect to y / (ideal element size)), or relative decrease of the energy over 3 iterations
  // below inner_energy_tolerance
  double inner_gradient_tolerance = 1e-5;
  double inner_absolute_gradient_tolerance = 1e-6;
  double inner_energy_tolerance = 1e-10;
  // outer stop: no inverted element and relative energy decrease of an outer iteration below this
  double energy_tolerance = 1e-5;
  // stop as soon as no element is inverted (repairs that should move the map as little as possible)
  bool stop_when_untangled = false;
  // epsilon of the first outer iteration; <= 0: 1 if some element is inverted (det K <= 0), else
  // minimum_epsilon (a valid start is then optimized with the true barrier, which never inverts it)
  double initial_epsilon = -1;
  double minimum_epsilon = 1e-10;
  // called after every outer iteration with (outer iteration, energy, epsilon, min det K, #det K <= 0)
  std::function<void(int, double, double, double, std::size_t)> on_iteration;
};

struct Foldover_free_result
{
  bool success = false;            // no inverted element at the end (exact orientation)
  int outer_iterations = 0;
  int inner_iterations = 0;        // L-BFGS iterations summed over the outer iterations
  std::size_t evaluations = 0;     // energy + gradient evaluations (also counts failed line searches)
  double min_det_before = 0;       // min det K_e (floating point)
  double min_det_after = 0;
  std::size_t inverted_before = 0; // elements whose corners are not oriented as sign(det M_e) (exact)
  std::size_t inverted_after = 0;
  double energy = 0;               // sum_e w_e f(K_e) at the end, with the final epsilon
  double epsilon = 0;              // the final epsilon
  double seconds = 0;
};

// Energy, gradient and determinants on the unknowns y; the LBFGS++ objective.
class Foldover_free_evaluator
{
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator Row_iterator;

public:
  Foldover_free_evaluator(const Foldover_free_problem& p, double theta)
    : m_p(p), m_theta(theta), m_Pt(p.P.transpose()),
      m_energy(p.number_of_elements()), m_det(p.number_of_elements()),
      m_gx(Eigen::VectorXd::Zero(p.x0.size())), m_unit_column(std::size_t(p.P.rows()), 0)
  {
    double total = 0;
    for(double w : p.w) total += w;
    // the normalized energy is O(1) whatever the mesh size, so that tolerances are absolute
    m_scale = total > 0 ? 1. / total : 1.;
    for(Eigen::Index i = 0; i < p.P.rows(); ++i) {
      Row_iterator it(p.P, i);
      if(!it) continue;
      const double v = it.value();
      const std::int64_t column = std::int64_t(it.col()) + 1;
      if(++it || !(v == 1. || v == -1.) || column > std::numeric_limits<std::int32_t>::max()) continue;
      m_unit_column[std::size_t(i)] = std::int32_t(v > 0 ? column : -column);
    }
  }

  double epsilon = 1.;

  Eigen::Matrix3d K(const Eigen::VectorXd& x, std::size_t e) const { return K(x.data() + 12 * e, e); }

  // K_e from the 12 corner values c of element e.
  Eigen::Matrix3d K(const double* c, std::size_t e) const
  {
    Eigen::Matrix3d D;
    for(int k = 0; k < 3; ++k)
      for(int r = 0; r < 3; ++r) D(r, k) = c[3 * (k + 1) + r] - c[r];
    return D * m_p.M[e];
  }

  // Row i of x = P y + x0, with the arithmetic of Eigen's product (a sum from 0 over the row's entries,
  // then x0 added): the same bits as `P * y + x0`. Most rows of a map's P are one variable with
  // coefficient +-1 (a corner value is a variable of its chart or its opposite): those are read from
  // one signed index instead of the row's index, column and value (corners() was 13% of the flange's
  // map, memory-bound).
  double corner(Eigen::Index i, const Eigen::VectorXd& y) const
  {
    const std::int32_t u = m_unit_column[std::size_t(i)];
    double sum = 0;
    if(u != 0) // without a branch on the sign, which the rows' order does not predict
      sum += (u < 0 ? -1. : 1.) * y[(u < 0 ? -u : u) - 1];
    else
      for(Row_iterator it(m_p.P, i); it; ++it) sum += it.value() * y[it.col()];
    return (0. + sum) + m_p.x0[i];
  }

  // The 12 corner values of element e.
  void element_corners(const Eigen::VectorXd& y, std::size_t e, double* c) const
  {
    for(int i = 0; i < 12; ++i) c[i] = corner(Eigen::Index(12 * e + std::size_t(i)), y);
  }

  // x = P y + x0, into x's storage (large meshes: a fresh vector per evaluation costs page faults)
  void corners(const Eigen::VectorXd& y, Eigen::VectorXd& x) const
  {
    x.resize(m_p.x0.size());
    const std::ptrdiff_t E = std::ptrdiff_t(m_p.number_of_elements());
#pragma omp parallel for schedule(static) if(E >= parallel_elements)
    for(std::ptrdiff_t e = 0; e < E; ++e) element_corners(y, std::size_t(e), x.data() + 12 * e);
  }

  // Below this many elements (a local untangling around a few folds) the loops run on one thread:
  // waking the team for every evaluation cost more than the work.
  static constexpr std::ptrdiff_t parallel_elements = 4096;

  // min det K_e and the number of det K_e <= 0 (floating point), on corner values x
  std::pair<double, std::size_t> determinants(const Eigen::VectorXd& x)
  {
    const std::ptrdiff_t E = std::ptrdiff_t(m_p.number_of_elements());
#pragma omp parallel for schedule(static) if(E >= parallel_elements)
    for(std::ptrdiff_t e = 0; e < E; ++e) m_det[e] = K(x, std::size_t(e)).determinant();
    double detmin = (std::numeric_limits<double>::max)();
    std::size_t inverted = 0;
    for(double d : m_det) {
      detmin = (std::min)(detmin, d);
      if(d <= 0) ++inverted;
    }
    return std::make_pair(detmin, inverted);
  }

  // normalized energy (sum_e w_e f_e / sum_e w_e) and its gradient with respect to y
  double operator()(const Eigen::VectorXd& y, Eigen::VectorXd& grad)
  {
    const std::ptrdiff_t E = std::ptrdiff_t(m_p.number_of_elements());
#pragma omp parallel for schedule(static) if(E >= parallel_elements)
    for(std::ptrdiff_t e = 0; e < E; ++e) {
      double c[12];
      element_corners(y, std::size_t(e), c);
      m_energy[e] = foldover_free_fused_element(c, m_p.M[e], m_p.w[e] * m_scale, epsilon, m_theta, m_gx.data() + 12 * e);
    }
    // fixed-order reductions: the result does not depend on the number of threads
    double F = 0;
    for(double f : m_energy) F += f;
    grad.resize(y.size());
    grad.noalias() = m_Pt * m_gx;
    if(m_p.anchor_weight.size() == y.size() && m_p.anchor.size() == y.size()) {
      const Eigen::VectorXd d = y - m_p.anchor;
      F += m_scale * d.dot(m_p.anchor_weight.cwiseProduct(d));
      grad += (2. * m_scale) * m_p.anchor_weight.cwiseProduct(d);
    }
    ++m_evaluations;
    if(!(F >= m_best_energy) && std::isfinite(F)) {
      m_best_energy = F;
      m_best_y = y;
    }
    return F;
  }

  double value(const Eigen::VectorXd& y)
  {
    Eigen::VectorXd g;
    return (*this)(y, g);
  }

  void reset_best() { m_best_energy = std::numeric_limits<double>::infinity(); m_best_y.resize(0); }
  double best_energy() const { return m_best_energy; }
  const Eigen::VectorXd& best_y() const { return m_best_y; }
  double scale() const { return m_scale; }
  std::size_t evaluations() const { return m_evaluations; }

private:
  const Foldover_free_problem& m_p;
  double m_theta;
  double m_scale = 1;
  Eigen::SparseMatrix<double, Eigen::RowMajor> m_Pt; // row-major P^T: the product is a per-row sum
  std::vector<double> m_energy;
  std::vector<double> m_det;
  Eigen::VectorXd m_gx;
  // per row of P: +-(column + 1) if the row is that one column with coefficient +-1, else 0
  std::vector<std::int32_t> m_unit_column;
  double m_best_energy = std::numeric_limits<double>::infinity();
  Eigen::VectorXd m_best_y;
  std::size_t m_evaluations = 0;
};

// Number of elements whose corners (from x) are not strictly oriented as sign(det M_e), exactly.
inline std::size_t count_inverted_elements(const Foldover_free_problem& p, const Eigen::VectorXd& x)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;
  std::size_t inverted = 0;
  for(std::size_t e = 0; e < p.number_of_elements(); ++e) {
    const double* c = x.data() + 12 * e;
    const Point a(c[0], c[1], c[2]), b(c[3], c[4], c[5]), d(c[6], c[7], c[8]), f(c[9], c[10], c[11]);
    // CGAL::orientation(p, q, r, s) is the sign of det[q - p, r - p, s - p]
    const CGAL::Orientation o = CGAL::orientation(a, b, d, f);
    const CGAL::Orientation valid = p.M[e].determinant() > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
    if(o != valid) ++inverted;
  }
  return inverted;
}

// Mean edge length of the ideal elements, cbrt(1 / |det M_e|): the L-BFGS unknowns are y / length, so
// that the first step (of unit length) moves the vertices by about one element, whatever the units of y.
inline double characteristic_length(const Foldover_free_problem& p)
{
  double sum = 0;
  std::size_t count = 0;
  for(const Eigen::Matrix3d& M : p.M) {
    const double d = std::abs(M.determinant());
    if(d > 0 && std::isfinite(d)) { sum += std::cbrt(1. / d); ++count; }
  }
  return count > 0 && sum > 0 ? sum / double(count) : 1.;
}

// The evaluator on scaled unknowns z = y / length.
struct Scaled_objective
{
  Foldover_free_evaluator& ev;
  double length;
  Eigen::VectorXd y, g;
  double operator()(const Eigen::VectorXd& z, Eigen::VectorXd& gz)
  {
    y = length * z;
    const double f = ev(y, g);
    gz = length * g;
    return f;
  }
};

// Minimizes the foldover-free energy over y (in/out). Outer loop: the epsilon schedule of the
// paper, mu = (1 - sigma) chi(detmin, eps), sigma = max(1 - E/E_prev, 0.1),
// eps <- 2 sqrt(mu (mu - detmin)) if detmin < mu, else eps <- minimum_epsilon; inner loop: L-BFGS
// (LBFGS++); a failed line search keeps the best point evaluated. Deterministic (fixed-order sums).
// Throws Error if the sizes of the problem disagree.
inline Foldover_free_result minimize_foldover_free(const Foldover_free_problem& p, Eigen::VectorXd& y,
                                                   const Foldover_free_options& options = Foldover_free_options())
{
  const auto start = std::chrono::steady_clock::now();
  const std::size_t E = p.number_of_elements();
  if(p.w.size() != E || std::size_t(p.x0.size()) != 12 * E || std::size_t(p.P.rows()) != 12 * E ||
     p.P.cols() != y.size() || (p.anchor_weight.size() != 0 && p.anchor_weight.size() != y.size()) ||
     p.anchor.size() != p.anchor_weight.size())
    throw Error("minimize_foldover_free: inconsistent sizes (P " + std::to_string(p.P.rows()) + "x" +
                std::to_string(p.P.cols()) + ", x0 " + std::to_string(p.x0.size()) + ", M " +
                std::to_string(E) + ", w " + std::to_string(p.w.size()) + ", y " + std::to_string(y.size()) + ")");
  Foldover_free_result result;
  Foldover_free_evaluator ev(p, options.theta);
  Eigen::VectorXd x;
  ev.corners(y, x);
  std::pair<double, std::size_t> dets = ev.determinants(x);
  result.min_det_before = E > 0 ? dets.first : 0;
  result.inverted_before = count_inverted_elements(p, x);
  const double length = characteristic_length(p);
  ev.epsilon = options.initial_epsilon > 0 ? options.initial_epsilon
               : (dets.second > 0 ? 1. : options.minimum_epsilon);

  if(E > 0 && y.size() > 0) {
    for(int outer = 0; outer < options.max_outer_iterations; ++outer) {
      Eigen::VectorXd g;
      ev.reset_best();
      const double E_prev = ev(y, g);
      LBFGSpp::LBFGSParam<double> param;
      param.m = 7;
      param.epsilon = (std::max)(options.inner_gradient_tolerance * length * g.norm(),
                                 options.inner_absolute_gradient_tolerance * std::sqrt(double(y.size())) / double(E));
      param.epsilon_rel = 0;
      param.past = 3;
      param.delta = options.inner_energy_tolerance;
      param.max_iterations = options.max_inner_iterations;
      param.max_linesearch = 60;
      // Wolfe backtracking: a rejected trial point (a NaN, an overflowed barrier) halves the step, the
      // curvature condition keeps the L-BFGS pairs positive on this non-convex energy, and a failure
      // throws instead of returning a worse point
      param.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_WOLFE;
      LBFGSpp::LBFGSSolver<double, LBFGSpp::LineSearchBacktracking> solver(param);
      Scaled_objective objective{ ev, length, Eigen::VectorXd(), Eigen::VectorXd() };
      Eigen::VectorXd z = y / length;
      double fz = E_prev;
      int it = 0;
      try {
        it = solver.minimize(objective, z, fz);
      } catch(const std::exception&) {
        // no decrease found along the search direction (precision limit): z may be a rejected
        // trial point; the best evaluated point is kept below
        it = 0;
      }
      result.inner_iterations += it;
      if(ev.best_energy() <= E_prev && ev.best_y().size() == y.size()) y = ev.best_y();
      ++result.outer_iterations;

      const double En = ev.value(y);
      ev.corners(y, x);
      dets = ev.determinants(x);
      if(options.on_iteration)
        options.on_iteration(outer, En / ev.scale(), ev.epsilon, dets.first, dets.second);

      const double sigma = (std::max)(1. - En / E_prev, 0.1);
      const double mu = (1. - sigma) * foldover_free_chi(dets.first, ev.epsilon);
      ev.epsilon = dets.first < mu ? 2. * std::sqrt(mu * (mu - dets.first)) : options.minimum_epsilon;
      ev.epsilon = (std::max)(ev.epsilon, options.minimum_epsilon);

      if(dets.second == 0 && (options.stop_when_untangled || std::abs(E_prev - En) <= options.energy_tolerance * En))
        break;
    }
  }

  ev.corners(y, x);
  dets = ev.determinants(x);
  result.min_det_after = E > 0 ? dets.first : 0;
  result.inverted_after = count_inverted_elements(p, x);
  result.success = result.inverted_after == 0;
  result.energy = E > 0 ? ev.value(y) / ev.scale() : 0;
  result.epsilon = ev.epsilon;
  result.evaluations = ev.evaluations();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_UNTANGLING_FOLDOVER_FREE_MAP_H
