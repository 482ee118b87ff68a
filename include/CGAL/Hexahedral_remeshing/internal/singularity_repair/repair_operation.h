// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The interface of the repair operations of the singularity graph: each proposes changes of face
// matchings around a defect (an edge or a vertex that fails the local check); the driver keeps the
// proposal that lowers the cost of Singularity_repair_state most.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_OPERATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_OPERATION_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_state.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Where the check fails: an interior edge (improper, jog) or a vertex (zipper, node, contact).
struct Repair_site
{
  bool is_edge = true;
  std::uint32_t index = 0;
};

template <class Mesh>
class Singularity_repair_operation
{
public:
  virtual ~Singularity_repair_operation() {}
  // The name in reports.
  virtual const char* name() const = 0;
  // Appends to `out` the changes this operation proposes at `site` (delta left to the driver).
  virtual void propose(Singularity_repair_state<Mesh>& state, const Repair_site& site, std::vector<Face_change>& out) const = 0;
};

// The editable faces around interior edge e.
template <class Mesh>
void editable_ring_faces(const Singularity_repair_state<Mesh>& state, typename Mesh::Index e, std::vector<typename Mesh::Index>& out)
{
  for(auto f : state.mesh().edge_ring_faces(e))
    if(state.is_editable(f)) out.push_back(f);
}

// The singular edges at vertex v.
template <class Mesh>
std::vector<typename Mesh::Index> singular_edges_at(const Singularity_repair_state<Mesh>& state, typename Mesh::Index v)
{
  std::vector<typename Mesh::Index> out;
  for(auto e : state.mesh().vertex_edges(v))
    if(is_singular_class(state.edge_class(e))) out.push_back(e);
  return out;
}

// Every other matching of face f.
inline void all_other_matchings(std::uint32_t f, int current, std::vector<Face_change>& out)
{
  for(int g = 0; g < Octahedral_group::size; ++g)
    if(g != current) out.push_back({f, g, 0.});
}

// The change `c` followed by the best of the changes `propose_second(state, proposals)` makes with c
// applied, of a face other than c's: two changes evaluated together, for a step whose first half alone
// raises the cost (a jog or a curve's end slid past a vertex). `matching` is -1 if there is no second.
template <class Mesh, class ProposeSecond>
Face_change with_best_second_change(Singularity_repair_state<Mesh>& state, const Face_change& c, const ProposeSecond& propose_second)
{
  const int old = state.matching(c.face);
  state.apply(c.face, c.matching);
  std::vector<Face_change> second;
  propose_second(state, second);
  Face_change best;
  best.delta = std::numeric_limits<double>::infinity();
  for(const Face_change& d : second) {
    if(d.face == c.face) continue;
    const double delta = state.evaluate(d.face, d.matching);
    if(delta < best.delta) { best = d; best.delta = delta; }
  }
  state.apply(c.face, old);
  if(best.matching < 0) return Face_change{};
  return {c.face, c.matching, 0., std::int64_t(best.face), best.matching};
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_REPAIR_OPERATION_H
