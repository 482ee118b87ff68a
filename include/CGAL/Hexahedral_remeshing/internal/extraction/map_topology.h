// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_MAP_TOPOLOGY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_MAP_TOPOLOGY_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace extraction {

// Local face f of a tetrahedron is the face opposite local vertex f; its vertices in this order.
constexpr int face_vertices[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
// Local edges (a, b) of a tetrahedron and the two local vertices opposite to them.
constexpr int edge_vertices[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
constexpr int edge_opposite[6][2] = {{2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1}};

constexpr std::uint32_t no_tetrahedron = 0xffffffffu;

// Face adjacency, edges and vertex stars of the tetrahedra of a map, matched by sorted vertex ids
// (a map read from a file has no other topology).
struct Map_topology
{
  // neighbor[t][f]: the tetrahedron across local face f (no_tetrahedron on the boundary) and
  // neighbor_face[t][f] its local face index.
  std::vector<std::array<std::uint32_t, 4> > neighbor;
  std::vector<std::array<std::int8_t, 4> > neighbor_face;
  // Edges as sorted vertex pairs; tetrahedron_edges[t][e] is the id of local edge e of t.
  std::vector<std::array<std::uint32_t, 2> > edges;
  std::vector<std::array<std::uint32_t, 6> > tetrahedron_edges;
  // Smallest tetrahedron index containing each edge / vertex (the owner of the simplex).
  std::vector<std::uint32_t> edge_owner, vertex_owner;
  // Boundary marks.
  std::vector<char> edge_on_boundary, vertex_on_boundary;
  // Tetrahedra containing every edge (CSR).
  std::vector<std::uint32_t> edge_star_begin, edge_star;
  // Incident tetrahedra of every vertex (CSR).
  std::vector<std::uint32_t> vertex_star_begin, vertex_star;
  std::size_t interior_faces = 0, boundary_faces = 0;

  std::uint32_t face_owner(std::uint32_t t, int f) const
  {
    const std::uint32_t n = neighbor[t][f];
    return n == no_tetrahedron ? t : (std::min)(t, n);
  }
};

inline void build_map_topology(const Integer_grid_map& map, Map_topology& topo)
{
  const std::size_t nt = map.tetrahedra.size(), nv = map.points.size();
  if(map.parameters.size() != nt)
    throw Input_error(map.source, 0, "integer-grid map with " + std::to_string(nt) + " tetrahedra but " +
                                         std::to_string(map.parameters.size()) + " parameter sets");
  for(std::size_t t = 0; t < nt; ++t)
    for(int k = 0; k < 4; ++k)
      if(map.tetrahedra[t][k] >= nv)
        throw Input_error(map.source, 0, "tetrahedron " + std::to_string(t) + ": vertex id out of range");

  struct Face_key { std::array<std::uint32_t, 3> v; std::uint32_t t; int f; };
  std::vector<Face_key> faces;
  faces.reserve(4 * nt);
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int f = 0; f < 4; ++f) {
      std::array<std::uint32_t, 3> v;
      for(int k = 0; k < 3; ++k) v[k] = map.tetrahedra[t][face_vertices[f][k]];
      std::sort(v.begin(), v.end());
      faces.push_back({v, t, f});
    }
  std::sort(faces.begin(), faces.end(), [](const Face_key& a, const Face_key& b) {
    return a.v != b.v ? a.v < b.v : a.t < b.t;
  });
  topo.neighbor.assign(nt, {{no_tetrahedron, no_tetrahedron, no_tetrahedron, no_tetrahedron}});
  topo.neighbor_face.assign(nt, {{-1, -1, -1, -1}});
  topo.interior_faces = topo.boundary_faces = 0;
  for(std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while(j < faces.size() && faces[j].v == faces[i].v) ++j;
    if(j - i > 2)
      throw Input_error(map.source, 0, "face (" + std::to_string(faces[i].v[0]) + ", " + std::to_string(faces[i].v[1]) +
                                           ", " + std::to_string(faces[i].v[2]) + ") is shared by " +
                                           std::to_string(j - i) + " tetrahedra (non-manifold or duplicate tetrahedra)");
    if(j - i == 2) {
      const Face_key& a = faces[i];
      const Face_key& b = faces[i + 1];
      topo.neighbor[a.t][a.f] = b.t; topo.neighbor_face[a.t][a.f] = std::int8_t(b.f);
      topo.neighbor[b.t][b.f] = a.t; topo.neighbor_face[b.t][b.f] = std::int8_t(a.f);
      ++topo.interior_faces;
    } else {
      ++topo.boundary_faces;
    }
    i = j;
  }

  struct Edge_key { std::uint32_t a, b, t; int e; };
  std::vector<Edge_key> ek;
  ek.reserve(6 * nt);
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int e = 0; e < 6; ++e) {
      std::uint32_t a = map.tetrahedra[t][edge_vertices[e][0]], b = map.tetrahedra[t][edge_vertices[e][1]];
      if(a > b) std::swap(a, b);
      ek.push_back({a, b, t, e});
    }
  std::sort(ek.begin(), ek.end(), [](const Edge_key& x, const Edge_key& y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.t < y.t;
  });
  topo.edges.clear(); topo.edge_owner.clear();
  topo.tetrahedron_edges.assign(nt, {});
  for(std::size_t i = 0; i < ek.size();) {
    std::size_t j = i;
    const std::uint32_t id = std::uint32_t(topo.edges.size());
    topo.edges.push_back({ek[i].a, ek[i].b});
    topo.edge_owner.push_back(ek[i].t);
    while(j < ek.size() && ek[j].a == ek[i].a && ek[j].b == ek[i].b) {
      topo.tetrahedron_edges[ek[j].t][ek[j].e] = id;
      ++j;
    }
    i = j;
  }

  topo.edge_star_begin.assign(topo.edges.size() + 1, 0);
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int e = 0; e < 6; ++e) ++topo.edge_star_begin[topo.tetrahedron_edges[t][e] + 1];
  for(std::size_t e = 0; e < topo.edges.size(); ++e) topo.edge_star_begin[e + 1] += topo.edge_star_begin[e];
  topo.edge_star.resize(6 * nt);
  {
    std::vector<std::uint32_t> fill(topo.edge_star_begin.begin(), topo.edge_star_begin.end() - 1);
    for(std::uint32_t t = 0; t < nt; ++t)
      for(int e = 0; e < 6; ++e) topo.edge_star[fill[topo.tetrahedron_edges[t][e]]++] = t;
  }

  topo.vertex_owner.assign(nv, no_tetrahedron);
  topo.vertex_star_begin.assign(nv + 1, 0);
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int k = 0; k < 4; ++k) {
      const std::uint32_t v = map.tetrahedra[t][k];
      topo.vertex_owner[v] = (std::min)(topo.vertex_owner[v], t);
      ++topo.vertex_star_begin[v + 1];
    }
  for(std::size_t v = 0; v < nv; ++v) topo.vertex_star_begin[v + 1] += topo.vertex_star_begin[v];
  topo.vertex_star.resize(4 * nt);
  {
    std::vector<std::uint32_t> fill(topo.vertex_star_begin.begin(), topo.vertex_star_begin.end() - 1);
    for(std::uint32_t t = 0; t < nt; ++t)
      for(int k = 0; k < 4; ++k) topo.vertex_star[fill[map.tetrahedra[t][k]]++] = t;
  }

  topo.edge_on_boundary.assign(topo.edges.size(), 0);
  topo.vertex_on_boundary.assign(nv, 0);
  for(std::uint32_t t = 0; t < nt; ++t)
    for(int f = 0; f < 4; ++f) {
      if(topo.neighbor[t][f] != no_tetrahedron) continue;
      for(int k = 0; k < 3; ++k) topo.vertex_on_boundary[map.tetrahedra[t][face_vertices[f][k]]] = 1;
      for(int e = 0; e < 6; ++e)
        if(edge_vertices[e][0] != f && edge_vertices[e][1] != f) topo.edge_on_boundary[topo.tetrahedron_edges[t][e]] = 1;
    }
}

} // namespace extraction
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_MAP_TOPOLOGY_H
