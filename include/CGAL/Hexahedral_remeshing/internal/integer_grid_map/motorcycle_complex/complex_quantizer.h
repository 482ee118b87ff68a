// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_COMPLEX_QUANTIZER_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_COMPLEX_QUANTIZER_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/integer_program.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/block_extents.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/motorcycle_complex.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/quantizer.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// What the quantization by the motorcycle complex did (issue 27 steps 2-4).
struct Complex_quantization_report
{
  bool used = false;       // the map comes from the complex's program and does not fold
  std::string reason;      // why not, or how it ended
  Motorcycle_complex_report complex;
  std::size_t extents = 0, separated = 0;      // block extents in the program, those kept >= 1
  std::size_t skipped_extents = 0;             // sides without a known form, not boxes, forms off the map
  std::size_t variables = 0, constraints = 0;  // of the last program
  int rounds = 0;                               // programs solved
  double objective = 0, program_seconds = 0;
  std::size_t folds = 0;                        // folded tetrahedra of the last map
};

// The quantization on the motorcycle complex of the injective seamless map (QGP3D's formulation on the
// variables of the map): every block extent (the length of the block's arcs along one axis) is an
// affine function of the integer variables; one integer program (Cbc) chooses the integer values
// closest to the seamless ones (sum |z - z_seamless|) with every extent >= 0 and >= 1 where the two
// sides must stay apart (Block_extent::separate); the continuous variables are then solved with the
// integer ones held (the re-embedding: patch sides equal by construction, since the arcs are those of
// one map). Where the map still folds, the zero extents of the blocks with folded tetrahedra are kept
// apart too (lazily, up to `maximum_rounds` programs).
class Complex_quantizer : public Quantizer
{
public:
  typedef std::function<std::vector<char>(const Eigen::VectorXd&)> Folded; // per input tetrahedron
  double time_limit = 60;
  int maximum_rounds = 4;
  Complex_quantization_report report;

  Complex_quantizer(Block_extents extents, const Eigen::VectorXd& seamless, Folded folded)
    : m_extents(std::move(extents)), m_seamless(seamless), m_folded(std::move(folded))
  {}

  Quantization_result quantize(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                               const std::vector<char>& integer, Fixed_variable_solver& solver,
                               Eigen::VectorXd& y) override
  {
    Quantization_result q;
    q.relaxed = m_seamless;
    solver.set_system(H, rhs);
    const std::vector<Block_extent*> extents = usable_extents(integer);
    std::vector<Integer_program_variable> variables;
    for(Eigen::Index i = 0; i < Eigen::Index(integer.size()); ++i)
      if(integer[std::size_t(i)]) variables.push_back({i, m_seamless[i], 1.0, m_seamless[i], 0.0});
    report.variables = variables.size();
    double seconds_left = time_limit;
    for(;;) {
      const std::vector<Linear_form> constraints = program_constraints(extents);
      const Integer_program_result p = solve_integer_program(variables, constraints, seconds_left);
      ++report.rounds;
      report.program_seconds += p.seconds;
      seconds_left -= p.seconds;
      if(p.status == Integer_program_result::INFEASIBLE) { report.reason = "the complex's program is infeasible"; break; }
      if(p.status == Integer_program_result::FAILED) { report.reason = "the complex's program failed or timed out"; break; }
      report.objective = p.objective;
      for(std::size_t i = 0; i < variables.size(); ++i) solver.fix(variables[i].column, p.values[i]);
      if(!solver.solve(y)) { q.success = false; report.reason = "factorization failed"; break; }
      const std::vector<char> folded = m_folded(y);
      report.folds = std::size_t(std::count(folded.begin(), folded.end(), char(1)));
      if(report.folds == 0) { report.used = true; report.reason = "no fold"; break; }
      if(report.rounds == maximum_rounds || seconds_left <= 0) { report.reason = "folds left after the last program"; break; }
      if(separate_zero_extents_at(extents, folded, y) == 0) { report.reason = "folds left without a zero extent there"; break; }
    }
    return q;
  }

private:
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
    return out;
  }

  std::vector<Linear_form> program_constraints(const std::vector<Block_extent*>& extents)
  {
    std::vector<Linear_form> c;
    report.separated = 0;
    for(const Block_extent* e : extents) {
      if(e->form.terms.empty()) continue; // fixed by the constraints of the map
      Linear_form f = e->form;
      if(e->separate) ++report.separated;
      else f.constant += 1; // extent >= 0
      c.push_back(f);
    }
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    report.extents = extents.size();
    report.constraints = c.size();
    return c;
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

  Block_extents m_extents;
  Eigen::VectorXd m_seamless;
  Folded m_folded;
};

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_COMPLEX_QUANTIZER_H
