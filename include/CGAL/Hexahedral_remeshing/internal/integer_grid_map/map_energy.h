// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_ENERGY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_ENERGY_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Per tetrahedron: the gradients of the four barycentric coordinates G_t = B_t^{-1} S (3x4, B_t rows
// p1-p0, p2-p0, p3-p0) and the volume, so that the Jacobian of the affine map with corner
// parameters U_t (3x4) is J_t = U_t G_t^T.
struct Map_geometry
{
  std::vector<Eigen::Matrix<double, 3, 4> > gradients;
  std::vector<double> volumes;
};

// Rows: the edge vectors p1 - p0, p2 - p0, p3 - p0 of tetrahedron t.
template <class Traits>
Eigen::Matrix3d tetrahedron_edge_matrix(const Tetrahedral_mesh_3<Traits>& mesh, std::size_t t)
{
  const auto& tv = mesh.tetrahedron_vertices(typename Tetrahedral_mesh_3<Traits>::Index(t));
  Eigen::Matrix3d B;
  for(int i = 0; i < 3; ++i) {
    const auto d = mesh.point(tv[i + 1]) - mesh.point(tv[0]);
    B.row(i) << CGAL::to_double(d.x()), CGAL::to_double(d.y()), CGAL::to_double(d.z());
  }
  return B;
}

template <class Traits>
Map_geometry compute_map_geometry(const Tetrahedral_mesh_3<Traits>& mesh)
{
  Map_geometry g;
  const std::size_t nt = mesh.number_of_tetrahedra();
  g.gradients.resize(nt);
  g.volumes.resize(nt);
  Eigen::Matrix<double, 3, 4> S;
  S << -1, 1, 0, 0, -1, 0, 1, 0, -1, 0, 0, 1;
  for(std::size_t t = 0; t < nt; ++t) {
    const Eigen::Matrix3d B = tetrahedron_edge_matrix(mesh, t);
    g.volumes[t] = std::abs(B.determinant()) / 6.0;
    g.gradients[t] = B.inverse() * S;
  }
  return g;
}

// The energy sum_t w_t vol_t |U_t G_t^T - s E_t^T|_F^2 on the 12 n corner scalars
// (x[12 t + 3 c + r] = coordinate r of corner c), as x^T A x - 2 b^T x + const.
inline void assemble_map_energy(const Map_geometry& geometry, const std::vector<Eigen::Matrix3d>& frames,
                                double s, const std::vector<double>& weights,
                                Eigen::SparseMatrix<double>& A, Eigen::VectorXd& b)
{
  const std::size_t nt = geometry.volumes.size();
  std::vector<Eigen::Triplet<double> > triplets;
  triplets.reserve(nt * 48);
  b.setZero(Eigen::Index(12 * nt));
  for(std::size_t t = 0; t < nt; ++t) {
    const double w = geometry.volumes[t] * (weights.empty() ? 1.0 : weights[t]);
    const Eigen::Matrix<double, 3, 4>& G = geometry.gradients[t];
    const Eigen::Matrix4d K = w * G.transpose() * G;
    for(int r = 0; r < 3; ++r) {
      // row r of s E_t^T is s times column r of E_t
      const Eigen::Vector4d br = w * s * (G.transpose() * frames[t].col(r));
      for(int c = 0; c < 4; ++c) {
        b[Eigen::Index(12 * t + 3 * c + r)] = br[c];
        for(int d = 0; d < 4; ++d)
          triplets.emplace_back(int(12 * t + 3 * c + r), int(12 * t + 3 * d + r), K(c, d));
      }
    }
  }
  A.resize(Eigen::Index(12 * nt), Eigen::Index(12 * nt));
  A.setFromTriplets(triplets.begin(), triplets.end());
}

// Jacobian of tetrahedron t for the corner scalars x.
inline Eigen::Matrix3d map_jacobian(const Map_geometry& geometry, const Eigen::VectorXd& x, std::size_t t)
{
  Eigen::Matrix<double, 3, 4> U;
  for(int c = 0; c < 4; ++c) U.col(c) = x.segment<3>(Eigen::Index(12 * t + 3 * c));
  return U * geometry.gradients[t].transpose();
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MAP_ENERGY_H
