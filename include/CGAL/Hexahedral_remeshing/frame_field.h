// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_FRAME_FIELD_H
#define CGAL_HEXAHEDRAL_REMESHING_FRAME_FIELD_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/boundary_propagation.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/relaxation.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/problem.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/smoothing.h>

#include <Eigen/Dense>

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Weights of the interior faces in the smoothness energy.
enum class Face_weights
{
  UNIFORM,            ///< every interior face weighs 1
  AREA_OVER_DISTANCE  ///< face area over the distance of the two tet centroids, normalized to mean 1 (graded meshes)
};

/// \ingroup PkgHexahedralRemeshingRef
/// The field the L-BFGS smoothing starts from.
enum class Frame_field_initialization
{
  /// `RELAXATION` for `compute_frame_field()`; `CGAL::hexahedral_remeshing()` starts from the relaxation
  /// and, if that gives no valid hex mesh, runs again from the boundary propagation.
  AUTOMATIC,
  /// The projected convex relaxation of Ray et al.: the harmonic extension of the boundary's spherical
  /// harmonics, projected to frames.
  RELAXATION,
  /// Every tetrahedron without a boundary face takes the frame of the nearest tetrahedron with one (the
  /// relaxation's frame there; nearest along the tetrahedra's adjacency, by centroid distance). Where the
  /// boundary frames turn around an axis (a torus's tube) the relaxation vanishes near the axis, its
  /// projection is arbitrary and the smoothing can keep a twisted field (the HexMe torus `s16c`: 3
  /// singular curves irregularly around the tube, a map with 145 inverted tetrahedra); the propagated
  /// field has the boundary's pattern on every layer and gives a valid hex mesh there.
  BOUNDARY_PROPAGATION
};

/// \ingroup PkgHexahedralRemeshingRef
/// Default visitor of the frame-field stages: every hook does nothing. Derive from it and pass it
/// with the named parameter `visitor` to follow the progress.
struct Frame_field_visitor
{
  /// Called when a stage starts (`"setup"`, `"initialization"`, `"smoothing"`).
  void start_stage(const std::string& /*stage*/) {}
  /// Called when a stage ends, with its duration in seconds.
  void end_stage(const std::string& /*stage*/, double /*seconds*/) {}
  /// Called after each round of L-BFGS iterations with the smoothness energy and the total
  /// number of iterations so far; the energy never increases from one call to the next.
  void smoothing_progress(double /*energy*/, int /*iterations*/) {}
};

/// \ingroup PkgHexahedralRemeshingRef
/// Outcome of `compute_frame_field()`.
struct Frame_field_result
{
  /// The field the smoothing started from (`RELAXATION` or `BOUNDARY_PROPAGATION`).
  Frame_field_initialization initialization = Frame_field_initialization::RELAXATION;
  /// Smoothness energy `sum_f w_f |q_i - q_j|^2` of the field the smoothing starts from (the projected
  /// relaxation, or its boundary propagation).
  double initial_energy = 0;
  /// Smoothness energy of the returned frames.
  double energy = 0;
  /// Conjugate-gradient iterations of the relaxation.
  int relaxation_iterations = 0;
  /// Final relative residual of the relaxation.
  double relaxation_residual = 0;
  /// L-BFGS iterations of the smoothing.
  int smoothing_iterations = 0;
  /// Seconds spent building the problem.
  double setup_seconds = 0;
  /// Seconds of the relaxation and projection.
  double initialization_seconds = 0;
  /// Seconds of the L-BFGS smoothing.
  double smoothing_seconds = 0;
  /// Total seconds.
  double seconds = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// The order in which `compute_frame_field()` and `realign_frame_field()` number the tetrahedra of
/// `mesh` by default: along a Hilbert curve through their centroids on meshes of 30,000
/// tetrahedra or more (there the solves are memory-bound and neighbours close in memory make their
/// loops about a fifth faster), empty (the mesh's own order) below. Deterministic. Computing it once
/// and passing it to both (named parameter `tetrahedron_order`) saves the second computation
/// (about 1.3 s at a million tetrahedra).
/// \returns a permutation of the tetrahedra's indices, or an empty vector
template <class Traits>
std::vector<std::uint32_t> solver_tetrahedron_order(const Tetrahedral_mesh_3<Traits>& mesh)
{
  return internal::default_solver_order(mesh);
}

namespace internal {

template <class Traits, class NamedParameters>
std::vector<std::uint32_t> solver_order(const Tetrahedral_mesh_3<Traits>& mesh, const NamedParameters& np)
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  if constexpr(is_default_parameter<NamedParameters, internal_np::tetrahedron_order_t>::value)
    return default_solver_order(mesh);
  else
    return std::vector<std::uint32_t>(get_parameter(np, internal_np::tetrahedron_order));
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Computes a smooth octahedral frame field, one frame per tetrahedron, following Ray et al. 2016
/// with the boundary alignment of Desobry et al.: each tetrahedron with a boundary face keeps one
/// axis exactly on that face's direction (the direction constraint `v_i` of
/// `compute_boundary_direction_constraints()`, or the normal for the classic field).
///
/// Stages: convex relaxation in L4 spherical harmonics with exact elimination of the constraints
/// (matrix-free conjugate gradients), projection to the closest frames, then L-BFGS on rotation
/// parameters until the relative decrease of the energy stalls. On meshes of 30,000 tetrahedra or
/// more both solves are preconditioned by an aggregation multigrid, and the tetrahedra are numbered
/// along a Hilbert curve inside the solver (the frames come back in the mesh's order); see the user
/// manual, section "The Linear Solves at Scale". Deterministic: the result does not depend on the
/// number of threads.
///
/// \param mesh the tetrahedral mesh; each tetrahedron must have at most one boundary face
///        (the default preprocessing of `build_tetrahedral_mesh()` ensures it)
/// \param boundary_directions one direction per boundary triangle (need not be unit)
/// \param frames output: one rotation per tetrahedron, its columns are the three axes
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_weights}
///     \cgalParamDescription{weights of the interior faces}
///     \cgalParamType{`Face_weights`}
///     \cgalParamDefault{`Face_weights::AREA_OVER_DISTANCE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{frame_field_initialization}
///     \cgalParamDescription{the field the smoothing starts from (`AUTOMATIC` is `RELAXATION` here)}
///     \cgalParamType{`Frame_field_initialization`}
///     \cgalParamDefault{`Frame_field_initialization::AUTOMATIC`}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing}
///     \cgalParamDescription{run the L-BFGS smoothing after the relaxation}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_smoothing_iterations}
///     \cgalParamDescription{maximum number of L-BFGS iterations}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`2000`}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing_tolerance}
///     \cgalParamDescription{the smoothing stops when an iteration (three iterations together on the
///       meshes where it is preconditioned) decreases the energy by less than this fraction}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-7`}
///   \cgalParamNEnd
///   \cgalParamNBegin{relaxation_tolerance}
///     \cgalParamDescription{relative residual at which the conjugate gradients of the relaxation stop}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-6`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fixed_frames}
///     \cgalParamDescription{tetrahedra whose frame is given and kept: no unknown in the relaxation
///       nor in the smoothing. A tetrahedron with a boundary face must have an axis on its boundary
///       direction. The pipeline uses it near acute edges of valence 1 (see
///       `compute_frame_field_pipeline()`)}
///     \cgalParamType{`std::vector<std::pair<std::size_t, Eigen::Matrix3d> >`, (tetrahedron, rotation) pairs}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{tetrahedron_order}
///     \cgalParamDescription{the order in which the solvers number the tetrahedra (empty: the mesh's
///       own). Compute it once with `solver_tetrahedron_order()` and pass it to `realign_frame_field()` too}
///     \cgalParamType{`std::vector<std::uint32_t>`, a permutation of the tetrahedra}
///     \cgalParamDefault{`solver_tetrahedron_order(mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress callbacks}
///     \cgalParamType{a class with the member functions of `Frame_field_visitor`}
///     \cgalParamDefault{`Frame_field_visitor()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Error if the directions do not match the boundary triangles, a tetrahedron has two
///         boundary faces, a fixed frame is not a rotation, names no tetrahedron of the mesh, or
///         leaves its boundary direction, or the tetrahedron order is not a permutation.
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Frame_field_result compute_frame_field(const Tetrahedral_mesh_3<Traits>& mesh,
                                       const std::vector<Eigen::Vector3d>& boundary_directions,
                                       std::vector<Eigen::Matrix3d>& frames,
                                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  const Face_weights weights = choose_parameter(get_parameter(np, internal_np::face_weights), Face_weights::AREA_OVER_DISTANCE);
  const bool smooth = choose_parameter(get_parameter(np, internal_np::smoothing), true);
  const bool propagate = choose_parameter(get_parameter(np, internal_np::frame_field_initialization),
                                          Frame_field_initialization::AUTOMATIC) ==
                         Frame_field_initialization::BOUNDARY_PROPAGATION;
  const int max_iterations = choose_parameter(get_parameter(np, internal_np::maximum_smoothing_iterations), 2000);
  const double tolerance = choose_parameter(get_parameter(np, internal_np::smoothing_tolerance), 1e-7);
  const double cg_tolerance = choose_parameter(get_parameter(np, internal_np::relaxation_tolerance), 1e-6);
  Frame_field_visitor default_visitor;
  auto& visitor = choose_parameter(get_parameter_reference(np, CGAL::internal_np::visitor), default_visitor);
  const std::vector<std::pair<std::size_t, Eigen::Matrix3d> > no_fixed_frames;
  // a copy: a parameter passed by value comes back from get_parameter_reference() as a temporary
  const std::vector<std::pair<std::size_t, Eigen::Matrix3d> > fixed =
    choose_parameter(get_parameter(np, internal_np::fixed_frames), no_fixed_frames);

  typedef std::chrono::steady_clock Clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  Frame_field_result result;
  const auto start = Clock::now();

  visitor.start_stage("setup");
  auto t = Clock::now();
  const std::vector<std::uint32_t> order = internal::solver_order(mesh, np);
  const internal::Frame_field_problem problem = internal::make_frame_field_problem(
    mesh, boundary_directions,
    weights == Face_weights::UNIFORM ? internal::Face_weighting::UNIFORM : internal::Face_weighting::AREA_OVER_DISTANCE,
    fixed, order);
  // released before the smoothing, whose peak memory it would add to (about 300 bytes per tetrahedron)
  std::unique_ptr<internal::Frame_field_relaxation> relaxation(new internal::Frame_field_relaxation(problem));
  result.setup_seconds = seconds_since(t);
  visitor.end_stage("setup", result.setup_seconds);

  visitor.start_stage("initialization");
  t = Clock::now();
  frames = relaxation->project(
    relaxation->solve(cg_tolerance, 20000, result.relaxation_iterations, result.relaxation_residual));
  relaxation.reset();
  if(propagate) {
    internal::propagate_boundary_frames(problem, internal::tetrahedron_centroids(mesh, problem), frames);
    result.initialization = Frame_field_initialization::BOUNDARY_PROPAGATION;
  }
  result.initial_energy = internal::frame_field_energy(problem, frames);
  result.initialization_seconds = seconds_since(t);
  visitor.end_stage("initialization", result.initialization_seconds);

  result.energy = result.initial_energy;
  if(smooth) {
    visitor.start_stage("smoothing");
    t = Clock::now();
    internal::Frame_field_smoother smoother(problem, frames);
    result.energy = smoother.minimize(max_iterations, tolerance,
                                      [&](double e, int it) { visitor.smoothing_progress(e, it); },
                                      result.smoothing_iterations);
    result.smoothing_seconds = seconds_since(t);
    visitor.end_stage("smoothing", result.smoothing_seconds);
  }
  if(!problem.mesh_tet.empty()) {
    std::vector<Eigen::Matrix3d> in_mesh_order(frames.size());
    for(std::size_t i = 0; i < frames.size(); ++i) in_mesh_order[problem.mesh_tet[i]] = frames[i];
    frames.swap(in_mesh_order);
  }
  result.seconds = seconds_since(start);
  return result;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_FRAME_FIELD_H
