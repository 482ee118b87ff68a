// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_REALIGN_FRAME_FIELD_H
#define CGAL_HEXAHEDRAL_REMESHING_REALIGN_FRAME_FIELD_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/frame_field.h>
#include <CGAL/Hexahedral_remeshing/internal/realignment/realignment_system.h>
#include <CGAL/Hexahedral_remeshing/internal/realignment/solve_realignment.h>
#include <CGAL/Hexahedral_remeshing/internal/realignment/break_matching_ties.h>
#include <CGAL/Hexahedral_remeshing/internal/realignment/project_to_rotations.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Outcome of `realign_frame_field()`.
struct Realignment_result
{
  /// Largest `|1 - |E_t^T n_i|_inf|` over the constrained tetrahedra after realignment
  /// (0 when every constrained frame has an axis exactly on its normal).
  double alignment_error = 0;
  /// Largest violation of the linear constraints `n_i^T E_t = v_i^T E_t^old` before projection.
  double constraint_error = 0;
  /// Conjugate-gradient iterations and final relative residual of the linear solve.
  int solver_iterations = 0;
  /// Final relative residual of the linear solve.
  double solver_residual = 0;
  /// Interior faces whose recomputed matching differs from the fixed one (0 expected).
  std::size_t changed_matchings = 0;
  /// Interior faces where the projected frames were as close to another matching as to the fixed one
  /// (two constrained tetrahedra at a 45-degree turn of the normals, a CAD chamfer): one of the two
  /// frames turned by 1e-5 radian towards the fixed matching, so that the frames alone give it.
  std::size_t broken_ties = 0;
  /// Interior edges whose type (regular, valence 3, 5, improper) changed (0 expected).
  std::size_t changed_edges = 0;
  /// Seconds.
  double seconds = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Realigns a frame field with the surface normals while keeping its matchings, hence its
/// singularity graph (Desobry et al., Sec. 3.3, Eq. 4): solves
/// `min sum_f w_f |E'_i - E'_j g_ij|_F^2 + mu sum_t |E'_t - E_t|_F^2` subject to
/// `n_i^T E'_t = v_i^T E_t` for the tetrahedron `t` of each boundary triangle `i` (enforced exactly
/// by elimination: `E'_t = n_i c^T + T Y_t`, `c = E_t^T v_i`, `T` a basis of the plane orthogonal to
/// `n_i`), by matrix-free conjugate gradients (preconditioned by an aggregation multigrid on large meshes) from `E'` = `E`, then projects every matrix to the
/// closest rotation (the constrained column kept exactly on `+-n_i`, a 2D Procrustes for the others).
/// Afterwards the matchings are recomputed and compared with `matchings`, and the singularity graph
/// with the one of `frames`: any difference is reported in the result (never hidden).
///
/// \param mesh the mesh
/// \param frames in: the field of step 2, aligned with `directions`; out: the realigned field
/// \param matchings the matchings of the input field (kept)
/// \param directions the directions `v_i` the input field is aligned with, per boundary triangle
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_weights}
///     \cgalParamDescription{weights of the interior faces, as in `compute_frame_field()`}
///     \cgalParamType{`Face_weights`}
///     \cgalParamDefault{`Face_weights::AREA_OVER_DISTANCE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{relaxation_tolerance}
///     \cgalParamDescription{relative residual at which the conjugate gradients stop}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-5`}
///   \cgalParamNEnd
///   \cgalParamNBegin{tetrahedron_order}
///     \cgalParamDescription{the order in which the solver numbers the tetrahedra (empty: the mesh's
///       own), as in `compute_frame_field()`; the frames come back in the mesh's order}
///     \cgalParamType{`std::vector<std::uint32_t>`, a permutation of the tetrahedra}
///     \cgalParamDefault{`solver_tetrahedron_order(mesh)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Error if the sizes do not match the mesh or the tetrahedron order is not a permutation.
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Realignment_result realign_frame_field(const Tetrahedral_mesh_3<Traits>& mesh, std::vector<Eigen::Matrix3d>& frames,
                                       const Matchings& matchings, const std::vector<Eigen::Vector3d>& directions,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double tolerance = choose_parameter(get_parameter(np, internal_np::relaxation_tolerance), 1e-5);
  const bool uniform = choose_parameter(get_parameter(np, internal_np::face_weights), Face_weights::AREA_OVER_DISTANCE) ==
                       Face_weights::UNIFORM;
  const auto start = std::chrono::steady_clock::now();
  if(frames.size() != mesh.number_of_tetrahedra() || directions.size() != mesh.number_of_boundary_triangles() ||
     matchings.face_matching.size() != mesh.number_of_faces())
    throw Error("realign_frame_field: frames, matchings or directions do not match the mesh");
  const std::vector<Eigen::Vector3d> normals = boundary_triangle_unit_normals(mesh);
  const Singularity_graph graph_before = compute_singularity_graph(mesh, frames, matchings);

  Realignment_result result;
  {
    const internal::Realignment_system<Traits> system(mesh, frames, matchings, directions, normals, uniform, np);
    const std::vector<Eigen::Matrix3d> E =
      internal::solve_realignment(system, frames, tolerance, result.solver_iterations, result.solver_residual);
    internal::project_to_rotations(system, E, normals, directions, frames, result.constraint_error,
                                   result.alignment_error);
  }
  // Post-checks: matchings and singular graph must be unchanged; ties broken first (break_matching_ties.h)
  Matchings after = compute_matchings(mesh, frames);
  std::vector<std::size_t> disagreeing;
  for(std::size_t f = 0; f < after.face_matching.size(); ++f)
    if(after.face_matching[f] != matchings.face_matching[f]) disagreeing.push_back(f);
  std::vector<std::size_t> turned = internal::break_matching_ties(mesh, frames, matchings, disagreeing);
  result.broken_ties = turned.size();
  if(!turned.empty()) {
    after = compute_matchings(mesh, frames);
    // the turned frames' axes left their normals by 1e-5 radian at most
    std::sort(turned.begin(), turned.end());
    for(std::size_t b = 0; b < normals.size(); ++b) {
      const std::size_t t = std::size_t(mesh.boundary_triangle_tetrahedron(typename Tetrahedral_mesh_3<Traits>::Index(b)));
      if(!std::binary_search(turned.begin(), turned.end(), t)) continue;
      const Eigen::Vector3d c = frames[t].transpose() * normals[b];
      result.alignment_error = (std::max)(result.alignment_error, std::abs(1.0 - c.cwiseAbs().maxCoeff()));
    }
  }
  for(std::size_t f = 0; f < after.face_matching.size(); ++f)
    result.changed_matchings += after.face_matching[f] != matchings.face_matching[f];
  const Singularity_graph graph_after = compute_singularity_graph(mesh, frames, matchings);
  for(std::size_t e = 0; e < graph_after.edge_valence.size(); ++e)
    result.changed_edges += graph_after.edge_valence[e] != graph_before.edge_valence[e];
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_REALIGN_FRAME_FIELD_H
