// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// hexmesh smooth IN_HEX --reference IN_TETS_OR_SURFACE --out OUT.{mesh,vtk} [--json REPORT]
//                [--iterations N] [--quiet]
// Untangles and smooths a hex mesh against the boundary of a tet mesh or a closed surface,
// smooth_hexahedral_mesh(): boundary vertices on the surface, feature vertices on their curve,
// corners fixed, minimum scaled Jacobian never lower.
#ifndef HEXMESH_COMMAND_SMOOTH_H
#define HEXMESH_COMMAND_SMOOTH_H

#include "cli_common.h"
#include "command_extract.h"
#include "command_info.h"

#include <CGAL/Hexahedral_remeshing/IO/read_hexahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/write_hexahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_boundary_groups.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_orientation.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_smoothing.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>
#include <CGAL/Hexahedral_remeshing/internal/text_tokenizer.h>

#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace hexmesh {

inline std::vector<std::string> smooth_options() { return {"reference", "out", "json", "iterations"}; }
inline std::vector<std::string> smooth_flags() { return {"quiet"}; }

// The reference of the smoothing: a surface file (.off .obj .stl .ply) as it is (polygons split into
// fans; its sharp edges are found by the smoothing), any other input of the tet readers through its
// boundary, feature curves and corners.
inline CGAL::Hexahedral_remeshing::Hexahedral_smoothing_reference read_smoothing_reference(const std::string& file)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  const std::string ext = HR::IO::file_extension(file);
  HR::Hexahedral_smoothing_reference ref;
  if(ext == "off" || ext == "obj" || ext == "stl" || ext == "ply") {
    std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
    std::vector<std::vector<std::size_t> > polygons;
    HR::IO::read_surface_soup(HR::internal::Text_tokenizer::read_file(file), ext, file, points, polygons);
    ref.points.assign(points.begin(), points.end());
    for(const auto& poly : polygons) {
      for(std::size_t i : poly)
        if(i >= points.size()) throw HR::Input_error(file, 0, "a face refers to vertex " + std::to_string(i) + " of " +
                                                                std::to_string(points.size()));
      for(std::size_t i = 1; i + 1 < poly.size(); ++i)
        ref.triangles.push_back({ {std::uint32_t(poly[0]), std::uint32_t(poly[i]), std::uint32_t(poly[i + 1])} });
    }
    if(ref.triangles.empty()) throw HR::Input_error(file, 0, "the surface has no triangle");
    return ref;
  }
  Mesh mesh;
  HR::IO::read_tetrahedral_mesh(file, mesh);
  ref = HR::make_hexahedral_smoothing_reference(mesh);
  if(ref.triangles.empty()) throw HR::Input_error(file, 0, "the tet mesh has no boundary triangle");
  return ref;
}

inline void add_smoothing_quality(Json& json, const std::string& key, const CGAL::Hexahedral_remeshing::Hexahedral_mesh_quality& q)
{
  json.begin(key)
      .value("min_scaled_jacobian", q.min_scaled_jacobian)
      .value("mean_scaled_jacobian", q.mean_scaled_jacobian)
      .value("share_below_0_3", q.low_quality_share)
      .value("non_positive", q.non_positive)
      .value("hausdorff_distance", q.hausdorff_distance)
      .value("max_constraint_distance", q.max_constraint_distance)
      .end();
}

inline double bounding_box_diagonal(const std::vector<CGAL::Hexahedral_remeshing::Hexahedral_mesh_3::Point_3>& points)
{
  if(points.empty()) return 0;
  const CGAL::Bbox_3 b = CGAL::bbox_3(points.begin(), points.end());
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

inline int command_smooth(const Arguments& args)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  if(args.positional().size() != 1) throw Usage_error("smooth expects one input hex mesh (.mesh or .vtk)");
  const std::string& in = args.positional()[0];
  if(!args.has("reference")) throw Usage_error("smooth needs --reference TETS_OR_SURFACE (the boundary to keep)");
  const std::string reference_file = args.value("reference");
  const bool quiet = args.has("quiet");
  const int iterations = args.integer("iterations", 10, 0, 1000000);
  const std::vector<std::string> outs = hex_output_options(args, "smooth");
  const std::string& out = outs.front();
  Output_files outputs;
  for(const std::string& o : outs) outputs.add(o);
  if(args.has("json")) outputs.add(args.value("json"));

  Progress progress(quiet);
  progress.start("reading " + in);
  HR::Hexahedral_mesh_3 hexes;
  HR::IO::read_hexahedral_mesh(in, hexes);
  // a hex mesh from another tool may list its vertices in the mirrored order, or mix both: oriented
  // here (degenerate hexahedra and faces that do not pair up are refused)
  const HR::Hexahedral_orientation_result orientation = HR::orient_hexahedral_mesh(hexes, in);
  const HR::Hexahedral_mesh_check input_check = HR::check_hexahedral_mesh(hexes);
  progress.finish();
  progress.start("reading " + reference_file);
  const HR::Hexahedral_smoothing_reference reference = read_smoothing_reference(reference_file);
  const double read_seconds = progress.finish();

  progress.start("smoothing");
  HR::Hexahedral_smoothing_report r;
  try {
    r = HR::smooth_hexahedral_mesh(hexes, reference, CGAL::parameters::number_of_iterations(iterations));
  } catch(const HR::Input_error&) {
    throw;
  } catch(const std::exception& e) {
    throw Stage_error("smoothing of " + in + ": " + e.what());
  }
  progress.finish();
  progress.start("checking the hex mesh");
  const HR::Hexahedral_mesh_check check = HR::check_hexahedral_mesh(hexes);
  // never an output worse than the input with exit 0: lower minimum scaled Jacobian, more inverted
  // hexahedra, a boundary farther from the reference
  std::string worse;
  if(check.min_scaled_jacobian < input_check.min_scaled_jacobian - 1e-9)
    worse = "its minimum scaled Jacobian would drop from " + std::to_string(input_check.min_scaled_jacobian) + " to " +
            std::to_string(check.min_scaled_jacobian);
  else if(check.inverted_hexahedra > input_check.inverted_hexahedra)
    worse = std::to_string(check.inverted_hexahedra) + " hexahedra would be inverted (" +
            std::to_string(input_check.inverted_hexahedra) + " in the input)";
  else if(r.before.hausdorff_distance >= 0 &&
          r.after.hausdorff_distance > 1.5 * r.before.hausdorff_distance + 1e-3 * bounding_box_diagonal(hexes.points))
    worse = "its boundary would move away from the reference (Hausdorff distance " +
            std::to_string(r.before.hausdorff_distance) + " -> " + std::to_string(r.after.hausdorff_distance) + ")";
  if(!worse.empty()) throw Stage_error(in + ": the smoothing cannot improve this hex mesh: " + worse + "; nothing written");
  // the boundary groups from the reference's patches (regions between its sharp edges)
  HR::compute_hexahedral_boundary_groups(hexes, reference);
  progress.finish();

  progress.start("writing the outputs");
  for(const std::string& o : outs) outputs.write({o}, [&] { HR::IO::write_hexahedral_mesh(o, hexes); });
  if(args.has("json")) {
    Json json;
    json.begin().value("input", in).value("reference", reference_file).value("output", out);
    json.begin("smoothing")
        .value("iterations", iterations)
        .value("sweeps", r.rounds)
        .value("untangling", r.untangling_run)
        .value("untangling_sweeps", r.untangling_sweeps)
        .value("global_untangling", r.global_untangling_run)
        .value("accepted_state", r.accepted_state)
        .value("vertex_moves", r.vertex_moves)
        .value("interior_vertices", r.interior_vertices)
        .value("surface_vertices", r.surface_vertices)
        .value("curve_vertices", r.curve_vertices)
        .value("fixed_vertices", r.fixed_vertices)
        .value("detected_feature_polylines", r.detected_feature_polylines)
        .value("reoriented_hexahedra", orientation.reoriented)
        .value("seconds", r.seconds)
        .end();
    add_smoothing_quality(json, "before", r.before);
    add_smoothing_quality(json, "after", r.after);
    add_hexahedral_mesh_check(json, check);
    json.begin("seconds").value("read", read_seconds).value("smoothing", r.seconds).end();
    json.end();
    const std::string f = args.value("json");
    outputs.write({f}, [&] { json.write(f); });
  }
  progress.finish();

  if(!quiet) {
    auto line = [](const char* name, const HR::Hexahedral_mesh_quality& q) {
      std::ostringstream s;
      s << std::fixed << std::setprecision(3) << "  " << name << "min SJ " << q.min_scaled_jacobian << ", mean "
        << q.mean_scaled_jacobian << ", " << std::setprecision(1) << 100 * q.low_quality_share << "% below 0.3, "
        << q.non_positive << " with SJ <= 0, Hausdorff " << std::scientific << std::setprecision(2)
        << q.hausdorff_distance << "\n";
      return s.str();
    };
    std::cout << in << ": " << hexes.number_of_hexahedra() << " hexahedra, " << hexes.number_of_vertices()
              << " vertices (" << r.interior_vertices << " interior, " << r.surface_vertices << " on the surface, "
              << r.curve_vertices << " on feature curves, " << r.fixed_vertices << " fixed)\n"
              << (orientation.reoriented == 0 ? std::string()
                  : "  orientation         " + std::to_string(orientation.reoriented) + " hexahedra re-oriented (" +
                      (orientation.mirrored_components == orientation.components ? std::string("written in the mirrored vertex order")
                                                                                 : std::string("mixed orientations")) + ")\n")
              << line("before              ", r.before) << line("after               ", r.after)
              << "  smoothing           " << r.rounds << " sweeps, " << r.vertex_moves << " vertex moves"
              << (r.untangling_run ? std::string(", untangling ") + (r.global_untangling_run ? "local + global" : "local") : std::string())
              << (r.accepted_state < 0 ? ", input kept (no better state)" : "") << "\n"
              << std::fixed << std::setprecision(2) << "  seconds             read " << read_seconds << ", smoothing "
              << r.seconds << "\n" << std::defaultfloat
              << "  hex mesh file       " << out << "\n";
    if(args.has("json")) std::cout << "  report              " << args.value("json") << "\n";
  }
  if(r.after.non_positive > 0)
    std::cerr << "hexmesh: warning: " << in << ": " << r.after.non_positive
              << " hexahedra still have a scaled Jacobian <= 0 after the smoothing\n";
  return EXIT_OK;
}

} // namespace hexmesh

#endif // HEXMESH_COMMAND_SMOOTH_H
