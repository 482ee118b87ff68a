// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTEGER_GRID_MAP_FUNCTION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTEGER_GRID_MAP_FUNCTION_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/integer_grid_map_impl.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/jog_refinement.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal_np {
enum target_edge_length_t { target_edge_length };
enum maximum_stiffening_iterations_t { maximum_stiffening_iterations };
enum untangling_t { untangling };
enum quantization_t { quantization };
enum quantization_time_limit_t { quantization_time_limit };
enum seamless_map_parameters_t { seamless_map_parameters };
enum jog_refinement_t { jog_refinement };
enum singular_vertex_relocation_t { singular_vertex_relocation };
enum maximum_continuation_steps_t { maximum_continuation_steps };
} // namespace internal_np

/// \ingroup PkgHexahedralRemeshingRef
/// How `compute_integer_grid_map()` makes the integer values of the map (named parameter
/// `quantization`), and which way made it (`Integer_grid_map_result::quantization`).
enum class Integer_grid_map_quantization {
  /// Greedy rounding checked on the motorcycle complex when the seamless map is injective (see
  /// `MOTORCYCLE_COMPLEX`), then, if the map still folds, the separation program where it folds; a
  /// program's map is kept if it does not fold (as a parameter: the default).
  AUTOMATIC,
  /// Greedy mixed-integer rounding only (one variable batch at a time, re-solving in between).
  GREEDY_ROUNDING,
  /// The motorcycle complex of the injective seamless map checks the rounded values (every block
  /// extent >= 0, >= 1 between boundary sheets or curves) and, if they break one or fold the map, its
  /// integer program chooses them (as a parameter: without the separation program afterwards).
  /// (reported) The map of the complex's program, which did not fold.
  MOTORCYCLE_COMPLEX,
  /// (reported) The map of the separation program: the rounded map folded, and the integer program
  /// that keeps apart the entities it collapsed around the folds gave a map without folds (as a
  /// parameter: greedy rounding and the separation program, without the motorcycle complex).
  SEPARATION_PROGRAM
};

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// Integer-grid map: edge length of the hexahedra in model units (`double` > 0, default: the length
/// that gives about 2000 unit cells of parameter volume, `cbrt(volume / 2000)`).
template <class T> unspecified_type target_edge_length(const T& value);
/// Integer-grid map: maximum number of stiffening rounds when tetrahedra are inverted (`int`, default 20).
template <class T> unspecified_type maximum_stiffening_iterations(const T& value);
/// Integer-grid map: run the foldover-free untangling when tetrahedra remain inverted (`bool`, default `true`).
template <class T> unspecified_type untangling(const T& value);
/// Integer-grid map: `Integer_grid_map_quantization::AUTOMATIC` (default) or `GREEDY_ROUNDING`.
template <class T> unspecified_type quantization(const T& value);
/// Integer-grid map: seconds the separation programs may take together (`double`, default 60).
template <class T> unspecified_type quantization_time_limit(const T& value);
/// Integer-grid map: receives the corner parameters of the seamless map, before any rounding
/// (`std::vector<std::array<Eigen::Vector3d, 4> >*`, one array per tetrahedron; default none).
template <class T> unspecified_type seamless_map_parameters(const T& value);
/// Integer-grid map: split the edges that close singular jogs before the map (`bool`, default `false`).
template <class T> unspecified_type jog_refinement(const T& value);
/// Integer-grid map: move the interior vertices of the singular curves towards their holonomy axes
/// before the map (`bool`, default `false`).
template <class T> unspecified_type singular_vertex_relocation(const T& value);
/// Integer-grid map: steps of the continuation from the seamless map when the quantized map folds or
/// branches (`int` >= 0, default 60; 0: none).
template <class T> unspecified_type maximum_continuation_steps(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(target_edge_length)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(maximum_stiffening_iterations)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(untangling)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(quantization)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(quantization_time_limit)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(seamless_map_parameters)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(jog_refinement)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(singular_vertex_relocation)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(maximum_continuation_steps)
#endif
} // namespace parameters

/// \ingroup PkgHexahedralRemeshingRef
/// The folded (inverted or flat) tetrahedra of the seamless map by what they say of the stage that must
/// change, each in the first class that fits (`Integer_grid_map_result::seamless_fold_causes`).
struct Seamless_fold_causes
{
  /// Flat in every map that respects the constraints (`structurally_flat_tetrahedra`), with a boundary
  /// face: the constraints put its corners on one line or plane (two feature curves of one parameter
  /// line, a boundary sheet that meets itself); another field or another mesh is needed.
  std::size_t structural_at_boundary = 0;
  /// Flat in every map, inside: three corners on one singular line (a curve jogging inside a face).
  std::size_t structural_inside = 0;
  /// A corner at a defect of the field's graph: an end of a jog or improper edge, a dangling end, a zipper.
  std::size_t at_field_defects = 0;
  /// Other tetrahedra with a corner on the boundary.
  std::size_t at_boundary = 0;
  /// The others.
  std::size_t inside = 0;
  /// Their sum: the size of `Integer_grid_map_result::seamless_folds`.
  std::size_t total() const { return structural_at_boundary + structural_inside + at_field_defects + at_boundary + inside; }
};

/// \ingroup PkgHexahedralRemeshingRef
/// Outcome of `compute_integer_grid_map()`, the most serious first.
enum class Integer_grid_map_status {
  /// Every tetrahedron keeps its orientation in parameter space: the map is locally injective.
  OK,
  /// The map is valid but some tetrahedra are flat in parameter space (collapsed singular jogs).
  DEGENERATE_TETRAHEDRA,
  /// Some tetrahedra are inverted in parameter space after rounding, stiffening and untangling.
  INVERTED_TETRAHEDRA,
  /// The singularity graph is not hex-meshable (improper edges, dangling curve ends, 3-5 zippers);
  /// the map is computed anyway (see `Integer_grid_map_result::defects`).
  NON_MESHABLE_SINGULARITIES,
  /// The matchings contradict the cut or the constraints (sign contradictions, inconsistent rows).
  INCONSISTENT_MATCHINGS,
  /// The sparse factorization failed.
  SOLVER_FAILURE,
  /// Every tetrahedron is positively oriented, but around some interior edges the parameter angles
  /// do not sum to 3, 4 or 5 quarter turns (`Integer_grid_map_result::branched_edges`): the map is
  /// not locally injective there (the untangling can leave a valence-5 curve at valence 1 beside a
  /// regular edge at valence 8); the hexahedra there are broken unless the branch holds no integer point.
  BRANCHED_EDGES
};

/// \ingroup PkgHexahedralRemeshingRef
/// A location where the frame field is not hex-meshable, taken from the singularity graph.
struct Integer_grid_map_defect
{
  /// Kind of defect.
  enum Kind {
    /// An interior edge with a holonomy that is not a quarter turn along it (`index`: edge).
    IMPROPER_EDGE,
    /// An interior vertex where a singular curve ends (`index`: vertex).
    DANGLING_END,
    /// An interior vertex where a valence-3 curve turns into a valence-5 curve (`index`: vertex).
    ZIPPER
  };
  /// The kind.
  Kind kind = IMPROPER_EDGE;
  /// The edge or vertex index in the map's tetrahedral mesh (the input mesh with the jog edges split:
  /// its first vertices are the input's).
  std::uint32_t index = 0;
  /// Position (model units): the vertex, or the edge midpoint.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

/// \ingroup PkgHexahedralRemeshingRef
/// The motorcycle complex of the seamless map and its integer program (issue 27; robust_pipeline.md
/// §3): walls traced exactly from every singular and feature curve of the injective seamless map, in
/// order of parametric distance; the blocks' extents as functions of the integer variables.
struct Integer_grid_map_complex
{
  /// True if the complex was traced (the seamless map is injective, the walls stopped in time).
  bool traced = false;
  /// Why it was not traced, or how its program ended.
  std::string reason;
  /// Blocks of the complex (not reduced).
  std::size_t blocks = 0;
  /// Patches (block faces).
  std::size_t patches = 0;
  /// Arcs (patch edges).
  std::size_t arcs = 0;
  /// Nodes (arc ends).
  std::size_t nodes = 0;
  /// Tetrahedra of the map's mesh once split by the walls.
  std::size_t split_tetrahedra = 0;
  /// Edges split by the walls.
  std::size_t split_edges = 0;
  /// Block extents in the program (a block's length along one axis of its chart).
  std::size_t extents = 0;
  /// Extents kept >= 1 (two boundary sides, two curves, or zero at a fold).
  std::size_t separated_extents = 0;
  /// Chains of blocks stacked along one direction, all of zero extent, between two sides that must stay
  /// apart (QGP3D's zero-length paths), kept >= 1 in sum.
  std::size_t separated_paths = 0;
  /// Extents left out (a side whose position is unknown, a block that is not a box).
  std::size_t skipped_extents = 0;
  /// Folded tetrahedra of the rounded map.
  std::size_t folds_after_rounding = 0;
  /// Folded tetrahedra of the last program's map (its linear map, before any untangling).
  std::size_t folds_after_program = 0;
  /// True if the last program's lengths were re-embedded: the quantized map still folded after its
  /// repair (stiffening, untangling) and the program had given other lengths, which were held and
  /// repaired the same way; the map with fewer folds is kept (`quantization` says which).
  bool reembedded = false;
  /// Folded tetrahedra (the structurally flat ones left out) of the quantized map after its repair,
  /// and of the program's re-embedded map after its repair (equal if not re-embedded).
  std::size_t folds_after_repair_quantized = 0;
  /// See `folds_after_repair_quantized`.
  std::size_t folds_after_repair_program = 0;
  /// Integer variables of the last program.
  std::size_t program_variables = 0;
  /// Constraints of the last program.
  std::size_t program_constraints = 0;
  /// Programs solved (0: the rounded values kept every block and did not fold).
  int programs = 0;
  /// Objective of the last program.
  double objective = 0;
  /// Seconds of the tracing (with the extents).
  double seconds = 0;
  /// Seconds of the programs (Cbc).
  double program_seconds = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// The quantized map reached from the seamless map without a fold (issue 27, the re-embedding). When the
/// quantized map folds (or branches: every tetrahedron positive, but the map turns around an interior edge
/// by a number of quarter turns other than 3, 4 or 5), the local untangling of its folds leaves a fold or a
/// branch, and the seamless map folds nowhere (the structurally flat tetrahedra left out), the seamless
/// map is moved to the quantized integer values in steps: along the
/// linear response to the change of the integer values, each step halved until no tetrahedron folds, then
/// relaxed by the foldover-free energy's barrier where the map is thin (det J below a tenth of the
/// target's, and two rings around). When the quantizer kept values other than the motorcycle
/// complex's program's lengths (their linear map folded more), those lengths, which admit a valid map
/// (QGP3D), are the first target and the quantized values the second. The angle sum around an edge changes only when a tetrahedron of its ring
/// goes through zero volume, so the map reached turns around every edge as the seamless map does, which the
/// repair of the folds (the untangling) does not ensure: it runs only if the continuation was not kept.
struct Integer_grid_map_continuation
{
  /// True if it ran (the quantized map folded or branched, the seamless map did neither).
  bool ran = false;
  /// True if the integer values were reached (else the steps ran out or became too short).
  bool reached = false;
  /// True if the map reached, with no fold and no branched edge, replaced the quantized map (no repair
  /// of the folds then runs).
  bool kept = false;
  /// True if the last target was the complex's program's lengths (kept: `quantization` is then
  /// `MOTORCYCLE_COMPLEX`); false if it was the quantized values (the lengths were not reached, or the
  /// quantizer kept them).
  bool program_lengths = false;
  /// Steps taken, and steps halved because the map would have folded (both targets together).
  int steps = 0;
  /// See `steps`.
  int halvings = 0;
  /// How far the map got from the seamless values (0) to the integer ones (1).
  double parameter = 0;
  /// Folded tetrahedra (`det J <= 0`, the structurally flat ones left out) and branched edges of the
  /// quantized map (branched edges counted only without folds).
  std::size_t folds_before = 0;
  /// See `folds_before`.
  std::size_t branched_before = 0;
  /// Folded tetrahedra and branched edges of the map reached (if reached).
  std::size_t folds_after = 0;
  /// See `folds_after`.
  std::size_t branched_after = 0;
  /// Seconds.
  double seconds = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Report of `compute_integer_grid_map()`.
struct Integer_grid_map_result
{
  /// Overall status.
  Integer_grid_map_status status = Integer_grid_map_status::OK;
  /// Tetrahedra whose four parameter points are negatively oriented (exact `CGAL::orientation`).
  std::size_t inverted_tetrahedra = 0;
  /// Tetrahedra whose four parameter points are coplanar (exact).
  std::size_t degenerate_tetrahedra = 0;
  /// Interior edges away from inverted and flat tetrahedra whose parameter angle sum is not 3, 4 or 5
  /// quarter turns (`Integer_grid_map_check::unusual_interior_edges` of the map): the field's
  /// singular edges have valence 3 or 5 and its regular ones 4, so the map is branched there
  /// (status `BRANCHED_EDGES` unless a worse one applies).
  std::size_t branched_edges = 0;
  /// Minimum over the tetrahedra of `det J_t / s^3` (1 for a perfect map at the target size).
  double min_relative_jacobian = 0;
  /// Hex edge length used (model units); `s = 1 / target_edge_length`.
  double target_edge_length = 0;
  /// Edges of the input mesh split at their midpoints before the map (named parameter
  /// `jog_refinement`): the third edge of each face whose two other edges are singular. The map's
  /// mesh (`Integer_grid_map::points`, `tetrahedra`) is the input mesh with these splits; its first
  /// vertices are the input's.
  std::size_t split_jog_edges = 0;
  /// Interior vertices of singular curves moved towards their curves' holonomy axes before the map
  /// (named parameter `singular_vertex_relocation`; the map's mesh has them at their new positions,
  /// the boundary is unchanged), and the jogs (singular edges more than 45 degrees off their axis)
  /// of the map's mesh before and after the moves.
  std::size_t relocated_vertices = 0;
  /// Jogs before the relocation.
  std::size_t relocation_jogs_before = 0;
  /// Jogs after the relocation.
  std::size_t relocation_jogs_after = 0;
  /// Tetrahedra of the map's mesh (the input's, more if jog edges were split).
  std::size_t map_tetrahedra = 0;
  /// Interior faces of the cut (faces with an unknown integer jump).
  std::size_t cut_faces = 0;
  /// Free variables of the reduced problem, and how many of them are integer.
  std::size_t variables = 0;
  /// Integer variables of the reduced problem (boundary planes, singular lines, seam jumps).
  std::size_t integer_variables = 0;
  /// Solves of the greedy rounding (one numeric factorization each).
  int rounding_rounds = 0;
  /// Largest distance to an integer of a variable when it was rounded.
  double max_rounding = 0;
  /// Tetrahedra with `det J <= 0` (floating point) in the minimizer of the seamless map (every
  /// variable continuous), before its untangling.
  std::size_t relaxed_inverted_tetrahedra = 0;
  /// The seamless map before any rounding, after its untangling and snapping: tetrahedra whose
  /// parameter points are negatively oriented (exact `CGAL::orientation`).
  std::size_t seamless_inverted_tetrahedra = 0;
  /// The seamless map: tetrahedra whose parameter points are coplanar (exact; includes the
  /// structurally flat ones, which no seamless map with these constraints can open).
  std::size_t seamless_degenerate_tetrahedra = 0;
  /// The seamless map without a fold: interior edges whose ring's parameter-space dihedral angles sum
  /// to a number of quarter turns other than 3, 4 or 5 (the untangling wrapped the map around them).
  /// Not counted where some tetrahedron folds.
  std::size_t seamless_branched_edges = 0;
  /// Where the seamless map folds: its boundary vertices around which it wraps the boundary surface
  /// (vertex indices of the map's mesh). At a boundary vertex of a hex mesh, the parameter angles of the
  /// vertex's boundary triangles (negative where the tetrahedron is inverted) sum to a positive number of
  /// quarter turns, 3, 4 or 5 on a smooth part of the surface; a sum of 0 or less, or on a smooth part one
  /// other than 3, 4 or 5, is listed. The untangling changes such a winding only through a degenerate
  /// triangle, and seldom does (the energy's minimizer is wrapped already, `relaxed_wrapped_boundary_vertices`).
  /// Computed in floating point as a diagnostic (two curves ending at one smooth vertex, 2 or 6 quarter
  /// turns, are listed too); empty where the seamless map folds nowhere.
  std::vector<std::uint32_t> seamless_wrapped_boundary_vertices;
  /// The same count on the energy's minimizer before the untangling (0 if the minimizer folds nowhere).
  std::size_t relaxed_wrapped_boundary_vertices = 0;
  /// Tetrahedra of `seamless_folds` with a corner in `seamless_wrapped_boundary_vertices`.
  std::size_t seamless_folds_at_wrapped_boundary = 0;
  /// True if the untangled seamless map folded nowhere but branched, and was untangled again from the
  /// energy's minimizer with every variable free (boundary planes and singular lines too; first those of
  /// the tetrahedra one ring around the minimizer's folds, then, if it still branches, all), kept if it
  /// folds nowhere and branches less (`seamless_branched_edges` is the count of the map kept).
  bool seamless_unbranching_ran = false;
  /// True if every tetrahedron of the seamless map is positively oriented (exact) and no interior edge
  /// is branched (`seamless_branched_edges`): the map is locally injective before the rounding.
  bool seamless_injective = false;
  /// Where the seamless map is not injective: its inverted and flat tetrahedra (indices in the map's
  /// mesh, `Integer_grid_map::tetrahedra`).
  std::vector<std::uint32_t> seamless_folds;
  /// The tetrahedra of `seamless_folds` by cause.
  Seamless_fold_causes seamless_fold_causes;
  /// True if the foldover-free untangling of the seamless map ran (its minimizer folded).
  bool seamless_untangling_ran = false;
  /// Tetrahedra with `det J <= 0` (floating point) after the quantization, before the repair.
  std::size_t rounded_inverted_tetrahedra = 0;
  /// The way the integer values were made: `GREEDY_ROUNDING`, `MOTORCYCLE_COMPLEX` or `SEPARATION_PROGRAM`.
  Integer_grid_map_quantization quantization = Integer_grid_map_quantization::GREEDY_ROUNDING;
  /// The motorcycle complex of the seamless map and its program (traced with `AUTOMATIC` and
  /// `MOTORCYCLE_COMPLEX` when the seamless map is injective).
  Integer_grid_map_complex motorcycle_complex;
  /// Why the separation program was not run, stopped, or not kept (empty with `GREEDY_ROUNDING` asked).
  std::string quantization_reason;
  /// Tetrahedra with `det J <= 0` after the greedy rounding, and the fewest after a separation
  /// program (the structurally flat ones left out; equal if no program ran or none did better).
  std::size_t folds_after_rounding = 0;
  /// The fewest folded tetrahedra after a separation program (as `folds_after_rounding` if none did better).
  std::size_t folds_after_separation = 0;
  /// Separation programs solved (Cbc), constraints and integer variables of the last one, their seconds.
  int separation_rounds = 0;
  /// Separation constraints of the last program.
  std::size_t separation_constraints = 0;
  /// Integer variables of the last program.
  std::size_t separation_variables = 0;
  /// Seconds of the programs (Cbc).
  double separation_seconds = 0;
  /// The map reached from the seamless map without a fold, when the quantized map folds or branches.
  Integer_grid_map_continuation continuation;
  /// Stiffening rounds run (0 if the local untangling of the rounded map repaired it).
  int stiffening_rounds = 0;
  /// True if the foldover-free untangling ran (only when tetrahedra other than the structurally flat
  /// ones are inverted or flat after rounding).
  bool untangling_ran = false;
  /// Tetrahedra that the constraints flatten for every value of the continuous variables (three
  /// corners on one singular line where the curve jogs). The stiffening and the untangling, which
  /// cannot repair them, run only while other tetrahedra are inverted or flat.
  std::size_t structurally_flat_tetrahedra = 0;
  /// Sign contradictions of the signed union-find (x = -x): a bad cut or inconsistent matchings.
  std::size_t sign_contradictions = 0;
  /// Constraint rows that were inconsistent or could not be resolved over the integers.
  std::size_t inconsistent_constraints = 0;
  /// Interior faces where the closest matching of the frames differs from the kept matching
  /// (the frames turn by more than 45 degrees there; the map follows the kept matchings).
  std::size_t disagreeing_faces = 0;
  /// Singular edges running across their holonomy axis (more than 45 degrees off it): jogs.
  std::size_t jogs = 0;
  /// Jogs with an inverted or flat tetrahedron in their ring after the map.
  std::size_t degenerate_jogs = 0;
  /// Non-meshable locations of the singularity graph.
  std::vector<Integer_grid_map_defect> defects;
  /// Largest move of a parameter by the snapping to the dyadic grid.
  double sanitize_move = 0;
  /// Largest violation of a transition `u_t0 = R u_t1 + t` after sanitizing (0: exact).
  double transition_error = 0;
  /// Seconds of the cut graph.
  double cut_seconds = 0;
  /// Seconds of the variable reduction (union-find and integer tags).
  double reduction_seconds = 0;
  /// Seconds of the constraint elimination and the assembly of the reduced system.
  double elimination_seconds = 0;
  /// Seconds of the seamless map: its solve, untangling, snapping and exact check.
  double seamless_seconds = 0;
  /// Seconds of the quantization (greedy rounding, separation programs).
  double rounding_seconds = 0;
  /// Seconds of the stiffening.
  double stiffening_seconds = 0;
  /// Seconds of the untangling.
  double untangling_seconds = 0;
  /// Seconds of the sanitizing and the final checks.
  double sanitize_seconds = 0;
  /// Seconds of the whole map.
  double seconds = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Default visitor of `compute_integer_grid_map()`: called when a stage starts and ends (`"cut"`,
/// `"reduction"`, `"elimination"`, `"seamless_map"`, `"rounding"`, `"untangling"`, `"continuation"`, `"stiffening"`,
/// `"untangling"`, `"sanitizing"`; the repair stages only while tetrahedra are inverted: the untangling runs
/// first around the folds of the rounded map; the continuation if that leaves a fold or a branch and the
/// seamless map folds nowhere; the stiffening and a second untangling only if folds remain).
struct Integer_grid_map_visitor
{
  /// Called when a stage starts.
  void start_stage(const std::string& /*stage*/) {}
  /// Called when a stage ends, with its duration in seconds.
  void end_stage(const std::string& /*stage*/, double /*seconds*/) {}
};

namespace internal {

template <class Traits>
double default_target_edge_length(const Tetrahedral_mesh_3<Traits>& mesh)
{
  // summed as the map's geometry sums them (compute_map_geometry()), bit for bit
  double volume = 0;
  for(std::size_t t = 0; t < mesh.number_of_tetrahedra(); ++t) volume += std::abs(tetrahedron_edge_matrix(mesh, t).determinant()) / 6.0;
  return std::cbrt(volume / 2000.0);
}

// Frames, matchings and graph sized for `mesh`, matchings that fit its faces; Input_error otherwise.
template <class Traits>
void check_map_inputs(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                      const Matchings& matchings, const Singularity_graph& singularities)
{
  const std::string source = mesh.source().empty() ? std::string("<memory>") : mesh.source();
  const std::size_t nt = mesh.number_of_tetrahedra(), nf = mesh.number_of_faces(), ne = mesh.number_of_edges();
  auto fail = [&](const std::string& what) { throw Input_error(source, 0, "compute_integer_grid_map: " + what); };
  if(frames.size() != nt)
    fail(std::to_string(frames.size()) + " frames for " + std::to_string(nt) + " tetrahedra (frames of another mesh?)");
  if(matchings.face_matching.size() != nf)
    fail(std::to_string(matchings.face_matching.size()) + " matchings for " + std::to_string(nf) + " faces (matchings of another mesh?)");
  if(singularities.edge_valence.size() != ne || singularities.edge_holonomy.size() != ne)
    fail("singularity graph with " + std::to_string(singularities.edge_valence.size()) + " edges for " + std::to_string(ne) +
         " edges (graph of another mesh?)");
  for(std::uint32_t f = 0; f < nf; ++f)
    if((matchings.face_matching[f] < 0) != mesh.is_boundary_face(f) || matchings.face_matching[f] >= 24)
      fail("face " + std::to_string(f) + ": matching " + std::to_string(matchings.face_matching[f]) +
           " does not fit the mesh (matchings of another mesh?)");
}

// The named parameters of compute_integer_grid_map(), checked.
struct Map_options
{
  double h = 0;
  int maximum_stiffening = 20;
  bool untangle = true;
  int untangling_rings = 3; // the local untangling's reach around the folds (tets through shared vertices)
  Integer_grid_map_quantization quantization = Integer_grid_map_quantization::AUTOMATIC;
  double quantization_time_limit = 60;
  std::vector<std::array<Eigen::Vector3d, 4> >* seamless_parameters = nullptr;
  bool jog_refinement = false;
  bool relocation = false;
  int maximum_continuation_steps = 60;
};

template <class Traits, class NamedParameters>
Map_options map_options(const Tetrahedral_mesh_3<Traits>& mesh, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::string source = mesh.source().empty() ? std::string("<memory>") : mesh.source();
  Map_options o;
  o.h = choose_parameter(get_parameter(np, internal_np::target_edge_length), default_target_edge_length(mesh));
  if(!(o.h > 0) || !std::isfinite(o.h)) {
    std::ostringstream os;
    os << "compute_integer_grid_map: target_edge_length must be a positive finite length, got " << o.h;
    throw Input_error(source, 0, os.str());
  }
  o.maximum_stiffening = choose_parameter(get_parameter(np, internal_np::maximum_stiffening_iterations), 20);
  o.untangle = choose_parameter(get_parameter(np, internal_np::untangling), true);
  o.jog_refinement = choose_parameter(get_parameter(np, internal_np::jog_refinement), false);
  o.relocation = choose_parameter(get_parameter(np, internal_np::singular_vertex_relocation), false);
  o.maximum_continuation_steps = choose_parameter(get_parameter(np, internal_np::maximum_continuation_steps), 60);
  if(o.maximum_continuation_steps < 0)
    throw Input_error(source, 0, "compute_integer_grid_map: maximum_continuation_steps must be >= 0");
  o.quantization = choose_parameter(get_parameter(np, internal_np::quantization), Integer_grid_map_quantization::AUTOMATIC);
  o.quantization_time_limit = choose_parameter(get_parameter(np, internal_np::quantization_time_limit), 60.0);
  if(!(o.quantization_time_limit >= 0) || !std::isfinite(o.quantization_time_limit))
    throw Input_error(source, 0, "compute_integer_grid_map: quantization_time_limit must be a finite number of seconds >= 0");
  o.seamless_parameters = choose_parameter(get_parameter(np, internal_np::seamless_map_parameters),
                                           static_cast<std::vector<std::array<Eigen::Vector3d, 4> >*>(nullptr));
  return o;
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Computes a seamless integer-grid map of `mesh` guided by a frame field (paper Sec. 3.4, step 4
/// "extract a seamless parametrization"; CubeCover, Nieser et al. 2011; algorithms.md §4): per
/// tetrahedron an affine map `u_t` whose gradient approximates `E_t^T / target_edge_length`, which
/// jumps across every interior face `f` only by the rotation `g_f^T` of the kept matching plus an
/// integer translation, puts every boundary face on an integer plane of the local axis along its
/// normal, and every singular edge (valence 3 or 5) on an integer line of the local holonomy axis.
///
/// Steps: cut graph (dual spanning tree, pruned, singular and boundary edges protected); signed
/// union-find of the 12 corner scalars per tetrahedron across uncut faces; integer tags; exact
/// elimination of the cut constraints; the seamless map (every variable continuous), untangled
/// with the foldover-free solver where it folds, snapped, and checked with exact orientations
/// (`seamless_injective`, `seamless_folds`); greedy mixed-integer rounding with a CHOLMOD factorization
/// analysed once; where the rounded map folds and the seamless map is injective, the motorcycle
/// complex of the seamless map (walls traced exactly from its singular and feature curves, in order of
/// parametric distance; Brückler, Bommes, Campen 2022) gives every block extent as a function of the
/// integer variables, and an integer program solved with COIN-OR Cbc keeps them >= 0, >= 1 between
/// two boundary sides or two curves and, lazily, at the folds, with the fewest changes; where the map
/// still folds, separation constraints between the entities the rounding collapsed (boundary planes,
/// singular and feature lines that the seamless map keeps apart along an axis) searched around the
/// folds in the tetrahedral mesh, and a program that satisfies them (robust_pipeline.md §3); a
/// program's map is kept only if it does not fold; repair of the folds (foldover-free untangling around them, then stiffening of
/// distorted tetrahedra and untangling everywhere if folds remain), where the local untangling leaves a
/// fold or a branch, only if the integer values cannot be reached from the seamless map, when it folds
/// nowhere, by steps on which no tetrahedron folds (`Integer_grid_map_continuation`); snapping to a dyadic
/// grid so that every transition holds exactly in double.
///
/// \param mesh the tetrahedral mesh of the frame field
/// \param frames one frame per tetrahedron (columns = axes), normally realigned with the normals
/// \param matchings the kept matchings of the field (one per face)
/// \param singularities the singularity graph of `frames` and `matchings`
/// \param map receives the points and tetrahedra of `mesh`, the corner parameters (in hex edges) and
///        the transitions of the interior faces (`u_t0 = R u_t1 + translation`)
/// \param np an optional sequence of named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{target_edge_length}
///     \cgalParamDescription{hex edge length in model units}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`cbrt(volume / 2000)`: about 2000 hexahedra; the value used is reported}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_stiffening_iterations}
///     \cgalParamDescription{maximum number of stiffening rounds}
///     \cgalParamType{`int`}
///     \cgalParamDefault{20}
///   \cgalParamNEnd
///   \cgalParamNBegin{untangling}
///     \cgalParamDescription{run the foldover-free untangling (Garanzha et al. 2021) of the continuous variables if tetrahedra are inverted after the rounding (without it, only the stiffening repairs)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{quantization}
///     \cgalParamDescription{how the integer values are made: greedy rounding, followed where the rounded map folds by the motorcycle complex's program, then the separation program (`AUTOMATIC`); the complex's program only (`MOTORCYCLE_COMPLEX`); the separation program only (`SEPARATION_PROGRAM`); or greedy rounding only (`GREEDY_ROUNDING`)}
///     \cgalParamType{`Integer_grid_map_quantization`}
///     \cgalParamDefault{`Integer_grid_map_quantization::AUTOMATIC`}
///   \cgalParamNEnd
///   \cgalParamNBegin{quantization_time_limit}
///     \cgalParamDescription{seconds the complex's programs, and the separation programs, may take together; the best map found by then is kept}
///     \cgalParamType{`double`}
///     \cgalParamDefault{60}
///   \cgalParamNEnd
///   \cgalParamNBegin{jog_refinement}
///     \cgalParamDescription{split at its midpoint every interior regular edge that closes a face with two singular edges (a jog of a singular curve): the map puts the two singular edges on one integer line, which flattens every tetrahedron of that face whatever the map; the map is then computed on the split mesh, each new tetrahedron with its parent's frame. Off by default: where the curve doubles back along its axis the opened tetrahedra come out inverted (shared models i01c: 77 -> 154 inverted, n01c: 618 -> 751; the cylinder: 47 flat and 1 inverted -> 1 flat and 15 inverted)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{singular_vertex_relocation}
///     \cgalParamDescription{move every interior vertex of a singular curve (two singular edges of valence 3 or 5, no other) towards the position that aligns its two edges with their holonomy axes, within an inversion barrier (exact orientations; no tetrahedron around it worse than half its worst start shape), in Gauss-Seidel sweeps; the map is computed on the moved mesh. Nodes, boundary vertices and the boundary stay}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_continuation_steps}
///     \cgalParamDescription{steps of the continuation from the seamless map to the integer values (to each of the two targets: the complex's lengths if the quantizer kept other values, then the quantized values) when the quantized map folds or branches (every tetrahedron positive, but an interior edge turned by a number of quarter turns other than 3, 4 or 5) and the seamless map folds nowhere; each step moves the map along the linear response to the integer values, halved until no tetrahedron folds, then relaxed by the foldover-free barrier; the map reached is kept if it neither folds nor branches (`Integer_grid_map_result::continuation`), else the folds are repaired by the untangling; 0 turns it off}
///     \cgalParamType{`int`}
///     \cgalParamDefault{60}
///   \cgalParamNEnd
///   \cgalParamNBegin{seamless_map_parameters}
///     \cgalParamDescription{receives the corner parameters (in hex edges) of the seamless map before any rounding, after its untangling: one array of four points per tetrahedron, in the order of its vertices}
///     \cgalParamType{`std::vector<std::array<Eigen::Vector3d, 4> >*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress callbacks}
///     \cgalParamType{a class with the member functions of `Integer_grid_map_visitor`}
///     \cgalParamDefault{`Integer_grid_map_visitor()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the report; the map is filled whatever the status (the best map found).
/// \throws Input_error if `target_edge_length` is not a positive finite number, or if `frames`,
///         `matchings` or `singularities` are not sized for `mesh`.
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Integer_grid_map_result compute_integer_grid_map(const Tetrahedral_mesh_3<Traits>& mesh,
                                                 const std::vector<Eigen::Matrix3d>& frames,
                                                 const Matchings& matchings,
                                                 const Singularity_graph& singularities,
                                                 Integer_grid_map& map,
                                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter_reference;
  typedef std::chrono::steady_clock Clock;
  Integer_grid_map_visitor default_visitor;
  auto& visitor = choose_parameter(get_parameter_reference(np, CGAL::internal_np::visitor), default_visitor);
  internal::check_map_inputs(mesh, frames, matchings, singularities);
  const auto start = Clock::now();
  const internal::Map_options o = internal::map_options(mesh, np);
  Integer_grid_map_result r;
  r.target_edge_length = o.h;
  internal::Refined_field<Traits> refined;
  if(o.jog_refinement && internal::refine_jogs(mesh, frames, matchings, singularities, refined)) {
    r.split_jog_edges = refined.mesh.number_of_vertices() - mesh.number_of_vertices();
    internal::relocate_and_compute_map_stages(refined.mesh, refined.frames, refined.matchings, refined.singularities, o, visitor, map, r);
  } else {
    internal::relocate_and_compute_map_stages(mesh, frames, matchings, singularities, o, visitor, map, r);
  }
  r.map_tetrahedra = map.tetrahedra.size();
  // every tetrahedron positive does not make the map locally injective around the edges
  r.branched_edges = check_integer_grid_map(map).unusual_interior_edges.size();
  if(r.branched_edges > 0 && (r.status == Integer_grid_map_status::OK || r.status == Integer_grid_map_status::DEGENERATE_TETRAHEDRA))
    r.status = Integer_grid_map_status::BRANCHED_EDGES;
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return r;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Computes the integer-grid map of the field of a frame-field pipeline run: its frames, kept
/// matchings and singularity graph (see the other overload for the parameters).
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
Integer_grid_map_result compute_integer_grid_map(const Tetrahedral_mesh_3<Traits>& mesh,
                                                 const Frame_field_pipeline_result& field,
                                                 Integer_grid_map& map,
                                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  return compute_integer_grid_map(mesh, field.frames, field.matchings, field.singularities, map, np);
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTEGER_GRID_MAP_FUNCTION_H
