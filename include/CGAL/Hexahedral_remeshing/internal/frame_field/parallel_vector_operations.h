// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PARALLEL_VECTOR_OPERATIONS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PARALLEL_VECTOR_OPERATIONS_H

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Dot products and vector updates of the iterative solvers (conjugate gradients, L-BFGS), in
// parallel and still independent of the number of threads: a reduction sums fixed blocks of
// `vector_block` entries, then the blocks' sums in block order, so its rounding depends on the
// length only. Eigen evaluates them on one thread, which on a million tetrahedra left the second
// core idle for a third of the smoothing (measured at 200k tets: 10 % of all samples in the L-BFGS
// recursion's vector operations). Below `parallel_vector_minimum` entries Eigen's own (and its
// rounding) is kept: threads cost more there than they save, and small meshes keep their results.
constexpr Eigen::Index vector_block = 8192;
constexpr Eigen::Index parallel_vector_minimum = Eigen::Index(1) << 18;

inline bool use_parallel_vector_operations(Eigen::Index n) { return n >= parallel_vector_minimum; }

// dots[i] = u . v[i] for every i, in one pass over u.
inline void parallel_dots(const Eigen::VectorXd& u, const std::vector<const Eigen::VectorXd*>& v, std::vector<double>& dots)
{
  const std::size_t k = v.size();
  dots.assign(k, 0.);
  if(k == 0) return;
  const Eigen::Index n = u.size();
  if(!use_parallel_vector_operations(n)) {
    for(std::size_t i = 0; i < k; ++i) dots[i] = u.dot(*v[i]);
    return;
  }
  const Eigen::Index blocks = (n + vector_block - 1) / vector_block;
  std::vector<double> partial(std::size_t(blocks) * k);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
  for(Eigen::Index b = 0; b < blocks; ++b) {
    const Eigen::Index begin = b * vector_block, size = (std::min)(vector_block, n - begin);
    for(std::size_t i = 0; i < k; ++i)
      partial[std::size_t(b) * k + i] = u.segment(begin, size).dot(v[i]->segment(begin, size));
  }
  for(Eigen::Index b = 0; b < blocks; ++b)
    for(std::size_t i = 0; i < k; ++i) dots[i] += partial[std::size_t(b) * k + i];
}

inline double parallel_dot(const Eigen::VectorXd& u, const Eigen::VectorXd& v)
{
  std::vector<double> d;
  parallel_dots(u, {&v}, d);
  return d[0];
}

// Calls f(begin, size) on consecutive segments covering [0, n), in parallel when n is large.
template <class F>
void for_each_segment(Eigen::Index n, const F& f)
{
  if(!use_parallel_vector_operations(n)) {
    f(Eigen::Index(0), n);
    return;
  }
  const Eigen::Index blocks = (n + vector_block - 1) / vector_block;
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
  for(Eigen::Index b = 0; b < blocks; ++b) f(b * vector_block, (std::min)(vector_block, n - b * vector_block));
}

// Sum of f(begin, size) over the same segments, in segment order: a reduction fused with updates.
template <class F>
double parallel_segment_sum(Eigen::Index n, const F& f)
{
  if(!use_parallel_vector_operations(n)) return f(Eigen::Index(0), n);
  const Eigen::Index blocks = (n + vector_block - 1) / vector_block;
  std::vector<double> partial(std::size_t(blocks), 0.);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
  for(Eigen::Index b = 0; b < blocks; ++b)
    partial[std::size_t(b)] = f(b * vector_block, (std::min)(vector_block, n - b * vector_block));
  double sum = 0;
  for(double p : partial) sum += p;
  return sum;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PARALLEL_VECTOR_OPERATIONS_H
