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

// sums[i] = the sum over consecutive segments covering [0, n) of the i-th of the k sums that
// f(begin, size, out) writes to out[0..k), in parallel over the segments, then summed in segment order.
template <class F>
void parallel_block_sums(Eigen::Index n, std::size_t k, const F& f, std::vector<double>& sums)
{
  sums.assign(k, 0.);
  const Eigen::Index blocks = (n + vector_block - 1) / vector_block;
  std::vector<double> partial(std::size_t(blocks) * k);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
  for(Eigen::Index b = 0; b < blocks; ++b)
    f(b * vector_block, (std::min)(vector_block, n - b * vector_block), &partial[std::size_t(b) * k]);
  for(Eigen::Index b = 0; b < blocks; ++b)
    for(std::size_t i = 0; i < k; ++i) sums[i] += partial[std::size_t(b) * k + i];
}

// dots[i] = u . v[i] for every i, in one pass over u.
inline void parallel_dots(const Eigen::VectorXd& u, const std::vector<const Eigen::VectorXd*>& v, std::vector<double>& dots)
{
  const std::size_t k = v.size();
  if(!use_parallel_vector_operations(u.size())) {
    dots.assign(k, 0.);
    for(std::size_t i = 0; i < k; ++i) dots[i] = u.dot(*v[i]);
    return;
  }
  parallel_block_sums(u.size(), k, [&](Eigen::Index begin, Eigen::Index size, double* out) {
    for(std::size_t i = 0; i < k; ++i) out[i] = u.segment(begin, size).dot(v[i]->segment(begin, size));
  }, dots);
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
  std::vector<double> sum;
  parallel_block_sums(n, 1, [&](Eigen::Index begin, Eigen::Index size, double* out) { *out = f(begin, size); }, sum);
  return sum[0];
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PARALLEL_VECTOR_OPERATIONS_H
