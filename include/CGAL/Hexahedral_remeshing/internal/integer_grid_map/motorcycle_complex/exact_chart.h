// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_EXACT_CHART_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_EXACT_CHART_H

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

#include <gmp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// Exact parameter space of a seamless map: the corner values of the map are doubles, hence dyadic
// rationals; every wall position, split point and transition below is computed exactly from them.
typedef CGAL::Gmpq Rational;
typedef std::array<Rational, 3> Parameter;

// x rounded to the nearest multiple of 2^-bits (halves away from zero, so that rounding commutes with
// negation and with translations by dyadic numbers of at most `bits` fractional bits: with the charts'
// translations so, the rounded points of two charts still correspond exactly).
// A dyadic x (a power of two below) is kept as it is: the wall's own coordinate, exact.
inline Rational rounded_to_grid(const Rational& x, unsigned bits = 40)
{
  mpq_srcptr q = x.mpq();
  if(mpz_popcount(mpq_denref(q)) == 1) return x;
  mpz_t n, r;
  mpz_init(n);
  mpz_init(r);
  mpz_mul_2exp(n, mpq_numref(q), bits);
  mpz_tdiv_qr(n, r, n, mpq_denref(q));
  mpz_mul_2exp(r, r, 1);
  mpz_abs(r, r);
  if(mpz_cmp(r, mpq_denref(q)) >= 0) {
    if(mpq_sgn(q) > 0) mpz_add_ui(n, n, 1);
    else mpz_sub_ui(n, n, 1);
  }
  Rational out;
  mpq_ptr o = out.mpq();
  mpq_set_num(o, n);
  mpz_set_ui(r, 1);
  mpz_mul_2exp(r, r, bits);
  mpq_set_den(o, r);
  mpq_canonicalize(o);
  mpz_clear(n);
  mpz_clear(r);
  return out;
}

// A rotation of the octahedral group as a signed permutation: (R p)[i] = sign[i] * p[axis[i]].
struct Signed_permutation
{
  std::array<int, 3> axis{{0, 1, 2}};
  std::array<int, 3> sign{{1, 1, 1}};

  bool is_identity() const { return axis == std::array<int, 3>{{0, 1, 2}} && sign == std::array<int, 3>{{1, 1, 1}}; }
  bool operator==(const Signed_permutation& o) const { return axis == o.axis && sign == o.sign; }
};

// The 24 rotations (determinant +1) of the cube.
inline const std::vector<Signed_permutation>& octahedral_rotations()
{
  static const std::vector<Signed_permutation> all = [] {
    std::vector<Signed_permutation> r;
    const int permutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    for(int p = 0; p < 6; ++p)
      for(int s = 0; s < 8; ++s) {
        Signed_permutation R;
        int product = p < 3 ? 1 : -1; // parity of the permutation
        for(int i = 0; i < 3; ++i) {
          R.axis[std::size_t(i)] = permutations[p][i];
          R.sign[std::size_t(i)] = (s >> i) & 1 ? -1 : 1;
          product *= R.sign[std::size_t(i)];
        }
        if(product == 1) r.push_back(R);
      }
    return r;
  }();
  return all;
}

// q = R p + t: the change of chart from one tetrahedron to an adjacent one.
struct Chart_transition
{
  Signed_permutation R;
  Parameter t{{Rational(0), Rational(0), Rational(0)}};

  Parameter operator()(const Parameter& p) const
  {
    Parameter q;
    for(std::size_t i = 0; i < 3; ++i)
      q[i] = (R.sign[i] > 0 ? p[std::size_t(R.axis[i])] : -p[std::size_t(R.axis[i])]) + t[i];
    return q;
  }
  Chart_transition inverse() const
  {
    Chart_transition c;
    for(std::size_t i = 0; i < 3; ++i) {
      const std::size_t j = std::size_t(R.axis[i]);
      c.R.axis[j] = int(i);
      c.R.sign[j] = R.sign[i];
      c.t[j] = R.sign[i] > 0 ? -t[i] : t[i];
    }
    return c;
  }
  bool is_identity() const { return R.is_identity() && CGAL::is_zero(t[0]) && CGAL::is_zero(t[1]) && CGAL::is_zero(t[2]); }
  // this, then `next`
  Chart_transition then(const Chart_transition& next) const
  {
    if(next.is_identity()) return *this;
    Chart_transition c;
    for(std::size_t i = 0; i < 3; ++i) {
      const std::size_t j = std::size_t(next.R.axis[i]);
      c.R.axis[i] = R.axis[j];
      c.R.sign[i] = next.R.sign[i] * R.sign[j];
      c.t[i] = (next.R.sign[i] > 0 ? t[j] : -t[j]) + next.t[i];
    }
    return c;
  }
};

// The transition that maps the three points `from` (one chart) onto `to` (the adjacent chart), exact;
// false if no rotation of the cube and translation does (the map is not seamless there, or the three
// points are collinear in parameter space).
inline bool transition_between(const std::array<Parameter, 3>& from, const std::array<Parameter, 3>& to, Chart_transition& out)
{
  // the rotation that the edge vectors suggest in floating point first, then all of them
  std::array<std::array<double, 3>, 2> d, e;
  for(std::size_t k = 0; k < 2; ++k)
    for(std::size_t i = 0; i < 3; ++i) {
      d[k][i] = CGAL::to_double(from[k + 1][i] - from[0][i]);
      e[k][i] = CGAL::to_double(to[k + 1][i] - to[0][i]);
    }
  std::vector<std::pair<double, const Signed_permutation*> > order;
  for(const Signed_permutation& R : octahedral_rotations()) {
    double mismatch = 0;
    for(std::size_t k = 0; k < 2; ++k)
      for(std::size_t i = 0; i < 3; ++i) mismatch += std::abs(e[k][i] - R.sign[i] * d[k][std::size_t(R.axis[i])]);
    order.emplace_back(mismatch, &R);
  }
  std::sort(order.begin(), order.end());
  for(const auto& candidate : order) {
    const Signed_permutation& R = *candidate.second;
    Chart_transition c;
    c.R = R;
    for(std::size_t i = 0; i < 3; ++i) c.t[i] = Rational(0);
    const Parameter r0 = c(from[0]);
    for(std::size_t i = 0; i < 3; ++i) c.t[i] = to[0][i] - r0[i];
    bool ok = true;
    for(std::size_t k = 1; k < 3 && ok; ++k) ok = c(from[k]) == to[k];
    if(ok) { out = c; return true; }
  }
  return false;
}

// x as an interval: the double itself when x is one (the map's parameters and the split points, rounded
// to 2^-40, are dyadic with few significant bits), else the interval that rounding gives (slower).
inline CGAL::Interval_nt<> interval_of(const Rational& x)
{
  const mpq_srcptr q = x.mpq();
  if(mpz_sizeinbase(mpq_numref(q), 2) <= 53 && mpz_popcount(mpq_denref(q)) == 1 && mpz_sizeinbase(mpq_denref(q), 2) <= 960)
    return CGAL::Interval_nt<>(mpq_get_d(q));
  return CGAL::Interval_nt<>(CGAL::to_interval(x));
}

// The plane p[axis] == value of one chart.
struct Axis_plane
{
  int axis = 0;
  Rational value;

  CGAL::Sign side(const Parameter& p) const { return CGAL::compare(p[std::size_t(axis)], value); }
  Axis_plane in(const Chart_transition& c) const
  {
    Axis_plane q;
    for(std::size_t i = 0; i < 3; ++i)
      if(c.R.axis[i] == axis) {
        q.axis = int(i);
        q.value = (c.R.sign[i] > 0 ? value : -value) + c.t[i];
      }
    return q;
  }
};

inline Parameter exact_parameter(double u, double v, double w) { return Parameter{{Rational(u), Rational(v), Rational(w)}}; }

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_EXACT_CHART_H
