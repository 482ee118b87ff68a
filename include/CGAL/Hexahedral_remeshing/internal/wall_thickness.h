// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_WALL_THICKNESS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_WALL_THICKNESS_H

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// How thick the walls of a solid are, by ray casting: from the centroid of boundary triangles, along
// the inward normal, to the boundary on the other side. `thickness` is the area-weighted median of
// these lengths: the wall thickness of most of the part (a plate: its thickness; a block: its
// sides; a wedge: well above its thin edge), which the hexahedra must fit in; `thinnest` is the
// shortest (a wedge's edge, a fillet's end: no reason to refuse on its own).
struct Wall_thickness
{
  double thickness = std::numeric_limits<double>::infinity(); // infinity: no ray hit anything
  std::array<double, 3> location{ {0, 0, 0} };               // a ray of about that length left from here
  double thinnest = std::numeric_limits<double>::infinity();
  double volume = 0;                                         // of the solid (divergence theorem)
  double area = 0;                                           // of its boundary

  std::string where() const
  {
    std::ostringstream os;
    os.precision(4);
    os << "(" << location[0] << ", " << location[1] << ", " << location[2] << ")";
    return os.str();
  }
};

// `triangles` index `points` and are oriented outward (counter-clockwise seen from outside). Rays
// are cast from every triangle (at most `max_rays`, evenly spread over the list, so that large
// surfaces stay quick); a hit closer than 1e-9 of the bounding box is the ray's own neighbourhood
// and skipped.
template <class Point>
Wall_thickness wall_thickness(const std::vector<Point>& points, const std::vector<std::array<std::uint32_t, 3> >& triangles,
                             std::size_t max_rays = 200000)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator> > > Tree;
  Wall_thickness w;
  std::vector<K::Triangle_3> tris;
  tris.reserve(triangles.size());
  for(const auto& t : triangles) {
    K::Point_3 p[3];
    for(int i = 0; i < 3; ++i)
      p[i] = K::Point_3(CGAL::to_double(points[t[i]][0]), CGAL::to_double(points[t[i]][1]), CGAL::to_double(points[t[i]][2]));
    tris.emplace_back(p[0], p[1], p[2]);
    const K::Vector_3 n = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    w.area += std::sqrt(n.squared_length()) / 2;
    w.volume += CGAL::determinant(p[0] - CGAL::ORIGIN, p[1] - CGAL::ORIGIN, p[2] - CGAL::ORIGIN) / 6;
  }
  if(tris.empty()) return w;
  Tree tree(tris.cbegin(), tris.cend());
  const auto box = tree.bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const std::size_t step = (std::max)(std::size_t(1), tris.size() / (std::max)(std::size_t(1), max_rays));
  std::vector<std::pair<double, double> > length_area; // (ray length, triangle area)
  std::vector<K::Point_3> origin;
  for(std::size_t i = 0; i < tris.size(); i += step) {
    const K::Triangle_3& t = tris[i];
    const K::Vector_3 n = CGAL::cross_product(t[1] - t[0], t[2] - t[0]);
    if(!(n.squared_length() > 0)) continue;
    const K::Point_3 c = CGAL::centroid(t);
    const Iterator self = tris.cbegin() + std::ptrdiff_t(i);
    const auto hit = tree.first_intersection(K::Ray_3(c, -n), [&](const Iterator& id) { return id == self; });
    if(!hit) continue;
    const K::Point_3* q = boost::get<K::Point_3>(&hit->first);
    if(q == nullptr) continue; // a segment: the ray runs in a face, not across the wall
    const double d = std::sqrt(CGAL::squared_distance(c, *q));
    if(!(d > 1e-9 * diagonal)) continue;
    length_area.emplace_back(d, std::sqrt(n.squared_length()) / 2);
    origin.push_back(c);
    w.thinnest = (std::min)(w.thinnest, d);
  }
  if(length_area.empty()) return w;
  std::vector<std::size_t> order(length_area.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return length_area[a] < length_area[b]; });
  double total = 0, sum = 0;
  for(const auto& la : length_area) total += la.second;
  for(std::size_t i : order) {
    sum += length_area[i].second;
    if(sum >= total / 2) {
      w.thickness = length_area[i].first;
      w.location = { {origin[i].x(), origin[i].y(), origin[i].z()} };
      break;
    }
  }
  return w;
}

// A wall thinner than half a hexahedron rounds to no layer at all: the map collapses it.
constexpr double minimum_wall_thickness_over_hex_edge = 0.5;

// The refusal of a hex size that fits no layer of hexahedra in the walls of a part of `volume`.
inline std::string thin_wall_for_hexahedra_message(double thickness, const std::string& where, double h, double volume)
{
  std::ostringstream os;
  os.precision(3);
  const double n = volume > 0 && thickness > 0 ? volume / (thickness * thickness * thickness) : 0;
  os << "the part's walls are " << thickness << " thick (near " << where << "; half of its surface is closer than "
     << "that to the opposite side): hexahedra of edge " << h << " fit no layer in them; give a hex edge length of "
     << "at most " << thickness << " (named parameter target_edge_length, hexmesh --target-edge-length "
     << thickness << ": about " << std::llround(n) << " hexahedra), or thicken the walls";
  return os.str();
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_WALL_THICKNESS_H
