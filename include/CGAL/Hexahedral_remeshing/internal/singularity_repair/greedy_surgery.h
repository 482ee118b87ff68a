// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The driver of the matching surgery: visits the defects in a queue, asks every operation for its
// proposals, applies the one that lowers the cost most, and queues the defects it may have created
// or left. Every applied change lowers the cost of Singularity_repair_state strictly, so the loop
// ends; a step budget bounds it on fields with thousands of defects.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_GREEDY_SURGERY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_GREEDY_SURGERY_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_operation.h>

#include <deque>
#include <memory>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Mesh>
bool is_edge_defect(const Singularity_repair_state<Mesh>& state, typename Mesh::Index e)
{
  const signed char c = state.edge_class(e);
  return c == JOG_CLASS || c == IMPROPER_CLASS;
}

template <class Mesh>
bool is_vertex_defect(const Singularity_repair_state<Mesh>& state, typename Mesh::Index v)
{
  return vertex_singularity(state.mesh(), state.edge_classes(), v).kind != Vertex_singularity::NONE || state.is_invalid_boundary_corner(v) ||
         state.ends_in_boundary_plane(v) || state.is_zigzag(v);
}

// Whether a curve ends in a boundary plane somewhere (ends_in_boundary_plane()).
template <class Mesh>
bool has_curve_end_in_boundary_plane(const Singularity_repair_state<Mesh>& state)
{
  for(typename Mesh::Index v = 0; v < state.mesh().number_of_vertices(); ++v)
    if(state.mesh().is_boundary_vertex(v) && state.ends_in_boundary_plane(v)) return true;
  return false;
}

// Queues the defects of the edges and vertices of face f and of the edges at its vertices.
template <class Mesh>
void queue_defects_around(const Singularity_repair_state<Mesh>& state, typename Mesh::Index f, std::deque<Repair_site>& queue)
{
  const Mesh& mesh = state.mesh();
  for(auto v : mesh.face_vertices(f)) {
    if(is_vertex_defect(state, v)) queue.push_back({false, std::uint32_t(v)});
    for(auto e : mesh.vertex_edges(v))
      if(is_edge_defect(state, e)) queue.push_back({true, std::uint32_t(e)});
  }
}

// Runs the surgery to a local minimum of the cost; `applied[k]` counts the changes of operation k.
// Returns the number of changes.
template <class Mesh>
std::size_t greedy_surgery(Singularity_repair_state<Mesh>& state,
                           const std::vector<std::unique_ptr<Singularity_repair_operation<Mesh> > >& operations,
                           std::size_t max_steps, std::vector<std::size_t>& applied)
{
  typedef typename Mesh::Index Index;
  const Mesh& mesh = state.mesh();
  applied.assign(operations.size(), 0);
  std::deque<Repair_site> queue;
  for(Index e = 0; e < mesh.number_of_edges(); ++e)
    if(is_edge_defect(state, e)) queue.push_back({true, std::uint32_t(e)});
  for(Index v = 0; v < mesh.number_of_vertices(); ++v)
    if(is_vertex_defect(state, v)) queue.push_back({false, std::uint32_t(v)});
  std::size_t steps = 0, changes = 0;
  std::vector<Face_change> proposals;
  while(!queue.empty() && steps < max_steps) {
    const Repair_site site = queue.front();
    queue.pop_front();
    if(site.is_edge ? !is_edge_defect(state, site.index) : !is_vertex_defect(state, site.index)) continue;
    ++steps;
    Face_change best;
    std::size_t best_operation = operations.size();
    for(std::size_t k = 0; k < operations.size(); ++k) {
      proposals.clear();
      operations[k]->propose(state, site, proposals);
      for(Face_change& c : proposals) {
        c.delta = state.evaluate(c);
        if(c.delta < best.delta - 1e-12) { best = c; best_operation = k; }
      }
    }
    if(best_operation == operations.size() || !(best.delta < -1e-9)) continue;
    state.apply(best);
    ++applied[best_operation];
    ++changes;
    Singularity_repair_state<Mesh>::for_each_face(best, [&](Index f, int) { queue_defects_around(state, f, queue); });
  }
  return changes;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_GREEDY_SURGERY_H
