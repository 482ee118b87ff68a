// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// hexmesh info IN [--json FILE]: statistics of a tetrahedral mesh.
#ifndef HEXMESH_COMMAND_INFO_H
#define HEXMESH_COMMAND_INFO_H

#include "cli_common.h"

#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/mesh_statistics.h>

#include <cmath>

namespace hexmesh {

typedef CGAL::Hexahedral_remeshing::Tetrahedral_mesh_3<> Mesh;

inline void add_statistics(Json& json, const CGAL::Hexahedral_remeshing::Mesh_statistics& s)
{
  json.begin("mesh")
      .value("vertices", s.vertices).value("input_vertices", s.input_vertices).value("tetrahedra", s.tetrahedra)
      .value("faces", s.faces).value("edges", s.edges)
      .value("boundary_triangles", s.boundary_triangles).value("boundary_edges", s.boundary_edges)
      .value("boundary_vertices", s.boundary_vertices)
      .value("components", s.components).value("boundary_components", s.boundary_components)
      .value("boundary_euler_characteristic", (long long)s.boundary_euler_characteristic)
      .value("boundary_genus", (long long)s.boundary_genus)
      .value("split_tetrahedra", s.split_tetrahedra).value("reoriented_tetrahedra", s.reoriented_tetrahedra)
      .value("feature_edges", s.feature_edges).value("feature_curves", s.feature_curves)
      .value("surface_patches", s.surface_patches).value("corners", s.corners)
      .array("dihedral_class_histogram", s.dihedral_class_histogram)
      .value("min_dihedral_angle_degrees", s.min_dihedral_angle_degrees)
      .value("max_dihedral_angle_degrees", s.max_dihedral_angle_degrees)
      .end();
}

inline void print_statistics(std::ostream& out, const std::string& file, const CGAL::Hexahedral_remeshing::Mesh_statistics& s)
{
  out << file << "\n"
      << "  vertices            " << s.vertices << " (" << s.input_vertices << " from the input)\n"
      << "  tetrahedra          " << s.tetrahedra << " (" << s.split_tetrahedra << " split 1-to-4, "
      << s.reoriented_tetrahedra << " re-oriented)\n"
      << "  boundary            " << s.boundary_triangles << " triangles, " << s.boundary_edges << " edges, "
      << s.boundary_vertices << " vertices\n"
      << "  components          " << s.components << " (boundary: " << s.boundary_components
      << " surfaces, Euler characteristic " << s.boundary_euler_characteristic << ", genus " << s.boundary_genus << ")\n"
      << "  features (input)    " << s.feature_edges << " feature edges on " << s.feature_curves << " curves, "
      << s.surface_patches << " surface patches, " << s.corners << " corners\n"
      << "  dihedral angles     " << std::fixed << std::setprecision(2) << s.min_dihedral_angle_degrees << " to "
      << s.max_dihedral_angle_degrees << " degrees\n" << std::defaultfloat
      << "  boundary edges by exact class round(2 phi / pi):\n";
  static const char* names[5] = {"0 (phi < 45, not meshable)", "1 (45..135, convex)", "2 (135..225, flat)",
                                 "3 (225..315, concave)", "4 (>= 315)"};
  for(int k = 0; k < 5; ++k) out << "    k = " << names[k] << ": " << s.dihedral_class_histogram[std::size_t(k)] << "\n";
}

// Options every command reading a mesh accepts.
inline std::vector<std::string> input_options() { return {"max-volume", "radius-edge", "mesh-size", "coincident-vertices", "time-limit"}; }

// Seconds after which gmsh or TetGen is stopped (--time-limit; 0: none).
inline double input_time_limit(const Arguments& args)
{
  const double limit = args.number("time-limit", 900.);
  if(!(limit >= 0) || !std::isfinite(limit)) throw Usage_error("option --time-limit expects a number of seconds (0: no limit)");
  return limit;
}

// Reads the input; `split_chords` also splits the interior edges joining two boundary vertices
// (what the frame-field pipeline needs at acute features).
inline void read_input_mesh(const Arguments& args, const std::string& in, Mesh& mesh, bool split_chords = false)
{
  namespace HP = CGAL::Hexahedral_remeshing::parameters;
  typedef CGAL::Hexahedral_remeshing::Coincident_vertices Coincident;
  // TetGen loops on radius-edge bounds below 1 and reads a non-positive volume bound as none
  const double radius_edge = args.number("radius-edge", 2.);
  if(radius_edge != 0 && radius_edge < 1) throw Usage_error("option --radius-edge expects 0 (no refinement) or a bound >= 1");
  if(args.has("max-volume") && !(args.number("max-volume", 0.) > 0))
    throw Usage_error("option --max-volume expects a positive volume");
  const double mesh_size = args.number("mesh-size", 0.);
  if(args.has("mesh-size") && !(mesh_size > 0)) throw Usage_error("option --mesh-size expects a positive length");
  const std::string coincident = args.value("coincident-vertices", "refuse");
  if(coincident != "refuse" && coincident != "merge" && coincident != "keep")
    throw Usage_error("option --coincident-vertices expects refuse, merge or keep, got '" + coincident + "'");
  const Coincident policy = coincident == "merge" ? Coincident::MERGE : coincident == "keep" ? Coincident::KEEP
                                                                                              : Coincident::REFUSE;
  CGAL::Hexahedral_remeshing::IO::read_tetrahedral_mesh(
    in, mesh, HP::maximum_tetrahedron_volume(args.number("max-volume", 0.), HP::radius_edge_ratio(args.number("radius-edge", 2.),
              HP::split_boundary_chords(split_chords, HP::mesh_size(mesh_size,
              HP::acute_edge_grading(!args.has("no-acute-grading"), HP::coincident_vertices(policy,
              HP::time_limit(input_time_limit(args)))))))));
}

inline int command_info(const Arguments& args)
{
  if(args.positional().size() != 1) throw Usage_error("info expects one input file");
  const std::string& in = args.positional()[0];
  Mesh mesh;
  read_input_mesh(args, in, mesh);
  const auto s = CGAL::Hexahedral_remeshing::compute_mesh_statistics(mesh);
  print_statistics(std::cout, in, s);
  if(args.has("json")) {
    Json json;
    json.begin().value("input", in);
    add_statistics(json, s);
    json.end();
    json.write(args.value("json"));
  }
  return EXIT_OK;
}

} // namespace hexmesh

#endif // HEXMESH_COMMAND_INFO_H
