// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_AGGREGATION_MULTIGRID_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_AGGREGATION_MULTIGRID_H

#include <CGAL/Hexahedral_remeshing/internal/frame_field/parallel_vector_operations.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Signed permutation of 9 components: (M v)[i] = sign[i] v[perm[i]]. The matchings act on the
// 9 unknowns of a tet as such (a frame times one of the 24 rotations permutes its columns).
struct Signed_permutation_9
{
  std::array<std::uint8_t, 9> perm;
  std::array<std::int8_t, 9> sign; // 18 bytes: one per tet and level

  static Signed_permutation_9 identity()
  {
    Signed_permutation_9 p;
    for(int i = 0; i < 9; ++i) { p.perm[i] = std::uint8_t(i); p.sign[i] = 1; }
    return p;
  }
  Signed_permutation_9 transpose() const
  {
    Signed_permutation_9 t;
    for(int i = 0; i < 9; ++i) { t.perm[perm[i]] = std::uint8_t(i); t.sign[perm[i]] = sign[i]; }
    return t;
  }
  // (a b v)[i] = a.sign[i] (b v)[a.perm[i]]
  friend Signed_permutation_9 operator*(const Signed_permutation_9& a, const Signed_permutation_9& b)
  {
    Signed_permutation_9 c;
    for(int i = 0; i < 9; ++i) { c.perm[i] = b.perm[a.perm[i]]; c.sign[i] = std::int8_t(a.sign[i] * b.sign[a.perm[i]]); }
    return c;
  }
  Eigen::Matrix<double, 9, 9> matrix() const
  {
    Eigen::Matrix<double, 9, 9> m = Eigen::Matrix<double, 9, 9>::Zero();
    for(int i = 0; i < 9; ++i) m(i, perm[i]) = sign[i];
    return m;
  }
};

// E -> E g on the column-major entries of a 3x3 matrix E, g a signed permutation matrix.
inline Signed_permutation_9 right_multiplication(const Eigen::Matrix3d& g)
{
  Signed_permutation_9 p;
  for(int j = 0; j < 3; ++j)
    for(int k = 0; k < 3; ++k)
      if(g(k, j) != 0)
        for(int i = 0; i < 3; ++i) { p.perm[i + 3 * j] = std::uint8_t(i + 3 * k); p.sign[i + 3 * j] = g(k, j) > 0 ? 1 : -1; }
  return p;
}

// The fine system of both frame-field solves: the energy
//   sum_f w_f |q_s - M_f q_t|^2 + mu sum_t |q_t|^2,  (s, t) the two tets of interior face f,
// in the reduced unknowns x_t of each tet, q_t = Q_t x_t with Q_t = I (9 unknowns), a 9 x d
// matrix with orthonormal columns (d unknowns, the exactly eliminated boundary constraint) or
// nothing (a fixed tet). M_f is a signed permutation: the identity for the relaxation, the
// matching for the realignment.
struct Multigrid_fine_system
{
  typedef std::uint32_t Index;
  static constexpr Index none = Index(-1);
  std::size_t number_of_tets = 0;
  const std::vector<std::array<Index, 2> >* face_tets = nullptr;
  const std::vector<double>* face_weight = nullptr;
  const std::vector<std::array<Index, 4> >* tet_faces = nullptr; // interior faces of each tet, or none
  std::vector<Signed_permutation_9> face_rotation;              // empty: every M_f is the identity
  std::vector<std::size_t> offset;                              // x_t = x[offset[t], offset[t + 1])
  std::vector<std::size_t> embedding;                           // per tet with 0 < d < 9: Q_t (9 x d, column-major)
  std::vector<double> embeddings;                               //   at embeddings.data() + embedding[t],
  static constexpr std::size_t leading_identity = std::size_t(-1); // or, as embedding[t], the first d columns of I
  Eigen::Map<const Eigen::Matrix<double, 9, Eigen::Dynamic> > Q(std::size_t t) const
  {
    return Eigen::Map<const Eigen::Matrix<double, 9, Eigen::Dynamic> >(embeddings.data() + embedding[t], 9,
                                                                        Eigen::Index(offset[t + 1] - offset[t]));
  }
  double mu = 0;
  std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)> apply; // y = A x, matrix-free
};

// How the coarse levels are visited. V: once per level, a linear and symmetric preconditioner
// (what L-BFGS needs of its initial inverse Hessian). K: each coarse level's correction is two
// flexible conjugate-gradient iterations preconditioned by the level's own cycle (Notay's K-cycle,
// as in AGMG), so the conjugate gradients around it must be flexible too; with plain aggregation
// the V-cycle's outer iterations grow with the number of levels, the K-cycle's hardly (relaxation
// and realignment of a 502k-tet cylinder: 41 -> 20 and 56 -> 22 iterations).
enum class Multigrid_cycle { V, K };

// Aggregation multigrid preconditioner (one symmetric V-cycle or a K-cycle) for the system above, so that the
// conjugate gradients need a number of iterations that hardly grows with the mesh, where Jacobi
// needs about the cube root of the number of tets (the diameter of the dual graph).
// Unsmoothed aggregation (Vanek, Mandel and Brezina 1996; as in Notay's AGMG, 2010) adapted to
// frames: coarse unknowns are one 9-vector per aggregate (greedy aggregation: a seed with its free
// neighbours and, on the tets, their free neighbours too; every node left joins its strongest
// aggregated neighbour); a tet of aggregate A sees q_t = Q_t Q_t^T G_t xi_A, where the gauge G_t transports
// the aggregate's unknowns to the tet's chart along the tree the aggregate grew by (the matchings
// differ from tet to tet, the constant of the coarse space must not). Coarse operators are the
// Galerkin products P^T A P, assembled row-wise per aggregate (parallel and deterministic);
// smoothing is l1-Jacobi (convergent without a damping parameter) on the coarse levels and
// Jacobi damped by 2/3 on the fine one; the coarsest level is solved by a sparse LDL^T.
// Fine-level work is matrix-free; each coarse level stores only its non-zero entries (the
// signed permutations of interior blocks give 9 of 81), so memory stays a fraction of the fine
// operator's.
class Aggregation_multigrid
{
public:
  typedef std::uint32_t Index;
  static constexpr Index none = Index(-1);

  Aggregation_multigrid(Multigrid_fine_system fine, Multigrid_cycle cycle) : m_fine(std::move(fine)), m_cycle(cycle)
  {
    const std::size_t nt = m_fine.number_of_tets;
    m_degree.assign(nt, 0.);
    for(std::size_t t = 0; t < nt; ++t)
      for(Index f : (*m_fine.tet_faces)[t])
        if(f != none) m_degree[t] += (*m_fine.face_weight)[f];
    // damped Jacobi: the diagonal of the fine operator is (degree + mu) I
    m_inverse_diagonal.resize(nt);
    for(std::size_t t = 0; t < nt; ++t)
      m_inverse_diagonal[t] = m_degree[t] + m_fine.mu > 0 ? (2.0 / 3.0) / (m_degree[t] + m_fine.mu) : 0.0;
    build_first_level();
    while(m_levels.back().nodes > 200 && m_levels.size() < 12) {
      const std::size_t before = m_levels.back().nodes;
      build_next_level();
      if(m_levels.back().nodes * 10 > before * 8) break; // no longer coarsening
    }
    factorize_coarsest();
  }

  std::size_t number_of_levels() const { return m_levels.size() + 1; }
  std::size_t coarse_nodes(std::size_t level) const { return m_levels[level - 1].nodes; }
  std::size_t coarse_nonzeros(std::size_t level) const { return m_levels[level - 1].A.value.size(); }

  // z = M^-1 r: one V-cycle from zero.
  void operator()(const Eigen::VectorXd& r, Eigen::VectorXd& z) const
  {
    const Eigen::Index n = r.size();
    z.resize(n);
    const std::size_t nt = m_fine.number_of_tets;
    // pre-smoothing from zero
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t t = 0; t < std::ptrdiff_t(nt); ++t)
      for(std::size_t k = m_fine.offset[t]; k < m_fine.offset[t + 1]; ++k)
        z[Eigen::Index(k)] = m_inverse_diagonal[t] * r[Eigen::Index(k)];
    const Level& c = m_levels.front();
    if(c.nodes == 0) return;
    m_fine.apply(z, m_fine_work);
    for_each_segment(n, [&](Eigen::Index b, Eigen::Index size) {
      m_fine_work.segment(b, size) = r.segment(b, size) - m_fine_work.segment(b, size);
    });
    restrict_from_fine(m_fine_work, c.b);
    coarse_correction(0);
    prolong_to_fine(c.x, z);
    // post-smoothing
    m_fine.apply(z, m_fine_work);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t t = 0; t < std::ptrdiff_t(nt); ++t)
      for(std::size_t k = m_fine.offset[t]; k < m_fine.offset[t + 1]; ++k)
        z[Eigen::Index(k)] += m_inverse_diagonal[t] * (r[Eigen::Index(k)] - m_fine_work[Eigen::Index(k)]);
  }

private:
  typedef Eigen::Matrix<double, 9, 9> Matrix9;
  typedef Eigen::Matrix<double, 9, 1> Vector9;

  struct Csr
  {
    std::vector<std::size_t> start;
    std::vector<Index> column;
    std::vector<double> value;
    void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const
    {
      const std::ptrdiff_t rows = std::ptrdiff_t(start.size()) - 1;
      y.resize(rows);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
      for(std::ptrdiff_t i = 0; i < rows; ++i) {
        double s = 0;
        for(std::size_t k = start[i]; k < start[i + 1]; ++k) s += value[k] * x[Eigen::Index(column[k])];
        y[i] = s;
      }
    }
  };

  // A coarse level: its matrix, and how the nodes of the level above (tets for the first) map to it.
  struct Level
  {
    std::size_t nodes = 0;
    Csr A;
    Eigen::VectorXd inv_l1;
    std::vector<Index> parent;                // per child node: its aggregate here, or none
    std::vector<Signed_permutation_9> gauge;  // per child node: xi_child = gauge xi_parent
    std::vector<std::size_t> member_start;    // children of each node
    std::vector<Index> members;
    mutable Eigen::VectorXd b, x, work;
    mutable Eigen::VectorXd k_rhs, k_v, k_w; // K-cycle
  };

  struct Aggregation
  {
    std::vector<Index> parent;
    std::vector<Index> attached_to; // the node it joined through (itself for a seed)
    std::vector<Index> order;       // the nodes with a parent, each after the node it is attached to
    std::size_t count = 0;
  };

  // Greedy aggregation. neighbours(i, f) calls f(j, strength) for each neighbour j of node i.
  // A seed is a node whose neighbours are all free: it takes them, and with radius 2 their free
  // neighbours too; every node left joins the aggregate of its strongest neighbour of that pass.
  template <class Active, class Neighbours>
  static Aggregation aggregate(std::size_t n, const Active& active, const Neighbours& neighbours, int radius)
  {
    Aggregation a;
    a.parent.assign(n, none);
    a.attached_to.assign(n, none);
    std::vector<Index> ring;
    for(std::size_t i = 0; i < n; ++i) {
      if(!active(i) || a.parent[i] != none) continue;
      bool free = true;
      neighbours(i, [&](std::size_t j, double) { if(a.parent[j] != none) free = false; });
      if(!free) continue;
      const Index id = Index(a.count++);
      a.parent[i] = id;
      a.attached_to[i] = Index(i);
      a.order.push_back(Index(i));
      ring.clear();
      neighbours(i, [&](std::size_t j, double) {
        a.parent[j] = id; a.attached_to[j] = Index(i); a.order.push_back(Index(j)); ring.push_back(Index(j));
      });
      if(radius > 1)
        for(Index j : ring)
          neighbours(j, [&](std::size_t k, double) {
            if(a.parent[k] == none) { a.parent[k] = id; a.attached_to[k] = j; a.order.push_back(Index(k)); }
          });
    }
    const std::vector<Index> first_pass = a.parent;
    for(std::size_t i = 0; i < n; ++i) {
      if(!active(i) || a.parent[i] != none) continue;
      double best = -1;
      std::size_t to = i;
      neighbours(i, [&](std::size_t j, double s) {
        if(first_pass[j] != none && s > best) { best = s; to = j; }
      });
      if(to == i) { a.parent[i] = Index(a.count++); a.attached_to[i] = Index(i); }
      else { a.parent[i] = first_pass[to]; a.attached_to[i] = Index(to); }
      a.order.push_back(Index(i));
    }
    return a;
  }

  static void set_members(Level& level, std::size_t children)
  {
    level.member_start.assign(level.nodes + 1, 0);
    for(std::size_t c = 0; c < children; ++c)
      if(level.parent[c] != none) ++level.member_start[level.parent[c] + 1];
    for(std::size_t a = 0; a < level.nodes; ++a) level.member_start[a + 1] += level.member_start[a];
    level.members.resize(level.member_start.back());
    std::vector<std::size_t> next(level.member_start.begin(), level.member_start.end() - 1);
    for(std::size_t c = 0; c < children; ++c)
      if(level.parent[c] != none) level.members[next[level.parent[c]]++] = Index(c);
  }

  std::size_t dofs(std::size_t t) const { return m_fine.offset[t + 1] - m_fine.offset[t]; }

  // M with q_t ~ M q_u across interior face f of tet t (u the other tet).
  Signed_permutation_9 rotation_from(Index f, std::size_t t) const
  {
    if(m_fine.face_rotation.empty()) return Signed_permutation_9::identity();
    return (*m_fine.face_tets)[f][0] == t ? m_fine.face_rotation[f] : m_fine.face_rotation[f].transpose();
  }

  typedef Eigen::Matrix<double, 9, Eigen::Dynamic, 0, 9, 9> Matrix9xd;

  // Q_t (9 x d), or the identity for a tet with 9 unknowns.
  Matrix9xd embedding_of(std::size_t t) const
  {
    const std::size_t d = dofs(t);
    if(d == 9) return Matrix9::Identity();
    if(m_fine.embedding[t] == Multigrid_fine_system::leading_identity) return Matrix9xd::Identity(9, Eigen::Index(d));
    return m_fine.Q(t);
  }

  // U = G^T Q_t: a coarse vector xi reaches the tet's unknowns as x_t = U^T xi.
  static Matrix9xd lift(const Signed_permutation_9& G, const Matrix9xd& Q)
  {
    Matrix9xd U(9, Q.cols());
    for(int i = 0; i < 9; ++i) U.row(G.perm[i]) = G.sign[i] * Q.row(i);
    return U;
  }

  static Matrix9& block(std::vector<std::pair<Index, Matrix9> >& blocks, Index node)
  {
    for(auto& b : blocks)
      if(b.first == node) return b.second;
    blocks.push_back({node, Matrix9::Zero()});
    return blocks.back().second;
  }

  // Fills level.A from per-node dense blocks computed by row_of(node, blocks), in parallel, in two
  // passes (count, then fill): computing the blocks twice is cheaper than holding every row twice.
  template <class RowOf>
  static void assemble(Level& level, const RowOf& row_of)
  {
    Csr& A = level.A;
    const std::size_t rows = 9 * level.nodes;
    A.start.assign(rows + 1, 0);
    auto node_blocks = [&](std::size_t a, std::vector<std::pair<Index, Matrix9> >& blocks) {
      blocks.clear();
      row_of(a, blocks);
      std::sort(blocks.begin(), blocks.end(), [](const std::pair<Index, Matrix9>& x, const std::pair<Index, Matrix9>& y) { return x.first < y.first; });
    };
    for(int pass = 0; pass < 2; ++pass) {
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 64)
#endif
      for(std::ptrdiff_t a = 0; a < std::ptrdiff_t(level.nodes); ++a) {
        std::vector<std::pair<Index, Matrix9> > blocks;
        node_blocks(std::size_t(a), blocks);
        for(std::size_t i = 9 * std::size_t(a); i < 9 * std::size_t(a) + 9; ++i) {
          std::size_t k = pass == 0 ? 0 : A.start[i];
          for(const auto& blk : blocks)
            for(int j = 0; j < 9; ++j) {
              const double v = blk.second(int(i % 9), j);
              if(v == 0) continue;
              if(pass == 1) { A.column[k] = Index(9 * blk.first + j); A.value[k] = v; }
              ++k;
            }
          if(pass == 0) A.start[i + 1] = k;
        }
      }
      if(pass == 0) {
        for(std::size_t i = 0; i < rows; ++i) A.start[i + 1] += A.start[i];
        A.column.resize(A.start.back());
        A.value.resize(A.start.back());
      }
    }
    level.inv_l1.resize(Eigen::Index(rows));
    for(std::size_t i = 0; i < rows; ++i) {
      double l1 = 0;
      for(std::size_t k = A.start[i]; k < A.start[i + 1]; ++k) l1 += std::abs(A.value[k]);
      level.inv_l1[Eigen::Index(i)] = l1 > 0 ? 1.0 / l1 : 0.0;
    }
  }

  void build_first_level()
  {
    const std::size_t nt = m_fine.number_of_tets;
    const auto& tet_faces = *m_fine.tet_faces;
    const auto& face_tets = *m_fine.face_tets;
    const auto& weight = *m_fine.face_weight;
    auto other = [&](Index f, std::size_t t) { return std::size_t(face_tets[f][0] == t ? face_tets[f][1] : face_tets[f][0]); };
    auto active = [&](std::size_t t) { return dofs(t) > 0; };
    auto neighbours = [&](std::size_t t, const std::function<void(std::size_t, double)>& f) {
      for(Index fi : tet_faces[t])
        if(fi != none && active(other(fi, t))) f(other(fi, t), weight[fi]);
    };
    Aggregation agg = aggregate(nt, active, neighbours, 2);
    m_levels.emplace_back();
    Level& level = m_levels.back();
    level.nodes = agg.count;
    level.parent = std::move(agg.parent);
    // gauges: seeds first, then their neighbours, then the tets of the second pass
    level.gauge.assign(nt, Signed_permutation_9::identity());
    if(!m_fine.face_rotation.empty()) {
      auto face_between = [&](std::size_t t, std::size_t u) {
        for(Index fi : tet_faces[t])
          if(fi != none && other(fi, t) == u) return fi;
        return none;
      };
      for(const Index t : agg.order) {
        const std::size_t from = agg.attached_to[t];
        if(from == t) continue;
        // q_from ~ M q_t and q = G xi in both: G_t = M^T G_from
        level.gauge[t] = rotation_from(face_between(from, t), from).transpose() * level.gauge[from];
      }
    }
    set_members(level, nt);
    // With U_t = G_t^T Q_t, face f between s and t (q_s ~ M q_t) adds w U_s U_s^T and
    // -w U_s (Q_s^T M Q_t) U_t^T to the row of s's aggregate: small products of the reduced sizes;
    // a signed permutation alone between two tets with 9 unknowns each.
    assemble(level, [&](std::size_t a, std::vector<std::pair<Index, Matrix9> >& blocks) {
      for(std::size_t k = level.member_start[a]; k < level.member_start[a + 1]; ++k) {
        const std::size_t s = level.members[k];
        const bool free_s = dofs(s) == 9;
        const Matrix9xd Q_s = embedding_of(s);
        const Matrix9xd U_s = lift(level.gauge[s], Q_s);
        block(blocks, Index(a)) += (m_fine.mu + m_degree[s]) * (U_s * U_s.transpose());
        for(Index fi : tet_faces[s]) {
          if(fi == none) continue;
          const std::size_t t = other(fi, s);
          if(dofs(t) == 0) continue;
          const double w = weight[fi];
          const Signed_permutation_9 M = rotation_from(fi, s);
          const Index b = level.parent[t];
          if(free_s && dofs(t) == 9) {
            const Signed_permutation_9 R = level.gauge[s].transpose() * M * level.gauge[t];
            Matrix9& off = block(blocks, b);
            for(int i = 0; i < 9; ++i) off(i, R.perm[i]) -= w * R.sign[i];
          } else {
            const Matrix9xd Q_t = embedding_of(t);
            Matrix9xd MQ_t(9, Q_t.cols());
            for(int i = 0; i < 9; ++i) MQ_t.row(i) = M.sign[i] * Q_t.row(M.perm[i]);
            const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 9, 9> C = Q_s.transpose() * MQ_t;
            block(blocks, b) -= w * (U_s * C) * lift(level.gauge[t], Q_t).transpose();
          }
        }
      }
    });
  }

  // Dominant signed permutation R of a coupling block C ~ -w R, or the identity.
  static Signed_permutation_9 dominant_rotation(const Matrix9& C)
  {
    Signed_permutation_9 R;
    std::array<bool, 9> used{};
    for(int i = 0; i < 9; ++i) {
      Eigen::Index j = 0;
      if(C.row(i).cwiseAbs().maxCoeff(&j) == 0 || used[j]) return Signed_permutation_9::identity();
      used[j] = true;
      R.perm[i] = std::uint8_t(j);
      R.sign[i] = C(i, j) < 0 ? 1 : -1;
    }
    return R;
  }

  Matrix9 coupling(const Level& level, std::size_t i, std::size_t j) const
  {
    Matrix9 C = Matrix9::Zero();
    for(int r = 0; r < 9; ++r)
      for(std::size_t k = level.A.start[9 * i + r]; k < level.A.start[9 * i + r + 1]; ++k)
        if(level.A.column[k] / 9 == j) C(r, level.A.column[k] % 9) = level.A.value[k];
    return C;
  }

  void build_next_level()
  {
    const Level& fine = m_levels.back();
    const std::size_t n = fine.nodes;
    auto active = [](std::size_t) { return true; };
    auto neighbours = [&](std::size_t i, const std::function<void(std::size_t, double)>& f) {
      // strength: sum of |entries| of the coupling block, nodes in increasing order
      std::vector<std::pair<Index, double> > s;
      for(std::size_t r = 9 * i; r < 9 * i + 9; ++r)
        for(std::size_t k = fine.A.start[r]; k < fine.A.start[r + 1]; ++k) {
          const Index j = fine.A.column[k] / 9;
          if(j == i) continue;
          auto it = std::find_if(s.begin(), s.end(), [&](const std::pair<Index, double>& e) { return e.first == j; });
          if(it == s.end()) s.push_back({j, std::abs(fine.A.value[k])});
          else it->second += std::abs(fine.A.value[k]);
        }
      std::sort(s.begin(), s.end());
      for(const auto& e : s) f(e.first, e.second);
    };
    Aggregation agg = aggregate(n, active, neighbours, 1);
    Level next;
    next.nodes = agg.count;
    next.parent = std::move(agg.parent);
    next.gauge.assign(n, Signed_permutation_9::identity());
    if(!m_fine.face_rotation.empty())
      for(const Index i : agg.order) {
        const std::size_t from = agg.attached_to[i];
        if(from == i) continue;
        // xi_from ~ R xi_i, both = H xi: H_i = R^T H_from
        next.gauge[i] = dominant_rotation(coupling(fine, from, i)).transpose() * next.gauge[from];
      }
    set_members(next, n);
    assemble(next, [&](std::size_t a, std::vector<std::pair<Index, Matrix9> >& blocks) {
      for(std::size_t k = next.member_start[a]; k < next.member_start[a + 1]; ++k) {
        const std::size_t c = next.members[k];
        const Signed_permutation_9& Hc = next.gauge[c];
        for(int r = 0; r < 9; ++r)
          for(std::size_t e = fine.A.start[9 * c + r]; e < fine.A.start[9 * c + r + 1]; ++e) {
            const std::size_t d = fine.A.column[e] / 9;
            const int col = int(fine.A.column[e] % 9);
            const Signed_permutation_9& Hd = next.gauge[d];
            block(blocks, next.parent[d])(Hc.perm[r], Hd.perm[col]) += Hc.sign[r] * Hd.sign[col] * fine.A.value[e];
          }
      }
    });
    m_levels.push_back(std::move(next));
  }

  void factorize_coarsest()
  {
    const Level& c = m_levels.back();
    const Eigen::Index n = Eigen::Index(9 * c.nodes);
    std::vector<Eigen::Triplet<double> > triplets;
    double max_diagonal = 0;
    for(Eigen::Index i = 0; i < n; ++i)
      for(std::size_t k = c.A.start[i]; k < c.A.start[i + 1]; ++k) {
        triplets.emplace_back(i, Eigen::Index(c.A.column[k]), c.A.value[k]);
        if(Eigen::Index(c.A.column[k]) == i) max_diagonal = (std::max)(max_diagonal, c.A.value[k]);
      }
    // the rows a constrained tet alone leaves empty, and the constant of a field without any
    // constraint, are null: a tiny shift keeps the factorization definite
    for(Eigen::Index i = 0; i < n; ++i) triplets.emplace_back(i, i, 1e-10 * (max_diagonal > 0 ? max_diagonal : 1.0));
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(triplets.begin(), triplets.end());
    m_coarsest.compute(A);
    m_coarsest_ok = m_coarsest.info() == Eigen::Success;
  }

  void restrict_from_fine(const Eigen::VectorXd& r, Eigen::VectorXd& b) const
  {
    const Level& c = m_levels.front();
    b.setZero(Eigen::Index(9 * c.nodes));
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t a = 0; a < std::ptrdiff_t(c.nodes); ++a) {
      Vector9 sum = Vector9::Zero();
      for(std::size_t k = c.member_start[a]; k < c.member_start[a + 1]; ++k) {
        const std::size_t t = c.members[k];
        const std::size_t d = dofs(t);
        Vector9 u;
        if(d == 9) u = r.segment<9>(Eigen::Index(m_fine.offset[t]));
        else if(m_fine.embedding[t] == Multigrid_fine_system::leading_identity) {
          u.setZero();
          for(std::size_t j = 0; j < d; ++j) u[Eigen::Index(j)] = r[Eigen::Index(m_fine.offset[t] + j)];
        } else {
          // written out: Eigen's dynamic-size product costs more than the product itself here
          const double* Q = m_fine.embeddings.data() + m_fine.embedding[t];
          const double* x = r.data() + m_fine.offset[t];
          u.setZero();
          for(std::size_t j = 0; j < d; ++j)
            for(int i = 0; i < 9; ++i) u[i] += Q[9 * j + std::size_t(i)] * x[j];
        }
        const Signed_permutation_9& G = c.gauge[t];
        for(int i = 0; i < 9; ++i) sum[G.perm[i]] += G.sign[i] * u[i]; // G^T u
      }
      b.segment<9>(9 * a) = sum;
    }
  }

  void prolong_to_fine(const Eigen::VectorXd& xi, Eigen::VectorXd& z) const
  {
    const Level& c = m_levels.front();
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t ti = 0; ti < std::ptrdiff_t(m_fine.number_of_tets); ++ti) {
      const std::size_t t = std::size_t(ti);
      const std::size_t d = dofs(t);
      if(d == 0) continue;
      const Signed_permutation_9& G = c.gauge[t];
      const Eigen::Index a = Eigen::Index(c.parent[t]);
      Vector9 v;
      for(int i = 0; i < 9; ++i) v[i] = G.sign[i] * xi[9 * a + G.perm[i]];
      if(d == 9) z.segment<9>(Eigen::Index(m_fine.offset[t])) += v;
      else if(m_fine.embedding[t] == Multigrid_fine_system::leading_identity) {
        for(std::size_t j = 0; j < d; ++j) z[Eigen::Index(m_fine.offset[t] + j)] += v[Eigen::Index(j)];
      } else {
        const double* Q = m_fine.embeddings.data() + m_fine.embedding[t];
        double* y = z.data() + m_fine.offset[t];
        for(std::size_t j = 0; j < d; ++j) {
          double s = 0;
          for(int i = 0; i < 9; ++i) s += Q[9 * j + std::size_t(i)] * v[i];
          y[j] += s;
        }
      }
    }
  }

  // x = approximately A_j^-1 b on coarse level j: one cycle there, or with the K-cycle two
  // flexible conjugate-gradient iterations preconditioned by it (Notay and Vassilevski 2008; the
  // second one only if the first left more than a quarter of the residual, as in AGMG).
  void coarse_correction(std::size_t j) const
  {
    if(m_cycle == Multigrid_cycle::V || j + 1 == m_levels.size()) { cycle(j); return; }
    const Level& L = m_levels[j];
    L.k_rhs = L.b;
    cycle(j);
    L.k_v = L.x;
    L.A.multiply(L.k_v, L.k_w);
    const double rho1 = parallel_dot(L.k_v, L.k_w), alpha1 = parallel_dot(L.k_v, L.k_rhs);
    if(!(rho1 > 0)) return;
    const double a1 = alpha1 / rho1;
    L.b = L.k_rhs - a1 * L.k_w;
    if(parallel_dot(L.b, L.b) <= 0.0625 * parallel_dot(L.k_rhs, L.k_rhs)) { L.x = a1 * L.k_v; return; }
    cycle(j); // L.x = the cycle applied to the residual L.b
    L.A.multiply(L.x, L.work);
    const double gamma = parallel_dot(L.x, L.k_w), beta = parallel_dot(L.x, L.work);
    const double alpha2 = parallel_dot(L.x, L.b), rho2 = beta - gamma * gamma / rho1;
    if(!(rho2 > 0)) { L.x = a1 * L.k_v; return; }
    L.x = (alpha2 / rho2) * L.x + (a1 - gamma * alpha2 / (rho1 * rho2)) * L.k_v;
  }

  // V-cycle on coarse level k: x = approximately A_k^-1 b.
  void cycle(std::size_t k) const
  {
    const Level& L = m_levels[k];
    if(k + 1 == m_levels.size()) {
      if(m_coarsest_ok) L.x = m_coarsest.solve(L.b);
      else {
        L.x = L.inv_l1.cwiseProduct(L.b);
        for(int s = 0; s < 20; ++s) { L.A.multiply(L.x, L.work); L.x += L.inv_l1.cwiseProduct(L.b - L.work); }
      }
      return;
    }
    // l1-Jacobi sweeps x += D^-1 (b - A x), from x = D^-1 b; elementwise updates, so the same in parallel
    const int sweeps = 2;
    const Eigen::Index rows = Eigen::Index(9 * L.nodes);
    auto sweep = [&]() {
      L.A.multiply(L.x, L.work);
      for_each_segment(rows, [&](Eigen::Index b, Eigen::Index size) {
        L.x.segment(b, size) += L.inv_l1.segment(b, size).cwiseProduct(L.b.segment(b, size) - L.work.segment(b, size));
      });
    };
    L.x.resize(rows);
    for_each_segment(rows, [&](Eigen::Index b, Eigen::Index size) {
      L.x.segment(b, size) = L.inv_l1.segment(b, size).cwiseProduct(L.b.segment(b, size));
    });
    for(int s = 1; s < sweeps; ++s) sweep();
    L.A.multiply(L.x, L.work);
    for_each_segment(rows, [&](Eigen::Index b, Eigen::Index size) {
      L.work.segment(b, size) = L.b.segment(b, size) - L.work.segment(b, size);
    });
    // restriction, gathered per aggregate over its members in increasing order (as a scatter in
    // node order would add them), so in parallel
    const Level& C = m_levels[k + 1];
    C.b.resize(Eigen::Index(9 * C.nodes));
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t a = 0; a < std::ptrdiff_t(C.nodes); ++a) {
      Vector9 sum = Vector9::Zero();
      for(std::size_t m = C.member_start[a]; m < C.member_start[a + 1]; ++m) {
        const std::size_t i = C.members[m];
        const Signed_permutation_9& H = C.gauge[i];
        for(int r = 0; r < 9; ++r) sum[H.perm[r]] += H.sign[r] * L.work[9 * Eigen::Index(i) + r];
      }
      C.b.segment<9>(9 * a) = sum;
    }
    coarse_correction(k + 1);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for(std::ptrdiff_t i = 0; i < std::ptrdiff_t(L.nodes); ++i) {
      const Signed_permutation_9& H = C.gauge[i];
      for(int r = 0; r < 9; ++r) L.x[9 * i + r] += H.sign[r] * C.x[9 * Eigen::Index(C.parent[i]) + H.perm[r]];
    }
    for(int s = 0; s < sweeps; ++s) sweep();
  }

  Multigrid_fine_system m_fine;
  Multigrid_cycle m_cycle;
  std::vector<double> m_degree;
  std::vector<Level> m_levels;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > m_coarsest;
  bool m_coarsest_ok = false;
  std::vector<double> m_inverse_diagonal;
  mutable Eigen::VectorXd m_fine_work;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_AGGREGATION_MULTIGRID_H
