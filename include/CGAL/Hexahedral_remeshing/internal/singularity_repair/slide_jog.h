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
    std::vector<Face_change> first;
    m_move.propose(state, site, first);
    for(const Face_change& c : first) {
      const Face_change pair = with_best_second_change(state, c, [&](Singularity_repair_state<Mesh>& s, std::vector<Face_change>& second) {
        for(auto v : s.mesh().face_vertices(c.face)) m_zigzag.propose(s, Repair_site{false, std::uint32_t(v)}, second);
        for(auto e : s.face_edges(c.face))
          if(s.edge_class(e) == JOG_CLASS || s.edge_class(e) == IMPROPER_CLASS)
            m_move.propose(s, Repair_site{true, std::uint32_t(e)}, second);
      });
      if(pair.matching >= 0) out.push_back(pair);
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
