// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_FIXED_VARIABLE_SOLVER_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_FIXED_VARIABLE_SOLVER_H

#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <algorithm>
#include <memory>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Minimizes y^T H y - 2 rhs^T y with some variables fixed to given values, with CHOLMOD's
// supernodal Cholesky. A fixed variable keeps its entries in the matrix: its row and column are set
// to the identity (the other entries to 0, not removed) and its column times its value moves to the
// right side, so the sparsity pattern never changes and the symbolic analysis is done once; every
// later solve is a numeric factorization only (algorithms.md §4 "Mixed-integer solve"), and none at
// all if neither H nor the set of fixed variables changed since the last one (the values the fixed
// variables take only move the right side): the flange of make_parts.py at 91,446 tetrahedra made 6
// factorizations of its 49,186 variables, 4 of them of the same matrix as the one before.
// H is given with both triangles (CHOLMOD reads the lower one).
class Fixed_variable_solver
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;

  // Replaces the system; keeps the symbolic analysis if the pattern is the same.
  void set_system(const Matrix& H, const Eigen::VectorXd& rhs)
  {
    const bool same = m_H.rows() == H.rows() && m_H.nonZeros() == H.nonZeros() &&
                      std::equal(H.outerIndexPtr(), H.outerIndexPtr() + H.outerSize() + 1, m_H.outerIndexPtr()) &&
                      std::equal(H.innerIndexPtr(), H.innerIndexPtr() + H.nonZeros(), m_H.innerIndexPtr());
    if(!same) m_analysed = false;
    if(!same || !std::equal(H.valuePtr(), H.valuePtr() + H.nonZeros(), m_H.valuePtr())) m_factored = false;
    m_H = H;
    m_H.makeCompressed();
    m_rhs = rhs;
    if(m_fixed.size() != std::size_t(H.rows())) {
      m_fixed.assign(std::size_t(H.rows()), 0);
      m_values.setZero(H.rows());
    }
  }

  void fix(Eigen::Index i, double value) { m_fixed[std::size_t(i)] = 1; m_values[i] = value; }
  bool is_fixed(Eigen::Index i) const { return m_fixed[std::size_t(i)] != 0; }
  // Frees every variable (a new quantization after one that was not kept).
  void unfix_all()
  {
    std::fill(m_fixed.begin(), m_fixed.end(), char(0));
    m_values.setZero();
  }
  // Numeric factorizations made (those found in hand not counted).
  int factorizations() const { return m_factorizations; }

  // Solves; returns false if the factorization failed (matrix not positive definite).
  bool solve(Eigen::VectorXd& y)
  {
    if(!factorize(m_fixed)) return false;
    Eigen::VectorXd r = m_rhs - m_H * m_values; // m_values is 0 at the free variables
    for(Eigen::Index i = 0; i < r.size(); ++i)
      if(m_fixed[std::size_t(i)]) r[i] = m_values[i];
    y = m_llt->solve(r);
    if(m_llt->info() != Eigen::Success) return false;
    for(Eigen::Index i = 0; i < y.size(); ++i)
      if(m_fixed[std::size_t(i)]) y[i] = m_values[i];
    return true;
  }

  // The minimizer as an affine function of the free variables `vars`, with one factorization:
  // y(z) = y0 + Y z for the values z of vars (the other fixed variables at their values); Y has one
  // column per variable of vars. The fixed set is left as it was. Returns false if the factorization
  // failed.
  bool solve_affine(const std::vector<Eigen::Index>& vars, Eigen::VectorXd& y0, Eigen::MatrixXd& Y)
  {
    std::vector<char> fixed = m_fixed;
    for(Eigen::Index i : vars) fixed[std::size_t(i)] = 1;
    if(!factorize(fixed)) return false;
    const Eigen::Index k = Eigen::Index(vars.size());
    // column 0: the vars at 0; column c + 1: the response to vars[c] = 1 (homogeneous)
    Eigen::MatrixXd R(m_H.rows(), k + 1);
    R.col(0) = m_rhs - m_H * m_values;
    for(Eigen::Index c = 0; c < k; ++c) R.col(c + 1) = -m_H.col(vars[std::size_t(c)]);
    for(Eigen::Index i = 0; i < R.rows(); ++i)
      if(fixed[std::size_t(i)]) R.row(i).setZero();
    for(Eigen::Index i = 0; i < R.rows(); ++i)
      if(m_fixed[std::size_t(i)]) R(i, 0) = m_values[i];
    for(Eigen::Index c = 0; c < k; ++c) R(vars[std::size_t(c)], c + 1) = 1.0;
    const Eigen::MatrixXd X = m_llt->solve(R);
    if(m_llt->info() != Eigen::Success) return false;
    y0 = X.col(0);
    Y = X.rightCols(k);
    for(Eigen::Index i = 0; i < Y.rows(); ++i)
      if(fixed[std::size_t(i)]) { y0[i] = m_fixed[std::size_t(i)] ? m_values[i] : 0.0; Y.row(i).setZero(); }
    for(Eigen::Index c = 0; c < k; ++c) Y(vars[std::size_t(c)], c) = 1.0;
    return true;
  }

private:
  // Numeric factorization of H with the rows and columns of the `fixed` variables replaced by the
  // identity's (the symbolic analysis is done once; the last factorization if it was of the same).
  bool factorize(const std::vector<char>& fixed)
  {
    if(m_factored && fixed == m_factored_fixed) return m_factored_ok;
    Matrix M = m_H;
    for(Eigen::Index j = 0; j < M.outerSize(); ++j)
      for(Matrix::InnerIterator it(M, j); it; ++it)
        if(fixed[std::size_t(it.row())] || fixed[std::size_t(j)]) it.valueRef() = it.row() == j ? 1.0 : 0.0;
    if(!m_analysed) {
      m_llt = std::make_unique<Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> >();
      m_llt->analyzePattern(M);
      m_analysed = true;
    }
    m_llt->factorize(M);
    ++m_factorizations;
    m_factored = true;
    m_factored_fixed = fixed;
    m_factored_ok = m_llt->info() == Eigen::Success;
    return m_factored_ok;
  }

  Matrix m_H;
  Eigen::VectorXd m_rhs, m_values;
  std::vector<char> m_fixed;
  std::unique_ptr<Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> > m_llt;
  bool m_analysed = false;
  int m_factorizations = 0;
  // the factorization in m_llt: of m_H with m_factored_fixed fixed (valid while m_factored)
  bool m_factored = false, m_factored_ok = false;
  std::vector<char> m_factored_fixed;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_FIXED_VARIABLE_SOLVER_H
