// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_QUANTIZER_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_QUANTIZER_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fixed_variable_solver.h>

#include <Eigen/Sparse>

#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The quantization of the seamless map: the mixed-integer problem min y^T H y - 2 rhs^T y with the
// variables flagged in `integer` restricted to integers. The greedy rounding below implements it; a
// more robust quantizer (motorcycle complex + LP sheet separations, as QGP3D) can replace it behind
// this interface. On return every integer variable is fixed in `solver` at its (integer) value and
// `y` is the minimizer of the continuous variables given them.
struct Quantization_result
{
  bool success = true;   // false if a factorization failed
  int rounds = 0;        // solves of the rounding loop
  double max_rounding = 0; // largest |y_i - round(y_i)| of a variable when it was rounded
  Eigen::VectorXd relaxed;  // the solution of the continuous relaxation (first solve)
  // Integer values (column, value) of a quantization that was not kept because its linear map folded
  // more (the motorcycle complex's program): re-embedded if the kept map still folds once repaired.
  std::vector<std::pair<Eigen::Index, double> > alternative;
};

class Quantizer
{
public:
  virtual ~Quantizer() = default;
  virtual Quantization_result quantize(const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                                       const std::vector<char>& integer, Fixed_variable_solver& solver,
                                       Eigen::VectorXd& y) = 0;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_QUANTIZER_H
