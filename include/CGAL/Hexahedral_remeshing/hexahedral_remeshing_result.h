// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_REMESHING_RESULT_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_REMESHING_RESULT_H

#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_boundary_groups.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_smoothing.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>
#include <CGAL/Hexahedral_remeshing/integer_grid_map.h>

#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal_np {
enum number_of_hexahedra_t { number_of_hexahedra };
enum hexahedral_smoothing_t { hexahedral_smoothing };
enum integer_grid_map_output_t { integer_grid_map_output };
enum tetrahedron_refinement_t { tetrahedron_refinement };
enum refined_mesh_output_t { refined_mesh_output };
} // namespace internal_np

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// `hexahedral_remeshing()`: approximate number of hexahedra wanted (`std::size_t`); sets the target edge
/// length to `cbrt(volume / n)` unless `target_edge_length` is given.
template <class T> unspecified_type number_of_hexahedra(const T& value);
/// `hexahedral_remeshing()`: untangle and smooth the extracted hex mesh (`bool`, default `true`).
template <class T> unspecified_type hexahedral_smoothing(const T& value);
/// `hexahedral_remeshing()`: receives the integer-grid map the hexahedra come from
/// (`std::reference_wrapper<Integer_grid_map>`, e.g. `std::ref(map)`; default: none kept).
template <class T> unspecified_type integer_grid_map_output(const T& value);
/// `hexahedral_remeshing()`: when the mesh as given has fewer than 12 tetrahedra per hexahedron and gives
/// no valid hex mesh, run again on its red refinement (`refine_tetrahedral_soup()`, once or twice) and
/// keep that hex mesh if it is valid (`bool`, default `true`; never with `prescribed_edge_valences`,
/// whose edges are the input's).
template <class T> unspecified_type tetrahedron_refinement(const T& value);
/// `hexahedral_remeshing()`: receives the refined tetrahedral mesh when the hex mesh comes from it
/// (`Hexahedral_remeshing_result::refinement`; `std::reference_wrapper<Tetrahedral_mesh_3<Traits> >`,
/// e.g. `std::ref(fine)`; untouched otherwise). Its first vertices are those of the input, and the
/// per-element reports (`frame_field`) refer to it.
template <class T> unspecified_type refined_mesh_output(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(number_of_hexahedra)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(hexahedral_smoothing)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(integer_grid_map_output)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(tetrahedron_refinement)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(refined_mesh_output)
#endif
} // namespace parameters

/// \ingroup PkgHexahedralRemeshingRef
/// Overall outcome of `CGAL::hexahedral_remeshing()`.
enum class Hexahedral_remeshing_status {
  /// A valid hex mesh of the whole solid: conforming, closed 2-manifold boundary, no duplicates, every
  /// scaled Jacobian > 0, and no cell left out by the extraction.
  OK,
  /// A hex mesh was produced but it is not valid (inverted hexahedra), or cells are missing where the map
  /// is broken (the mesh does not fill the solid), or its boundary has other components or another
  /// Euler characteristic than the solid's (a cavity where cells were dropped), or its boundary is
  /// more than 5% of the bounding-box diagonal away from the solid's (Hausdorff distance after the
  /// smoothing: a slit along a seam of the map): see `Hexahedral_remeshing_result::check`,
  /// `Hexahedral_remeshing_result::volume_ratio` and the stage reports.
  INVALID_HEX_MESH,
  /// The integer-grid map has no complete integer cell: no hexahedron (the map status says why).
  NO_HEXAHEDRA
};

/// \ingroup PkgHexahedralRemeshingRef
/// Name of a status (`"OK"`, `"INVALID_HEX_MESH"`, `"NO_HEXAHEDRA"`).
inline const char* status_name(Hexahedral_remeshing_status s)
{
  switch(s) {
    case Hexahedral_remeshing_status::OK: return "OK";
    case Hexahedral_remeshing_status::INVALID_HEX_MESH: return "INVALID_HEX_MESH";
    case Hexahedral_remeshing_status::NO_HEXAHEDRA: return "NO_HEXAHEDRA";
  }
  return "UNKNOWN";
}

/// \ingroup PkgHexahedralRemeshingRef
/// Name of an integer-grid map status (`"OK"`, `"INVERTED_TETRAHEDRA"`, ...), as the enumerator is spelled.
inline const char* status_name(Integer_grid_map_status s)
{
  typedef Integer_grid_map_status S;
  switch(s) {
    case S::OK: return "OK";
    case S::DEGENERATE_TETRAHEDRA: return "DEGENERATE_TETRAHEDRA";
    case S::INVERTED_TETRAHEDRA: return "INVERTED_TETRAHEDRA";
    case S::NON_MESHABLE_SINGULARITIES: return "NON_MESHABLE_SINGULARITIES";
    case S::INCONSISTENT_MATCHINGS: return "INCONSISTENT_MATCHINGS";
    case S::SOLVER_FAILURE: return "SOLVER_FAILURE";
    case S::BRANCHED_EDGES: return "BRANCHED_EDGES";
  }
  return "UNKNOWN";
}

/// \ingroup PkgHexahedralRemeshingRef
/// Default visitor of `CGAL::hexahedral_remeshing()`: the hooks of `Frame_field_visitor`, called for the
/// stages of every step: those of `compute_frame_field_pipeline()`, those of `compute_integer_grid_map()`,
/// those of `extract_hexahedra()`, then `"hex smoothing"` and `"check"`.
struct Hexahedral_remeshing_visitor : Frame_field_pipeline_visitor
{
};

/// \ingroup PkgHexahedralRemeshingRef
/// The second run of `CGAL::hexahedral_remeshing()` on the red refinement of a tetrahedral mesh coarser
/// than the hexahedra (named parameter `tetrahedron_refinement`).
struct Tetrahedron_refinement_report
{
  /// Rounds of 1-to-8 refinement of the second run; 0 if there was none (the first run gave a valid
  /// mesh, the mesh has 6 tetrahedra or more per hexahedron, or the refinement is off).
  int rounds = 0;
  /// Tetrahedra of the refined mesh the second run ran on.
  std::size_t tetrahedra = 0;
  /// True if the hex mesh and every report come from the refined mesh (valid there, not on the mesh as given).
  bool used = false;
  /// The status, failed stage and message of the run whose result was not kept.
  std::string other_outcome;
  /// Seconds of the run whose result was not kept (included in `Hexahedral_remeshing_result::seconds`).
  double other_seconds = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// The run of `CGAL::hexahedral_remeshing()` from a second starting field: when the field smoothed from
/// the relaxation gives no valid hex mesh (after the repair's fallbacks and the refinement), everything
/// runs again from the boundary propagation (`Frame_field_initialization`, named parameter
/// `frame_field_initialization` left to `AUTOMATIC`).
struct Frame_field_restart_report
{
  /// True if the second run took place.
  bool tried = false;
  /// True if the hex mesh and every report come from the second run (valid there, not from the relaxation).
  bool used = false;
  /// The status, failed stage and message of the run whose result was not kept.
  std::string other_outcome;
  /// Seconds of the run whose result was not kept (included in `Hexahedral_remeshing_result::seconds`).
  double other_seconds = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Everything `CGAL::hexahedral_remeshing()` computes, stage by stage.
struct Hexahedral_remeshing_result
{
  /// Overall status.
  Hexahedral_remeshing_status status = Hexahedral_remeshing_status::NO_HEXAHEDRA;
  /// One line saying what went wrong (empty when `status` is `OK`).
  std::string message;
  /// The first stage that failed when `status` is not `OK` (empty otherwise): `"frame_field"` (the
  /// field is not locally meshable after the repair), `"seamless_map"` (the map folds before any
  /// rounding), `"rounding"` (the rounded map folds and the repair of the folds could not unfold it),
  /// `"extraction"` (cells of the map could not be completed), `"smoothing"` (hexahedra still
  /// inverted after the untangling), `"check"` (a valid mesh whose boundary differs from the solid's).
  std::string failed_stage;
  /// Why that stage failed, in one line (counts by reason for the frame field).
  std::string failure_reason;
  /// Tetrahedra of the mesh the pipeline ran on (after the preprocessing of the input).
  std::size_t tetrahedra = 0;
  /// True if the hex mesh of the repaired field (the default, `singularity_repair`) was not valid while
  /// the field without the repair gives a valid one: this result, hex mesh and `frame_field` are then
  /// those of the field without the repair (`frame_field.repaired` false).
  bool repair_fallback = false;
  /// True if the hex mesh of the repaired field was not valid while the field repaired without the
  /// sweeps (`repair_sweeps`) gives a valid one: this result, hex mesh and `frame_field` are then those
  /// of the field repaired without the sweeps.
  bool sweep_fallback = false;
  /// True if the hex mesh of the field repaired in rounds (`maximum_repair_rounds`) was not valid while
  /// the field of the first round alone gives a valid one: this result, hex mesh and `frame_field` are
  /// then those of the first round's field. `sweep_fallback` and `repair_fallback` are tried after it,
  /// from one round.
  bool rounds_fallback = false;
  /// With `repair_fallback`, `sweep_fallback` or `rounds_fallback`: the status, failed stage and message
  /// of the run on the repaired field.
  std::string repaired_field_outcome;
  /// The run on the refined tetrahedral mesh, if any (`tetrahedron_refinement`).
  Tetrahedron_refinement_report refinement;
  /// The run from the boundary propagation, if any (`frame_field_initialization`).
  Frame_field_restart_report field_restart;
  /// Valences, constraints, frame field, matchings, singularity graph, realignment.
  Frame_field_pipeline_result frame_field;
  /// Report of the integer-grid map (target edge length used, status, inverted tetrahedra, ...).
  Integer_grid_map_result map;
  /// Independent check of the map from its parameters (edge valences from angle sums, ...).
  Integer_grid_map_check map_check;
  /// Report of the extraction.
  Hexahedral_extraction_result extraction;
  /// True if the hex mesh was untangled and smoothed (not when cells are missing: the mesh is then
  /// reported as extracted).
  bool smoothed = false;
  /// Report of the smoothing (quality before and after, Hausdorff distance to the input boundary).
  Hexahedral_smoothing_report smoothing;
  /// Check of the final hex mesh (conformity, manifoldness, scaled Jacobian, irregular edges).
  Hexahedral_mesh_check check;
  /// Volume of the hex mesh over the volume of the tetrahedral mesh (1 when the hexahedra fill the solid
  /// exactly; curved boundaries make it differ by O(edge length / size)).
  double volume_ratio = 0;
  /// Length of the sharp edges of the input: its boundary edges of prescribed valence other than 2 (a
  /// CAD curve between tangent faces or a seam is not sharp).
  double feature_length = 0;
  /// Share (0..1) of `feature_length` followed by boundary hex edges: hex edges whose endpoints lie on
  /// the sharp edges and whose midpoint is within 10% of their length of them (chords of a curved sharp
  /// edge count), the sharp edges covered where they are that close to such a hex edge.
  double feature_coverage = 0;
  /// Boundary hex edges lying along sharp edges, and how many of them have the prescribed valence
  /// (number of hexahedra around them).
  std::size_t hex_feature_edges = 0;
  /// Hex feature edges with the prescribed valence.
  std::size_t hex_feature_edges_with_prescribed_valence = 0;
  /// Approximate Hausdorff distance between the hex boundary and the input boundary over the bounding
  /// box diagonal (-1 if the smoothing did not run: it computes it).
  double relative_hausdorff_distance = -1;
  /// The boundary groups of the hex mesh (`Hexahedral_mesh_3::boundary_quadrilaterals` and
  /// `feature_edges`, filled from the input's surface patches and feature curves when hexahedra were made).
  Hexahedral_boundary_groups_report boundary_groups;
  /// Seconds of the preprocessing of a C3t3 or surface input (0 for a `Tetrahedral_mesh_3`).
  double preprocessing_seconds = 0;
  /// Seconds of the check and the feature measures.
  double check_seconds = 0;
  /// Seconds of the whole call.
  double seconds = 0;
};

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_REMESHING_RESULT_H
