// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_ACUTE_EDGE_FRAMES_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_ACUTE_EDGE_FRAMES_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The frame a hexahedron has at a boundary edge of valence 1: the edge tangent and the two
// directions v_i, v_j of its triangles (phi(v_i, v_j) ~ pi/2), made orthonormal symmetrically so
// that neither triangle is favoured.
inline Eigen::Matrix3d valence_one_edge_frame(const Eigen::Vector3d& tangent, const Eigen::Vector3d& vi,
                                              const Eigen::Vector3d& vj)
{
  const Eigen::Vector3d t = tangent.normalized();
  const Eigen::Vector3d a = (vi - vi.dot(t) * t).normalized(), b = (vj - vj.dot(t) * t).normalized();
  Eigen::Vector3d m = a + b, d = a - b;
  // a = -b cannot happen at valence 1 (phi ~ pi/2); guard the degenerate inputs anyway
  if(!(m.norm() > 1e-12) || !(d.norm() > 1e-12)) {
    Eigen::Matrix3d E;
    E.col(0) = a;
    E.col(1) = t.cross(a);
    E.col(2) = t;
    return E;
  }
  m.normalize();
  d.normalize();
  Eigen::Matrix3d E;
  E.col(0) = (m + d) / std::sqrt(2.);
  E.col(1) = (m - d) / std::sqrt(2.);
  E.col(2) = E.col(0).cross(E.col(1));
  return E;
}

// Rotates E minimally so that its axis closest to the unit direction v becomes v exactly (the
// exact alignment that the solver keeps on a tetrahedron with a boundary face).
inline Eigen::Matrix3d align_closest_axis(const Eigen::Matrix3d& E, const Eigen::Vector3d& v)
{
  const Eigen::Vector3d c = E.transpose() * v;
  int k = 0;
  c.cwiseAbs().maxCoeff(&k);
  const Eigen::Vector3d axis = c[k] >= 0 ? Eigen::Vector3d(E.col(k)) : Eigen::Vector3d(-E.col(k));
  const Eigen::Vector3d w = axis.cross(v);
  const double s = w.norm(), cs = axis.dot(v);
  if(s < 1e-15) return E;
  return Eigen::AngleAxisd(std::atan2(s, cs), w / s).toRotationMatrix() * E;
}

// The band of an acute edge of prescribed valence 1 (interior dihedral angle below pi/4, exact class
// 0, near ties included: with boundary_edge_near_tie_class() the 18 of MAMBO B41's 24 edges at 45
// degrees that are exact class 0 lost the band, and its hex mesh, valid with it, came out invalid).
// One hexahedron spans the wedge along such an edge, and the cross-section's valence-3 curve
// belongs about a hexahedron or more away from it; but merged with the edge, the curve lowers the
// edge's mismatch from pi/2 - phi to phi, so the smooth field pulls it there (through the vertices
// of a 10-degree edge at every tetrahedron size), where no integer-grid map can keep the two faces
// of the wedge apart. Within `radius` of such edges the frames are held fixed to the edge frame,
// which keeps singular curves out; the boundary directions within the radius become axes of that
// frame, and those up to 3 radius turn towards them by a weight falling linearly to 0, so that the
// field meets no jump where the band ends on the faces (with a jump, the curve sits on the faces
// there instead). Returns the fixed (tetrahedron, frame) pairs, sorted by tetrahedron: the
// tetrahedra incident to the vertices of these edges or with their centroid within the radius,
// each with the frame of the nearest edge, turned onto its boundary direction if it has a
// boundary face. `redirected` counts the boundary directions changed. Nothing if radius <= 0.
template <class Traits>
std::vector<std::pair<std::size_t, Eigen::Matrix3d> >
acute_edge_band(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<int>& valences,
                std::vector<Eigen::Vector3d>& directions, double radius, std::size_t& redirected)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  std::vector<std::pair<std::size_t, Eigen::Matrix3d> > fixed;
  redirected = 0;
  if(!(radius > 0) || !std::isfinite(radius)) return fixed;
  if(valences.size() != mesh.number_of_edges() || directions.size() != mesh.number_of_boundary_triangles())
    return fixed;
  auto to_eigen = [](const auto& p) {
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  std::vector<Index> edges;
  std::vector<Eigen::Matrix3d> edge_frames;
  std::vector<Eigen::Vector3d> midpoints, ends0, ends1;
  std::vector<std::vector<std::uint32_t> > vertex_edges(mesh.number_of_vertices());
  for(Index e = 0; e < mesh.number_of_edges(); ++e) {
    if(!mesh.is_boundary_edge(e) || valences[e] != 1) continue;
    if(boundary_edge_dihedral_class(mesh, e) != 0) continue;
    const auto& ev = mesh.edge_vertices(e);
    const auto& bt = mesh.edge_boundary_triangles(e);
    const Eigen::Vector3d p0 = to_eigen(mesh.point(ev[0])), p1 = to_eigen(mesh.point(ev[1]));
    vertex_edges[ev[0]].push_back(std::uint32_t(edges.size()));
    vertex_edges[ev[1]].push_back(std::uint32_t(edges.size()));
    edges.push_back(e);
    edge_frames.push_back(valence_one_edge_frame(p0 - p1, directions[bt[0]], directions[bt[1]]));
    midpoints.push_back(0.5 * (p0 + p1));
    ends0.push_back(p0);
    ends1.push_back(p1);
  }
  if(edges.empty()) return fixed;
  // only points in the bounding box of the edges grown by 3 radius can be within reach
  Eigen::Vector3d lo = ends0[0], hi = ends0[0];
  for(std::size_t k = 0; k < edges.size(); ++k) {
    lo = lo.cwiseMin(ends0[k]).cwiseMin(ends1[k]);
    hi = hi.cwiseMax(ends0[k]).cwiseMax(ends1[k]);
  }
  lo.array() -= 3 * radius;
  hi.array() += 3 * radius;
  auto nearest_edge = [&](const Eigen::Vector3d& c, double& best) {
    best = std::numeric_limits<double>::infinity();
    if((c.array() < lo.array()).any() || (c.array() > hi.array()).any()) return std::uint32_t(0);
    std::uint32_t best_edge = 0;
    for(std::uint32_t k = 0; k < edges.size(); ++k) {
      const Eigen::Vector3d d = ends1[k] - ends0[k];
      const double s = std::clamp((c - ends0[k]).dot(d) / d.squaredNorm(), 0., 1.);
      const double dist = (ends0[k] + s * d - c).squaredNorm();
      if(dist < best) { best = dist; best_edge = k; }
    }
    return best_edge;
  };
  {
    for(Index b = 0; b < mesh.number_of_boundary_triangles(); ++b) {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for(Index v : mesh.boundary_triangle_vertices(b)) c += to_eigen(mesh.point(v));
      c /= 3;
      double dist;
      const std::uint32_t k = nearest_edge(c, dist);
      const double blend_end = 3 * radius;
      if(dist > blend_end * blend_end) continue;
      const Eigen::Matrix3d& E = edge_frames[k];
      const Eigen::Vector3d d = directions[b].normalized();
      const Eigen::Vector3d a = E.transpose() * d;
      int i = 0;
      a.cwiseAbs().maxCoeff(&i);
      const Eigen::Vector3d target = a[i] >= 0 ? Eigen::Vector3d(E.col(i)) : Eigen::Vector3d(-E.col(i));
      const double w = std::clamp((blend_end - std::sqrt(dist)) / (blend_end - radius), 0., 1.);
      const Eigen::Vector3d axis = d.cross(target);
      const double sn = axis.norm(), angle = std::atan2(sn, d.dot(target));
      const Eigen::Vector3d turned = (w >= 1 || sn < 1e-15) ? (w >= 1 ? target : d)
                                                             : Eigen::Vector3d(Eigen::AngleAxisd(w * angle, axis / sn) * d);
      if(turned != directions[b]) ++redirected;
      directions[b] = turned;
    }
  }
  for(Index t = 0; t < mesh.number_of_tetrahedra(); ++t) {
    const auto& tv = mesh.tetrahedron_vertices(t);
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for(Index v : tv) c += to_eigen(mesh.point(v));
    c /= 4;
    double best = std::numeric_limits<double>::infinity();
    std::uint32_t best_edge = 0;
    for(Index v : tv)
      for(std::uint32_t k : vertex_edges[v]) {
        const double d = (midpoints[k] - c).squaredNorm();
        if(d < best || (d == best && k < best_edge)) { best = d; best_edge = k; }
      }
    {
      double dist;
      const std::uint32_t k = nearest_edge(c, dist);
      if(dist <= radius * radius) { best = dist; best_edge = k; }
    }
    if(best == std::numeric_limits<double>::infinity()) continue;
    Eigen::Matrix3d E = edge_frames[best_edge];
    for(int i = 0; i < 4; ++i) {
      const Index f = mesh.tetrahedron_face(t, i);
      if(mesh.is_boundary_face(f)) E = align_closest_axis(E, directions[mesh.face_boundary_triangle(f)].normalized());
    }
    fixed.emplace_back(std::size_t(t), E);
  }
  return fixed;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_ACUTE_EDGE_FRAMES_H
