// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Two boundary quadrilaterals of the extracted hexahedra that share three corners are one face with a
// crack: where the map is flat, the extraction puts the fourth corners of the two cells on either side
// apart (HexMe n02c, where two feature curves of a face meet tangentially: two hexahedra folded onto
// each other around a corner, the boundary touching itself along the face's diagonal, 2 non-manifold
// boundary vertices and nothing else wrong). Merging the two fourth corners glues the quadrilaterals
// into one interior face; the untangling and smoothing that follow place the merged vertex.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_CLOSE_BOUNDARY_CRACKS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_CLOSE_BOUNDARY_CRACKS_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/boundary_groups.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// A cracked face: the fourth corners `a` and `b` of two boundary faces of two different hexahedra that
// share the three corners `shared`, and the faces' mean edge length.
struct Boundary_crack
{
  std::uint32_t a, b;
  double edge;
  std::array<std::uint32_t, 3> shared;
};

inline std::vector<Boundary_crack> crack_corners(const Hexahedral_mesh_3& hexes)
{
  const std::vector<Hexahedral_boundary_quadrilateral> boundary = boundary_quadrilaterals_of(hexes);
  std::map<std::array<std::uint32_t, 3>, std::vector<std::size_t> > by_triple;
  auto corners = [&](std::size_t q) {
    std::array<std::uint32_t, 4> c;
    for(std::size_t i = 0; i < 4; ++i) c[i] = std::uint32_t(boundary[q].vertices[i]);
    return c;
  };
  auto edge = [&](std::size_t q) {
    const std::array<std::uint32_t, 4> c = corners(q);
    double l = 0;
    for(int i = 0; i < 4; ++i) l += std::sqrt(CGAL::squared_distance(hexes.points[c[std::size_t(i)]], hexes.points[c[std::size_t((i + 1) % 4)]]));
    return l / 4;
  };
  for(std::size_t q = 0; q < boundary.size(); ++q) {
    const std::array<std::uint32_t, 4> c = corners(q);
    for(int skip = 0; skip < 4; ++skip) {
      std::array<std::uint32_t, 3> t;
      for(int i = 0, j = 0; i < 4; ++i)
        if(i != skip) t[std::size_t(j++)] = c[std::size_t(i)];
      std::sort(t.begin(), t.end());
      by_triple[t].push_back(q);
    }
  }
  std::vector<Boundary_crack> cracks;
  for(const auto& entry : by_triple) {
    if(entry.second.size() != 2) continue;
    const std::size_t q0 = entry.second[0], q1 = entry.second[1];
    const std::array<std::uint32_t, 4> c0 = corners(q0), c1 = corners(q1);
    std::uint32_t a = c0[0], b = c1[0];
    for(std::uint32_t v : c0)
      if(!std::binary_search(entry.first.begin(), entry.first.end(), v)) a = v;
    for(std::uint32_t v : c1)
      if(!std::binary_search(entry.first.begin(), entry.first.end(), v)) b = v;
    if(a != b && boundary[q0].hexahedron != boundary[q1].hexahedron)
      cracks.push_back({a, b, (edge(q0) + edge(q1)) / 2, entry.first});
  }
  return cracks;
}

// Removes the vertices `v` with `target[v] != v` (merged into another), compacting every per-vertex array.
inline void drop_merged_vertices(Hexahedral_mesh_3& hexes, const std::vector<std::uint32_t>& target)
{
  std::vector<std::uint32_t> index(hexes.points.size(), 0);
  std::uint32_t n = 0;
  for(std::uint32_t v = 0; v < index.size(); ++v) {
    index[v] = n;
    if(target[v] != v) continue;
    hexes.points[n] = hexes.points[v];
    if(v < hexes.vertex_locations.size()) hexes.vertex_locations[n] = hexes.vertex_locations[v];
    if(v < hexes.vertex_tags.size()) hexes.vertex_tags[n] = hexes.vertex_tags[v];
    ++n;
  }
  hexes.points.resize(n);
  if(!hexes.vertex_locations.empty()) hexes.vertex_locations.resize(n);
  if(!hexes.vertex_tags.empty()) hexes.vertex_tags.resize(n);
  for(auto& h : hexes.hexahedra)
    for(auto& v : h) v = index[v];
}

// Merges the fourth corners of every cracked face (crack_corners()): the vertex on a feature curve or
// a corner of the input is kept where it is, else the two meet halfway; merged vertices are removed
// (every per-vertex array compacted). Rounds until one closes nothing: a face whose two sides share only
// a diagonal shares three corners once a neighbouring crack has merged a third (MAMBO B41 refined 1-to-8:
// one round closed 9 and left 17 non-manifold boundary vertices). `depth` gives how far a point is inside
// the input solid (<= 0 on its boundary or outside): two corners apart are merged only where the glued
// face (the three shared corners and the merged one) has its centre inside the solid by 5% of the faces'
// edge. Otherwise they are the corners of two walls of a thin slot that a collapsed map put on one plane,
// not of one face split in two (in rounds, the crack at the bottom of such a slot zips the whole slot
// shut). The merged corner itself may be on the boundary or off it (B41 refined: most cracks have both
// fourth corners on one face of the part, the glued faces' centres 0.06 to 0.6 of an edge deep; a test of
// the merged corner's depth closed 13 of them, this one 15). `feature_curves_near(p, d)` lists the input's
// feature curves within d of p: two corners apart on two feature curves (within 5% of the edge) that
// share none are left apart too, since merging them would pinch the face between the curves: the
// 0.1-wide floor of the slot of slotted_block.step at hex edge 0.3 (the glued faces lie under the floor,
// inside the solid), the 1.03-wide floors of two grooves of B41 (1.3 hex edges, both edges of valence 3)
// that its map folds.
// Returns the number of cracks closed.
inline std::size_t close_boundary_cracks(
  Hexahedral_mesh_3& hexes, const std::function<double(const Hexahedral_mesh_3::Point_3&)>& depth = {},
  const std::function<std::vector<std::size_t>(const Hexahedral_mesh_3::Point_3&, double)>& feature_curves_near = {})
{
  typedef Hexahedral_mesh_3::Point_3 Point;
  std::vector<Boundary_crack> pairs = crack_corners(hexes);
  if(pairs.empty()) return 0;
  std::vector<std::uint32_t> target(hexes.points.size());
  for(std::uint32_t v = 0; v < target.size(); ++v) target[v] = v;
  auto find = [&](std::uint32_t v) {
    while(target[v] != v) v = target[v];
    return v;
  };
  auto rank = [&](std::uint32_t v) { return v < hexes.vertex_tags.size() ? int(hexes.vertex_tags[v]) : 0; };
  auto in_one_cell = [&](std::uint32_t a, std::uint32_t b) {
    for(const auto& h : hexes.hexahedra)
      if(std::count(h.begin(), h.end(), a) > 0 && std::count(h.begin(), h.end(), b) > 0) return true;
    return false;
  };
  auto glued_face_centre = [&](const Boundary_crack& p, const Point& merged) {
    double x = merged.x(), y = merged.y(), z = merged.z();
    for(std::uint32_t v : p.shared) {
      const Point& q = hexes.points[find(v)];
      x += q.x(); y += q.y(); z += q.z();
    }
    return Point(x / 4, y / 4, z / 4);
  };
  // two corners on feature curves, none of them shared: a face between the curves would collapse
  auto on_two_curves = [&](const Point& a, const Point& b, double tolerance) {
    if(!feature_curves_near) return false;
    const std::vector<std::size_t> ca = feature_curves_near(a, tolerance), cb = feature_curves_near(b, tolerance);
    if(ca.empty() || cb.empty()) return false;
    for(std::size_t c : ca)
      if(std::find(cb.begin(), cb.end(), c) != cb.end()) return false;
    return true;
  };
  std::size_t closed = 0;
  for(std::size_t round_closed = 1; round_closed > 0 && !pairs.empty(); pairs = crack_corners(hexes)) {
    round_closed = 0;
    for(const auto& p : pairs) {
      std::uint32_t a = find(p.a), b = find(p.b);
      if(a == b || in_one_cell(a, b)) continue; // the merge would collapse a cell
      if(rank(b) > rank(a)) std::swap(a, b); // a stays
      const Point merged = rank(a) == rank(b) ? CGAL::midpoint(hexes.points[a], hexes.points[b]) : hexes.points[a];
      const double tolerance = 0.05 * p.edge;
      if(CGAL::squared_distance(hexes.points[a], hexes.points[b]) > tolerance * tolerance &&
         ((depth && !(depth(glued_face_centre(p, merged)) > tolerance)) ||
          on_two_curves(hexes.points[a], hexes.points[b], tolerance)))
        continue; // two walls, or a thin face
      hexes.points[a] = merged;
      target[b] = a;
      for(auto& h : hexes.hexahedra) std::replace(h.begin(), h.end(), b, a);
      ++round_closed;
    }
    closed += round_closed;
  }
  drop_merged_vertices(hexes, target);
  return closed;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_CLOSE_BOUNDARY_CRACKS_H
