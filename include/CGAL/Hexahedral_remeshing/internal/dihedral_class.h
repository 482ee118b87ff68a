// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_DIHEDRAL_CLASS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_DIHEDRAL_CLASS_H

#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/number_utils.h>

#include <array>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// s = <n_i x n_j, e>, c = <n_i, n_j> and |e|^2 for the edge p -> q of the triangles (p, q, a) and
// (q, p, b) given by the 12 coordinates, evaluated in the number type FT (intervals or exact).
template <class FT>
void dihedral_polynomials(const std::array<double, 12>& xyz, FT& s, FT& c, FT& e2)
{
  const FT px(xyz[0]), py(xyz[1]), pz(xyz[2]);
  const FT qx(xyz[3]), qy(xyz[4]), qz(xyz[5]);
  const FT ax(xyz[6]), ay(xyz[7]), az(xyz[8]);
  const FT bx(xyz[9]), by(xyz[10]), bz(xyz[11]);
  // e = q - p, n_i = e x (a - p), n_j = (p - q) x (b - q)
  const FT ex = qx - px, ey = qy - py, ez = qz - pz;
  const FT apx = ax - px, apy = ay - py, apz = az - pz;
  const FT bqx = bx - qx, bqy = by - qy, bqz = bz - qz;
  const FT nix = ey * apz - ez * apy, niy = ez * apx - ex * apz, niz = ex * apy - ey * apx;
  const FT njx = -ey * bqz + ez * bqy, njy = -ez * bqx + ex * bqz, njz = -ex * bqy + ey * bqx;
  const FT cx = niy * njz - niz * njy, cy = niz * njx - nix * njz, cz = nix * njy - niy * njx;
  s = cx * ex + cy * ey + cz * ez;
  c = nix * njx + niy * njy + niz * njz;
  e2 = ex * ex + ey * ey + ez * ez;
}

// The dihedral angle of the paper (Desobry et al., Sec. 4.1) at a boundary edge is
//   phi = pi - atan2(<n_i x n_j, e/|e|>, <n_i, n_j>)
// with e the half-edge of triangle i.  With s = <n_i x n_j, e> and c = <n_i, n_j> (polynomials of
// the input coordinates), beta = atan2(s/|e|, c) and the class round(2 phi / pi) only depends on
// sign(s), sign(c) and sign(c^2 |e|^2 - s^2): no trigonometry, hence an exact predicate once the
// polynomials are evaluated exactly.  Ties at (2m+1) pi/4 round up (towards the larger valence).
template <class FT>
int dihedral_class_from_coordinates(const std::array<double, 12>& xyz)
{
  FT s, c, e2;
  dihedral_polynomials(xyz, s, c, e2);

  const Sign sign_s = CGAL::sign(s);
  const Sign sign_c = CGAL::sign(c);
  const Sign cmp = CGAL::sign(c * c * e2 - s * s); // > 0: |beta| < pi/4 or |beta| > 3pi/4

  if(cmp == POSITIVE) {
    if(sign_c == POSITIVE) return 2;              // |beta| < pi/4: phi in (3pi/4, 5pi/4)
    return sign_s == NEGATIVE ? 4 : 0;            // beta near -pi: phi near 2pi; near pi: phi near 0
  }
  if(cmp == NEGATIVE) return sign_s == POSITIVE ? 1 : 3;
  // |beta| exactly pi/4 or 3pi/4 (c != 0 since the normals are not zero): ties round up.
  if(sign_c == POSITIVE) return sign_s == POSITIVE ? 2 : 3;   // phi = 3pi/4 -> 2, phi = 5pi/4 -> 3
  return sign_s == POSITIVE ? 1 : 4;                          // phi = pi/4 -> 1, phi = 7pi/4 -> 4
}

inline int dihedral_class_exact(const std::array<double, 12>& xyz)
{
  {
    Protect_FPU_rounding<true> protection;
    try {
      return dihedral_class_from_coordinates<Interval_nt<false> >(xyz);
    } catch(Uncertain_conversion_exception&) {}
  }
  return dihedral_class_from_coordinates<Exact_rational>(xyz);
}

/// Functor of the traits: class round(2 phi / pi) of the dihedral angle phi at edge pq, where
/// (p, q, a) is the first boundary triangle and (q, p, b) the second, both oriented outward.
template <class Kernel>
struct Dihedral_class_3
{
  typedef int result_type;
  int operator()(const typename Kernel::Point_3& p, const typename Kernel::Point_3& q,
                 const typename Kernel::Point_3& a, const typename Kernel::Point_3& b) const
  {
    const std::array<double, 12> xyz = {
      CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()),
      CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()),
      CGAL::to_double(a.x()), CGAL::to_double(a.y()), CGAL::to_double(a.z()),
      CGAL::to_double(b.x()), CGAL::to_double(b.y()), CGAL::to_double(b.z())};
    return dihedral_class_exact(xyz);
  }
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_DIHEDRAL_CLASS_H
