// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_HEXAHEDRON_TOPOLOGY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_HEXAHEDRON_TOPOLOGY_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>

#include <array>
#include <cmath>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Local topology of a hexahedron in VTK order (algorithms.md §6). Corner i sits at
// hex_unit_corners[i] in the hex's own chart.
inline const std::array<std::array<int, 3>, 8>& hex_unit_corners()
{
  static const std::array<std::array<int, 3>, 8> c{ {
    {{0, 0, 0}}, {{1, 0, 0}}, {{1, 1, 0}}, {{0, 1, 0}},
    {{0, 0, 1}}, {{1, 0, 1}}, {{1, 1, 1}}, {{0, 1, 1}} } };
  return c;
}

// The 6 faces, each a cycle of 4 corners oriented so that its normal (right-hand rule) points out of
// the hex: the same face seen from the neighbouring hex runs the other way, which is what the
// conformity check relies on.
inline const std::array<std::array<int, 4>, 6>& hex_faces()
{
  static const std::array<std::array<int, 4>, 6> f{ {
    {{0, 3, 2, 1}},   // bottom, w = 0
    {{4, 5, 6, 7}},   // top, w = 1
    {{0, 1, 5, 4}},   // v = 0
    {{1, 2, 6, 5}},   // u = 1
    {{2, 3, 7, 6}},   // v = 1
    {{3, 0, 4, 7}} } }; // u = 0
  return f;
}

// The 12 edges.
inline const std::array<std::array<int, 2>, 12>& hex_edges()
{
  static const std::array<std::array<int, 2>, 12> e{ {
    {{0, 1}}, {{1, 2}}, {{2, 3}}, {{3, 0}},
    {{4, 5}}, {{5, 6}}, {{6, 7}}, {{7, 4}},
    {{0, 4}}, {{1, 5}}, {{2, 6}}, {{3, 7}} } };
  return e;
}

// Corner neighbours (a, b, c) such that (x_a - x_i, x_b - x_i, x_c - x_i) is a right-handed frame in
// a positively oriented hex.
inline const std::array<std::array<int, 3>, 8>& hex_corner_neighbors()
{
  static const std::array<std::array<int, 3>, 8> n{ {
    {{1, 3, 4}}, {{2, 0, 5}}, {{3, 1, 6}}, {{0, 2, 7}},
    {{7, 5, 0}}, {{4, 6, 1}}, {{5, 7, 2}}, {{6, 4, 3}} } };
  return n;
}

// Scaled Jacobian of corner `i`: the determinant of the three unit edge vectors; 1 for a cube corner,
// <= 0 when the corner is inverted or degenerate (a zero-length edge gives 0).
inline double hex_corner_scaled_jacobian(const std::array<Hexahedral_mesh_3::Point_3, 8>& p, int i)
{
  const auto& nb = hex_corner_neighbors()[i];
  double e[3][3];
  for(int k = 0; k < 3; ++k) {
    const auto& q = p[nb[k]];
    e[k][0] = q.x() - p[i].x();
    e[k][1] = q.y() - p[i].y();
    e[k][2] = q.z() - p[i].z();
    const double len = std::sqrt(e[k][0] * e[k][0] + e[k][1] * e[k][1] + e[k][2] * e[k][2]);
    if(!(len > 0.))
      return 0.;
    for(int d = 0; d < 3; ++d)
      e[k][d] /= len;
  }
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1])
       - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0])
       + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

// Signed volume of the hexahedron: each face is split into 4 triangles around its centroid and coned
// to the cell centroid (24 tets), which is exact for trilinear hexes with planar faces and symmetric
// in the corners otherwise.
inline double hex_signed_volume(const std::array<Hexahedral_mesh_3::Point_3, 8>& p)
{
  double c[3] = {0., 0., 0.};
  for(const auto& q : p) {
    c[0] += q.x() / 8.; c[1] += q.y() / 8.; c[2] += q.z() / 8.;
  }
  double volume = 0.;
  for(const auto& f : hex_faces()) {
    double fc[3] = {0., 0., 0.};
    for(int j = 0; j < 4; ++j) {
      fc[0] += p[f[j]].x() / 4.; fc[1] += p[f[j]].y() / 4.; fc[2] += p[f[j]].z() / 4.;
    }
    for(int j = 0; j < 4; ++j) {
      const auto& a = p[f[j]];
      const auto& b = p[f[(j + 1) % 4]];
      // tet (a, b, face centre, cell centre): the face normal points outwards, so
      // det(a - c, b - c, fc - c) is positive for a positive hex
      const double A[3] = {a.x() - c[0], a.y() - c[1], a.z() - c[2]};
      const double B[3] = {b.x() - c[0], b.y() - c[1], b.z() - c[2]};
      const double F[3] = {fc[0] - c[0], fc[1] - c[1], fc[2] - c[2]};
      volume += (A[0] * (B[1] * F[2] - B[2] * F[1]) - A[1] * (B[0] * F[2] - B[2] * F[0])
               + A[2] * (B[0] * F[1] - B[1] * F[0])) / 6.;
    }
  }
  return volume;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_HEXAHEDRON_TOPOLOGY_H
