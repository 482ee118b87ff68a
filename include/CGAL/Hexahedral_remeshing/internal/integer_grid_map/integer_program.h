// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_INTEGER_PROGRAM_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_INTEGER_PROGRAM_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/linear_form.h>

#include <coin/Cbc_C_Interface.h>

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The integer program of the quantization, solved with COIN-OR Cbc (branch and cut over Clp):
//   minimize  sum_i  w_i |z_i - a_i| + v_i |z_i - b_i|     over integer z_i
//   subject to  form(z) >= 1  for every separation constraint,
// with two targets per variable (the value it had, the seamless value). The absolute values are
// linearized with one continuous variable each. A fresh Cbc model per solve: Cbc's C interface
// does not re-read rows added after a solve.
struct Integer_program_result
{
  enum Status { OPTIMAL, FEASIBLE, INFEASIBLE, FAILED };
  Status status = FAILED;
  std::vector<double> values;   // per variable, in the order of `variables`
  double objective = 0;
  double seconds = 0;
};

struct Integer_program_variable
{
  Eigen::Index column;   // variable of the map problem
  double first_target, first_weight, second_target, second_weight;
};

inline Integer_program_result solve_integer_program(const std::vector<Integer_program_variable>& variables,
                                                    const std::vector<Linear_form>& constraints, double time_limit)
{
  Integer_program_result r;
  std::unique_ptr<Cbc_Model, void (*)(Cbc_Model*)> model(Cbc_newModel(), Cbc_deleteModel);
  Cbc_Model* m = model.get();
  Cbc_setLogLevel(m, 0);
  Cbc_setMaximumSeconds(m, time_limit);
  std::map<Eigen::Index, int> index;
  const int n = int(variables.size());
  const double big = 1e7;
  for(int i = 0; i < n; ++i) {
    index[variables[std::size_t(i)].column] = i;
    Cbc_addCol(m, "", -big, big, 0.0, 1, 0, nullptr, nullptr);
  }
  // |z - a| <= e: z - e <= a, -z - e <= -a
  auto add_deviation = [&](int i, double target, double weight) {
    if(weight <= 0) return;
    const int e = Cbc_getNumCols(m);
    Cbc_addCol(m, "", 0.0, 1e30, weight, 0, 0, nullptr, nullptr);
    int cols[2] = {i, e};
    double up[2] = {1.0, -1.0}, down[2] = {-1.0, -1.0};
    Cbc_addRow(m, "", 2, cols, up, 'L', target);
    Cbc_addRow(m, "", 2, cols, down, 'L', -target);
  };
  for(int i = 0; i < n; ++i) {
    const Integer_program_variable& v = variables[std::size_t(i)];
    add_deviation(i, v.first_target, v.first_weight);
    add_deviation(i, v.second_target, v.second_weight);
  }
  for(const Linear_form& c : constraints) {
    std::vector<int> cols;
    std::vector<double> coefs;
    for(const auto& t : c.terms) {
      const auto it = index.find(t.first);
      if(it == index.end()) return r; // every column of a constraint must be a variable
      cols.push_back(it->second);
      coefs.push_back(t.second);
    }
    Cbc_addRow(m, "", int(cols.size()), cols.data(), coefs.data(), 'G', 1.0 - c.constant);
  }
  const auto start = std::chrono::steady_clock::now();
  Cbc_solve(m);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(Cbc_isProvenInfeasible(m)) { r.status = Integer_program_result::INFEASIBLE; return r; }
  const double* x = Cbc_bestSolution(m);
  if(x == nullptr) return r;
  r.status = Cbc_isProvenOptimal(m) ? Integer_program_result::OPTIMAL : Integer_program_result::FEASIBLE;
  r.objective = Cbc_getObjValue(m);
  for(int i = 0; i < n; ++i) r.values.push_back(std::round(x[i]));
  return r;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_INTEGER_PROGRAM_H
