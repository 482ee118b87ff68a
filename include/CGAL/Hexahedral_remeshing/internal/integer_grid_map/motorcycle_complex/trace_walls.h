// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_TRACE_WALLS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_TRACE_WALLS_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/edge_rings.h>

#include <cstdint>
#include <queue>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// The walls of the motorcycle complex (robust_pipeline.md §3.1; Brückler, Bommes, Campen 2022):
// from every singular and feature curve, one wall in each of the two iso-planes containing the curve.
// A wall grows through the tetrahedra its plane meets, splitting exactly the edges it crosses, so
// that it is made of faces of the refined mesh; it stops at the boundary and at walls already there.
// All walls grow at once in order of parametric distance from their curve (the distance is measured
// in the second plane of the curve, the "ruler"), so that of two crossing walls the one that comes
// first goes on and the other stops on it: no wall can spiral forever.
class Wall_tracer
{
public:
  std::size_t split_edges = 0, seeds = 0, not_seamless = 0;
  bool too_large = false;

  Wall_tracer(Exact_map_mesh& mesh, std::size_t maximum_tetrahedra) : m_mesh(mesh), m_maximum(maximum_tetrahedra) {}

  // Two walls from the curve edge (x, y) of tetrahedron t (one line of its chart: two coordinates
  // constant), in every tetrahedron around the edge that the planes meet.
  void seed(std::size_t t, std::uint32_t x, std::uint32_t y)
  {
    const Parameter& px = m_mesh.tetrahedra[t].parameter[std::size_t(m_mesh.corner(t, x))];
    const Parameter& py = m_mesh.tetrahedra[t].parameter[std::size_t(m_mesh.corner(t, y))];
    int along = -1;
    for(int k = 0; k < 3; ++k)
      if(px[std::size_t(k)] != py[std::size_t(k)]) along = along < 0 ? k : 3;
    if(along < 0 || along == 3) return; // not on a line of the chart: no wall (counted by the caller)
    for(int k = 0; k < 3; ++k) {
      if(k == along) continue;
      const int r = 3 - along - k;
      seed_plane(t, x, y, Axis_plane{k, px[std::size_t(k)]}, Axis_plane{r, px[std::size_t(r)]});
    }
  }

  // Grows all walls; false if the mesh grew past the limit.
  bool run()
  {
    while(!m_queue.empty()) {
      const Front f = m_queue.top();
      m_queue.pop();
      if(m_mesh.tetrahedra.size() > m_maximum) { too_large = true; return false; }
      process(f);
    }
    return true;
  }

  int walls() const { return m_walls; }

private:
  struct Front
  {
    Rational distance;
    std::uint64_t order;
    std::size_t tet;
    int wall;
    Axis_plane plane, ruler;
  };
  struct Later
  {
    bool operator()(const Front& a, const Front& b) const
    {
      return b.distance < a.distance || (b.distance == a.distance && b.order < a.order);
    }
  };

  // Whether the plane cuts tetrahedron t through its edge (x, y) or holds one of its faces there.
  bool meets_beyond_edge(std::size_t t, std::uint32_t x, std::uint32_t y, const Axis_plane& plane) const
  {
    const std::array<std::uint32_t, 2> o = m_mesh.other_vertices(t, x, y);
    const CGAL::Sign a = plane.side(m_mesh.tetrahedra[t].parameter[std::size_t(m_mesh.corner(t, o[0]))]);
    const CGAL::Sign b = plane.side(m_mesh.tetrahedra[t].parameter[std::size_t(m_mesh.corner(t, o[1]))]);
    return a == CGAL::ZERO || b == CGAL::ZERO || a != b;
  }

  void push(std::size_t t, int wall, const Axis_plane& plane, const Axis_plane& ruler)
  {
    Rational d = -1;
    for(const Parameter& p : m_mesh.tetrahedra[t].parameter) {
      const Rational a = CGAL::abs(p[std::size_t(ruler.axis)] - ruler.value);
      if(d < 0 || a < d) d = a;
    }
    m_queue.push(Front{d, m_order++, t, wall, plane, ruler});
  }

  void seed_plane(std::size_t t, std::uint32_t x, std::uint32_t y, const Axis_plane& plane, const Axis_plane& ruler)
  {
    const int wall = m_walls++;
    ++seeds;
    if(meets_beyond_edge(t, x, y, plane)) push(t, wall, plane, ruler);
    const std::array<std::uint32_t, 2> z = m_mesh.other_vertices(t, x, y);
    for(std::uint32_t start : z) {
      Chart_transition chart;
      const bool closed = m_mesh.walk_around(t, x, y, start, [&](std::size_t from, int f, std::int64_t to) {
        if(to < 0 || std::size_t(to) == t) return true;
        Chart_transition c;
        if(!m_mesh.transition(from, f, c)) { ++not_seamless; return false; }
        chart = chart.then(c);
        const Axis_plane p = plane.in(chart);
        if(meets_beyond_edge(std::size_t(to), x, y, p)) push(std::size_t(to), wall, p, ruler.in(chart));
        return true;
      });
      if(closed) break;
    }
  }

  // From tetrahedron t across its face opposite z (x, y, z: a face of t on the wall's plane): the
  // first tetrahedron around (x, y) that the plane meets beyond the edge, unless a wall or the
  // boundary comes first.
  void continue_past(std::size_t t, std::uint32_t x, std::uint32_t y, std::uint32_t z, int wall, const Axis_plane& plane,
                     const Axis_plane& ruler)
  {
    Chart_transition chart;
    m_mesh.walk_around(t, x, y, z, [&](std::size_t from, int f, std::int64_t to) {
      if(m_mesh.tetrahedra[from].wall[std::size_t(f)] != NOT_A_WALL || std::size_t(to) == t) return false;
      Chart_transition c;
      if(!m_mesh.transition(from, f, c)) { ++not_seamless; return false; }
      chart = chart.then(c);
      const Axis_plane p = plane.in(chart);
      if(!meets_beyond_edge(std::size_t(to), x, y, p)) return true;
      push(std::size_t(to), wall, p, ruler.in(chart));
      return false;
    });
  }

  void process(const Front& w)
  {
    const std::size_t t = w.tet;
    std::array<CGAL::Sign, 4> s;
    for(std::size_t c = 0; c < 4; ++c) s[c] = w.plane.side(m_mesh.tetrahedra[t].parameter[c]);
    for(std::size_t i = 0; i < 4; ++i)
      for(std::size_t j = i + 1; j < 4; ++j) {
        if(s[i] == CGAL::ZERO || s[j] == CGAL::ZERO || s[i] == s[j]) continue;
        const Map_tetrahedron& T = m_mesh.tetrahedra[t];
        const std::size_t k = std::size_t(w.plane.axis);
        const Rational lambda = (w.plane.value - T.parameter[i][k]) / (T.parameter[j][k] - T.parameter[i][k]);
        const std::uint32_t x = T.vertex[i];
        m_mesh.split_edge(t, x, T.vertex[j], lambda);
        ++split_edges;
        const std::size_t half = std::size_t(m_mesh.tetrahedra[t].neighbor[std::size_t(m_mesh.corner(t, x))]);
        push(t, w.wall, w.plane, w.ruler);
        push(half, w.wall, w.plane, w.ruler);
        return;
      }
    for(int f = 0; f < 4; ++f) {
      bool on_plane = s[std::size_t(f)] != CGAL::ZERO;
      for(int c = 0; c < 4; ++c) on_plane = on_plane && (c == f || s[std::size_t(c)] == CGAL::ZERO);
      if(!on_plane || m_mesh.tetrahedra[t].wall[std::size_t(f)] != NOT_A_WALL) continue;
      mark_and_continue(t, f, w);
    }
  }

  void mark_and_continue(std::size_t t, int f, const Front& w)
  {
    Map_tetrahedron& T = m_mesh.tetrahedra[t];
    const std::size_t n = std::size_t(T.neighbor[std::size_t(f)]);
    T.wall[std::size_t(f)] = w.wall;
    m_mesh.tetrahedra[n].wall[std::size_t(m_mesh.face_towards(n, t))] = w.wall;
    Chart_transition into_n;
    const bool seamless = m_mesh.transition(t, f, into_n);
    not_seamless += !seamless;
    const std::array<std::uint32_t, 4> v = T.vertex;
    for(int a = 0; a < 4; ++a) {
      if(a == f) continue;
      std::array<std::uint32_t, 2> edge;
      for(int b = 0, j = 0; b < 4; ++b)
        if(b != f && b != a) edge[std::size_t(j++)] = v[std::size_t(b)];
      continue_past(t, edge[0], edge[1], v[std::size_t(a)], w.wall, w.plane, w.ruler);
      if(seamless) continue_past(n, edge[0], edge[1], v[std::size_t(a)], w.wall, w.plane.in(into_n), w.ruler.in(into_n));
    }
  }

  Exact_map_mesh& m_mesh;
  std::size_t m_maximum;
  int m_walls = 0;
  std::uint64_t m_order = 0;
  std::priority_queue<Front, std::vector<Front>, Later> m_queue;
};

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_TRACE_WALLS_H
