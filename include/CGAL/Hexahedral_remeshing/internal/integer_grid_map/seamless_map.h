// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_MAP_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_MAP_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fixed_variable_solver.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_assembly.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_continuation.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/sanitize.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/stiffening.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/untangle_map.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/wrapped_boundary.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The corner parameters of the scalars `x` (12 per tetrahedron), one array per tetrahedron.
inline void corner_parameters(const Eigen::VectorXd& x, std::vector<std::array<Eigen::Vector3d, 4> >& parameters)
{
  parameters.resize(std::size_t(x.size()) / 12);
  for(std::size_t t = 0; t < parameters.size(); ++t)
    for(int c = 0; c < 4; ++c) parameters[t][std::size_t(c)] = x.segment<3>(Eigen::Index(12 * t + 3 * c));
}

// The seamless map before any rounding (issue 27 step 1; robust_pipeline.md §2): every variable
// continuous, boundary faces on coordinate planes and singular lines on coordinate lines by the
// reduction, transitions by the elimination.
struct Seamless_map
{
  Eigen::VectorXd y;                        // the free variables, snapped to the dyadic grid
  std::size_t inverted_before_untangling = 0; // det J <= 0 (floating) of the energy's minimizer
  std::size_t inverted = 0, degenerate = 0;   // exact orientation of the final seamless map
  std::vector<std::uint32_t> folds;           // its inverted and flat tetrahedra
  std::size_t branched = 0;                   // without a fold: interior edges not turning 3, 4 or 5 quarter turns
  std::size_t wrapped_before_untangling = 0;  // boundary vertices the minimizer wraps the surface around
  std::vector<std::uint32_t> wrapped;         // those of the final seamless map (wrapped_boundary.h)
  bool untangling_ran = false;
  bool unbranching_ran = false;               // the untangled map branched: unbranch() ran
  bool success = true;                        // false if the factorization failed
};

// Where the untangled seamless map `m.y` folds nowhere but branches (an interior edge turned by other than
// 3, 4 or 5 quarter turns), the untangling again from the `minimizer` with every variable free, the
// boundary planes and singular lines too: if the first untangling was `local`, first the variables of
// the tetrahedra one ring around the minimizer's folds, then, if it still branches, every variable;
// the map kept that folds nowhere and branches least, if less than `m.y`. Held where the minimizer put
// them, the planes and lines can leave no room but a map wrapped around an edge: the flange of
// make_parts.py at 87,415 tetrahedra, 3 branched edges beside a bolt hole after the local untangling,
// after a global one with those held as well, none with them free. Freed one ring around its 91 folds,
// 2,326 variables reaching 35,336 tetrahedra through the planes, the untangling ends without a
// branched edge in 8.4 s, against 22 s for the global one; which map comes out is a matter of the
// path, not of the region's size (with 0, 2 or 4 rings none branches, with 3 rings 4 edges do).
template <class Traits>
void unbranch(const Tetrahedral_mesh_3<Traits>& mesh, const Map_geometry& geometry, const std::vector<Eigen::Matrix3d>& frames,
              double s, const Eigen::SparseMatrix<double, Eigen::RowMajor>& P, const Eigen::VectorXd& x0,
              const std::vector<char>& flat, const Eigen::VectorXd& minimizer, bool local, Seamless_map& m)
{
  if(count_non_positive_jacobians(geometry, P * m.y + x0, &flat) > 0) return;
  std::size_t branched = count_branched_edges(mesh, P * m.y + x0);
  if(branched == 0) return;
  m.unbranching_ran = true;
  const std::vector<char> none(std::size_t(P.cols()), 0);
  auto untangle_from_minimizer = [&](const std::vector<char>* where) {
    Eigen::VectorXd z = minimizer;
    untangle_map(geometry, frames, s, P, x0, none, flat, z, where);
    const Eigen::VectorXd x = P * z + x0;
    if(count_non_positive_jacobians(geometry, x, &flat) > 0) return;
    const std::size_t b = count_branched_edges(mesh, x);
    if(b < branched) { m.y = z; branched = b; }
  };
  if(local) {
    const std::vector<char> region = untangling_region(mesh, geometry, P * minimizer + x0, flat, 1);
    untangle_from_minimizer(&region);
  }
  if(branched > 0) untangle_from_minimizer(nullptr);
}

// The minimizer of the map energy with no integer constraint; where it folds, the foldover-free
// untangling of its continuous variables (around the folds, or everywhere if their rings hold more
// than a quarter of the tetrahedra), kept if it folds fewer tetrahedra. The variables that will be
// integer (boundary planes, singular lines, jumps) are held where the minimizer put them: each
// reaches tetrahedra far from the folds (a plane, every tetrahedron on it), and moving them made the
// local untangling a global one (B0: 2 s for 2 folds in a region of 1,413 tetrahedra). Then every
// variable snapped to the dyadic grid (sanitize.h), so that the corner values, and with them the
// exact orientations reported, are those of a map whose transitions hold exactly.
template <class Traits>
Seamless_map compute_seamless_map(const Tetrahedral_mesh_3<Traits>& mesh, const Map_geometry& geometry,
                                  const std::vector<Eigen::Matrix3d>& frames, double s,
                                  const Eigen::SparseMatrix<double, Eigen::RowMajor>& P, const Eigen::VectorXd& x0,
                                  const std::vector<char>& integer_column, const std::vector<char>& flat,
                                  const Eigen::SparseMatrix<double>& H, const Eigen::VectorXd& rhs,
                                  Fixed_variable_solver& solver, bool untangle, int rings)
{
  Seamless_map m;
  solver.set_system(H, rhs);
  if(!solver.solve(m.y)) { m.success = false; m.y = Eigen::VectorXd::Zero(P.cols()); return m; }
  const std::vector<char> none(std::size_t(P.cols()), 0);
  const Eigen::VectorXd x = P * m.y + x0;
  m.inverted_before_untangling = count_non_positive_jacobians(geometry, x);
  if(m.inverted_before_untangling > 0) m.wrapped_before_untangling = wrapped_boundary_vertices(mesh, x).size();
  if(untangle && count_non_positive_jacobians(geometry, x, &flat) > 0) {
    const std::size_t nt = geometry.volumes.size();
    const std::vector<char> region = untangling_region(mesh, geometry, x, flat, rings);
    const bool local = std::size_t(std::count(region.begin(), region.end(), char(1))) <= nt / 4;
    const Eigen::VectorXd minimizer = m.y;
    m.untangling_ran = untangle_map(geometry, frames, s, P, x0, integer_column, flat, m.y, local ? &region : nullptr).ran;
    unbranch(mesh, geometry, frames, s, P, x0, flat, minimizer, local, m);
  }
  snap_to_dyadic_grid(m.y, none);
  const Eigen::VectorXd corners = P * m.y + x0;
  const std::vector<CGAL::Orientation> o = parameter_orientations(corners);
  for(std::size_t t = 0; t < o.size(); ++t) {
    if(o[t] == CGAL::POSITIVE) continue;
    m.folds.push_back(std::uint32_t(t));
    ++(o[t] == CGAL::NEGATIVE ? m.inverted : m.degenerate);
  }
  // every tetrahedron positive is not local injectivity: the untangling can wrap the map around an
  // edge (measured: the flange of make_parts.py at 87,415 tetrahedra, 3 such edges, which the
  // continuation then carries to the integer values)
  if(m.folds.empty()) m.branched = count_branched_edges(mesh, corners);
  else m.wrapped = wrapped_boundary_vertices(mesh, corners);
  return m;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_MAP_H
