// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_COMPLEX_QUANTIZER_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_COMPLEX_QUANTIZER_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/greedy_rounding.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/integer_program.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/block_extents.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/motorcycle_complex.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/quantizer.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// What the quantization by the motorcycle complex did (issue 27 steps 2-4).
struct Complex_quantization_report
{
  bool traced = false;     // the complex was traced (only when the rounded map folds)
  bool used = false;       // the map comes from the complex's program and does not fold
  std::string reason;      // why not, or how it ended
  Motorcycle_complex_report complex;
  std::size_t extents = 0, separated = 0;      // block extents in the program, those kept >= 1
  std::size_t paths = 0;                        // chains of zero extents between critical sides, kept >= 1
  std::size_t skipped_extents = 0;             // sides without a known form, not boxes, forms off the map
  std::size_t variables = 0, constraints = 0;  // of the last program
  int rounds = 0;                               // programs solved
  double objective = 0, program_seconds = 0;
  std::size_t folds_after_rounding = 0;         // folded tetrahedra of the rounded map
  std::size_t folds = 0;                        // folded tetrahedra of the last map
};

// The quantization on the motorcycle complex of the injective seamless map (QGP3D's formulation on the
// variables of the map): every block extent (the length of the block's arcs along one axis) is an
// affine function of the integer variables, to be >= 0, and >= 1 where the block's two sides must
// stay apart (Block_extent::separate). The greedy rounding runs first; if its map folds, the complex
// is traced and, if the rounded values break an extent or leave a zero extent at the folds (then kept
// >= 1), one integer program (Cbc) moves as few integer values as it can (sum |z - z_rounded|
// + 1/4 |z - z_seamless|) to satisfy every extent, and the continuous variables are solved with the
// integer ones held (the re-embedding: patch sides equal by construction, the arcs being those of one
// map). Where a map folds, QGP3D's separation is added lazily: every chain of blocks stacked along
// one direction whose extents are all zero and that joins two critical sides (zero_length_paths())
// gets sum >= 1, and the zero extents of the blocks with folded tetrahedra are kept apart too (up to
// `maximum_rounds` programs). The program's map is kept only if it does not fold; else the rounded one
// (the caller then tries the separation around the folds), the program's values offered as the
// alternative (Quantization_result), which the untangling may re-embed better than the rounded ones.
class Complex_quantizer : public Quantizer
{
public:
  typedef std::function<std::vector<char>(const Eigen::VectorXd&)> Folded; // per input tetrahedron
  Greedy_rounding_quantizer greedy;
  double time_limit = 60;
  int maximum_rounds = 4;
  double seamless_weight = 0.25;
  Complex_quantization_report report;

  // `trace` fills the block extents of the complex (false if there is none); it is called only if the
  // rounded map folds.
  typedef std::function<bool(Block_extents&)> Trace;

  Complex_quantizer(Trace trace, const Eigen::VectorXd& seamless, Folded folded)
    : m_trace(std::move(trace)), m_seamless(seamless), m_folded(std::move(folded))
  {}

  Quantization_result quantize(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                               const std::vector<char>& integer, Fixed_variable_solver& solver,
                               Eigen::VectorXd& y) override
  {
    Quantization_result q = greedy.quantize(H, rhs, integer, solver, y);
    if(!q.success) { report.reason = "the rounding failed"; return q; }
    const std::vector<char> folded = m_folded(y);
    report.folds = report.folds_after_rounding = std::size_t(std::count(folded.begin(), folded.end(), char(1)));
    // a rounded map that does not fold has merged nothing that must stay apart: a collapsed block
    // flattens the tetrahedra of the entities it merges
    if(report.folds == 0) { report.reason = "the rounded map does not fold"; return q; }
    if(!m_trace(m_extents)) { report.reason = "no motorcycle complex"; return q; }
    report.traced = true;
    const std::vector<Block_extent*> extents = usable_extents(integer);
    const std::size_t broken = broken_extents(extents, y);
    const std::size_t zero_at_folds = separate_zero_extents_at(extents, folded, y);
    if(broken + zero_at_folds + add_zero_length_paths(extents, y) == 0) {
      report.reason = "the rounded map keeps every block";
      return q;
    }
    const Eigen::VectorXd rounded = y;
    std::vector<Integer_program_variable> variables;
    for(Eigen::Index i = 0; i < Eigen::Index(integer.size()); ++i)
      if(integer[std::size_t(i)]) variables.push_back({i, rounded[i], 1.0, m_seamless[i], seamless_weight});
    report.variables = variables.size();
    solve_programs(extents, variables, solver, y);
    if(!report.used) {
      // the last program's lengths stay on offer: the untangling may re-embed them where the rounded ones fail
      q.alternative = m_program;
      for(const Integer_program_variable& v : variables) solver.fix(v.column, rounded[v.column]);
      y = rounded;
      report.reason += " (the rounded map kept)";
    }
    return q;
  }

private:
  void solve_programs(const std::vector<Block_extent*>& extents, const std::vector<Integer_program_variable>& variables,
                      Fixed_variable_solver& solver, Eigen::VectorXd& y)
  {
    double seconds_left = time_limit;
    for(;;) {
      const std::vector<Linear_form> constraints = program_constraints(extents);
      const Integer_program_result p = solve_integer_program(variables, constraints, seconds_left);
      ++report.rounds;
      report.program_seconds += p.seconds;
      seconds_left -= p.seconds;
      if(p.status == Integer_program_result::INFEASIBLE) { report.reason = "the complex's program is infeasible"; return; }
      if(p.status == Integer_program_result::FAILED) { report.reason = "the complex's program failed or timed out"; return; }
      report.objective = p.objective;
      m_program.clear();
      for(std::size_t i = 0; i < variables.size(); ++i) {
        solver.fix(variables[i].column, p.values[i]);
        m_program.emplace_back(variables[i].column, p.values[i]);
      }
      if(!solver.solve(y)) { report.reason = "factorization failed"; return; }
      const std::vector<char> folded = m_folded(y);
      report.folds = std::size_t(std::count(folded.begin(), folded.end(), char(1)));
      if(report.folds == 0) { report.used = true; report.reason = "no fold"; return; }
      if(report.rounds == maximum_rounds || seconds_left <= 0) { report.reason = "folds left after the last program"; return; }
      const std::size_t zero_at_folds = separate_zero_extents_at(extents, folded, y);
      if(zero_at_folds + add_zero_length_paths(extents, y) == 0) { report.reason = "folds left without a zero extent there"; return; }
    }
  }

  std::size_t broken_extents(const std::vector<Block_extent*>& extents, const Eigen::VectorXd& y) const
  {
    std::size_t n = 0;
    for(const Block_extent* e : extents) n += e->form(y) < (e->separate ? 0.5 : -0.5);
    return n;
  }

  // The extents whose forms are over integer variables and agree with the seamless map.
  std::vector<Block_extent*> usable_extents(const std::vector<char>& integer)
  {
    std::vector<Block_extent*> out;
    report.skipped_extents = 0;
    for(Block_extent& e : m_extents.extents) {
      bool ok = std::abs(e.form(m_seamless) - CGAL::to_double(e.seamless)) < 1e-6;
      for(const auto& t : e.form.terms) ok = ok && integer[std::size_t(t.first)] && t.second == std::round(t.second);
      if(ok) out.push_back(&e);
      else ++report.skipped_extents;
    }
    report.skipped_extents += m_extents.sides_without_form + m_extents.not_boxes;
    report.extents = out.size();
    report.separated = std::size_t(std::count_if(out.begin(), out.end(), [](const Block_extent* e) { return e->separate; }));
    return out;
  }

  std::vector<Linear_form> program_constraints(const std::vector<Block_extent*>& extents)
  {
    std::vector<Linear_form> c;
    report.separated = 0;
    for(const Block_extent* e : extents) {
      report.separated += e->separate;
      if(e->form.terms.empty()) continue; // fixed by the constraints of the map
      Linear_form f = e->form;
      if(!e->separate) f.constant += 1; // extent >= 0
      c.push_back(f);
    }
    c.insert(c.end(), m_paths.begin(), m_paths.end());
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    report.constraints = c.size();
    return c;
  }

  // The chains of zero extents in `y` between critical sides, each as sum >= 1; returns the new ones.
  std::size_t add_zero_length_paths(const std::vector<Block_extent*>& extents, const Eigen::VectorXd& y)
  {
    std::vector<double> values(m_extents.extents.size(), std::numeric_limits<double>::quiet_NaN());
    for(const Block_extent* e : extents) values[std::size_t(e - m_extents.extents.data())] = e->form(y);
    std::size_t added = 0;
    for(const std::vector<std::uint32_t>& path : zero_length_paths(m_extents, values)) {
      Linear_form sum;
      for(std::uint32_t i : path) sum = sum.plus(m_extents.extents[i].form, 1.0);
      if(!sum.terms.empty()) added += m_paths.insert(sum).second;
    }
    report.paths = m_paths.size();
    return added;
  }

  std::size_t separate_zero_extents_at(const std::vector<Block_extent*>& extents, const std::vector<char>& folded,
                                       const Eigen::VectorXd& y)
  {
    std::size_t added = 0;
    for(Block_extent* e : extents) {
      if(e->separate || e->form(y) > 0.5) continue;
      bool at_fold = false;
      for(std::uint32_t t : e->input_tetrahedra) at_fold = at_fold || folded[t];
      if(at_fold) { e->separate = true; ++added; }
    }
    return added;
  }

  Trace m_trace;
  Block_extents m_extents;
  std::set<Linear_form> m_paths;
  std::vector<std::pair<Eigen::Index, double> > m_program; // the integer values of the last program
  Eigen::VectorXd m_seamless;
  Folded m_folded;
};

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_COMPLEX_QUANTIZER_H
