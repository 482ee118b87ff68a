// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_CONSTRAINT_ELIMINATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_CONSTRAINT_ELIMINATION_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Exact elimination of sparse linear equality constraints `sum a_k z_k + c = 0` over continuous and
// integer variables (algorithms.md §4 "Constraint elimination"). Each row is reduced with the
// previous eliminations, then one variable is expressed by the others:
// - a continuous variable with coefficient +-1 if there is one (exact in double: no division);
// - else, when every term is integer with an integer coefficient and the constant is an integer, an
//   integer variable with coefficient +-1 (after division by the gcd), so integers stay integers;
// - else any continuous variable.
// An empty row is redundant (or inconsistent if its constant is not 0); a row over integers only
// without a unit coefficient is left unresolved and counted. The survivors are the free variables;
// every variable is then an affine expression of them (x = P y + x0).
class Constraint_elimination
{
public:
  struct Term
  {
    std::uint32_t var;
    double coef;
  };
  struct Expression
  {
    std::vector<Term> terms;
    double constant = 0;
  };

  std::uint32_t add_variable(bool integer)
  {
    m_integer.push_back(integer ? 1 : 0);
    m_expression.push_back(-1);
    return std::uint32_t(m_integer.size() - 1);
  }
  std::size_t number_of_variables() const { return m_integer.size(); }
  bool is_integer(std::uint32_t v) const { return m_integer[v] != 0; }
  bool is_free(std::uint32_t v) const { return m_expression[v] < 0; }

  // Fixes v = value (v must be free).
  void fix(std::uint32_t v, double value)
  {
    Expression e;
    e.constant = value;
    set_expression(v, std::move(e));
  }

  enum Row_outcome { ELIMINATED, REDUNDANT, INCONSISTENT, UNRESOLVED };

  Row_outcome add_row(const std::vector<Term>& row, double constant)
  {
    Expression r;
    r.constant = constant;
    for(const Term& t : row) accumulate(t.var, t.coef, r);
    normalize(r);
    if(r.terms.empty()) {
      if(std::abs(r.constant) > 1e-9) { ++m_inconsistent; return INCONSISTENT; }
      ++m_redundant;
      return REDUNDANT;
    }
    int pivot = -1;
    for(std::size_t i = 0; i < r.terms.size() && pivot < 0; ++i)
      if(!m_integer[r.terms[i].var] && std::abs(std::abs(r.terms[i].coef) - 1.0) == 0) pivot = int(i);
    if(pivot < 0) {
      bool all_integer = is_integral(r.constant);
      long g = 0;
      for(const Term& t : r.terms) {
        all_integer = all_integer && m_integer[t.var] && is_integral(t.coef);
        if(all_integer) g = std::gcd(g, std::labs(std::lround(t.coef)));
      }
      if(all_integer && g > 1) {
        if(!is_integral(r.constant / double(g))) { ++m_inconsistent; return INCONSISTENT; }
        for(Term& t : r.terms) t.coef /= double(g);
        r.constant /= double(g);
      }
      if(all_integer)
        for(std::size_t i = 0; i < r.terms.size() && pivot < 0; ++i)
          if(std::abs(r.terms[i].coef) == 1.0) pivot = int(i);
    }
    if(pivot < 0)
      for(std::size_t i = 0; i < r.terms.size() && pivot < 0; ++i)
        if(!m_integer[r.terms[i].var]) pivot = int(i);
    if(pivot < 0) { ++m_unresolved; return UNRESOLVED; }
    const Term p = r.terms[std::size_t(pivot)];
    Expression e;
    e.constant = -r.constant / p.coef;
    for(std::size_t i = 0; i < r.terms.size(); ++i)
      if(int(i) != pivot) e.terms.push_back(Term{r.terms[i].var, -r.terms[i].coef / p.coef});
    set_expression(p.var, std::move(e));
    ++m_eliminated;
    return ELIMINATED;
  }

  // The expression of v in the variables that are free now (memoized: the stored expression is
  // replaced by its expansion, which stays valid whatever is eliminated later).
  const Expression& expand(std::uint32_t v)
  {
    static const Expression none;
    const int id = m_expression[v];
    if(id < 0) return none;
    Expression& e = m_expressions[std::size_t(id)];
    bool reduced = true;
    for(const Term& t : e.terms) reduced = reduced && m_expression[t.var] < 0;
    if(reduced) return e;
    Expression out;
    out.constant = e.constant;
    const std::vector<Term> terms = e.terms;
    for(const Term& t : terms) accumulate(t.var, t.coef, out);
    normalize(out);
    m_expressions[std::size_t(id)] = std::move(out);
    return m_expressions[std::size_t(id)];
  }

  std::size_t eliminated_rows() const { return m_eliminated; }
  std::size_t redundant_rows() const { return m_redundant; }
  std::size_t inconsistent_rows() const { return m_inconsistent; }
  std::size_t unresolved_rows() const { return m_unresolved; }

private:
  static bool is_integral(double x) { return std::abs(x - std::round(x)) < 1e-9; }

  void set_expression(std::uint32_t v, Expression e)
  {
    m_expression[v] = int(m_expressions.size());
    m_expressions.push_back(std::move(e));
  }

  // out += coef * (expression of var in the free variables)
  void accumulate(std::uint32_t var, double coef, Expression& out)
  {
    if(m_expression[var] < 0) { out.terms.push_back(Term{var, coef}); return; }
    const Expression& e = expand(var);
    out.constant += coef * e.constant;
    for(const Term& t : e.terms) out.terms.push_back(Term{t.var, coef * t.coef});
  }

  static void normalize(Expression& e)
  {
    std::sort(e.terms.begin(), e.terms.end(), [](const Term& a, const Term& b) { return a.var < b.var; });
    std::size_t k = 0;
    for(std::size_t i = 0; i < e.terms.size();) {
      Term t = e.terms[i++];
      while(i < e.terms.size() && e.terms[i].var == t.var) t.coef += e.terms[i++].coef;
      if(std::abs(t.coef) > 1e-12) e.terms[k++] = t;
    }
    e.terms.resize(k);
  }

  std::vector<char> m_integer;
  std::vector<int> m_expression;
  std::vector<Expression> m_expressions;
  std::size_t m_eliminated = 0, m_redundant = 0, m_inconsistent = 0, m_unresolved = 0;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_CONSTRAINT_ELIMINATION_H
