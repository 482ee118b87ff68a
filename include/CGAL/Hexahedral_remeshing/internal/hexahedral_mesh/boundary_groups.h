// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_BOUNDARY_GROUPS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_BOUNDARY_GROUPS_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The surface the boundary groups are read from: triangles with their patch, and the feature curves
// as segments with their curve id (may be empty).
struct Patch_surface
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<K::Triangle_3> triangles;
  std::vector<int> triangle_patch;
  std::vector<K::Segment_3> segments;
  std::vector<int> segment_curve;
};

// The quads used by exactly one hexahedron, as (hexahedron, local face), in hexahedron order.
inline std::vector<Hexahedral_boundary_quadrilateral> boundary_quadrilaterals_of(const Hexahedral_mesh_3& hexes)
{
  std::map<std::array<std::uint32_t, 4>, std::pair<int, std::pair<std::uint32_t, std::uint8_t> > > faces;
  for(std::size_t h = 0; h < hexes.hexahedra.size(); ++h)
    for(int f = 0; f < 6; ++f) {
      std::array<std::uint32_t, 4> key;
      for(int i = 0; i < 4; ++i) key[i] = hexes.hexahedra[h][hex_faces()[f][i]];
      std::sort(key.begin(), key.end());
      auto& slot = faces.emplace(key, std::make_pair(0, std::make_pair(std::uint32_t(h), std::uint8_t(f)))).first->second;
      ++slot.first;
    }
  std::vector<Hexahedral_boundary_quadrilateral> quads;
  for(const auto& kv : faces) {
    if(kv.second.first != 1) continue;
    Hexahedral_boundary_quadrilateral q;
    q.hexahedron = kv.second.second.first;
    q.face = kv.second.second.second;
    for(int i = 0; i < 4; ++i) q.vertices[i] = hexes.hexahedra[q.hexahedron][hex_faces()[q.face][i]];
    quads.push_back(q);
  }
  std::sort(quads.begin(), quads.end(), [](const auto& a, const auto& b) {
    return std::make_pair(a.hexahedron, a.face) < std::make_pair(b.hexahedron, b.face);
  });
  return quads;
}

// The patch of each quad: a vote of the patches of the surface triangles closest to five points of
// the quad (its centre and the midpoints between the centre and its corners), the centre's patch
// breaking ties. Sampling inside the quad keeps the vote away from the sharp edges, where the
// closest triangle may belong to either patch.
inline void vote_quad_patches(const Hexahedral_mesh_3& hexes, const Patch_surface& surface,
                              std::vector<Hexahedral_boundary_quadrilateral>& quads)
{
  typedef Patch_surface::K K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator> > > Tree;
  if(surface.triangles.empty()) return;
  Tree tree(surface.triangles.cbegin(), surface.triangles.cend());
  tree.accelerate_distance_queries();
  auto patch_at = [&](const K::Point_3& p) {
    return surface.triangle_patch[std::size_t(tree.closest_point_and_primitive(p).second - surface.triangles.cbegin())];
  };
  for(auto& q : quads) {
    double c[3] = {0, 0, 0};
    for(auto v : q.vertices)
      for(int d = 0; d < 3; ++d) c[d] += hexes.points[v][d] / 4;
    const K::Point_3 centre(c[0], c[1], c[2]);
    std::map<int, int> votes;
    const int central = patch_at(centre);
    votes[central] += 1;
    for(auto v : q.vertices) ++votes[patch_at(CGAL::midpoint(centre, hexes.points[v]))];
    int best = central;
    for(const auto& kv : votes)
      if(kv.second > votes[best]) best = kv.first;
    q.patch = best;
  }
}

// Hex edges between quads of two different patches, with the curve of the nearest feature segment
// (when the surface has some within a quarter of the edge's length), else a number per pair of
// patches (first seen, from 0; after the largest segment curve id).
inline std::vector<Hexahedral_feature_edge> feature_edges_between_patches(
  const Hexahedral_mesh_3& hexes, const Patch_surface& surface, const std::vector<Hexahedral_boundary_quadrilateral>& quads)
{
  typedef Patch_surface::K K;
  typedef std::vector<K::Segment_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_segment_primitive<K, Iterator> > > Tree;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<int> > edge_patches;
  for(const auto& q : quads)
    for(int i = 0; i < 4; ++i) {
      const std::uint32_t a = q.vertices[i], b = q.vertices[(i + 1) % 4];
      edge_patches[std::make_pair((std::min)(a, b), (std::max)(a, b))].push_back(q.patch);
    }
  Tree tree(surface.segments.cbegin(), surface.segments.cend());
  if(!surface.segments.empty()) tree.accelerate_distance_queries();
  int next_pair_id = 0;
  for(int c : surface.segment_curve) next_pair_id = (std::max)(next_pair_id, c + 1);
  std::map<std::pair<int, int>, int> pair_id;
  std::vector<Hexahedral_feature_edge> edges;
  for(const auto& kv : edge_patches) {
    const auto mm = std::minmax_element(kv.second.begin(), kv.second.end());
    if(*mm.first == *mm.second) continue;
    Hexahedral_feature_edge e;
    e.vertices = { {kv.first.first, kv.first.second} };
    const K::Point_3& a = hexes.points[e.vertices[0]];
    const K::Point_3& b = hexes.points[e.vertices[1]];
    if(!surface.segments.empty()) {
      const auto cp = tree.closest_point_and_primitive(CGAL::midpoint(a, b));
      if(CGAL::squared_distance(cp.first, CGAL::midpoint(a, b)) <= CGAL::squared_distance(a, b) / 16)
        e.curve = surface.segment_curve[std::size_t(cp.second - surface.segments.cbegin())];
    }
    if(e.curve < 0) {
      const auto key = std::make_pair(*mm.first, *mm.second);
      auto it = pair_id.find(key);
      if(it == pair_id.end()) it = pair_id.emplace(key, next_pair_id++).first;
      e.curve = it->second;
    }
    edges.push_back(e);
  }
  return edges;
}

// Fills the boundary quadrilaterals (sorted by patch, hexahedron, face) and the feature edges of
// `hexes` from `surface`.
inline void assign_boundary_groups(Hexahedral_mesh_3& hexes, const Patch_surface& surface)
{
  std::vector<Hexahedral_boundary_quadrilateral> quads = boundary_quadrilaterals_of(hexes);
  vote_quad_patches(hexes, surface, quads);
  hexes.feature_edges = feature_edges_between_patches(hexes, surface, quads);
  std::stable_sort(quads.begin(), quads.end(), [](const auto& a, const auto& b) { return a.patch < b.patch; });
  hexes.boundary_quadrilaterals = std::move(quads);
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_BOUNDARY_GROUPS_H
