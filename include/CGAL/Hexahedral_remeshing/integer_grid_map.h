// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTEGER_GRID_MAP_FUNCTION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTEGER_GRID_MAP_FUNCTION_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/constraint_elimination.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/cut_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/dof_reduction.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/field_diagnostics.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fixed_variable_solver.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_assembly.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/greedy_rounding.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/integer_tags.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/reduced_system.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/sanitize.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/separating_quantizer.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/separation_constraints.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/signed_union_find.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/stiffening.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/structurally_flat.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/untangle_map.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

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
} // namespace internal_np

/// \ingroup PkgHexahedralRemeshingRef
/// How `compute_integer_grid_map()` makes the integer values of the map (named parameter
/// `quantization`), and which way made it (`Integer_grid_map_result::quantization`).
enum class Integer_grid_map_quantization {
  /// Greedy rounding, then, if the rounded map folds, the separation program where it folds; the
  /// program's map is kept if it does not fold (as a parameter: the default).
  AUTOMATIC,
  /// Greedy mixed-integer rounding only (one variable batch at a time, re-solving in between).
  GREEDY_ROUNDING,
  /// (reported) The map of the separation program: the rounded map folded, and the integer program
  /// that keeps apart the entities it collapsed gave a map without folds.
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
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(target_edge_length)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(maximum_stiffening_iterations)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(untangling)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(quantization)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(quantization_time_limit)
#endif
} // namespace parameters

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
  SOLVER_FAILURE
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
  /// The edge or vertex index in the tetrahedral mesh.
  std::uint32_t index = 0;
  /// Position (model units): the vertex, or the edge midpoint.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
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
  /// Minimum over the tetrahedra of `det J_t / s^3` (1 for a perfect map at the target size).
  double min_relative_jacobian = 0;
  /// Hex edge length used (model units); `s = 1 / target_edge_length`.
  double target_edge_length = 0;
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
  /// Tetrahedra with `det J <= 0` (floating point) in the continuous relaxation, before rounding.
  std::size_t relaxed_inverted_tetrahedra = 0;
  /// Tetrahedra with `det J <= 0` (floating point) after the quantization, before the repair.
  std::size_t rounded_inverted_tetrahedra = 0;
  /// The way the integer values were made: `GREEDY_ROUNDING` or `SEPARATION_PROGRAM`.
  Integer_grid_map_quantization quantization = Integer_grid_map_quantization::GREEDY_ROUNDING;
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
  /// Seconds of the greedy rounding.
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
/// `"reduction"`, `"elimination"`, `"rounding"`, `"untangling"`, `"stiffening"`, `"untangling"`,
/// `"sanitizing"`; the repair stages only while tetrahedra are inverted: the untangling runs first
/// around the folds of the rounded map, and the stiffening and a second untangling only if folds remain).
struct Integer_grid_map_visitor
{
  /// Called when a stage starts.
  void start_stage(const std::string& /*stage*/) {}
  /// Called when a stage ends, with its duration in seconds.
  void end_stage(const std::string& /*stage*/, double /*seconds*/) {}
};

namespace internal {

template <class Traits>
double default_target_edge_length(const Tetrahedral_mesh_3<Traits>& mesh, const Map_geometry& geometry)
{
  (void)mesh;
  double volume = 0;
  for(double v : geometry.volumes) volume += v;
  return std::cbrt(volume / 2000.0);
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
/// elimination of the cut constraints; greedy mixed-integer rounding with a CHOLMOD factorization
/// analysed once; where the rounded map folds, separation constraints between the entities the
/// rounding collapsed (boundary planes, singular and feature lines that the seamless map keeps apart
/// along an axis) and an integer program solved with COIN-OR Cbc that satisfies them with the fewest
/// changes (robust_pipeline.md §3; QGP3D's separation, searched around the folds in the tetrahedral
/// mesh, not in a motorcycle complex); repair of the folds (foldover-free untangling around them, then stiffening of
/// distorted tetrahedra and untangling everywhere if folds remain); snapping to a dyadic
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
///     \cgalParamDescription{how the integer values are made: greedy rounding, followed where the rounded map folds by the separation program (`AUTOMATIC`), or greedy rounding only}
///     \cgalParamType{`Integer_grid_map_quantization`}
///     \cgalParamDefault{`Integer_grid_map_quantization::AUTOMATIC`}
///   \cgalParamNEnd
///   \cgalParamNBegin{quantization_time_limit}
///     \cgalParamDescription{seconds the separation programs may take together; the best map found by then is kept}
///     \cgalParamType{`double`}
///     \cgalParamDefault{60}
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
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  typedef std::chrono::steady_clock Clock;
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Row_matrix;
  auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  Integer_grid_map_visitor default_visitor;
  auto& visitor = choose_parameter(get_parameter_reference(np, CGAL::internal_np::visitor), default_visitor);

  const std::string source = mesh.source().empty() ? std::string("<memory>") : mesh.source();
  const std::size_t nt = mesh.number_of_tetrahedra(), nf = mesh.number_of_faces(), ne = mesh.number_of_edges();
  if(frames.size() != nt)
    throw Input_error(source, 0, "compute_integer_grid_map: " + std::to_string(frames.size()) + " frames for " +
                                   std::to_string(nt) + " tetrahedra (frames of another mesh?)");
  if(matchings.face_matching.size() != nf)
    throw Input_error(source, 0, "compute_integer_grid_map: " + std::to_string(matchings.face_matching.size()) +
                                   " matchings for " + std::to_string(nf) + " faces (matchings of another mesh?)");
  if(singularities.edge_valence.size() != ne || singularities.edge_holonomy.size() != ne)
    throw Input_error(source, 0, "compute_integer_grid_map: singularity graph with " +
                                   std::to_string(singularities.edge_valence.size()) + " edges for " +
                                   std::to_string(ne) + " edges (graph of another mesh?)");
  for(Index f = 0; f < nf; ++f)
    if((matchings.face_matching[f] < 0) != mesh.is_boundary_face(f) || matchings.face_matching[f] >= 24)
      throw Input_error(source, 0, "compute_integer_grid_map: face " + std::to_string(f) +
                                     ": matching " + std::to_string(matchings.face_matching[f]) +
                                     " does not fit the mesh (matchings of another mesh?)");

  Integer_grid_map_result r;
  const auto start = Clock::now();
  const internal::Map_geometry geometry = internal::compute_map_geometry(mesh);
  const double h = choose_parameter(get_parameter(np, internal_np::target_edge_length),
                                    internal::default_target_edge_length(mesh, geometry));
  if(!(h > 0) || !std::isfinite(h)) {
    std::ostringstream os;
    os << "compute_integer_grid_map: target_edge_length must be a positive finite length, got " << h;
    throw Input_error(source, 0, os.str());
  }
  const int max_stiffening = choose_parameter(get_parameter(np, internal_np::maximum_stiffening_iterations), 20);
  const bool untangle = choose_parameter(get_parameter(np, internal_np::untangling), true);
  // the local untangling's reach around the folds (tets through shared vertices)
  const int untangling_rings = 3;
  const Integer_grid_map_quantization quantization =
    choose_parameter(get_parameter(np, internal_np::quantization), Integer_grid_map_quantization::AUTOMATIC);
  const double quantization_time_limit = choose_parameter(get_parameter(np, internal_np::quantization_time_limit), 60.0);
  if(!(quantization_time_limit >= 0) || !std::isfinite(quantization_time_limit))
    throw Input_error(source, 0, "compute_integer_grid_map: quantization_time_limit must be a finite number of seconds >= 0");
  if(quantization == Integer_grid_map_quantization::SEPARATION_PROGRAM)
    throw Input_error(source, 0, "compute_integer_grid_map: quantization is AUTOMATIC or GREEDY_ROUNDING "
                                 "(SEPARATION_PROGRAM is reported, not asked)");
  r.target_edge_length = h;
  const double s = 1.0 / h;

  // Diagnostics of the field: non-meshable locations, frames disagreeing with the kept matchings, jogs.
  const std::vector<Index> jog_edges = internal::diagnose_field(mesh, frames, matchings, singularities, r);

  // 1. Cut graph.
  visitor.start_stage("cut");
  auto t = Clock::now();
  std::vector<char> protected_edge(ne, 0), singular_edge(ne, 0);
  for(Index e = 0; e < ne; ++e) {
    if(mesh.is_boundary_edge(e)) { protected_edge[e] = 1; continue; }
    if(singularities.edge_holonomy[e] != internal::Octahedral_group::identity_index) protected_edge[e] = singular_edge[e] = 1;
  }
  const std::vector<char> cut = internal::compute_cut_faces(mesh, protected_edge, singular_edge);
  std::vector<std::uint32_t> cut_index(nf, std::uint32_t(-1));
  for(Index f = 0; f < nf; ++f)
    if(cut[f]) cut_index[f] = std::uint32_t(r.cut_faces++);
  r.cut_seconds = seconds_since(t);
  visitor.end_stage("cut", r.cut_seconds);

  // 2. Variable reduction and integer tags.
  visitor.start_stage("reduction");
  t = Clock::now();
  internal::Signed_union_find uf(12 * nt);
  r.sign_contradictions = internal::glue_uncut_faces(mesh, matchings, cut, uf);
  std::vector<char> integer_scalar(12 * nt, 0);
  internal::tag_boundary_planes(mesh, frames, uf, integer_scalar);
  internal::tag_singular_lines(mesh, matchings, singularities, uf, integer_scalar);
  const internal::Map_dofs dofs = internal::label_dofs(uf, integer_scalar);
  r.reduction_seconds = seconds_since(t);
  visitor.end_stage("reduction", r.reduction_seconds);

  // 3. Exact elimination of the cut constraints.
  visitor.start_stage("elimination");
  t = Clock::now();
  internal::Constraint_elimination elimination;
  for(std::size_t d = 0; d < dofs.number_of_dofs; ++d) elimination.add_variable(dofs.integer[d] != 0);
  const std::uint32_t first_jump = std::uint32_t(dofs.number_of_dofs);
  for(std::size_t k = 0; k < 3 * r.cut_faces; ++k) elimination.add_variable(true);
  for(std::size_t d = 0; d < dofs.number_of_dofs; ++d)
    if(dofs.contradicted[d]) elimination.fix(std::uint32_t(d), 0.0);
  // Pin one corner per connected component (the one with the most integer coordinates) at 0: the
  // energy does not see translations.
  {
    std::vector<int> best(mesh.number_of_components(), -1);
    std::vector<std::uint32_t> best_corner(mesh.number_of_components(), 0);
    for(Index tt = 0; tt < nt; ++tt)
      for(int c = 0; c < 4; ++c) {
        int count = 0;
        for(int k = 0; k < 3; ++k) count += dofs.integer[dofs.dof[internal::map_scalar(tt, c, k)]];
        const Index comp = mesh.tetrahedron_component(tt);
        if(count > best[comp]) { best[comp] = count; best_corner[comp] = 4 * tt + std::uint32_t(c); }
      }
    for(std::size_t comp = 0; comp < best.size(); ++comp)
      for(int k = 0; k < 3; ++k) {
        const std::uint32_t d = dofs.dof[internal::map_scalar(best_corner[comp] / 4, int(best_corner[comp] % 4), k)];
        if(elimination.is_free(d)) elimination.fix(d, 0.0);
      }
  }
  typedef internal::Constraint_elimination::Term Term;
  for(Index f = 0; f < nf; ++f) {
    if(!cut[f]) continue;
    const auto& ft = mesh.face_tetrahedra(f);
    const int R = internal::transition_rotation(matchings, f);
    for(Index v : mesh.face_vertices(f)) {
      const int c0 = internal::local_corner(mesh, ft[0], v), c1 = internal::local_corner(mesh, ft[1], v);
      for(int k = 0; k < 3; ++k) {
        const auto [col, sign] = internal::transition_row(R, k);
        const std::uint32_t a = internal::map_scalar(ft[0], c0, k), b = internal::map_scalar(ft[1], c1, col);
        // x_a - sign x_b - tau = 0
        const std::vector<Term> row = {Term{dofs.dof[a], double(dofs.sign[a])},
                                       Term{dofs.dof[b], -double(sign * dofs.sign[b])},
                                       Term{first_jump + 3 * cut_index[f] + std::uint32_t(k), -1.0}};
        elimination.add_row(row, 0.0);
      }
    }
  }
  r.inconsistent_constraints = elimination.inconsistent_rows() + elimination.unresolved_rows();

  // x = P y + x0 over the free variables.
  std::vector<std::int64_t> column(elimination.number_of_variables(), -1);
  std::vector<char> integer_column;
  for(std::uint32_t v = 0; v < elimination.number_of_variables(); ++v)
    if(elimination.is_free(v)) {
      column[v] = std::int64_t(integer_column.size());
      integer_column.push_back(elimination.is_integer(v) ? 1 : 0);
    }
  const Eigen::Index m = Eigen::Index(integer_column.size());
  r.variables = std::size_t(m);
  for(char c : integer_column) r.integer_variables += (c != 0);
  auto expression = [&](std::uint32_t v) {
    internal::Constraint_elimination::Expression e;
    if(elimination.is_free(v)) e.terms.push_back(Term{v, 1.0});
    else e = elimination.expand(v);
    return e;
  };
  std::vector<internal::Constraint_elimination::Expression> dof_expression(dofs.number_of_dofs);
  for(std::uint32_t d = 0; d < dofs.number_of_dofs; ++d) dof_expression[d] = expression(d);
  Row_matrix P(Eigen::Index(12 * nt), m);
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(Eigen::Index(12 * nt));
  {
    std::vector<Eigen::Triplet<double> > triplets;
    triplets.reserve(12 * nt * 2);
    for(std::size_t i = 0; i < 12 * nt; ++i) {
      const auto& e = dof_expression[dofs.dof[i]];
      const double sg = dofs.sign[i];
      x0[Eigen::Index(i)] = sg * e.constant;
      for(const Term& term : e.terms) triplets.emplace_back(int(i), int(column[term.var]), sg * term.coef);
    }
    P.setFromTriplets(triplets.begin(), triplets.end());
  }
  Eigen::SparseMatrix<double> H;
  Eigen::VectorXd rhs;
  internal::assemble_reduced_system(geometry, frames, s, std::vector<double>(), P, x0, H, rhs);
  // what neither the stiffening nor the untangling can repair
  const std::vector<char> flat = internal::structurally_flat_tetrahedra(geometry, P, x0);
  r.structurally_flat_tetrahedra = std::size_t(std::count(flat.begin(), flat.end(), char(1)));
  r.elimination_seconds = seconds_since(t);
  visitor.end_stage("elimination", r.elimination_seconds);

  // 4. Quantization.
  visitor.start_stage("rounding");
  t = Clock::now();
  internal::Fixed_variable_solver solver;
  auto jump_form = [&](Index f, int k) {
    internal::Linear_form form;
    const auto e = expression(first_jump + 3 * cut_index[f] + std::uint32_t(k));
    form.constant = e.constant;
    for(const Term& term : e.terms) form.terms.emplace_back(Eigen::Index(column[term.var]), term.coef);
    std::sort(form.terms.begin(), form.terms.end());
    return form;
  };
  const internal::Separation_finder<Traits> finder(mesh, matchings, cut, geometry, P, x0, integer_column, flat, jump_form);
  internal::Greedy_rounding_quantizer greedy;
  internal::Separating_quantizer separating(
    [&](const Eigen::VectorXd& seamless, const Eigen::VectorXd& v) { return finder.violated(seamless, v); },
    [&](const Eigen::VectorXd& v) { const auto f = finder.folded(v); return std::size_t(std::count(f.begin(), f.end(), char(1))); });
  separating.time_limit = quantization_time_limit;
  internal::Quantizer& quantizer = quantization == Integer_grid_map_quantization::GREEDY_ROUNDING
                                     ? static_cast<internal::Quantizer&>(greedy) : separating;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(m);
  const internal::Quantization_result q = quantizer.quantize(H, rhs, integer_column, solver, y);
  if(quantization != Integer_grid_map_quantization::GREEDY_ROUNDING) {
    const internal::Separation_report& sr = separating.report;
    r.quantization = sr.used ? Integer_grid_map_quantization::SEPARATION_PROGRAM : Integer_grid_map_quantization::GREEDY_ROUNDING;
    r.quantization_reason = sr.reason;
    r.folds_after_rounding = sr.folds_after_rounding;
    r.folds_after_separation = sr.folds_after_program;
    r.separation_rounds = sr.rounds;
    r.separation_constraints = sr.constraints;
    r.separation_variables = sr.variables;
    r.separation_seconds = sr.program_seconds;
  }
  r.rounding_rounds = q.rounds;
  r.max_rounding = q.max_rounding;
  if(q.relaxed.size() == m) r.relaxed_inverted_tetrahedra = internal::count_non_positive_jacobians(geometry, P * q.relaxed + x0);
  r.rounded_inverted_tetrahedra = internal::count_non_positive_jacobians(geometry, P * y + x0);
  r.rounding_seconds = seconds_since(t);
  visitor.end_stage("rounding", r.rounding_seconds);

  // 5. Repair of the folds. First the local untangling of the rounded map (the tets within a few rings of
  // the folds): it repairs most maps alone, and the stiffening, a numeric factorization per round over
  // the whole mesh, rarely changes the count (B0: 2 inverted before and after 3 rounds, 4.5 s of its 7.4 s
  // map). If folds remain: stiffening from the rounded map, then the local untangling again and the
  // global one if folds still remain (from the stiffened map: from the partly untangled one, s12c's hex
  // mesh came out invalid). Folds whose rings hold more than a quarter of the tets go to the global
  // untangling directly.
  auto folds = [&](const Eigen::VectorXd& v) { return internal::count_non_positive_jacobians(geometry, P * v + x0, &flat); };
  auto untangle_locally = [&](Eigen::VectorXd& v) {
    const std::vector<char> region = internal::untangling_region(mesh, geometry, P * v + x0, flat, untangling_rings);
    if(std::size_t(std::count(region.begin(), region.end(), char(1))) > nt / 4) return false;
    r.untangling_ran = internal::untangle_map(geometry, frames, s, P, x0, integer_column, flat, v, &region).ran || r.untangling_ran;
    return true;
  };
  // (a failed rounding leaves nothing to repair: its map is reported as it is)
  bool repaired = !q.success || folds(y) == 0;
  if(!repaired && untangle) {
    visitor.start_stage("untangling");
    t = Clock::now();
    Eigen::VectorXd z = y;
    if(untangle_locally(z) && folds(z) == 0) { y = z; repaired = true; }
    r.untangling_seconds += seconds_since(t);
    visitor.end_stage("untangling", seconds_since(t));
  }
  if(!repaired) {
    visitor.start_stage("stiffening");
    t = Clock::now();
    r.stiffening_rounds = internal::stiffen_map(geometry, frames, s, P, x0, flat, solver, y, max_stiffening);
    r.stiffening_seconds = seconds_since(t);
    visitor.end_stage("stiffening", r.stiffening_seconds);
    if(untangle && folds(y) > 0) {
      visitor.start_stage("untangling");
      t = Clock::now();
      const Eigen::VectorXd stiffened = y;
      if(!untangle_locally(y) || folds(y) > 0) {
        y = stiffened;
        r.untangling_ran = internal::untangle_map(geometry, frames, s, P, x0, integer_column, flat, y).ran || r.untangling_ran;
      }
      r.untangling_seconds += seconds_since(t);
      visitor.end_stage("untangling", seconds_since(t));
    }
  }

  // 7. Sanitizing and the final map.
  visitor.start_stage("sanitizing");
  t = Clock::now();
  r.sanitize_move = internal::snap_to_dyadic_grid(y, integer_column);
  const Eigen::VectorXd x = P * y + x0;

  internal::assemble_map(mesh, matchings, cut, geometry, s, x, jog_edges,
                         [&](Index f, int k) { return int(std::lround(jump_form(f, k)(y))); }, map, r);
  r.sanitize_seconds = seconds_since(t);
  visitor.end_stage("sanitizing", r.sanitize_seconds);

  if(!q.success) r.status = Integer_grid_map_status::SOLVER_FAILURE;
  else if(r.sign_contradictions > 0 || r.inconsistent_constraints > 0) r.status = Integer_grid_map_status::INCONSISTENT_MATCHINGS;
  else if(!r.defects.empty()) r.status = Integer_grid_map_status::NON_MESHABLE_SINGULARITIES;
  else if(r.inverted_tetrahedra > 0) r.status = Integer_grid_map_status::INVERTED_TETRAHEDRA;
  else if(r.degenerate_tetrahedra > 0) r.status = Integer_grid_map_status::DEGENERATE_TETRAHEDRA;
  r.seconds = seconds_since(start);
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
