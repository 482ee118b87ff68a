// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_UNTANGLE_MAP_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_UNTANGLE_MAP_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>
#include <CGAL/Hexahedral_remeshing/internal/untangling/foldover_free_map.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

struct Map_untangling_result
{
  bool ran = false;
  std::size_t structurally_flat = 0; // tetrahedra flat for every value of the free variables
  std::size_t inverted_before = 0, inverted_after = 0;
};

// Foldover-free untangling of the continuous variables with the integer ones fixed (algorithms.md §4
// "Validity and repair" (2), Garanzha et al. 2021): K_t = J_t E_t / s, ideal K = I, weight vol_t.
// Seamlessness and the integer constraints are untouched since only the free continuous y move.
// Tetrahedra that the constraints flatten whatever y is (`flat`, see structurally_flat_tetrahedra())
// cannot be repaired and would stall the barrier: they are left out. With `region` (one flag per
// tetrahedron), only the continuous variables of the region's tetrahedra move, and the energy is that
// of the tetrahedra they reach (the others keep their map). The result is kept only if it has fewer
// inverted tetrahedra. With `relax`, a map without inverted tetrahedra is optimized by the barrier (which
// never inverts one) for one outer iteration instead (the flange's continuation, the whole map relaxed at
// each step: 7.5 s for its 18 steps, 13 s with two), and kept if it still has none. `outer_iterations`:
// the barrier's updates at most.
inline Map_untangling_result untangle_map(const Map_geometry& geometry, const std::vector<Eigen::Matrix3d>& frames,
                                          double s, const Eigen::SparseMatrix<double, Eigen::RowMajor>& P,
                                          const Eigen::VectorXd& x0, const std::vector<char>& integer,
                                          const std::vector<char>& flat, Eigen::VectorXd& y,
                                          const std::vector<char>* region = nullptr, bool relax = false,
                                          int outer_iterations = 50)
{
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Row_matrix;
  Map_untangling_result r;
  const std::size_t nt = geometry.volumes.size();
  // the moving (continuous) columns
  std::vector<char> moving(std::size_t(P.cols()), 0);
  for(std::size_t t = 0; t < nt; ++t)
    if(!region || (*region)[t])
      for(Eigen::Index i = Eigen::Index(12 * t); i < Eigen::Index(12 * t + 12); ++i)
        for(Row_matrix::InnerIterator it(P, i); it; ++it)
          if(!integer[std::size_t(it.col())]) moving[std::size_t(it.col())] = 1;
  std::vector<Eigen::Index> free_columns;
  std::vector<Eigen::Index> column_of(std::size_t(P.cols()), -1);
  Eigen::VectorXd y_fixed = y;
  for(Eigen::Index j = 0; j < P.cols(); ++j)
    if(moving[std::size_t(j)]) {
      column_of[std::size_t(j)] = Eigen::Index(free_columns.size());
      free_columns.push_back(j);
      y_fixed[j] = 0;
    }
  if(free_columns.empty()) return r;
  auto reached = [&](std::size_t t) {
    if(!region) return true;
    for(Eigen::Index i = Eigen::Index(12 * t); i < Eigen::Index(12 * t + 12); ++i)
      for(Row_matrix::InnerIterator it(P, i); it; ++it)
        if(moving[std::size_t(it.col())]) return true;
    return false;
  };
  std::vector<std::size_t> elements;
  for(std::size_t t = 0; t < nt; ++t) {
    if(flat[t]) ++r.structurally_flat;
    else if(reached(t)) elements.push_back(t);
  }
  Foldover_free_problem problem;
  const Eigen::Index E = Eigen::Index(elements.size());
  problem.x0.resize(12 * E);
  problem.M.resize(elements.size());
  problem.w.resize(elements.size());
  const Eigen::VectorXd x_fixed = P * y_fixed + x0;
  std::vector<Eigen::Triplet<double> > triplets;
  Eigen::Matrix<double, 3, 4> S;
  S << -1, 1, 0, 0, -1, 0, 1, 0, -1, 0, 0, 1;
  for(Eigen::Index e = 0; e < E; ++e) {
    const std::size_t t = elements[std::size_t(e)];
    problem.x0.segment<12>(12 * e) = x_fixed.segment<12>(Eigen::Index(12 * t));
    for(Eigen::Index i = 0; i < 12; ++i)
      for(Row_matrix::InnerIterator it(P, Eigen::Index(12 * t) + i); it; ++it)
        if(column_of[std::size_t(it.col())] >= 0) triplets.emplace_back(int(12 * e + i), int(column_of[std::size_t(it.col())]), it.value());
    // G = B^{-1} S, so B^{-1} = columns 1..3 of G; M = B^{-T} E / s
    const Eigen::Matrix3d B_inverse = geometry.gradients[t].rightCols<3>();
    problem.M[std::size_t(e)] = B_inverse.transpose() * frames[t] / s;
    problem.w[std::size_t(e)] = geometry.volumes[t];
  }
  problem.P.resize(12 * E, Eigen::Index(free_columns.size()));
  problem.P.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::VectorXd z(Eigen::Index(free_columns.size()));
  for(std::size_t k = 0; k < free_columns.size(); ++k) z[Eigen::Index(k)] = y[free_columns[k]];
  Foldover_free_options options;
  options.stop_when_untangled = true;
  options.max_outer_iterations = outer_iterations;
  // The barrier's epsilon, not the inner convergence, is what untangles: it falls about 10% per outer
  // iteration whatever the inner loop does, and every outer iteration hit a cap of 300 L-BFGS steps.
  // With 30 the graded acute wedge (65,164 tetrahedra, 19,679 inverted) untangles in 29 outer
  // iterations and 10.6 s instead of 25 and 72 s; over the 42 shared models the same 17 give valid
  // hex meshes, the map 1.5-14x faster (B0 52.6 -> 29.0 s, i01c 44.8 -> 16.1 s, n06c 58.9 -> 4.1 s).
  options.max_inner_iterations = 30;
  if(relax) {
    options.stop_when_untangled = false;
    options.max_outer_iterations = 1;
  }
  const Foldover_free_result f = minimize_foldover_free(problem, z, options);
  r.ran = true;
  r.inverted_before = f.inverted_before;
  r.inverted_after = f.inverted_after;
  if(f.inverted_after < f.inverted_before || (relax && f.inverted_after == 0))
    for(std::size_t k = 0; k < free_columns.size(); ++k) y[free_columns[k]] = z[Eigen::Index(k)];
  return r;
}

// The tetrahedra within `rings` rings (through shared vertices) of those with det J <= `below` that are
// not structurally flat: where a local untangling (`below` = 0) or relaxation moves the map.
template <class Traits>
std::vector<char> untangling_region(const Tetrahedral_mesh_3<Traits>& mesh, const Map_geometry& geometry,
                                    const Eigen::VectorXd& x, const std::vector<char>& flat, int rings, double below = 0)
{
  const std::size_t nt = geometry.volumes.size();
  std::vector<char> region(nt, 0), marked(mesh.number_of_vertices(), 0);
  for(std::size_t t = 0; t < nt; ++t)
    region[t] = !flat[t] && !(map_jacobian(geometry, x, t).determinant() > below);
  for(int ring = 0; ring < rings; ++ring) {
    for(std::size_t t = 0; t < nt; ++t)
      if(region[t])
        for(auto v : mesh.tetrahedron_vertices(typename Tetrahedral_mesh_3<Traits>::Index(t))) marked[v] = 1;
    for(std::size_t t = 0; t < nt; ++t)
      for(auto v : mesh.tetrahedron_vertices(typename Tetrahedral_mesh_3<Traits>::Index(t)))
        if(marked[v]) { region[t] = 1; break; }
  }
  return region;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_UNTANGLE_MAP_H
