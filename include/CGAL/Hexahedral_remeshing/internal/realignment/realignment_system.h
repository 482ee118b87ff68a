// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_REALIGNMENT_SYSTEM_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_REALIGNMENT_SYSTEM_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/problem.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Orthonormal basis (columns) of the plane orthogonal to the unit vector n.
inline Eigen::Matrix<double, 3, 2> tangent_basis(const Eigen::Vector3d& n)
{
  const Eigen::Vector3d a = std::abs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d t1 = (a - a.dot(n) * n).normalized();
  Eigen::Matrix<double, 3, 2> T;
  T.col(0) = t1;
  T.col(1) = n.cross(t1);
  return T;
}

// A rotation of the octahedral group as a signed permutation: column j of E g is sign[j] times
// column perm[j] of E, so that the solver's products need no 3x3 multiplication.
struct Signed_permutation
{
  std::array<int, 3> perm;
  std::array<double, 3> sign;
  explicit Signed_permutation(const Eigen::Matrix3d& g)
  {
    for(int j = 0; j < 3; ++j)
      for(int i = 0; i < 3; ++i)
        if(g(i, j) != 0) { perm[j] = i; sign[j] = g(i, j); }
  }
  void add_product(const Eigen::Matrix3d& E, double w, Eigen::Matrix3d& out) const // out -= w E g
  {
    for(int j = 0; j < 3; ++j) out.col(j) -= (w * sign[j]) * E.col(perm[j]);
  }
};

// The linear system of the realignment (Desobry et al., Sec. 3.3, Eq. 4), matrix-free, in the
// solver's numbering of the tetrahedra. Unknowns: 9 per free tet (E' itself), 6 per constrained
// tet (Y_t, E' = X0_t + T_t Y_t, which enforces n_i^T E'_t = v_i^T E_t exactly). The operator is
// P^T (L + mu I) P with L the matching-twisted graph Laplacian of the interior faces.
template <class Traits>
struct Realignment_system
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  typedef Eigen::Matrix<double, 3, 2> Matrix32;
  static constexpr Index null = Tetrahedral_mesh_3<Traits>::null_index;
  // only there to make the system definite (the face weights have mean 1)
  static constexpr double mu = 1e-6;

  // An interior face between solver tets a and b (E_a ~ E_b g, g = the matching), 24 bytes: the
  // matching's steps both ways are looked up in tables of the 24 rotations.
  struct Face { Index a, b; std::uint8_t matching; double w; };

  std::size_t nt = 0;
  std::vector<std::uint32_t> order, rank;   // solver tet -> mesh tet and back (empty: identity)
  std::vector<Index> constraint;            // per solver tet, its boundary triangle or null
  std::vector<Eigen::Matrix3d> X0;          // per solver tet, the eliminated part n_i c^T
  std::vector<Matrix32> T;                  // per solver tet, the tangent basis of n_i
  std::vector<Face> faces;
  std::vector<double> weights;              // per face, normalized to mean 1
  std::vector<Signed_permutation> step_ab, step_ba;
  std::vector<std::array<Index, 4> > tet_faces;
  std::vector<double> degree;
  std::vector<std::size_t> offset;          // first unknown of each solver tet; offset[nt] = size
  Eigen::Index n = 0;

  std::size_t mesh_tet(std::size_t s) const { return order.empty() ? s : std::size_t(order[s]); }
  Index solver_tet(std::size_t t) const { return rank.empty() ? Index(t) : Index(rank[t]); }
  bool is_constrained(std::size_t t) const { return constraint[t] != null; }

  // Constraints (one boundary triangle per tet at most), faces and unknowns of `mesh`.
  template <class NamedParameters>
  Realignment_system(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                     const Matchings& matchings, const std::vector<Eigen::Vector3d>& directions,
                     const std::vector<Eigen::Vector3d>& normals, bool uniform, const NamedParameters& np)
    : nt(mesh.number_of_tetrahedra())
  {
    // the solver numbers the tets in the frame field's order (a Hilbert curve on the meshes where it
    // is memory-bound)
    order = solver_order(mesh, np);
    rank = ranks_of_order(order, nt, "realign_frame_field");
    add_constraints(mesh, frames, directions, normals);
    add_faces(mesh, matchings, uniform);
    offset.assign(nt + 1, 0);
    for(std::size_t t = 0; t < nt; ++t) offset[t + 1] = offset[t] + (is_constrained(t) ? 6 : 9);
    n = Eigen::Index(offset[nt]);
  }

  void add_constraints(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                       const std::vector<Eigen::Vector3d>& directions, const std::vector<Eigen::Vector3d>& normals)
  {
    constraint.assign(nt, null);
    X0.assign(nt, Eigen::Matrix3d::Zero());
    T.resize(nt);
    for(Index b = 0; b < mesh.number_of_boundary_triangles(); ++b) {
      const Index t = mesh.boundary_triangle_tetrahedron(b);
      const Index st = solver_tet(t);
      if(constraint[st] != null)
        throw Error("realign_frame_field: tetrahedron " + std::to_string(t) + " has several boundary faces");
      constraint[st] = b;
      const Eigen::Vector3d c = frames[t].transpose() * directions[b].normalized();
      X0[st] = normals[b] * c.transpose();
      T[st] = tangent_basis(normals[b]);
    }
  }

  void add_faces(const Tetrahedral_mesh_3<Traits>& mesh, const Matchings& matchings, bool uniform)
  {
    const Octahedral_group& group = octahedral_group();
    for(int m = 0; m < 24; ++m) {
      step_ab.emplace_back(group.matrix(m));
      step_ba.emplace_back(Eigen::Matrix3d(group.matrix(m).transpose()));
    }
    tet_faces.assign(nt, {null, null, null, null});
    for(const Index f : interior_faces_in_order(mesh, rank)) {
      const auto& ft = mesh.face_tetrahedra(f);
      faces.push_back({solver_tet(ft[0]), solver_tet(ft[1]), std::uint8_t(matchings.face_matching[f]), 1.0});
      weights.push_back(uniform ? 1.0 : area_over_distance(mesh, f));
    }
    normalize_mean(weights);
    for(std::size_t fi = 0; fi < faces.size(); ++fi) faces[fi].w = weights[fi];
    for(Index fi = 0; fi < faces.size(); ++fi)
      for(Index t : {faces[fi].a, faces[fi].b})
        for(int k = 0; k < 4; ++k)
          if(tet_faces[t][k] == null) { tet_faces[t][k] = fi; break; }
    degree.assign(nt, 0.);
    for(const Face& f : faces) { degree[f.a] += f.w; degree[f.b] += f.w; }
  }

  // E = P y (+ X0 when with_offset), per solver tet.
  void expand(const Eigen::VectorXd& y, std::vector<Eigen::Matrix3d>& E, bool with_offset) const
  {
    E.resize(nt);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t ti = 0; ti < std::ptrdiff_t(nt); ++ti) {
      const std::size_t t = std::size_t(ti);
      if(is_constrained(t)) {
        E[t] = T[t] * Eigen::Map<const Eigen::Matrix<double, 2, 3> >(y.data() + offset[t]);
        if(with_offset) E[t] += X0[t];
      } else {
        E[t] = Eigen::Map<const Eigen::Matrix3d>(y.data() + offset[t]);
      }
    }
  }

  // out = P^T (L + mu I) E, gathered per tet.
  void apply(const std::vector<Eigen::Matrix3d>& E, Eigen::VectorXd& out) const
  {
    out.resize(n);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t ti = 0; ti < std::ptrdiff_t(nt); ++ti) {
      const std::size_t t = std::size_t(ti);
      Eigen::Matrix3d r = (mu + degree[t]) * E[t];
      for(Index fi : tet_faces[t]) {
        if(fi == null) continue;
        const Face& f = faces[fi];
        if(f.a == t) step_ab[f.matching].add_product(E[f.b], f.w, r);
        else step_ba[f.matching].add_product(E[f.a], f.w, r);
      }
      if(is_constrained(t)) Eigen::Map<Eigen::Matrix<double, 2, 3> >(out.data() + offset[t]) = T[t].transpose() * r;
      else Eigen::Map<Eigen::Matrix3d>(out.data() + offset[t]) = r;
    }
  }

  // Right-hand side P^T (mu E_old - (L + mu I) X0) and initial guess, the old frames projected.
  void right_hand_side(const std::vector<Eigen::Matrix3d>& frames, Eigen::VectorXd& b, Eigen::VectorXd& x) const
  {
    b.resize(n);
    x.resize(n);
    std::vector<Eigen::Matrix3d> E0;
    Eigen::VectorXd zero = Eigen::VectorXd::Zero(n), AX0;
    expand(zero, E0, true);
    apply(E0, AX0);
    for(std::size_t t = 0; t < nt; ++t) {
      const Eigen::Matrix3d& F = frames[mesh_tet(t)];
      if(is_constrained(t)) {
        Eigen::Map<Eigen::Matrix<double, 2, 3> >(b.data() + offset[t]) = T[t].transpose() * (mu * F);
        Eigen::Map<Eigen::Matrix<double, 2, 3> >(x.data() + offset[t]) = T[t].transpose() * F;
      } else {
        Eigen::Map<Eigen::Matrix3d>(b.data() + offset[t]) = mu * F;
        Eigen::Map<Eigen::Matrix3d>(x.data() + offset[t]) = F;
      }
    }
    b -= AX0;
  }
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_REALIGNMENT_REALIGNMENT_SYSTEM_H
