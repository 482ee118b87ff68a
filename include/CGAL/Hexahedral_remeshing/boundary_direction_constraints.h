// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_DIRECTION_CONSTRAINTS_H
#define CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_DIRECTION_CONSTRAINTS_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/internal/direction_constraints_energy.h>
#include <CGAL/Hexahedral_remeshing/internal/greedy_direction_optimization.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// What `compute_boundary_direction_constraints()` reports. Energies are angles in radians.
struct Boundary_direction_constraints_result
{
  /// `E(n)`: the maximum angle deviation of the unit outward normals, the directions a classic
  /// normal-aligned frame field follows.
  double initial_energy = 0;
  /// `E(v)`: the maximum angle deviation of the computed directions. Below pi/4, a smooth frame
  /// field aligned with them rounds every boundary dihedral angle to the prescribed valence.
  double final_energy = 0;
  /// `E_i(v)` of every boundary triangle.
  std::vector<double> face_energies;
  /// The boundary triangles with `E_i(v) >= pi/4`, increasing (the failures).
  std::vector<std::uint32_t> failed_faces;
  /// Number of accepted updates of a direction (Algorithm 1).
  std::size_t iterations = 0;
  /// Number of triangles taken from the queue (Algorithm 1).
  std::size_t queue_pops = 0;
  /// Number of direction searches (Algorithm 2); the other pops ended at the early exit.
  std::size_t searches = 0;
  /// Number of evaluations of `E_i` inside the searches.
  std::size_t energy_evaluations = 0;
  /// `false` if `maximum_number_of_queue_pops` stopped the optimization before the queue emptied.
  bool converged = true;
  /// Wall-clock time of the computation, in seconds.
  double seconds = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// The dihedral angle `phi(v_i, v_j)` that the directions of the two boundary triangles of boundary
/// edge `e` define, in radians in [0, 2 pi): `phi(v_i, v_j) = pi - atan2(<v_i x v_j, e_ij/|e_ij|>,
/// <v_i, v_j>)` (Desobry et al., Sec. 4.1) with `i = mesh.edge_boundary_triangles(e)[0]`, `j` the
/// second triangle and `e_ij` the half-edge of `i`, from `edge_vertices(e)[1]` to
/// `edge_vertices(e)[0]`. With the unit normals as directions it is the interior dihedral angle.
/// A frame field aligned with the directions gives `e` the valence `round(2 phi / pi)` (modulo 4).
/// \pre `mesh.is_boundary_edge(e)` and `directions.size() == mesh.number_of_boundary_triangles()`
template <class Traits>
double boundary_edge_direction_angle(const Tetrahedral_mesh_3<Traits>& mesh, typename Tetrahedral_mesh_3<Traits>::Index e,
                                     const std::vector<Eigen::Vector3d>& directions)
{
  const auto& ev = mesh.edge_vertices(e);
  const auto& bt = mesh.edge_boundary_triangles(e);
  const auto d = mesh.point(ev[0]) - mesh.point(ev[1]);
  Eigen::Vector3d edge(CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z()));
  edge /= edge.norm();
  const Eigen::Vector3d vi = directions[bt[0]].normalized(), vj = directions[bt[1]].normalized();
  return internal::Boundary_direction_energy::dihedral_angle(vi, vj, edge);
}

/// \ingroup PkgHexahedralRemeshingRef
/// Evaluates the angle deviations of Desobry et al. (Sec. 4.1 and 6.2) of a field of directions:
/// `E_i(v) = max(delta^d_i(v), delta^n_i(v))` per boundary triangle, where `delta^d_i` is the largest
/// deviation of `phi(v_i, v_j)` from `k_ij pi / 2` over the three neighbours (modulo 2 pi for
/// `k_ij >= 5`) and `delta^n_i` the largest angle between `v_i` and the ideal half-edge normals.
///
/// \param mesh the tetrahedral mesh
/// \param valences valence of every edge, indexed by edge (see `compute_boundary_edge_valences()`),
///        0 to 6 on the boundary edges; interior entries are ignored
/// \param directions unit direction per boundary triangle (the normals give `E(n)`)
/// \param face_energies output: `E_i(v)` per boundary triangle
/// \returns `E(v) = max_i E_i(v)`
/// \throws Error if the sizes do not match, Input_error if a boundary valence is outside 0..6.
template <class Traits>
double compute_boundary_direction_deviation(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<int>& valences,
                                            const std::vector<Eigen::Vector3d>& directions,
                                            std::vector<double>& face_energies)
{
  const internal::Boundary_direction_energy energy(mesh, valences, maximum_prescribed_valence);
  if(directions.size() != energy.number_of_faces())
    throw Error("direction constraints: " + std::to_string(directions.size()) + " directions for " +
                std::to_string(energy.number_of_faces()) + " boundary triangles");
  face_energies.resize(energy.number_of_faces());
  double emax = 0;
  for(std::uint32_t i = 0; i < energy.number_of_faces(); ++i) {
    face_energies[i] = energy.face_energy(i, directions);
    emax = (std::max)(emax, face_energies[i]);
  }
  return emax;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Computes the boundary direction constraints of Desobry et al. (Sec. 4): one unit direction `v_i`
/// per boundary triangle such that a smooth frame field aligned with `v` instead of the normals `n`
/// rounds the dihedral angle `phi(v_i, v_j)` of every boundary edge to `k_ij pi / 2`, while `v` stays
/// close to the ideal half-edge normals (the curvature of the boundary).
///
/// The greedy Algorithm 1 starts from the normals and processes a FIFO queue of triangles; each
/// popped triangle gets the direction minimizing its deviation `E_i` with its neighbours fixed,
/// searched on integer points of cubes (Algorithm 2: 26 directions, then refinements around the
/// best), and its neighbours are queued again when it changed. The deviation of a valence of 5 or 6
/// is measured modulo 2 pi (Sec. 6.2). The computation is sequential and deterministic: two runs
/// on the same input give bitwise identical directions. Floating-point arithmetic: the valences,
/// where exactness matters, come from `compute_boundary_edge_valences()`.
///
/// \param mesh the tetrahedral mesh
/// \param valences valence of every edge, indexed by edge (see `compute_boundary_edge_valences()`),
///        0 to 6 on the boundary edges; interior entries are ignored
/// \param directions output: unit direction `v_i` per boundary triangle
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_refinements}
///     \cgalParamDescription{number of refinements of the direction search after its 26 initial
///       directions (each doubles the cube and tests the neighbours of the best point; the angular
///       resolution after `r` refinements is about `2^-r` radians)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`9`, as in the paper}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy_tolerance}
///     \cgalParamDescription{a triangle taken from the queue whose deviation `E_i` is at most this
///       value, in radians, keeps its direction without search. Such a triangle cannot raise `E(v)`
///       above the tolerance, and the search could not do much better anyway: its resolution is
///       about `2^-r`. 0 searches every triangle whose deviation is not exactly 0.}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_number_of_queue_pops}
///     \cgalParamDescription{stop after this many queue pops (the optimization terminates by itself:
///       this is a safety net; `converged` tells whether it was hit). 0: no bound}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `E(n)`, `E(v)`, `E_i(v)`, the triangles with `E_i(v) >= pi/4`, counters and the time.
/// \throws Error if `valences` does not have one entry per edge; Input_error if a boundary valence is
///         outside 0..6; Error if `number_of_refinements` is negative or above 20.
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Boundary_direction_constraints_result
compute_boundary_direction_constraints(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<int>& valences,
                                       std::vector<Eigen::Vector3d>& directions,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto start = std::chrono::steady_clock::now();
  const int refinements = choose_parameter(get_parameter(np, internal_np::number_of_refinements), 9);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::energy_tolerance), 1e-3);
  const std::size_t maximum_pops =
    choose_parameter(get_parameter(np, internal_np::maximum_number_of_queue_pops), std::size_t(0));
  if(refinements < 0 || refinements > 20)
    throw Error("direction constraints: number_of_refinements must be between 0 and 20, got " +
                std::to_string(refinements));

  const internal::Boundary_direction_energy energy(mesh, valences, maximum_prescribed_valence);
  Boundary_direction_constraints_result result;
  directions = energy.normals();
  const std::size_t nf = energy.number_of_faces();
  for(std::uint32_t i = 0; i < nf; ++i)
    result.initial_energy = (std::max)(result.initial_energy, energy.face_energy(i, directions));

  const internal::Greedy_direction_statistics stats =
    internal::greedy_direction_optimization(energy, directions, refinements, tolerance, maximum_pops);
  result.iterations = stats.iterations;
  result.queue_pops = stats.queue_pops;
  result.searches = stats.searches;
  result.energy_evaluations = stats.evaluations;
  result.converged = stats.converged;

  result.face_energies.resize(nf);
  for(std::uint32_t i = 0; i < nf; ++i) {
    const double e = energy.face_energy(i, directions);
    result.face_energies[i] = e;
    result.final_energy = (std::max)(result.final_energy, e);
    if(e >= CGAL_PI / 4) result.failed_faces.push_back(i);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_BOUNDARY_DIRECTION_CONSTRAINTS_H
