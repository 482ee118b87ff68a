// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_CAD_ACUTE_CURVE_GRADING_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_CAD_ACUTE_CURVE_GRADING_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>

#include <CGAL/number_utils.h>

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Interior dihedral angle of the solid along each CAD curve of a tetrahedralized part (its smallest
// value over the curve's edges), for the curves whose angle is below `max_angle` (radians). The angle
// of an edge is the sum of the dihedral angles of the tetrahedra around it: it needs no orientation
// of the surfaces, which CAD faces do not give reliably.
template <class Point>
std::map<int, double> acute_cad_curves(const Tetrahedral_soup_3<Point>& soup, double max_angle)
{
  typedef std::pair<std::size_t, std::size_t> Edge;
  std::map<Edge, int> curve_of;
  for(std::size_t e = 0; e < soup.feature_edges.size(); ++e) {
    const auto& fe = soup.feature_edges[e];
    curve_of[Edge((std::min)(fe[0], fe[1]), (std::max)(fe[0], fe[1]))] = soup.feature_edge_curves[e];
  }
  std::map<Edge, double> angle;
  // plain arrays: the readers build without Eigen (the fuzzers do)
  typedef std::array<double, 3> Vector;
  auto point = [&](std::size_t v) {
    const Point& p = soup.points[v];
    return Vector{ {CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2])} };
  };
  auto minus = [](const Vector& a, const Vector& b) { return Vector{ {a[0] - b[0], a[1] - b[1], a[2] - b[2]} }; };
  auto dot = [](const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto cross = [](const Vector& a, const Vector& b) {
    return Vector{ {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]} };
  };
  static const int edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for(const auto& t : soup.tetrahedra)
    for(const auto& e : edges) {
      const Edge key((std::min)(t[e[0]], t[e[1]]), (std::max)(t[e[0]], t[e[1]]));
      if(curve_of.find(key) == curve_of.end()) continue;
      const Vector a = point(t[e[0]]);
      Vector u = minus(point(t[e[1]]), a);
      const double length = std::sqrt(dot(u, u));
      if(!(length > 0)) continue;
      for(double& x : u) x /= length;
      Vector c = minus(point(t[e[2]]), a), d = minus(point(t[e[3]]), a);
      const double cu = dot(c, u), du = dot(d, u);
      for(int k = 0; k < 3; ++k) { c[k] -= cu * u[k]; d[k] -= du * u[k]; }
      const Vector n = cross(c, d);
      angle[key] += std::atan2(std::sqrt(dot(n, n)), dot(c, d));
    }
  std::map<int, double> acute;
  for(const auto& ea : angle) {
    if(!(ea.second < max_angle)) continue;
    const int curve = curve_of[ea.first];
    const auto it = acute.find(curve);
    if(it == acute.end() || ea.second < it->second) acute[curve] = ea.second;
  }
  return acute;
}

// Background mesh size of gmsh graded towards the acute curves (curve -> interior angle phi), for
// tetrahedra of size `size` elsewhere: size / 7 on the curve, growing as tan(phi) times the distance
// (at most 8 sizes away), the minimum over the curves. The frame field's band of fixed frames along an
// acute edge of valence 1 (twice the hex edge length, some 3.3 tetrahedron sizes) holds the singular
// curve of the cross-section off the edge only where the tetrahedra are thinner than the wedge (on
// the 10-degree wedge: 0.003 on the edge, 0.04 at 0.2, a slope of tan 10 degrees, gives a valid map;
// the mesh uniform at the hex size folds).
inline void set_acute_curve_grading(const std::map<int, double>& acute, double size)
{
  namespace field = gmsh::model::mesh::field;
  std::vector<double> thresholds;
  int tag = 1000;
  for(const auto& ca : acute) {
    const double slope = (std::max)(std::tan(ca.second), 1e-3);
    const double size_min = size / 7;
    const double distance = (std::min)((size - size_min) / slope, 8 * size);
    const int d = ++tag, t = ++tag;
    field::add("Distance", d);
    field::setNumbers(d, "CurvesList", {double(ca.first)});
    field::setNumber(d, "NumPointsPerCurve", 200);
    field::add("Threshold", t);
    field::setNumber(t, "InField", d);
    field::setNumber(t, "SizeMin", size_min);
    field::setNumber(t, "SizeMax", size);
    field::setNumber(t, "DistMin", 0);
    field::setNumber(t, "DistMax", distance);
    thresholds.push_back(double(t));
  }
  const int all = ++tag;
  field::add("Min", all);
  field::setNumbers(all, "FieldsList", thresholds);
  field::setAsBackgroundMesh(all);
  // the field alone decides the size (as gmsh's manual advises for background fields)
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_CAD_ACUTE_CURVE_GRADING_H
