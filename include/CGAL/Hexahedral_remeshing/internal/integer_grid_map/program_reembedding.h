// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The re-embedding of the motorcycle complex's lengths when the quantized map still folds after its
// repair (issue 27 step 4). The complex's program keeps every block extent >= 0 and the sides that must
// stay apart >= 1: lengths that admit a valid integer-grid map (Brueckler, Bommes, Campen 2022). Their
// linear map (the energy's minimizer with the lengths held) often folds more than the rounded one, which
// is why the quantizer keeps the rounded values; but a map is re-embedded by the untangling, not by the
// linear solve. On the flange of make_parts.py the rounded map keeps 32 inverted tetrahedra after its
// repair, and the program's map (318 folded before its repair, 197 for the rounded one) none.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_PROGRAM_REEMBEDDING_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_PROGRAM_REEMBEDDING_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fold_repair.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

struct Program_reembedding
{
  bool ran = false;                   // the quantized map folded after its repair and there were other lengths
  bool kept = false;                  // the program's map folds less once repaired: it replaced `y`
  std::size_t folds_quantized = 0;    // folded tetrahedra of the quantized map after its repair
  std::size_t folds_program = 0;      // of the program's map after its repair
  Fold_repair_report repair;          // of the program's map
};

// If `y` (the quantized map after repair_folds()) still folds and `lengths` (integer values by column,
// the complex's program) are given: the map with those values held, from the unstiffened system
// (`H`, `rhs`), repaired the same way; kept in `y` if it has fewer folded tetrahedra (the structurally
// flat ones left out). `solver`'s system and fixed values are left to the map kept.
template <class Traits, class Visitor>
Program_reembedding reembed_program_lengths(const Tetrahedral_mesh_3<Traits>& mesh, const Fold_repair_input& in,
                                            const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                                            const std::vector<std::pair<Eigen::Index, double> >& lengths, bool untangle,
                                            int maximum_stiffening, int rings, Fixed_variable_solver& solver, Visitor& visitor,
                                            Eigen::VectorXd& y)
{
  Program_reembedding r;
  auto folds = [&](const Eigen::VectorXd& v) { return count_non_positive_jacobians(in.geometry, in.P * v + in.x0, &in.flat); };
  r.folds_quantized = r.folds_program = folds(y);
  if(r.folds_quantized == 0 || lengths.empty()) return r;
  r.ran = true;
  solver.set_system(H, rhs);
  for(const auto& l : lengths) solver.fix(l.first, l.second);
  Eigen::VectorXd z = y;
  if(solver.solve(z)) {
    r.repair = repair_folds(mesh, in, solver, untangle, maximum_stiffening, rings, visitor, z);
    r.folds_program = folds(z);
  }
  r.kept = r.folds_program < r.folds_quantized;
  if(r.kept) y = z;
  else
    for(const auto& l : lengths) solver.fix(l.first, y[l.first]);
  return r;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_PROGRAM_REEMBEDDING_H
