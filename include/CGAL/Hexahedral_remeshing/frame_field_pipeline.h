// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_FRAME_FIELD_PIPELINE_H
#define CGAL_HEXAHEDRAL_REMESHING_FRAME_FIELD_PIPELINE_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_direction_constraints.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>
#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/frame_field.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/local_meshability.h>
#include <CGAL/Hexahedral_remeshing/realign_frame_field.h>
#include <CGAL/Hexahedral_remeshing/repair_singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/acute_edge_frames.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_realigned_field.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>

#include <Eigen/Dense>

#include <chrono>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal_np {
enum baseline_t { baseline };
enum realignment_t { realignment };
enum acute_edge_band_radius_t { acute_edge_band_radius };
} // namespace internal_np

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// Pipeline: align the frame field with the normals, without valences nor constraints (the classic
/// field the paper compares against) (`bool`, default `false`).
template <class T> unspecified_type baseline(const T& value);
/// Pipeline: realign the field with the normals after the frame field (`bool`, default `true`).
template <class T> unspecified_type realignment(const T& value);
/// Pipeline: radius of the band around the acute edges of valence 1 where the frames are held fixed
/// (`double`, model units, default 0: no band; `hexahedral_remeshing()` uses twice the hex edge length).
template <class T> unspecified_type acute_edge_band_radius(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(baseline)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(realignment)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(acute_edge_band_radius)
#endif
} // namespace parameters

/// \ingroup PkgHexahedralRemeshingRef
/// Default visitor of the pipeline: the hooks of `Frame_field_visitor`, called for every stage of
/// the pipeline (`"valences"`, `"constraints"`, `"setup"`, `"initialization"`, `"smoothing"`,
/// `"matchings"`, `"realignment"`, `"repair"`), in this order (`"smoothing"`, `"realignment"` and
/// `"repair"` only when they run).
struct Frame_field_pipeline_visitor : Frame_field_visitor
{
};

/// \ingroup PkgHexahedralRemeshingRef
/// Everything the frame-field pipeline computes, stage by stage.
struct Frame_field_pipeline_result
{
  /// True if the field is the classic normal-aligned one (named parameter `baseline`).
  bool baseline = false;
  /// True if the field was realigned with the normals.
  bool realigned = false;
  /// Prescribed valence of every edge (-1 for interior edges); the geometric classes for the baseline.
  std::vector<int> valences;
  /// Histogram of the prescribed valences.
  Boundary_edge_valences_statistics valence_statistics;
  /// The directions the field of step 2 is aligned with, per boundary triangle (`v`, or the normals).
  std::vector<Eigen::Vector3d> directions;
  /// Report of the direction constraints (`E(n)`, `E(v)`, failures); for the baseline `E(v) = E(n)`.
  Boundary_direction_constraints_result constraints;
  /// The frames, one per tetrahedron (realigned unless `realignment(false)` or baseline).
  std::vector<Eigen::Matrix3d> frames;
  /// The frames held fixed by the solver near acute edges of valence 1, (tetrahedron, rotation)
  /// pairs sorted by tetrahedron (named parameter `acute_edge_band_radius`).
  std::vector<std::pair<std::size_t, Eigen::Matrix3d> > fixed_frames;
  /// Boundary directions turned within 3 band radii of those edges (`constraints` then reports the
  /// deviation of the turned directions).
  std::size_t redirected_directions = 0;
  /// Report of the frame-field solver.
  Frame_field_result frame_field;
  /// Matchings of the field of step 2 (kept by the realignment), repaired if the repair was accepted.
  Matchings matchings;
  /// Singularity graph of the field of step 2; after an accepted repair, of the returned frames with
  /// the repaired matchings.
  Singularity_graph singularities;
  /// Local meshability check of the field of step 2 with its closest matchings, before the repair
  /// (feature sectors from `boundary_valences`; no disagreeing face, by construction).
  Local_meshability_report meshability_before;
  /// Report of the repair of the singularity graph (named parameter `singularity_repair`).
  Singularity_repair_result repair;
  /// True if the repair ran.
  bool repaired = false;
  /// Local meshability check of the returned frames with the kept matchings (the normals for the
  /// feature sectors once realigned).
  Local_meshability_report meshability;
  /// Valences of the boundary edges produced by the field, compared with `valences`.
  Boundary_valences boundary_valences;
  /// Report of the realignment (if any).
  Realignment_result realignment;
  /// Seconds of the valence stage.
  double valences_seconds = 0, constraints_seconds = 0, matchings_seconds = 0, seconds = 0;
};

/// \var Frame_field_pipeline_result::constraints_seconds
/// Seconds of the direction constraint stage (the frame-field stages are timed in `frame_field`,
/// the realignment in `realignment`).

/// \var Frame_field_pipeline_result::matchings_seconds
/// Seconds of the matchings, the singularity graph and the achieved boundary valences.

/// \var Frame_field_pipeline_result::seconds
/// Seconds of the whole pipeline.

/// \ingroup PkgHexahedralRemeshingRef
/// The frame-field half of the hexahedral remeshing pipeline of Desobry et al.: boundary edge
/// valences (heuristic or prescribed), boundary direction constraints `v` (Algorithms 1 and 2),
/// smooth frame field aligned with `v` (Ray et al.), matchings and singularity graph, achieved
/// boundary valences, then realignment with the normals keeping the matchings.
///
/// \param mesh the tetrahedral mesh (built with the default preprocessing, possibly with
///        `split_boundary_chords(true)`, recommended for acute features)
/// \param np an optional sequence of named parameters: those of `compute_boundary_edge_valences()`
///        (`valence_heuristic`, `prescribed_edge_valences`, `prescribed_curve_valences`), of
///        `compute_boundary_direction_constraints()` (`number_of_refinements`, ...), of
///        `compute_frame_field()` (`face_weights`, `smoothing`, ...), and:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{baseline}
///     \cgalParamDescription{align with the normals and skip valences and constraints: the classic field}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{realignment}
///     \cgalParamDescription{realign the field with the normals (paper Sec. 3.3)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{singularity_repair}
///     \cgalParamDescription{repair the singularity graph by matching surgery (`repair_singularity_graph()`,
///       with `maximum_repair_steps` if given). After the realignment, the surgery uses the realigned frames,
///       the frames are re-optimized with the repaired matchings fixed (the realignment's solver), and the
///       result is kept only if it is no worse with the kept matchings and from the frames alone, and
///       better in one, and the non-meshable locations the map reports of it (improper edges, dangling ends,
///       zippers of `compute_singularity_graph()`) do not grow (`Singularity_repair_result::accepted`); rounds of
///       this follow, each from the field the last one kept, until one is not kept (`maximum_repair_rounds`,
///       `Singularity_repair_result::rounds`); without realignment, the matchings of the
///       field of step 3 are repaired in place}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`, except with `baseline(true)` (the paper's comparison field, kept as it is)}
///   \cgalParamNEnd
///   \cgalParamNBegin{acute_edge_band_radius}
///     \cgalParamDescription{radius, in model units, of a band around the boundary edges of prescribed
///       valence 1 whose dihedral angle is below pi/4 (exact class 0), where the frames are held fixed
///       to the frame of the one hexahedron spanning the wedge (the edge and the directions `v` of its
///       two triangles); the directions within the radius become axes of that frame and those up to 3
///       radius turn partly towards them. Without it, the smoothing pulls the singular curve of the
///       wedge's cross-section onto the edge (a 10-degree wedge: through the edge's vertices at every
///       tetrahedron size), where no integer-grid map can keep the wedge's faces apart. The band needs
///       tetrahedra smaller than the wedge is thick at the radius to hold the curve off the faces.
///       0: no band. No effect on the baseline (it never prescribes valence 1 below pi/4)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress callbacks, for every stage}
///     \cgalParamType{a class with the member functions of `Frame_field_visitor`}
///     \cgalParamDefault{`Frame_field_pipeline_visitor()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Input_error for impossible prescriptions; Error if a stage cannot run.
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Frame_field_pipeline_result compute_frame_field_pipeline(const Tetrahedral_mesh_3<Traits>& mesh,
                                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  typedef std::chrono::steady_clock Clock;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  Frame_field_pipeline_visitor default_visitor;
  auto& visitor = choose_parameter(get_parameter_reference(np, CGAL::internal_np::visitor), default_visitor);

  Frame_field_pipeline_result r;
  r.baseline = choose_parameter(get_parameter(np, internal_np::baseline), false);
  const bool realign = !r.baseline && choose_parameter(get_parameter(np, internal_np::realignment), true);
  const auto start = Clock::now();

  visitor.start_stage("valences");
  auto t = Clock::now();
  if(r.baseline)
    r.valence_statistics = compute_boundary_edge_valences(mesh, r.valences,
                                                          parameters::valence_heuristic(Valence_heuristic::GEOMETRIC));
  else
    r.valence_statistics = compute_boundary_edge_valences(mesh, r.valences, np);
  r.valences_seconds = seconds_since(t);
  visitor.end_stage("valences", r.valences_seconds);

  visitor.start_stage("constraints");
  t = Clock::now();
  if(r.baseline) {
    r.directions = boundary_triangle_unit_normals(mesh);
    r.constraints.initial_energy = r.constraints.final_energy =
      compute_boundary_direction_deviation(mesh, r.valences, r.directions, r.constraints.face_energies);
    for(std::uint32_t i = 0; i < r.constraints.face_energies.size(); ++i)
      if(r.constraints.face_energies[i] >= CGAL_PI / 4) r.constraints.failed_faces.push_back(i);
  } else {
    r.constraints = compute_boundary_direction_constraints(mesh, r.valences, r.directions, np);
  }
  r.constraints_seconds = seconds_since(t);
  visitor.end_stage("constraints", r.constraints_seconds);

  const double band = choose_parameter(get_parameter(np, internal_np::acute_edge_band_radius), 0.);
  if(!(band >= 0) || !std::isfinite(band))
    throw Input_error(mesh.source(), 0, "acute_edge_band_radius must be a finite number >= 0, got " + std::to_string(band));
  if(!r.baseline && band > 0) {
    r.fixed_frames = internal::acute_edge_band(mesh, r.valences, r.directions, band, r.redirected_directions);
    if(r.redirected_directions > 0) {
      // the report describes the directions the field follows
      r.constraints.final_energy =
        compute_boundary_direction_deviation(mesh, r.valences, r.directions, r.constraints.face_energies);
      r.constraints.failed_faces.clear();
      for(std::uint32_t i = 0; i < r.constraints.face_energies.size(); ++i)
        if(r.constraints.face_energies[i] >= CGAL_PI / 4) r.constraints.failed_faces.push_back(i);
    }
  }
  // one order of the tets for both solvers
  const std::vector<std::uint32_t> order = solver_tetrahedron_order(mesh);
  r.frame_field = compute_frame_field(mesh, r.directions, r.frames,
                                      parameters::tetrahedron_order(order, parameters::fixed_frames(r.fixed_frames, np)));

  visitor.start_stage("matchings");
  t = Clock::now();
  r.matchings = compute_matchings(mesh, r.frames);
  r.singularities = compute_singularity_graph(mesh, r.frames, r.matchings);
  r.boundary_valences = compute_achieved_boundary_valences(mesh, r.frames, r.matchings, r.directions, r.valences);
  // the matchings are the frames' closest: no face disagrees; the boundary valences are those above
  r.meshability_before = internal::local_meshability(mesh, r.frames, r.matchings, &r.boundary_valences.achieved, r.valences, false);
  r.matchings_seconds = seconds_since(t);
  visitor.end_stage("matchings", r.matchings_seconds);

  if(realign) {
    visitor.start_stage("realignment");
    r.realignment = realign_frame_field(mesh, r.frames, r.matchings, r.directions,
                                        parameters::tetrahedron_order(order,
                                          parameters::face_weights(choose_parameter(get_parameter(np, internal_np::face_weights),
                                                                                    Face_weights::AREA_OVER_DISTANCE))));
    r.realigned = true;
    visitor.end_stage("realignment", r.realignment.seconds);
  }
  if(choose_parameter(get_parameter(np, internal_np::singularity_repair), !r.baseline)) {
    visitor.start_stage("repair");
    if(r.realigned) {
      r.repair = internal::repair_realigned_field(mesh, r.frames, r.matchings, r.singularities, r.valences, np,
                   parameters::tetrahedron_order(order, parameters::face_weights(
                     choose_parameter(get_parameter(np, internal_np::face_weights), Face_weights::AREA_OVER_DISTANCE))));
    } else {
      r.repair = repair_singularity_graph(mesh, r.frames, r.matchings, r.directions, np);
      // an unchanged field keeps its graph bitwise
      if(r.repair.accepted) r.singularities = compute_singularity_graph(mesh, r.frames, r.matchings);
    }
    r.repaired = true;
    visitor.end_stage("repair", r.repair.seconds);
  }
  r.meshability = check_local_meshability(mesh, r.frames, r.matchings, r.valences,
                                          r.realigned ? boundary_triangle_unit_normals(mesh) : r.directions);
  r.seconds = seconds_since(start);
  return r;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_FRAME_FIELD_PIPELINE_H
