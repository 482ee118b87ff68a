// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SANITIZE_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SANITIZE_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Snaps the free variables to a common dyadic grid (multiples of 2^-bits; the integer variables are
// integers already) so that every corner value x = P y + x0, a sum of such values with coefficients
// +-1 (or halves), is computed exactly in double: the transitions u_i = R u_j + t then hold bitwise
// and exact predicates on the parameters decide the extraction (HexEx truncatePrecision). The map is
// in hex units and stays far below 2^(52 - bits). Returns the largest move.
inline double snap_to_dyadic_grid(Eigen::VectorXd& y, const std::vector<char>& integer, int bits = 20)
{
  const double scale = std::ldexp(1.0, bits);
  double move = 0;
  for(Eigen::Index i = 0; i < y.size(); ++i) {
    const double snapped = integer[std::size_t(i)] ? std::round(y[i]) : std::round(y[i] * scale) / scale;
    move = (std::max)(move, std::abs(snapped - y[i]));
    y[i] = snapped;
  }
  return move;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SANITIZE_H
