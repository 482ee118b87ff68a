// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Sweeps a defective piece of a singular curve across a sheet of triangles: a chain of edge moves
// (Move_singular_edge), each of a singular edge of the last two triangles moved across a triangle not
// moved yet, the cheapest next one each time, up to `max_moves`; the prefix of the chain whose total
// change of cost is lowest is proposed. A curve bent into a side face (three jogs running along it to its
// end) must be swept across the whole sheet between that route and a straight one, and every move on the
// way raises the cost: one or two moves (the other operations) cannot get there. Proposed only where no
// single move helps and the best prefix has three moves or more, so that the short operations keep the
// defects they repair.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SWEEP_CURVE_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SWEEP_CURVE_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/move_singular_edge.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_operation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Mesh>
class Sweep_curve : public Singularity_repair_operation<Mesh>
{
  typedef typename Mesh::Index Index;

public:
  explicit Sweep_curve(std::size_t max_moves = 24, std::size_t starts = 8) : m_max_moves(max_moves), m_starts(starts) {}

  const char* name() const override { return "sweep_curve"; }

  void propose(Singularity_repair_state<Mesh>& state, const Repair_site& site, std::vector<Face_change>& out) const override
  {
    std::vector<Face_change> first;
    if(site.is_edge) m_move.propose(state, site, first);
    else
      for(Index e : singular_edges_at(state, Index(site.index))) m_move.propose(state, Repair_site{true, std::uint32_t(e)}, first);
    for(Face_change& c : first) {
      c.delta = state.evaluate(c.face, c.matching);
      if(c.delta < -1e-9) return; // a single move helps: Move_singular_edge's
    }
    std::sort(first.begin(), first.end(), [](const Face_change& a, const Face_change& b) { return a.delta < b.delta; });
    if(first.size() > m_starts) first.resize(m_starts);
    for(const Face_change& c : first) {
      Face_change chain = best_chain(state, c);
      if(chain.matching >= 0) out.push_back(std::move(chain));
    }
  }

private:
  // The cheapest prefix of the greedy chain that starts with c, if it has three moves or more and
  // lowers the cost (an empty change otherwise). The state is left as it was.
  Face_change best_chain(Singularity_repair_state<Mesh>& state, const Face_change& c) const
  {
    std::vector<std::pair<Index, int> > moves, undo; // (face, new matching), (face, old matching)
    auto apply = [&](Index f, int g) {
      undo.emplace_back(f, state.matching(f));
      moves.emplace_back(f, g);
      state.apply(f, g);
    };
    double total = c.delta, best = 0;
    std::size_t best_length = 0;
    apply(Index(c.face), c.matching);
    std::vector<Face_change> next;
    while(moves.size() < m_max_moves) {
      next.clear();
      for(std::size_t k = moves.size() >= 2 ? moves.size() - 2 : 0; k < moves.size(); ++k)
        for(Index e : state.face_edges(moves[k].first))
          if(is_singular_class(state.edge_class(e))) m_move.propose(state, Repair_site{true, std::uint32_t(e)}, next);
      Face_change step;
      step.delta = std::numeric_limits<double>::infinity();
      for(const Face_change& d : next) {
        if(std::any_of(moves.begin(), moves.end(), [&](const std::pair<Index, int>& m) { return m.first == Index(d.face); })) continue;
        const double delta = state.evaluate(d.face, d.matching);
        if(delta < step.delta) { step = d; step.delta = delta; }
      }
      if(!std::isfinite(step.delta)) break;
      apply(Index(step.face), step.matching);
      total += step.delta;
      if(total < best - 1e-9) { best = total; best_length = moves.size(); }
    }
    for(auto u = undo.rbegin(); u != undo.rend(); ++u) state.apply(u->first, u->second);
    Face_change chain;
    if(best_length < 3) return chain;
    chain.face = std::uint32_t(moves[0].first);
    chain.matching = moves[0].second;
    for(std::size_t k = 1; k < best_length; ++k) chain.more.emplace_back(std::uint32_t(moves[k].first), moves[k].second);
    return chain;
  }

  Move_singular_edge<Mesh> m_move;
  std::size_t m_max_moves, m_starts;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_SWEEP_CURVE_H
