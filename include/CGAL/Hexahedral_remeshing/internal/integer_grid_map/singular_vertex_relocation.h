// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SINGULAR_VERTEX_RELOCATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SINGULAR_VERTEX_RELOCATION_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/field_diagnostics.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <CGAL/Kernel/global_functions.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// What the relocation of the singular curves' vertices did.
struct Singular_vertex_relocation
{
  std::size_t moved_vertices = 0;   // vertices whose position changed
  std::size_t jogs_before = 0;      // singular edges more than 45 degrees off their holonomy axis
  std::size_t jogs_after = 0;
};

// The world axis of singular edge e: the holonomy axis in the frame of the first tetrahedron of its
// ring, the frame the holonomy is expressed in (as compute_singularity_graph() walks the ring).
template <class Traits>
Eigen::Vector3d singular_edge_axis(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                                   const Singularity_graph& g, std::uint32_t e)
{
  return (frames[*mesh.edge_ring(e).begin()] * octahedral_group().axis(g.edge_holonomy[e])).normalized();
}

// |cos| of the angle between singular edge e and its axis.
template <class Traits>
double singular_edge_alignment(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                               const Singularity_graph& g, std::uint32_t e)
{
  const auto& ev = mesh.edge_vertices(e);
  const Eigen::Vector3d d = (vertex_point(mesh, ev[1]) - vertex_point(mesh, ev[0])).normalized();
  return std::abs(d.dot(singular_edge_axis(mesh, frames, g, e)));
}

// Shape quality of a tetrahedron in [0, 1] (1: regular; <= 0: flat or inverted), the mean ratio
// 12 (3 |V|)^(2/3) / sum of squared edge lengths, signed by the volume.
inline double tetrahedron_shape_quality(const std::array<Eigen::Vector3d, 4>& p)
{
  const double volume = (p[1] - p[0]).cross(p[2] - p[0]).dot(p[3] - p[0]) / 6;
  double squares = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j) squares += (p[j] - p[i]).squaredNorm();
  if(!(squares > 0)) return 0;
  const double q = 12 * std::pow(3 * std::abs(volume), 2.0 / 3.0) / squares;
  return volume > 0 ? q : -q;
}

// The interior vertices of the singular curves with exactly two singular edges of valence 3 or 5 and
// no other singular edge (nodes, ends on the boundary and vertices of improper edges stay), with the
// two edges.
template <class Traits>
std::vector<std::array<std::uint32_t, 3> > relocatable_curve_vertices(const Tetrahedral_mesh_3<Traits>& mesh, const Singularity_graph& g)
{
  std::vector<std::array<std::uint32_t, 3> > out;
  for(std::uint32_t v = 0; v < mesh.number_of_vertices(); ++v) {
    if(mesh.is_boundary_vertex(v)) continue;
    std::array<std::uint32_t, 3> entry = {{v, 0, 0}};
    int count = 0;
    bool other = false;
    for(auto e : mesh.vertex_edges(v)) {
      const int k = g.edge_valence[e];
      if(k == 4) continue;
      if((k != 3 && k != 5) || count == 2) { other = true; break; }
      entry[1 + count++] = e;
    }
    if(!other && count == 2) out.push_back(entry);
  }
  return out;
}

// The position of v that puts both its singular edges (v, p) and (v, n) closest to their axes a, b in
// the least-squares sense: min |P_a (x - p)|^2 + |P_b (x - n)|^2 + lambda |x - v|^2 with P the
// projection across the axis; lambda keeps x where the two axes leave it free (along a common axis).
inline Eigen::Vector3d aligned_position(const Eigen::Vector3d& v, const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                        const Eigen::Vector3d& n, const Eigen::Vector3d& b)
{
  const Eigen::Matrix3d Pa = Eigen::Matrix3d::Identity() - a * a.transpose();
  const Eigen::Matrix3d Pb = Eigen::Matrix3d::Identity() - b * b.transpose();
  const double lambda = 1e-2;
  const Eigen::Matrix3d A = Pa + Pb + lambda * Eigen::Matrix3d::Identity();
  return A.ldlt().solve(Pa * p + Pb * n + lambda * v);
}

// Singular edges of valence 3 or 5 more than 45 degrees off their holonomy axis.
template <class Traits>
std::size_t count_singular_jogs(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                                const Singularity_graph& g)
{
  std::size_t n = 0;
  for(std::uint32_t e = 0; e < mesh.number_of_edges(); ++e)
    if(!mesh.is_boundary_edge(e) && (g.edge_valence[e] == 3 || g.edge_valence[e] == 5) &&
       singular_edge_alignment(mesh, frames, g, e) < std::sqrt(0.5)) ++n;
  return n;
}

// The moves of one curve vertex within the inversion barrier: every tetrahedron around it positively
// oriented (exact predicate) and none worse in shape than `floor`.
template <class Traits>
class Curve_vertex_mover
{
  typedef typename Traits::Point_3 Point_3;

public:
  explicit Curve_vertex_mover(Tetrahedral_mesh_3<Traits>& mesh) : m_mesh(mesh), m_vertex_tets(mesh.number_of_vertices())
  {
    for(std::uint32_t t = 0; t < mesh.number_of_tetrahedra(); ++t)
      for(auto v : mesh.tetrahedron_vertices(t)) m_vertex_tets[v].push_back(t);
  }

  // The worst shape of the tetrahedra of v with v at x.
  double worst_shape(std::uint32_t v, const Eigen::Vector3d& x) const
  {
    double q = 1;
    for(auto t : m_vertex_tets[v]) {
      std::array<Eigen::Vector3d, 4> p;
      const auto& tv = m_mesh.tetrahedron_vertices(t);
      for(int i = 0; i < 4; ++i) p[i] = tv[i] == v ? x : vertex_point(m_mesh, tv[i]);
      q = (std::min)(q, tetrahedron_shape_quality(p));
    }
    return q;
  }

  // Moves v to x if the barrier allows it.
  bool move(std::uint32_t v, const Eigen::Vector3d& x, double floor)
  {
    if(worst_shape(v, x) < floor) return false;
    const Point_3 q(x[0], x[1], x[2]);
    for(auto t : m_vertex_tets[v]) {
      const auto& tv = m_mesh.tetrahedron_vertices(t);
      std::array<const Point_3*, 4> p;
      for(int i = 0; i < 4; ++i) p[i] = tv[i] == v ? &q : &m_mesh.point(tv[i]);
      if(CGAL::orientation(*p[0], *p[1], *p[2], *p[3]) != CGAL::POSITIVE) return false;
    }
    m_mesh.move_interior_vertex(v, q);
    return true;
  }

private:
  Tetrahedral_mesh_3<Traits>& m_mesh;
  std::vector<std::vector<std::uint32_t> > m_vertex_tets;
};

// One step of curve vertex `entry` (the vertex and its two singular edges) towards aligned_position(),
// the largest of 1, 1/2, ..., 1/16 of the way that the barrier allows and that leaves the worse aligned
// of its two edges no worse (where the two axes differ, aligning one edge can make the other a jog).
template <class Traits>
bool step_curve_vertex(Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames, const Singularity_graph& g,
                       Curve_vertex_mover<Traits>& mover, const std::array<std::uint32_t, 3>& entry, double floor)
{
  const std::uint32_t v = entry[0];
  const Eigen::Vector3d x = vertex_point(mesh, v);
  std::array<Eigen::Vector3d, 2> other, axis;
  for(int k = 0; k < 2; ++k) {
    const auto& ev = mesh.edge_vertices(entry[1 + k]);
    other[k] = vertex_point(mesh, ev[0] == v ? ev[1] : ev[0]);
    axis[k] = singular_edge_axis(mesh, frames, g, entry[1 + k]);
  }
  const Eigen::Vector3d target = aligned_position(x, other[0], axis[0], other[1], axis[1]);
  if(!((target - x).norm() > 0.5e-3 * ((other[0] - x).norm() + (other[1] - x).norm()))) return false;
  auto alignment = [&](const Eigen::Vector3d& y) {
    return (std::min)(std::abs((other[0] - y).normalized().dot(axis[0])), std::abs((other[1] - y).normalized().dot(axis[1])));
  };
  const double aligned = alignment(x);
  for(double step = 1; step >= 1.0 / 16; step /= 2) {
    const Eigen::Vector3d y = x + step * (target - x);
    if(alignment(y) >= aligned && mover.move(v, y, floor)) return true;
  }
  return false;
}

// Vertex relocation of the singular curves (robust_pipeline.md §1, Liu et al. 2023): each interior
// vertex of a curve steps towards the position aligning its two singular edges with their holonomy
// axes (step_curve_vertex), no tetrahedron around it worse in shape than half its worst shape at the
// start; Gauss-Seidel sweeps until no vertex moves. A jog is a curve that cannot follow its axis in
// the mesh as it is; the map puts the curve on an integer line whatever its geometry, and the
// tetrahedra around a jog are sheared by the difference. Only interior vertices move: the solid is
// unchanged.
template <class Traits>
Singular_vertex_relocation relocate_singular_vertices(Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                                                      const Singularity_graph& g, int sweeps = 20)
{
  Singular_vertex_relocation r;
  r.jogs_before = r.jogs_after = count_singular_jogs(mesh, frames, g);
  const auto vertices = relocatable_curve_vertices(mesh, g);
  if(vertices.empty()) return r;
  Curve_vertex_mover<Traits> mover(mesh);
  std::vector<double> floor(vertices.size());
  for(std::size_t i = 0; i < vertices.size(); ++i) floor[i] = 0.5 * mover.worst_shape(vertices[i][0], vertex_point(mesh, vertices[i][0]));
  std::vector<char> moved(vertices.size(), 0);
  for(int sweep = 0; sweep < sweeps; ++sweep) {
    bool any = false;
    for(std::size_t i = 0; i < vertices.size(); ++i)
      if(step_curve_vertex(mesh, frames, g, mover, vertices[i], floor[i])) any = moved[i] = 1;
    if(!any) break;
  }
  r.moved_vertices = std::size_t(std::count(moved.begin(), moved.end(), 1));
  r.jogs_after = count_singular_jogs(mesh, frames, g);
  return r;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SINGULAR_VERTEX_RELOCATION_H
