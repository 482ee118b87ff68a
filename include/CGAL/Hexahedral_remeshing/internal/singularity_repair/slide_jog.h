// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Slides a jog along its curve: a singular edge a-b across its holonomy axis (a sideways step of the
// curve) cannot be moved across one triangle without making another jog, but two changes can: move
// it across a triangle (a, b, x) so that a-x runs along the axis, then remove the zigzag x-b, b-q
// (q the curve's next vertex) through the triangle (x, b, q). The step moves one vertex along the
// curve; repeated, it reaches the boundary, a node or an opposite step and disappears. Each pair is
// evaluated as one change, so the cost may go up in between.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SLIDE_JOG_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SLIDE_JOG_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/move_singular_edge.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/remove_zigzag.h>

#include <limits>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Mesh>
class Slide_jog : public Singularity_repair_operation<Mesh>
{
public:
  const char* name() const override { return "slide_jog"; }

  // Proposes, per first move of the edge across a triangle of its ring, the best second change.
  void propose(Singularity_repair_state<Mesh>& state, const Repair_site& site, std::vector<Face_change>& out) const override
  {
    if(!site.is_edge) return;
    std::vector<Face_change> first, second;
    m_move.propose(state, site, first);
    for(const Face_change& c : first) {
      const int old = state.matching(c.face);
      state.apply(c.face, c.matching);
      second.clear();
      for(auto v : state.mesh().face_vertices(c.face)) m_zigzag.propose(state, Repair_site{false, std::uint32_t(v)}, second);
      for(auto e : state.face_edges(c.face))
        if(state.edge_class(e) == JOG_CLASS || state.edge_class(e) == IMPROPER_CLASS)
          m_move.propose(state, Repair_site{true, std::uint32_t(e)}, second);
      Face_change best;
      best.delta = std::numeric_limits<double>::infinity();
      for(const Face_change& d : second) {
        if(d.face == c.face) continue;
        const double delta = state.evaluate(d.face, d.matching);
        if(delta < best.delta) { best = d; best.delta = delta; }
      }
      state.apply(c.face, old);
      if(best.matching >= 0) out.push_back({c.face, c.matching, 0., std::int64_t(best.face), best.matching});
    }
  }

private:
  Move_singular_edge<Mesh> m_move;
  Remove_zigzag<Mesh> m_zigzag;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SLIDE_JOG_H
