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
// and better in one of them.
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

// Graph defects of the frames with their own closest matchings.
template <class Traits>
std::size_t frame_graph_defects(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames)
{
  return check_local_meshability(mesh, frames, compute_matchings(mesh, frames)).graph_defects();
}

// `realignment_np`: the named parameters of the realignment (solver order, face weights).
template <class Traits, class NamedParameters, class RealignmentParameters>
Singularity_repair_result repair_realigned_field(const Tetrahedral_mesh_3<Traits>& mesh, std::vector<Eigen::Matrix3d>& frames,
                                                 Matchings& matchings, const NamedParameters& np,
                                                 const RealignmentParameters& realignment_np)
{
  const auto start = std::chrono::steady_clock::now();
  Matchings repaired = matchings;
  Singularity_repair_result r = repair_singularity_graph(mesh, frames, repaired, np);
  r.graph_defects_before = graph_defect_count(r.defects_before);
  r.frame_graph_defects_before = frame_graph_defects(mesh, frames);
  r.graph_defects_after = r.graph_defects_before;
  r.frame_graph_defects_after = r.frame_graph_defects_before;
  if(r.changed_faces > 0) {
    std::vector<Eigen::Matrix3d> reoptimized = frames;
    realign_frame_field(mesh, reoptimized, repaired, boundary_triangle_unit_normals(mesh), realignment_np);
    const std::size_t kept = check_local_meshability(mesh, reoptimized, repaired).graph_defects();
    const std::size_t alone = frame_graph_defects(mesh, reoptimized);
    r.accepted = kept <= r.graph_defects_before && alone <= r.frame_graph_defects_before &&
                 (kept < r.graph_defects_before || alone < r.frame_graph_defects_before);
    if(r.accepted) {
      frames.swap(reoptimized);
      matchings = std::move(repaired);
      r.graph_defects_after = kept;
      r.frame_graph_defects_after = alone;
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_REALIGNED_FIELD_H
