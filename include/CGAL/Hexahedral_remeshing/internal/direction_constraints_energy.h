// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_DIRECTION_CONSTRAINTS_ENERGY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_DIRECTION_CONSTRAINTS_ENERGY_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The angle deviations of Desobry et al., Sec. 4.1, with the extension of Sec. 6.2.
//
// Orientation conventions (they must match the paper's dihedral angle formula):
// - n_i is the unit outward normal of boundary triangle i, whose vertices (a0, a1, a2) are
//   counter-clockwise seen from outside;
// - the neighbour j of i across local slot s (the edge opposite a_s) shares the half-edge
//   e_ij = a_{s+2} - a_{s+1} of triangle i (a half-edge of i, i.e. counter-clockwise about n_i);
//   triangle j holds the opposite half-edge e_ji = -e_ij.  For a boundary edge e of the mesh,
//   `edge_boundary_triangles(e)[0]` holds the half-edge v1 -> v0 of `edge_vertices(e)`, so
//   phi(v_i, v_j) of that edge uses i = edge_boundary_triangles(e)[0] and e_ij = p(v0) - p(v1);
// - phi(a, b) = pi - atan2(<a x b, e_ij / |e_ij|>, <a, b>), in [0, 2 pi): for a = n_i, b = n_j it
//   is the interior dihedral angle (pi on a flat edge, pi/2 on a convex cube edge, 3 pi/2 on a
//   concave one).  It is symmetric: phi computed from j with e_ji is the same number, bit for bit
//   (the cross product and the dot product with the opposite edge only flip signs twice).
//
// With beta = atan2(<n_i x n_j, e>, <n_i, n_j>) the right-handed angle about e_ij from n_i to n_j,
// phi(n_i, n_j) = pi - beta.  The constraint phi = k pi/2 means beta = pi - k pi/2.  The paper's
// R_ij is "the rotation of angle pi - k pi/2 about the edge" that brings n_j back onto n_i when the
// constraint holds: with the sign conventions above that is the right-handed rotation of angle
// theta = k pi/2 - pi about e_ij (i.e. of angle pi - k pi/2 about e_ji).  The ideal half-edge normal
//     nbar_ij = (n_i + R_ij n_j) / |n_i + R_ij n_j|
// is the bisector of n_i and R_ij n_j; both are orthogonal to e_ij, and R_ij n_j is at angle
// w = beta + theta (wrapped to (-pi, pi]) from n_i, so nbar_ij = rotation of n_i by w/2 about e_ij.
// We compute it in that form, which equals the paper's formula whenever |w| < pi and stays defined
// when n_i + R_ij n_j = 0 (w = pi: the normals are exactly opposite to the ideal configuration; we
// then turn by +pi/2).  The pair (nbar_ij, nbar_ji) satisfies phi = k pi/2 (modulo 2 pi).
//
//   delta^d_i(v) = max_j dev(phi(v_i, v_j), k_ij pi/2), dev(a, t) = |a - t| for k <= 4 (Eq. 5), and
//                  min_p |a - t + 2 p pi| for k >= 5 (Sec. 6.2: phi lies in [0, 2 pi), so a valence
//                  of 5 or 6 is reached modulo 2 pi);
//   delta^n_i(v) = max_j arccos(<v_i, nbar_ij>) (Eq. 7);
//   E_i(v) = max(delta^d_i(v), delta^n_i(v)), E(v) = max_i E_i(v).
class Boundary_direction_energy
{
public:
  typedef std::uint32_t Index;
  typedef Eigen::Vector3d Vector;

  struct Half_edge
  {
    Vector edge;          // unit e_ij, half-edge of triangle i
    Vector ideal_normal;  // nbar_ij
    double target = 0;    // k_ij pi / 2
    Index neighbor = 0;   // j
    bool modulo = false;  // k_ij >= 5: deviation modulo 2 pi
  };

  template <class Traits>
  Boundary_direction_energy(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<int>& valences,
                            int maximum_valence)
  {
    typedef Tetrahedral_mesh_3<Traits> Mesh;
    if(valences.size() != mesh.number_of_edges())
      throw Error("direction constraints: " + std::to_string(valences.size()) + " valences for " +
                  std::to_string(mesh.number_of_edges()) + " edges");
    for(Index e : mesh.boundary_edges())
      if(valences[e] < 0 || valences[e] > maximum_valence) {
        const auto& ev = mesh.edge_vertices(e);
        throw Input_error("valences", 0, "boundary edge " + std::to_string(e) + " (vertices " + std::to_string(ev[0]) +
                          " " + std::to_string(ev[1]) + "): valence " + std::to_string(valences[e]) +
                          " is outside 0.." + std::to_string(maximum_valence));
      }
    const std::size_t nf = mesh.number_of_boundary_triangles();
    m_half_edges.resize(nf);
    auto to_vector = [](const auto& p) {
      return Vector(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    };
    m_normals = boundary_triangle_unit_normals(mesh);
    for(Index i = 0; i < nf; ++i) {
      const auto& tv = mesh.boundary_triangle_vertices(i);
      for(int s = 0; s < 3; ++s) {
        Half_edge& h = m_half_edges[i][std::size_t(s)];
        const Vector a = to_vector(mesh.point(tv[std::size_t((s + 1) % 3)]));
        const Vector b = to_vector(mesh.point(tv[std::size_t((s + 2) % 3)]));
        const Vector d = b - a;
        h.edge = d / d.norm();
        h.neighbor = mesh.boundary_triangle_neighbor(i, s);
        CGAL_assertion(h.neighbor != Mesh::null_index);
        const int k = valences[mesh.boundary_triangle_edge(i, s)];
        h.target = k * (CGAL_PI / 2);
        h.modulo = (k >= 5);
        h.ideal_normal = ideal_half_edge_normal(m_normals[i], m_normals[h.neighbor], h.edge, k);
      }
    }
  }

  std::size_t number_of_faces() const { return m_normals.size(); }
  const std::vector<Vector>& normals() const { return m_normals; }
  const std::array<Half_edge, 3>& half_edges(Index i) const { return m_half_edges[i]; }

  // phi(a, b) about the unit half-edge e, in [0, 2 pi).
  static double dihedral_angle(const Vector& a, const Vector& b, const Vector& e)
  {
    double phi = CGAL_PI - std::atan2(a.cross(b).dot(e), a.dot(b));
    if(phi >= 2 * CGAL_PI) phi -= 2 * CGAL_PI;
    return phi;
  }

  // Deviation of the dihedral angle phi from the target k pi / 2, plain (Eq. 5) or modulo 2 pi (Sec. 6.2).
  static double dihedral_deviation(double phi, double target, bool modulo)
  {
    const double d = std::abs(phi - target);
    if(!modulo) return d;
    const double r = std::fmod(d, 2 * CGAL_PI);
    return (std::min)(r, 2 * CGAL_PI - r);
  }

  // Right-handed rotation of x by angle a about the unit axis e (Rodrigues).
  static Vector rotate(const Vector& x, const Vector& e, double a)
  {
    const double c = std::cos(a), s = std::sin(a);
    return c * x + s * e.cross(x) + (1 - c) * e.dot(x) * e;
  }

  // nbar_ij (see the comment of the class).
  static Vector ideal_half_edge_normal(const Vector& ni, const Vector& nj, const Vector& e, int k)
  {
    const double beta = std::atan2(ni.cross(nj).dot(e), ni.dot(nj));
    double w = beta + k * (CGAL_PI / 2) - CGAL_PI;
    w = std::remainder(w, 2 * CGAL_PI);           // in [-pi, pi]
    if(w <= -CGAL_PI) w += 2 * CGAL_PI;           // in (-pi, pi]
    const Vector r = rotate(ni, e, w / 2);
    return r / r.norm();
  }

  // E_i(v) (with v_i = v[i]).
  double face_energy(Index i, const std::vector<Vector>& v) const
  {
    return face_energy_below(i, v[i], v, std::numeric_limits<double>::infinity());
  }

  // E_i of the field v in which v_i is replaced by the unit vector u, if it is below `bound`;
  // otherwise +infinity, returned as soon as one term reaches `bound` (the value of a candidate
  // that is not better than the best so far does not matter).  The result never depends on the
  // bound when it is below it.  `cos_bound` is cos(bound) when bound < pi (any value otherwise),
  // computed once by the caller.
  double face_energy_below(Index i, const Vector& u, const std::vector<Vector>& v, double bound, double cos_bound) const
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    const std::array<Half_edge, 3>& h = m_half_edges[i];
    // delta^n: arccos is decreasing, so the largest angle is the one of the smallest dot product;
    // a dot product clearly below cos(bound) rejects the candidate without any trigonometry.
    const double d = (std::min)({u.dot(h[0].ideal_normal), u.dot(h[1].ideal_normal), u.dot(h[2].ideal_normal)});
    if(bound < CGAL_PI && d < cos_bound - 1e-12) return infinity; // arccos(d) is certainly > bound
    double e = 0;
    for(int s = 0; s < 3; ++s) {
      const double dev = dihedral_deviation(dihedral_angle(u, v[h[s].neighbor], h[s].edge), h[s].target, h[s].modulo);
      if(dev >= bound) return infinity;
      e = (std::max)(e, dev);
    }
    const double en = std::acos((std::max)(-1.0, (std::min)(1.0, d)));
    if(en >= bound) return infinity;
    return (std::max)(e, en);
  }

  double face_energy_below(Index i, const Vector& u, const std::vector<Vector>& v, double bound) const
  {
    return face_energy_below(i, u, v, bound, bound < CGAL_PI ? std::cos(bound) : -1.0);
  }

private:
  std::vector<Vector> m_normals;
  std::vector<std::array<Half_edge, 3> > m_half_edges;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_DIRECTION_CONSTRAINTS_ENERGY_H
