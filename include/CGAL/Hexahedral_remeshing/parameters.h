// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_PARAMETERS_H
#define CGAL_HEXAHEDRAL_REMESHING_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Hexahedral_remeshing {

/// Tags of the named parameters of this package (CGAL's own tags live in `CGAL::internal_np`).
namespace internal_np {
enum split_multi_boundary_tetrahedra_t { split_multi_boundary_tetrahedra };
enum split_boundary_chords_t { split_boundary_chords };
enum maximum_tetrahedron_volume_t { maximum_tetrahedron_volume };
enum radius_edge_ratio_t { radius_edge_ratio };
enum preserve_surface_triangles_t { preserve_surface_triangles };
enum valence_heuristic_t { valence_heuristic };
enum prescribed_edge_valences_t { prescribed_edge_valences };
enum prescribed_curve_valences_t { prescribed_curve_valences };
enum number_of_refinements_t { number_of_refinements };
enum energy_tolerance_t { energy_tolerance };
enum maximum_number_of_queue_pops_t { maximum_number_of_queue_pops };
// frame field
enum face_weights_t { face_weights };
enum smoothing_t { smoothing };
enum maximum_smoothing_iterations_t { maximum_smoothing_iterations };
enum smoothing_tolerance_t { smoothing_tolerance };
enum relaxation_tolerance_t { relaxation_tolerance };
enum fixed_frames_t { fixed_frames };
enum tetrahedron_order_t { tetrahedron_order };
enum frame_field_initialization_t { frame_field_initialization };
} // namespace internal_np

/// \ingroup PkgHexahedralRemeshingRef
/// Named parameters of the package.
///
/// Chaining rule (CGAL 5.5 generates the member-function chaining only for its own parameters):
/// - each parameter `p` of this package comes as `p(value)` and as `p(value, np)`, the latter
///   appending to an existing pack `np` (ours or CGAL's):
///   `split_multi_boundary_tetrahedra(false, radius_edge_ratio(1.5))`;
/// - CGAL's own parameters chain as members after ours: `radius_edge_ratio(1.5).verbose(true)`.
namespace parameters {

#define CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(NAME)                                              \
  template <class T>                                                                                \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& value)                    \
  {                                                                                                 \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t>(value);                        \
  }                                                                                                 \
  template <class T, class T2, class Tag2, class Base2>                                             \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t,                                         \
                                  CGAL::Named_function_parameters<T2, Tag2, Base2> >                \
  NAME(const T& value, const CGAL::Named_function_parameters<T2, Tag2, Base2>& np)                  \
  {                                                                                                 \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t,                                \
                                           CGAL::Named_function_parameters<T2, Tag2, Base2> >(value, np); \
  }

#ifdef DOXYGEN_RUNNING
/// Split every tetrahedron with more than one boundary face 1-to-4 at its barycentre (`bool`, default `true`).
template <class T> unspecified_type split_multi_boundary_tetrahedra(const T& value);
/// TetGen: maximum volume of a tetrahedron (`double`, default: no bound).
template <class T> unspecified_type maximum_tetrahedron_volume(const T& value);
/// TetGen: radius-edge ratio bound of the quality refinement (`double`, default `2.0`; 0 disables refinement).
template <class T> unspecified_type radius_edge_ratio(const T& value);
/// TetGen: keep every surface triangle as a boundary face (`bool`, default `false`).
template <class T> unspecified_type preserve_surface_triangles(const T& value);
/// Frame field: weights of the interior faces (`Face_weights`, default `Face_weights::AREA_OVER_DISTANCE`).
template <class T> unspecified_type face_weights(const T& value);
/// Frame field: run the L-BFGS smoothing (`bool`, default `true`).
template <class T> unspecified_type smoothing(const T& value);
/// Frame field: maximum number of L-BFGS iterations (`int`, default 2000).
template <class T> unspecified_type maximum_smoothing_iterations(const T& value);
/// Frame field: relative energy decrease below which the smoothing stops (`double`, default 1e-7).
template <class T> unspecified_type smoothing_tolerance(const T& value);
/// Frame field: relative residual of the relaxation's conjugate gradients (`double`, default 1e-6).
template <class T> unspecified_type relaxation_tolerance(const T& value);
/// Frame field: frames held fixed, as (tetrahedron, rotation) pairs
/// (`std::vector<std::pair<std::size_t, Eigen::Matrix3d> >`, default none).
template <class T> unspecified_type fixed_frames(const T& value);
/// Frame field and realignment: the order in which the solvers number the tetrahedra, a permutation of
/// their indices (`std::vector<std::uint32_t>`; empty: the mesh's own order; default: along a Hilbert
/// curve on meshes of 30,000 tetrahedra or more). The results come back in the mesh's order whatever it is.
template <class T> unspecified_type tetrahedron_order(const T& value);
/// Frame field: the field the smoothing starts from (`Frame_field_initialization`, default
/// `Frame_field_initialization::AUTOMATIC`).
template <class T> unspecified_type frame_field_initialization(const T& value);
/// Split every interior edge joining two boundary vertices at its midpoint (`bool`, default `false`).
template <class T> unspecified_type split_boundary_chords(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(split_boundary_chords)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(face_weights)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(smoothing)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(maximum_smoothing_iterations)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(smoothing_tolerance)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(relaxation_tolerance)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(fixed_frames)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(tetrahedron_order)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(frame_field_initialization)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(split_multi_boundary_tetrahedra)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(preserve_surface_triangles)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(maximum_tetrahedron_volume)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(radius_edge_ratio)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(valence_heuristic)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(prescribed_edge_valences)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(prescribed_curve_valences)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(number_of_refinements)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(energy_tolerance)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(maximum_number_of_queue_pops)
#endif

} // namespace parameters
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_PARAMETERS_H
