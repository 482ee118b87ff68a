// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_GREEDY_ROUNDING_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_GREEDY_ROUNDING_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/quantizer.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Greedy mixed-integer rounding (MIQ / CoMISo style, algorithms.md §4): solve the relaxation, fix the
// unfixed integer variables that are closest to an integer (all those within `batch_distance` of an
// integer, and at least `minimum_batch_fraction` of the remaining ones, at least one), re-solve with
// a numeric factorization only, until every integer variable is fixed.
class Greedy_rounding_quantizer : public Quantizer
{
public:
  double batch_distance = 0.05;
  double minimum_batch_fraction = 0.02;

  Quantization_result quantize(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                               const std::vector<char>& integer, Fixed_variable_solver& solver,
                               Eigen::VectorXd& y) override
  {
    Quantization_result r;
    solver.set_system(H, rhs);
    std::vector<Eigen::Index> pending;
    for(Eigen::Index i = 0; i < Eigen::Index(integer.size()); ++i)
      if(integer[std::size_t(i)] && !solver.is_fixed(i)) pending.push_back(i);
    for(;;) {
      ++r.rounds;
      if(!solver.solve(y)) { r.success = false; return r; }
      if(r.rounds == 1) r.relaxed = y;
      if(pending.empty()) return r;
      std::vector<std::pair<double, Eigen::Index> > by_distance;
      by_distance.reserve(pending.size());
      for(Eigen::Index i : pending) by_distance.emplace_back(std::abs(y[i] - std::round(y[i])), i);
      std::sort(by_distance.begin(), by_distance.end());
      const std::size_t at_least = (std::max)(std::size_t(1), std::size_t(std::ceil(minimum_batch_fraction * double(pending.size()))));
      std::size_t k = 0;
      while(k < by_distance.size() && (k < at_least || by_distance[k].first <= batch_distance)) {
        const Eigen::Index i = by_distance[k].second;
        r.max_rounding = (std::max)(r.max_rounding, by_distance[k].first);
        solver.fix(i, std::round(y[i]));
        ++k;
      }
      pending.clear();
      for(std::size_t j = k; j < by_distance.size(); ++j) pending.push_back(by_distance[j].second);
      std::sort(pending.begin(), pending.end());
    }
  }
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_GREEDY_ROUNDING_H
