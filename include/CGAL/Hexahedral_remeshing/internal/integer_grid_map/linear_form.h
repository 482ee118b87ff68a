// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_LINEAR_FORM_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_LINEAR_FORM_H

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// An affine function `constant + sum coef * y[column]` of the free variables y of the reduced map
// problem, its terms sorted by column without zero coefficients (so that equal functions compare equal).
struct Linear_form
{
  std::vector<std::pair<Eigen::Index, double> > terms;
  double constant = 0;

  double operator()(const Eigen::VectorXd& y) const
  {
    double v = constant;
    for(const auto& t : terms) v += t.second * y[t.first];
    return v;
  }

  // this + factor * other
  Linear_form plus(const Linear_form& other, double factor) const
  {
    Linear_form r;
    r.constant = constant + factor * other.constant;
    std::size_t i = 0, j = 0;
    while(i < terms.size() || j < other.terms.size()) {
      if(j == other.terms.size() || (i < terms.size() && terms[i].first < other.terms[j].first)) r.terms.push_back(terms[i++]);
      else if(i == terms.size() || other.terms[j].first < terms[i].first) {
        r.terms.emplace_back(other.terms[j].first, factor * other.terms[j].second);
        ++j;
      } else {
        const double c = terms[i].second + factor * other.terms[j].second;
        if(c != 0) r.terms.emplace_back(terms[i].first, c);
        ++i;
        ++j;
      }
    }
    return r;
  }

  Linear_form scaled(double factor) const
  {
    Linear_form r;
    r.constant = factor * constant;
    for(const auto& t : terms) r.terms.emplace_back(t.first, factor * t.second);
    return r;
  }

  bool operator<(const Linear_form& o) const
  {
    if(terms != o.terms) return terms < o.terms;
    return constant < o.constant;
  }
  bool operator==(const Linear_form& o) const { return terms == o.terms && constant == o.constant; }
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_LINEAR_FORM_H
