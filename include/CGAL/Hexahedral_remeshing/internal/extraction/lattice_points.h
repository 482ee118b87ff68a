// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_LATTICE_POINTS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_LATTICE_POINTS_H

#include <CGAL/Hexahedral_remeshing/internal/extraction/check_map.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <functional>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace extraction {

// Points of the lattice Z^3 + h (1,1,1), h = 0 (hex vertices) or 1/2 (hex cell centres), in the relative
// interior of one simplex of parameter space: the lowest-dimension rule of HexEx, each point belongs to
// exactly one simplex. Candidates are generated in floating point and rounded to the lattice; the
// decision is exact (Epick orientation, collinear, coplanar_orientation on the sanitized doubles).
// The callback receives the point and its barycentric coordinates on the simplex.
typedef std::function<void(const Eigen::Vector3d&, const std::array<double, 4>&)> Lattice_callback;

inline double to_lattice(double x, double h) { return std::round(x - h) + h; }

inline bool on_lattice(const Eigen::Vector3d& p, double h)
{
  for(int c = 0; c < 3; ++c)
    if(to_lattice(p[c], h) != p[c]) return false;
  return true;
}

inline void lattice_points_on_edge(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double h, const Lattice_callback& f)
{
  const Eigen::Vector3d d = b - a;
  int c;
  if(d.cwiseAbs().maxCoeff(&c) == 0.) return;
  const double lo = (std::min)(a[c], b[c]), hi = (std::max)(a[c], b[c]);
  for(double i = std::ceil(lo - h); i + h <= hi; ++i) {
    const double xc = i + h;
    if(xc <= lo || xc >= hi) continue;
    const double s = (xc - a[c]) / d[c];
    Eigen::Vector3d q;
    for(int k = 0; k < 3; ++k) q[k] = k == c ? xc : to_lattice(a[k] + s * d[k], h);
    if(!CGAL::collinear(parameter_point(a), parameter_point(b), parameter_point(q))) continue;
    f(q, {{1. - s, s, 0., 0.}});
  }
}

inline void lattice_points_in_triangle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                                       double h, const Lattice_callback& f)
{
  const Parameter_point P0 = parameter_point(p0), P1 = parameter_point(p1), P2 = parameter_point(p2);
  if(CGAL::collinear(P0, P1, P2)) return;
  const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
  int c;
  n.cwiseAbs().maxCoeff(&c);
  const int a = (c + 1) % 3, b = (c + 2) % 3;
  const double alo = (std::min)({p0[a], p1[a], p2[a]}), ahi = (std::max)({p0[a], p1[a], p2[a]});
  const double blo = (std::min)({p0[b], p1[b], p2[b]}), bhi = (std::max)({p0[b], p1[b], p2[b]});
  // 2D barycentric coordinates in the projection on (a, b), where the triangle is not degenerate
  const double det = (p1[a] - p0[a]) * (p2[b] - p0[b]) - (p2[a] - p0[a]) * (p1[b] - p0[b]);
  for(double i = std::ceil(alo - h); i + h <= ahi; ++i)
    for(double j = std::ceil(blo - h); j + h <= bhi; ++j) {
      Eigen::Vector3d q;
      q[a] = i + h;
      q[b] = j + h;
      q[c] = to_lattice(p0[c] - (n[a] * (q[a] - p0[a]) + n[b] * (q[b] - p0[b])) / n[c], h);
      const Parameter_point Q = parameter_point(q);
      if(!CGAL::coplanar(P0, P1, P2, Q)) continue;
      if(CGAL::coplanar_orientation(P0, P1, P2, Q) != CGAL::POSITIVE ||
         CGAL::coplanar_orientation(P1, P2, P0, Q) != CGAL::POSITIVE ||
         CGAL::coplanar_orientation(P2, P0, P1, Q) != CGAL::POSITIVE)
        continue;
      const double l1 = ((q[a] - p0[a]) * (p2[b] - p0[b]) - (p2[a] - p0[a]) * (q[b] - p0[b])) / det;
      const double l2 = ((p1[a] - p0[a]) * (q[b] - p0[b]) - (q[a] - p0[a]) * (p1[b] - p0[b])) / det;
      f(q, {{1. - l1 - l2, l1, l2, 0.}});
    }
}

// Interior points of a positively oriented tetrahedron.
inline void lattice_points_in_tetrahedron(const std::array<Eigen::Vector3d, 4>& u, double h, const Lattice_callback& f)
{
  Eigen::Vector3d lo = u[0], hi = u[0];
  for(int k = 1; k < 4; ++k) { lo = lo.cwiseMin(u[k]); hi = hi.cwiseMax(u[k]); }
  const Parameter_point P[4] = {parameter_point(u[0]), parameter_point(u[1]), parameter_point(u[2]), parameter_point(u[3])};
  Eigen::Matrix3d M;
  for(int k = 0; k < 3; ++k) M.col(k) = u[k + 1] - u[0];
  const Eigen::PartialPivLU<Eigen::Matrix3d> lu(M);
  for(double x = std::ceil(lo[0] - h); x + h < hi[0]; ++x) {
    if(x + h <= lo[0]) continue;
    for(double y = std::ceil(lo[1] - h); y + h < hi[1]; ++y) {
      if(y + h <= lo[1]) continue;
      for(double z = std::ceil(lo[2] - h); z + h < hi[2]; ++z) {
        if(z + h <= lo[2]) continue;
        const Eigen::Vector3d q(x + h, y + h, z + h);
        const Parameter_point Q = parameter_point(q);
        if(CGAL::orientation(Q, P[1], P[2], P[3]) != CGAL::POSITIVE || CGAL::orientation(P[0], Q, P[2], P[3]) != CGAL::POSITIVE ||
           CGAL::orientation(P[0], P[1], Q, P[3]) != CGAL::POSITIVE || CGAL::orientation(P[0], P[1], P[2], Q) != CGAL::POSITIVE)
          continue;
        const Eigen::Vector3d l = lu.solve(q - u[0]);
        f(q, {{1. - l.sum(), l[0], l[1], l[2]}});
      }
    }
  }
}

} // namespace extraction
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_LATTICE_POINTS_H
