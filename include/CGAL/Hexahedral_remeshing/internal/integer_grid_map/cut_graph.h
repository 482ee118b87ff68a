// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_CUT_GRAPH_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_CUT_GRAPH_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>

#include <cstdint>
#include <deque>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The cut of the seamless map (algorithms.md §4 "Cut"): the interior faces across which the map may
// jump by a transition with an unknown integer translation. Everywhere else the charts of two
// neighbouring tetrahedra are glued by the matching alone.
//
// 1. The faces not in a breadth-first dual spanning tree are cut (the tree is the glued part).
// 2. A cut face with an unprotected edge that has no other cut face is uncut: the ring of that edge
//    becomes entirely glued and the cycle around it has the trivial holonomy of a regular edge, so
//    the glued part stays consistent. Boundary edges and edges with a non-trivial holonomy are
//    protected.
// 3. A face is never uncut if it is the last cut face of an edge with a non-trivial holonomy:
//    with a fully glued ring the coordinates crossing the holonomy would be forced to x = -x = 0.
//
// `protected_edge[e]` != 0 for the protected edges; `singular_edge[e]` != 0 for the edges with a
// non-trivial holonomy. Returns per face: 1 if cut (interior faces only).
template <class Traits>
std::vector<char> compute_cut_faces(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<char>& protected_edge,
                                    const std::vector<char>& singular_edge)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const Index null = Tetrahedral_mesh_3<Traits>::null_index;
  const std::size_t nt = mesh.number_of_tetrahedra(), nf = mesh.number_of_faces(), ne = mesh.number_of_edges();
  std::vector<char> cut(nf, 0);
  for(Index f = 0; f < nf; ++f) cut[f] = !mesh.is_boundary_face(f);

  std::vector<char> visited(nt, 0);
  std::deque<Index> queue;
  for(Index seed = 0; seed < nt; ++seed) {
    if(visited[seed]) continue;
    visited[seed] = 1;
    queue.push_back(seed);
    while(!queue.empty()) {
      const Index t = queue.front();
      queue.pop_front();
      for(int i = 0; i < 4; ++i) {
        const Index n = mesh.tetrahedron_neighbor(t, i);
        if(n == null || visited[n]) continue;
        visited[n] = 1;
        cut[mesh.tetrahedron_face(t, i)] = 0;
        queue.push_back(n);
      }
    }
  }

  // edges of every face (3 per face, from the rings)
  std::vector<std::array<Index, 3> > face_edges(nf, {null, null, null});
  std::vector<std::uint8_t> filled(nf, 0);
  std::vector<std::uint32_t> cut_count(ne, 0);
  for(Index e = 0; e < ne; ++e)
    for(Index f : mesh.edge_ring_faces(e)) {
      if(filled[f] < 3) face_edges[f][filled[f]++] = e;
      cut_count[e] += cut[f];
    }

  auto removable = [&](Index f) {
    if(!cut[f]) return false;
    bool free_edge = false;
    for(Index e : face_edges[f]) {
      if(singular_edge[e] && cut_count[e] <= 1) return false;
      if(!protected_edge[e] && cut_count[e] == 1) free_edge = true;
    }
    return free_edge;
  };
  std::vector<Index> stack;
  for(Index e = 0; e < ne; ++e)
    if(!protected_edge[e] && cut_count[e] == 1) stack.push_back(e);
  while(!stack.empty()) {
    const Index e = stack.back();
    stack.pop_back();
    if(protected_edge[e] || cut_count[e] != 1) continue;
    Index face = null;
    for(Index f : mesh.edge_ring_faces(e))
      if(cut[f]) { face = f; break; }
    if(face == null || !removable(face)) continue;
    cut[face] = 0;
    for(Index e2 : face_edges[face]) {
      --cut_count[e2];
      if(!protected_edge[e2] && cut_count[e2] == 1) stack.push_back(e2);
    }
  }
  return cut;
}

// The cut of the map: the faces cut by compute_cut_faces() with the boundary edges and the edges of
// non-trivial holonomy protected, and each cut face's index among them (-1 elsewhere).
struct Map_cut
{
  std::vector<char> cut;                 // per face
  std::vector<std::uint32_t> cut_index;  // per face
  std::size_t cut_faces = 0;
};

template <class Traits>
Map_cut compute_map_cut(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<int>& edge_holonomy, int identity)
{
  const std::size_t ne = mesh.number_of_edges(), nf = mesh.number_of_faces();
  std::vector<char> protected_edge(ne, 0), singular_edge(ne, 0);
  for(std::uint32_t e = 0; e < ne; ++e) {
    if(mesh.is_boundary_edge(e)) { protected_edge[e] = 1; continue; }
    if(edge_holonomy[e] != identity) protected_edge[e] = singular_edge[e] = 1;
  }
  Map_cut c;
  c.cut = compute_cut_faces(mesh, protected_edge, singular_edge);
  c.cut_index.assign(nf, std::uint32_t(-1));
  for(std::uint32_t f = 0; f < nf; ++f)
    if(c.cut[f]) c.cut_index[f] = std::uint32_t(c.cut_faces++);
  return c;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_CUT_GRAPH_H
