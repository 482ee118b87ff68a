// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The fallback: every other matching of every editable face around the defect (the ring of a
// defective edge; the rings of the singular edges at a defective vertex). It finds the splits of
// improper edges into two proper ones and the moves the other operations do not name.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_LOCAL_MATCHING_SEARCH_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_LOCAL_MATCHING_SEARCH_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_operation.h>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Mesh>
class Local_matching_search : public Singularity_repair_operation<Mesh>
{
public:
  const char* name() const override { return "matching_search"; }

  void propose(Singularity_repair_state<Mesh>& state, const Repair_site& site, std::vector<Face_change>& out) const override
  {
    std::vector<typename Mesh::Index> edges, faces;
    if(site.is_edge) edges.push_back(site.index);
    else edges = singular_edges_at(state, typename Mesh::Index(site.index));
    for(auto e : edges) editable_ring_faces(state, e, faces);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    for(auto f : faces) all_other_matchings(std::uint32_t(f), state.matching(f), out);
  }
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_LOCAL_MATCHING_SEARCH_H
