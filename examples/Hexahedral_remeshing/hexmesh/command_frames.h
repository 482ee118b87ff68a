// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// hexmesh frames IN [--heuristic NAME] [--valences FILE] [--baseline] [--no-realign] [--no-chord-split]
//                   [--frames OUT.vtk] [--singularities OUT.vtk] [--json FILE] [--valences-out FILE]
//                   [--cubecover PREFIX] [--threads N] [--quiet]
// The frame-field pipeline of Desobry et al.: valences, direction constraints, frame field,
// matchings and singularity graph, realignment with the normals; exports for ParaView and CubeCover.
#ifndef HEXMESH_COMMAND_FRAMES_H
#define HEXMESH_COMMAND_FRAMES_H

#include "cli_common.h"
#include "command_info.h"

#include <CGAL/Hexahedral_remeshing/IO/edge_valences.h>
#include <CGAL/Hexahedral_remeshing/IO/write_CubeCover.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_frame_field.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_remeshing/run_pipeline.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <cmath>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace hexmesh {

inline std::vector<std::string> frames_options()
{
  std::vector<std::string> options = input_options();
  for(const char* o : {"heuristic", "valences", "frames", "singularities", "json", "valences-out", "cubecover", "threads",
                       "acute-edge-band", "field-initialization"})
    options.push_back(o);
  return options;
}

inline std::vector<std::string> frames_flags() { return {"baseline", "no-realign", "repair", "no-repair", "no-chord-split", "no-acute-grading", "quiet"}; }

// Pipeline visitor: per-stage progress on stderr (stages over a second), smoothing notes.
struct Frames_progress_visitor : CGAL::Hexahedral_remeshing::Frame_field_pipeline_visitor
{
  explicit Frames_progress_visitor(Progress& p) : progress(p) {}
  void start_stage(const std::string& stage) { progress.start(stage); }
  void end_stage(const std::string& /*stage*/, double /*seconds*/) { progress.finish(); }
  void smoothing_progress(double energy, int iterations)
  {
    std::ostringstream s;
    s << iterations << " L-BFGS iterations, energy " << std::setprecision(6) << energy;
    progress.note(s.str());
  }
  Progress& progress;
};

// The options shared by the commands that run the frame-field pipeline (frames, parametrize, remesh).
struct Frame_field_options
{
  CGAL::Hexahedral_remeshing::Valence_heuristic heuristic;
  bool baseline = false, realign = true, repair = false, quiet = false;
  // the map's quantization (parametrize, remesh): --greedy-rounding asks for the rounding alone
  CGAL::Hexahedral_remeshing::Integer_grid_map_quantization quantization =
    CGAL::Hexahedral_remeshing::Integer_grid_map_quantization::AUTOMATIC;
  // the map on a mesh whose singular curves' vertices moved towards their axes (parametrize, remesh)
  bool relocation = false;
  int continuation_steps = 60; // 0 with --no-continuation
  // --acute-edge-band: radius in model units (0: none); negative when absent (the command's default)
  double acute_edge_band = -1;
  // --field-initialization: the field the smoothing starts from (remesh: the relaxation, then the
  // boundary propagation if no valid hex mesh came out; frames and parametrize: the relaxation)
  CGAL::Hexahedral_remeshing::Frame_field_initialization initialization =
    CGAL::Hexahedral_remeshing::Frame_field_initialization::AUTOMATIC;
};

inline Frame_field_options frame_field_options(const Arguments& args)
{
  Frame_field_options o;
  o.heuristic = heuristic_option(args);
  o.baseline = args.has("baseline");
  o.realign = !args.has("no-realign");
  if(args.has("repair") && args.has("no-repair")) throw Usage_error("--repair and --no-repair exclude each other");
  // the repair runs by default, except on the baseline (the paper's comparison field, kept as it is)
  o.repair = o.baseline ? args.has("repair") : !args.has("no-repair");
  if(args.has("greedy-rounding")) o.quantization = CGAL::Hexahedral_remeshing::Integer_grid_map_quantization::GREEDY_ROUNDING;
  o.relocation = args.has("relocate-singular-vertices");
  if(args.has("no-continuation")) o.continuation_steps = 0;
  o.quiet = args.has("quiet");
  if(args.has("acute-edge-band")) {
    o.acute_edge_band = args.number("acute-edge-band", 0.);
    if(!(o.acute_edge_band >= 0) || !std::isfinite(o.acute_edge_band))
      throw Usage_error("option --acute-edge-band expects a radius >= 0 in model units (0: no band)");
  }
  if(args.has("field-initialization")) {
    const std::string v = args.value("field-initialization");
    if(v == "relaxation") o.initialization = CGAL::Hexahedral_remeshing::Frame_field_initialization::RELAXATION;
    else if(v == "propagation") o.initialization = CGAL::Hexahedral_remeshing::Frame_field_initialization::BOUNDARY_PROPAGATION;
    else throw Usage_error("option --field-initialization expects relaxation or propagation, not '" + v + "'");
  }
  if(o.baseline && (args.has("heuristic") || args.has("valences")))
    throw Usage_error("--baseline aligns the field with the normals: it takes no --heuristic nor --valences");
  if(args.has("threads")) {
    const int threads = args.integer("threads", 1, 1, 1024);
#ifdef _OPENMP
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
  }
  return o;
}

// Surfaces and CAD parts are tetrahedralized again at the hex size unless --max-volume or --mesh-size
// say otherwise: TetGen at most h^3/6 per tetrahedron, gmsh an edge length of 0.6 h (both some 30
// tetrahedra per hexahedron). A field on tetrahedra coarser than the hexahedra places its singular
// curves badly: the shipped cylinder tetrahedralized from its surface alone (854 tetrahedra) gives 5
// valence-3 and 1 valence-5 curves and an inverted map, at h^3/6 (27,634) a valid hex mesh.
// h: the target edge length, else the one of `hexahedra` hexahedra, else of about 2000.
inline void tetrahedralize_for_hex_size(const Arguments& args, const std::string& in, Mesh& mesh, double target,
                                        std::size_t hexahedra, Progress& progress)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  const std::string ext = HR::IO::file_extension(in);
  const bool surface = ext == "off" || ext == "obj" || ext == "stl" || ext == "ply";
  const bool cad = ext == "step" || ext == "stp" || ext == "brep" || ext == "iges" || ext == "igs";
  if((!surface && !cad) || args.has("max-volume") || args.has("mesh-size")) return;
  const double volume = HR::internal::tetrahedral_mesh_volume(mesh);
  namespace HP = CGAL::Hexahedral_remeshing::parameters;
  // the size the pipeline will use (0 means not given)
  const double h = HR::internal::pipeline_hex_edge_length(mesh, HP::target_edge_length(target, HP::number_of_hexahedra(hexahedra)));
  const double max_volume = HR::internal::hex_size_tetrahedron_volume(volume, h);
  if(!(max_volume > 0)) return;
  Arguments sized = args;
  std::ostringstream os;
  // a regular tetrahedron of edge a has volume a^3 / (6 sqrt 2): gmsh's size for the same density
  os << std::setprecision(17) << (surface ? max_volume : 0.6 * std::cbrt(6 * max_volume));
  sized.set(surface ? "max-volume" : "mesh-size", os.str());
  progress.start("tetrahedralizing " + in + " at the hex size");
  Mesh fine;
  read_input_mesh(sized, in, fine, !args.has("no-chord-split"));
  if(fine.number_of_tetrahedra() > mesh.number_of_tetrahedra()) mesh = std::move(fine);
  progress.finish();
}

// A CAD part (without --mesh-size) is measured on a surface mesh first (seconds): its volume gives the
// hex size, its walls are checked against it (a wall thinner than half a hexahedron is refused here,
// before a tetrahedralization that would take minutes), and it is tetrahedralized once, at the size
// of tetrahedralize_for_hex_size() or the default size, whichever is finer. Returns false for
// another input (nothing read).
inline bool read_cad_at_hex_size(const Arguments& args, const std::string& in, Mesh& mesh, double target,
                                 std::size_t hexahedra, Progress& progress)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  const std::string ext = HR::IO::file_extension(in);
  const bool cad = ext == "step" || ext == "stp" || ext == "brep" || ext == "iges" || ext == "igs";
  if(!cad || args.has("mesh-size") || args.has("max-volume")) return false;
  // one progress line for the measure and the tetrahedralization: a refusal stays the only line printed
  progress.start("reading " + in + " (tetrahedralized at the hex size)");
  const HR::IO::CAD_part_measures m = HR::IO::measure_CAD_part(in, input_time_limit(args));
  const double h = target > 0 ? target : std::cbrt(m.volume / (hexahedra > 0 ? double(hexahedra) : 2000.));
  if(m.wall_thickness < HR::internal::minimum_wall_thickness_over_hex_edge * h) {
    HR::internal::Wall_thickness w;
    w.location = m.wall_location;
    throw HR::Input_error(in, 0, HR::internal::thin_wall_for_hexahedra_message(m.wall_thickness, w.where(), h, m.volume));
  }
  const double max_volume = HR::internal::hex_size_tetrahedron_volume(m.volume, h);
  double size = m.diagonal / 20;
  if(max_volume > 0) size = (std::min)(size, 0.6 * std::cbrt(6 * max_volume));
  Arguments sized = args;
  std::ostringstream os;
  os << std::setprecision(17) << size;
  sized.set("mesh-size", os.str());
  read_input_mesh(sized, in, mesh, !args.has("no-chord-split"));
  progress.finish();
  return true;
}

// The size of the hexahedra a command will make, for tetrahedralize_for_hex_size().
struct Hex_size
{
  double target = 0;
  std::size_t hexahedra = 0;
};

// Reads the input (chords split unless --no-chord-split), tetrahedralized at `size` if given (a surface or
// a CAD part), then the --valences file, whose vertex indices are those of that final mesh; returns the seconds.
inline double read_frame_field_input(const Arguments& args, const std::string& in, Mesh& mesh,
                                     std::vector<std::pair<Mesh::Index, int> >& prescribed, Progress& progress,
                                     const Hex_size* size = nullptr)
{
  const auto start = std::chrono::steady_clock::now();
  if(size == nullptr || !read_cad_at_hex_size(args, in, mesh, size->target, size->hexahedra, progress)) {
    progress.start("reading " + in);
    read_input_mesh(args, in, mesh, !args.has("no-chord-split"));
    progress.finish();
    if(size != nullptr) tetrahedralize_for_hex_size(args, in, mesh, size->target, size->hexahedra, progress);
  }
  if(args.has("valences")) prescribed = CGAL::Hexahedral_remeshing::IO::read_edge_valences(args.value("valences"), mesh);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// "improper_edge 3, jog 12" (the reasons with violations), or "none".
inline std::string meshability_counts(const std::array<std::size_t, CGAL::Hexahedral_remeshing::number_of_meshability_reasons>& c)
{
  std::ostringstream s;
  for(std::size_t k = 0; k < c.size(); ++k)
    if(c[k] > 0) s << (s.tellp() > 0 ? ", " : "") << CGAL::Hexahedral_remeshing::meshability_reason_name(CGAL::Hexahedral_remeshing::Meshability_reason(k)) << " " << c[k];
  return s.tellp() > 0 ? s.str() : std::string("none");
}

// The local meshability check before and after the repair, and the repair's operations.
// `fallback`: the field is the one without the repair because the repaired one gave no valid hex mesh.
inline void print_meshability(std::ostream& out, const CGAL::Hexahedral_remeshing::Frame_field_pipeline_result& r,
                              bool fallback = false)
{
  out << "  meshability         before the repair: " << meshability_counts(r.meshability_before.counts) << "\n";
  if(r.repaired) {
    std::ostringstream ops;
    for(const auto& o : r.repair.operations) if(o.second > 0) ops << (ops.tellp() > 0 ? ", " : "") << o.first << " " << o.second;
    out << "  repair              " << r.repair.changed_faces << " face matchings changed (" << (ops.tellp() > 0 ? ops.str() : std::string("no operation"))
        << "), " << (r.repair.rounds > 1 ? std::to_string(r.repair.rounds) + " rounds, " : std::string())
        << std::fixed << std::setprecision(3) << r.repair.seconds << " s"
        << (r.repair.without_sweeps ? "; without the sweeps (with them: not kept)" : "")
        << (r.repair.changed_faces > 0 && !r.repair.accepted ? "; not kept (no better, or more non-meshable locations for the map)" : "")
        << "\n" << std::defaultfloat;
  } else {
    out << "  repair              "
        << (fallback ? "left out (see the repair fallback below)"
                     : std::string("not run (") + (r.baseline ? "--repair runs it on the baseline" : "--no-repair") + ")")
        << "\n";
  }
  out << "  meshability         final field: " << meshability_counts(r.meshability.counts) << "\n";
}

inline void add_meshability_counts(Json& json, const char* name, const std::array<std::size_t, CGAL::Hexahedral_remeshing::number_of_meshability_reasons>& c)
{
  json.begin(name);
  for(std::size_t k = 0; k < c.size(); ++k)
    json.value(CGAL::Hexahedral_remeshing::meshability_reason_name(CGAL::Hexahedral_remeshing::Meshability_reason(k)), c[k]);
  json.end();
}

// JSON "meshability": the counts by reason before the repair, after the surgery and for the final
// field, the repair's operations and seconds.
inline void add_meshability(Json& json, const CGAL::Hexahedral_remeshing::Frame_field_pipeline_result& r)
{
  json.begin("meshability");
  add_meshability_counts(json, "before_repair", r.meshability_before.counts);
  add_meshability_counts(json, "after_surgery", r.repaired ? r.repair.defects_after : r.meshability_before.counts);
  add_meshability_counts(json, "final", r.meshability.counts);
  json.value("final_graph_defects", r.meshability.graph_defects());
  json.begin("repair").value("performed", r.repaired).value("accepted", r.repaired && r.repair.accepted)
    .value("without_sweeps", r.repair.without_sweeps).value("rounds", r.repair.rounds).value("changed_faces", r.repair.changed_faces);
  for(const auto& o : r.repair.operations) json.value(o.first, o.second);
  json.begin("hex_scale").value("clusters", r.repair.hex_scale_clusters).value("removed", r.repair.simplified_clusters);
  for(const auto& k : r.repair.hex_scale_kept) json.value(k.first, k.second);
  json.end();
  json.value("seconds", r.repair.seconds).end();
  json.end();
}

// Runs the frame-field pipeline with progress; an impossible prescription stays an Input_error (exit 3),
// any other failure becomes a Stage_error (exit 4). `band`: radius of the fixed frames along acute
// valence-1 edges when --acute-edge-band is absent; `hex_edge`: the map's hex edge length, at which the
// repair simplifies the singular curves (0: frames alone, no map to come).
inline CGAL::Hexahedral_remeshing::Frame_field_pipeline_result
run_frame_field_pipeline(const Frame_field_options& o, const std::string& in, const Mesh& mesh,
                         const std::vector<std::pair<Mesh::Index, int> >& prescribed, Progress& progress,
                         double band = 0, double hex_edge = 0)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  namespace HP = CGAL::Hexahedral_remeshing::parameters;
  Frames_progress_visitor visitor(progress);
  try {
    return HR::compute_frame_field_pipeline(
      mesh, HP::valence_heuristic(o.heuristic, HP::prescribed_edge_valences(std::cref(prescribed),
                                  HP::baseline(o.baseline, HP::realignment(o.realign, HP::singularity_repair(o.repair,
                                  HP::repair_hex_edge_length(hex_edge, HP::acute_edge_band_radius(o.acute_edge_band >= 0 ? o.acute_edge_band : band,
                                  HP::frame_field_initialization(o.initialization)))))))).visitor(std::ref(visitor)));
  } catch(const HR::Input_error&) {
    throw;
  } catch(const std::exception& e) {
    throw Stage_error(std::string("frame-field pipeline on ") + in + ": " + e.what());
  }
}

inline int command_frames(const Arguments& args)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  namespace HP = CGAL::Hexahedral_remeshing::parameters;
  typedef Mesh::Index Index;

  // Usage first, then the outputs, then the inputs: every error before any computation.
  if(args.positional().size() != 1) throw Usage_error("frames expects one input file");
  const std::string& in = args.positional()[0];
  const Frame_field_options options = frame_field_options(args);
  const HR::Valence_heuristic heuristic = options.heuristic;
  const bool baseline = options.baseline, quiet = options.quiet;
  Output_files outputs;
  const std::string cubecover = args.value("cubecover");
  for(const char* o : {"frames", "singularities", "valences-out", "json"})
    if(args.has(o)) outputs.add(args.value(o));
  if(args.has("cubecover")) {
    if(cubecover.empty()) throw Usage_error("option --cubecover expects a path prefix");
    for(const char* ext : {".mesh", ".fra", ".perm"}) outputs.add(cubecover + ext);
  }

  Progress progress(quiet);
  Mesh mesh;
  std::vector<std::pair<Index, int> > prescribed;
  const double read_seconds = read_frame_field_input(args, in, mesh, prescribed, progress);
  const HR::Frame_field_pipeline_result r = run_frame_field_pipeline(options, in, mesh, prescribed, progress);
  const HR::Mesh_statistics statistics = HR::compute_mesh_statistics(mesh);

  // Achieved valence by exact dihedral class: row = class 0..4, column = achieved valence 0..4.
  std::array<std::array<std::size_t, 5>, 5> by_class{};
  for(Index e : mesh.boundary_edges()) {
    const int c = HR::boundary_edge_dihedral_class(mesh, e);
    const int k = r.boundary_valences.achieved[e];
    ++by_class[std::size_t(std::min(std::max(c, 0), 4))][std::size_t(std::min(std::max(k, 0), 4))];
  }
  const HR::Singularity_graph& g = r.singularities;
  auto curve_edges = [&](int valence) {
    std::size_t n = 0;
    for(const HR::Singular_curve& c : g.curves) if(c.valence == valence) n += c.edges.size();
    return n;
  };

  // Outputs.
  progress.start("writing the outputs");
  if(args.has("frames")) {
    const std::string f = args.value("frames");
    outputs.write({f}, [&] { HR::IO::write_VTK_frame_field(f, mesh, r.frames); });
  }
  if(args.has("singularities")) {
    const std::string f = args.value("singularities");
    outputs.write({f}, [&] { HR::IO::write_VTK_singularity_graph(f, mesh, g, r.meshability); });
  }
  if(args.has("valences-out")) {
    const std::string f = args.value("valences-out");
    outputs.write({f}, [&] { HR::IO::write_edge_valences(f, mesh, r.valences); });
  }
  if(args.has("cubecover"))
    outputs.write({cubecover + ".mesh", cubecover + ".fra", cubecover + ".perm"},
                  [&] { HR::IO::write_CubeCover(cubecover, mesh, r.frames, r.matchings); });
  if(args.has("json")) {
    Json json;
    json.begin().value("input", in).value("baseline", r.baseline).value("realigned", r.realigned);
    add_statistics(json, statistics);
    json.begin("preprocessing")
        .value("split_boundary_chords", !args.has("no-chord-split"))
        .value("split_chords", mesh.number_of_split_chords())
        .value("split_tetrahedra", mesh.number_of_split_tetrahedra())
        .end();
    json.begin("valences")
        .value("heuristic", baseline ? "geometric (baseline)" : HR::valence_heuristic_name(heuristic))
        .value("prescribed_edges", r.valence_statistics.prescribed_edges)
        .value("edges_differing_from_geometry", r.valence_statistics.edges_differing_from_geometry)
        .array("histogram", r.valence_statistics.histogram)
        .end();
    json.begin("constraints")
        .value("E_initial", r.constraints.initial_energy)
        .value("E_final", r.constraints.final_energy)
        .value("failed_faces", r.constraints.failed_faces.size())
        .value("iterations", r.constraints.iterations)
        .value("converged", r.constraints.converged)
        .end();
    json.begin("frame_field")
        .value("energy", r.frame_field.energy)
        .value("initialization", r.frame_field.initialization == HR::Frame_field_initialization::BOUNDARY_PROPAGATION
                                   ? "boundary_propagation" : "relaxation")
        .value("initial_energy", r.frame_field.initial_energy)
        .value("relaxation_iterations", r.frame_field.relaxation_iterations)
        .value("relaxation_residual", r.frame_field.relaxation_residual)
        .value("smoothing_iterations", r.frame_field.smoothing_iterations)
        .value("under_resolved_faces", r.matchings.under_resolved_faces)
        .value("fixed_frames", r.fixed_frames.size())
        .value("redirected_directions", r.redirected_directions)
        .value("seconds", r.frame_field.seconds)
        .end();
    json.begin("singularities")
        .value("valence3_edges", g.valence3_edges)
        .value("valence5_edges", g.valence5_edges)
        .value("improper_edges", g.improper_edges)
        .value("curves", g.curves.size())
        .value("valence3_curves", g.number_of_curves(3))
        .value("valence5_curves", g.number_of_curves(5))
        .value("improper_curves", g.number_of_curves(0))
        .value("dangling_vertices", g.dangling_vertices.size())
        .value("zipper_vertices", g.zipper_vertices.size())
        .end();
    add_meshability(json, r);
    json.begin("boundary_valences")
        .value("total", r.boundary_valences.total)
        .value("matched", r.boundary_valences.matched)
        .value("mismatched", r.boundary_valences.mismatched)
        .array("histogram", r.boundary_valences.histogram)
        .matrix("by_dihedral_class", by_class)
        .value("max_deviation", r.boundary_valences.max_deviation)
        .end();
    json.begin("realignment")
        .value("performed", r.realigned)
        .value("alignment_error", r.realignment.alignment_error)
        .value("constraint_error", r.realignment.constraint_error)
        .value("changed_matchings", r.realignment.changed_matchings)
        .value("changed_edges", r.realignment.changed_edges)
        .value("broken_ties", r.realignment.broken_ties)
        .value("solver_iterations", r.realignment.solver_iterations)
        .end();
    json.begin("seconds")
        .value("read", read_seconds)
        .value("valences", r.valences_seconds)
        .value("constraints", r.constraints_seconds)
        .value("setup", r.frame_field.setup_seconds)
        .value("initialization", r.frame_field.initialization_seconds)
        .value("smoothing", r.frame_field.smoothing_seconds)
        .value("matchings", r.matchings_seconds)
        .value("repair", r.repair.seconds)
        .value("realignment", r.realignment.seconds)
        .value("total", r.seconds)
        .end();
    json.end();
    const std::string f = args.value("json");
    outputs.write({f}, [&] { json.write(f); });
  }
  progress.finish();

  if(!quiet) {
    const double deg = 180 / CGAL_PI;
    auto histogram = [](const auto& h) {
      std::ostringstream s;
      bool first = true;
      for(std::size_t k = 0; k < h.size(); ++k)
        if(h[k] > 0) { s << (first ? "" : ", ") << "k=" << k << ": " << h[k]; first = false; }
      return first ? std::string("none") : s.str();
    };
    std::cout << in << ": frame field " << (baseline ? "aligned with the normals (baseline)" : "with prescribed boundary valences")
              << "\n"
              << "  mesh                " << mesh.number_of_tetrahedra() << " tetrahedra (" << mesh.number_of_split_chords()
              << " boundary chords split), " << mesh.number_of_boundary_triangles() << " boundary triangles, "
              << mesh.boundary_edges().size() << " boundary edges\n"
              << "  valences            " << (baseline ? "geometric" : HR::valence_heuristic_name(heuristic)) << " ("
              << r.valence_statistics.prescribed_edges << " prescribed): " << histogram(r.valence_statistics.histogram) << "\n"
              << std::fixed << std::setprecision(4)
              << "  E(n) -> E(v)        " << r.constraints.initial_energy << " -> " << r.constraints.final_energy << " rad ("
              << std::setprecision(1) << r.constraints.initial_energy * deg << " -> " << r.constraints.final_energy * deg
              << " deg), " << r.constraints.failed_faces.size() << " triangles with E_i >= pi/4\n"
              << std::setprecision(4)
              << "  frame field         energy " << r.frame_field.energy << " (" << r.frame_field.initial_energy
              << (r.frame_field.initialization == HR::Frame_field_initialization::BOUNDARY_PROPAGATION
                      ? " after the boundary propagation), " : " after the relaxation), ") << r.frame_field.smoothing_iterations << " L-BFGS iterations"
              << (r.fixed_frames.empty() ? std::string() : ", " + std::to_string(r.fixed_frames.size()) +
                                                              " frames fixed at acute valence-1 edges")
              << "\n"
              << "  singular curves     " << g.number_of_curves(3) << " of valence 3 (" << curve_edges(3) << " edges), "
              << g.number_of_curves(5) << " of valence 5 (" << curve_edges(5) << " edges), " << g.number_of_curves(0)
              << " improper (" << g.improper_edges << " edges); " << g.dangling_vertices.size() << " dangling ends, "
              << g.zipper_vertices.size() << " zippers\n"
              << "  boundary valences   " << r.boundary_valences.matched << "/" << r.boundary_valences.total
              << " as prescribed (" << r.boundary_valences.mismatched << " mismatched); achieved "
              << histogram(r.boundary_valences.histogram) << "; edges below 45 degrees: " << histogram(by_class[0]) << "\n";
    print_meshability(std::cout, r);
    if(r.realigned)
      std::cout << std::scientific << std::setprecision(1) << "  realignment         alignment error "
                << r.realignment.alignment_error << ", changed matchings " << r.realignment.changed_matchings
                << ", changed edge types " << r.realignment.changed_edges << " (0 expected)\n";
    else
      std::cout << "  realignment         not run" << (baseline ? " (the baseline is aligned with the normals)" : "") << "\n";
    std::cout << std::fixed << std::setprecision(2) << "  seconds             read " << read_seconds << ", valences "
              << r.valences_seconds << ", constraints " << r.constraints_seconds << ", setup " << r.frame_field.setup_seconds
              << ", initialization " << r.frame_field.initialization_seconds << ", smoothing "
              << r.frame_field.smoothing_seconds << ", matchings " << r.matchings_seconds << ", realignment "
              << r.realignment.seconds << ", total " << r.seconds << "\n" << std::defaultfloat;
    if(args.has("frames"))
      std::cout << "  ParaView            " << args.value("frames") << " (tetrahedra; Glyph filter on frame_u, frame_v, frame_w)\n";
    if(args.has("singularities"))
      std::cout << "  ParaView            " << args.value("singularities") << " (singular curves; color by valence)\n";
    if(args.has("cubecover"))
      std::cout << "  CubeCover           " << cubecover << ".mesh, " << cubecover << ".fra, " << cubecover << ".perm\n";
    if(args.has("valences-out")) std::cout << "  valences            " << args.value("valences-out") << " (a b k)\n";
    if(args.has("json")) std::cout << "  report              " << args.value("json") << "\n";
  }

  // Warnings: one line per kind of problem.
  if(r.valence_statistics.histogram[0] > 0)
    std::cerr << "hexmesh: warning: " << r.valence_statistics.histogram[0] << " boundary edge"
              << (r.valence_statistics.histogram[0] > 1 ? "s get" : " gets") << " valence k = 0 (dihedral angle below 45 degrees"
              << (baseline ? " with the normal-aligned baseline" : "") << "): no hexahedron can fill a valence-0 edge\n";
  if(r.boundary_valences.mismatched > 0)
    std::cerr << "hexmesh: warning: " << r.boundary_valences.mismatched << " of " << r.boundary_valences.total
              << " boundary edges do not get the prescribed valence (E(v) = " << std::setprecision(4)
              << r.constraints.final_energy << " rad)\n" << std::defaultfloat;
  if(r.realigned && (r.realignment.changed_matchings > 0 || r.realignment.changed_edges > 0))
    std::cerr << "hexmesh: warning: after the realignment, " << r.realignment.changed_matchings
              << " face matchings recomputed from the frames differ from the kept ones and " << r.realignment.changed_edges
              << " interior edges changed type (the exports keep the matchings of the field before realignment)\n";
  return EXIT_OK;
}

} // namespace hexmesh

#endif // HEXMESH_COMMAND_FRAMES_H
