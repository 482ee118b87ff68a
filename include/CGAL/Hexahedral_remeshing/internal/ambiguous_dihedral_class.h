// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_AMBIGUOUS_DIHEDRAL_CLASS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_AMBIGUOUS_DIHEDRAL_CLASS_H

#include <CGAL/Hexahedral_remeshing/internal/dihedral_class.h>

#include <CGAL/Exact_rational.h>
#include <boost/multiprecision/gmp.hpp>
#ifdef CGAL_USE_GMP
#include <CGAL/Gmpq.h>
#endif
#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>

#include <gmp.h>
#include <mpfr.h>

#include <array>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Classes of the dihedral angle phi whose rounding thresholds are moved below the odd multiples of
// pi/4: with m = round(2 phi / pi) the exact class of `dihedral_class_exact()` (ties up), write
// phi = m pi/2 + psi with psi in [-pi/4, pi/4); the biased class is m + 1 if psi >= theta0 and m
// otherwise, for theta0 = N pi / D just below pi/4. Two biases are used:
//  - the "ambiguous" heuristic (Desobry et al., Sec. 5.2), round(2 phi / pi + 0.05):
//    theta0 = 0.45 pi/2 = 9 pi/40 (40.5 degrees);
//  - the near ties, theta0 = 2047 pi/8192 (pi/8192, 0.022 degrees, below pi/4): a CAD angle of 45,
//    135, 225 or 315 degrees meshed with rounded coordinates lands on either side of the exact tie,
//    edge by edge, so that one CAD curve (a 45-degree chamfer, the toe of a gusset) got two valences.
//
// The test psi >= theta0 is decided exactly for the double coordinates of the four points:
// with s = <n_i x n_j, e>, c = <n_i, n_j> and e2 = |e|^2 (the polynomials of dihedral_class.h),
// (cos phi, sin phi) is proportional to (X0, Y0) = (-c |e|, s).  Rotating by -m pi/2 gives
// (X, Y) proportional to (cos psi, sin psi) with X > 0, and
//     psi >= theta0  <=>  Y > 0  and  Y^2 >= T X^2,   T = tan^2(theta0),
// where Y^2 and X^2 are s^2 or c^2 e2, polynomials of the coordinates (|e| appears squared only).
// T is irrational (tan^2 of a rational multiple of pi is rational only for 0, 1/3, 1, 3, by
// Niven's theorem applied to cos(2 theta0) = (1 - T) / (1 + T)), so the comparison never ties.
// Decision: an interval filter with a double enclosure of T; if it fails, Y^2 and X^2 are
// evaluated exactly (Exact_rational) and compared with enclosures of T computed by MPFR with
// directed rounding at increasing precision, until the enclosure excludes the rational Y^2 / X^2
// (this terminates because T is irrational).

// Enclosure [lo, hi] of T = tan^2(N pi / D) (0 < N / D < 1/4) computed with MPFR at `bits` bits,
// directed rounding: pi is enclosed, then tan is increasing on (0, pi/2) and squaring is increasing
// on positives.
template <unsigned long N, unsigned long D>
void class_threshold_enclosure(mpfr_prec_t bits, mpfr_t lo, mpfr_t hi)
{
  static_assert(0 < N && 4 * N < D, "the threshold is an angle in (0, pi/4)");
  mpfr_t a;
  mpfr_init2(a, bits);
  mpfr_const_pi(lo, MPFR_RNDD);
  mpfr_mul_ui(lo, lo, N, MPFR_RNDD);
  mpfr_div_ui(lo, lo, D, MPFR_RNDD);
  mpfr_tan(lo, lo, MPFR_RNDD);
  mpfr_sqr(lo, lo, MPFR_RNDD);
  mpfr_const_pi(a, MPFR_RNDU);
  mpfr_mul_ui(a, a, N, MPFR_RNDU);
  mpfr_div_ui(a, a, D, MPFR_RNDU);
  mpfr_tan(a, a, MPFR_RNDU);
  mpfr_sqr(hi, a, MPFR_RNDU);
  mpfr_clear(a);
}

// Double enclosure of T, for the interval filter.
template <unsigned long N, unsigned long D>
const Interval_nt<false>& class_threshold_interval()
{
  static const Interval_nt<false> t = [] {
    mpfr_t lo, hi;
    mpfr_init2(lo, 128);
    mpfr_init2(hi, 128);
    class_threshold_enclosure<N, D>(128, lo, hi);
    const double l = mpfr_get_d(lo, MPFR_RNDD), h = mpfr_get_d(hi, MPFR_RNDU);
    mpfr_clear(lo);
    mpfr_clear(hi);
    return Interval_nt<false>(l, h);
  }();
  return t;
}

#ifdef CGAL_USE_GMPXX
inline mpq_srcptr mpq_of(const ::mpq_class& q) { return q.get_mpq_t(); }
#endif
#ifdef CGAL_USE_GMP
inline mpq_srcptr mpq_of(const Gmpq& q) { return q.mpq(); }
#endif
// CGAL::Exact_rational is Boost.Multiprecision's GMP rational when gmpxx is not configured
// (e.g. a build without CGAL's CMake): its backend holds an mpq_t too.
template <class Backend, boost::multiprecision::expression_template_option ET>
mpq_srcptr mpq_of(const boost::multiprecision::number<Backend, ET>& q) { return q.backend().data(); }

// Exact comparison of the rational a / b (b > 0) with T: true if a / b >= T (never equal).
template <unsigned long N, unsigned long D, class Rational>
bool ratio_at_least_class_threshold(const Rational& a, const Rational& b)
{
  mpq_t r;
  mpq_init(r);
  mpq_div(r, mpq_of(a), mpq_of(b));
  bool result = false;
  for(mpfr_prec_t bits = 128;; bits *= 2) {
    mpfr_t lo, hi;
    mpfr_init2(lo, bits);
    mpfr_init2(hi, bits);
    class_threshold_enclosure<N, D>(bits, lo, hi);
    const int below_lo = mpfr_cmp_q(lo, r);   // > 0: r < lo
    const int above_hi = mpfr_cmp_q(hi, r);   // < 0: r > hi
    mpfr_clear(lo);
    mpfr_clear(hi);
    if(below_lo > 0) { result = false; break; }
    if(above_hi < 0) { result = true; break; }
  }
  mpq_clear(r);
  return result;
}

// Y^2 and X^2 of the comment above, and the sign of Y, for class m.
template <class FT>
void biased_rotated_squares(const std::array<double, 12>& xyz, int m, FT& y2, FT& x2, Sign& sign_y)
{
  FT s, c, e2;
  dihedral_polynomials(xyz, s, c, e2);
  // (X0, Y0) = (-c|e|, s); rotation by -m pi/2: m = 0, 4: (X0, Y0); 1: (Y0, -X0); 2: (-X0, -Y0); 3: (-Y0, X0)
  const bool y_is_s = (m % 2 == 0);
  const Sign sign_base = CGAL::sign(y_is_s ? s : c); // throws Uncertain_conversion_exception with intervals
  sign_y = (m % 4 < 2) ? sign_base : CGAL::opposite(sign_base);
  if(y_is_s) { y2 = s * s; x2 = c * c * e2; }
  else { y2 = c * c * e2; x2 = s * s; }
}

// The class of phi with the thresholds at (m + 1/2) pi/2 moved down to m pi/2 + N pi / D, for the
// edge described by `xyz` (same layout as dihedral_class_exact()).
template <unsigned long N, unsigned long D>
int biased_dihedral_class_exact(const std::array<double, 12>& xyz)
{
  const int m = dihedral_class_exact(xyz);
  if(m == 4) return 4; // phi >= 7 pi/4: psi < 0, the bias cannot reach the next class
  const Interval_nt<false> threshold = class_threshold_interval<N, D>(); // computed outside the rounding-mode change
  {
    Protect_FPU_rounding<true> protection;
    try {
      Interval_nt<false> y2, x2;
      Sign sign_y;
      biased_rotated_squares(xyz, m, y2, x2, sign_y);
      if(sign_y != POSITIVE) return m;
      const Interval_nt<false> d = y2 - threshold * x2;
      return CGAL::sign(d) == NEGATIVE ? m : m + 1; // throws if the sign is uncertain (d is never 0)
    } catch(Uncertain_conversion_exception&) {}
  }
  Exact_rational y2, x2;
  Sign sign_y;
  biased_rotated_squares(xyz, m, y2, x2, sign_y);
  if(sign_y != POSITIVE) return m;
  return ratio_at_least_class_threshold<N, D>(y2, x2) ? m + 1 : m;
}

// round(2 phi / pi + 0.05), the class of the "ambiguous" heuristic.
inline int ambiguous_dihedral_class_exact(const std::array<double, 12>& xyz)
{
  return biased_dihedral_class_exact<9, 40>(xyz);
}

// round(2 phi / pi) with the angles within pi/8192 (0.022 degrees) below an odd multiple of pi/4
// taken as ties, which round up: the class of the valence heuristics other than the geometric one.
inline int near_tie_dihedral_class_exact(const std::array<double, 12>& xyz)
{
  return biased_dihedral_class_exact<2047, 8192>(xyz);
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_AMBIGUOUS_DIHEDRAL_CLASS_H
