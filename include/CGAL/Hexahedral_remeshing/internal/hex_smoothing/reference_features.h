// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_REFERENCE_FEATURES_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_REFERENCE_FEATURES_H

#include <CGAL/Hexahedral_remeshing/internal/union_find.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Sharp edges of a triangle surface and the patches they bound.
//
// An edge is sharp when its two triangles' normals differ by more than `angle` (radians; the normals
// compared as if the triangles were consistently oriented across the edge, so the input orientation
// does not matter), when it has one triangle (border) or more than two, or when it lies on one of
// `ref.feature_polylines` (consecutive polyline points that are the edge's end points). If
// `add_features`, the sharp edges are chained into `ref.feature_polylines` (split at vertices of
// sharp degree other than 2 and where a curve turns by more than `angle`) and these split points are
// appended to `ref.corners`. Returns the patch of every triangle (components across non-sharp edges),
// numbered in order of first triangle.
template <class Reference>
std::vector<int> reference_patches(Reference& ref, double angle, bool add_features)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Vector_3 Vector_3;
  typedef std::pair<std::uint32_t, std::uint32_t> Edge;
  const std::size_t T = ref.triangles.size();
  const double cos_angle = std::cos(angle);
  std::map<Edge, std::vector<std::pair<std::uint32_t, bool> > > edges; // (triangle, runs a -> b with a < b)
  for(std::size_t t = 0; t < T; ++t)
    for(int i = 0; i < 3; ++i) {
      const std::uint32_t a = ref.triangles[t][i], b = ref.triangles[t][(i + 1) % 3];
      if(a == b) continue;
      edges[Edge((std::min)(a, b), (std::max)(a, b))].emplace_back(std::uint32_t(t), a < b);
    }
  std::vector<Vector_3> normal(T, Vector_3(0, 0, 0));
  for(std::size_t t = 0; t < T; ++t) {
    const auto& p = ref.points;
    const Vector_3 n = CGAL::cross_product(p[ref.triangles[t][1]] - p[ref.triangles[t][0]], p[ref.triangles[t][2]] - p[ref.triangles[t][0]]);
    const double l = std::sqrt(n.squared_length());
    if(l > 0) normal[t] = n / l;
  }
  std::set<std::pair<typename Reference::Point_3, typename Reference::Point_3> > given;
  for(const auto& pl : ref.feature_polylines)
    for(std::size_t i = 0; i + 1 < pl.size(); ++i) {
      given.insert(std::make_pair(pl[i], pl[i + 1]));
      given.insert(std::make_pair(pl[i + 1], pl[i]));
    }
  Union_find patches(T);
  std::vector<Edge> sharp;
  for(const auto& e : edges) {
    bool is_sharp = e.second.size() != 2;
    if(!is_sharp) {
      const auto& t0 = e.second[0];
      const auto& t1 = e.second[1];
      // consistently oriented triangles run along the edge in opposite directions
      const double c = (t0.second != t1.second ? 1. : -1.) * (normal[t0.first] * normal[t1.first]);
      is_sharp = c < cos_angle;
    }
    if(!is_sharp && !given.empty())
      is_sharp = given.count(std::make_pair(ref.points[e.first.first], ref.points[e.first.second])) > 0;
    if(is_sharp) sharp.push_back(e.first);
    else patches.unite(e.second[0].first, e.second[1].first);
  }
  std::vector<int> patch(T, -1);
  std::map<std::size_t, int> ids;
  for(std::size_t t = 0; t < T; ++t) {
    const auto it = ids.emplace(patches.find(std::uint32_t(t)), int(ids.size())).first;
    patch[t] = it->second;
  }
  if(!add_features || sharp.empty()) return patch;

  // chain the sharp edges (deterministic: edges sorted, walks from the lowest vertex)
  std::map<std::uint32_t, std::vector<std::size_t> > incident;
  for(std::size_t i = 0; i < sharp.size(); ++i) {
    incident[sharp[i].first].push_back(i);
    incident[sharp[i].second].push_back(i);
  }
  auto other = [&](std::size_t e, std::uint32_t v) { return sharp[e].first == v ? sharp[e].second : sharp[e].first; };
  std::set<std::uint32_t> junction;
  for(const auto& kv : incident) {
    if(kv.second.size() != 2) { junction.insert(kv.first); continue; }
    const auto& p = ref.points;
    const Vector_3 d0 = p[other(kv.second[0], kv.first)] - p[kv.first];
    const Vector_3 d1 = p[kv.first] - p[other(kv.second[1], kv.first)];
    const double l = std::sqrt(d0.squared_length() * d1.squared_length());
    if(l > 0 && (d0 * d1) / l < cos_angle) junction.insert(kv.first);
  }
  std::vector<bool> used(sharp.size(), false);
  auto walk = [&](std::uint32_t start, std::size_t first) {
    std::vector<typename Reference::Point_3> pl{ ref.points[start] };
    std::uint32_t v = start;
    std::size_t e = first;
    for(;;) {
      used[e] = true;
      v = other(e, v);
      pl.push_back(ref.points[v]);
      if(v == start || junction.count(v) > 0) break;
      std::size_t next = e;
      for(std::size_t f : incident[v])
        if(!used[f]) { next = f; break; }
      if(next == e) break;
      e = next;
    }
    ref.feature_polylines.push_back(pl);
  };
  for(std::uint32_t v : junction)
    for(std::size_t e : incident[v])
      if(!used[e]) walk(v, e);
  for(std::size_t e = 0; e < sharp.size(); ++e) // closed curves without a junction
    if(!used[e]) walk(sharp[e].first, e);
  for(std::uint32_t v : junction) ref.corners.push_back(ref.points[v]);
  return patch;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_REFERENCE_FEATURES_H
