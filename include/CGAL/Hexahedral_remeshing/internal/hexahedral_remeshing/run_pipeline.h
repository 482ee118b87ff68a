// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_RUN_PIPELINE_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_RUN_PIPELINE_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_remeshing_result.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_smoothing.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/reference_projector.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/close_boundary_cracks.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_remeshing/feature_fidelity.h>
#include <CGAL/Hexahedral_remeshing/internal/wall_thickness.h>

#include <CGAL/Named_function_parameters.h>

#include <chrono>
#include <functional>
#include <array>
#include <memory>
#include <cmath>
#include <sstream>
#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// What close_boundary_cracks() asks of the input solid `mesh`: how far a point is inside it (its distance
// to the boundary, an AABB tree of the boundary triangles, if a tetrahedron holds it by exact orientations
// against those whose box holds it, else minus that distance), and which feature curves of its boundary
// pass within a distance of a point. The tree, the curves and the tetrahedra are built at the first query
// (most runs have no crack); the queries refer to `mesh`, which must outlive them.
struct Solid_queries
{
  std::function<double(const Hexahedral_mesh_3::Point_3&)> depth;
  std::function<std::vector<std::size_t>(const Hexahedral_mesh_3::Point_3&, double)> feature_curves_near;
};

template <class Traits>
Solid_queries solid_queries_of_tetrahedral_mesh(const Tetrahedral_mesh_3<Traits>& mesh)
{
  typedef Hexahedral_mesh_3::Point_3 Point;
  struct State
  {
    std::unique_ptr<Reference_projector> projector;
    std::vector<std::array<Point, 4> > tetrahedra;
  };
  auto state = std::make_shared<State>();
  auto build = [&mesh, state]() {
    if(state->projector) return;
    state->projector.reset(new Reference_projector(make_hexahedral_smoothing_reference(mesh)));
    state->tetrahedra.reserve(mesh.number_of_tetrahedra());
    for(std::uint32_t t = 0; t < mesh.number_of_tetrahedra(); ++t) {
      std::array<Point, 4> c;
      for(std::size_t i = 0; i < 4; ++i) {
        const auto& v = mesh.point(mesh.tetrahedron_vertices(t)[i]);
        c[i] = Point(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
      }
      state->tetrahedra.push_back(c);
    }
  };
  auto inside = [state](const Point& q) {
    for(const auto& c : state->tetrahedra) {
      if(!CGAL::do_overlap(q.bbox(), c[0].bbox() + c[1].bbox() + c[2].bbox() + c[3].bbox())) continue;
      const CGAL::Orientation o = CGAL::orientation(c[0], c[1], c[2], c[3]);
      if(o == CGAL::COPLANAR) continue;
      bool in = true;
      for(std::size_t i = 0; i < 4 && in; ++i) {
        std::array<Point, 4> d = c;
        d[i] = q;
        const CGAL::Orientation oi = CGAL::orientation(d[0], d[1], d[2], d[3]);
        in = oi == o || oi == CGAL::COPLANAR;
      }
      if(in) return true;
    }
    return false;
  };
  Solid_queries queries;
  queries.depth = [state, build, inside](const Point& p) {
    build();
    const double d = state->projector->has_surface() ? state->projector->distance_to_surface(p) : 0.;
    return inside(p) ? d : -d;
  };
  queries.feature_curves_near = [state, build](const Point& p, double distance) {
    build();
    std::vector<std::size_t> curves;
    for(std::size_t c = 0; c < state->projector->number_of_polylines(); ++c) {
      double d = distance + 1;
      if(state->projector->has_polyline(c)) state->projector->closest_on_polyline(c, p, nullptr, &d);
      if(d <= distance) curves.push_back(c);
    }
    return curves;
  };
  return queries;
}

template <class Traits>
double tetrahedral_mesh_volume(const Tetrahedral_mesh_3<Traits>& mesh)
{
  double v = 0;
  for(std::size_t t = 0; t < mesh.number_of_tetrahedra(); ++t) {
    const auto& tv = mesh.tetrahedron_vertices(typename Tetrahedral_mesh_3<Traits>::Index(t));
    v += CGAL::to_double(CGAL::volume(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]), mesh.point(tv[3])));
  }
  return v;
}

// Relative Hausdorff distance above which a hex mesh does not remesh the solid (chord sag of a coarse
// mesh of the shipped cylinder: 0.013).
constexpr double maximum_relative_hausdorff_distance = 0.05;

// Scaled Jacobian below which a hexahedron that the check finds positive is flat all the same: a
// solver's element matrix is singular there (n03c after the untangling: 4.6e-15).
constexpr double minimum_scaled_jacobian = 1e-6;

// The hex edge length the pipeline uses on `mesh`: target_edge_length, else the one of
// number_of_hexahedra hexahedra, else the map's default (about 2000 hexahedra).
template <class Traits, class NamedParameters>
double pipeline_hex_edge_length(const Tetrahedral_mesh_3<Traits>& mesh, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double h = choose_parameter(get_parameter(np, internal_np::target_edge_length), 0.);
  if(h > 0) return h;
  const double n = double(choose_parameter(get_parameter(np, internal_np::number_of_hexahedra), std::size_t(0)));
  return std::cbrt(tetrahedral_mesh_volume(mesh) / (n > 0 ? n : 2000.));
}

// Largest tetrahedron volume for a tetrahedralization at the hex size h: h^3 / 6 (some 30
// tetrahedra per hexahedron), but never more than 2e6 tetrahedra; 0 (no bound) for an invalid h.
inline double hex_size_tetrahedron_volume(double volume, double h)
{
  if(!(h > 0) || !std::isfinite(h) || !(volume > 0)) return 0;
  return (std::max)(h * h * h / 6, volume / 2e6);
}

template <class Traits>
double bounding_box_diagonal(const Tetrahedral_mesh_3<Traits>& mesh)
{
  if(mesh.number_of_vertices() == 0) return 0;
  const CGAL::Bbox_3 b = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

// The first stage of a failed run whose output is already broken, and why (design notes §5): the
// field's local check, then the continuous map, the rounded map, the extraction, the smoothing.
// Where the seamless map folds (empty if it does not): what tells the field's defects from the constraints.
inline std::string seamless_fold_phrase(const Integer_grid_map_result& m)
{
  if(m.seamless_folds.empty()) return std::string();
  const Seamless_fold_causes& c = m.seamless_fold_causes;
  return "; the seamless map folds " + std::to_string(c.total()) + " tetrahedra: " + std::to_string(c.at_field_defects) +
         " at the field's defects, " + std::to_string(c.structural_at_boundary + c.structural_inside) +
         " flat in every map (" + std::to_string(c.structural_at_boundary) + " at the boundary), " +
         std::to_string(c.at_boundary + c.inside) + " others (" + std::to_string(c.at_boundary) + " at the boundary)" +
         (m.seamless_wrapped_boundary_vertices.empty()
            ? std::string()
            : "; it wraps the boundary around " + std::to_string(m.seamless_wrapped_boundary_vertices.size()) + " vertices (" +
                std::to_string(m.seamless_folds_at_wrapped_boundary) + " folds there)");
}

inline void name_failed_stage(Hexahedral_remeshing_result& r)
{
  const Local_meshability_report& m = r.frame_field.meshability;
  if(m.graph_defects() > 0) {
    std::string reasons;
    for(std::size_t k = 0; k < m.counts.size(); ++k)
      if(m.counts[k] > 0 && Meshability_reason(k) != Meshability_reason::DISAGREEING_FACE && Meshability_reason(k) != Meshability_reason::FEATURE_SECTOR)
        reasons += (reasons.empty() ? "" : ", ") + std::string(meshability_reason_name(Meshability_reason(k))) + " " + std::to_string(m.counts[k]);
    r.failed_stage = "frame_field";
    r.failure_reason = "the singularity graph is not locally meshable after the repair (" + reasons + ")" + seamless_fold_phrase(r.map);
  } else if(!r.map.seamless_injective && r.map.inverted_tetrahedra + r.map.degenerate_tetrahedra > 0) {
    r.failed_stage = "seamless_map";
    r.failure_reason = "the seamless map is not injective before rounding (" + std::to_string(r.map.seamless_inverted_tetrahedra) +
                       " inverted and " + std::to_string(r.map.seamless_degenerate_tetrahedra) + " flat tetrahedra after its untangling" +
                       (r.map.seamless_branched_edges ? ", " + std::to_string(r.map.seamless_branched_edges) + " branched interior edges" : std::string()) +
                       "); " +
                       std::to_string(r.map.inverted_tetrahedra) + " inverted and " + std::to_string(r.map.degenerate_tetrahedra) +
                       " flat in the final map" + seamless_fold_phrase(r.map);
  } else if(r.map.inverted_tetrahedra + r.map.degenerate_tetrahedra > 0) {
    r.failed_stage = "rounding";
    r.failure_reason = "the rounded map folds " + std::to_string(r.map.rounded_inverted_tetrahedra) + " tetrahedra; " +
                       std::to_string(r.map.inverted_tetrahedra) + " inverted and " + std::to_string(r.map.degenerate_tetrahedra) +
                       " flat after the repair of the folds" +
                       (r.map.quantization_reason.empty() ? std::string() : "; separation: " + r.map.quantization_reason);
  } else if(r.map.branched_edges > 0) {
    r.failed_stage = "rounding";
    r.failure_reason = "every tetrahedron of the map is positive, but it is branched around " + std::to_string(r.map.branched_edges) +
                       " interior edges (parameter angle sums other than 3, 4 or 5 quarter turns) after the repair of the folds";
  } else if(r.extraction.incomplete_cells + r.extraction.untraced_corners > 0) {
    r.failed_stage = "extraction";
    r.failure_reason = std::to_string(r.extraction.incomplete_cells) + " cells and " + std::to_string(r.extraction.untraced_corners) +
                       " corners of the map could not be completed";
  } else if(r.check.inverted_hexahedra > 0) {
    r.failed_stage = "smoothing";
    r.failure_reason = std::to_string(r.check.inverted_hexahedra) + " hexahedra still inverted after the untangling";
  } else {
    r.failed_stage = "check";
    r.failure_reason = r.message;
  }
}

// The wall thickness of the solid of a tetrahedral mesh (its boundary triangles are oriented outward).
template <class Traits>
Wall_thickness tetrahedral_mesh_wall_thickness(const Tetrahedral_mesh_3<Traits>& mesh)
{
  std::vector<std::array<std::uint32_t, 3> > triangles;
  triangles.reserve(mesh.number_of_boundary_triangles());
  for(std::size_t b = 0; b < mesh.number_of_boundary_triangles(); ++b) {
    const auto& t = mesh.boundary_triangle_vertices(typename Tetrahedral_mesh_3<Traits>::Index(b));
    triangles.push_back({ {std::uint32_t(t[0]), std::uint32_t(t[1]), std::uint32_t(t[2])} });
  }
  return wall_thickness(mesh.points(), triangles);
}

// The hex edge length the map is asked for (0: the map's own default), after refusing, before any work,
// walls thinner than half a hexahedron (they round to no layer) and sizes that would make more
// hexahedra than fit in memory.
template <class Traits, class NamedParameters>
double checked_map_edge_length(const Tetrahedral_mesh_3<Traits>& mesh, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  {
    const double h = pipeline_hex_edge_length(mesh, np);
    const Wall_thickness w = tetrahedral_mesh_wall_thickness(mesh);
    if(w.thickness < minimum_wall_thickness_over_hex_edge * h)
      throw Input_error(mesh.source(), 0, thin_wall_for_hexahedra_message(w.thickness, w.where(), h, tetrahedral_mesh_volume(mesh)));
  }
  // Hex size: target_edge_length, else number_of_hexahedra, else the map's own default.
  double h = choose_parameter(get_parameter(np, internal_np::target_edge_length), 0.);
  const double n = double(choose_parameter(get_parameter(np, internal_np::number_of_hexahedra), std::size_t(0)));
  if(!(h > 0) && n > 0) h = std::cbrt(tetrahedral_mesh_volume(mesh) / n);
  if(h > 0) {
    const double estimate = tetrahedral_mesh_volume(mesh) / (h * h * h);
    if(estimate > 2e7)
      throw Input_error(mesh.source(), 0, "target_edge_length " + std::to_string(h) + " would give about " +
                                              std::to_string(std::llround(estimate)) +
                                              " hexahedra (at most 2e7): choose a larger edge length");
  }
  return h;
}

// The untangling and smoothing of the extracted hexahedra (its own parameters passed on; its visitor
// hooks differ: the stage is reported here).
template <class Traits, class NamedParameters, class Visitor>
void smooth_extracted_hexahedra(const Tetrahedral_mesh_3<Traits>& mesh, Hexahedral_mesh_3& hexes, const NamedParameters& np,
                                Visitor& visitor, Hexahedral_remeshing_result& r)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  visitor.start_stage("hex smoothing");
  const auto t = std::chrono::steady_clock::now();
  r.smoothing = smooth_hexahedral_mesh(
    hexes, make_hexahedral_smoothing_reference(mesh),
    parameters::smoothing_sharp_angle(
      choose_parameter(get_parameter(np, internal_np::smoothing_sharp_angle), 30.),
      parameters::smoothing_boundary(
        choose_parameter(get_parameter(np, internal_np::smoothing_boundary), Hexahedral_smoothing_boundary::SLIDE),
        CGAL::parameters::number_of_iterations(
          choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 10)))));
  r.smoothed = true;
  visitor.end_stage("hex smoothing", std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
}

// The check of the hex mesh: validity, feature fidelity, distance and volume to the solid, boundary groups.
template <class Traits, class NamedParameters, class Visitor>
void check_extracted_hexahedra(const Tetrahedral_mesh_3<Traits>& mesh, Hexahedral_mesh_3& hexes, const NamedParameters& np,
                               Visitor& visitor, Hexahedral_remeshing_result& r)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  visitor.start_stage("check");
  const auto t = std::chrono::steady_clock::now();
  r.check = check_hexahedral_mesh(hexes, parameters::flat_scaled_jacobian_threshold(minimum_scaled_jacobian));
  const double diagonal = bounding_box_diagonal(mesh);
  const Feature_fidelity f = measure_feature_fidelity(mesh, r.frame_field.valences, hexes, 1e-6 * diagonal);
  r.feature_length = f.feature_length;
  r.feature_coverage = f.feature_length > 0 ? f.covered_length / f.feature_length : 1.;
  r.hex_feature_edges = f.hex_feature_edges;
  r.hex_feature_edges_with_prescribed_valence = f.valence_matched;
  if(r.smoothed && r.smoothing.after.hausdorff_distance >= 0 && diagonal > 0)
    r.relative_hausdorff_distance = r.smoothing.after.hausdorff_distance / diagonal;
  const double volume = tetrahedral_mesh_volume(mesh);
  r.volume_ratio = volume > 0 ? r.check.total_volume / volume : 0.;
  // the groups a solver puts its loads on, read from the final positions
  r.boundary_groups = compute_hexahedral_boundary_groups(
    hexes, mesh, choose_parameter(get_parameter(np, internal_np::smoothing_sharp_angle), 30.));
  r.check_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  visitor.end_stage("check", r.check_seconds);
}

// The status of a checked hex mesh and, if it is not OK, the message and the stage it failed at.
template <class Traits>
void decide_remeshing_status(const Tetrahedral_mesh_3<Traits>& mesh, Hexahedral_remeshing_result& r)
{
  const std::size_t missing = r.extraction.incomplete_cells + r.extraction.untraced_corners;
  // Cells dropped inside a fold of the map leave a closed cavity: a valid-looking mesh whose boundary
  // has more components (or another genus) than the solid's.
  const bool same_topology = r.check.boundary_components == mesh.number_of_boundary_components() &&
                             r.check.boundary_euler_characteristic == mesh.boundary_euler_characteristic();
  // A slit along a seam (cells on both sides, no cell across) keeps the topology but puts boundary
  // quads deep inside the solid: the boundary is then far from the input's.
  const bool follows_boundary = !(r.relative_hausdorff_distance > maximum_relative_hausdorff_distance);
  // valid but for flat hexahedra (the check counts them apart from the inverted ones)
  const bool flat_only = !r.check.valid && r.check.flat_hexahedra > 0 && r.check.inverted_hexahedra == 0 &&
                         r.check.invalid_hexahedra == 0 && r.check.conforming && r.check.manifold_boundary &&
                         r.check.duplicate_vertices == 0 && r.check.duplicate_hexahedra == 0;
  if(r.check.valid && missing == 0 && same_topology && follows_boundary) {
    r.status = Hexahedral_remeshing_status::OK;
    return;
  }
  r.status = Hexahedral_remeshing_status::INVALID_HEX_MESH;
  if(flat_only && missing == 0) {
    std::ostringstream os;
    os << r.check.flat_hexahedra << " hexahedra are flat (min scaled Jacobian " << r.check.min_scaled_jacobian << ", below "
       << minimum_scaled_jacobian << ") where the integer-grid map is " << status_name(r.map.status);
    r.message = os.str();
  } else if(r.check.valid && missing == 0 && same_topology) {
    std::ostringstream os;
    os << "the boundary of the hex mesh is " << r.relative_hausdorff_distance
       << " of the diagonal away from the solid's (at most " << maximum_relative_hausdorff_distance
       << "): boundary quads inside the solid where the integer-grid map is " << status_name(r.map.status);
    r.message = os.str();
  } else if(r.check.valid && missing == 0) {
    r.message = "the boundary of the hex mesh has " + std::to_string(r.check.boundary_components) +
                " components and Euler characteristic " + std::to_string(r.check.boundary_euler_characteristic) +
                ", the solid's " + std::to_string(mesh.number_of_boundary_components()) + " and " +
                std::to_string(mesh.boundary_euler_characteristic()) + " (cells missing where the integer-grid map is " +
                status_name(r.map.status) + ")";
  } else {
    r.message = std::to_string(r.check.inverted_hexahedra) + " inverted hexahedra (min scaled Jacobian " +
                std::to_string(r.check.min_scaled_jacobian) + "), " + std::to_string(r.check.non_conforming_quads) +
                " non-conforming quads, " +
                (r.check.manifold_boundary ? std::string()
                                           : "a non-manifold boundary (" + std::to_string(r.check.non_manifold_boundary_edges) +
                                               " edges, " + std::to_string(r.check.non_manifold_boundary_vertices) + " vertices), ") +
                std::to_string(r.extraction.incomplete_cells) +
                " cells left out by the extraction (hex volume " + std::to_string(r.volume_ratio) +
                " of the solid's); integer-grid map status " + status_name(r.map.status);
  }
  name_failed_stage(r);
}

// The paper's pipeline on a tetrahedral mesh: frame field (valences, constraints, field, matchings,
// realignment, repair) -> integer-grid map -> extraction -> untangling and smoothing -> check. Data flows
// forward: each stage reads only the outputs of the stages before it.
template <class Traits, class NamedParameters>
Hexahedral_remeshing_result run_pipeline_once(const Tetrahedral_mesh_3<Traits>& mesh, Hexahedral_mesh_3& hexes,
                                              const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::get_parameter_reference;
  const auto start = std::chrono::steady_clock::now();
  auto seconds = [&]() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  Hexahedral_remeshing_visitor default_visitor;
  auto& visitor = choose_parameter(get_parameter_reference(np, CGAL::internal_np::visitor), default_visitor);

  Hexahedral_remeshing_result r;
  hexes.clear();
  r.tetrahedra = mesh.number_of_tetrahedra();
  const double h = checked_map_edge_length(mesh, np);
  // the band that keeps singular curves off acute edges of valence 1: two hexahedra wide unless given
  double band = choose_parameter(get_parameter(np, internal_np::acute_edge_band_radius), -1.);
  if(band < 0) band = 2 * pipeline_hex_edge_length(mesh, np);
  // the repair removes curves that have no room at the hex size
  const double repair_h = choose_parameter(get_parameter(np, internal_np::repair_hex_edge_length), pipeline_hex_edge_length(mesh, np));
  r.frame_field = compute_frame_field_pipeline(mesh, parameters::repair_hex_edge_length(repair_h, parameters::acute_edge_band_radius(band, np)));

  Integer_grid_map own_map;
  Integer_grid_map& map = choose_parameter(get_parameter_reference(np, internal_np::integer_grid_map_output), own_map);
  if(h > 0)
    r.map = compute_integer_grid_map(mesh, r.frame_field.frames, r.frame_field.matchings, r.frame_field.singularities,
                                     map, parameters::target_edge_length(h, np));
  else
    r.map = compute_integer_grid_map(mesh, r.frame_field.frames, r.frame_field.matchings, r.frame_field.singularities,
                                     map, np);
  r.map_check = check_integer_grid_map(map);
  // the smoothing untangles: a folded cell kept is repaired there, one left out would be a hole
  const bool smoothing = choose_parameter(get_parameter(np, internal_np::hexahedral_smoothing), true);
  r.extraction = extract_hexahedra(
    map, hexes, parameters::keep_folded_cells(choose_parameter(get_parameter(np, internal_np::keep_folded_cells), smoothing), np));
  if(hexes.number_of_hexahedra() == 0) {
    r.status = Hexahedral_remeshing_status::NO_HEXAHEDRA;
    r.message = std::string("the integer-grid map (status ") + status_name(r.map.status) +
                ", " + std::to_string(r.map.inverted_tetrahedra) + " inverted tetrahedra) has no complete integer cell";
    name_failed_stage(r);
    r.seconds = seconds();
    return r;
  }
  // smoothing cannot fill the cells the extraction left out: an incomplete mesh is reported as it is;
  // the smoothing places the vertices that close the cracks
  if(r.extraction.incomplete_cells + r.extraction.untraced_corners == 0 && smoothing) {
    const Solid_queries solid = solid_queries_of_tetrahedral_mesh(mesh);
    r.extraction.closed_boundary_cracks = close_boundary_cracks(hexes, solid.depth, solid.feature_curves_near);
    smooth_extracted_hexahedra(mesh, hexes, np, visitor, r);
  }
  check_extracted_hexahedra(mesh, hexes, np, visitor, r);
  decide_remeshing_status(mesh, r);
  r.seconds = seconds();
  return r;
}

// Hands the map and hex mesh of a run that replaces the first one to the caller: the map to
// `integer_grid_map_output` (if given), the hexahedra to `hexes`.
template <class NamedParameters>
void adopt_map_and_hexahedra(const NamedParameters& np, Integer_grid_map& other_map, Hexahedral_mesh_3& other_hexes,
                             Hexahedral_mesh_3& hexes)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter_reference;
  Integer_grid_map own_map;
  Integer_grid_map& map = choose_parameter(get_parameter_reference(np, internal_np::integer_grid_map_output), own_map);
  map = std::move(other_map);
  hexes = std::move(other_hexes);
}

// The pipeline with the named parameters `np`, kept in place of `r` (with its hex mesh and map) if its hex
// mesh is valid; `r`'s seconds are added to the result kept either way.
template <class Traits, class NamedParameters, class OtherParameters>
bool keep_if_valid(const Tetrahedral_mesh_3<Traits>& mesh, Hexahedral_mesh_3& hexes, const NamedParameters& np,
                   const OtherParameters& other_np, Hexahedral_remeshing_result& r)
{
  Hexahedral_mesh_3 other_hexes;
  Integer_grid_map other_map;
  Hexahedral_remeshing_result other =
    run_pipeline_once(mesh, other_hexes, parameters::integer_grid_map_output(std::ref(other_map), other_np));
  if(other.status != Hexahedral_remeshing_status::OK) {
    r.seconds += other.seconds;
    return false;
  }
  adopt_map_and_hexahedra(np, other_map, other_hexes, hexes);
  other.repaired_field_outcome = std::string(status_name(r.status)) + " (failed at the " + r.failed_stage + " stage): " + r.message;
  other.seconds += r.seconds;
  r = std::move(other);
  return true;
}

// The pipeline; where the repaired field (the default) gives no valid hex mesh but changed the field, the
// repair of one round (if it ran more), the repair of one round without the sweeps (if it swept curves) and
// then the field without the repair are tried too, and
// the first with a valid hex mesh is kept. The repair's acceptance compares the graph's defects, which do
// not decide alone whether the map folds where the extraction and the smoothing cannot recover (the
// stepped shaft: the repair takes its jogs from 67 to 15 and its flat tetrahedra from 105 to 0, yet 3
// inverted ones leave 69 inverted hexahedra, where the 2 inverted and 105 flat of the unrepaired map give
// a valid mesh; the icosahedron n15c: valid with the short changes, not with the sweeps): so neither the
// repair nor its sweeps by default ever cost a mesh.
template <class Traits, class NamedParameters>
Hexahedral_remeshing_result run_hexahedral_remeshing(const Tetrahedral_mesh_3<Traits>& mesh, Hexahedral_mesh_3& hexes,
                                                     const NamedParameters& np)
{
  Hexahedral_remeshing_result r = run_pipeline_once(mesh, hexes, np);
  if(r.status == Hexahedral_remeshing_status::OK || !r.frame_field.repaired || !r.frame_field.repair.accepted) return r;
  // then the first round's field alone, and the fallbacks from it (the torus s16c: valid from its first
  // round without the sweeps, not from its three rounds)
  const bool rounds = r.frame_field.repair.rounds > 1;
  const auto one_round = parameters::maximum_repair_rounds(1, np);
  if(rounds && keep_if_valid(mesh, hexes, np, one_round, r)) {
    r.rounds_fallback = true;
    return r;
  }
  if(r.frame_field.repair.swept_curves > 0 && keep_if_valid(mesh, hexes, np, parameters::repair_sweeps(false, one_round), r)) {
    r.sweep_fallback = true;
    return r;
  }
  if(keep_if_valid(mesh, hexes, np, parameters::singularity_repair(false, np), r)) r.repair_fallback = true;
  return r;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_RUN_PIPELINE_H
