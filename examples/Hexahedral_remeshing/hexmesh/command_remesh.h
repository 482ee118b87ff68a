// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// hexmesh remesh IN --out OUT.{mesh,vtk,vtu,inp,msh} [--target-edge-length H | --hexahedra N] [--heuristic NAME]
//                [--valences F] [--valences-out F] [--baseline] [--no-smoothing] [--frames F] [--singularities F] [--json F]
//                [--hexex F] [--acute-edge-band R] [--keep-partial] [--threads N] [--quiet]
// The whole pipeline in one call, CGAL::hexahedral_remeshing(): tetrahedra in, hexahedra out.
#ifndef HEXMESH_COMMAND_REMESH_H
#define HEXMESH_COMMAND_REMESH_H

#include "cli_common.h"
#include "command_extract.h"
#include "command_frames.h"
#include "command_parametrize.h"

#include <CGAL/hexahedral_remeshing.h>

#include <iomanip>
#include <limits>
#include <iostream>
#include <string>
#include <vector>

namespace hexmesh {

inline std::vector<std::string> remesh_options()
{
  std::vector<std::string> options = input_options();
  for(const char* o : {"out", "heuristic", "valences", "frames", "singularities", "json", "valences-out",
                       "target-edge-length", "hexahedra", "threads", "hexex", "acute-edge-band",
                       "field-initialization"})
    options.push_back(o);
  return options;
}

inline std::vector<std::string> remesh_flags() { return {"baseline", "repair", "no-repair", "greedy-rounding", "relocate-singular-vertices", "no-continuation", "no-smoothing", "no-chord-split", "no-tet-refinement", "no-acute-grading", "keep-partial", "quiet"}; }

inline int command_remesh(const Arguments& args)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  namespace HP = CGAL::Hexahedral_remeshing::parameters;
  typedef Mesh::Index Index;
  if(args.positional().size() != 1) throw Usage_error("remesh expects one input file");
  const std::string& in = args.positional()[0];
  const Frame_field_options options = frame_field_options(args);
  const std::vector<std::string> outs = hex_output_options(args, "remesh");
  const std::string& out = outs.front();
  const double target = target_edge_length_option(args);
  if(args.has("target-edge-length") && args.has("hexahedra"))
    throw Usage_error("give either --target-edge-length or --hexahedra, not both");
  const std::size_t hexahedra = args.has("hexahedra") ? std::size_t(args.integer("hexahedra", 0, 1, 20000000)) : 0;
  Output_files outputs;
  for(const std::string& o : outs) outputs.add(o);
  for(const char* o : {"frames", "singularities", "json", "valences-out", "hexex"})
    if(args.has(o)) outputs.add(args.value(o));

  Progress progress(options.quiet);
  Mesh mesh;
  std::vector<std::pair<Index, int> > prescribed;
  const Hex_size size{target, hexahedra};
  const double read_seconds = read_frame_field_input(args, in, mesh, prescribed, progress, &size);

  Frames_progress_visitor visitor(progress);
  HR::Hexahedral_mesh_3 hexes;
  HR::Hexahedral_remeshing_result r;
  HR::Integer_grid_map map;
  Mesh refined;  // the refined tetrahedra, when the hex mesh comes from them (r.refinement.used)
  // the size is the tail of the parameter chain: --target-edge-length, else --hexahedra, else the default
  auto run = [&](const auto& size) {
    return CGAL::hexahedral_remeshing(
      mesh, hexes,
      HP::valence_heuristic(options.heuristic, HP::prescribed_edge_valences(std::cref(prescribed),
        HP::baseline(options.baseline, HP::realignment(options.realign, HP::singularity_repair(options.repair,
        HP::hexahedral_smoothing(!args.has("no-smoothing"), HP::acute_edge_band_radius(options.acute_edge_band,
        HP::quantization(options.quantization, HP::singular_vertex_relocation(options.relocation, HP::maximum_continuation_steps(options.continuation_steps, HP::integer_grid_map_output(std::ref(map),
        HP::tetrahedron_refinement(!args.has("no-tet-refinement"), HP::refined_mesh_output(std::ref(refined),
        HP::frame_field_initialization(options.initialization, size)))))))))))))).visitor(std::ref(visitor)));
  };
  try {
    if(target > 0) r = run(HP::target_edge_length(target));
    else r = run(HP::number_of_hexahedra(hexahedra));
  } catch(const HR::Input_error&) {
    throw;
  } catch(const std::exception& e) {
    throw Stage_error(std::string("remeshing of ") + in + ": " + e.what());
  }
  // the outputs per element (frames, singularities, valences) refer to the mesh the hexahedra come from
  if(r.refinement.used) mesh = std::move(refined);
  const HR::Boundary_valence_agreement agreement = map_valence_agreement(mesh, r.frame_field.valences, r.map_check);
  const bool ok = r.status == HR::Hexahedral_remeshing_status::OK;
  const bool write_hexes = ok || (args.has("keep-partial") && hexes.number_of_hexahedra() > 0);

  progress.start("writing the outputs");
  if(write_hexes) for(const std::string& o : outs) outputs.write({o}, [&] { HR::IO::write_hexahedral_mesh(o, hexes); });
  // a failed run writes its JSON report only (and the partial outputs with --keep-partial)
  if(args.has("frames") && write_hexes) {
    const std::string f = args.value("frames");
    outputs.write({f}, [&] { HR::IO::write_VTK_frame_field(f, mesh, r.frame_field.frames); });
  }
  if(args.has("singularities") && write_hexes) {
    const std::string f = args.value("singularities");
    outputs.write({f}, [&] { HR::IO::write_VTK_singularity_graph(f, mesh, r.frame_field.singularities, r.frame_field.meshability); });
  }
  if(args.has("valences-out") && write_hexes) {
    const std::string v = args.value("valences-out");
    outputs.write({v}, [&] { HR::IO::write_edge_valences(v, mesh, r.frame_field.valences); });
  }
  if(args.has("hexex") && write_hexes && !map.tetrahedra.empty()) {
    const std::string x = args.value("hexex");
    outputs.write({x}, [&] { HR::IO::write_HexEx(x, map); });
  }
  if(args.has("json")) {
    const HR::Frame_field_pipeline_result& f = r.frame_field;
    Json json;
    json.begin().value("input", in).value("output", write_hexes ? out : std::string()).value("status", HR::status_name(r.status))
        .value("message", r.message).value("failed_stage", r.failed_stage).value("failure_reason", r.failure_reason).value("baseline", f.baseline).value("tetrahedra", r.tetrahedra)
        .value("repair_fallback", r.repair_fallback).value("sweep_fallback", r.sweep_fallback).value("rounds_fallback", r.rounds_fallback)
        .value("repaired_field_outcome", r.repaired_field_outcome);
    json.begin("tetrahedron_refinement")
        .value("rounds", r.refinement.rounds)
        .value("tetrahedra", r.refinement.tetrahedra)
        .value("used", r.refinement.used)
        .value("other_outcome", r.refinement.other_outcome)
        .value("other_seconds", r.refinement.other_seconds)
        .end();
    json.begin("field_restart")
        .value("tried", r.field_restart.tried)
        .value("used", r.field_restart.used)
        .value("other_outcome", r.field_restart.other_outcome)
        .value("other_seconds", r.field_restart.other_seconds)
        .end();
    json.begin("frame_field")
        .value("energy", f.frame_field.energy)
        .value("initialization", f.frame_field.initialization == HR::Frame_field_initialization::BOUNDARY_PROPAGATION
                                   ? "boundary_propagation" : "relaxation")
        .value("E_initial", f.constraints.initial_energy)
        .value("E_final", f.constraints.final_energy)
        .value("valence3_curves", f.singularities.number_of_curves(3))
        .value("valence5_curves", f.singularities.number_of_curves(5))
        .value("improper_edges", f.singularities.improper_edges)
        .value("boundary_valences_total", f.boundary_valences.total)
        .value("boundary_valences_matched", f.boundary_valences.matched)
        .value("fixed_frames", f.fixed_frames.size())
        .value("redirected_directions", f.redirected_directions)
        .end();
    add_meshability(json, f);
    add_integer_grid_map(json, r.map, r.map_check, agreement);
    json.begin("extraction")
        .value("hexahedra", r.extraction.hexahedra)
        .value("degenerate_tetrahedra", r.extraction.degenerate_tetrahedra)
        .value("inverted_tetrahedra", r.extraction.inverted_tetrahedra)
        .value("incomplete_cells", r.extraction.incomplete_cells)
        .value("resolved_cells", r.extraction.resolved_cells)
        .value("closed_boundary_cracks", r.extraction.closed_boundary_cracks)
        .end();
    json.begin("smoothing")
        .value("performed", r.smoothed)
        .value("min_scaled_jacobian_before", r.smoothing.before.min_scaled_jacobian)
        .value("min_scaled_jacobian_after", r.smoothing.after.min_scaled_jacobian)
        .value("mean_scaled_jacobian_before", r.smoothing.before.mean_scaled_jacobian)
        .value("mean_scaled_jacobian_after", r.smoothing.after.mean_scaled_jacobian)
        .value("seconds", r.smoothing.seconds)
        .end();
    add_hexahedral_mesh_check(json, r.check);
    json.begin("features")
        .value("length", r.feature_length)
        .value("coverage", r.feature_coverage)
        .value("hex_feature_edges", r.hex_feature_edges)
        .value("hex_feature_edges_with_prescribed_valence", r.hex_feature_edges_with_prescribed_valence)
        .value("relative_hausdorff_distance", r.relative_hausdorff_distance >= 0 ? r.relative_hausdorff_distance
                                                                                 : std::numeric_limits<double>::quiet_NaN())
        .value("volume_ratio", r.volume_ratio)
        .end();
    json.begin("boundary_groups")
        .value("quadrilaterals", r.boundary_groups.boundary_quadrilaterals)
        .value("patches", r.boundary_groups.patches)
        .value("feature_edges", r.boundary_groups.feature_edges)
        .value("curves", r.boundary_groups.curves)
        .end();
    json.begin("seconds")
        .value("read", read_seconds)
        .value("frame_field", f.seconds)
        .value("map", r.map.seconds)
        .value("extraction", r.extraction.seconds)
        .value("smoothing", r.smoothing.seconds)
        .value("check", r.check_seconds)
        .value("total", r.seconds)
        .end();
    json.end();
    const std::string j = args.value("json");
    outputs.write({j}, [&] { json.write(j); });
  }
  progress.finish();

  if(!options.quiet) {
    const HR::Frame_field_pipeline_result& f = r.frame_field;
    std::cout << in << ": " << r.tetrahedra << " tetrahedra -> " << hexes.number_of_hexahedra() << " hexahedra ("
              << HR::status_name(r.status) << ")" << (options.baseline ? ", normal-aligned baseline" : "") << "\n"
              << "  frame field         " << f.singularities.number_of_curves(3) << " valence-3 and "
              << f.singularities.number_of_curves(5) << " valence-5 singular curves, " << f.singularities.improper_edges
              << " improper edges; boundary valences of the field " << f.boundary_valences.matched << "/"
              << f.boundary_valences.total << " as prescribed"
              << (f.fixed_frames.empty() ? std::string()
                                         : "; " + std::to_string(f.fixed_frames.size()) +
                                             " frames fixed around acute valence-1 edges")
              << "\n";
    print_meshability(std::cout, f, r.repair_fallback);
    if(r.repair_fallback)
      std::cout << "  repair fallback     the repaired field gave " << r.repaired_field_outcome
                << "; this hex mesh is the field's without the repair\n";
    if(r.sweep_fallback)
      std::cout << "  sweep fallback      the repaired field gave " << r.repaired_field_outcome
                << "; this hex mesh is the field's repaired without the sweeps\n";
    if(r.rounds_fallback)
      std::cout << "  rounds fallback     the field repaired in rounds gave " << r.repaired_field_outcome
                << "; this hex mesh is the field's of the repair's first round\n";
    if(r.refinement.rounds > 0)
      std::cout << "  tet refinement      " << (r.refinement.used ? "used" : "tried") << ": " << r.refinement.rounds
                << (r.refinement.rounds == 1 ? " round" : " rounds") << " of 1-to-8, " << r.refinement.tetrahedra
                << " tetrahedra; the " << (r.refinement.used ? "mesh as given" : "refined mesh") << " gave "
                << r.refinement.other_outcome << "\n";
    if(r.field_restart.tried)
      std::cout << "  field restart       " << (r.field_restart.used ? "used" : "tried")
                << ": the frame field smoothed from the boundary propagation; the "
                << (r.field_restart.used ? "relaxation's field" : "propagated field") << " gave "
                << r.field_restart.other_outcome << "\n";
    print_integer_grid_map(std::cout, r.map, r.map_check, agreement);
    if(hexes.number_of_hexahedra() > 0) {
      print_hexahedral_mesh_check(std::cout, r.check);
      std::cout << "  features            " << r.hex_feature_edges_with_prescribed_valence << "/" << r.hex_feature_edges
                << " hex edges on sharp edges with the prescribed valence; " << std::fixed << std::setprecision(1)
                << 100 * r.feature_coverage << "% of the sharp-edge length on hex edges; hex volume "
                << std::setprecision(3) << r.volume_ratio << " of the solid's; Hausdorff distance ";
      if(r.relative_hausdorff_distance >= 0)
        std::cout << std::scientific << std::setprecision(2) << r.relative_hausdorff_distance << " of the diagonal\n";
      else
        std::cout << "not computed (the smoothing did not run)\n";
      std::cout << std::defaultfloat;
      std::cout << "  boundary groups     " << r.boundary_groups.patches << " surface patches ("
                << r.boundary_groups.boundary_quadrilaterals << " quads), " << r.boundary_groups.curves
                << " feature curves (" << r.boundary_groups.feature_edges << " hex edges): groups of .inp, .msh, .vtu, .mesh\n";
      if(r.extraction.incomplete_cells > 0)
        std::cout << "  incomplete          " << r.extraction.incomplete_cells
                  << " cells of the map could not be completed and are missing\n"
                << std::defaultfloat;
      if(r.smoothed)
        std::cout << std::fixed << std::setprecision(3) << "  smoothing           min scaled Jacobian "
                  << r.smoothing.before.min_scaled_jacobian << " -> " << r.smoothing.after.min_scaled_jacobian << ", mean "
                  << r.smoothing.before.mean_scaled_jacobian << " -> " << r.smoothing.after.mean_scaled_jacobian << "\n"
                  << std::defaultfloat;
    }
    std::cout << std::fixed << std::setprecision(2) << "  seconds             read " << read_seconds << ", frame field "
              << f.seconds << ", map " << r.map.seconds << ", extraction " << r.extraction.seconds << ", smoothing "
              << r.smoothing.seconds << ", check " << r.check_seconds << ", total " << r.seconds << "\n" << std::defaultfloat;
    if(!ok) std::cout << "  failed stage        " << r.failed_stage << ": " << r.failure_reason << "\n";
    if(write_hexes)
      for(const std::string& o : outs) std::cout << "  hex mesh            " << o << (ok ? "" : " (partial: --keep-partial)") << "\n";
    if(args.has("frames")) std::cout << "  ParaView            " << args.value("frames") << " (frames: Glyph on frame_u, frame_v, frame_w)\n";
    if(args.has("singularities")) std::cout << "  ParaView            " << args.value("singularities") << " (singular curves)\n";
    if(args.has("valences-out")) std::cout << "  valences            " << args.value("valences-out") << " (a b k: edit, then --valences)\n";
    if(args.has("hexex") && write_hexes) std::cout << "  map                 " << args.value("hexex") << " (the integer-grid map, libHexEx's format)\n";
    if(args.has("json")) std::cout << "  report              " << args.value("json") << "\n";
  }
  if(!ok) throw Stage_error(in + ": " + HR::status_name(r.status) + " (failed at the " + r.failed_stage + " stage): " + r.message +
                            (write_hexes ? " (partial mesh written)" : " (no hex mesh written)"));
  return EXIT_OK;
}

} // namespace hexmesh

#endif // HEXMESH_COMMAND_REMESH_H
