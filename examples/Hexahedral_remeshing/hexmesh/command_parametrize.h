// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// hexmesh parametrize IN --hexex OUT.hexex [--vtk OUT.vtk] [--json REPORT] [--valences-out F]
//                        [--target-edge-length H] [--heuristic NAME] [--valences F] [--baseline] [--keep-partial] [--quiet]
// The frame-field pipeline, then the seamless integer-grid map (paper Sec. 3.4).
#ifndef HEXMESH_COMMAND_PARAMETRIZE_H
#define HEXMESH_COMMAND_PARAMETRIZE_H

#include "cli_common.h"
#include "command_frames.h"

#include <CGAL/Hexahedral_remeshing/IO/edge_valences.h>
#include <CGAL/Hexahedral_remeshing/IO/write_HexEx.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_extraction.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_remeshing_result.h>
#include <CGAL/Hexahedral_remeshing/integer_grid_map.h>

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace hexmesh {

inline std::vector<std::string> parametrize_options()
{
  std::vector<std::string> options = input_options();
  for(const char* o : {"heuristic", "valences", "hexex", "seamless-hexex", "vtk", "json", "valences-out", "target-edge-length", "threads",
                       "acute-edge-band", "field-initialization"})
    options.push_back(o);
  return options;
}

inline std::vector<std::string> parametrize_flags() { return {"baseline", "repair", "no-repair", "greedy-rounding", "relocate-singular-vertices", "no-continuation", "no-chord-split", "no-acute-grading", "keep-partial", "quiet"}; }

// The --target-edge-length option: a positive number of model units, 0 when absent (default size).
inline double target_edge_length_option(const Arguments& args)
{
  const double h = args.number("target-edge-length", 0.);
  if(args.has("target-edge-length") && !(h > 0))
    throw Usage_error("option --target-edge-length expects a positive length in model units");
  return h;
}

struct Map_progress_visitor : CGAL::Hexahedral_remeshing::Integer_grid_map_visitor
{
  explicit Map_progress_visitor(Progress& p) : progress(p) {}
  void start_stage(const std::string& stage) { progress.start("integer-grid map: " + stage); }
  void end_stage(const std::string&, double) { progress.finish(); }
  Progress& progress;
};

// Runs the map with progress; failures other than bad inputs become Stage_errors (exit 4).
inline CGAL::Hexahedral_remeshing::Integer_grid_map_result
run_integer_grid_map(const std::string& in, const Mesh& mesh, const CGAL::Hexahedral_remeshing::Frame_field_pipeline_result& f,
                     double target_edge_length, CGAL::Hexahedral_remeshing::Integer_grid_map& map, Progress& progress,
                     CGAL::Hexahedral_remeshing::Integer_grid_map_quantization quantization, bool relocation, int continuation_steps,
                     std::vector<std::array<Eigen::Vector3d, 4> >* seamless = nullptr)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  namespace HP = CGAL::Hexahedral_remeshing::parameters;
  Map_progress_visitor visitor(progress);
  try {
    const double h = target_edge_length > 0 ? target_edge_length : HR::internal::default_target_edge_length(mesh);
    return HR::compute_integer_grid_map(mesh, f.frames, f.matchings, f.singularities, map,
                                        HP::quantization(quantization, HP::singular_vertex_relocation(relocation, HP::maximum_continuation_steps(continuation_steps, HP::target_edge_length(h, HP::seamless_map_parameters(seamless))))).visitor(std::ref(visitor)));
  } catch(const HR::Input_error&) {
    throw;
  } catch(const std::exception& e) {
    throw Stage_error(std::string("integer-grid map of ") + in + ": " + e.what());
  }
}

// The boundary edges of the map that have the valence given to them by the frame-field stage.
inline CGAL::Hexahedral_remeshing::Boundary_valence_agreement
map_valence_agreement(const Mesh& mesh, const std::vector<int>& valences, const CGAL::Hexahedral_remeshing::Integer_grid_map_check& c)
{
  std::vector<std::tuple<std::uint32_t, std::uint32_t, int> > prescribed;
  prescribed.reserve(mesh.boundary_edges().size());
  for(const auto e : mesh.boundary_edges())
    prescribed.emplace_back(std::uint32_t(mesh.edge_vertices(e)[0]), std::uint32_t(mesh.edge_vertices(e)[1]), valences[e]);
  return CGAL::Hexahedral_remeshing::boundary_valence_agreement(c, prescribed);
}

inline std::string quantization_name(CGAL::Hexahedral_remeshing::Integer_grid_map_quantization q)
{
  switch(q) {
  case CGAL::Hexahedral_remeshing::Integer_grid_map_quantization::SEPARATION_PROGRAM: return "separation_program";
  case CGAL::Hexahedral_remeshing::Integer_grid_map_quantization::MOTORCYCLE_COMPLEX: return "motorcycle_complex";
  case CGAL::Hexahedral_remeshing::Integer_grid_map_quantization::GREEDY_ROUNDING: return "greedy_rounding";
  default: return "automatic";
  }
}

// One line on the motorcycle complex of the seamless map and its program.
inline std::string complex_summary(const CGAL::Hexahedral_remeshing::Integer_grid_map_complex& c)
{
  if(!c.traced) return "not traced" + (c.reason.empty() ? std::string() : " (" + c.reason + ")");
  std::ostringstream os;
  os << c.blocks << " blocks, " << c.patches << " patches, " << c.arcs << " arcs, " << c.nodes << " nodes ("
     << c.split_edges << " edges split, " << c.seconds << " s); " << c.extents << " block extents (" << c.separated_extents
     << " kept >= 1, " << c.skipped_extents << " left out, " << c.separated_paths << " zero-length paths kept >= 1), ";
  if(c.programs == 0) os << "the rounded values keep every block";
  else
    os << c.programs << " program(s) of " << c.program_variables << " variables and " << c.program_constraints
       << " constraints, folds " << c.folds_after_rounding << " -> " << c.folds_after_program << " (" << c.reason << ", "
       << c.program_seconds << " s)";
  if(c.reembedded)
    os << "; once repaired, folds " << c.folds_after_repair_quantized << " (quantized map) and " << c.folds_after_repair_program
       << " (the program's lengths re-embedded)";
  return os.str();
}

// One line on the map reached from the seamless map without a fold.
inline std::string continuation_summary(const CGAL::Hexahedral_remeshing::Integer_grid_map_continuation& c)
{
  std::ostringstream os;
  os << "from the seamless map without a fold: ";
  if(c.reached)
    os << (c.program_lengths ? "the complex's lengths" : "the quantized values") << " reached in " << c.steps << " steps (" << c.halvings << " halved), " << (c.kept ? "kept" : "not kept")
       << ": folds " << c.folds_before << " -> " << c.folds_after << ", branched edges " << c.branched_before << " -> " << c.branched_after;
  else
    os << "stopped at " << c.parameter << " of the way to " << (c.program_lengths ? "the complex's lengths" : "the quantized values")
       << " after " << c.steps << " steps (" << c.halvings << " halved); the quantized map repaired instead (" << c.folds_before
       << " folds, " << c.branched_before << " branched edges)";
  os << ", " << c.seconds << " s";
  return os.str();
}

// The map block of the JSON reports of parametrize and remesh.
inline void add_integer_grid_map(Json& json, const CGAL::Hexahedral_remeshing::Integer_grid_map_result& m,
                                 const CGAL::Hexahedral_remeshing::Integer_grid_map_check& c,
                                 const CGAL::Hexahedral_remeshing::Boundary_valence_agreement& a)
{
  json.begin("integer_grid_map")
      .value("status", CGAL::Hexahedral_remeshing::status_name(m.status))
      .value("target_edge_length", m.target_edge_length)
      .value("inverted_tetrahedra", m.inverted_tetrahedra)
      .value("degenerate_tetrahedra", m.degenerate_tetrahedra)
      .value("branched_edges", m.branched_edges)
      .value("min_relative_jacobian", m.min_relative_jacobian)
      .value("cut_faces", m.cut_faces)
      .value("variables", m.variables)
      .value("integer_variables", m.integer_variables)
      .value("rounding_rounds", m.rounding_rounds)
      .value("stiffening_rounds", m.stiffening_rounds)
      .value("untangling_ran", m.untangling_ran)
      .value("disagreeing_faces", m.disagreeing_faces)
      .value("jogs", m.jogs)
      .value("degenerate_jogs", m.degenerate_jogs)
      .value("defects", m.defects.size())
      .value("transition_error", m.transition_error)
      .value("seconds", m.seconds);
  const std::size_t shown = (std::min)(m.seamless_folds.size(), std::size_t(100));
  json.begin("seamless_map")
      .value("injective", m.seamless_injective)
      .value("branched_edges", m.seamless_branched_edges)
      .value("unbranching_ran", m.seamless_unbranching_ran)
      .value("inverted_tetrahedra", m.seamless_inverted_tetrahedra)
      .value("degenerate_tetrahedra", m.seamless_degenerate_tetrahedra)
      .value("inverted_before_untangling", m.relaxed_inverted_tetrahedra)
      .value("untangling_ran", m.seamless_untangling_ran)
      .value("wrapped_boundary_vertices", m.seamless_wrapped_boundary_vertices.size())
      .value("wrapped_before_untangling", m.relaxed_wrapped_boundary_vertices)
      .value("folds_at_wrapped_boundary", m.seamless_folds_at_wrapped_boundary)
      .array("folded_tetrahedra", std::vector<std::uint32_t>(m.seamless_folds.begin(), m.seamless_folds.begin() + std::ptrdiff_t(shown)))
      .begin("folds_by_cause")
      .value("structural_at_boundary", m.seamless_fold_causes.structural_at_boundary)
      .value("structural_inside", m.seamless_fold_causes.structural_inside)
      .value("at_field_defects", m.seamless_fold_causes.at_field_defects)
      .value("at_boundary", m.seamless_fold_causes.at_boundary)
      .value("inside", m.seamless_fold_causes.inside)
      .end()
      .value("seconds", m.seamless_seconds)
      .end();
  json.begin("relocation")
      .value("moved_vertices", m.relocated_vertices)
      .value("jogs_before", m.relocation_jogs_before)
      .value("jogs_after", m.relocation_jogs_after)
      .end();
  json.begin("continuation")
      .value("ran", m.continuation.ran)
      .value("reached", m.continuation.reached)
      .value("kept", m.continuation.kept)
      .value("program_lengths", m.continuation.program_lengths)
      .value("steps", m.continuation.steps)
      .value("halvings", m.continuation.halvings)
      .value("parameter", m.continuation.parameter)
      .value("folds_before", m.continuation.folds_before)
      .value("branched_before", m.continuation.branched_before)
      .value("folds_after", m.continuation.folds_after)
      .value("branched_after", m.continuation.branched_after)
      .value("seconds", m.continuation.seconds)
      .end();
  json.begin("quantization")
      .value("path", quantization_name(m.quantization))
      .value("reason", m.quantization_reason)
      .value("folds_after_rounding", m.folds_after_rounding)
      .value("folds_after_separation", m.folds_after_separation)
      .value("separation_programs", m.separation_rounds)
      .value("separation_constraints", m.separation_constraints)
      .value("separation_variables", m.separation_variables)
      .value("separation_seconds", m.separation_seconds)
      .begin("motorcycle_complex")
      .value("traced", m.motorcycle_complex.traced)
      .value("reason", m.motorcycle_complex.reason)
      .value("blocks", m.motorcycle_complex.blocks)
      .value("patches", m.motorcycle_complex.patches)
      .value("arcs", m.motorcycle_complex.arcs)
      .value("nodes", m.motorcycle_complex.nodes)
      .value("split_tetrahedra", m.motorcycle_complex.split_tetrahedra)
      .value("split_edges", m.motorcycle_complex.split_edges)
      .value("extents", m.motorcycle_complex.extents)
      .value("separated_extents", m.motorcycle_complex.separated_extents)
      .value("separated_paths", m.motorcycle_complex.separated_paths)
      .value("skipped_extents", m.motorcycle_complex.skipped_extents)
      .value("folds_after_rounding", m.motorcycle_complex.folds_after_rounding)
      .value("folds_after_program", m.motorcycle_complex.folds_after_program)
      .value("reembedded", m.motorcycle_complex.reembedded)
      .value("folds_after_repair_quantized", m.motorcycle_complex.folds_after_repair_quantized)
      .value("folds_after_repair_program", m.motorcycle_complex.folds_after_repair_program)
      .value("program_variables", m.motorcycle_complex.program_variables)
      .value("program_constraints", m.motorcycle_complex.program_constraints)
      .value("programs", m.motorcycle_complex.programs)
      .value("objective", m.motorcycle_complex.objective)
      .value("seconds", m.motorcycle_complex.seconds)
      .value("program_seconds", m.motorcycle_complex.program_seconds)
      .end()
      .end();
  std::vector<std::vector<long long> > interior, boundary;
  for(const auto& kv : c.interior_edge_valences) interior.push_back({kv.first, (long long)kv.second});
  for(const auto& kv : c.boundary_edge_valences) boundary.push_back({kv.first, (long long)kv.second});
  json.begin("check")
      .value("integer_grid", c.is_integer_grid())
      .value("inverted_tetrahedra", c.inverted_tetrahedra)
      .value("degenerate_tetrahedra", c.degenerate_tetrahedra)
      .value("max_jump_deviation", c.max_jump_deviation)
      .value("max_boundary_deviation", c.max_boundary_deviation)
      .matrix("interior_edge_valences", interior)
      .matrix("boundary_edge_valences", boundary)
      .value("boundary_valences_total", a.total)
      .value("boundary_valences_matched", a.matched)
      .value("boundary_valences_at_degenerate_tetrahedra", a.at_degenerate_tetrahedra)
      .end();
  json.end();
}

// The causes of the seamless map's folds, as one phrase.
inline std::string seamless_fold_cause_list(const CGAL::Hexahedral_remeshing::Seamless_fold_causes& c)
{
  return "folds: " + std::to_string(c.structural_at_boundary) + " flat for every map at the boundary, " +
         std::to_string(c.structural_inside) + " inside, " + std::to_string(c.at_field_defects) + " at field defects, " +
         std::to_string(c.at_boundary) + " at the boundary, " + std::to_string(c.inside) + " inside";
}

inline void print_integer_grid_map(std::ostream& out, const CGAL::Hexahedral_remeshing::Integer_grid_map_result& m,
                                   const CGAL::Hexahedral_remeshing::Integer_grid_map_check& c,
                                   const CGAL::Hexahedral_remeshing::Boundary_valence_agreement& a)
{
  out << "  integer-grid map    " << CGAL::Hexahedral_remeshing::status_name(m.status) << ": hex edge " << m.target_edge_length
      << ", " << m.inverted_tetrahedra << " inverted and " << m.degenerate_tetrahedra << " degenerate tetrahedra, "
      << (m.branched_edges ? std::to_string(m.branched_edges) + " branched interior edges (angle sums not 3, 4 or 5 quarter turns), " : std::string())
      << "min det J "
      << std::setprecision(3) << m.min_relative_jacobian << std::defaultfloat << " of the target; " << m.integer_variables
      << " integer variables, " << m.rounding_rounds << " rounding and " << m.stiffening_rounds << " stiffening rounds\n"
      << "  seamless map        "
      << (m.seamless_injective ? std::string("injective")
          : m.seamless_branched_edges ? "NOT injective: no fold, but " + std::to_string(m.seamless_branched_edges) +
                                          " interior edges branched (angle sums not 3, 4 or 5 quarter turns)"
                               : "NOT injective: " + std::to_string(m.seamless_inverted_tetrahedra) + " inverted and " +
                                   std::to_string(m.seamless_degenerate_tetrahedra) + " flat tetrahedra (" +
                                   std::to_string(m.structurally_flat_tetrahedra) + " flat for every map); " +
                                   seamless_fold_cause_list(m.seamless_fold_causes) +
                                   (m.seamless_wrapped_boundary_vertices.empty()
                                      ? std::string()
                                      : "; the boundary wrapped around " + std::to_string(m.seamless_wrapped_boundary_vertices.size()) +
                                          " vertices (" + std::to_string(m.relaxed_wrapped_boundary_vertices) + " in the minimizer), " +
                                          std::to_string(m.seamless_folds_at_wrapped_boundary) + " folds there"))
      << " before rounding"
      << (m.relocated_vertices ? "; " + std::to_string(m.relocated_vertices) + " curve vertices moved towards their axes (jogs " +
                                   std::to_string(m.relocation_jogs_before) + " -> " + std::to_string(m.relocation_jogs_after) + ")"
                               : std::string())
      << (m.seamless_untangling_ran ? " (untangled: " + std::to_string(m.relaxed_inverted_tetrahedra) + " folded in the minimizer)" : std::string())
      << "\n"
      << "  quantization        "
      << (m.quantization == CGAL::Hexahedral_remeshing::Integer_grid_map_quantization::SEPARATION_PROGRAM
            ? "separation program: " + std::to_string(m.folds_after_rounding) + " folded tetrahedra after the rounding, " +
                std::to_string(m.folds_after_separation) + " after " + std::to_string(m.separation_rounds) + " program(s) with " +
                std::to_string(m.separation_constraints) + " separation constraint(s)"
            : m.quantization == CGAL::Hexahedral_remeshing::Integer_grid_map_quantization::MOTORCYCLE_COMPLEX && m.continuation.kept
                ? "the motorcycle complex's program (" + m.quantization_reason + ")"
            : m.quantization == CGAL::Hexahedral_remeshing::Integer_grid_map_quantization::MOTORCYCLE_COMPLEX && m.motorcycle_complex.reembedded
                ? "the motorcycle complex's program, re-embedded (" + m.quantization_reason + ")"
            : m.quantization == CGAL::Hexahedral_remeshing::Integer_grid_map_quantization::MOTORCYCLE_COMPLEX
                ? "the motorcycle complex's program: " + std::to_string(m.motorcycle_complex.folds_after_rounding) +
                    " folded tetrahedra after the rounding, 0 after " + std::to_string(m.motorcycle_complex.programs) + " program(s)"
                : "greedy rounding" + (m.quantization_reason.empty() ? std::string() : " (" + m.quantization_reason + ")"))
      << "\n"
      << "  motorcycle complex  " << complex_summary(m.motorcycle_complex) << "\n"
      << (m.continuation.ran ? "  continuation        " + continuation_summary(m.continuation) + "\n" : std::string())
      << "  map check           " << (c.is_integer_grid() ? "integer-grid" : "NOT integer-grid") << ", interior edges by valence "
      << valence_list(c.interior_edge_valences) << "; boundary edges by valence " << valence_list(c.boundary_edge_valences)
      << "; boundary valences of the map " << a.matched << "/" << a.total << " as prescribed"
      << (a.at_degenerate_tetrahedra ? " (" + std::to_string(a.at_degenerate_tetrahedra) + " others next to degenerate tetrahedra)" : std::string())
      << "\n"
      << "  map defects         " << m.jogs << " singular jogs (" << m.degenerate_jogs << " degenerate), " << m.disagreeing_faces
      << " faces where frames and matchings disagree, " << m.defects.size() << " non-meshable singularities\n";
}

inline int command_parametrize(const Arguments& args)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  typedef Mesh::Index Index;
  if(args.positional().size() != 1) throw Usage_error("parametrize expects one input file");
  const std::string& in = args.positional()[0];
  const Frame_field_options options = frame_field_options(args);
  if(!args.has("hexex")) throw Usage_error("parametrize needs --hexex OUT.hexex");
  const double target = target_edge_length_option(args);
  Output_files outputs;
  for(const char* o : {"hexex", "seamless-hexex", "vtk", "json", "valences-out"})
    if(args.has(o)) outputs.add(args.value(o));

  Progress progress(options.quiet);
  Mesh mesh;
  std::vector<std::pair<Index, int> > prescribed;
  const Hex_size size{target, 0};
  const double read_seconds = read_frame_field_input(args, in, mesh, prescribed, progress, &size);
  // the band of fixed frames along acute edges is the one of remesh (two hex edges), so that the map
  // written here is the one remesh extracts
  const double hex_edge = HR::internal::pipeline_hex_edge_length(mesh, HR::parameters::target_edge_length(target));
  const HR::Frame_field_pipeline_result f = run_frame_field_pipeline(options, in, mesh, prescribed, progress, 2 * hex_edge, hex_edge);
  HR::Integer_grid_map map;
  std::vector<std::array<Eigen::Vector3d, 4> > seamless;
  const HR::Integer_grid_map_result m = run_integer_grid_map(in, mesh, f, target, map, progress, options.quantization, options.relocation,
                                                             options.continuation_steps, args.has("seamless-hexex") ? &seamless : nullptr);
  progress.start("checking the map");
  const HR::Integer_grid_map_check check = HR::check_integer_grid_map(map);
  const HR::Boundary_valence_agreement agreement = map_valence_agreement(mesh, f.valences, check);
  progress.finish();

  // a map whose tetrahedra fold (or that the solver could not make) is a failed stage: only its JSON report
  // is written, unless --keep-partial; flat tetrahedra (collapsed jogs) are tolerated by the extraction, and
  // so are branched edges where the branch holds no integer point (MAMBO B1_tet: a valid hex mesh)
  const bool usable = m.status == HR::Integer_grid_map_status::OK || m.status == HR::Integer_grid_map_status::DEGENERATE_TETRAHEDRA ||
                      m.status == HR::Integer_grid_map_status::BRANCHED_EDGES;
  const bool write_map = usable || args.has("keep-partial");
  progress.start("writing the outputs");
  const std::string hexex = args.value("hexex");
  if(write_map) outputs.write({hexex}, [&] { HR::IO::write_HexEx(hexex, map); });
  if(args.has("seamless-hexex") && seamless.size() == map.tetrahedra.size()) {
    // the map before any rounding, on the map's mesh: not an integer-grid map (its transitions' shifts
    // and its boundary planes are not integers), for inspection and independent checks
    HR::Integer_grid_map s = map;
    s.parameters = seamless;
    const std::string v = args.value("seamless-hexex");
    outputs.write({v}, [&] { HR::IO::write_HexEx(v, s); });
  }
  if(args.has("vtk") && write_map) {
    const std::string v = args.value("vtk");
    outputs.write({v}, [&] { HR::IO::write_VTK_integer_grid_map(v, map); });
  }
  if(args.has("valences-out") && write_map) {
    const std::string v = args.value("valences-out");
    outputs.write({v}, [&] { HR::IO::write_edge_valences(v, mesh, f.valences); });
  }
  if(args.has("json")) {
    Json json;
    json.begin().value("input", in).value("baseline", f.baseline).value("tetrahedra", mesh.number_of_tetrahedra());
    json.begin("singularities")
        .value("valence3_curves", f.singularities.number_of_curves(3))
        .value("valence5_curves", f.singularities.number_of_curves(5))
        .value("improper_edges", f.singularities.improper_edges)
        .end();
    json.begin("boundary_valences")
        .value("total", f.boundary_valences.total)
        .value("matched", f.boundary_valences.matched)
        .value("mismatched", f.boundary_valences.mismatched)
        .end();
    add_integer_grid_map(json, m, check, agreement);
    json.begin("seconds")
        .value("read", read_seconds)
        .value("frame_field", f.seconds)
        .value("cut", m.cut_seconds)
        .value("reduction", m.reduction_seconds)
        .value("elimination", m.elimination_seconds)
        .value("seamless_map", m.seamless_seconds)
        .value("rounding", m.rounding_seconds)
        .value("stiffening", m.stiffening_seconds)
        .value("untangling", m.untangling_seconds)
        .value("continuation", m.continuation.seconds)
        .value("sanitize", m.sanitize_seconds)
        .value("map", m.seconds)
        .end();
    json.end();
    const std::string j = args.value("json");
    outputs.write({j}, [&] { json.write(j); });
  }
  progress.finish();

  if(!options.quiet) {
    std::cout << in << ": integer-grid map of " << mesh.number_of_tetrahedra() << " tetrahedra\n"
              << "  frame field         " << f.singularities.number_of_curves(3) << " valence-3 and "
              << f.singularities.number_of_curves(5) << " valence-5 singular curves, " << f.singularities.improper_edges
              << " improper edges; boundary valences " << f.boundary_valences.matched << "/" << f.boundary_valences.total
              << " as prescribed\n";
    print_integer_grid_map(std::cout, m, check, agreement);
    std::cout << std::fixed << std::setprecision(2) << "  seconds             read " << read_seconds << ", frame field "
              << f.seconds << ", map " << m.seconds << " (cut " << m.cut_seconds << ", reduction " << m.reduction_seconds
              << ", elimination " << m.elimination_seconds << ", seamless map " << m.seamless_seconds << ", rounding " << m.rounding_seconds << ", stiffening "
              << m.stiffening_seconds << ", untangling " << m.untangling_seconds << ", continuation " << m.continuation.seconds
              << ", sanitize " << m.sanitize_seconds
              << ")\n" << std::defaultfloat
              << "  map                 " << (write_map ? hexex + " (hexmesh extract " + hexex + " --out OUT.mesh)" : std::string("not written"))
              << "\n";
    if(args.has("vtk")) std::cout << "  ParaView            " << args.value("vtk") << " (exploded tetrahedra, point data uvw)\n";
    if(args.has("json")) std::cout << "  report              " << args.value("json") << "\n";
  }
  const std::string what = std::string("integer-grid map status ") + HR::status_name(m.status) + " (" +
                           std::to_string(m.inverted_tetrahedra) + " inverted, " + std::to_string(m.degenerate_tetrahedra) +
                           " flat tetrahedra, " + (m.branched_edges ? std::to_string(m.branched_edges) + " branched edges, " : std::string()) +
                           std::to_string(m.defects.size()) + " non-meshable singularities)";
  if(!usable)
    throw Stage_error(in + ": " + what + (write_map ? " (map written: --keep-partial)" : " (no map written)"));
  if(m.status != HR::Integer_grid_map_status::OK)
    std::cerr << "hexmesh: warning: " << in << ": " << what << "\n";
  return EXIT_OK;
}

} // namespace hexmesh

#endif // HEXMESH_COMMAND_PARAMETRIZE_H
