// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_REFERENCE_PROJECTOR_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_REFERENCE_PROJECTOR_H

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Closest points on the reference boundary of the hex smoothing: the triangle surface (CGAL AABB
// tree), one feature polyline at a time (linear scan of its segments), the corners.
// `Reference` has `points`, `triangles` (3 indices into points), `feature_polylines` (vectors of
// points, a closed curve repeats its first point) and `corners` (points).
class Reference_projector
{
public:
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef K::Point_3 Point_3;
  typedef K::Vector_3 Vector_3;
  typedef K::Triangle_3 Triangle_3;
  typedef std::vector<Triangle_3>::const_iterator Triangle_iterator;
  typedef CGAL::AABB_triangle_primitive<K, Triangle_iterator> Primitive;
  typedef CGAL::AABB_traits<K, Primitive> Traits;
  typedef CGAL::AABB_tree<Traits> Tree;

  // `patch` (empty, or one id >= 0 per triangle of `ref`): the surface patches a vertex can be
  // kept on (closest point on its own patch, so that it cannot jump across a sharp edge).
  template <class Reference>
  explicit Reference_projector(const Reference& ref, const std::vector<int>& patch = std::vector<int>())
  {
    std::vector<int> kept_patch;
    for(std::size_t i = 0; i < ref.triangles.size(); ++i) {
      const auto& t = ref.triangles[i];
      const Triangle_3 tri(ref.points[t[0]], ref.points[t[1]], ref.points[t[2]]);
      if(tri.is_degenerate()) continue;
      m_triangles.push_back(tri);
      kept_patch.push_back(i < patch.size() ? patch[i] : 0);
    }
    if(!m_triangles.empty()) {
      m_tree.reset(new Tree(m_triangles.begin(), m_triangles.end()));
      m_tree->accelerate_distance_queries();
    }
    if(!patch.empty()) {
      int P = 0;
      for(int q : kept_patch) P = (std::max)(P, q + 1);
      m_patch_triangles.resize(std::size_t(P));
      for(std::size_t i = 0; i < m_triangles.size(); ++i) m_patch_triangles[std::size_t(kept_patch[i])].push_back(m_triangles[i]);
      m_triangle_patch = kept_patch;
      for(const auto& tris : m_patch_triangles) {
        m_patch_trees.emplace_back(tris.empty() ? nullptr : new Tree(tris.begin(), tris.end()));
        if(!tris.empty()) m_patch_trees.back()->accelerate_distance_queries();
      }
    }
    for(const auto& pl : ref.feature_polylines) {
      std::vector<std::pair<Point_3, Point_3> > segments;
      for(std::size_t i = 0; i + 1 < pl.size(); ++i)
        if(pl[i] != pl[i + 1]) segments.emplace_back(pl[i], pl[i + 1]);
      if(segments.empty() && !pl.empty()) segments.emplace_back(pl.front(), pl.front());
      m_polylines.push_back(segments);
    }
    m_corners.assign(ref.corners.begin(), ref.corners.end());
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    bool first = true;
    auto extend = [&](const Point_3& p) {
      for(int d = 0; d < 3; ++d) {
        if(first || p[d] < lo[d]) lo[d] = p[d];
        if(first || p[d] > hi[d]) hi[d] = p[d];
      }
      first = false;
    };
    for(const Point_3& p : ref.points) extend(p);
    for(const auto& pl : ref.feature_polylines) for(const Point_3& p : pl) extend(p);
    for(const Point_3& p : ref.corners) extend(p);
    m_diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                           (hi[2] - lo[2]) * (hi[2] - lo[2]));
  }

  bool has_surface() const { return m_tree != nullptr; }
  std::size_t number_of_polylines() const { return m_polylines.size(); }
  bool has_polyline(std::size_t c) const { return c < m_polylines.size() && !m_polylines[c].empty(); }
  const std::vector<Point_3>& corners() const { return m_corners; }
  // diagonal of the bounding box of the reference
  double diagonal() const { return m_diagonal; }

  // Closest point of the surface; `normal` (if given) receives the unit normal of its triangle.
  // \pre has_surface()
  // `patch` >= 0: the closest point of that patch only.
  Point_3 closest_on_surface(const Point_3& p, Vector_3* normal = nullptr, int patch = -1) const
  {
    const auto cp = tree(patch).closest_point_and_primitive(p);
    if(normal != nullptr) {
      Vector_3 n = cp.second->supporting_plane().orthogonal_vector();
      *normal = n / std::sqrt(n.squared_length());
    }
    return cp.first;
  }

  double distance_to_surface(const Point_3& p, int patch = -1) const
  {
    return std::sqrt(tree(patch).squared_distance(p));
  }

  // The patch of the triangle closest to p (0 without patches).
  int patch_of(const Point_3& p) const
  {
    if(m_triangle_patch.empty()) return 0;
    const auto cp = m_tree->closest_point_and_primitive(p);
    return m_triangle_patch[std::size_t(cp.second - m_triangles.begin())];
  }

  std::size_t number_of_patches() const { return m_patch_trees.size(); }

  // Closest point of polyline `c` and the unit tangent of its segment there. \pre has_polyline(c)
  Point_3 closest_on_polyline(std::size_t c, const Point_3& p, Vector_3* tangent = nullptr,
                              double* distance = nullptr) const
  {
    double best = (std::numeric_limits<double>::max)();
    Point_3 q = p;
    Vector_3 t(0, 0, 0);
    for(const auto& s : m_polylines[c]) {
      const Vector_3 d = s.second - s.first;
      const double l2 = d.squared_length();
      double u = l2 > 0 ? ((p - s.first) * d) / l2 : 0.;
      u = (std::min)(1., (std::max)(0., u));
      // the end points exactly, so that a vertex projected onto a polyline end stays there
      const Point_3 r = u == 0. ? s.first : (u == 1. ? s.second : s.first + u * d);
      const double dist = CGAL::squared_distance(p, r);
      if(dist < best) {
        best = dist;
        q = r;
        t = l2 > 0 ? d / std::sqrt(l2) : Vector_3(0, 0, 0);
      }
    }
    if(tangent != nullptr) *tangent = t;
    if(distance != nullptr) *distance = std::sqrt(best);
    return q;
  }

  // The polyline closest to p (and its distance), or number_of_polylines() if there is none.
  std::size_t nearest_polyline(const Point_3& p, double* distance = nullptr) const
  {
    std::size_t best = m_polylines.size();
    double bd = (std::numeric_limits<double>::max)();
    for(std::size_t c = 0; c < m_polylines.size(); ++c) {
      if(m_polylines[c].empty()) continue;
      double d;
      closest_on_polyline(c, p, nullptr, &d);
      if(d < bd) { bd = d; best = c; }
    }
    if(distance != nullptr) *distance = bd;
    return best;
  }

  // Index of the nearest corner (and its distance), or corners().size() if there is none.
  std::size_t nearest_corner(const Point_3& p, double* distance = nullptr) const
  {
    std::size_t best = m_corners.size();
    double bd = (std::numeric_limits<double>::max)();
    for(std::size_t c = 0; c < m_corners.size(); ++c) {
      const double d = std::sqrt(CGAL::squared_distance(p, m_corners[c]));
      if(d < bd) { bd = d; best = c; }
    }
    if(distance != nullptr) *distance = bd;
    return best;
  }

  // Distance to the nearest corner (max double if there is none).
  double distance_to_corners(const Point_3& p) const
  {
    double bd = (std::numeric_limits<double>::max)();
    for(const Point_3& c : m_corners) bd = (std::min)(bd, std::sqrt(CGAL::squared_distance(p, c)));
    return bd;
  }

  const std::vector<Triangle_3>& triangles() const { return m_triangles; }

private:
  const Tree& tree(int patch) const
  {
    if(patch >= 0 && std::size_t(patch) < m_patch_trees.size() && m_patch_trees[std::size_t(patch)]) return *m_patch_trees[std::size_t(patch)];
    return *m_tree;
  }

  std::vector<Triangle_3> m_triangles;
  std::unique_ptr<Tree> m_tree;
  std::vector<int> m_triangle_patch;
  std::vector<std::vector<Triangle_3> > m_patch_triangles;
  std::vector<std::unique_ptr<Tree> > m_patch_trees;
  std::vector<std::vector<std::pair<Point_3, Point_3> > > m_polylines;
  std::vector<Point_3> m_corners;
  double m_diagonal = 0;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_REFERENCE_PROJECTOR_H
