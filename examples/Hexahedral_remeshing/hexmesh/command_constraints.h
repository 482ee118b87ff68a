// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// hexmesh constraints IN [--heuristic NAME] [--valences FILE] [--json FILE] [--vtk FILE]
//                        [--refinements N] [--save-valences FILE]
// Boundary edge valences (Desobry et al., Sec. 5) and boundary direction constraints (Sec. 4).
#ifndef HEXMESH_COMMAND_CONSTRAINTS_H
#define HEXMESH_COMMAND_CONSTRAINTS_H

#include "cli_common.h"
#include "command_info.h"

#include <CGAL/Hexahedral_remeshing/IO/edge_valences.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_boundary.h>
#include <CGAL/Hexahedral_remeshing/boundary_direction_constraints.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace hexmesh {

inline std::vector<std::string> constraints_options()
{
  std::vector<std::string> options = input_options();
  for(const char* o : {"json", "vtk", "heuristic", "valences", "refinements", "save-valences"}) options.push_back(o);
  return options;
}

inline int command_constraints(const Arguments& args)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  namespace HP = CGAL::Hexahedral_remeshing::parameters;
  if(args.positional().size() != 1) throw Usage_error("constraints expects one input file");
  const std::string& in = args.positional()[0];

  const HR::Valence_heuristic heuristic = heuristic_option(args);
  const int refinements = args.integer("refinements", 9, 0, 20);

  Output_files outputs; // checked before any computation; all or nothing
  for(const char* o : {"save-valences", "vtk", "json"})
    if(args.has(o)) outputs.add(args.value(o));

  Mesh mesh;
  read_input_mesh(args, in, mesh);

  std::vector<std::pair<Mesh::Index, int> > prescribed;
  if(args.has("valences")) prescribed = HR::IO::read_edge_valences(args.value("valences"), mesh);

  Progress progress(false);
  progress.start("valences");
  std::vector<int> valences;
  const HR::Boundary_edge_valences_statistics vs = HR::compute_boundary_edge_valences(
    mesh, valences, HP::valence_heuristic(heuristic, HP::prescribed_edge_valences(std::cref(prescribed))));
  const double valence_seconds = progress.finish();

  progress.start("direction constraints");
  std::vector<Eigen::Vector3d> directions;
  const HR::Boundary_direction_constraints_result r =
    HR::compute_boundary_direction_constraints(mesh, valences, directions, HP::number_of_refinements(refinements));
  progress.finish();

  const double deg = 180 / CGAL_PI;
  std::cout << in << "\n"
            << "  boundary            " << mesh.number_of_boundary_triangles() << " triangles, "
            << mesh.boundary_edges().size() << " edges\n"
            << "  valences            heuristic " << HR::valence_heuristic_name(heuristic) << ", "
            << vs.prescribed_edges << " prescribed edges, " << vs.edges_differing_from_geometry
            << " edges differ from round(2 phi / pi)\n";
  for(int k = 0; k <= HR::maximum_prescribed_valence; ++k)
    if(vs.histogram[std::size_t(k)] > 0) std::cout << "    k = " << k << ": " << vs.histogram[std::size_t(k)] << "\n";
  std::cout << std::fixed << std::setprecision(4)
            << "  E(n)                " << r.initial_energy << " rad (" << std::setprecision(2) << r.initial_energy * deg
            << " deg), deviation of the normals\n" << std::setprecision(4)
            << "  E(v)                " << r.final_energy << " rad (" << std::setprecision(2) << r.final_energy * deg
            << " deg), after " << r.iterations << " updates, " << r.queue_pops << " queue pops, " << r.searches
            << " searches, " << std::setprecision(3) << r.seconds << " s\n"
            << "  failed triangles    " << r.failed_faces.size() << " (E_i >= pi/4)\n" << std::defaultfloat;

  // One line per kind of problem, never one per element.
  const std::size_t zero = vs.histogram[0];
  if(zero > 0)
    std::cerr << "hexmesh: warning: " << zero << " boundary edge" << (zero > 1 ? "s get" : " gets")
              << " valence k = 0 (dihedral angle below 45 degrees with heuristic '"
              << HR::valence_heuristic_name(heuristic) << "'): no hexahedron can fill a valence-0 edge, so the part"
              << " is not hex-meshable there; use --heuristic low_angle or prescribe k >= 1 with --valences\n";
  if(!r.failed_faces.empty())
    std::cerr << "hexmesh: warning: " << r.failed_faces.size() << " boundary triangle"
              << (r.failed_faces.size() > 1 ? "s keep" : " keeps") << " a deviation E_i >= pi/4 (E(v) = "
              << std::setprecision(4) << r.final_energy << " rad): a frame field aligned with the directions will"
              << " not reproduce the prescribed valences there\n";

  if(args.has("save-valences")) {
    const std::string f = args.value("save-valences");
    outputs.write({f}, [&] { HR::IO::write_edge_valences(f, mesh, valences); });
  }
  if(args.has("vtk")) {
    const std::vector<Eigen::Vector3d> normals = HR::boundary_triangle_unit_normals(mesh);
    std::vector<HR::IO::VTK_array> arrays(4);
    arrays[0].name = "n"; arrays[0].components = 3;
    arrays[1].name = "v"; arrays[1].components = 3;
    arrays[2].name = "E_i";
    arrays[3].name = "failed";
    for(std::size_t i = 0; i < directions.size(); ++i) {
      for(int c = 0; c < 3; ++c) {
        arrays[0].values.push_back(normals[i][c]);
        arrays[1].values.push_back(directions[i][c]);
      }
      arrays[2].values.push_back(r.face_energies[i]);
      arrays[3].values.push_back(r.face_energies[i] >= CGAL_PI / 4 ? 1. : 0.);
    }
    const std::string f = args.value("vtk");
    outputs.write({f}, [&] { HR::IO::write_VTK_boundary(f, mesh, arrays); });
  }
  if(args.has("json")) {
    Json json;
    json.begin().value("input", in);
    json.begin("mesh")
        .value("tetrahedra", mesh.number_of_tetrahedra())
        .value("boundary_triangles", mesh.number_of_boundary_triangles())
        .value("boundary_edges", mesh.boundary_edges().size())
        .end();
    json.begin("valences")
        .value("heuristic", HR::valence_heuristic_name(heuristic))
        .value("prescribed_edges", vs.prescribed_edges)
        .value("edges_differing_from_geometry", vs.edges_differing_from_geometry)
        .value("zero_valence_edges", zero)
        .array("histogram", vs.histogram)
        .value("seconds", valence_seconds)
        .end();
    json.begin("constraints")
        .value("E_initial", r.initial_energy)
        .value("E_final", r.final_energy)
        .value("failed_faces", r.failed_faces.size())
        .array("failed_face_indices", r.failed_faces)
        .value("iterations", r.iterations)
        .value("queue_pops", r.queue_pops)
        .value("searches", r.searches)
        .value("energy_evaluations", r.energy_evaluations)
        .value("refinements", refinements)
        .value("converged", r.converged)
        .value("seconds", r.seconds)
        .end();
    json.end();
    const std::string f = args.value("json");
    outputs.write({f}, [&] { json.write(f); });
  }
  return EXIT_OK;
}

} // namespace hexmesh

#endif // HEXMESH_COMMAND_CONSTRAINTS_H
