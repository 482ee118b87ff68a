// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_RELAXATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_RELAXATION_H

#include <CGAL/Hexahedral_remeshing/internal/frame_field/problem.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/aggregation_multigrid.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/conjugate_gradients.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_projection.h>
#include <CGAL/Hexahedral_remeshing/internal/spherical_harmonics.h>

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Convex relaxation of Ray et al. (design 1.5) with exact elimination of the boundary constraint:
// q_t is free (9 unknowns) in an unconstrained tet and q_t = B_t x_t + c_t (2 unknowns) in a tet
// aligned with direction v_t, where B_t = D(R_v)[e0 e8] and c_t = D(R_v) sqrt(7/12) e4.
// The normal equations of sum_f w_f |q_i - q_j|^2 are solved by conjugate gradients, matrix-free:
// an interior coupling is w I9, so applying the operator costs O(9 #faces), far cheaper than a
// sparse Cholesky of the 9x-blown-up dual Laplacian (whose fill would be 81 times the scalar one).
// The preconditioner is an aggregation multigrid on the same dual graph (aggregation_multigrid.h).
// A fixed tet has no unknown: q_t = q(E_t) is all constant part.
class Frame_field_relaxation
{
public:
  explicit Frame_field_relaxation(const Frame_field_problem& p) : m_p(p)
  {
    const std::size_t nt = p.number_of_tets;
    m_offset.resize(nt + 1);
    m_offset[0] = 0;
    m_family.resize(nt);
    for(std::size_t t = 0; t < nt; ++t) {
      const Frame_field_problem::Index ti = Frame_field_problem::Index(t);
      const bool c = p.is_constrained(ti);
      m_offset[t + 1] = m_offset[t] + (p.is_fixed(ti) ? 0 : c ? 2 : 9);
      if(p.is_fixed(ti)) m_family[t].offset = frame_to_sh(p.frame(ti));
      else if(c) m_family[t] = sh_frame_family(p.direction(ti));
    }
    m_degree.assign(nt, 0.);
    for(std::size_t t = 0; t < nt; ++t)
      for(Frame_field_problem::Index f : p.tet_faces[t])
        if(f != Frame_field_problem::none) m_degree[t] += p.face_weight[f];
  }

  std::size_t number_of_unknowns() const { return m_offset.back(); }

  // q_t for every tet from the reduced unknowns x (with the constant part if with_offset).
  void expand(const Eigen::VectorXd& x, std::vector<Vector9>& q, bool with_offset) const
  {
    q.resize(m_p.number_of_tets);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t ti = 0; ti < std::ptrdiff_t(m_p.number_of_tets); ++ti) {
      const std::size_t t = std::size_t(ti);
      if(m_p.is_fixed(Frame_field_problem::Index(t))) {
        q[t] = with_offset ? m_family[t].offset : Vector9::Zero();
      } else if(m_p.is_constrained(Frame_field_problem::Index(t))) {
        q[t] = m_family[t].basis * x.segment<2>(Eigen::Index(m_offset[t]));
        if(with_offset) q[t] += m_family[t].offset;
      } else {
        q[t] = x.segment<9>(Eigen::Index(m_offset[t]));
      }
    }
  }

  // y = P^T L q: per-tet gather of sum_f w_f (q_t - q_neighbour), restricted to the unknowns.
  void apply_laplacian(const std::vector<Vector9>& q, Eigen::VectorXd& y) const
  {
    y.resize(Eigen::Index(number_of_unknowns()));
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t ti = 0; ti < std::ptrdiff_t(m_p.number_of_tets); ++ti) {
      const std::size_t t = std::size_t(ti);
      Vector9 r = Vector9::Zero();
      for(Frame_field_problem::Index f : m_p.tet_faces[t]) {
        if(f == Frame_field_problem::none) continue;
        const auto& ft = m_p.face_tets[f];
        const std::size_t other = ft[0] == t ? ft[1] : ft[0];
        r += m_p.face_weight[f] * (q[t] - q[other]);
      }
      if(m_p.is_fixed(Frame_field_problem::Index(t))) continue;
      if(m_p.is_constrained(Frame_field_problem::Index(t)))
        y.segment<2>(Eigen::Index(m_offset[t])) = m_family[t].basis.transpose() * r;
      else
        y.segment<9>(Eigen::Index(m_offset[t])) = r;
    }
  }

  // Solves the relaxation; returns the relaxed q of every tet. Reports CG iterations and residual.
  // The conjugate gradients are preconditioned by Jacobi or (flexible) by an aggregation multigrid's
  // K-cycle (iterations nearly independent of the mesh size), see Frame_field_preconditioner.
  std::vector<Vector9> solve(double tolerance, int max_iterations, int& iterations, double& relative_residual,
                             Frame_field_preconditioner preconditioner = Frame_field_preconditioner::AUTOMATIC,
                             Multigrid_cycle cycle = Multigrid_cycle::K) const
  {
    const Eigen::Index n = Eigen::Index(number_of_unknowns());
    std::vector<Vector9> q;
    // right-hand side: b = -P^T L c (c = constant parts)
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n), b;
    expand(x, q, true);
    apply_laplacian(q, b);
    b = -b;
    std::vector<Vector9> qv; // reused: a fresh one per product costs its page faults every time
    auto apply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& Av) {
      expand(v, qv, false);
      apply_laplacian(qv, Av);
    };
    if(use_multigrid(preconditioner, m_p.number_of_tets)) {
      Multigrid_fine_system fine;
      fine.number_of_tets = m_p.number_of_tets;
      fine.face_tets = &m_p.face_tets;
      fine.face_weight = &m_p.face_weight;
      fine.tet_faces = &m_p.tet_faces;
      fine.offset = m_offset;
      fine.embedding.assign(m_p.number_of_tets, 0);
      for(std::size_t t = 0; t < m_p.number_of_tets; ++t) {
        if(m_offset[t + 1] - m_offset[t] != 2) continue;
        fine.embedding[t] = fine.embeddings.size();
        fine.embeddings.insert(fine.embeddings.end(), m_family[t].basis.data(), m_family[t].basis.data() + 18);
      }
      fine.apply = apply;
      const Aggregation_multigrid multigrid(std::move(fine), cycle);
      preconditioned_conjugate_gradients(apply, multigrid, std::move(b), x, tolerance, max_iterations, iterations,
                                         relative_residual, cycle == Multigrid_cycle::K);
    } else {
      Eigen::VectorXd inv_diag(n);
      for(std::size_t t = 0; t < m_p.number_of_tets; ++t) {
        const double d = m_degree[t] > 0 ? 1.0 / m_degree[t] : 1.0;
        for(std::size_t k = m_offset[t]; k < m_offset[t + 1]; ++k) inv_diag[Eigen::Index(k)] = d;
      }
      preconditioned_conjugate_gradients(apply, [&](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = inv_diag.cwiseProduct(r); },
                                         std::move(b), x, tolerance, max_iterations, iterations, relative_residual);
    }
    expand(x, q, true);
    return q;
  }

  // Closest frame of each relaxed q: closed form on the constrained family, multi-start
  // Gauss-Newton elsewhere. Independent per tet (parallel, deterministic).
  std::vector<Eigen::Matrix3d> project(const std::vector<Vector9>& q) const
  {
    std::vector<Eigen::Matrix3d> frames(m_p.number_of_tets);
    const std::ptrdiff_t nt = std::ptrdiff_t(m_p.number_of_tets);
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 256)
#endif
    for(std::ptrdiff_t t = 0; t < nt; ++t) {
      const Frame_field_problem::Index ti = Frame_field_problem::Index(t);
      if(m_p.is_fixed(ti)) {
        frames[t] = m_p.frame(ti);
      } else if(m_p.is_constrained(ti)) {
        // (a, b) are the coordinates of q - c on the orthonormal basis B_t
        const Eigen::Vector2d ab = m_family[t].basis.transpose() * (q[t] - m_family[t].offset);
        frames[t] = frame_from_family(m_p.direction(ti), ab[0], ab[1]);
      } else {
        frames[t] = project_to_frame_fast(q[t]);
      }
    }
    return frames;
  }

private:
  const Frame_field_problem& m_p;
  std::vector<std::size_t> m_offset;
  std::vector<Sh_frame_family> m_family;
  std::vector<double> m_degree;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_RELAXATION_H
