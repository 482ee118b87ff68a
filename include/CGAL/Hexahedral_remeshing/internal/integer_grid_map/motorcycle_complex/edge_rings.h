// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_EDGE_RINGS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_EDGE_RINGS_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/exact_map_mesh.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// A face around an edge: face `face` of tetrahedron `tet`, and the chart change from the first
// tetrahedron of the ring to `tet`.
struct Ring_face
{
  std::size_t tet;
  int face;
  Chart_transition chart;
};

// The faces around an edge in order: for an interior edge every face once, from the first
// tetrahedron around; for a boundary edge from one boundary face to the other (both included).
struct Edge_ring
{
  std::vector<Ring_face> faces;
  bool closed = false;
  bool seamless = true;
  Chart_transition holonomy; // closed rings: the chart change once around the edge
};

inline Edge_ring ring_of_edge(const Exact_map_mesh& mesh, std::size_t t, std::uint32_t x, std::uint32_t y)
{
  Edge_ring ring;
  std::size_t start = t;
  int start_face = -1;
  std::uint32_t start_z = mesh.other_vertices(t, x, y)[0];
  ring.closed = mesh.walk_around(t, x, y, start_z, [&](std::size_t from, int f, std::int64_t to) {
    if(to >= 0) return true;
    start = from;
    start_face = f;
    // the other face of `from` around the edge is opposite the third vertex of the boundary face
    for(std::uint32_t v : mesh.tetrahedra[from].vertex)
      if(v != x && v != y && v != mesh.tetrahedra[from].vertex[std::size_t(f)]) start_z = v;
    return false;
  });
  if(!ring.closed) ring.faces.push_back(Ring_face{start, start_face, Chart_transition()});
  Chart_transition chart;
  mesh.walk_around(start, x, y, start_z, [&](std::size_t from, int f, std::int64_t to) {
    ring.faces.push_back(Ring_face{from, f, chart});
    if(to < 0) return false;
    const Chart_transition* c = mesh.transition(from, f);
    if(!c) { ring.seamless = false; return false; }
    if(mesh.tetrahedra[from].origin != mesh.tetrahedra[std::size_t(to)].origin) chart = chart.then(*c);
    return true;
  });
  ring.holonomy = chart;
  return ring;
}

// The axis plane that holds face f of tetrahedron t in its chart (false if none: the face is not on
// a plane of the map).
inline bool plane_of_face(const Exact_map_mesh& mesh, std::size_t t, int f, Axis_plane& plane)
{
  const Map_tetrahedron& T = mesh.tetrahedra[t];
  const std::size_t a = std::size_t(f == 0 ? 1 : 0), b = std::size_t(f <= 1 ? 2 : 1), c = std::size_t(f <= 2 ? 3 : 2);
  for(std::size_t k = 0; k < 3; ++k)
    if(T.parameter[a][k] == T.parameter[b][k] && T.parameter[a][k] == T.parameter[c][k]) {
      plane = Axis_plane{int(k), T.parameter[a][k]};
      return true;
    }
  return false;
}

// Whether two faces of a ring lie on one plane (a sheet that goes on across the edge).
inline bool coplanar(const Exact_map_mesh& mesh, const Ring_face& a, const Ring_face& b)
{
  Axis_plane p;
  if(!plane_of_face(mesh, a.tet, a.face, p)) return false;
  const Axis_plane q = p.in(a.chart.inverse()).in(b.chart);
  const Map_tetrahedron& T = mesh.tetrahedra[b.tet];
  for(int c = 0; c < 4; ++c)
    if(c != b.face && q.side(T.parameter[std::size_t(c)]) != CGAL::ZERO) return false;
  return true;
}

// The curves the walls start from: singular edges (a closed ring whose holonomy is not the
// identity) and feature edges (a boundary edge whose two boundary faces are not on one plane).
struct Curve_edges
{
  std::vector<std::pair<std::size_t, std::array<std::uint32_t, 2> > > singular, feature;
  std::size_t not_seamless = 0;
};

inline Curve_edges curve_edges(const Exact_map_mesh& mesh)
{
  // every edge once, with a tetrahedron having it
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::size_t> > edges;
  edges.reserve(6 * mesh.tetrahedra.size());
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) {
        std::uint32_t a = mesh.tetrahedra[t].vertex[std::size_t(i)], b = mesh.tetrahedra[t].vertex[std::size_t(j)];
        if(a > b) std::swap(a, b);
        edges.emplace_back(std::make_pair(a, b), t);
      }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end(), [](const auto& p, const auto& q) { return p.first == q.first; }), edges.end());
  Curve_edges curves;
  for(const auto& e : edges) {
    const std::array<std::uint32_t, 2> xy{{e.first.first, e.first.second}};
    const Edge_ring ring = ring_of_edge(mesh, e.second, xy[0], xy[1]);
    if(!ring.seamless) { ++curves.not_seamless; continue; }
    if(ring.closed && !ring.holonomy.R.is_identity()) curves.singular.emplace_back(e.second, xy);
    if(!ring.closed && !coplanar(mesh, ring.faces.front(), ring.faces.back())) curves.feature.emplace_back(e.second, xy);
  }
  return curves;
}

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_EDGE_RINGS_H
