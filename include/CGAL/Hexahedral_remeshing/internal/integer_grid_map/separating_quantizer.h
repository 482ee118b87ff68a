// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEPARATING_QUANTIZER_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEPARATING_QUANTIZER_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/greedy_rounding.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/integer_program.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/linear_form.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/quantizer.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// What the separation program did (reported by compute_integer_grid_map()).
struct Separation_report
{
  bool used = false;             // the map comes from the program (it does not fold, the rounded one did)
  std::string reason;            // why the program was not run, stopped, or not kept
  int rounds = 0;                // programs solved
  std::size_t constraints = 0;   // separation constraints at the end
  std::size_t variables = 0;     // integer variables of the last program
  std::size_t folds_after_rounding = 0, folds_after_program = 0;
  double program_seconds = 0;
};

// Greedy rounding, then, where the rounded map folds, separation constraints added lazily and an
// integer program (Cbc) that moves as few integer values as it can to satisfy them:
//   1. round greedily (the map of the greedy rounding is kept whenever it does not fold);
//   2. around the folds, find the entities that the seamless map keeps apart and the rounding
//      collapsed (Separation_finder): each gives `later - earlier >= 1`;
//   3. solve min sum |z - z_rounded| + 1/4 |z - z_seamless| over the integer variables of the
//      constraints under all constraints found so far, the other integer values held; re-solve the
//      continuous variables; repeat from 2 while folds remain and new constraints appear.
// The program's map is kept only if it does not fold (else the rounded one). This is the separation of QGP3D without its motorcycle
// complex: the collapses are found in the tetrahedral mesh, around the folds only.
class Separating_quantizer : public Quantizer
{
public:
  typedef std::function<std::vector<Linear_form>(const Eigen::VectorXd&, const Eigen::VectorXd&)> Violated;
  typedef std::function<std::size_t(const Eigen::VectorXd&)> Fold_count;

  Greedy_rounding_quantizer greedy;
  int maximum_rounds = 8;
  double time_limit = 60;           // seconds, over all programs
  double seamless_weight = 0.25;
  // The seamless map that orders the entities and anchors the objective: the untangled one of
  // compute_seamless_map() (an order read from a folded map is not an order); the rounding's
  // relaxation if empty.
  Eigen::VectorXd seamless;
  // Folds of the seamless map itself (det J <= 0, structurally flat tetrahedra left out): the program
  // cannot remove them, and its map is kept only without folds, so it is not run (none of the 14 shared
  // models whose seamless map folds got a program's map; n05c spent 43 s in 4 programs).
  std::size_t seamless_folds = 0;
  Separation_report report;

  Separating_quantizer(Violated violated, Fold_count folds) : m_violated(std::move(violated)), m_folds(std::move(folds)) {}

  Quantization_result quantize(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                               const std::vector<char>& integer, Fixed_variable_solver& solver,
                               Eigen::VectorXd& y) override
  {
    Quantization_result q = greedy.quantize(H, rhs, integer, solver, y);
    if(!q.success || q.relaxed.size() != y.size()) { report.reason = "the rounding failed"; return q; }
    report.folds_after_rounding = report.folds_after_program = m_folds(y);
    if(report.folds_after_rounding == 0) { report.reason = "the rounded map does not fold"; return q; }
    if(seamless_folds > 0) { report.reason = "the seamless map folds before any rounding (the rounded map kept)"; return q; }
    separate(seamless.size() == y.size() ? seamless : q.relaxed, solver, y);
    return q;
  }

private:
  void separate(const Eigen::VectorXd& reference, Fixed_variable_solver& solver, Eigen::VectorXd& y)
  {
    const Eigen::VectorXd rounded = y;
    Eigen::VectorXd best = y, current = y;
    std::set<Linear_form> constraints;
    std::set<Eigen::Index> columns;
    double seconds_left = time_limit;
    for(;;) {
      if(report.rounds == maximum_rounds) { report.reason = "round limit with folds left"; break; }
      std::size_t added = 0;
      for(Linear_form& c : m_violated(reference, current)) added += constraints.insert(std::move(c)).second;
      if(added == 0) { report.reason = report.rounds == 0 ? "no collapse found at the folds" : "folds left without a collapse"; break; }
      std::vector<Integer_program_variable> variables;
      for(const Linear_form& c : constraints)
        for(const auto& t : c.terms) columns.insert(t.first);
      for(Eigen::Index col : columns) variables.push_back({col, rounded[col], 1.0, reference[col], seamless_weight});
      const Integer_program_result p =
        solve_integer_program(variables, std::vector<Linear_form>(constraints.begin(), constraints.end()), seconds_left);
      ++report.rounds;
      report.program_seconds += p.seconds;
      seconds_left -= p.seconds;
      report.constraints = constraints.size();
      report.variables = variables.size();
      if(p.status == Integer_program_result::INFEASIBLE) { report.reason = "separation program infeasible"; break; }
      if(p.status == Integer_program_result::FAILED) { report.reason = "separation program failed or timed out"; break; }
      for(std::size_t i = 0; i < variables.size(); ++i) solver.fix(variables[i].column, p.values[i]);
      if(!solver.solve(current)) { report.reason = "factorization failed"; break; }
      const std::size_t folds = m_folds(current);
      if(folds < report.folds_after_program) { best = current; report.folds_after_program = folds; }
      if(folds == 0) { report.reason = "no fold left"; break; }
      if(seconds_left <= 0) { report.reason = "time limit with folds left"; break; }
    }
    // Only a map without folds replaces the rounded one: with folds left, the repair that follows
    // (untangling, stiffening) did better from the rounded map on 4 of the 42 shared models.
    report.used = report.folds_after_program == 0;
    if(!report.used) {
      best = rounded;
      report.reason += " (the rounded map kept)";
    }
    for(Eigen::Index col : columns) solver.fix(col, best[col]);
    y = best;
  }

  Violated m_violated;
  Fold_count m_folds;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEPARATING_QUANTIZER_H
