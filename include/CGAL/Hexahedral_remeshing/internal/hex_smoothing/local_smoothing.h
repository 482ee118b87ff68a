// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_LOCAL_SMOOTHING_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_LOCAL_SMOOTHING_H

// Vertex-by-vertex (Gauss-Seidel) optimization of the corner-tet energy of a hex mesh. The global
// L-BFGS minimization of the same energy stalls on the barrier (the step length is set by the worst
// element of the whole mesh, so thousands of iterations move the bulk by almost nothing); a vertex
// problem has at most 3 unknowns and a few dozen elements: a damped Newton step on it costs
// microseconds and its barrier only sees the vertex's own star.

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/reference_projector.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/vertex_constraints.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/hexahedron_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/untangling/foldover_free_energy.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

struct Local_smoothing_options
{
  // weight of the volume term against the shape term of the corner-tet energy
  double theta = 0.2;
  // a star's smallest scaled Jacobian may drop only while it stays at least this high (or the
  // star's own minimum before the move, if that is lower)
  double quality_floor = 0.5;
  // the low-quality threshold of the reports: a move that raises a star's minimum may lower its other
  // hexahedra, but not below this
  double low_quality = 0.3;
  // Newton steps per vertex visit
  int newton_steps = 1;
  // a vertex that moves less than this fraction of its hex size does not wake its neighbours
  double move_tolerance = 1e-3;
};

// Per-vertex incidences (hexahedron, local corner), CSR.
struct Hex_vertex_stars
{
  std::vector<std::uint32_t> offset; // V + 1
  std::vector<std::uint32_t> hex;
  std::vector<std::uint8_t> corner;
};

inline Hex_vertex_stars make_hex_vertex_stars(const Hexahedral_mesh_3& mesh)
{
  Hex_vertex_stars s;
  const std::size_t V = mesh.number_of_vertices();
  s.offset.assign(V + 1, 0);
  for(const auto& h : mesh.hexahedra)
    for(std::uint32_t v : h) ++s.offset[v + 1];
  for(std::size_t v = 0; v < V; ++v) s.offset[v + 1] += s.offset[v];
  s.hex.resize(s.offset[V]);
  s.corner.resize(s.offset[V]);
  std::vector<std::uint32_t> fill(s.offset.begin(), s.offset.end() - 1);
  for(std::size_t h = 0; h < mesh.number_of_hexahedra(); ++h)
    for(int i = 0; i < 8; ++i) {
      const std::uint32_t v = mesh.hexahedra[h][i];
      s.hex[fill[v]] = std::uint32_t(h);
      s.corner[fill[v]] = std::uint8_t(i);
      ++fill[v];
    }
  return s;
}

// Corner-tet energy of the stars, vertex by vertex. Works on `mesh.points` in place.
class Local_hex_smoother
{
public:
  typedef Hexahedral_mesh_3::Point_3 Point;
  typedef Reference_projector::Vector_3 Vector_3;

  Local_hex_smoother(Hexahedral_mesh_3& mesh, const std::vector<Hex_vertex_constraint>& constraints,
                     const Reference_projector& reference, const std::vector<double>& hex_size,
                     const Local_smoothing_options& options)
    : m_mesh(mesh), m_constraints(constraints), m_reference(reference), m_size(hex_size), m_options(options),
      m_stars(make_hex_vertex_stars(mesh)), m_sj(mesh.number_of_hexahedra())
  {
    double worst = (std::numeric_limits<double>::max)();
    for(std::size_t h = 0; h < m_sj.size(); ++h) {
      m_sj[h] = hex_sj(h);
      worst = (std::min)(worst, m_sj[h]);
    }
    // on a mesh already better than the floors, they rise to its minimum: no move may lower it
    if(!m_sj.empty()) {
      m_options.quality_floor = (std::max)(m_options.quality_floor, worst);
      m_options.low_quality = (std::max)(m_options.low_quality, worst);
    }
    const std::size_t V = mesh.number_of_vertices();
    std::uint32_t largest = 0;
    for(std::size_t v = 0; v < V; ++v) largest = (std::max)(largest, m_stars.offset[v + 1] - m_stars.offset[v]);
    m_trial.resize(largest);
    m_vertex_size.assign(V, 0.);
    for(std::size_t v = 0; v < V; ++v) {
      double s = 0;
      for(std::uint32_t k = m_stars.offset[v]; k < m_stars.offset[v + 1]; ++k) s += m_size[m_stars.hex[k]];
      const std::uint32_t n = m_stars.offset[v + 1] - m_stars.offset[v];
      m_vertex_size[v] = n > 0 ? s / n : 0.;
    }
  }

  const std::vector<double>& scaled_jacobians() const { return m_sj; }
  const Hex_vertex_stars& stars() const { return m_stars; }

  bool movable(std::size_t v) const
  {
    return m_constraints[v].kind != Hex_vertex_kind::FIXED && m_stars.offset[v + 1] > m_stars.offset[v];
  }

  // Scaled Jacobian of hexahedron h with the current points.
  double hex_sj(std::size_t h) const
  {
    std::array<Point, 8> p;
    for(int i = 0; i < 8; ++i) p[i] = m_mesh.points[m_mesh.hexahedra[h][i]];
    double sj = 1;
    for(int c = 0; c < 8; ++c) sj = (std::min)(sj, hex_corner_scaled_jacobian(p, c));
    return sj;
  }

  // Smallest scaled Jacobian of the star of v and its number of hexahedra with scaled Jacobian <= 0,
  // from the cache.
  std::pair<double, int> star_quality(std::size_t v) const
  {
    double m = (std::numeric_limits<double>::max)();
    int bad = 0;
    for(std::uint32_t k = m_stars.offset[v]; k < m_stars.offset[v + 1]; ++k) {
      const double s = m_sj[m_stars.hex[k]];
      m = (std::min)(m, s);
      if(s <= 0) ++bad;
    }
    return std::make_pair(m, bad);
  }

  // Smallest det K of the corner tets of the star of v (K = D / size: 1 for a cube corner of the
  // ideal size).
  double star_min_det(std::size_t v, const Eigen::Vector3d& x) const
  {
    double m = (std::numeric_limits<double>::max)();
    for_each_star_tet(v, x, [&](const Eigen::Matrix3d& K, double, int, int) { m = (std::min)(m, K.determinant()); });
    return m;
  }

  // Energy of the star of v with v at x, and its gradient with respect to x (if given).
  double star_energy(std::size_t v, const Eigen::Vector3d& x, double eps, Eigen::Vector3d* grad) const
  {
    double E = 0;
    if(grad != nullptr) grad->setZero();
    for_each_star_tet(v, x, [&](const Eigen::Matrix3d& K, double inv_size, int role, int) {
      Eigen::Matrix3d G;
      E += foldover_free_element_energy(K, eps, m_options.theta, grad != nullptr ? &G : nullptr);
      if(grad != nullptr) {
        // dE/dD = G / size; the apex gets minus the sum of the columns, neighbour k column k
        const Eigen::Matrix3d dD = G * inv_size;
        if(role < 0) *grad -= dD.col(0) + dD.col(1) + dD.col(2);
        else *grad += dD.col(role);
      }
    });
    return E;
  }

  // One visit of vertex v: damped Newton steps on its star energy in its degrees of freedom, the
  // result projected onto its constraint; kept only if the star stays acceptable. Returns the
  // distance moved.
  double relax_vertex(std::size_t v)
  {
    if(!movable(v)) return 0;
    const Point old_point = m_mesh.points[v];
    const std::pair<double, int> before = star_quality(v);
    const double hsize = m_vertex_size[v];
    if(!(hsize > 0)) return 0;
    Eigen::Vector3d x(old_point.x(), old_point.y(), old_point.z());
    const double det0 = star_min_det(v, x);
    // regularization: the true barrier on a valid star; on a tangled (or nearly) one an epsilon of
    // the order of its worst determinant, as in the foldover-free schedule, so that the inverted
    // corners are pulled out instead of being walled in
    const double eps = det0 > 1e-3 ? 1e-8 : (std::max)(1e-3, 2. * std::abs(det0));
    for(int step = 0; step < m_options.newton_steps; ++step) {
      Eigen::Matrix<double, 3, Eigen::Dynamic> B;
      if(!basis(v, x, B)) break;
      const int k = int(B.cols());
      Eigen::Vector3d g3;
      const double E0 = star_energy(v, x, eps, &g3);
      if(!std::isfinite(E0)) break;
      const Eigen::VectorXd g = B.transpose() * g3;
      // Hessian in the degrees of freedom by forward differences of the analytic gradient
      const double h = 1e-6 * hsize;
      Eigen::MatrixXd H(k, k);
      for(int a = 0; a < k; ++a) {
        Eigen::Vector3d ga;
        star_energy(v, x + h * B.col(a), eps, &ga);
        H.col(a) = (B.transpose() * (ga - g3)) / h;
      }
      H = 0.5 * (H + H.transpose()).eval();
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(H);
      Eigen::VectorXd lambda = es.eigenvalues();
      const double lmax = (std::max)(lambda.cwiseAbs().maxCoeff(), 1e-300);
      for(int a = 0; a < k; ++a) lambda[a] = (std::max)(std::abs(lambda[a]), 1e-6 * lmax);
      Eigen::VectorXd d = -es.eigenvectors() * (es.eigenvectors().transpose() * g).cwiseQuotient(lambda);
      if(!d.allFinite()) break;
      // trust region: a third of the hex size per step
      const double len = d.norm();
      if(len > hsize / 3.) d *= hsize / (3. * len);
      double alpha = 1;
      bool found = false;
      Eigen::Vector3d xn;
      for(int ls = 0; ls < 12; ++ls, alpha *= 0.5) {
        xn = x + alpha * (B * d);
        const double En = star_energy(v, xn, eps, nullptr);
        if(std::isfinite(En) && En < E0) { found = true; break; }
      }
      if(!found) break;
      const double moved = (xn - x).norm();
      x = xn;
      if(moved < 1e-9 * hsize) break;
    }
    project(v, x);
    // acceptance on the scaled Jacobians of the star; halve the move while refused
    const Eigen::Vector3d x_old(old_point.x(), old_point.y(), old_point.z());
    for(int attempt = 0; attempt < 3; ++attempt) {
      if(attempt > 0) {
        x = 0.5 * (x + x_old);
        project(v, x);
      }
      if((x - x_old).norm() <= 1e-12 * hsize) break;
      const bool lower = before.second > 0 && star_energy(v, x, eps, nullptr) < star_energy(v, x_old, eps, nullptr);
      if(try_move(v, x, before, lower)) return (x - x_old).norm();
    }
    return 0;
  }

  // Moves v to x if its star stays acceptable: no hexahedron below the floor gets worse and none above
  // falls below it; or the star's minimum rises and the others stay above min(their own, 0.3); or the
  // star has a hexahedron with SJ <= 0 and its minimum rises or (`energy_decreased`) the move lowers
  // its foldover-free energy. The number of hexahedra with SJ <= 0
  // never grows. Otherwise v stays where it was.
  bool try_move(std::size_t v, const Eigen::Vector3d& x, const std::pair<double, int>& before, bool energy_decreased = false)
  {
    const Point old_point = m_mesh.points[v];
    m_mesh.points[v] = Point(x[0], x[1], x[2]);
    double m = (std::numeric_limits<double>::max)();
    int bad = 0;
    for(std::uint32_t i = m_stars.offset[v]; i < m_stars.offset[v + 1]; ++i) {
      const double s = hex_sj(m_stars.hex[i]);
      m_trial[i - m_stars.offset[v]] = s;
      m = (std::min)(m, s);
      if(s <= 0) ++bad;
    }
    bool ok = bad <= before.second;
    const bool raised = m > before.first + 1e-9;
    // a tangled star: the foldover-free energy decides (its scaled Jacobians are not monotone along
    // the way out of a fold: a corner gets more inverted before it flips), as long as no hexahedron
    // is added to the non-positive ones; the best-state selection of the caller keeps the minimum
    const bool untangling = before.second > 0 && (raised || energy_decreased);
    for(std::uint32_t i = m_stars.offset[v]; ok && !untangling && i < m_stars.offset[v + 1]; ++i) {
      const double old_sj = m_sj[m_stars.hex[i]], new_sj = m_trial[i - m_stars.offset[v]];
      ok = new_sj >= (std::min)(old_sj, m_options.quality_floor) ||
           (raised && new_sj >= (std::min)(old_sj, (std::max)(m, m_options.low_quality)));
    }
    if(!ok) {
      m_mesh.points[v] = old_point;
      return false;
    }
    for(std::uint32_t i = m_stars.offset[v]; i < m_stars.offset[v + 1]; ++i) m_sj[m_stars.hex[i]] = m_trial[i - m_stars.offset[v]];
    return true;
  }

  // Soft minimum (-log sum exp(-t sj) / t) of the corner scaled Jacobians of the star of v with v at x.
  double star_soft_min(std::size_t v, const Eigen::Vector3d& x, double t)
  {
    const Point old_point = m_mesh.points[v];
    m_mesh.points[v] = Point(x[0], x[1], x[2]);
    m_corner_sj.clear();
    double lo = (std::numeric_limits<double>::max)();
    for(std::uint32_t k = m_stars.offset[v]; k < m_stars.offset[v + 1]; ++k) {
      std::array<Point, 8> p;
      for(int i = 0; i < 8; ++i) p[i] = m_mesh.points[m_mesh.hexahedra[m_stars.hex[k]][i]];
      for(int c = 0; c < 8; ++c) {
        m_corner_sj.push_back(hex_corner_scaled_jacobian(p, c));
        lo = (std::min)(lo, m_corner_sj.back());
      }
    }
    m_mesh.points[v] = old_point;
    double sum = 0;
    for(double c : m_corner_sj) sum += std::exp(-t * (c - lo));
    return lo - std::log(sum) / t;
  }

  // Raises the smallest scaled Jacobian of the star of v directly: ascent on its soft minimum (finite
  // differences in the degrees of freedom of v), a step kept only if the true minimum rises. For the
  // worst hexahedra, whose corners the corner-tet energy trades against the rest of the star.
  bool raise_star_minimum(std::size_t v)
  {
    if(!movable(v)) return false;
    const double hsize = m_vertex_size[v];
    if(!(hsize > 0)) return false;
    const Point p0 = m_mesh.points[v];
    Eigen::Vector3d x(p0.x(), p0.y(), p0.z());
    bool moved = false;
    double step = 0.05 * hsize;
    for(int it = 0; it < 8; ++it) {
      const std::pair<double, int> before = star_quality(v);
      Eigen::Matrix<double, 3, Eigen::Dynamic> B;
      if(!basis(v, x, B)) break;
      const double t = 50.;
      const double f0 = star_soft_min(v, x, t);
      const double h = 1e-6 * hsize;
      Eigen::Vector3d g = Eigen::Vector3d::Zero();
      for(int a = 0; a < int(B.cols()); ++a) g += (star_soft_min(v, x + h * B.col(a), t) - f0) / h * B.col(a);
      const double gn = g.norm();
      if(!(gn > 0) || !std::isfinite(gn)) break;
      bool accepted = false;
      for(int ls = 0; ls < 6 && !accepted; ++ls, step *= 0.5) {
        Eigen::Vector3d xn = x + (step / gn) * g;
        project(v, xn);
        if(try_move(v, xn, before)) {
          x = xn;
          moved = true;
          accepted = star_quality(v).first > before.first + 1e-9;
          if(!accepted) return true; // acceptable but no higher: the ascent is over
        }
      }
      if(!accepted) break;
      step *= 4; // the next iteration starts from a longer step again
    }
    return moved;
  }

  // raise_star_minimum() on the vertices (in index order) of the hexahedra whose scaled Jacobian is
  // below `threshold`. Returns the number of vertices moved.
  std::size_t raise_minimum_pass(double threshold)
  {
    std::vector<char> low(m_mesh.number_of_vertices(), 0);
    for(std::size_t h = 0; h < m_sj.size(); ++h)
      if(m_sj[h] < threshold)
        for(std::uint32_t v : m_mesh.hexahedra[h]) low[v] = 1;
    std::size_t moved = 0;
    for(std::size_t v = 0; v < low.size(); ++v)
      if(low[v] && raise_star_minimum(v)) ++moved;
    return moved;
  }

  // One Gauss-Seidel sweep over the active vertices in index order (deterministic); the vertices of
  // the stars of a vertex that moved become active for the next sweep. Returns the number of moves.
  std::size_t sweep(std::vector<char>& active)
  {
    const std::size_t V = m_mesh.number_of_vertices();
    std::vector<char> next(V, 0);
    std::size_t moves = 0;
    for(std::size_t v = 0; v < V; ++v) {
      if(!active[v] || !movable(v)) continue;
      const double moved = relax_vertex(v);
      if(moved > m_options.move_tolerance * m_vertex_size[v]) {
        ++moves;
        for(std::uint32_t k = m_stars.offset[v]; k < m_stars.offset[v + 1]; ++k)
          for(std::uint32_t w : m_mesh.hexahedra[m_stars.hex[k]]) next[w] = 1;
      }
    }
    active.swap(next);
    return moves;
  }

private:
  // f(K, 1/size, role, hex) for the corner tets of the star of v with v at x; role -1: v is the apex,
  // k: v is the k-th neighbour.
  template <class F>
  void for_each_star_tet(std::size_t v, const Eigen::Vector3d& x, F&& f) const
  {
    auto at = [&](std::uint32_t w) {
      if(w == v) return x;
      const Point& p = m_mesh.points[w];
      return Eigen::Vector3d(p.x(), p.y(), p.z());
    };
    const auto& nbs = hex_corner_neighbors();
    for(std::uint32_t k = m_stars.offset[v]; k < m_stars.offset[v + 1]; ++k) {
      const std::size_t h = m_stars.hex[k];
      const int i = m_stars.corner[k];
      const auto& hex = m_mesh.hexahedra[h];
      const double inv = 1. / m_size[h];
      // the corner tets that contain i: its own and those of its three neighbours
      for(int t = -1; t < 3; ++t) {
        const int apex = t < 0 ? i : nbs[i][t];
        int role = -1;
        if(t >= 0)
          for(int r = 0; r < 3; ++r)
            if(nbs[apex][r] == i) role = r;
        const Eigen::Vector3d a = at(hex[apex]);
        Eigen::Matrix3d K;
        for(int c = 0; c < 3; ++c) K.col(c) = (at(hex[nbs[apex][c]]) - a) * inv;
        f(K, inv, role, int(h));
      }
    }
  }

  // Degrees of freedom of v at x: 3 (interior), the tangent plane (surface), the tangent (curve).
  bool basis(std::size_t v, const Eigen::Vector3d& x, Eigen::Matrix<double, 3, Eigen::Dynamic>& B) const
  {
    const Hex_vertex_constraint& c = m_constraints[v];
    const Point p(x[0], x[1], x[2]);
    if(c.kind == Hex_vertex_kind::INTERIOR) {
      B = Eigen::Matrix3d::Identity();
      return true;
    }
    if(c.kind == Hex_vertex_kind::SURFACE) {
      Vector_3 n;
      m_reference.closest_on_surface(p, &n, c.patch);
      const Eigen::Vector3d nn(n.x(), n.y(), n.z());
      int axis = 0;
      for(int a = 1; a < 3; ++a)
        if(std::abs(nn[a]) < std::abs(nn[axis])) axis = a;
      const Eigen::Vector3d t1 = nn.cross(Eigen::Vector3d::Unit(axis)).normalized();
      B.resize(3, 2);
      B.col(0) = t1;
      B.col(1) = nn.cross(t1);
      return B.allFinite();
    }
    if(c.kind == Hex_vertex_kind::CURVE) {
      Vector_3 t;
      m_reference.closest_on_polyline(c.polyline, p, &t);
      if(!(t.squared_length() > 0)) return false;
      B.resize(3, 1);
      B.col(0) = Eigen::Vector3d(t.x(), t.y(), t.z());
      return true;
    }
    return false;
  }

  void project(std::size_t v, Eigen::Vector3d& x) const
  {
    const Hex_vertex_constraint& c = m_constraints[v];
    Point p(x[0], x[1], x[2]);
    if(c.kind == Hex_vertex_kind::SURFACE) p = m_reference.closest_on_surface(p, nullptr, c.patch);
    else if(c.kind == Hex_vertex_kind::CURVE) p = m_reference.closest_on_polyline(c.polyline, p);
    else return;
    x = Eigen::Vector3d(p.x(), p.y(), p.z());
  }

  Hexahedral_mesh_3& m_mesh;
  const std::vector<Hex_vertex_constraint>& m_constraints;
  const Reference_projector& m_reference;
  const std::vector<double>& m_size;
  Local_smoothing_options m_options;
  Hex_vertex_stars m_stars;
  std::vector<double> m_sj;
  std::vector<double> m_vertex_size;
  std::vector<double> m_trial;
  std::vector<double> m_corner_sj;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEX_SMOOTHING_LOCAL_SMOOTHING_H
