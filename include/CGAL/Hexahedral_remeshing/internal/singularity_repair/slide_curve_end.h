// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Slides the end of a curve that ends in a boundary plane (ends_in_boundary_plane()) by two triangles:
// its last edge (w, v) moves across a triangle (w, v, c) of its ring, then an edge of that triangle that is
// singular after the move (the new last edge (w, c), or (c, v) where c is inside) moves across a second
// triangle, the two changes evaluated together. One move reaches the neighbours of v only; on a patch's
// corner or a feature curve the vertex one step away may still lie in the plane, which no single change
// can cross without the cost rising on the way (Move_singular_edge and Local_matching_search propose
// those single changes).
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SLIDE_CURVE_END_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SLIDE_CURVE_END_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/move_singular_edge.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_operation.h>

#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Mesh>
class Slide_curve_end : public Singularity_repair_operation<Mesh>
{
public:
  const char* name() const override { return "slide_end"; }

  void propose(Singularity_repair_state<Mesh>& state, const Repair_site& site, std::vector<Face_change>& out) const override
  {
    if(site.is_edge || !state.ends_in_boundary_plane(typename Mesh::Index(site.index))) return;
    std::vector<Face_change> first;
    for(auto e : singular_edges_at(state, typename Mesh::Index(site.index))) {
      first.clear();
      m_move.propose(state, Repair_site{true, std::uint32_t(e)}, first);
      for(const Face_change& c : first) {
        const Face_change pair = with_best_second_change(state, c, [&](Singularity_repair_state<Mesh>& s, std::vector<Face_change>& second) {
          for(auto e2 : s.face_edges(c.face))
            if(is_singular_class(s.edge_class(e2))) m_move.propose(s, Repair_site{true, std::uint32_t(e2)}, second);
        });
        if(pair.matching >= 0) out.push_back(pair);
      }
    }
  }

private:
  Move_singular_edge<Mesh> m_move;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SLIDE_CURVE_END_H
