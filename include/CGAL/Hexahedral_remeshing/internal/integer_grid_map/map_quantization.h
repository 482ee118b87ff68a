// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_QUANTIZATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_QUANTIZATION_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fixed_variable_solver.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/greedy_rounding.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_continuation.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/complex_quantizer.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/program_reembedding.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/seamless_map.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/separating_quantizer.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Starts and ends the stages of compute_integer_grid_map() on its visitor; end() returns the seconds.
template <class Visitor>
struct Map_stage_timer
{
  Visitor& visitor;
  std::string stage = std::string();
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();

  void start(const std::string& name)
  {
    stage = name;
    visitor.start_stage(stage);
    started = std::chrono::steady_clock::now();
  }
  double end()
  {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    visitor.end_stage(stage, seconds);
    return seconds;
  }
};

// The seamless map's part of the report (`Result`: Integer_grid_map_result).
template <class Result>
void report_seamless_map(const Seamless_map& m, Result& r)
{
  r.relaxed_inverted_tetrahedra = m.inverted_before_untangling;
  r.seamless_inverted_tetrahedra = m.inverted;
  r.seamless_degenerate_tetrahedra = m.degenerate;
  r.seamless_branched_edges = m.branched;
  r.seamless_injective = m.success && m.folds.empty() && m.branched == 0;
  r.seamless_folds = m.folds;
  r.seamless_untangling_ran = m.untangling_ran;
  r.seamless_unbranching_ran = m.unbranching_ran;
  r.relaxed_wrapped_boundary_vertices = m.wrapped_before_untangling;
  r.seamless_wrapped_boundary_vertices = m.wrapped;
}

// The complex's part of the report (`Complex`: Integer_grid_map_complex).
template <class Complex>
void report_complex_quantization(const motorcycle::Complex_quantization_report& q, Complex& c)
{
  if(q.traced || c.reason.empty()) c.reason = q.reason; // else why it was not traced
  c.traced = c.traced && q.traced;
  c.extents = q.extents;
  c.separated_extents = q.separated;
  c.separated_paths = q.paths;
  c.skipped_extents = q.skipped_extents;
  c.folds_after_rounding = q.folds_after_rounding;
  c.folds_after_program = q.folds;
  c.program_variables = q.variables;
  c.program_constraints = q.constraints;
  c.programs = q.rounds;
  c.objective = q.objective;
  c.program_seconds = q.program_seconds;
}

// The quantization on the motorcycle complex (complex_quantizer.h); true if its map is final: the
// program's map does not fold, or the rounded one does not, or no other quantizer is asked, or the
// seamless map has `seamless_folds` of its own (which no program removes: the rounded map is kept,
// and not rounded a second time by the separating quantizer).
template <class Finder, class Options, class Result>
bool quantize_on_complex(const Finder& finder, const motorcycle::Complex_quantizer::Trace& trace, const Eigen::SparseMatrix<double>& H,
                         const Eigen::VectorXd& rhs, const std::vector<char>& integer_column, const Eigen::VectorXd& seamless,
                         std::size_t seamless_folds, const Options& o, Fixed_variable_solver& solver, Eigen::VectorXd& y,
                         Result& r, Quantization_result& q)
{
  typedef decltype(r.quantization) Path;
  motorcycle::Complex_quantizer quantizer(trace, seamless, [&](const Eigen::VectorXd& v) { return finder.folded(v); });
  quantizer.time_limit = o.quantization_time_limit;
  q = quantizer.quantize(H, rhs, integer_column, solver, y);
  report_complex_quantization(quantizer.report, r.motorcycle_complex);
  r.quantization = quantizer.report.used ? Path::MOTORCYCLE_COMPLEX : Path::GREEDY_ROUNDING;
  r.folds_after_rounding = r.folds_after_separation = quantizer.report.folds_after_rounding;
  if(!q.success || quantizer.report.used || quantizer.report.folds_after_rounding == 0 || o.quantization == Path::MOTORCYCLE_COMPLEX)
    return true;
  if(seamless_folds > 0) {
    r.quantization_reason = "the seamless map folds before any rounding (the rounded map kept)";
    return true;
  }
  solver.unfix_all();
  return false;
}

// The separating quantizer (separating_quantizer.h) with `seamless` (the untangled seamless map) as its
// reference, unless the seamless map has `seamless_folds` of its own; `alternative`: the complex's
// program's lengths, kept on offer for the re-embedding; the report copied into `r`.
template <class Finder, class Options, class Result>
Quantization_result separate_map(const Finder& finder, const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                                 const std::vector<char>& integer_column, const Eigen::VectorXd& seamless,
                                 std::size_t seamless_folds, const Options& o,
                                 const std::vector<std::pair<Eigen::Index, double> >& alternative,
                                 Fixed_variable_solver& solver, Eigen::VectorXd& y, Result& r)
{
  typedef decltype(r.quantization) Path;
  Separating_quantizer separating(
    [&](const Eigen::VectorXd& reference, const Eigen::VectorXd& v) { return finder.violated(reference, v); },
    [&](const Eigen::VectorXd& v) { const auto f = finder.folded(v); return std::size_t(std::count(f.begin(), f.end(), char(1))); });
  separating.time_limit = o.quantization_time_limit;
  separating.seamless = seamless;
  separating.seamless_folds = seamless_folds;
  Quantization_result q = separating.quantize(H, rhs, integer_column, solver, y);
  q.alternative = alternative;
  const Separation_report& sr = separating.report;
  r.quantization = sr.used ? Path::SEPARATION_PROGRAM : Path::GREEDY_ROUNDING;
  r.quantization_reason = sr.reason;
  r.folds_after_rounding = sr.folds_after_rounding;
  r.folds_after_separation = sr.folds_after_program;
  r.separation_rounds = sr.rounds;
  r.separation_constraints = sr.constraints;
  r.separation_variables = sr.variables;
  r.separation_seconds = sr.program_seconds;
  return q;
}

// The quantization of the map (`Options`: Map_options; `Result`: Integer_grid_map_result): greedy
// rounding; where it folds, corrected on the motorcycle complex of the seamless map if there is one
// (`trace`: Complex_quantizer::Trace); then, where the map still folds, the separating quantizer
// (separate_map()), unless `separation_deferred` is asked and the complex's program offers lengths
// (`alternative`): then it is left to the caller, true on return, and `y` is the rounded map.
template <class Finder, class Options, class Result>
Quantization_result quantize_map(const Finder& finder, const motorcycle::Complex_quantizer::Trace& trace, const Eigen::SparseMatrix<double>& H,
                                 const Eigen::VectorXd& rhs, const std::vector<char>& integer_column, const Eigen::VectorXd& seamless,
                                 std::size_t seamless_folds, const Options& o, Fixed_variable_solver& solver, Eigen::VectorXd& y, Result& r,
                                 bool& separation_deferred)
{
  typedef decltype(r.quantization) Path;
  const bool may_defer = separation_deferred;
  separation_deferred = false;
  if(o.quantization == Path::GREEDY_ROUNDING) {
    Greedy_rounding_quantizer greedy;
    return greedy.quantize(H, rhs, integer_column, solver, y);
  }
  Quantization_result q;
  if(o.quantization != Path::SEPARATION_PROGRAM &&
     quantize_on_complex(finder, trace, H, rhs, integer_column, seamless, seamless_folds, o, solver, y, r, q))
    return q;
  if(may_defer && !q.alternative.empty()) {
    separation_deferred = true;
    return q;
  }
  return separate_map(finder, H, rhs, integer_column, seamless, seamless_folds, o, q.alternative, solver, y, r);
}

// The re-embedding of the complex's lengths in the report (`Result`: Integer_grid_map_result).
template <class Result>
void report_program_reembedding(const Program_reembedding& pr, Result& r)
{
  typedef decltype(r.quantization) Path;
  auto& c = r.motorcycle_complex;
  c.reembedded = pr.ran;
  c.folds_after_repair_quantized = pr.folds_quantized;
  c.folds_after_repair_program = pr.folds_program;
  if(!pr.ran) return;
  r.untangling_ran = r.untangling_ran || pr.repair.untangling_ran;
  r.stiffening_seconds += pr.repair.stiffening_seconds;
  r.untangling_seconds += pr.repair.untangling_seconds;
  if(!pr.kept) return;
  const std::string replaced = r.quantization == Path::SEPARATION_PROGRAM ? "the separation program's" : "the rounded";
  r.quantization = Path::MOTORCYCLE_COMPLEX;
  r.stiffening_rounds = pr.repair.stiffening_rounds;
  r.quantization_reason = "the complex's lengths, re-embedded by the untangling: " + std::to_string(pr.folds_program) +
                          " folded tetrahedra against " + std::to_string(pr.folds_quantized) + " for " + replaced + " map once repaired";
}

// The continuation from the seamless map in the report (`Result`: Integer_grid_map_result).
template <class Result>
void report_map_continuation(const Map_continuation& mc, Result& r)
{
  auto& c = r.continuation;
  c.ran = mc.ran;
  c.reached = mc.reached;
  c.kept = mc.kept;
  c.steps = mc.steps;
  c.halvings = mc.halvings;
  c.parameter = mc.parameter;
  c.folds_before = mc.folds_before;
  c.branched_before = mc.branched_before;
  c.folds_after = mc.folds_after;
  c.branched_after = mc.branched_after;
  c.seconds = mc.seconds;
  c.program_lengths = mc.program_lengths;
  if(mc.kept && mc.program_lengths) {
    r.quantization = decltype(r.quantization)::MOTORCYCLE_COMPLEX;
    r.quantization_reason = "the complex's lengths, reached from the seamless map without a fold";
  }
}

// The status of the map, the most serious first (`Result`: Integer_grid_map_result).
template <class Result>
void set_map_status(bool solved, Result& r)
{
  typedef decltype(r.status) Status;
  if(!solved) r.status = Status::SOLVER_FAILURE;
  else if(r.sign_contradictions > 0 || r.inconsistent_constraints > 0) r.status = Status::INCONSISTENT_MATCHINGS;
  else if(!r.defects.empty()) r.status = Status::NON_MESHABLE_SINGULARITIES;
  else if(r.inverted_tetrahedra > 0) r.status = Status::INVERTED_TETRAHEDRA;
  else if(r.degenerate_tetrahedra > 0) r.status = Status::DEGENERATE_TETRAHEDRA;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_QUANTIZATION_H
