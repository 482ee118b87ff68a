// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Moves a defective singular edge (a jog, an improper edge) across one of the triangles of its ring:
// the face's matching is changed by the edge's holonomy, so that the edge becomes regular and the
// holonomy runs along the two other edges of the triangle (Li et al. 2012, "All-hex meshing using
// singularity-restricted field", matching adjustment).
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_MOVE_SINGULAR_EDGE_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_MOVE_SINGULAR_EDGE_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_operation.h>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Mesh>
class Move_singular_edge : public Singularity_repair_operation<Mesh>
{
public:
  const char* name() const override { return "move_singular_edge"; }

  void propose(Singularity_repair_state<Mesh>& state, const Repair_site& site, std::vector<Face_change>& out) const override
  {
    if(!site.is_edge) return;
    std::vector<typename Mesh::Index> faces;
    editable_ring_faces(state, site.index, faces);
    for(auto f : faces) {
      const int g = regularizing_matching(state, site.index, f);
      if(g >= 0) out.push_back({std::uint32_t(f), g, 0.});
    }
  }

private:
  // The matching of face f that makes edge e's holonomy the identity (-1 if none: e not in f's ring).
  static int regularizing_matching(Singularity_repair_state<Mesh>& state, typename Mesh::Index e, typename Mesh::Index f)
  {
    const Mesh& mesh = state.mesh();
    const int current = state.matching(f);
    // the holonomy is linear in the face's step: try the 24 elements (exact table look-ups)
    for(int g = 0; g < Octahedral_group::size; ++g) {
      if(g == current) continue;
      if(holonomy_with(mesh, state, e, f, g) == Octahedral_group::identity_index) return g;
    }
    return -1;
  }

  static int holonomy_with(const Mesh& mesh, const Singularity_repair_state<Mesh>& state, typename Mesh::Index e,
                           typename Mesh::Index f, int g)
  {
    const Octahedral_group& group = octahedral_group();
    const auto ring = mesh.edge_ring(e);
    const auto faces = mesh.edge_ring_faces(e);
    int G = Octahedral_group::identity_index;
    for(std::size_t k = 0; k < ring.size(); ++k) {
      const int m = faces[k] == f ? g : state.matching(faces[k]);
      G = group.multiply(mesh.face_tetrahedra(faces[k])[0] == ring[k] ? m : group.inverse(m), G);
    }
    return G;
  }
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_MOVE_SINGULAR_EDGE_H
