// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_CORNER_TET_PROBLEM_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_CORNER_TET_PROBLEM_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/reference_projector.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/vertex_constraints.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/untangling/foldover_free_map.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Local degrees of freedom of every vertex: x_v = p_v + B_v y_v with B_v = I (interior), an
// orthonormal basis of the tangent plane of the reference surface at the vertex's closest point
// (surface), the unit tangent of its polyline (curve), nothing (fixed). Sliding in the tangent
// space is a linearization: the positions are projected back onto the reference afterwards.
struct Hex_vertex_dofs
{
  std::vector<int> offset;             // first unknown of v in y
  std::vector<int> count;              // 0..3
  std::vector<Eigen::Matrix3d> basis;  // the first count[v] columns are used
  int n = 0;
};

inline Hex_vertex_dofs make_hex_vertex_dofs(const std::vector<Hexahedral_mesh_3::Point_3>& points,
                                            const std::vector<Hex_vertex_constraint>& constraints,
                                            const Reference_projector& reference, bool boundary_fixed)
{
  typedef Reference_projector::Vector_3 Vector_3;
  Hex_vertex_dofs d;
  const std::size_t V = points.size();
  d.offset.assign(V, 0);
  d.count.assign(V, 0);
  d.basis.assign(V, Eigen::Matrix3d::Identity());
  for(std::size_t v = 0; v < V; ++v) {
    const Hex_vertex_constraint& c = constraints[v];
    int k = 0;
    if(c.kind == Hex_vertex_kind::INTERIOR) k = 3;
    else if(boundary_fixed || c.kind == Hex_vertex_kind::FIXED) k = 0;
    else if(c.kind == Hex_vertex_kind::SURFACE) {
      Vector_3 n;
      reference.closest_on_surface(points[v], &n, c.patch);
      const Eigen::Vector3d nn(n.x(), n.y(), n.z());
      // any vector not parallel to n gives the first tangent; the least aligned axis is the stablest
      int axis = 0;
      for(int a = 1; a < 3; ++a)
        if(std::abs(nn[a]) < std::abs(nn[axis])) axis = a;
      const Eigen::Vector3d t1 = nn.cross(Eigen::Vector3d::Unit(axis)).normalized();
      d.basis[v].col(0) = t1;
      d.basis[v].col(1) = nn.cross(t1);
      k = 2;
    } else if(c.kind == Hex_vertex_kind::CURVE) {
      Vector_3 t;
      reference.closest_on_polyline(c.polyline, points[v], &t);
      if(t.squared_length() > 0) {
        d.basis[v].col(0) = Eigen::Vector3d(t.x(), t.y(), t.z());
        k = 1;
      }
    }
    d.offset[v] = d.n;
    d.count[v] = k;
    d.n += k;
  }
  return d;
}

// The foldover-free problem of the 8 corner tetrahedra of every hex (corner i and its neighbours
// (a, b, c) in VTK order, so that a cube corner has D = h I): K = D / size_h, the ideal corner is a
// cube corner of edge size_h; weight 1 per corner. The sliding (surface, curve) unknowns get the
// anchor `boundary_anchor / s_v^2` (s_v: mean size of the hexahedra at v): their tangent-space moves
// are only first-order exact, and on a curved surface the energy has near-null modes along it (a
// rotation of a cylinder's boundary) that would otherwise carry them far from the reference.
inline Foldover_free_problem make_corner_tet_problem(const Hexahedral_mesh_3& mesh,
                                                     const std::vector<Hexahedral_mesh_3::Point_3>& points,
                                                     const Hex_vertex_dofs& dofs,
                                                     const std::vector<double>& hex_size,
                                                     double boundary_anchor = 0)
{
  Foldover_free_problem p;
  const std::size_t E = 8 * mesh.number_of_hexahedra();
  p.x0.resize(Eigen::Index(12 * E));
  p.M.reserve(E);
  p.w.assign(E, 1.);
  std::vector<Eigen::Triplet<double> > triplets;
  triplets.reserve(12 * E * 2);
  for(std::size_t h = 0; h < mesh.number_of_hexahedra(); ++h) {
    const auto& hex = mesh.hexahedra[h];
    for(int i = 0; i < 8; ++i) {
      const std::size_t e = 8 * h + std::size_t(i);
      const auto& nb = hex_corner_neighbors()[i];
      const std::array<std::uint32_t, 4> corner{ {hex[i], hex[nb[0]], hex[nb[1]], hex[nb[2]]} };
      for(int c = 0; c < 4; ++c) {
        const std::uint32_t v = corner[c];
        const int row = int(12 * e + 3 * c);
        for(int r = 0; r < 3; ++r) {
          p.x0[row + r] = points[v][r];
          for(int k = 0; k < dofs.count[v]; ++k)
            if(dofs.basis[v](r, k) != 0) triplets.emplace_back(row + r, dofs.offset[v] + k, dofs.basis[v](r, k));
        }
      }
      p.M.push_back(Eigen::Matrix3d::Identity() / hex_size[h]);
    }
  }
  p.P.resize(Eigen::Index(12 * E), dofs.n);
  p.P.setFromTriplets(triplets.begin(), triplets.end());
  if(boundary_anchor > 0) {
    std::vector<double> size_sum(points.size(), 0.);
    std::vector<int> size_count(points.size(), 0);
    for(std::size_t h = 0; h < mesh.number_of_hexahedra(); ++h)
      for(std::uint32_t v : mesh.hexahedra[h]) { size_sum[v] += hex_size[h]; ++size_count[v]; }
    p.anchor = Eigen::VectorXd::Zero(dofs.n);
    p.anchor_weight = Eigen::VectorXd::Zero(dofs.n);
    for(std::size_t v = 0; v < points.size(); ++v)
      if(dofs.count[v] > 0 && dofs.count[v] < 3 && size_count[v] > 0) {
        const double s = size_sum[v] / size_count[v];
        for(int k = 0; k < dofs.count[v]; ++k) p.anchor_weight[dofs.offset[v] + k] = boundary_anchor / (s * s);
      }
  }
  return p;
}

// x_v = p_v + B_v y_v
inline void apply_hex_vertex_dofs(const Hex_vertex_dofs& dofs, const Eigen::VectorXd& y,
                                  std::vector<Hexahedral_mesh_3::Point_3>& points)
{
  for(std::size_t v = 0; v < points.size(); ++v) {
    if(dofs.count[v] == 0) continue;
    Eigen::Vector3d dx = Eigen::Vector3d::Zero();
    for(int k = 0; k < dofs.count[v]; ++k) dx += y[dofs.offset[v] + k] * dofs.basis[v].col(k);
    points[v] = Hexahedral_mesh_3::Point_3(points[v].x() + dx[0], points[v].y() + dx[1], points[v].z() + dx[2]);
  }
}

// Mean edge length of every hexahedron (the ideal size of its corners); the mean over the mesh for
// a degenerate one.
inline std::vector<double> hex_mean_edge_lengths(const Hexahedral_mesh_3& mesh)
{
  std::vector<double> s(mesh.number_of_hexahedra(), 0.);
  double total = 0;
  std::size_t count = 0;
  for(std::size_t h = 0; h < s.size(); ++h) {
    for(const auto& e : hex_edges())
      s[h] += std::sqrt(CGAL::squared_distance(mesh.points[mesh.hexahedra[h][e[0]]], mesh.points[mesh.hexahedra[h][e[1]]])) / 12.;
    if(s[h] > 0 && std::isfinite(s[h])) { total += s[h]; ++count; }
  }
  const double fallback = count > 0 ? total / double(count) : 1.;
  for(double& x : s)
    if(!(x > 0) || !std::isfinite(x)) x = fallback;
  return s;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_CORNER_TET_PROBLEM_H
