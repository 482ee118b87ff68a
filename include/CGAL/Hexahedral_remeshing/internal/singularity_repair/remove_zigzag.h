// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Two singular edges a-v, v-b that bound one triangle (a, v, b): changing that triangle's matching
// replaces them by the third edge a-b (a zigzag shortcut), or removes both (a 3-5 pair or a zipper
// cancelled: a curve that doubles back along its axis), or splits them otherwise.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REMOVE_ZIGZAG_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REMOVE_ZIGZAG_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_operation.h>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Mesh>
class Remove_zigzag : public Singularity_repair_operation<Mesh>
{
public:
  const char* name() const override { return "remove_zigzag"; }

  void propose(Singularity_repair_state<Mesh>& state, const Repair_site& site, std::vector<Face_change>& out) const override
  {
    const Mesh& mesh = state.mesh();
    std::vector<typename Mesh::Index> vertices;
    if(site.is_edge) for(auto v : mesh.edge_vertices(site.index)) vertices.push_back(v);
    else vertices.push_back(site.index);
    for(auto v : vertices) {
      const auto edges = singular_edges_at(state, v);
      for(std::size_t i = 0; i < edges.size(); ++i)
        for(std::size_t j = i + 1; j < edges.size(); ++j) {
          const auto f = face_of_edges(mesh, edges[i], edges[j]);
          if(f != Mesh::null_index && state.is_editable(f)) all_other_matchings(std::uint32_t(f), state.matching(f), out);
        }
    }
  }
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REMOVE_ZIGZAG_H
