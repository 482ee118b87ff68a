// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_CONJUGATE_GRADIENTS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_CONJUGATE_GRADIENTS_H

#include <CGAL/Hexahedral_remeshing/internal/frame_field/parallel_vector_operations.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Preconditioner of the frame-field solves. AUTOMATIC: Jacobi below multigrid_minimum_tets
// tetrahedra, where the multigrid's setup and its three operator products per iteration cost more
// than the iterations it saves (measured with 2 threads: 6.8k tets, relaxation 50 -> 65 ms;
// 22k, 186 -> 219 ms; 38k, 424 -> 337 ms; 91k, 1.81 -> 1.19 s), the multigrid above.
enum class Frame_field_preconditioner { AUTOMATIC, JACOBI, MULTIGRID };
constexpr std::size_t multigrid_minimum_tets = 30000;

inline bool use_multigrid(Frame_field_preconditioner p, std::size_t tets)
{
  return p == Frame_field_preconditioner::MULTIGRID ||
         (p == Frame_field_preconditioner::AUTOMATIC && tets >= multigrid_minimum_tets);
}

// Preconditioned conjugate gradients on A x = b from the given x, matrix-free: apply(v, Av) and
// precondition(r, z) (z = M^-1 r, M symmetric positive definite). Stops at |b - A x| < tolerance |b|
// or after max_iterations. The vector operations are those of parallel_vector_operations.h, so the
// iterates do not depend on the number of threads. b is taken by value and becomes the residual (one vector
// of the size of the system less at the peak: move it in). flexible: the preconditioner may vary
// from one call to the next (a K-cycle, Multigrid_cycle): Polak-Ribiere's beta (Notay's flexible
// CG, one more dot product fused in the same pass) keeps it converging where Fletcher-Reeves'
// would not.
template <class Apply, class Precondition>
void preconditioned_conjugate_gradients(const Apply& apply, const Precondition& precondition, Eigen::VectorXd b,
                                        Eigen::VectorXd& x, double tolerance, int max_iterations, int& iterations,
                                        double& relative_residual, bool flexible = false)
{
  Eigen::VectorXd Ax;
  apply(x, Ax);
  const double b_norm = (std::max)(b.norm(), 1e-300);
  Eigen::VectorXd r = std::move(b), z;
  r -= Ax;
  iterations = 0;
  relative_residual = r.norm() / b_norm;
  if(relative_residual < tolerance) return;
  precondition(r, z);
  Eigen::VectorXd d = z;
  double rz = r.dot(z);
  const Eigen::Index n = r.size();
  std::vector<double> dots;
  while(iterations < max_iterations) {
    apply(d, Ax);
    const double alpha = rz / parallel_dot(d, Ax);
    const double rr = parallel_segment_sum(n, [&](Eigen::Index begin, Eigen::Index size) {
      x.segment(begin, size) += alpha * d.segment(begin, size);
      r.segment(begin, size) -= alpha * Ax.segment(begin, size);
      return r.segment(begin, size).squaredNorm();
    });
    ++iterations;
    relative_residual = std::sqrt(rr) / b_norm;
    if(relative_residual < tolerance) break;
    precondition(r, z);
    double rz_new, beta;
    if(flexible) {
      // Polak-Ribiere: z_new . (r_new - r_old) = -alpha z_new . A d
      parallel_dots(z, {&r, &Ax}, dots);
      rz_new = dots[0];
      beta = -alpha * dots[1] / rz;
    } else {
      rz_new = parallel_dot(r, z);
      beta = rz_new / rz;
    }
    for_each_segment(n, [&](Eigen::Index begin, Eigen::Index size) {
      d.segment(begin, size) = z.segment(begin, size) + beta * d.segment(begin, size);
    });
    rz = rz_new;
  }
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_CONJUGATE_GRADIENTS_H
