// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_TRACE_WALLS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_TRACE_WALLS_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/edge_rings.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/wall_forms.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <queue>
#include <utility>
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
  // With forms: per wall and input tetrahedron, the planes of the wall in that chart with their values
  // as functions of the map's variables.
  std::map<std::pair<int, std::uint32_t>, std::vector<Plane_form> > wall_planes;

  // `forms` and `input` (the input tetrahedra) may be null: the walls' values are then not tracked.
  bool out_of_time = false;

  // The tracing stops when the mesh has `maximum_tetrahedra` or after `seconds` (the exact split
  // points of walls crossing walls' splits are rationals that grow: a fine graded mesh can make them
  // costly).
  Wall_tracer(Exact_map_mesh& mesh, std::size_t maximum_tetrahedra, const Map_forms* forms = nullptr,
              const std::vector<std::array<std::uint32_t, 4> >* input = nullptr, double seconds = 60)
    : m_mesh(mesh), m_maximum(maximum_tetrahedra), m_forms(forms), m_input(input), m_seconds(seconds)
  {}

  // Two walls from the curve edge (x, y) of tetrahedron t (one line of its chart: two coordinates
  // constant), in every tetrahedron around the edge that the planes meet.
  void seed(std::size_t t, std::uint32_t x, std::uint32_t y)
  {
    const Map_tetrahedron& T = m_mesh.tetrahedra[t];
    const Parameter& px = T.parameter[std::size_t(m_mesh.corner(t, x))];
    const Parameter& py = T.parameter[std::size_t(m_mesh.corner(t, y))];
    int along = -1;
    for(int k = 0; k < 3; ++k)
      if(px[std::size_t(k)] != py[std::size_t(k)]) along = along < 0 ? k : 3;
    if(along < 0 || along == 3) return; // not on a line of the chart: no wall (counted by the caller)
    for(int k = 0; k < 3; ++k) {
      if(k == along) continue;
      const int r = 3 - along - k;
      Carried c;
      c.plane.plane = Axis_plane{k, px[std::size_t(k)]};
      if(m_forms) c.plane.value = m_forms->corner(T.origin, x, k);
      c.ruler = Axis_plane{r, px[std::size_t(r)]};
      seed_plane(t, x, y, c);
    }
  }

  // Grows all walls; false if the mesh grew past the limit or the time ran out.
  bool run()
  {
    const auto start = std::chrono::steady_clock::now();
    for(std::size_t step = 0; !m_queue.empty(); ++step) {
      const Front f = m_queue.top();
      m_queue.pop();
      if(m_mesh.tetrahedra.size() > m_maximum) { too_large = true; return false; }
      if(step % 1024 == 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > m_seconds) {
        out_of_time = true;
        return false;
      }
      process(f);
    }
    return true;
  }

  int walls() const { return m_walls; }

private:
  // What a wall carries from chart to chart: its plane (with its value form) and its ruler.
  struct Carried
  {
    Plane_form plane;
    Axis_plane ruler;
  };
  struct Front
  {
    Rational distance;
    std::uint64_t order;
    std::size_t tet;
    int wall;
    Carried carried;
  };
  struct Later
  {
    bool operator()(const Front& a, const Front& b) const
    {
      return b.distance < a.distance || (b.distance == a.distance && b.order < a.order);
    }
  };

  // `c` from tetrahedron `from` across its face f into the neighbor; false if not seamless there.
  bool carry(Carried& c, std::size_t from, int f) const
  {
    const std::uint32_t o1 = m_mesh.tetrahedra[from].origin;
    const std::uint32_t o2 = m_mesh.tetrahedra[std::size_t(m_mesh.tetrahedra[from].neighbor[std::size_t(f)])].origin;
    if(o1 == o2) return true; // one chart: the identity
    const Chart_transition* tp = m_mesh.transition(from, f);
    if(!tp) return false;
    const Chart_transition& t = *tp;
    c.ruler = c.ruler.in(t);
    if(m_forms) c.plane = plane_form_in(c.plane, t, translation_forms(*m_forms, *m_input, o1, o2, t));
    else c.plane.plane = c.plane.plane.in(t);
    return true;
  }

  // Whether the plane cuts tetrahedron t through its edge (x, y) or holds one of its faces there.
  bool meets_beyond_edge(std::size_t t, std::uint32_t x, std::uint32_t y, const Axis_plane& plane) const
  {
    const std::array<std::uint32_t, 2> o = m_mesh.other_vertices(t, x, y);
    const CGAL::Sign a = plane.side(m_mesh.tetrahedra[t].parameter[std::size_t(m_mesh.corner(t, o[0]))]);
    const CGAL::Sign b = plane.side(m_mesh.tetrahedra[t].parameter[std::size_t(m_mesh.corner(t, o[1]))]);
    return a == CGAL::ZERO || b == CGAL::ZERO || a != b;
  }

  void push(std::size_t t, int wall, const Carried& c)
  {
    Rational d = -1;
    for(const Parameter& p : m_mesh.tetrahedra[t].parameter) {
      const Rational a = CGAL::abs(p[std::size_t(c.ruler.axis)] - c.ruler.value);
      if(d < 0 || a < d) d = a;
    }
    m_queue.push(Front{d, m_order++, t, wall, c});
  }

  void seed_plane(std::size_t t, std::uint32_t x, std::uint32_t y, const Carried& seed)
  {
    const int wall = m_walls++;
    ++seeds;
    if(meets_beyond_edge(t, x, y, seed.plane.plane)) push(t, wall, seed);
    const std::array<std::uint32_t, 2> z = m_mesh.other_vertices(t, x, y);
    for(std::uint32_t start : z) {
      Carried c = seed;
      const bool closed = m_mesh.walk_around(t, x, y, start, [&](std::size_t from, int f, std::int64_t to) {
        if(to < 0 || std::size_t(to) == t) return true;
        if(!carry(c, from, f)) { ++not_seamless; return false; }
        if(meets_beyond_edge(std::size_t(to), x, y, c.plane.plane)) push(std::size_t(to), wall, c);
        return true;
      });
      if(closed) break;
    }
  }

  // From tetrahedron t across its face opposite z (x, y, z: a face of t on the wall's plane): the
  // first tetrahedron around (x, y) that the plane meets beyond the edge, unless a wall or the
  // boundary comes first.
  void continue_past(std::size_t t, std::uint32_t x, std::uint32_t y, std::uint32_t z, int wall, Carried c)
  {
    m_mesh.walk_around(t, x, y, z, [&](std::size_t from, int f, std::int64_t to) {
      if(m_mesh.tetrahedra[from].wall[std::size_t(f)] != NOT_A_WALL || std::size_t(to) == t) return false;
      if(!carry(c, from, f)) { ++not_seamless; return false; }
      if(!meets_beyond_edge(std::size_t(to), x, y, c.plane.plane)) return true;
      push(std::size_t(to), wall, c);
      return false;
    });
  }

  // Cuts tetrahedron w.tet by the wall's plane, all of it before any other wall acts there, then makes
  // its parts' faces on the plane wall faces. Of the edges the plane crosses, the one with the oldest
  // vertices is split first: two walls that cross the same edges would else split, in turn, the edges
  // that the other's last split made, forever (each new vertex closer to the old edge).
  void process(const Front& w)
  {
    const Axis_plane& plane = w.carried.plane.plane;
    std::vector<std::size_t> parts{w.tet};
    while(!parts.empty()) {
      const std::size_t t = parts.back();
      parts.pop_back();
      std::array<CGAL::Sign, 4> s;
      for(std::size_t c = 0; c < 4; ++c) s[c] = plane.side(m_mesh.tetrahedra[t].parameter[c]);
      const std::array<std::size_t, 2> e = oldest_crossing_edge(t, s);
      if(e[0] < 4) {
        parts.push_back(t);
        parts.push_back(split(t, e, plane));
        continue;
      }
      for(int f = 0; f < 4; ++f) {
        bool on_plane = s[std::size_t(f)] != CGAL::ZERO;
        for(int c = 0; c < 4; ++c) on_plane = on_plane && (c == f || s[std::size_t(c)] == CGAL::ZERO);
        if(!on_plane || m_mesh.tetrahedra[t].wall[std::size_t(f)] != NOT_A_WALL) continue;
        Front part = w;
        part.tet = t;
        mark_and_continue(t, f, part);
      }
    }
  }

  // The corners of the edge of t with opposite signs whose newer vertex is the oldest ({4, 4} if none).
  std::array<std::size_t, 2> oldest_crossing_edge(std::size_t t, const std::array<CGAL::Sign, 4>& s) const
  {
    const Map_tetrahedron& T = m_mesh.tetrahedra[t];
    std::array<std::size_t, 2> best{{4, 4}};
    std::pair<std::uint32_t, std::uint32_t> age(std::uint32_t(-1), std::uint32_t(-1));
    for(std::size_t i = 0; i < 4; ++i)
      for(std::size_t j = i + 1; j < 4; ++j) {
        if(s[i] == CGAL::ZERO || s[j] == CGAL::ZERO || s[i] == s[j]) continue;
        const auto a = std::make_pair((std::max)(T.vertex[i], T.vertex[j]), (std::min)(T.vertex[i], T.vertex[j]));
        if(a < age) { age = a; best = {{i, j}}; }
      }
    return best;
  }

  // Splits edge e of t where the plane crosses it; returns the part of t at the edge's second end.
  std::size_t split(std::size_t t, const std::array<std::size_t, 2>& e, const Axis_plane& plane)
  {
    const Map_tetrahedron& T = m_mesh.tetrahedra[t];
    const std::size_t k = std::size_t(plane.axis);
    const Rational lambda = (plane.value - T.parameter[e[0]][k]) / (T.parameter[e[1]][k] - T.parameter[e[0]][k]);
    const std::uint32_t x = T.vertex[e[0]];
    m_mesh.split_edge(t, x, T.vertex[e[1]], lambda);
    ++split_edges;
    return std::size_t(m_mesh.tetrahedra[t].neighbor[std::size_t(m_mesh.corner(t, x))]);
  }

  void record(std::size_t t, int wall, const Plane_form& p)
  {
    if(!m_forms) return;
    std::vector<Plane_form>& planes = wall_planes[std::make_pair(wall, m_mesh.tetrahedra[t].origin)];
    for(const Plane_form& q : planes)
      if(q.plane.axis == p.plane.axis && q.plane.value == p.plane.value) return;
    planes.push_back(p);
  }

  void mark_and_continue(std::size_t t, int f, const Front& w)
  {
    Map_tetrahedron& T = m_mesh.tetrahedra[t];
    const std::size_t n = std::size_t(T.neighbor[std::size_t(f)]);
    T.wall[std::size_t(f)] = w.wall;
    m_mesh.tetrahedra[n].wall[std::size_t(m_mesh.face_towards(n, t))] = w.wall;
    Carried beyond = w.carried;
    const bool seamless = carry(beyond, t, f);
    not_seamless += !seamless;
    record(t, w.wall, w.carried.plane);
    if(seamless) record(n, w.wall, beyond.plane);
    const std::array<std::uint32_t, 4> v = T.vertex;
    for(int a = 0; a < 4; ++a) {
      if(a == f) continue;
      std::array<std::uint32_t, 2> edge;
      for(int b = 0, j = 0; b < 4; ++b)
        if(b != f && b != a) edge[std::size_t(j++)] = v[std::size_t(b)];
      continue_past(t, edge[0], edge[1], v[std::size_t(a)], w.wall, w.carried);
      if(seamless) continue_past(n, edge[0], edge[1], v[std::size_t(a)], w.wall, beyond);
    }
  }

  Exact_map_mesh& m_mesh;
  std::size_t m_maximum;
  const Map_forms* m_forms;
  const std::vector<std::array<std::uint32_t, 4> >* m_input;
  double m_seconds;
  int m_walls = 0;
  std::uint64_t m_order = 0;
  std::priority_queue<Front, std::vector<Front>, Later> m_queue;
};

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_TRACE_WALLS_H
