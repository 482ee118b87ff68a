// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The repair of a realigned field, as the pipeline runs it: matching surgery with the realigned frames
// (the axes of the holonomies are those of the final field: the realignment turns the frames of thin
// wedges by up to 45 degrees, and a surgery done on the field of step 3 there can be undone by it), then
// the frames re-optimized with the repaired matchings fixed (the realignment's solver, directions = the
// normals the frames already follow). The result is kept only if it is no worse, both with the kept
// matchings and from the frames alone (their closest matchings, what any reader of the frames sees),
// in all graph defects and in those of the curves themselves, and better in one of them or simpler at
// the hex scale (a cluster of curves with no room in the map removed); and the
// non-meshable locations the map will report of it must not grow. Rounds of this follow while the last
// one is kept.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_REALIGNED_FIELD_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_REALIGNED_FIELD_H

#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/local_meshability.h>
#include <CGAL/Hexahedral_remeshing/realign_frame_field.h>
#include <CGAL/Hexahedral_remeshing/repair_singularity_graph.h>

#include <Eigen/Dense>

#include <chrono>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The defects of a check that the repair compares: all graph defects, and those of the edges and of
// the curves' ends and turns (improper edges, jogs, dangling ends, zippers); neither may grow.
// `nodes`: those of the curves that no map can follow at all (improper edges, dangling ends, zippers).
struct Compared_defects
{
  std::size_t graph = 0, curves = 0, nodes = 0;
  Compared_defects() = default;
  explicit Compared_defects(const std::array<std::size_t, number_of_meshability_reasons>& c)
    : graph(graph_defect_count(c)),
      curves(c[std::size_t(Meshability_reason::IMPROPER_EDGE)] + c[std::size_t(Meshability_reason::JOG)] +
             c[std::size_t(Meshability_reason::DANGLING_END)] + c[std::size_t(Meshability_reason::ZIPPER)]),
      nodes(c[std::size_t(Meshability_reason::IMPROPER_EDGE)] + c[std::size_t(Meshability_reason::DANGLING_END)] +
            c[std::size_t(Meshability_reason::ZIPPER)])
  {}
  bool no_worse_than(const Compared_defects& o) const { return graph <= o.graph && curves <= o.curves; }
  bool better_than(const Compared_defects& o) const { return no_worse_than(o) && (graph < o.graph || curves < o.curves); }
};

// The non-meshable locations the map reports of a field with graph g (diagnose_field(): improper edges,
// dangling ends, zippers of compute_singularity_graph(), which reads a jog by the side it leans to); the
// strict check counts a curve that runs backwards between two jogs as two jogs only.
inline std::size_t map_graph_defects(const Singularity_graph& g)
{
  return g.improper_edges + g.dangling_vertices.size() + g.zipper_vertices.size();
}

// The check of the frames with their own closest matchings.
template <class Traits>
Local_meshability_report frame_check(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames)
{
  return check_local_meshability(mesh, frames, compute_matchings(mesh, frames));
}

// A repaired field and its verdict: kept if no worse than the realigned one with the kept matchings and
// from the frames alone, better in one of them (or simpler at the hex scale), and the non-meshable
// locations the map will report of it do not grow.
struct Repair_attempt
{
  Singularity_repair_result report;
  std::vector<Eigen::Matrix3d> frames;
  Matchings matchings;
  Singularity_graph graph;
  Compared_defects kept, alone; // of the repaired field
};

template <class Traits, class NamedParameters, class RealignmentParameters>
Repair_attempt attempt_repair(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                              const Matchings& matchings, const std::vector<int>& prescribed,
                              const std::vector<Eigen::Vector3d>& normals, const Compared_defects& kept_before,
                              const Compared_defects& alone_before, const NamedParameters& np,
                              const RealignmentParameters& realignment_np, bool no_new_nodes)
{
  Repair_attempt a;
  a.matchings = matchings;
  a.report = repair_singularity_graph(mesh, frames, a.matchings, normals, np);
  a.report.accepted = false;
  if(a.report.changed_faces == 0) return a;
  a.frames = frames;
  realign_frame_field(mesh, a.frames, a.matchings, normals, realignment_np);
  a.kept = Compared_defects(check_local_meshability(mesh, a.frames, a.matchings, prescribed, normals).counts);
  a.alone = Compared_defects(frame_check(mesh, a.frames).counts);
  a.graph = compute_singularity_graph(mesh, a.frames, a.matchings);
  a.report.accepted = a.kept.no_worse_than(kept_before) && a.alone.no_worse_than(alone_before) &&
                      (a.kept.better_than(kept_before) || a.alone.better_than(alone_before) || a.report.simplified_clusters > 0) &&
                      map_graph_defects(a.graph) <= map_graph_defects(compute_singularity_graph(mesh, frames, matchings)) &&
                      (!no_new_nodes || (a.kept.nodes <= kept_before.nodes && a.alone.nodes <= alone_before.nodes));
  return a;
}

// One round: the repair with the sweeps, and without them if that one swept curves and is not kept.
// `no_new_nodes` (the rounds after the first): kept only if no improper edge, dangling end or zipper is
// added in either reading, a jog fewer being no reason for a curve no map can follow (n01c's second
// round traded two jogs for a zipper of the frames alone).
template <class Traits, class NamedParameters, class RealignmentParameters>
Repair_attempt repair_round(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                            const Matchings& matchings, const std::vector<int>& prescribed,
                            const std::vector<Eigen::Vector3d>& normals, const Compared_defects& kept_before,
                            const Compared_defects& alone_before, const NamedParameters& np,
                            const RealignmentParameters& realignment_np, bool no_new_nodes, bool& without_sweeps)
{
  Repair_attempt a =
    attempt_repair(mesh, frames, matchings, prescribed, normals, kept_before, alone_before, np, realignment_np, no_new_nodes);
  without_sweeps = !a.report.accepted && a.report.swept_curves > 0;
  if(without_sweeps)
    a = attempt_repair(mesh, frames, matchings, prescribed, normals, kept_before, alone_before,
                       parameters::repair_sweeps(false, np), realignment_np, no_new_nodes);
  return a;
}

// Adds the changes of a later round kept to the report of the rounds before it.
inline void add_round(Singularity_repair_result& r, const Singularity_repair_result& round)
{
  for(std::size_t k = 0; k < r.operations.size() && k < round.operations.size(); ++k) r.operations[k].second += round.operations[k].second;
  r.swept_curves += round.swept_curves;
  r.pulled_curve_ends += round.pulled_curve_ends;
  r.simplified_clusters += round.simplified_clusters;
  r.defects_after = round.defects_after;
}

// `singularities`: replaced by the repaired field's graph if that is kept (left as it is otherwise: the
// pipeline keeps an unchanged field's graph bitwise). `prescribed`: per edge, the prescribed valence of
// the boundary edges: with it the kept matchings are compared with the whole check (the hexahedra at
// the boundary vertices and the sectors at feature curves too).
// `realignment_np`: the named parameters of the realignment (solver order, face weights). A repair with
// sweeps that is not kept is tried again without them: a sweep may take the field where the frames,
// re-optimized, disagree, and lose the short changes' gains with it (s05c, s11c, n06c).
// Rounds follow while the last one is kept (`maximum_repair_rounds`): the re-optimized frames move the
// holonomy axes, so the surgery finds changes on them that it could not find on the frames before
// (n15c: 2 jogs after the first round, 0 after the third; n05c: 15 graph defects after the first, 5 after the third).
template <class Traits, class NamedParameters, class RealignmentParameters>
Singularity_repair_result repair_realigned_field(const Tetrahedral_mesh_3<Traits>& mesh, std::vector<Eigen::Matrix3d>& frames,
                                                 Matchings& matchings, Singularity_graph& singularities, const std::vector<int>& prescribed,
                                                 const NamedParameters& np, const RealignmentParameters& realignment_np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto start = std::chrono::steady_clock::now();
  const int max_rounds = choose_parameter(get_parameter(np, internal_np::maximum_repair_rounds), 8);
  const std::vector<Eigen::Vector3d> normals = boundary_triangle_unit_normals(mesh);
  const std::vector<int> input = matchings.face_matching;
  // the surgery's own check of the realigned field with the kept matchings
  Compared_defects kept_before(check_local_meshability(mesh, frames, matchings, prescribed, normals).counts);
  Compared_defects alone_before(frame_check(mesh, frames).counts);
  Singularity_repair_result r;
  r.graph_defects_before = r.graph_defects_after = kept_before.graph;
  r.frame_graph_defects_before = r.frame_graph_defects_after = alone_before.graph;
  for(int round = 0; round < max_rounds; ++round) {
    bool without_sweeps = false;
    Repair_attempt a = repair_round(mesh, frames, matchings, prescribed, normals, kept_before, alone_before, np, realignment_np,
                                    round > 0, without_sweeps);
    if(round == 0) {
      const std::size_t before = r.graph_defects_before, frame_before = r.frame_graph_defects_before;
      r = a.report;
      r.rounds = 0; // counted here: the surgery alone counts its own
      r.without_sweeps = without_sweeps;
      r.graph_defects_before = r.graph_defects_after = before;
      r.frame_graph_defects_before = r.frame_graph_defects_after = frame_before;
    } else if(a.report.accepted) {
      add_round(r, a.report);
    }
    if(!a.report.accepted) break;
    ++r.rounds;
    frames.swap(a.frames);
    matchings = std::move(a.matchings);
    singularities = std::move(a.graph);
    kept_before = a.kept;
    alone_before = a.alone;
    r.graph_defects_after = a.kept.graph;
    r.frame_graph_defects_after = a.alone.graph;
  }
  r.accepted = r.rounds > 0;
  if(r.accepted) {
    r.changed_faces = 0;
    for(std::size_t f = 0; f < input.size(); ++f) r.changed_faces += (input[f] != matchings.face_matching[f]);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_REALIGNED_FIELD_H
