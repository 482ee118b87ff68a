// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_ELIMINATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_ELIMINATION_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/constraint_elimination.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/dof_reduction.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/linear_form.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The map over its free variables after the exact elimination of the cut constraints: the 12 corner
// scalars of every tetrahedron are x = P y + x0 (rows 12 t + 3 c + k, see map_scalar()), and the
// integer jump of axis k across cut face f is jump_form(f, k)(y). Columns flagged in
// `integer_column` are integer in an integer-grid map (boundary planes, singular lines, jumps).
struct Reduced_map
{
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Row_matrix;
  Row_matrix P;
  Eigen::VectorXd x0;
  std::vector<char> integer_column;
  std::size_t inconsistent_rows = 0;

  Linear_form jump_form(std::size_t f, int k)
  {
    Linear_form form;
    const Constraint_elimination::Expression e = expression(first_jump + 3 * cut_index[f] + std::uint32_t(k));
    form.constant = e.constant;
    for(const Constraint_elimination::Term& t : e.terms) form.terms.emplace_back(Eigen::Index(column[t.var]), t.coef);
    std::sort(form.terms.begin(), form.terms.end());
    return form;
  }

  Constraint_elimination::Expression expression(std::uint32_t v)
  {
    Constraint_elimination::Expression e;
    if(elimination.is_free(v)) e.terms.push_back(Constraint_elimination::Term{v, 1.0});
    else e = elimination.expand(v);
    return e;
  }

  Constraint_elimination elimination;
  std::vector<std::int64_t> column;         // elimination variable -> column of y (-1: eliminated)
  std::vector<std::uint32_t> cut_index;     // face -> index among the cut faces
  std::uint32_t first_jump = 0;             // elimination variable of the first jump
};

// Pins one corner per connected component (the one with the most integer coordinates) at 0: the
// energy does not see translations.
template <class Traits>
void pin_one_corner_per_component(const Tetrahedral_mesh_3<Traits>& mesh, const Map_dofs& dofs,
                                  Constraint_elimination& elimination)
{
  const std::size_t nt = mesh.number_of_tetrahedra();
  std::vector<int> best(mesh.number_of_components(), -1);
  std::vector<std::uint32_t> best_corner(mesh.number_of_components(), 0);
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int c = 0; c < 4; ++c) {
      int count = 0;
      for(int k = 0; k < 3; ++k) count += dofs.integer[dofs.dof[map_scalar(t, c, k)]];
      const std::size_t comp = mesh.tetrahedron_component(t);
      if(count > best[comp]) { best[comp] = count; best_corner[comp] = 4 * t + std::uint32_t(c); }
    }
  for(std::size_t comp = 0; comp < best.size(); ++comp)
    for(int k = 0; k < 3; ++k) {
      const std::uint32_t d = dofs.dof[map_scalar(best_corner[comp] / 4, int(best_corner[comp] % 4), k)];
      if(elimination.is_free(d)) elimination.fix(d, 0.0);
    }
}

// The transition rows of the cut faces: x_a - sign x_b - jump = 0 per vertex and axis.
template <class Traits>
void add_cut_transitions(const Tetrahedral_mesh_3<Traits>& mesh, const Matchings& matchings, const std::vector<char>& cut,
                         const Map_dofs& dofs, Reduced_map& map)
{
  typedef Constraint_elimination::Term Term;
  for(std::uint32_t f = 0; f < mesh.number_of_faces(); ++f) {
    if(!cut[f]) continue;
    const auto& ft = mesh.face_tetrahedra(f);
    const int R = transition_rotation(matchings, f);
    for(auto v : mesh.face_vertices(f)) {
      const int c0 = local_corner(mesh, ft[0], v), c1 = local_corner(mesh, ft[1], v);
      for(int k = 0; k < 3; ++k) {
        const auto [col, sign] = transition_row(R, k);
        const std::uint32_t a = map_scalar(ft[0], c0, k), b = map_scalar(ft[1], c1, col);
        const std::vector<Term> row = {Term{dofs.dof[a], double(dofs.sign[a])},
                                       Term{dofs.dof[b], -double(sign * dofs.sign[b])},
                                       Term{map.first_jump + 3 * map.cut_index[f] + std::uint32_t(k), -1.0}};
        map.elimination.add_row(row, 0.0);
      }
    }
  }
}

// x = P y + x0 from the expressions of the dofs over the free variables.
inline void build_corner_matrix(std::size_t number_of_tetrahedra, const Map_dofs& dofs, Reduced_map& map)
{
  for(std::uint32_t v = 0; v < map.elimination.number_of_variables(); ++v)
    if(map.elimination.is_free(v)) {
      map.column[v] = std::int64_t(map.integer_column.size());
      map.integer_column.push_back(map.elimination.is_integer(v) ? 1 : 0);
    }
  std::vector<Constraint_elimination::Expression> dof_expression(dofs.number_of_dofs);
  for(std::uint32_t d = 0; d < dofs.number_of_dofs; ++d) dof_expression[d] = map.expression(d);
  const std::size_t n = 12 * number_of_tetrahedra;
  map.P.resize(Eigen::Index(n), Eigen::Index(map.integer_column.size()));
  map.x0 = Eigen::VectorXd::Zero(Eigen::Index(n));
  std::vector<Eigen::Triplet<double> > triplets;
  triplets.reserve(n * 2);
  for(std::size_t i = 0; i < n; ++i) {
    const auto& e = dof_expression[dofs.dof[i]];
    const double sg = dofs.sign[i];
    map.x0[Eigen::Index(i)] = sg * e.constant;
    for(const Constraint_elimination::Term& term : e.terms) triplets.emplace_back(int(i), int(map.column[term.var]), sg * term.coef);
  }
  map.P.setFromTriplets(triplets.begin(), triplets.end());
}

// Exact elimination of the cut constraints (algorithms.md §4): one variable per dof (integer if
// tagged) and three integer jumps per cut face; contradicted dofs fixed at 0; one corner pinned per
// component; then the transition rows of the cut faces.
template <class Traits>
Reduced_map eliminate_cut_constraints(const Tetrahedral_mesh_3<Traits>& mesh, const Matchings& matchings,
                                      const std::vector<char>& cut, const std::vector<std::uint32_t>& cut_index,
                                      std::size_t cut_faces, const Map_dofs& dofs)
{
  Reduced_map map;
  map.cut_index = cut_index;
  for(std::size_t d = 0; d < dofs.number_of_dofs; ++d) map.elimination.add_variable(dofs.integer[d] != 0);
  map.first_jump = std::uint32_t(dofs.number_of_dofs);
  for(std::size_t k = 0; k < 3 * cut_faces; ++k) map.elimination.add_variable(true);
  for(std::size_t d = 0; d < dofs.number_of_dofs; ++d)
    if(dofs.contradicted[d]) map.elimination.fix(std::uint32_t(d), 0.0);
  pin_one_corner_per_component(mesh, dofs, map.elimination);
  add_cut_transitions(mesh, matchings, cut, dofs, map);
  map.inconsistent_rows = map.elimination.inconsistent_rows() + map.elimination.unresolved_rows();
  map.column.assign(map.elimination.number_of_variables(), -1);
  build_corner_matrix(mesh.number_of_tetrahedra(), dofs, map);
  return map;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_ELIMINATION_H
