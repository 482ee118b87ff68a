// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Pulls the end of a curve that ends in a boundary plane (ends_in_boundary_plane()) towards the nearest
// boundary vertex that lies on faces the curve crosses only (their frame axis closest to the normal is
// the curve's): a beam search over chains of edge moves (Move_singular_edge) from the curve's last edge,
// each chain extended by the moves of the singular edges of its last two faces, ranked by its change of
// cost plus the distance of the curve's first edges to the line through that vertex along the curve's
// axis; states reached before are dropped; the chain of lowest cost found is proposed if it lowers the
// cost and frees the end (frees_end_alone()). Where a curve ends on a concave feature curve (a blind
// hole's rim, a boss's foot), the vertex it must reach lies a few triangles away across the face it
// crosses, and the cost rises on the way (the
// curve bends into jogs before it is straight again): the cheapest-next chain of Sweep_curve wanders off,
// a ranked search with a goal gets there. Such an end pins the curve's line to the plane it touches; a
// curve that touches two walls' planes so squeezes the wall between them to nothing in every map (the
// plate with a boss and a blind hole of make_parts.py: a U-shaped curve, one end at the hole's rim, the
// other at the boss's foot, and the seamless map folded 2,127 tetrahedra of the boss's wall; 5 once the
// end at the foot was pulled onto the plate).
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_PULL_CURVE_END_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_PULL_CURVE_END_H

#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/move_singular_edge.h>
#include <CGAL/Hexahedral_remeshing/internal/singularity_repair/repair_operation.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

template <class Mesh>
class Pull_curve_end : public Singularity_repair_operation<Mesh>
{
  typedef typename Mesh::Index Index;

  // The line the curve should run on near its new end: through `point` along `axis` (unit).
  struct Goal
  {
    Eigen::Vector3d point, axis;
  };

public:
  explicit Pull_curve_end(std::size_t max_moves = 16, std::size_t beam_width = 24, int max_depth = 6)
      : m_max_moves(max_moves), m_beam_width(beam_width), m_max_depth(max_depth) {}

  const char* name() const override { return "pull_end"; }

  void propose(Singularity_repair_state<Mesh>& state, const Repair_site& site, std::vector<Face_change>& out) const override
  {
    if(site.is_edge || !state.ends_in_boundary_plane(Index(site.index))) return;
    const Index v = Index(site.index);
    for(Index e : singular_edges_at(state, v)) {
      const signed char c = state.edge_class(e);
      if(c != 3 && c != 5 && c != JOG_CLASS) continue;
      Goal goal;
      if(!find_goal(state, v, quarter_turn_world_axis(state.mesh(), state.frames(), state.holonomies(), e), goal)) continue;
      Face_change chain = best_chain(state, v, e, goal);
      if(chain.matching >= 0) out.push_back(std::move(chain));
    }
  }

private:
  static Eigen::Vector3d point(const Mesh& mesh, Index v) { return to_eigen_point(mesh.point(v)); }

  // Whether every boundary triangle at boundary vertex t is crossed by a curve along `axis` (its frame
  // axis closest to its normal is the curve's, within 25 degrees).
  static bool is_crossed_only(const Singularity_repair_state<Mesh>& state, Index t, const Eigen::Vector3d& axis)
  {
    return smallest_boundary_axis_cosine(state.mesh(), state.frames(), t, axis) >= 0.9;
  }

  // The nearest boundary vertex (fewest boundary edges from v, then closest) on crossed faces only.
  bool find_goal(const Singularity_repair_state<Mesh>& state, Index v, const Eigen::Vector3d& axis, Goal& goal) const
  {
    const Mesh& mesh = state.mesh();
    std::vector<std::pair<Index, int> > seen{{v, 0}};
    std::deque<std::pair<Index, int> > queue{{v, 0}};
    Index best = Mesh::null_index;
    int best_depth = m_max_depth + 1;
    double best_distance = std::numeric_limits<double>::infinity();
    while(!queue.empty()) {
      const auto [u, depth] = queue.front();
      queue.pop_front();
      if(depth > best_depth) break;
      if(u != v && is_crossed_only(state, u, axis)) {
        const double d = (point(mesh, u) - point(mesh, v)).norm();
        if(d < best_distance) { best = u; best_depth = depth; best_distance = d; }
        continue;
      }
      if(depth == m_max_depth) continue;
      for(auto e : mesh.vertex_edges(u)) {
        if(!mesh.is_boundary_edge(e)) continue;
        const auto& ev = mesh.edge_vertices(e);
        const Index w = ev[0] == u ? ev[1] : ev[0];
        if(std::any_of(seen.begin(), seen.end(), [&](const std::pair<Index, int>& s) { return s.first == w; })) continue;
        seen.emplace_back(w, depth + 1);
        queue.emplace_back(w, depth + 1);
      }
    }
    if(best == Mesh::null_index) return false;
    goal.point = point(mesh, best);
    goal.axis = axis;
    return true;
  }

  // Sum over the singular edges among `edges` of their length times the distance of their midpoint to
  // the goal's line, in squared mean edge lengths.
  static double distance_to_goal(const Singularity_repair_state<Mesh>& state, const std::vector<Index>& edges, const Goal& goal)
  {
    double d = 0;
    for(Index e : edges) {
      if(!is_singular_class(state.edge_class(e))) continue;
      const auto& ev = state.mesh().edge_vertices(e);
      const Eigen::Vector3d p = point(state.mesh(), ev[0]), q = point(state.mesh(), ev[1]);
      const Eigen::Vector3d m = 0.5 * (p + q) - goal.point;
      d += (q - p).norm() * (m - m.dot(goal.axis) * goal.axis).norm();
    }
    return d / (state.mean_edge_length() * state.mean_edge_length());
  }

  // A chain of moves (face, new matching), its total change of cost and its rank in the beam.
  struct Chain
  {
    std::vector<std::pair<Index, int> > moves;
    double total = 0, score = 0;
    std::vector<std::pair<Index, int> > configuration; // singular touched edges and their holonomies
  };

  static void apply(Singularity_repair_state<Mesh>& state, const Chain& c, std::vector<std::pair<Index, int> >& undo)
  {
    undo.clear();
    for(const auto& m : c.moves) {
      undo.emplace_back(m.first, state.matching(m.first));
      state.apply(m.first, m.second);
    }
  }
  static void revert(Singularity_repair_state<Mesh>& state, const std::vector<std::pair<Index, int> >& undo)
  {
    for(auto u = undo.rbegin(); u != undo.rend(); ++u) state.apply(u->first, u->second);
  }

  // The next moves of chain c (applied): of the singular edges of its last two faces, or of e first.
  void next_moves(Singularity_repair_state<Mesh>& state, const Chain& c, Index e, std::vector<Face_change>& next) const
  {
    next.clear();
    if(c.moves.empty()) m_move.propose(state, Repair_site{true, std::uint32_t(e)}, next);
    for(std::size_t k = c.moves.size() >= 2 ? c.moves.size() - 2 : 0; k < c.moves.size(); ++k)
      for(Index s : state.face_edges(c.moves[k].first))
        if(is_singular_class(state.edge_class(s))) m_move.propose(state, Repair_site{true, std::uint32_t(s)}, next);
  }

  // The lowest-cost chain found by a beam search from edge e, ranked by cost plus distance to the goal
  // (the distance steers, the cost decides), if it lowers the cost (an empty change otherwise). The
  // state is left as it was.
  Face_change best_chain(Singularity_repair_state<Mesh>& state, Index v, Index e, const Goal& goal) const
  {
    const std::vector<Index> curve = curve_from(state, v, e, 8);
    const std::vector<Index> around = touched_vertices(state, Chain(), curve);
    const Defects_around before{node_defects(state, around), plane_ends(state, around)};
    std::vector<Chain> beam(1), candidates, seen;
    Chain best;
    std::vector<std::pair<Index, int> > undo;
    std::vector<Face_change> next;
    for(std::size_t depth = 0; depth < m_max_moves && !beam.empty(); ++depth) {
      candidates.clear();
      for(const Chain& c : beam) {
        apply(state, c, undo);
        next_moves(state, c, e, next);
        for(const Face_change& d : next) {
          const Index f = Index(d.face);
          if(std::any_of(c.moves.begin(), c.moves.end(), [&](const std::pair<Index, int>& m) { return m.first == f; })) continue;
          const double delta = state.evaluate(f, d.matching);
          if(!std::isfinite(delta)) continue;
          Chain n = c;
          n.moves.emplace_back(f, d.matching);
          n.total += delta;
          const int old = state.matching(f);
          state.apply(f, d.matching);
          const std::vector<Index> touched = touched_edges(state, n, curve);
          n.score = n.total + distance_to_goal(state, touched, goal);
          for(Index t : touched)
            if(is_singular_class(state.edge_class(t))) n.configuration.emplace_back(t, state.holonomy(t));
          state.apply(f, old);
          candidates.push_back(std::move(n));
        }
        revert(state, undo);
      }
      std::sort(candidates.begin(), candidates.end(), [](const Chain& a, const Chain& b) { return a.score < b.score; });
      beam.clear();
      for(Chain& c : candidates) {
        if(c.total < best.total - 1e-9 && frees_end_alone(state, c, v, curve, before)) best = c;
        if(beam.size() < m_beam_width && !c.configuration.empty() && !same_configuration_as_one_of(c, beam) && !same_configuration_as_one_of(c, seen)) {
          seen.push_back(c);
          beam.push_back(std::move(c));
        }
      }
    }
    Face_change chain;
    if(best.moves.empty()) return chain;
    chain.face = std::uint32_t(best.moves[0].first);
    chain.matching = best.moves[0].second;
    for(std::size_t k = 1; k < best.moves.size(); ++k) chain.more.emplace_back(std::uint32_t(best.moves[k].first), best.moves[k].second);
    return chain;
  }

  // Whether chain c leaves the touched edges as one of `chains` does (a chain that moves an edge
  // there and back, by other faces, is no new state).
  static bool same_configuration_as_one_of(const Chain& c, const std::vector<Chain>& chains)
  {
    return std::any_of(chains.begin(), chains.end(), [&](const Chain& b) { return b.configuration == c.configuration; });
  }

  // The curve's edges from end v through e, up to `count` of them (through vertices of two singular edges).
  static std::vector<Index> curve_from(const Singularity_repair_state<Mesh>& state, Index v, Index e, std::size_t count)
  {
    std::vector<Index> out{e};
    const Mesh& mesh = state.mesh();
    while(out.size() < count) {
      const auto& ev = mesh.edge_vertices(out.back());
      v = ev[0] == v ? ev[1] : ev[0];
      if(mesh.is_boundary_vertex(v)) break;
      const std::vector<Index> at = singular_edges_at(state, v);
      if(at.size() != 2) break;
      out.push_back(at[0] == out.back() ? at[1] : at[0]);
    }
    return out;
  }

  // The vertices of touched_edges().
  static std::vector<Index> touched_vertices(const Singularity_repair_state<Mesh>& state, const Chain& c, const std::vector<Index>& curve)
  {
    std::vector<Index> out;
    for(Index e : touched_edges(state, c, curve))
      for(Index x : state.mesh().edge_vertices(e)) out.push_back(x);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // Dangling ends, zippers (leaning ones too) and invalid nodes among `vertices`: a pulled end must not
  // buy its way with one of these (each costs as two ends in boundary planes).
  static std::size_t node_defects(const Singularity_repair_state<Mesh>& state, const std::vector<Index>& vertices)
  {
    std::size_t n = 0;
    for(Index x : vertices) {
      const auto kind = vertex_singularity(state.mesh(), state.edge_classes(), x).kind;
      n += kind == Vertex_singularity::DANGLING_END || kind == Vertex_singularity::ZIPPER || kind == Vertex_singularity::INVALID_NODE ||
           state.turns_lean(x) || state.is_invalid_boundary_corner(x);
    }
    return n;
  }

  struct Defects_around
  {
    std::size_t nodes, plane_ends;
  };

  // Boundary vertices among `vertices` where a curve ends in a boundary plane.
  static std::size_t plane_ends(const Singularity_repair_state<Mesh>& state, const std::vector<Index>& vertices)
  {
    return std::size_t(std::count_if(vertices.begin(), vertices.end(), [&](Index x) {
      return state.mesh().is_boundary_vertex(x) && state.ends_in_boundary_plane(x);
    }));
  }

  // Whether chain c, applied, frees end v, leaves fewer curve ends in boundary planes around the touched
  // edges than `before` and no more node_defects(). A chain that only lowers the cost (straighter curves on
  // the way, the end still in its plane) is not a pull: measured on n01c, such chains made the seamless
  // map fold more, and they doubled the repair's time on i01c.
  static bool frees_end_alone(Singularity_repair_state<Mesh>& state, const Chain& c, Index v, const std::vector<Index>& curve,
                              const Defects_around& before)
  {
    std::vector<std::pair<Index, int> > undo;
    apply(state, c, undo);
    const std::vector<Index> around = touched_vertices(state, c, curve);
    const bool ok = !state.ends_in_boundary_plane(v) && plane_ends(state, around) < before.plane_ends &&
                    node_defects(state, around) <= before.nodes;
    revert(state, undo);
    return ok;
  }

  // The curve's first edges and the edges of the faces of chain c.
  static std::vector<Index> touched_edges(const Singularity_repair_state<Mesh>& state, const Chain& c, const std::vector<Index>& curve)
  {
    std::vector<Index> out = curve;
    for(const auto& m : c.moves)
      for(Index s : state.face_edges(m.first)) out.push_back(s);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  Move_singular_edge<Mesh> m_move;
  std::size_t m_max_moves, m_beam_width;
  int m_max_depth;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_PULL_CURVE_END_H
