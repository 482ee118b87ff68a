// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_SMOOTHING_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_SMOOTHING_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/corner_tet_problem.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/hex_boundary.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/local_smoothing.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/reference_features.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/reference_projector.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/vertex_constraints.h>
#include <CGAL/Hexahedral_remeshing/internal/untangling/foldover_free_map.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// The input boundary a hexahedral mesh is smoothed against (`smooth_hexahedral_mesh()`): a triangle
/// surface, its feature curves as polylines, and its corners, in model units.
struct Hexahedral_smoothing_reference
{
  /// Point type.
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point_3;
  /// Points of the surface triangles.
  std::vector<Point_3> points;
  /// Surface triangles, 3 indices into `points` each (orientation does not matter).
  std::vector<std::array<std::uint32_t, 3> > triangles;
  /// Feature curves, each a polyline (a closed curve repeats its first point at the end). A hex
  /// vertex on a feature curve slides along the polyline it is closest to.
  std::vector<std::vector<Point_3> > feature_polylines;
  /// Corner points: hex vertices there do not move.
  std::vector<Point_3> corners;
};

/// \ingroup PkgHexahedralRemeshingRef
/// The reference of `smooth_hexahedral_mesh()` taken from a tetrahedral mesh: its boundary triangles,
/// its feature edges (`edge_curve(e) >= 0`) chained into polylines, and as corners its `corners()`
/// plus the points where feature curves end, branch or change curve id (a vertex there cannot slide
/// along a single curve).
/// Points are converted to `Hexahedral_smoothing_reference::Point_3` through their `x()`, `y()`, `z()`.
template <class Traits>
Hexahedral_smoothing_reference make_hexahedral_smoothing_reference(const Tetrahedral_mesh_3<Traits>& mesh)
{
  typedef Hexahedral_smoothing_reference::Point_3 Point;
  typedef std::uint32_t Id;
  Hexahedral_smoothing_reference ref;
  const std::size_t V = mesh.number_of_vertices();
  ref.points.reserve(V);
  for(std::size_t v = 0; v < V; ++v) {
    const auto& p = mesh.point(Id(v));
    ref.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  for(std::size_t b = 0; b < mesh.number_of_boundary_triangles(); ++b) {
    const auto& t = mesh.boundary_triangle_vertices(Id(b));
    ref.triangles.push_back({ {Id(t[0]), Id(t[1]), Id(t[2])} });
  }
  // feature graph: incident feature edges per vertex, sorted by edge index (deterministic walks)
  std::vector<std::vector<Id> > incident(V);
  std::vector<Id> feature_edges;
  for(std::size_t e = 0; e < mesh.number_of_edges(); ++e)
    if(mesh.edge_curve(Id(e)) >= 0) {
      feature_edges.push_back(Id(e));
      for(Id v : mesh.edge_vertices(Id(e))) incident[v].push_back(Id(e));
    }
  std::vector<bool> junction(V, false);
  for(Id c : mesh.corners()) junction[c] = true;
  for(std::size_t v = 0; v < V; ++v) {
    const auto& inc = incident[v];
    if(inc.empty()) continue;
    if(inc.size() != 2 || mesh.edge_curve(inc[0]) != mesh.edge_curve(inc[1])) junction[v] = true;
  }
  std::vector<bool> used(mesh.number_of_edges(), false);
  auto other = [&mesh](Id e, Id v) { const auto& ev = mesh.edge_vertices(e); return ev[0] == v ? ev[1] : ev[0]; };
  auto walk = [&](Id start, Id first_edge) {
    std::vector<Point> pl{ ref.points[start] };
    Id v = start, e = first_edge;
    for(;;) {
      used[e] = true;
      v = other(e, v);
      pl.push_back(ref.points[v]);
      if(junction[v] || v == start) break;
      Id next = e;
      for(Id f : incident[v])
        if(!used[f]) { next = f; break; }
      if(next == e) break;
      e = next;
    }
    ref.feature_polylines.push_back(pl);
  };
  for(std::size_t v = 0; v < V; ++v)
    if(junction[v])
      for(Id e : incident[v])
        if(!used[e]) walk(Id(v), e);
  for(Id e : feature_edges) // closed curves without a junction
    if(!used[e]) walk(mesh.edge_vertices(e)[0], e);
  for(std::size_t v = 0; v < V; ++v)
    if(junction[v]) ref.corners.push_back(ref.points[v]);
  return ref;
}

/// \ingroup PkgHexahedralRemeshingRef
/// What `smooth_hexahedral_mesh()` lets move on the boundary.
enum class Hexahedral_smoothing_boundary {
  /// Boundary vertices slide on the reference surface, feature vertices on their curve; corners fixed.
  SLIDE,
  /// Boundary vertices slide on the surface; feature-curve vertices and corners are fixed.
  FIX_FEATURES,
  /// Every boundary vertex is fixed: only interior vertices move.
  FIX_ALL
};

namespace internal_np {
enum smoothing_boundary_t { smoothing_boundary };
enum smoothing_fixed_vertices_t { smoothing_fixed_vertices };
enum smoothing_sharp_angle_t { smoothing_sharp_angle };
} // namespace internal_np

namespace parameters {
#ifdef DOXYGEN_RUNNING
/// Hex smoothing: what moves on the boundary (`Hexahedral_smoothing_boundary`, default `SLIDE`).
template <class T> unspecified_type smoothing_boundary(const T& value);
/// Hex smoothing: vertices that must not move (`std::vector<bool>` indexed by vertex, default empty).
template <class T> unspecified_type smoothing_fixed_vertices(const T& value);
/// Hex smoothing: angle in degrees between the normals of two reference triangles above which their
/// common edge is sharp (`double`, default 60; <= 0: no detection).
template <class T> unspecified_type smoothing_sharp_angle(const T& value);
#else
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(smoothing_boundary)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(smoothing_fixed_vertices)
CGAL_HEXAHEDRAL_REMESHING_NAMED_PARAMETER(smoothing_sharp_angle)
#endif
} // namespace parameters

/// \ingroup PkgHexahedralRemeshingRef
/// Quality of a hexahedral mesh and its faithfulness to the reference (`smooth_hexahedral_mesh()`).
struct Hexahedral_mesh_quality
{
  /// Smallest scaled Jacobian of a hexahedron (`hexahedron_scaled_jacobian()`), in [-1, 1].
  double min_scaled_jacobian = 0;
  /// Mean scaled Jacobian over the hexahedra.
  double mean_scaled_jacobian = 0;
  /// Share (0..1) of hexahedra whose scaled Jacobian is below 0.3.
  double low_quality_share = 0;
  /// Number of hexahedra whose scaled Jacobian is <= 0.
  std::size_t non_positive = 0;
  /// Approximate symmetric Hausdorff distance between the boundary quads and the reference surface
  /// (model units; both sides sampled at vertices, edge midpoints and face centres); -1 if not computed.
  double hausdorff_distance = -1;
  /// Largest distance of a constrained boundary vertex to what it must lie on (the surface, its
  /// feature polyline), model units.
  double max_constraint_distance = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Report of `smooth_hexahedral_mesh()`.
struct Hexahedral_smoothing_report
{
  /// Quality of the input.
  Hexahedral_mesh_quality before;
  /// Quality of the output.
  Hexahedral_mesh_quality after;
  /// True if the input had a hexahedron with scaled Jacobian <= 0 and the untangling stage ran.
  bool untangling_run = false;
  /// Number of interior vertices (free).
  std::size_t interior_vertices = 0;
  /// Number of vertices sliding on the reference surface.
  std::size_t surface_vertices = 0;
  /// Number of vertices sliding on a feature polyline.
  std::size_t curve_vertices = 0;
  /// Number of fixed vertices (corners, fixed by `smoothing_boundary` or `smoothing_fixed_vertices`).
  std::size_t fixed_vertices = 0;
  /// Number of feature polylines detected on the reference by dihedral angle (when it had none).
  std::size_t detected_feature_polylines = 0;
  /// Quality rounds run (optimization + projection onto the reference each).
  int rounds = 0;
  /// The state returned: -1 the input, 0 the untangled state, r >= 1 the state after round r.
  int accepted_state = -1;
  /// Outer (epsilon update) iterations of the foldover-free minimizations, summed.
  int outer_iterations = 0;
  /// Inner (L-BFGS) iterations of the foldover-free minimizations, summed.
  int inner_iterations = 0;
  /// Local untangling sweeps run (see `smooth_hexahedral_mesh()`).
  int untangling_sweeps = 0;
  /// True if the local untangling left inverted hexahedra and the global foldover-free minimization ran.
  bool global_untangling_run = false;
  /// Vertex moves accepted by the local sweeps, summed over the sweeps.
  std::size_t vertex_moves = 0;
  /// Wall-clock seconds.
  double seconds = 0;
};

/// \ingroup PkgHexahedralRemeshingRef
/// The default visitor of `smooth_hexahedral_mesh()`: does nothing. A visitor provides the same two
/// member functions (pass it with `CGAL::parameters::visitor(std::ref(v))` to keep its state).
struct Hexahedral_smoothing_default_visitor
{
  /// After the untangling stage, with the quality reached (`hausdorff_distance` not computed).
  void after_untangling(const Hexahedral_mesh_quality&) {}
  /// After quality round `round` (1-based), with the quality reached and whether this state is the
  /// best acceptable one so far.
  void after_round(int /*round*/, const Hexahedral_mesh_quality&, bool /*accepted*/) {}
};

namespace internal {

inline Hexahedral_mesh_quality hex_mesh_quality(const Hexahedral_mesh_3& mesh, const std::vector<Hex_vertex_constraint>& constraints,
                                                const Reference_projector& reference)
{
  Hexahedral_mesh_quality q;
  const std::vector<double> sj = hexahedra_scaled_jacobians(mesh);
  if(!sj.empty()) {
    q.min_scaled_jacobian = (std::numeric_limits<double>::max)();
    double sum = 0;
    std::size_t low = 0;
    for(double s : sj) {
      q.min_scaled_jacobian = (std::min)(q.min_scaled_jacobian, s);
      sum += s;
      if(s < 0.3) ++low;
      if(s <= 0) ++q.non_positive;
    }
    q.mean_scaled_jacobian = sum / double(sj.size());
    q.low_quality_share = double(low) / double(sj.size());
  }
  for(std::size_t v = 0; v < constraints.size(); ++v) {
    double d = 0;
    if(constraints[v].kind == Hex_vertex_kind::SURFACE)
      d = reference.distance_to_surface(mesh.points[v], constraints[v].patch);
    else if(constraints[v].kind == Hex_vertex_kind::CURVE)
      reference.closest_on_polyline(constraints[v].polyline, mesh.points[v], nullptr, &d);
    q.max_constraint_distance = (std::max)(q.max_constraint_distance, d);
  }
  return q;
}

inline void project_on_reference(std::vector<Hexahedral_mesh_3::Point_3>& points,
                                 const std::vector<Hex_vertex_constraint>& constraints, const Reference_projector& reference)
{
  for(std::size_t v = 0; v < points.size(); ++v) {
    if(constraints[v].kind == Hex_vertex_kind::SURFACE) points[v] = reference.closest_on_surface(points[v], nullptr, constraints[v].patch);
    else if(constraints[v].kind == Hex_vertex_kind::CURVE)
      points[v] = reference.closest_on_polyline(constraints[v].polyline, points[v]);
    else if(constraints[v].kind == Hex_vertex_kind::FIXED && constraints[v].corner < reference.corners().size())
      points[v] = reference.corners()[constraints[v].corner];
  }
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Untangles and smooths a hexahedral mesh in place, keeping its boundary on the reference: boundary
/// vertices on the surface, feature vertices on their feature curve, corner vertices fixed.
///
/// Method. The elements are the 8 corner tetrahedra of each hexahedron (corner `i` and its three
/// neighbours, VTK order), with the ideal element the corner of a cube of the hexahedron's mean edge
/// length, and the energy is the foldover-free energy of Garanzha, Kaporin, Kudryavtseva, Protais, Ray
/// and Sokolov ("Foldover-free maps in 50 lines of code", ACM TOG 2021). Constrained vertices are first
/// put on the reference: boundary vertices on the surface (closest point, CGAL AABB tree, on their own
/// patch between sharp edges), feature vertices on their polyline, corners fixed. (1) Untangling, if a
/// hexahedron has a scaled Jacobian <= 0: local sweeps from the vertices of those hexahedra (each
/// vertex moved alone, a move accepted if it lowers the energy of its star without lowering the star's
/// minimum scaled Jacobian nor adding a non-positive hexahedron), then, if some remain inverted, the
/// global minimization of the energy over the interior vertices with the boundary fixed (LBFGS++,
/// stopped as soon as nothing is inverted). (2) Up to `number_of_iterations` quality sweeps: every
/// vertex in turn takes a damped Newton step of its star's energy (boundary vertices in their tangent
/// plane, feature vertices along their curve, then projected back), accepted only if no hexahedron of
/// the star gets a lower scaled Jacobian than the star's minimum; then the worst hexahedra have their
/// minimum raised directly. The sweeps stop when nothing moves or a sweep gains almost nothing.
/// Which vertex lies on what comes from `hexes.vertex_tags` when it has full size, otherwise from the
/// boundary quads and the distance to the corners and polylines (below 1e-3 of the vertex's shortest
/// hex edge); a reference without feature curves gets its sharp edges (`smoothing_sharp_angle`) as
/// feature curves.
/// The returned state is the best of the untangled state and the sweep states among those whose
/// minimum scaled Jacobian is not lower than the input's (fewest hexahedra with scaled Jacobian
/// <= 0, then constrained vertices on the reference, then highest minimum, then highest mean scaled
/// Jacobian); the input is kept when no state qualifies, so the minimum scaled Jacobian never decreases.
///
/// Only `hexes.points` changes. Library code, never prints.
///
/// \param hexes the hexahedral mesh (VTK order, positively oriented hexahedra have positive scaled Jacobians).
/// \param reference the input boundary (`make_hexahedral_smoothing_reference()` builds it from a tet mesh).
/// \param np optional named parameters among:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{maximum number of quality rounds (`CGAL::parameters::number_of_iterations`);
///       0 only untangles}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`5`}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing_boundary}
///     \cgalParamDescription{what moves on the boundary}
///     \cgalParamType{`Hexahedral_smoothing_boundary`}
///     \cgalParamDefault{`Hexahedral_smoothing_boundary::SLIDE`}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing_fixed_vertices}
///     \cgalParamDescription{per vertex, true if it must not move}
///     \cgalParamType{`std::vector<bool>`}
///     \cgalParamDefault{empty: none besides the boundary rule}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{notified after the untangling and after each round
///       (`CGAL::parameters::visitor`)}
///     \cgalParamType{a class with the member functions of `Hexahedral_smoothing_default_visitor`}
///     \cgalParamDefault{`Hexahedral_smoothing_default_visitor`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the report: quality before and after (min, mean scaled Jacobian, share below 0.3, count
///   <= 0, Hausdorff distance to the reference), rounds, iterations, seconds.
/// \throws Input_error if a hexahedron has a vertex index out of range.
template <class NamedParameters = CGAL::parameters::Default_named_parameters>
Hexahedral_smoothing_report smooth_hexahedral_mesh(Hexahedral_mesh_3& hexes, const Hexahedral_smoothing_reference& reference,
                                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  typedef Hexahedral_mesh_3::Point_3 Point;
  const auto start = std::chrono::steady_clock::now();
  const int iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 10);
  const Hexahedral_smoothing_boundary boundary =
    choose_parameter(get_parameter(np, internal_np::smoothing_boundary), Hexahedral_smoothing_boundary::SLIDE);
  const std::vector<bool> user_fixed =
    choose_parameter(get_parameter(np, internal_np::smoothing_fixed_vertices), std::vector<bool>());
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::visitor_t, NamedParameters,
                                                             Hexahedral_smoothing_default_visitor>::reference Visitor_ref;
  Hexahedral_smoothing_default_visitor default_visitor;
  Visitor_ref visitor = choose_parameter(get_parameter_reference(np, CGAL::internal_np::visitor), default_visitor);

  const std::size_t V = hexes.number_of_vertices();
  for(std::size_t h = 0; h < hexes.number_of_hexahedra(); ++h)
    for(std::uint32_t v : hexes.hexahedra[h])
      if(v >= V)
        throw Input_error("<memory>", 0, "hexahedron " + std::to_string(h) + ": vertex index " + std::to_string(v) +
                                             " out of range (" + std::to_string(V) + " vertices)");

  const double sharp_angle = choose_parameter(get_parameter(np, internal_np::smoothing_sharp_angle), 60.);

  Hexahedral_smoothing_report report;
  // the surface patches between sharp edges (given curves, and by dihedral angle); without given
  // curves the sharp edges become the feature curves (a reference read from a surface file)
  Hexahedral_smoothing_reference augmented = reference;
  std::vector<int> patches;
  if(sharp_angle > 0) {
    patches = internal::reference_patches(augmented, sharp_angle * CGAL_PI / 180., reference.feature_polylines.empty());
    report.detected_feature_polylines = augmented.feature_polylines.size() - reference.feature_polylines.size();
  }
  const internal::Reference_projector projector(augmented, patches);
  const std::vector<std::array<std::uint32_t, 4> > quads = internal::hex_boundary_quads(hexes);
  const int keep = boundary == Hexahedral_smoothing_boundary::SLIDE ? 0 : (boundary == Hexahedral_smoothing_boundary::FIX_FEATURES ? 1 : 2);
  const std::vector<internal::Hex_vertex_constraint> constraints =
    internal::classify_hex_vertices(hexes, quads, projector, keep, user_fixed);
  for(const auto& c : constraints) {
    switch(c.kind) {
    case internal::Hex_vertex_kind::INTERIOR: ++report.interior_vertices; break;
    case internal::Hex_vertex_kind::SURFACE: ++report.surface_vertices; break;
    case internal::Hex_vertex_kind::CURVE: ++report.curve_vertices; break;
    default: ++report.fixed_vertices;
    }
  }
  report.before = internal::hex_mesh_quality(hexes, constraints, projector);
  report.before.hausdorff_distance = internal::hex_boundary_hausdorff_distance(hexes.points, quads, projector);
  if(hexes.number_of_hexahedra() == 0) {
    report.after = report.before;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
  }

  const std::vector<double> size = internal::hex_mean_edge_lengths(hexes);
  const double on_reference_tolerance = 1e-9 * (std::max)(projector.diagonal(), 1e-300);
  Hexahedral_mesh_3 work;
  work.hexahedra = hexes.hexahedra;
  work.points = hexes.points;

  // best acceptable state: min SJ >= the input's; then fewest SJ <= 0, on the reference, mean SJ
  std::vector<Point> best_points = hexes.points;
  Hexahedral_mesh_quality best_quality = report.before;
  bool have_candidate = false;
  // q1 better than q2: fewer SJ <= 0, then on the reference, then min SJ higher by more than 1e-3,
  // then mean SJ higher
  auto better_than = [on_reference_tolerance](const Hexahedral_mesh_quality& q1, const Hexahedral_mesh_quality& q2) {
    if(q1.non_positive != q2.non_positive) return q1.non_positive < q2.non_positive;
    const bool on1 = q1.max_constraint_distance <= on_reference_tolerance;
    const bool on2 = q2.max_constraint_distance <= on_reference_tolerance;
    if(on1 != on2) return on1;
    if(std::abs(q1.min_scaled_jacobian - q2.min_scaled_jacobian) > 1e-3)
      return q1.min_scaled_jacobian > q2.min_scaled_jacobian;
    return q1.mean_scaled_jacobian > q2.mean_scaled_jacobian;
  };
  auto better = [&](const Hexahedral_mesh_quality& q) {
    if(!(q.min_scaled_jacobian >= report.before.min_scaled_jacobian)) return false;
    return !have_candidate || better_than(q, best_quality);
  };
  auto offer = [&](const Hexahedral_mesh_quality& q, int state) {
    if(!better(q)) return false;
    have_candidate = true;
    best_quality = q;
    best_points = work.points;
    report.accepted_state = state;
    return true;
  };
  // the input itself competes (on the reference already, it may be the best)
  offer(report.before, -1);

  auto minimize = [&](bool boundary_fixed, const internal::Foldover_free_options& options) {
    const internal::Hex_vertex_dofs dofs = internal::make_hex_vertex_dofs(work.points, constraints, projector, boundary_fixed);
    if(dofs.n == 0) return;
    const internal::Foldover_free_problem problem = internal::make_corner_tet_problem(work, work.points, dofs, size, 0.);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(dofs.n);
    const internal::Foldover_free_result r = internal::minimize_foldover_free(problem, y, options);
    report.outer_iterations += r.outer_iterations;
    report.inner_iterations += r.inner_iterations;
    internal::apply_hex_vertex_dofs(dofs, y, work.points);
  };

  // constrained vertices off the reference are put on it first: every later move keeps them there
  internal::project_on_reference(work.points, constraints, projector);
  Hexahedral_mesh_quality current = internal::hex_mesh_quality(work, constraints, projector);
  const std::size_t max_sweeps = std::size_t((std::max)(iterations, 0));
  internal::Local_smoothing_options local_options;
  std::vector<char> active(V, 1);

  if(current.non_positive > 0) {
    report.untangling_run = true;
    {
      // local untangling: the sweeps only accept moves that lower no star's minimum scaled Jacobian
      // nor add a non-positive hexahedron; a few sweeps repair isolated foldovers
      internal::Local_hex_smoother smoother(work, constraints, projector, size, local_options);
      // start from the vertices of the hexahedra with SJ <= 0 and their neighbours: the sweeps then
      // spread only as far as vertices move
      std::fill(active.begin(), active.end(), char(0));
      for(std::size_t h = 0; h < work.number_of_hexahedra(); ++h)
        if(smoother.scaled_jacobians()[h] <= 0)
          for(std::uint32_t v : work.hexahedra[h])
            for(std::uint32_t k = smoother.stars().offset[v]; k < smoother.stars().offset[v + 1]; ++k)
              for(std::uint32_t w : work.hexahedra[smoother.stars().hex[k]]) active[w] = 1;
      for(int s = 0; s < 20; ++s) {
        ++report.untangling_sweeps;
        const std::size_t moves = smoother.sweep(active);
        report.vertex_moves += moves;
        std::size_t bad = 0;
        for(double x : smoother.scaled_jacobians()) bad += x <= 0 ? 1 : 0;
        if(bad == 0 || moves == 0) break;
      }
    }
    current = internal::hex_mesh_quality(work, constraints, projector);
    if(current.non_positive > 0) {
      // what the stars could not repair alone: the global foldover-free minimization of the interior
      // (boundary fixed), stopped as soon as nothing is inverted
      internal::Foldover_free_options untangling;
      untangling.stop_when_untangled = true;
      // capped: with the boundary fixed some foldovers cannot be repaired, and the minimization
      // would otherwise run its full schedule for nothing
      untangling.max_outer_iterations = 10;
      untangling.max_inner_iterations = 200;
      minimize(true, untangling);
      current = internal::hex_mesh_quality(work, constraints, projector);
      report.global_untangling_run = true;
    }
    offer(current, 0);
    visitor.after_untangling(current);
    std::fill(active.begin(), active.end(), char(1));
  }

  if(max_sweeps > 0) {
    internal::Local_hex_smoother smoother(work, constraints, projector, size, local_options);
    for(std::size_t sweep = 1; sweep <= max_sweeps; ++sweep) {
      std::size_t moves = smoother.sweep(active);
      // the worst hexahedra: their minimum raised directly (the energy averages over the corners)
      double worst = (std::numeric_limits<double>::max)();
      for(double x : smoother.scaled_jacobians()) worst = (std::min)(worst, x);
      const std::size_t raised = smoother.raise_minimum_pass((std::min)(local_options.quality_floor, worst + 0.1));
      moves += raised;
      report.vertex_moves += moves;
      report.rounds = int(sweep);
      const Hexahedral_mesh_quality q = internal::hex_mesh_quality(work, constraints, projector);
      const bool accepted = offer(q, int(sweep));
      visitor.after_round(int(sweep), q, accepted);
      // early exit: nothing moved, or a sweep that gains almost nothing
      const bool stalled = q.min_scaled_jacobian <= current.min_scaled_jacobian + 1e-6 &&
                           q.mean_scaled_jacobian <= current.mean_scaled_jacobian + 1e-4;
      current = q;
      if(moves == 0 || stalled) break;
    }
  }

  hexes.points = best_points;
  report.after = best_quality;
  report.after.hausdorff_distance = internal::hex_boundary_hausdorff_distance(hexes.points, quads, projector);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_SMOOTHING_H
