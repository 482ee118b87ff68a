// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_EXACT_MAP_MESH_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_EXACT_MAP_MESH_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/exact_chart.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// One tetrahedron of the map: its vertices, the exact parameters of its corners in its own chart,
// and per face (face i is opposite corner i) the adjacent tetrahedron (-1 on the boundary) and what
// the face is in the complex: NOT_A_WALL, BOUNDARY or the number of the wall it belongs to.
struct Map_tetrahedron
{
  std::array<std::uint32_t, 4> vertex;
  std::array<Parameter, 4> parameter;
  std::array<std::int64_t, 4> neighbor{{-1, -1, -1, -1}};
  std::array<int, 4> wall{{-1, -1, -1, -1}};
  std::uint32_t origin = 0; // the tetrahedron of the input it is part of (its chart is that one's)
};

constexpr int NOT_A_WALL = -1;
constexpr int BOUNDARY = -2;

// The tetrahedral mesh of a seamless map with exact charts, refined by edge bisections: splitting an
// edge splits every tetrahedron around it at the same parameter ratio (transitions are affine, so the
// ratio is the same in every chart), which keeps the mesh conforming and the map unchanged up to the
// rounding of the split points to 2^-40 (off the wall's plane; checked: every part stays positive).
class Exact_map_mesh
{
public:
  std::vector<Map_tetrahedron> tetrahedra;
  std::vector<std::array<double, 3> > points; // positions in the model, for output

  // `parameters[t][c]`: the map at corner c of tetrahedron t. Throws std::invalid_argument if a face
  // is shared by more than two tetrahedra.
  Exact_map_mesh(const std::vector<std::array<double, 3> >& positions, const std::vector<std::array<std::uint32_t, 4> >& tets,
                 const std::vector<std::array<Eigen::Vector3d, 4> >& parameters)
    : points(positions)
  {
    std::map<std::array<std::uint32_t, 3>, std::pair<std::int64_t, int> > open;
    tetrahedra.resize(tets.size());
    for(std::size_t t = 0; t < tets.size(); ++t) {
      Map_tetrahedron& T = tetrahedra[t];
      T.vertex = tets[t];
      T.origin = std::uint32_t(t);
      for(std::size_t c = 0; c < 4; ++c) T.parameter[c] = exact_parameter(parameters[t][c][0], parameters[t][c][1], parameters[t][c][2]);
      for(int f = 0; f < 4; ++f) {
        const std::array<std::uint32_t, 3> key = face_key(T, f);
        const auto it = open.find(key);
        if(it == open.end()) { open.emplace(key, std::make_pair(std::int64_t(t), f)); continue; }
        if(it->second.first < 0) throw std::invalid_argument("a face of the map is shared by more than two tetrahedra");
        T.neighbor[std::size_t(f)] = it->second.first;
        tetrahedra[std::size_t(it->second.first)].neighbor[std::size_t(it->second.second)] = std::int64_t(t);
        it->second.first = -1;
      }
    }
    for(Map_tetrahedron& T : tetrahedra)
      for(std::size_t f = 0; f < 4; ++f)
        if(T.neighbor[f] < 0) T.wall[f] = BOUNDARY;
  }

  static std::array<std::uint32_t, 3> face_key(const Map_tetrahedron& T, int f)
  {
    std::array<std::uint32_t, 3> k;
    for(int i = 0, j = 0; i < 4; ++i)
      if(i != f) k[std::size_t(j++)] = T.vertex[std::size_t(i)];
    std::sort(k.begin(), k.end());
    return k;
  }

  int corner(std::size_t t, std::uint32_t v) const
  {
    for(int c = 0; c < 4; ++c)
      if(tetrahedra[t].vertex[std::size_t(c)] == v) return c;
    return -1;
  }

  // The face of `n` shared with `t` (-1 if they are not adjacent).
  int face_towards(std::size_t n, std::size_t t) const
  {
    for(int f = 0; f < 4; ++f)
      if(tetrahedra[n].neighbor[std::size_t(f)] == std::int64_t(t)) return f;
    return -1;
  }

  // The chart change from tetrahedron t to its neighbor across face f; false if the map is not
  // seamless across it.
  // The parts of one input tetrahedron share its chart, so the change only depends on the two input
  // tetrahedra: computed once per pair. Null if the map is not seamless across the face.
  const Chart_transition* transition(std::size_t t, int f) const
  {
    static const Chart_transition identity;
    const Map_tetrahedron& T = tetrahedra[t];
    const std::size_t n = std::size_t(T.neighbor[std::size_t(f)]);
    if(tetrahedra[n].origin == T.origin) return &identity;
    // most faces are not on the cut: the same parameters on both sides (checked in place: copying
    // the parameters out costs more than the check)
    bool same = true;
    for(int i = 0; i < 4 && same; ++i)
      same = i == f || T.parameter[std::size_t(i)] == tetrahedra[n].parameter[std::size_t(corner(n, T.vertex[std::size_t(i)]))];
    if(same) return &identity;
    const std::uint64_t key = (std::uint64_t(T.origin) << 32) | tetrahedra[n].origin;
    auto it = m_transitions.find(key);
    if(it == m_transitions.end()) {
      std::array<Parameter, 3> from, to;
      for(int i = 0, j = 0; i < 4; ++i) {
        if(i == f) continue;
        from[std::size_t(j)] = T.parameter[std::size_t(i)];
        to[std::size_t(j++)] = tetrahedra[n].parameter[std::size_t(corner(n, T.vertex[std::size_t(i)]))];
      }
      Chart_transition c;
      const bool ok = transition_between(from, to, c);
      it = m_transitions.emplace(key, std::make_pair(c, ok)).first;
    }
    return it->second.second ? &it->second.first : nullptr;
  }

  // The singular edges, kept up to date by the splits (set by the caller).
  std::set<std::pair<std::uint32_t, std::uint32_t> > singular_edges;

  // Walks around the edge (x, y) of tetrahedron t, first across the face of t opposite its vertex z
  // (not x nor y). Calls step(from, face, to) at every crossing, face being the face of `from`
  // crossed and `to` the tetrahedron reached (-1 at the boundary, where the walk stops). Stops when
  // step returns false; returns true if the walk came back to t (a closed ring).
  template <class Step>
  bool walk_around(std::size_t t, std::uint32_t x, std::uint32_t y, std::uint32_t z, Step step) const
  {
    std::size_t cur = t;
    for(;;) {
      const Map_tetrahedron& C = tetrahedra[cur];
      const int f = corner(cur, z);
      const std::int64_t n = C.neighbor[std::size_t(f)];
      if(!step(cur, f, n) || n < 0) return false;
      if(std::size_t(n) == t) return true;
      // the next face of n around the edge is the one opposite the vertex of the crossed face other
      // than x and y
      for(std::uint32_t v : C.vertex)
        if(v != x && v != y && v != z) { z = v; break; }
      cur = std::size_t(n);
    }
  }

  // The two vertices of tetrahedron t other than x and y.
  std::array<std::uint32_t, 2> other_vertices(std::size_t t, std::uint32_t x, std::uint32_t y) const
  {
    std::array<std::uint32_t, 2> o{{0, 0}};
    for(int i = 0, j = 0; i < 4; ++i) {
      const std::uint32_t v = tetrahedra[t].vertex[std::size_t(i)];
      if(v != x && v != y && j < 2) o[std::size_t(j++)] = v;
    }
    return o;
  }

  // Splits the edge (x, y) of tetrahedron t at x + lambda (y - x), 0 < lambda < 1, in every
  // tetrahedron around it. Each keeps its number for its half at x; its half at y gets a new number.
  // Returns the new vertex.
  std::uint32_t split_edge(std::size_t t, std::uint32_t x, std::uint32_t y, const Rational& lambda)
  {
    const std::vector<std::size_t> ring = tetrahedra_around(t, x, y);
    const std::uint32_t w = std::uint32_t(points.size());
    const double l = CGAL::to_double(lambda);
    std::array<double, 3> pw;
    for(std::size_t i = 0; i < 3; ++i) pw[i] = (1 - l) * points[x][i] + l * points[y][i];
    points.push_back(pw);
    std::map<std::size_t, std::size_t> half_at_y;
    for(std::size_t r : ring) half_at_y[r] = tetrahedra.size() + half_at_y.size();
    tetrahedra.resize(tetrahedra.size() + ring.size());
    for(std::size_t r : ring) bisect(r, half_at_y[r], x, y, w, lambda, half_at_y);
    if(singular_edges.erase(std::make_pair(std::min(x, y), std::max(x, y)))) {
      singular_edges.emplace(std::min(x, w), std::max(x, w));
      singular_edges.emplace(std::min(y, w), std::max(y, w));
    }
    return w;
  }

  // Every tetrahedron having the edge (x, y), starting with t (both ways around at the boundary).
  std::vector<std::size_t> tetrahedra_around(std::size_t t, std::uint32_t x, std::uint32_t y) const
  {
    std::vector<std::size_t> ring{t};
    auto collect = [&](std::size_t, int, std::int64_t n) {
      if(n >= 0 && std::size_t(n) != t) ring.push_back(std::size_t(n));
      return true;
    };
    const std::array<std::uint32_t, 2> z = other_vertices(t, x, y);
    if(!walk_around(t, x, y, z[0], collect)) walk_around(t, x, y, z[1], collect);
    return ring;
  }

private:
  mutable std::unordered_map<std::uint64_t, std::pair<Chart_transition, bool> > m_transitions;

  void bisect(std::size_t t, std::size_t t2, std::uint32_t x, std::uint32_t y, std::uint32_t w, const Rational& lambda,
              const std::map<std::size_t, std::size_t>& half_at_y)
  {
    Map_tetrahedron& A = tetrahedra[t];
    const int cx = corner(t, x), cy = corner(t, y);
    // The split point, rounded to the grid of 2^-40 (walls crossing the splits of other walls would
    // else nest rationals whose size doubles at each level). The wall's own coordinate, a double,
    // stays exact; every chart rounds its copy alike, so the transitions still hold exactly.
    Parameter pw;
    for(std::size_t i = 0; i < 3; ++i)
      pw[i] = rounded_to_grid(A.parameter[std::size_t(cx)][i] + lambda * (A.parameter[std::size_t(cy)][i] - A.parameter[std::size_t(cx)][i]));
    Map_tetrahedron B = A;
    // the half at y: x replaced by w; across its face opposite w, the old neighbor opposite x
    B.vertex[std::size_t(cx)] = w;
    B.parameter[std::size_t(cx)] = pw;
    B.neighbor[std::size_t(cy)] = std::int64_t(t);
    B.wall[std::size_t(cy)] = NOT_A_WALL;
    for(int f = 0; f < 4; ++f) {
      if(f == cx || f == cy || B.neighbor[std::size_t(f)] < 0) continue;
      const auto it = half_at_y.find(std::size_t(B.neighbor[std::size_t(f)]));
      if(it != half_at_y.end()) B.neighbor[std::size_t(f)] = std::int64_t(it->second);
    }
    const std::int64_t m = A.neighbor[std::size_t(cx)];
    if(m >= 0) {
      const int back = face_towards(std::size_t(m), t);
      tetrahedra[std::size_t(m)].neighbor[std::size_t(back)] = std::int64_t(t2);
    }
    // the half at x: y replaced by w
    A.vertex[std::size_t(cy)] = w;
    A.parameter[std::size_t(cy)] = pw;
    A.neighbor[std::size_t(cx)] = std::int64_t(t2);
    A.wall[std::size_t(cx)] = NOT_A_WALL;
    tetrahedra[t2] = B;
  }
};

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_EXACT_MAP_MESH_H
