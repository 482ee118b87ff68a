// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_GREEDY_ROUNDING_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_GREEDY_ROUNDING_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/quantizer.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Greedy mixed-integer rounding (MIQ / CoMISo style, algorithms.md §4): solve the relaxation, fix the
// unfixed integer variables that are closest to an integer (all those within `batch_distance` of an
// integer, and at least `minimum_batch_fraction` of the remaining ones, at least one), re-solve,
// until every integer variable is fixed.
//
// Two ways to re-solve, the same minimizers up to round-off. With few integer variables (k, the
// usual case: 9 on B0), the minimizer is an affine function y0 + Y z of their values z, computed
// with one factorization and k + 1 solves; the rounding then works on the k x k reduced system
// (Y^T H Y) z = Y^T (rhs - H y0), whose solves cost nothing next to a factorization. Else (k above
// `maximum_reduced_variables`, or Y over `maximum_reduced_bytes`) every round is a numeric
// factorization of the whole system.
class Greedy_rounding_quantizer : public Quantizer
{
public:
  double batch_distance = 0.05;
  double minimum_batch_fraction = 0.02;
  std::size_t maximum_reduced_variables = 500;
  double maximum_reduced_bytes = 256.0 * 1024 * 1024;

  Quantization_result quantize(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                               const std::vector<char>& integer, Fixed_variable_solver& solver,
                               Eigen::VectorXd& y) override
  {
    solver.set_system(H, rhs);
    std::vector<Eigen::Index> pending;
    for(Eigen::Index i = 0; i < Eigen::Index(integer.size()); ++i)
      if(integer[std::size_t(i)] && !solver.is_fixed(i)) pending.push_back(i);
    const double bytes = 8.0 * double(H.rows()) * double(pending.size() + 1);
    if(!pending.empty() && pending.size() <= maximum_reduced_variables && bytes <= maximum_reduced_bytes)
      return quantize_reduced(H, rhs, pending, solver, y);
    Quantization_result r;
    for(;;) {
      ++r.rounds;
      if(!solver.solve(y)) { r.success = false; return r; }
      if(r.rounds == 1) r.relaxed = y;
      if(pending.empty()) return r;
      round_batch(y, pending, [&](Eigen::Index i, double value) { solver.fix(i, value); }, r);
    }
  }

private:
  // Fixes the batch of `pending` closest to integers at their rounded `values` and removes it from
  // `pending` (kept sorted).
  template <class Fix>
  void round_batch(const Eigen::VectorXd& values, std::vector<Eigen::Index>& pending, const Fix& fix, Quantization_result& r) const
  {
    std::vector<std::pair<double, Eigen::Index> > by_distance;
    by_distance.reserve(pending.size());
    for(Eigen::Index i : pending) by_distance.emplace_back(std::abs(values[i] - std::round(values[i])), i);
    std::sort(by_distance.begin(), by_distance.end());
    const std::size_t at_least = (std::max)(std::size_t(1), std::size_t(std::ceil(minimum_batch_fraction * double(pending.size()))));
    std::size_t k = 0;
    while(k < by_distance.size() && (k < at_least || by_distance[k].first <= batch_distance)) {
      const Eigen::Index i = by_distance[k].second;
      r.max_rounding = (std::max)(r.max_rounding, by_distance[k].first);
      fix(i, std::round(values[i]));
      ++k;
    }
    pending.clear();
    for(std::size_t j = k; j < by_distance.size(); ++j) pending.push_back(by_distance[j].second);
    std::sort(pending.begin(), pending.end());
  }

  Quantization_result quantize_reduced(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                                       const std::vector<Eigen::Index>& vars, Fixed_variable_solver& solver,
                                       Eigen::VectorXd& y) const
  {
    Quantization_result r;
    Eigen::VectorXd y0;
    Eigen::MatrixXd Y;
    if(!solver.solve_affine(vars, y0, Y)) { r.success = false; return r; }
    const Eigen::Index k = Eigen::Index(vars.size());
    const Eigen::MatrixXd S = Y.transpose() * (H * Y);
    const Eigen::VectorXd g = Y.transpose() * (rhs - H * y0);
    // the values of the variables by their global index, as the sparse rounding sees them
    Eigen::VectorXd values = Eigen::VectorXd::Zero(H.rows());
    std::vector<Eigen::Index> position(std::size_t(H.rows()), -1);
    for(Eigen::Index c = 0; c < k; ++c) position[std::size_t(vars[std::size_t(c)])] = c;
    std::vector<char> fixed(std::size_t(k), 0);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(k);
    std::vector<Eigen::Index> pending = vars;
    for(;;) {
      ++r.rounds;
      if(!pending.empty()) {
        // S_PP z_P = g_P - S_PF z_F
        const Eigen::Index np = Eigen::Index(pending.size());
        Eigen::MatrixXd Spp(np, np);
        Eigen::VectorXd b(np);
        for(Eigen::Index a = 0; a < np; ++a) {
          const Eigen::Index ca = position[std::size_t(pending[std::size_t(a)])];
          b[a] = g[ca];
          for(Eigen::Index c = 0; c < k; ++c)
            if(fixed[std::size_t(c)]) b[a] -= S(ca, c) * z[c];
          for(Eigen::Index e = 0; e < np; ++e) Spp(a, e) = S(ca, position[std::size_t(pending[std::size_t(e)])]);
        }
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(Spp);
        const Eigen::VectorXd zp = ldlt.solve(b);
        if(ldlt.info() != Eigen::Success || !zp.allFinite()) { r.success = false; return r; }
        for(Eigen::Index a = 0; a < np; ++a) z[position[std::size_t(pending[std::size_t(a)])]] = zp[a];
      }
      if(r.rounds == 1) r.relaxed = y0 + Y * z;
      if(pending.empty()) break;
      for(Eigen::Index i : pending) values[i] = z[position[std::size_t(i)]];
      round_batch(values, pending, [&](Eigen::Index i, double value) {
        const Eigen::Index c = position[std::size_t(i)];
        fixed[std::size_t(c)] = 1;
        z[c] = value;
      }, r);
    }
    y = y0 + Y * z;
    for(Eigen::Index c = 0; c < k; ++c) {
      y[vars[std::size_t(c)]] = z[c];
      solver.fix(vars[std::size_t(c)], z[c]);
    }
    return r;
  }
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_GREEDY_ROUNDING_H
