// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEPARATION_CONSTRAINTS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEPARATION_CONSTRAINTS_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/dof_reduction.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/linear_form.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/map_energy.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <functional>
#include <map>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Finds the separations a quantized map violates (robust_pipeline.md §3, the separation constraints
// of QGP3D, searched here in the tetrahedral mesh instead of a motorcycle complex).
//
// An *entity* is an integer iso-value of the map: a boundary plane, a coordinate of a singular or
// feature line, seen in one chart. Where the quantized map folds, the parameters of the tetrahedra
// around the fold are developed into the chart of one of them (transitions composed along a breadth-
// first search), so that every integer corner coordinate becomes a Linear_form over the variables.
// Along each chart axis, the entities that the seamless map orders strictly (by more than
// `minimum_seamless_gap`) but the quantized map does not keep at least one unit apart are a collapse
// (a thin wall rounded to no layer, two curves rounded onto one line); each such pair of neighbours in
// the seamless order gives a constraint `later - earlier >= 1`.
template <class Traits>
class Separation_finder
{
public:
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Row_matrix;
  // The integer jump of cut face f along its axis k as a form over the variables.
  typedef std::function<Linear_form(Index, int)> Jump_form;

  double minimum_seamless_gap = 1e-4;
  int region_rings = 2;               // face rings around the folds where entities are compared
  std::size_t maximum_region_tetrahedra = 200000;

  Separation_finder(const Tetrahedral_mesh_3<Traits>& mesh, const Matchings& matchings, const std::vector<char>& cut,
                    const Map_geometry& geometry, const Row_matrix& P, const Eigen::VectorXd& x0,
                    const std::vector<char>& integer_column, const std::vector<char>& flat, Jump_form jump)
    : m_mesh(mesh), m_matchings(matchings), m_cut(cut), m_geometry(geometry), m_P(P), m_x0(x0),
      m_integer_column(integer_column), m_flat(flat), m_jump(std::move(jump))
  {}

  // Tetrahedra with det J <= 0 for the variables y, the structurally flat ones left out.
  std::vector<char> folded(const Eigen::VectorXd& y) const
  {
    const Eigen::VectorXd x = m_P * y + m_x0;
    std::vector<char> f(m_mesh.number_of_tetrahedra(), 0);
    for(Index t = 0; t < m_mesh.number_of_tetrahedra(); ++t)
      if(!m_flat[t] && map_jacobian(m_geometry, x, t).determinant() <= 0) f[t] = 1;
    return f;
  }

  // The constraints `form >= 1` violated by the quantized `y` around its folds (`seamless`: the
  // continuous map the quantization started from).
  std::vector<Linear_form> violated(const Eigen::VectorXd& seamless, const Eigen::VectorXd& y) const
  {
    std::vector<char> near = folded(y);
    for(int ring = 0; ring < region_rings; ++ring) near = grow(near);
    std::vector<char> visited(m_mesh.number_of_tetrahedra(), 0);
    std::vector<Linear_form> out;
    for(Index t = 0; t < m_mesh.number_of_tetrahedra(); ++t)
      if(near[t] && !visited[t]) collapses_in_region(t, near, visited, seamless, y, out);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

private:
  struct Chart_pose
  {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); // root = rotation * u_t + translation
    std::array<Linear_form, 3> translation;
  };

  std::vector<char> grow(const std::vector<char>& in) const
  {
    std::vector<char> out = in;
    for(Index t = 0; t < m_mesh.number_of_tetrahedra(); ++t)
      if(in[t])
        for(int i = 0; i < 4; ++i) {
          const Index f = m_mesh.tetrahedron_face(t, i);
          if(m_mesh.is_boundary_face(f)) continue;
          const auto& ft = m_mesh.face_tetrahedra(f);
          out[ft[0]] = out[ft[1]] = 1;
        }
    return out;
  }

  // The pose of the neighbour across interior face f of a tetrahedron of pose `p`: u_t0 = R u_t1 + tau.
  Chart_pose neighbour_pose(const Chart_pose& p, Index f, bool from_first) const
  {
    const Eigen::Matrix3d R = octahedral_group().matrix(transition_rotation(m_matchings, f));
    std::array<Linear_form, 3> tau;
    if(m_cut[f])
      for(int k = 0; k < 3; ++k) tau[k] = m_jump(f, k);
    Chart_pose q;
    // from t0: root = Q0 (R u1 + tau) + T0; from t1: root = Q1 R^T (u0 - tau) + T1
    const Eigen::Matrix3d A = from_first ? Eigen::Matrix3d(p.rotation) : Eigen::Matrix3d(p.rotation * R.transpose());
    q.rotation = from_first ? Eigen::Matrix3d(p.rotation * R) : A;
    const double sign = from_first ? 1.0 : -1.0;
    for(int K = 0; K < 3; ++K) {
      q.translation[K] = p.translation[K];
      if(m_cut[f])
        for(int j = 0; j < 3; ++j)
          if(A(K, j) != 0) q.translation[K] = q.translation[K].plus(tau[j], sign * A(K, j));
    }
    return q;
  }

  // Corner scalar i as a form over the variables, if it is an integer iso-value (integer columns with
  // integer coefficients).
  bool integer_form(Eigen::Index i, Linear_form& form) const
  {
    form = Linear_form();
    form.constant = m_x0[i];
    for(Row_matrix::InnerIterator it(m_P, i); it; ++it) {
      if(it.value() == 0) continue;
      if(!m_integer_column[std::size_t(it.col())] || it.value() != std::round(it.value())) return false;
      form.terms.emplace_back(it.col(), it.value());
    }
    std::sort(form.terms.begin(), form.terms.end());
    return !form.terms.empty() || form.constant == std::round(form.constant);
  }

  void collapses_in_region(Index seed, const std::vector<char>& near, std::vector<char>& visited,
                           const Eigen::VectorXd& seamless, const Eigen::VectorXd& y, std::vector<Linear_form>& out) const
  {
    std::array<std::vector<Linear_form>, 3> entities;
    std::deque<std::pair<Index, Chart_pose> > queue;
    queue.emplace_back(seed, Chart_pose());
    visited[seed] = 1;
    std::size_t count = 0;
    while(!queue.empty() && count < maximum_region_tetrahedra) {
      const auto [t, pose] = queue.front();
      queue.pop_front();
      ++count;
      collect_entities(t, pose, entities);
      for(int i = 0; i < 4; ++i) {
        const Index f = m_mesh.tetrahedron_face(t, i);
        if(m_mesh.is_boundary_face(f)) continue;
        const auto& ft = m_mesh.face_tetrahedra(f);
        const Index n = ft[0] == t ? ft[1] : ft[0];
        if(!near[n] || visited[n]) continue;
        visited[n] = 1;
        queue.emplace_back(n, neighbour_pose(pose, f, ft[0] == t));
      }
    }
    for(int K = 0; K < 3; ++K) separate(entities[K], seamless, y, out);
  }

  void collect_entities(Index t, const Chart_pose& pose, std::array<std::vector<Linear_form>, 3>& entities) const
  {
    for(int K = 0; K < 3; ++K) {
      int j = 0;
      while(pose.rotation(K, j) == 0) ++j;
      const double sign = pose.rotation(K, j);
      for(int c = 0; c < 4; ++c) {
        Linear_form form;
        if(!integer_form(Eigen::Index(map_scalar(std::uint32_t(t), c, j)), form)) continue;
        entities[K].push_back(form.scaled(sign).plus(pose.translation[K], 1.0));
      }
    }
  }

  void separate(std::vector<Linear_form>& forms, const Eigen::VectorXd& seamless, const Eigen::VectorXd& y,
                std::vector<Linear_form>& out) const
  {
    std::sort(forms.begin(), forms.end());
    forms.erase(std::unique(forms.begin(), forms.end()), forms.end());
    std::vector<std::pair<double, std::size_t> > order;
    for(std::size_t i = 0; i < forms.size(); ++i) order.emplace_back(forms[i](seamless), i);
    std::sort(order.begin(), order.end());
    for(std::size_t k = 1; k < order.size(); ++k) {
      const Linear_form& a = forms[order[k - 1].second];
      const Linear_form& b = forms[order[k].second];
      if(order[k].first - order[k - 1].first <= minimum_seamless_gap) continue;
      if(b(y) - a(y) >= 0.5) continue;
      const Linear_form d = b.plus(a, -1.0);
      if(!d.terms.empty()) out.push_back(d);
    }
  }

  const Tetrahedral_mesh_3<Traits>& m_mesh;
  const Matchings& m_matchings;
  const std::vector<char>& m_cut;
  const Map_geometry& m_geometry;
  const Row_matrix& m_P;
  const Eigen::VectorXd& m_x0;
  const std::vector<char>& m_integer_column;
  const std::vector<char>& m_flat;
  Jump_form m_jump;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEPARATION_CONSTRAINTS_H
