// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_FEATURE_FIDELITY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_FEATURE_FIDELITY_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// How faithful a hex mesh is to the sharp edges of its input: the sharp edges are the boundary edges
// with a prescribed valence other than 2 (flat; a CAD curve between tangent faces, a seam, is not
// sharp).
struct Feature_fidelity
{
  double feature_length = 0;  // total length of the sharp edges of the tet mesh
  double covered_length = 0;  // length of the sharp edges that boundary hex edges follow
  std::size_t hex_feature_edges = 0;   // boundary hex edges lying along a sharp edge
  std::size_t valence_matched = 0;     // ... whose number of hexahedra is the prescribed valence
};

// A boundary hex edge lies along the sharp edges if its endpoints are within `tolerance` (model
// units) or 5% of its length of them, and its midpoint within 10% of its length: hex edges follow a
// curved sharp edge as chords (a chord of 1/16 of a circle is 5% of its length off the arc at its
// midpoint), while an edge cutting a corner is 35% off. Its valence is compared with the prescribed
// valence of the sharp edge nearest to its midpoint. A sharp edge (of the tet mesh) is covered
// where its midpoint is within 10% of the length of the nearest hex edge lying along, or `tolerance`.
template <class Traits>
Feature_fidelity measure_feature_fidelity(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<int>& valences,
                                          const Hexahedral_mesh_3& hexes, double tolerance)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef std::vector<K::Segment_3>::const_iterator Iterator;
  typedef CGAL::AABB_segment_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
  auto point = [](const auto& p) { return K::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())); };

  Feature_fidelity f;
  std::vector<K::Segment_3> segments;
  std::vector<int> segment_valence;
  for(auto e : mesh.boundary_edges()) {
    const int k = e < valences.size() ? valences[e] : 2;
    if(k == 2) continue;
    const auto& ev = mesh.edge_vertices(e);
    segments.emplace_back(point(mesh.point(ev[0])), point(mesh.point(ev[1])));
    segment_valence.push_back(k);
    f.feature_length += std::sqrt(segments.back().squared_length());
  }
  if(segments.empty()) return f;
  Tree tree(segments.cbegin(), segments.cend());
  tree.accelerate_distance_queries();

  // Hex edges with their number of hexahedra, and the boundary ones (on a quad used once).
  static const int edge_corners[12][2] = { {0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                           {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7} };
  static const int quad_corners[6][4] = { {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                          {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7} };
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t((std::min)(a, b)) << 32) | std::uint64_t((std::max)(a, b));
  };
  std::unordered_map<std::uint64_t, int> edge_hexes;
  std::vector<std::array<std::uint32_t, 4> > quads;
  for(const auto& h : hexes.hexahedra) {
    for(const auto& c : edge_corners) ++edge_hexes[key(h[c[0]], h[c[1]])];
    for(const auto& q : quad_corners) quads.push_back({h[q[0]], h[q[1]], h[q[2]], h[q[3]]});
  }
  std::vector<std::array<std::uint32_t, 4> > sorted(quads);
  for(auto& q : sorted) std::sort(q.begin(), q.end());
  std::vector<std::size_t> order(quads.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sorted[a] < sorted[b]; });
  std::unordered_map<std::uint64_t, char> boundary_edges;
  for(std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while(j < order.size() && sorted[order[j]] == sorted[order[i]]) ++j;
    if(j - i == 1) {
      const auto& q = quads[order[i]];
      for(int c = 0; c < 4; ++c) boundary_edges[key(q[c], q[(c + 1) % 4])] = 1;
    }
    i = j;
  }

  std::vector<K::Segment_3> along;
  for(const auto& be : boundary_edges) {
    const std::uint32_t a = std::uint32_t(be.first >> 32), b = std::uint32_t(be.first & 0xffffffffu);
    const K::Point_3 pa = point(hexes.points[a]), pb = point(hexes.points[b]);
    const K::Point_3 mid = CGAL::midpoint(pa, pb);
    const double length = std::sqrt(CGAL::squared_distance(pa, pb));
    const double tv = (std::max)(tolerance, 0.05 * length), tm = (std::max)(tolerance, 0.1 * length);
    if(tree.squared_distance(pa) > tv * tv || tree.squared_distance(pb) > tv * tv) continue;
    const auto closest = tree.closest_point_and_primitive(mid);
    if(CGAL::squared_distance(mid, closest.first) > tm * tm) continue;
    ++f.hex_feature_edges;
    along.emplace_back(pa, pb);
    const int prescribed = segment_valence[std::size_t(closest.second - segments.cbegin())];
    if(edge_hexes[be.first] == prescribed) ++f.valence_matched;
  }
  if(along.empty()) return f;
  Tree along_tree(along.cbegin(), along.cend());
  along_tree.accelerate_distance_queries();
  for(const K::Segment_3& s : segments) {
    const K::Point_3 mid = CGAL::midpoint(s.source(), s.target());
    const auto closest = along_tree.closest_point_and_primitive(mid);
    const double t = (std::max)(tolerance, 0.1 * std::sqrt(closest.second->squared_length()));
    if(CGAL::squared_distance(mid, closest.first) <= t * t) f.covered_length += std::sqrt(s.squared_length());
  }
  return f;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_REMESHING_FEATURE_FIDELITY_H
