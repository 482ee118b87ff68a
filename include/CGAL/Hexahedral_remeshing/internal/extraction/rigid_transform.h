// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_RIGID_TRANSFORM_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_RIGID_TRANSFORM_H

#include <Eigen/Dense> // before octahedral_group.h, which uses determinant() with Eigen/Core only

#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace extraction {

// x -> R x + t with R in the octahedral group and t integer: a transition between two charts.
// R is applied as a signed permutation (no multiplication), so once the parameters sit on a common
// dyadic grid every application is exact in double precision.
struct Rigid_transform
{
  int rotation = Octahedral_group::identity_index;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  bool is_identity() const { return rotation == Octahedral_group::identity_index && translation.isZero(0.); }
  bool operator==(const Rigid_transform& o) const { return rotation == o.rotation && translation == o.translation; }
  bool operator!=(const Rigid_transform& o) const { return !(*this == o); }
};

inline Eigen::Vector3d rotate(int rotation, const Eigen::Vector3d& x)
{
  const Octahedral_group& g = octahedral_group();
  Eigen::Vector3d y;
  for(int c = 0; c < 3; ++c) y[g.row_of_column(rotation, c)] = g.sign_of_column(rotation, c) * x[c];
  return y;
}

inline Eigen::Vector3d apply(const Rigid_transform& T, const Eigen::Vector3d& x)
{
  return rotate(T.rotation, x) + T.translation;
}

// a o b: first b, then a.
inline Rigid_transform compose(const Rigid_transform& a, const Rigid_transform& b)
{
  Rigid_transform c;
  c.rotation = octahedral_group().multiply(a.rotation, b.rotation);
  c.translation = rotate(a.rotation, b.translation) + a.translation;
  return c;
}

inline Rigid_transform inverse(const Rigid_transform& a)
{
  Rigid_transform c;
  c.rotation = octahedral_group().inverse(a.rotation);
  c.translation = -rotate(c.rotation, a.translation);
  return c;
}

} // namespace extraction
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_RIGID_TRANSFORM_H
