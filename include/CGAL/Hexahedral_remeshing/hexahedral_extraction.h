// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_EXTRACTION_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_EXTRACTION_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/check_map.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/hex_cells.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/hex_vertices.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/map_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/sanitize.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/transitions.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <sstream>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal_np {
enum keep_folded_cells_t { keep_folded_cells };
} // namespace internal_np

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// Hex extraction: keep the complete cells next to inverted tetrahedra that have a corner inverted in
/// space, for a mesh that is untangled next (`bool`, default `false`).
template <class T> unspecified_type keep_folded_cells(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(keep_folded_cells)
#endif
} // namespace parameters

/// \ingroup PkgHexahedralRemeshingRef
/// What an integer-grid map looks like, measured from its parameters alone (`check_integer_grid_map()`).
/// Faces are given as sorted vertex triples; deviations are in parameter units (hex edges).
struct Integer_grid_map_check
{
  /// Number of tetrahedra.
  std::size_t tetrahedra = 0;
  /// Number of interior faces (shared by two tetrahedra).
  std::size_t interior_faces = 0;
  /// Number of boundary faces.
  std::size_t boundary_faces = 0;
  /// Tetrahedra whose parameter points are negatively oriented (exact `orientation`).
  std::size_t inverted_tetrahedra = 0;
  /// Tetrahedra whose parameter points are coplanar (exact `orientation`).
  std::size_t degenerate_tetrahedra = 0;
  /// Tetrahedra whose positions (model space) are negatively oriented (exact `orientation`): the map
  /// folds the model there even if the parameters are fine.
  std::size_t inverted_positions = 0;
  /// Tetrahedra whose positions are coplanar.
  std::size_t degenerate_positions = 0;
  /// Largest misfit, over the interior faces, of the face edge vectors of one chart and the best
  /// rotation of the 24-group applied to the other chart's.
  double max_rotation_deviation = 0.;
  /// Face of `max_rotation_deviation`.
  std::array<std::uint32_t, 3> worst_rotation_face{};
  /// Largest distance of a transition's translation to an integer vector (includes the rotation misfit).
  double max_jump_deviation = 0.;
  /// Face of `max_jump_deviation`.
  std::array<std::uint32_t, 3> worst_jump_face{};
  /// Largest distance of a boundary face to the nearest integer coordinate plane.
  double max_boundary_deviation = 0.;
  /// Face of `max_boundary_deviation`.
  std::array<std::uint32_t, 3> worst_boundary_face{};
  /// Interior faces whose parameters do not determine the rotation (collinear or coincident).
  std::size_t ambiguous_transitions = 0;
  /// Interior edges by valence: (sum of the parameter-space dihedral angles of the incident tetrahedra,
  /// negative for inverted ones, 0 for degenerate ones) / (pi/2), rounded; 4 is regular.
  std::map<int, std::size_t> interior_edge_valences;
  /// Boundary edges by valence (same sum): 2 flat, 1 convex feature, 3 concave feature.
  std::map<int, std::size_t> boundary_edge_valences;
  /// Largest distance of an edge's angle sum / (pi/2) to an integer (edges at degenerate tetrahedra excluded).
  double max_valence_deviation = 0.;
  /// Edges incident to a degenerate tetrahedron (their valence is not reliable).
  std::size_t edges_at_degenerate_tetrahedra = 0;
  /// One boundary edge of the map with its valence (same sum as `boundary_edge_valences`).
  struct Boundary_edge
  {
    std::array<std::uint32_t, 2> vertices; ///< vertex ids, ascending
    int valence;                           ///< angle sum / (pi/2), rounded
    bool at_degenerate_tetrahedron;        ///< the valence is not reliable
  };
  /// Every boundary edge with its valence, sorted by vertex ids: compare with the prescribed valences
  /// (`boundary_valence_agreement()`).
  std::vector<Boundary_edge> boundary_edges;
  /// One interior edge of the map with its valence.
  struct Interior_edge
  {
    std::array<std::uint32_t, 2> vertices; ///< vertex ids, ascending
    int valence;                           ///< angle sum / (pi/2), rounded
  };
  /// Interior edges whose tetrahedra are all positively oriented but whose valence is not 3, 4 or 5,
  /// sorted by vertex ids: the map turns around them by another number of quarter turns. Where the
  /// field has singular edges of valence 3 and 5 only (as `compute_integer_grid_map()`'s), such an
  /// edge is a branch of the map (`Integer_grid_map_status::BRANCHED_EDGES`): every tetrahedron is
  /// positive, yet the map is not locally injective (a valence-1 edge of a valence-5 curve beside a
  /// valence-8 regular one: the curve's winding moved to a neighbour). Other maps may have edges of
  /// valence 2 or 6 on purpose (HexEx's sphere and hand).
  std::vector<Interior_edge> unusual_interior_edges;

  /// True when the transitions and the boundary planes are integer within `tolerance`.
  bool is_integer_grid(double tolerance = 1e-3) const
  {
    return max_rotation_deviation <= tolerance && max_jump_deviation <= tolerance && max_boundary_deviation <= tolerance;
  }
  /// True when no tetrahedron is inverted or degenerate in parameter space.
  bool is_locally_injective() const { return inverted_tetrahedra == 0 && degenerate_tetrahedra == 0; }
  /// Number of interior edges whose valence is not 4.
  std::size_t singular_interior_edges() const
  {
    std::size_t n = 0;
    for(const auto& kv : interior_edge_valences) n += kv.first != 4 ? kv.second : 0;
    return n;
  }
};

/// \ingroup PkgHexahedralRemeshingRef
/// Checks an integer-grid map from its parameters alone, independently of how it was produced:
/// transitions recovered per interior face (faces matched by sorted vertex triples; the rotation of
/// the 24-group best mapping one chart's face edge vectors onto the other's, the translation
/// `round(u_i - R u_j)`; `map.transitions` when given), boundary faces against integer planes,
/// inverted and degenerate tetrahedra by the exact orientation of their parameter points (and of their
/// positions), and the
/// valence of every edge from its parameter-space dihedral-angle sum (HexEx's singularity test,
/// Lyon, Bommes, Kobbelt 2016). Runs in O(n log n) for n tetrahedra.
/// \throws Input_error if the tetrahedra are not a manifold (a face shared by more than two) or a
///         vertex id is out of range.
inline Integer_grid_map_check check_integer_grid_map(const Integer_grid_map& map)
{
  namespace ex = internal::extraction;
  Integer_grid_map_check check;
  ex::Map_topology topo;
  ex::build_map_topology(map, topo);
  ex::Face_transitions tr;
  ex::compute_face_transitions(map, topo, tr);
  const std::size_t nt = map.tetrahedra.size();
  check.tetrahedra = nt;
  check.interior_faces = topo.interior_faces;
  check.boundary_faces = topo.boundary_faces;
  check.max_rotation_deviation = tr.max_rotation_deviation;
  check.max_jump_deviation = tr.max_jump_deviation;
  check.ambiguous_transitions = tr.ambiguous;
  if(tr.worst_rotation_tet != ex::no_tetrahedron)
    check.worst_rotation_face = ex::sorted_face(map, tr.worst_rotation_tet, tr.worst_rotation_face);
  if(tr.worst_jump_tet != ex::no_tetrahedron)
    check.worst_jump_face = ex::sorted_face(map, tr.worst_jump_tet, tr.worst_jump_face);

  std::vector<double> angle_sum(topo.edges.size(), 0.);
  std::vector<char> at_degenerate(topo.edges.size(), 0), at_inverted(topo.edges.size(), 0);
  for(std::uint32_t t = 0; t < nt; ++t) {
    const CGAL::Orientation o = ex::parameter_orientation(map.parameters[t]);
    if(o == CGAL::NEGATIVE) ++check.inverted_tetrahedra;
    if(o == CGAL::COPLANAR) ++check.degenerate_tetrahedra;
    const auto& tet = map.tetrahedra[t];
    const CGAL::Orientation og = CGAL::orientation(map.points[tet[0]], map.points[tet[1]], map.points[tet[2]], map.points[tet[3]]);
    if(og == CGAL::NEGATIVE) ++check.inverted_positions;
    if(og == CGAL::COPLANAR) ++check.degenerate_positions;
    for(int e = 0; e < 6; ++e) {
      const std::uint32_t id = topo.tetrahedron_edges[t][e];
      if(o == CGAL::COPLANAR) { at_degenerate[id] = 1; continue; }
      if(o == CGAL::NEGATIVE) at_inverted[id] = 1;
      const double a = ex::parameter_dihedral_angle(map.parameters[t], e);
      angle_sum[id] += o == CGAL::NEGATIVE ? -a : a;
    }
    for(int f = 0; f < 4; ++f) {
      if(topo.neighbor[t][f] != ex::no_tetrahedron) continue;
      int axis;
      double value, deviation;
      ex::boundary_plane(map, t, f, axis, value, deviation);
      if(deviation > check.max_boundary_deviation) {
        check.max_boundary_deviation = deviation;
        check.worst_boundary_face = ex::sorted_face(map, t, f);
      }
    }
  }
  const double quarter = 1.57079632679489661923;
  for(std::size_t e = 0; e < topo.edges.size(); ++e) {
    const double v = angle_sum[e] / quarter;
    const int valence = int(std::lround(v));
    if(at_degenerate[e]) ++check.edges_at_degenerate_tetrahedra;
    else check.max_valence_deviation = (std::max)(check.max_valence_deviation, std::abs(v - valence));
    if(topo.edge_on_boundary[e]) {
      ++check.boundary_edge_valences[valence];
      check.boundary_edges.push_back({topo.edges[e], valence, at_degenerate[e] != 0});
    } else {
      ++check.interior_edge_valences[valence];
      if(!at_degenerate[e] && !at_inverted[e] && (valence < 3 || valence > 5))
        check.unusual_interior_edges.push_back({topo.edges[e], valence});
    }
  }
  std::sort(check.unusual_interior_edges.begin(), check.unusual_interior_edges.end(),
            [](const auto& a, const auto& b) { return a.vertices < b.vertices; });
  std::sort(check.boundary_edges.begin(), check.boundary_edges.end(),
            [](const auto& a, const auto& b) { return a.vertices < b.vertices; });
  return check;
}

/// \ingroup PkgHexahedralRemeshingRef
/// How many boundary edges of a map have the prescribed valence (`boundary_valence_agreement()`).
struct Boundary_valence_agreement
{
  /// Boundary edges with a prescribed valence.
  std::size_t total = 0;
  /// Those whose valence in the map (parameter-space angle sum / (pi/2)) is the prescribed one.
  std::size_t matched = 0;
  /// Those of the others next to a degenerate tetrahedron of the map (their valence is not reliable).
  std::size_t at_degenerate_tetrahedra = 0;
  /// Prescribed edges that are not boundary edges of the map (a map of another mesh).
  std::size_t missing = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Compares the boundary valences of a map (from `check_integer_grid_map()`) with prescribed ones:
/// `prescribed` lists (vertex id, vertex id, valence) triples, e.g. every boundary edge of the
/// tetrahedral mesh with its valence from `compute_boundary_edge_valences()`.
inline Boundary_valence_agreement
boundary_valence_agreement(const Integer_grid_map_check& check,
                           const std::vector<std::tuple<std::uint32_t, std::uint32_t, int> >& prescribed)
{
  Boundary_valence_agreement a;
  for(const auto& [v0, v1, valence] : prescribed) {
    ++a.total;
    const std::array<std::uint32_t, 2> key = {(std::min)(v0, v1), (std::max)(v0, v1)};
    const auto it = std::lower_bound(check.boundary_edges.begin(), check.boundary_edges.end(), key,
                                     [](const auto& e, const std::array<std::uint32_t, 2>& k) { return e.vertices < k; });
    if(it == check.boundary_edges.end() || it->vertices != key) { ++a.missing; continue; }
    if(it->valence == valence) ++a.matched;
    else if(it->at_degenerate_tetrahedron) ++a.at_degenerate_tetrahedra;
  }
  return a;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Default visitor of `extract_hexahedra()`: every hook does nothing. Derive from it and pass it with
/// the named parameter `visitor` to follow the progress.
struct Hexahedral_extraction_visitor
{
  /// Called when a step starts (`"topology"`, `"sanitize"`, `"vertices"`, `"cells"`).
  void start_stage(const std::string& /*stage*/) {}
  /// Called when a step ends, with its duration in seconds.
  void end_stage(const std::string& /*stage*/, double /*seconds*/) {}
};

/// \ingroup PkgHexahedralRemeshingRef
/// Outcome of `extract_hexahedra()`: counts, the defects met and the time of each step.
struct Hexahedral_extraction_result
{
  /// `OK`: no defect met; `DEFECTS`: the mesh was extracted but some defect below is non-zero (cells may
  /// be missing where the map is broken).
  enum Status {
    OK,     ///< no defect
    DEFECTS ///< extracted with defects
  };
  /// Overall status.
  Status status = OK;
  /// Hexahedra emitted.
  std::size_t hexahedra = 0;
  /// Hex vertices (integer points of the map; some may belong to no emitted hexahedron near defects).
  std::size_t vertices = 0;
  /// Tetrahedra with coplanar parameter points (tolerated: they carry no cell interior).
  std::size_t degenerate_tetrahedra = 0;
  /// Tetrahedra with negatively oriented parameter points (their interiors are skipped).
  std::size_t inverted_tetrahedra = 0;
  /// Tetrahedra with negatively oriented positions (the hexahedra there may be folded in model space).
  std::size_t inverted_positions = 0;
  /// Cell corners that could not be reached from the cell centre through the tetrahedra (the hex
  /// edges that could not be traced).
  std::size_t untraced_corners = 0;
  /// Cells left out because a corner was missing or ambiguous.
  std::size_t incomplete_cells = 0;
  /// Cells whose corners were all found, some as two hex vertices (a fold covers the lattice point
  /// more than once), completed with the vertex their complete neighbours use (not in
  /// `incomplete_cells`).
  std::size_t resolved_cells = 0;
  /// Boundary faces of two cells that share three corners (a crack where the map is flat) glued into one
  /// face by merging their fourth corners; done by `hexahedral_remeshing()` before its smoothing, 0 here.
  std::size_t closed_boundary_cracks = 0;
  /// Cells next to inverted tetrahedra with a corner inverted in space (folds): left out, or kept
  /// with the named parameter `keep_folded_cells`.
  std::size_t folded_cells = 0;
  /// Hex vertices that belong to no emitted cell (spurious copies in folds), removed from the mesh.
  std::size_t removed_vertices = 0;
  /// Cells found twice (from two centres; only the first is kept).
  std::size_t duplicate_cells = 0;
  /// Tetrahedra reached with two different transitions while walking a cell.
  std::size_t inconsistent_walks = 0;
  /// Vertices moved onto the fixed axis of a singular edge while sanitizing.
  std::size_t singular_snaps = 0;
  /// Holonomies without a fixed point, boundary vertices on two different planes, faces whose
  /// transition does not hold exactly after sanitizing.
  std::size_t sanitizing_failures = 0;
  /// Largest change of a parameter by the sanitizing (parameter units).
  double max_sanitizing_move = 0.;
  /// Seconds of the topology and transitions.
  double topology_seconds = 0.;
  /// Seconds of the sanitizing.
  double sanitize_seconds = 0.;
  /// Seconds of the hex vertices and cell centres.
  double vertices_seconds = 0.;
  /// Seconds of the cells.
  double cells_seconds = 0.;
  /// Total seconds.
  double seconds = 0.;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Extracts the hexahedral mesh of an integer-grid map: its hexahedra are the integer unit cubes of
/// parameter space (Lyon, Bommes, Kobbelt 2016, "HexEx: Robust Hexahedral Mesh Extraction"). The map
/// type holds the tetrahedral mesh (positions and tetrahedra), so no separate mesh is passed.
///
/// Steps: (1) topology and transitions, recovered per face when `map.transitions` is empty (see
/// `check_integer_grid_map()`); (2) sanitizing: one reference chart per vertex, parameters on a
/// common dyadic grid, pushed through the transitions, boundary faces snapped onto their integer
/// planes and vertices of singular edges onto the edges' axes, so that every transition holds
/// exactly; (3) hex vertices and cell centres: the points of `Z^3` and `Z^3 + (1/2,1/2,1/2)` on each
/// simplex by the lowest-dimension rule with exact orientation tests (Epick on the sanitized doubles),
/// each identified by its simplex and its coordinates in that simplex's owner chart; (4) cells: from
/// each centre a walk through the tetrahedra covering the open unit cube, across the transitions,
/// finds its 8 corners; a corner found as two hex vertices (a fold covers the lattice point more than
/// once) takes, after all cells, the one that the complete cells use, if exactly one is used and no
/// quad of the cell has two hexahedra already. Positions are barycentric interpolations of the
/// tetrahedra's vertex positions.
///
/// Zero-volume tetrahedra are tolerated; where the map is folded (inverted tetrahedra) the cells that
/// cannot be completed are left out and counted, never emitted broken; complete cells with a corner
/// inverted in space are left out too, unless `keep_folded_cells` (for a mesh that is untangled next).
///
/// \param map the integer-grid map (parameters in hex edges; `map.source` names it in errors)
/// \param hexes the output (overwritten): points, hexahedra in VTK order (positively oriented in the
///        parameter chart), `vertex_locations` (simplex of the tetrahedral mesh), `vertex_tags`
///        (`BOUNDARY` on a boundary face of the tetrahedral mesh), `hexahedron_source_tetrahedra`
///        (the tetrahedron that owns the cell centre)
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{keep_folded_cells}
///     \cgalParamDescription{keep the complete cells next to inverted tetrahedra that have a corner
///       inverted in space (they are counted in `folded_cells` either way); without them a fold leaves
///       a hole, with them inverted hexahedra that `smooth_hexahedral_mesh()` untangles}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress hooks}
///     \cgalParamType{a class with the member functions of `Hexahedral_extraction_visitor`}
///     \cgalParamDefault{`Hexahedral_extraction_visitor()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the counts, defects and seconds
/// \throws Input_error `(map.source, 0, "not an integer-grid map: ...")` naming the face and the value
///         when a transition is not a rotation of the 24-group with an integer translation, or a
///         boundary face is not on an integer plane, within 1e-3 before sanitizing; Input_error for
///         a non-manifold tetrahedral mesh or inconsistent sizes.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
Hexahedral_extraction_result extract_hexahedra(const Integer_grid_map& map, Hexahedral_mesh_3& hexes,
                                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  namespace ex = internal::extraction;
  Hexahedral_extraction_visitor default_visitor;
  auto& visitor = choose_parameter(get_parameter_reference(np, CGAL::internal_np::visitor), default_visitor);
  const double tolerance = 1e-3;

  Hexahedral_extraction_result result;
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  Clock::time_point t0 = start;
  auto seconds = [&t0]() {
    const Clock::time_point t1 = Clock::now();
    const double s = std::chrono::duration<double>(t1 - t0).count();
    t0 = t1;
    return s;
  };
  auto face_name = [&](std::uint32_t t, int f) {
    const auto v = ex::sorted_face(map, t, f);
    return "face (" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + ")";
  };
  auto str = [](double x) { std::ostringstream ss; ss.precision(6); ss << x; return ss.str(); };

  visitor.start_stage("topology");
  ex::Map_topology topo;
  ex::build_map_topology(map, topo);
  ex::Face_transitions tr;
  ex::compute_face_transitions(map, topo, tr);
  if(tr.max_rotation_deviation > tolerance)
    throw Input_error(map.source, 0, "not an integer-grid map: " + face_name(tr.worst_rotation_tet, tr.worst_rotation_face) +
                                         ": the two charts differ by no rotation of the 24-group (misfit " +
                                         str(tr.max_rotation_deviation) + ")");
  if(tr.max_jump_deviation > tolerance)
    throw Input_error(map.source, 0, "not an integer-grid map: " + face_name(tr.worst_jump_tet, tr.worst_jump_face) +
                                         ": the jump is not an integer translation (off by " +
                                         str(tr.max_jump_deviation) + ")");
  for(std::uint32_t t = 0; t < map.tetrahedra.size(); ++t) {
    for(int f = 0; f < 4; ++f) {
      if(topo.neighbor[t][f] != ex::no_tetrahedron) continue;
      int axis;
      double value, deviation;
      ex::boundary_plane(map, t, f, axis, value, deviation);
      if(deviation > tolerance)
        throw Input_error(map.source, 0, "not an integer-grid map: boundary " + face_name(t, f) + " of tetrahedron " +
                                             std::to_string(t) + " is off the integer plane " + "uvw"[axis] + " = " +
                                             str(value) + " by " + str(deviation));
    }
    const auto& tet = map.tetrahedra[t];
    if(CGAL::orientation(map.points[tet[0]], map.points[tet[1]], map.points[tet[2]], map.points[tet[3]]) == CGAL::NEGATIVE)
      ++result.inverted_positions;
  }
  result.topology_seconds = seconds();
  visitor.end_stage("topology", result.topology_seconds);

  visitor.start_stage("sanitize");
  ex::Sanitized_map sm;
  ex::sanitize_map(map, topo, tr, sm);
  result.max_sanitizing_move = sm.max_move;
  result.singular_snaps = sm.singular_snaps;
  result.sanitizing_failures = sm.broken_holonomies + sm.boundary_conflicts + sm.inexact_faces;
  for(const auto& u : sm.parameters) {
    const CGAL::Orientation o = ex::parameter_orientation(u);
    if(o == CGAL::NEGATIVE) ++result.inverted_tetrahedra;
    if(o == CGAL::COPLANAR) ++result.degenerate_tetrahedra;
  }
  result.sanitize_seconds = seconds();
  visitor.end_stage("sanitize", result.sanitize_seconds);

  visitor.start_stage("vertices");
  ex::Lattice_points lp;
  ex::extract_lattice_points(map, topo, sm, tr, lp);
  result.vertices_seconds = seconds();
  visitor.end_stage("vertices", result.vertices_seconds);

  visitor.start_stage("cells");
  hexes.clear();
  ex::Cell_assembly_report cells;
  ex::assemble_hex_cells(map, topo, sm, tr, lp, hexes.hexahedra, hexes.hexahedron_source_tetrahedra, cells,
                         choose_parameter(get_parameter(np, internal_np::keep_folded_cells), false));
  {
    // keep only the vertices of the emitted cells (none is dropped on a valid map)
    std::vector<std::uint32_t> new_id(lp.positions.size(), ex::no_tetrahedron);
    for(auto& h : hexes.hexahedra)
      for(auto& v : h) {
        if(new_id[v] == ex::no_tetrahedron) {
          new_id[v] = std::uint32_t(hexes.points.size());
          hexes.points.push_back(lp.positions[v]);
          hexes.vertex_locations.push_back(lp.locations[v]);
          hexes.vertex_tags.push_back(lp.tags[v]);
        }
        v = new_id[v];
      }
    result.removed_vertices = lp.positions.size() - hexes.points.size();
  }
  result.folded_cells = cells.folded_cells;
  result.untraced_corners = cells.missing_corners;
  result.incomplete_cells = cells.incomplete_cells;
  result.resolved_cells = cells.resolved_cells;
  result.duplicate_cells = cells.duplicate_cells;
  result.inconsistent_walks = cells.inconsistent_walks + cells.truncated_walks;
  result.cells_seconds = seconds();
  visitor.end_stage("cells", result.cells_seconds);

  result.hexahedra = hexes.hexahedra.size();
  result.vertices = hexes.points.size();
  const bool clean = result.inverted_tetrahedra == 0 && result.inverted_positions == 0 && result.untraced_corners == 0 &&
                     result.incomplete_cells == 0 && result.duplicate_cells == 0 &&
                     result.folded_cells == 0 && result.removed_vertices == 0 && result.inconsistent_walks == 0 &&
                     result.sanitizing_failures == 0;
  result.status = clean ? Hexahedral_extraction_result::OK : Hexahedral_extraction_result::DEFECTS;
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_EXTRACTION_H
