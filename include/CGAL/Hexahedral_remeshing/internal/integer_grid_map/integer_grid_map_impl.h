// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_INTEGER_GRID_MAP_IMPL_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_INTEGER_GRID_MAP_IMPL_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/complex_quantization.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/cut_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/field_diagnostics.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fixed_variable_solver.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/fold_repair.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/integer_tags.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_assembly.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_elimination.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_quantization.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_continuation.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/program_reembedding.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/reduced_system.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/sanitize.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/seamless_map.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/seamless_fold_causes.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/separation_constraints.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/singular_vertex_relocation.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/stiffening.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/structurally_flat.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The motorcycle complex of the seamless map and its block extents (`Result`:
// Integer_grid_map_result); false if there is none.
template <class Traits, class Result>
bool trace_complex(const Tetrahedral_mesh_3<Traits>& mesh, const Eigen::SparseMatrix<double, Eigen::RowMajor>& P,
                   const Eigen::VectorXd& x0, const Seamless_map& seamless, double seconds, Result& r,
                   motorcycle::Block_extents& extents)
{
  motorcycle::Motorcycle_complex_report report;
  const std::unique_ptr<motorcycle::Motorcycle_complex> complex = seamless_map_complex(mesh, P, x0, seamless, seconds, report);
  auto& c = r.motorcycle_complex;
  c.traced = report.success;
  c.reason = report.success ? std::string() : report.reason;
  c.blocks = report.blocks;
  c.patches = report.patches;
  c.arcs = report.arcs;
  c.nodes = report.nodes;
  c.split_tetrahedra = report.tetrahedra_after;
  c.split_edges = report.split_edges;
  c.seconds = report.seconds;
  if(!complex || !report.success) return false;
  extents = std::move(complex->extents);
  return true;
}

// `y` with the integer values of the complex's program (`alternative`: column, value) in place of its own.
inline Eigen::VectorXd with_program_lengths(const Eigen::VectorXd& y, const std::vector<std::pair<Eigen::Index, double> >& alternative)
{
  Eigen::VectorXd lengths = y;
  for(const auto& l : alternative) lengths[l.first] = l.second;
  return lengths;
}

// Where the quantization left its separating quantizer to be run (`separation_deferred`: the seamless
// map folds nowhere and the complex's program offers lengths, `q.alternative`, that the rounded map `y`
// could not take), first the continuation from the seamless map to those lengths (map_continuation.h),
// then, if its map is not kept, `separate` (separate_map(), which replaces `q` and `y`). The
// continuation is what makes the map there (clevis, filleted_block, flange, pillow_block of
// make_parts.py and s15c: the program's lengths reached without a fold), and the separating quantizer's
// map was only its fallback's start (the flange at 87,415 tetrahedra: 4 s of separation spared).
// Returns true if the continuation's map was kept; `mc` holds its report.
template <class Traits, class Options, class Visitor, class Separate, class Result>
bool continue_before_separation(const Tetrahedral_mesh_3<Traits>& mesh, const Fold_repair_input& in, const Eigen::SparseMatrix<double>& H,
                                const Eigen::VectorXd& rhs, const Eigen::VectorXd& seamless_y, const Options& o,
                                Fixed_variable_solver& solver, Visitor& visitor, const Separate& separate,
                                Quantization_result& q, Map_continuation& mc, Eigen::VectorXd& y, Result& r)
{
  Map_stage_timer<Visitor> stage{visitor};
  mc = continuation_needed(mesh, in, y);
  stage.start("continuation");
  const Eigen::VectorXd lengths = with_program_lengths(y, q.alternative);
  mc.program_lengths = true;
  continue_from_seamless_map(mesh, in, H, rhs, seamless_y, lengths, o.maximum_continuation_steps, solver, mc, y);
  stage.end();
  if(mc.kept) return true;
  stage.start("rounding");
  solver.unfix_all();
  q = separate(y);
  r.rounding_seconds += stage.end();
  return false;
}

// The quantized map `y` made fold-free. First the local untangling of its folds (the map closest to
// the quantized one, and cheap), kept if it neither folds nor branches; cheap only if it is short: the
// repairs it makes take 9 to 15 updates of the barrier (bracket_l_hole of make_parts.py, s09c), and
// with 50 it failed on the flange of make_parts.py at 87,415 tetrahedra in 9.9 s (257 -> 124 folds), on
// the way to the continuation, which repaired all. Then, if the separating quantizer was deferred, the
// continuation to the complex's program's lengths (continue_before_separation()), and the local
// untangling of the separated map if it differs. Then, when the seamless map folds nowhere (the
// structurally flat tetrahedra left out), the continuation from it to the complex's program's lengths
// when the quantizer kept other values (the program's lengths admit a valid map, QGP3D) and they were
// not tried already, then to the quantized values (map_continuation.h): every tetrahedron stays positive
// on the way, so the map reached neither folds nor branches. Otherwise, or if neither is reached, the
// rest of the repair of the folds (fold_repair.h) and the re-embedding of the program's lengths
// (program_reembedding.h).
template <class Traits, class Options, class Visitor, class Separate, class Result>
void make_map_fold_free(const Tetrahedral_mesh_3<Traits>& mesh, const Fold_repair_input& in, const Eigen::SparseMatrix<double>& H,
                        const Eigen::VectorXd& rhs, const Eigen::VectorXd& seamless_y, std::size_t seamless_folds,
                        bool separation_deferred, const Separate& separate, Quantization_result& q, const Options& o,
                        Fixed_variable_solver& solver, Visitor& visitor, Eigen::VectorXd& y, Result& r)
{
  Map_stage_timer<Visitor> stage{visitor};
  constexpr int local_first_barrier_updates = 20;
  const bool continuation = seamless_folds == 0 && o.untangle && o.maximum_continuation_steps > 0;
  Map_continuation mc = continuation ? continuation_needed(mesh, in, y) : Map_continuation();
  bool local_first = false; // the local untangling of `y` tried
  auto untangle_first = [&]() {
    if(!mc.ran || mc.folds_before == 0) return false;
    local_first = true;
    stage.start("untangling");
    Eigen::VectorXd z = y;
    const bool repaired = untangle_folds_locally(mesh, in, o.untangling_rings, r.untangling_ran, z, local_first_barrier_updates) && !continuation_needed(mesh, in, z).ran;
    r.untangling_seconds += stage.end();
    if(repaired) y = z;
    return repaired;
  };
  if(untangle_first()) return;
  if(separation_deferred) {
    const Eigen::VectorXd rounded = y;
    Map_continuation early;
    if(continue_before_separation(mesh, in, H, rhs, seamless_y, o, solver, visitor, separate, q, early, y, r)) {
      report_map_continuation(early, r);
      return;
    }
    if(!q.success) return;
    mc = continuation ? continuation_needed(mesh, in, y) : Map_continuation();
    if(mc.ran) { // the report sums both continuations
      mc.steps = early.steps;
      mc.halvings = early.halvings;
      mc.seconds = early.seconds;
    }
    if(y != rounded) {
      local_first = false;
      if(untangle_first()) return;
    }
  }
  if(mc.ran) {
    stage.start("continuation");
    const Eigen::VectorXd lengths = with_program_lengths(y, q.alternative);
    mc.program_lengths = lengths != y && !separation_deferred; // tried already if deferred
    if(mc.program_lengths)
      continue_from_seamless_map(mesh, in, H, rhs, seamless_y, lengths, o.maximum_continuation_steps, solver, mc, y);
    if(!mc.kept) {
      mc.program_lengths = false;
      continue_from_seamless_map(mesh, in, H, rhs, seamless_y, y, o.maximum_continuation_steps, solver, mc, y);
    }
    stage.end();
  }
  report_map_continuation(mc, r);
  if(mc.kept) return;
  const Fold_repair_report fr =
    repair_folds(mesh, in, solver, o.untangle, o.maximum_stiffening, o.untangling_rings, visitor, y, !local_first);
  r.stiffening_rounds = fr.stiffening_rounds;
  r.untangling_ran = r.untangling_ran || fr.untangling_ran;
  r.stiffening_seconds += fr.stiffening_seconds;
  r.untangling_seconds += fr.untangling_seconds;
  const Program_reembedding pr = reembed_program_lengths(mesh, in, H, rhs, q.alternative, o.untangle, o.maximum_stiffening,
                                                         o.untangling_rings, solver, visitor, y);
  report_program_reembedding(pr, r);
}

// The stages of compute_integer_grid_map() on the map's mesh (the input mesh, or its copy with the
// jog chords split): cut, reduction, elimination, seamless map, quantization, repair of the folds,
// sanitizing and assembly. `Options`: Map_options; `Result`: Integer_grid_map_result.
template <class Traits, class Options, class Visitor, class Result>
void compute_map_stages(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                        const Matchings& matchings, const Singularity_graph& singularities, const Options& o,
                        Visitor& visitor, Integer_grid_map& map, Result& r)
{
  const Map_geometry geometry = compute_map_geometry(mesh);
  const double s = 1.0 / o.h;
  const std::vector<std::uint32_t> jog_edges = diagnose_field(mesh, frames, matchings, singularities, r);
  Map_stage_timer<decltype(visitor)> stage{visitor};

  stage.start("cut");
  const Map_cut cut = compute_map_cut(mesh, singularities.edge_holonomy, Octahedral_group::identity_index);
  r.cut_faces = cut.cut_faces;
  r.cut_seconds = stage.end();

  stage.start("reduction");
  const Map_dofs dofs = reduce_map_variables(mesh, frames, matchings, singularities, cut.cut, r.sign_contradictions);
  r.reduction_seconds = stage.end();

  stage.start("elimination");
  Reduced_map reduced = eliminate_cut_constraints(mesh, matchings, cut.cut, cut.cut_index, cut.cut_faces, dofs);
  const auto& P = reduced.P;
  const auto& x0 = reduced.x0;
  r.inconsistent_constraints = reduced.inconsistent_rows;
  r.variables = reduced.integer_column.size();
  for(char c : reduced.integer_column) r.integer_variables += (c != 0);
  Eigen::SparseMatrix<double> H;
  Eigen::VectorXd rhs;
  assemble_reduced_system(geometry, frames, s, std::vector<double>(), P, x0, H, rhs);
  // what neither the stiffening nor the untangling can repair
  const std::vector<char> flat = structurally_flat_tetrahedra(geometry, P, x0);
  r.structurally_flat_tetrahedra = std::size_t(std::count(flat.begin(), flat.end(), char(1)));
  r.elimination_seconds = stage.end();

  stage.start("seamless_map");
  Fixed_variable_solver solver;
  const Seamless_map seamless =
    compute_seamless_map(mesh, geometry, frames, s, P, x0, reduced.integer_column, flat, H, rhs, solver, o.untangle, o.untangling_rings);
  report_seamless_map(seamless, r);
  r.seamless_fold_causes = classify_seamless_folds<Traits, decltype(r.seamless_fold_causes)>(
    mesh, r.seamless_folds, flat, field_defect_vertices(mesh, singularities, jog_edges));
  r.seamless_folds_at_wrapped_boundary = count_tetrahedra_at(mesh, r.seamless_folds, seamless.wrapped);
  if(o.seamless_parameters) corner_parameters(P * seamless.y + x0, *o.seamless_parameters);
  r.seamless_seconds = stage.end();

  stage.start("rounding");
  auto jump_form = [&](std::uint32_t f, int k) { return reduced.jump_form(f, k); };
  const Separation_finder<Traits> finder(mesh, matchings, cut.cut, geometry, P, x0, reduced.integer_column, flat, jump_form);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(P.cols());
  auto trace = [&](motorcycle::Block_extents& extents) {
    return trace_complex(mesh, P, x0, seamless, o.quantization_time_limit, r, extents);
  };
  // the seamless map's own folds (exact), the structurally flat tetrahedra left out
  const std::size_t seamless_folds = std::size_t(
    std::count_if(seamless.folds.begin(), seamless.folds.end(), [&](std::uint32_t t) { return flat[t] == 0; }));
  bool separation_deferred = seamless_folds == 0 && o.untangle && o.maximum_continuation_steps > 0;
  Quantization_result q = seamless.success ? quantize_map(finder, trace, H, rhs, reduced.integer_column, seamless.y, seamless_folds, o,
                                                          solver, y, r, separation_deferred)
                                           : Quantization_result{false};
  r.rounded_inverted_tetrahedra = count_non_positive_jacobians(geometry, P * y + x0);
  r.rounding_seconds = stage.end();

  if(q.success) {
    const Fold_repair_input in{geometry, frames, s, P, x0, reduced.integer_column, flat};
    auto separate = [&](Eigen::VectorXd& v) {
      return separate_map(finder, H, rhs, reduced.integer_column, seamless.y, seamless_folds, o, q.alternative, solver, v, r);
    };
    make_map_fold_free(mesh, in, H, rhs, seamless.y, seamless_folds, separation_deferred, separate, q, o, solver, visitor, y, r);
  }

  stage.start("sanitizing");
  r.sanitize_move = snap_to_dyadic_grid(y, reduced.integer_column);
  assemble_map(mesh, matchings, cut.cut, geometry, s, P * y + x0, jog_edges,
               [&](std::uint32_t f, int k) { return int(std::lround(jump_form(f, k)(y))); }, map, r);
  r.sanitize_seconds = stage.end();
  set_map_status(q.success, r);
}

// The map stages on `mesh`, or, with the relocation asked, on a copy of it whose singular curves'
// interior vertices have moved towards their axes (singular_vertex_relocation.h).
template <class Traits, class Options, class Visitor, class Result>
void relocate_and_compute_map_stages(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                                     const Matchings& matchings, const Singularity_graph& singularities, const Options& o,
                                     Visitor& visitor, Integer_grid_map& map, Result& r)
{
  if(!o.relocation) {
    compute_map_stages(mesh, frames, matchings, singularities, o, visitor, map, r);
    return;
  }
  Tetrahedral_mesh_3<Traits> moved = mesh;
  const Singular_vertex_relocation relocation = relocate_singular_vertices(moved, frames, singularities);
  r.relocated_vertices = relocation.moved_vertices;
  r.relocation_jogs_before = relocation.jogs_before;
  r.relocation_jogs_after = relocation.jogs_after;
  compute_map_stages(moved, frames, matchings, singularities, o, visitor, map, r);
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_INTEGER_GRID_MAP_IMPL_H
