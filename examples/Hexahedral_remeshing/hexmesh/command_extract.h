// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// hexmesh extract IN.hexex --out OUT.{mesh,vtk} [--json REPORT] [--quiet]
// Reads an integer-grid map (libHexEx's .hexex), extracts its hexahedra, checks them and writes them.
#ifndef HEXMESH_COMMAND_EXTRACT_H
#define HEXMESH_COMMAND_EXTRACT_H

#include "cli_common.h"

#include <CGAL/Hexahedral_remeshing/IO/read_HexEx.h>
#include <CGAL/Hexahedral_remeshing/IO/write_hexahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>

#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <cctype>
#include <string>
#include <vector>

namespace hexmesh {

inline std::vector<std::string> extract_options() { return {"out", "json"}; }
inline std::vector<std::string> extract_flags() { return {"quiet"}; }

// The output file of a hex mesh: .mesh (MEDIT, HexaLab) or .vtk (ParaView); checked before any work.
// The hex mesh files (--out, possibly several: one per format), checked by extension.
inline std::vector<std::string> hex_output_options(const Arguments& args, const std::string& command)
{
  if(!args.has("out")) throw Usage_error(command + " needs --out OUT.{mesh,vtk,vtu,inp,msh}");
  std::vector<std::string> outs = args.all("out");
  if(outs.empty()) outs.push_back(args.value("out"));
  for(const std::string& out : outs) {
    std::string lower = out;
    for(char& c : lower) c = char(std::tolower((unsigned char)c));
    auto ends_with = [&](const std::string& ext) {
      return lower.size() > ext.size() && lower.compare(lower.size() - ext.size(), ext.size(), ext) == 0;
    };
    if(!ends_with(".mesh") && !ends_with(".vtk") && !ends_with(".vtu") && !ends_with(".inp") && !ends_with(".msh"))
      throw Usage_error("--out " + out + ": the hex mesh is written as .mesh (MEDIT: HexaLab, gmsh), .vtk or .vtu "
                        "(ParaView), .inp (Abaqus, CalculiX) or .msh (gmsh 4.1)");
  }
  return outs;
}

// The hex-mesh quality block shared by the JSON reports of extract and remesh.
inline void add_hexahedral_mesh_check(Json& json, const CGAL::Hexahedral_remeshing::Hexahedral_mesh_check& c)
{
  std::vector<std::vector<long long> > interior, boundary;
  for(const auto& kv : c.irregular_interior_edges) interior.push_back({kv.first, (long long)kv.second});
  for(const auto& kv : c.irregular_boundary_edges) boundary.push_back({kv.first, (long long)kv.second});
  json.begin("hex_mesh")
      .value("valid", c.valid)
      .value("hexahedra", c.hexahedra)
      .value("vertices", c.vertices)
      .value("conforming", c.conforming)
      .value("manifold_boundary", c.manifold_boundary)
      .value("non_conforming_quads", c.non_conforming_quads)
      .value("duplicate_vertices", c.duplicate_vertices)
      .value("duplicate_hexahedra", c.duplicate_hexahedra)
      .value("boundary_quads", c.boundary_quads)
      .value("min_scaled_jacobian", c.min_scaled_jacobian)
      .value("mean_scaled_jacobian", c.mean_scaled_jacobian)
      .value("share_below_0_3", c.low_quality_share)
      .value("inverted_hexahedra", c.inverted_hexahedra)
      .value("flat_hexahedra", c.flat_hexahedra)
      .value("volume", c.total_volume)
      .matrix("irregular_interior_edges", interior)
      .matrix("irregular_boundary_edges", boundary)
      .end();
}

// The summary lines of a hex mesh check (stdout).
inline void print_hexahedral_mesh_check(std::ostream& out, const CGAL::Hexahedral_remeshing::Hexahedral_mesh_check& c)
{
  out << "  hex mesh            " << c.hexahedra << " hexahedra, " << c.vertices << " vertices, "
      << (c.valid ? "valid" : "NOT valid") << " (" << (c.conforming ? "conforming" : "non-conforming") << ", "
      << (c.manifold_boundary ? "manifold boundary" : "non-manifold boundary") << ", " << c.duplicate_vertices
      << " duplicate vertices)\n"
      << std::fixed << std::setprecision(3) << "  scaled Jacobian     min " << c.min_scaled_jacobian << ", mean "
      << c.mean_scaled_jacobian << ", " << std::setprecision(1) << 100 * c.low_quality_share << "% below "
      << c.low_scaled_jacobian_threshold << ", " << c.inverted_hexahedra << " inverted, "
      << c.flat_hexahedra << " flat\n" << std::defaultfloat
      << "  irregular edges     interior by valence " << valence_list(c.irregular_interior_edges)
      << "; boundary by valence " << valence_list(c.irregular_boundary_edges) << "\n";
}

struct Extract_progress_visitor : CGAL::Hexahedral_remeshing::Hexahedral_extraction_visitor
{
  explicit Extract_progress_visitor(Progress& p) : progress(p) {}
  void start_stage(const std::string& stage) { progress.start("extraction: " + stage); }
  void end_stage(const std::string&, double) { progress.finish(); }
  Progress& progress;
};

inline int command_extract(const Arguments& args)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  if(args.positional().size() != 1) throw Usage_error("extract expects one input map (.hexex)");
  const std::string& in = args.positional()[0];
  const bool quiet = args.has("quiet");
  const std::vector<std::string> outs = hex_output_options(args, "extract");
  const std::string& out = outs.front();
  Output_files outputs;
  for(const std::string& o : outs) outputs.add(o);
  if(args.has("json")) outputs.add(args.value("json"));

  Progress progress(quiet);
  progress.start("reading " + in);
  HR::Integer_grid_map map;
  HR::IO::read_HexEx(in, map);
  const double read_seconds = progress.finish();

  Extract_progress_visitor visitor(progress);
  HR::Hexahedral_mesh_3 hexes;
  HR::Hexahedral_extraction_result r;
  try {
    r = HR::extract_hexahedra(map, hexes, CGAL::parameters::visitor(std::ref(visitor)));
  } catch(const HR::Input_error&) {
    throw; // not an integer-grid map: exit 3
  } catch(const std::exception& e) {
    throw Stage_error("extraction of " + in + ": " + e.what());
  }
  if(hexes.number_of_hexahedra() == 0)
    throw Stage_error(in + ": the map has no complete integer cell: no hexahedron to write");
  progress.start("checking the hex mesh");
  const HR::Hexahedral_mesh_check check = HR::check_hexahedral_mesh(hexes);
  progress.finish();

  progress.start("writing the outputs");
  for(const std::string& o : outs) outputs.write({o}, [&] { HR::IO::write_hexahedral_mesh(o, hexes); });
  if(args.has("json")) {
    Json json;
    json.begin().value("input", in).value("tetrahedra", map.number_of_tetrahedra()).value("output", out);
    json.begin("extraction")
        .value("status", r.status == HR::Hexahedral_extraction_result::OK ? "OK" : "DEFECTS")
        .value("hexahedra", r.hexahedra)
        .value("vertices", r.vertices)
        .value("degenerate_tetrahedra", r.degenerate_tetrahedra)
        .value("inverted_tetrahedra", r.inverted_tetrahedra)
        .value("inverted_positions", r.inverted_positions)
        .value("folded_cells", r.folded_cells)
        .value("inconsistent_walks", r.inconsistent_walks)
        .value("sanitizing_failures", r.sanitizing_failures)
        .value("untraced_corners", r.untraced_corners)
        .value("incomplete_cells", r.incomplete_cells)
        .value("resolved_cells", r.resolved_cells)
        .value("duplicate_cells", r.duplicate_cells)
        .value("max_sanitizing_move", r.max_sanitizing_move)
        .end();
    add_hexahedral_mesh_check(json, check);
    json.begin("seconds")
        .value("read", read_seconds)
        .value("topology", r.topology_seconds)
        .value("sanitize", r.sanitize_seconds)
        .value("vertices", r.vertices_seconds)
        .value("cells", r.cells_seconds)
        .value("extraction", r.seconds)
        .end();
    json.end();
    const std::string f = args.value("json");
    outputs.write({f}, [&] { json.write(f); });
  }
  progress.finish();

  if(!quiet) {
    std::cout << in << ": integer-grid map of " << map.number_of_tetrahedra() << " tetrahedra\n"
              << "  extraction          " << (r.status == HR::Hexahedral_extraction_result::OK ? "OK" : "with defects")
              << ": " << r.degenerate_tetrahedra << " degenerate and " << r.inverted_tetrahedra
              << " inverted tetrahedra in parameter space, " << r.inverted_positions << " inverted in space, "
              << r.incomplete_cells << " incomplete cells left out, " << r.resolved_cells
              << " completed with their neighbours' vertices\n";
    print_hexahedral_mesh_check(std::cout, check);
    std::cout << std::fixed << std::setprecision(3) << "  seconds             read " << read_seconds << ", extraction "
              << r.seconds << "\n" << std::defaultfloat
              << "  hex mesh file       " << out << "\n";
    if(args.has("json")) std::cout << "  report              " << args.value("json") << "\n";
  }
  if(r.status != HR::Hexahedral_extraction_result::OK)
    std::cerr << "hexmesh: warning: " << in << ": defects met: " << r.inverted_tetrahedra << " tetrahedra inverted and "
              << r.degenerate_tetrahedra << " flat in parameter space, " << r.inverted_positions
              << " inverted in space, " << r.folded_cells << " folded cells, " << r.untraced_corners
              << " untraced corners, " << r.inconsistent_walks << " inconsistent walks, " << r.sanitizing_failures
              << " sanitizing failures; " << r.incomplete_cells << " cells could not be completed and were left out\n";
  return EXIT_OK;
}

} // namespace hexmesh

#endif // HEXMESH_COMMAND_EXTRACT_H
