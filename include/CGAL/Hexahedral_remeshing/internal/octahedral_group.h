// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_OCTAHEDRAL_GROUP_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_OCTAHEDRAL_GROUP_H

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The octahedral group O: the 24 rotations mapping the coordinate axes onto themselves, i.e. the signed
// permutation matrices with det +1.  A frame E (columns = axes) is only defined modulo O (E and E g carry
// the same cross), so matchings between neighbouring frames and the holonomy around an edge are elements
// of O.  They are handled as indices 0..23 so that products around an edge ring are table look-ups and
// comparisons are exact.

// Geometric class of a group element; used to classify the holonomy around an edge (design 2.3).
enum class Octahedral_rotation_class {
  IDENTITY,      // trace 3
  QUARTER_TURN,  // +-90 degrees about a coordinate axis, trace 1
  HALF_TURN,     // 180 degrees about a coordinate axis or a face diagonal, trace -1
  THIRD_TURN     // 120 degrees about a cube diagonal, trace 0
};

class Octahedral_group
{
public:
  static constexpr int size = 24;
  static constexpr int identity_index = 0;

  // Built once on first use; C++11 guarantees a thread-safe initialization of the function-local static.
  static const Octahedral_group& instance()
  {
    static const Octahedral_group group;
    return group;
  }

  const Eigen::Matrix3d& matrix(int g) const { return m_matrices[g]; }

  // Index of matrix(a) * matrix(b).
  int multiply(int a, int b) const { return m_product[a][b]; }

  // Index of matrix(g)^T.
  int inverse(int g) const { return m_inverse[g]; }

  // Signed permutation encoded column by column: column c of matrix(g) is sign(g, c) e_{row(g, c)}.
  int row_of_column(int g, int c) const { return m_row[g][c]; }
  int sign_of_column(int g, int c) const { return m_sign[g][c]; }

  // Index of the group element equal to M up to `tolerance` (max-norm), or -1 if M is not (close to) a
  // signed permutation matrix with det +1.  Rounds each column to its dominant signed axis, so it also
  // accepts products of group matrices carrying floating-point noise.
  int index_of(const Eigen::Matrix3d& M, double tolerance = 1e-6) const
  {
    int key = 0;
    for(int c = 2; c >= 0; --c) {
      int r;
      M.col(c).cwiseAbs().maxCoeff(&r);
      key = key * 6 + 2 * r + (M(r, c) < 0 ? 1 : 0);
    }
    const int g = m_index_of_key[key];
    if(g < 0)
      return -1;
    if((M - m_matrices[g]).cwiseAbs().maxCoeff() > tolerance)
      return -1;
    return g;
  }

  // Rotation angle in [0, pi] of matrix(g): 0, pi/2, 2pi/3 or pi.
  double angle(int g) const { return m_angle[g]; }

  // Unit rotation axis such that matrix(g) = AngleAxis(angle(g), axis(g)); zero for the identity.  A half
  // turn has two valid axes (a and -a): the one whose first non-zero coordinate is positive is returned.
  const Eigen::Vector3d& axis(int g) const { return m_axis[g]; }

  Octahedral_rotation_class rotation_class(int g) const { return m_class[g]; }

private:
  Octahedral_group()
  {
    // Deterministic order: permutations in lexicographic order, then sign patterns (+++ first).
    // The identity permutation with signs +++ is the first element kept, hence index 0 = identity.
    static const int permutations[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    m_index_of_key.fill(-1);
    int n = 0;
    for(const auto& p : permutations) {
      for(int signs = 0; signs < 8; ++signs) {
        Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
        for(int c = 0; c < 3; ++c)
          M(p[c], c) = ((signs >> c) & 1) ? -1. : 1.;
        if(M.determinant() < 0)
          continue;
        m_matrices[n] = M;
        int key = 0;
        for(int c = 2; c >= 0; --c) {
          m_row[n][c] = p[c];
          m_sign[n][c] = ((signs >> c) & 1) ? -1 : 1;
          key = key * 6 + 2 * p[c] + ((signs >> c) & 1);
        }
        m_index_of_key[key] = n;
        ++n;
      }
    }

    // The entries are 0/+-1, so products are exact and the exact look-up cannot fail.
    for(int a = 0; a < size; ++a) {
      for(int b = 0; b < size; ++b)
        m_product[a][b] = index_of(m_matrices[a] * m_matrices[b], 0.);
      m_inverse[a] = index_of(m_matrices[a].transpose(), 0.);
    }

    for(int g = 0; g < size; ++g)
      compute_angle_axis(g);
  }

  void compute_angle_axis(int g)
  {
    constexpr double pi = 3.14159265358979323846;
    const Eigen::Matrix3d& M = m_matrices[g];
    // tr M = 1 + 2 cos(angle) is an integer for a signed permutation: 3, 1, 0 or -1.
    const int trace = static_cast<int>(std::lround(M.trace()));
    // Antisymmetric part (M - M^T)/2 = sin(angle) [axis]_x gives the oriented axis when sin(angle) != 0.
    const Eigen::Vector3d w(M(2, 1) - M(1, 2), M(0, 2) - M(2, 0), M(1, 0) - M(0, 1));
    switch(trace) {
    case 3:
      m_angle[g] = 0.;
      m_axis[g].setZero();
      m_class[g] = Octahedral_rotation_class::IDENTITY;
      break;
    case 1:
      m_angle[g] = 0.5 * pi;
      m_axis[g] = w.normalized();
      m_class[g] = Octahedral_rotation_class::QUARTER_TURN;
      break;
    case 0:
      m_angle[g] = 2. * pi / 3.;
      m_axis[g] = w.normalized();
      m_class[g] = Octahedral_rotation_class::THIRD_TURN;
      break;
    default: {
      // Half turn: M = 2 a a^T - I, so (M + I)/2 = a a^T; any non-zero column is parallel to a.
      const Eigen::Matrix3d A = 0.5 * (M + Eigen::Matrix3d::Identity());
      int c;
      A.colwise().squaredNorm().maxCoeff(&c);
      Eigen::Vector3d a = A.col(c).normalized();
      for(int i = 0; i < 3; ++i) {
        if(a[i] != 0.) {
          if(a[i] < 0)
            a = -a;
          break;
        }
      }
      m_angle[g] = pi;
      m_axis[g] = a;
      m_class[g] = Octahedral_rotation_class::HALF_TURN;
      break;
    }
    }
  }

  std::array<Eigen::Matrix3d, size> m_matrices;
  std::array<std::array<int, size>, size> m_product;
  std::array<int, size> m_inverse;
  std::array<std::array<int, 3>, size> m_row;
  std::array<std::array<int, 3>, size> m_sign;
  std::array<int, 216> m_index_of_key; // key = sum_c (2 row + [sign < 0]) 6^c
  std::array<double, size> m_angle;
  std::array<Eigen::Vector3d, size> m_axis;
  std::array<Octahedral_rotation_class, size> m_class;

};

inline const Octahedral_group& octahedral_group() { return Octahedral_group::instance(); }

// Local axis of frame E (columns = axes) closest to the world direction d: the axis a boundary
// triangle of normal d is aligned with, in the map and in the meshability check.
inline int closest_local_axis(const Eigen::Matrix3d& E, const Eigen::Vector3d& d)
{
  int k;
  (E.transpose() * d).cwiseAbs().maxCoeff(&k);
  return k;
}

struct Octahedral_matching
{
  int index;    // g in 0..23
  double trace; // tr(g^T E_j^T E_i) = 3 - ||E_i - E_j g||_F^2 / 2, in [-3, 3]
};

// Matching between two frames (design 2.2): g = argmin_g ||E_i - E_j g||_F = argmax_g tr(g^T E_j^T E_i),
// so that E_i ~ E_j g.  All 24 candidates are enumerated (robust and cheap); for a signed permutation
// tr(g^T P) = sum_c sign_c P(row_c, c).  Ties keep the lowest index, so the result is deterministic.
inline Octahedral_matching closest_matching(const Eigen::Matrix3d& E_i, const Eigen::Matrix3d& E_j)
{
  const Octahedral_group& group = octahedral_group();
  const Eigen::Matrix3d P = E_j.transpose() * E_i;
  Octahedral_matching best{-1, -std::numeric_limits<double>::infinity()};
  for(int g = 0; g < Octahedral_group::size; ++g) {
    double t = 0.;
    for(int c = 0; c < 3; ++c)
      t += group.sign_of_column(g, c) * P(group.row_of_column(g, c), c);
    if(t > best.trace)
      best = Octahedral_matching{g, t};
  }
  return best;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_OCTAHEDRAL_GROUP_H
