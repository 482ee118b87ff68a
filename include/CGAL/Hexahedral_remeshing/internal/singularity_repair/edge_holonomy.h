// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// The local quantities of the meshability check and of the repair: the holonomy of one interior edge
// from the face matchings around it, the edge's class (regular, singular along its axis, jog,
// improper), and the kind of singular vertex from the classes of its edges.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_EDGE_HOLONOMY_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_EDGE_HOLONOMY_H

#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>

#include <CGAL/number_utils.h>

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Edge classes: 4 regular, 3 / 5 singular along the axis, and these two.
constexpr signed char IMPROPER_CLASS = 0;
constexpr signed char JOG_CLASS = 1;

template <class Point>
Eigen::Vector3d to_eigen_point(const Point& p)
{
  return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// G = g_{t(m-1) t0} ... g_{t0 t1} around interior edge e (E_t0 ~ E_t0 G after one counter-clockwise
// turn), with the matchings `face_matching` (indexed by face, `E_t0 ~ E_t1 g_f` for (t0, t1) the
// face's tetrahedra): the convention of compute_singularity_graph().
template <class Mesh>
int edge_holonomy(const Mesh& mesh, const std::vector<int>& face_matching, typename Mesh::Index e)
{
  const Octahedral_group& group = octahedral_group();
  const auto ring = mesh.edge_ring(e);
  const auto faces = mesh.edge_ring_faces(e);
  int G = Octahedral_group::identity_index;
  for(std::size_t k = 0; k < ring.size(); ++k) {
    const int g = face_matching[faces[k]];
    G = group.multiply(mesh.face_tetrahedra(faces[k])[0] == ring[k] ? g : group.inverse(g), G);
  }
  return G;
}

// Cosine between the edge and the world axis of its quarter-turn holonomy G (signed: > 0 for
// valence 3, the convention of compute_singularity_graph()).
template <class Mesh>
double holonomy_axis_cosine(const Mesh& mesh, const std::vector<Eigen::Matrix3d>& frames, typename Mesh::Index e, int G)
{
  const auto& ev = mesh.edge_vertices(e);
  const Eigen::Vector3d d = (to_eigen_point(mesh.point(ev[1])) - to_eigen_point(mesh.point(ev[0]))).normalized();
  return (frames[mesh.edge_ring(e)[0]] * octahedral_group().axis(G)).dot(d);
}

// Class of interior edge e with holonomy G: 4 regular, 3 or 5 a quarter turn about an axis within
// 45 degrees of the edge, JOG_CLASS further off, IMPROPER_CLASS any other rotation.
template <class Mesh>
signed char classify_edge(const Mesh& mesh, const std::vector<Eigen::Matrix3d>& frames, typename Mesh::Index e, int G)
{
  if(G == Octahedral_group::identity_index) return 4;
  if(octahedral_group().rotation_class(G) != Octahedral_rotation_class::QUARTER_TURN) return IMPROPER_CLASS;
  const double c = holonomy_axis_cosine(mesh, frames, e, G);
  if(std::abs(c) < std::sqrt(0.5)) return JOG_CLASS;
  return c > 0 ? 3 : 5;
}

inline bool is_singular_class(signed char c) { return c >= 0 && c != 4; }

// The valence a quarter-turn edge of class c reads as where its angle alone decides it, as in
// compute_singularity_graph() (which the map's report of the field follows): +1 for valence 3, -1 for
// valence 5, 0 when the edge is nearly perpendicular to its axis (|cos| <= 1/4) or not a quarter turn.
// A jog 60 degrees off its axis reads as valence 3 or 5 by the side it leans to; between two edges of
// a curve leaning to opposite sides the curve runs backwards, which folds every map along it.
template <class Mesh>
signed char edge_lean(const Mesh& mesh, const std::vector<Eigen::Matrix3d>& frames, typename Mesh::Index e, int G, signed char c)
{
  if(c == 3) return 1;
  if(c == 5) return -1;
  if(c != JOG_CLASS) return 0;
  const double cosine = holonomy_axis_cosine(mesh, frames, e, G);
  return std::abs(cosine) > lenient_axis_cosine ? (cosine > 0 ? 1 : -1) : 0;
}

// An interior vertex where a curve of two quarter-turn edges turns from one lean to the other (a
// zipper as compute_singularity_graph() sees it, jogs included).
template <class Mesh>
bool is_leaning_zipper(const Mesh& mesh, const std::vector<signed char>& edge_class, const std::vector<signed char>& lean,
                       typename Mesh::Index v)
{
  if(mesh.is_boundary_vertex(v)) return false;
  signed char first = 0;
  int degree = 0;
  for(auto e : mesh.vertex_edges(v)) {
    if(!is_singular_class(edge_class[e])) continue;
    if(edge_class[e] == IMPROPER_CLASS || ++degree > 2 || lean[e] == 0) return false;
    if(degree == 1) first = lean[e];
    else if(lean[e] == first) return false;
  }
  return degree == 2;
}

// What a vertex is from the classes of its edges; the values of the vertex reasons of
// Meshability_reason (DANGLING_END = 2 ... BOUNDARY_CONTACT = 5).
struct Vertex_singularity
{
  enum Kind { NONE = -1, DANGLING_END = 2, ZIPPER = 3, INVALID_NODE = 4, BOUNDARY_CONTACT = 5 };
  Kind kind = NONE;
  int degree = 0;
};

template <class Mesh>
Vertex_singularity vertex_singularity(const Mesh& mesh, const std::vector<signed char>& edge_class, typename Mesh::Index v)
{
  Vertex_singularity s;
  int n3 = 0, n5 = 0, other = 0;
  for(auto e : mesh.vertex_edges(v)) {
    const signed char c = edge_class[e];
    if(!is_singular_class(c)) continue;
    ++s.degree;
    if(c == 3) ++n3;
    else if(c == 5) ++n5;
    else ++other;
  }
  if(mesh.is_boundary_vertex(v)) {
    if(s.degree == 2 && other == 0 && (n3 == 2 || n5 == 2)) s.kind = Vertex_singularity::BOUNDARY_CONTACT;
  } else if(s.degree == 1) {
    s.kind = Vertex_singularity::DANGLING_END;
  } else if(s.degree == 2 && n3 == 1 && n5 == 1) {
    s.kind = Vertex_singularity::ZIPPER;
  } else if(s.degree >= 3 && other == 0 && ((n3 + n5) % 2 != 0 || 3 * n3 + n5 > 12)) {
    // a jog or an improper edge at the node is reported as such; its valence is unknown here
    s.kind = Vertex_singularity::INVALID_NODE;
  }
  return s;
}

// The face spanned by edges e1 and e2 of one vertex (null_index if the third edge is not in the mesh
// or spans no face).
template <class Mesh>
typename Mesh::Index face_of_edges(const Mesh& mesh, typename Mesh::Index e1, typename Mesh::Index e2)
{
  const auto& a = mesh.edge_vertices(e1);
  const auto& b = mesh.edge_vertices(e2);
  for(auto f : mesh.edge_ring_faces(e1)) {
    const auto& fv = mesh.face_vertices(f);
    auto in_face = [&](typename Mesh::Index v) { return fv[0] == v || fv[1] == v || fv[2] == v; };
    if(in_face(b[0]) && in_face(b[1]) && in_face(a[0]) && in_face(a[1])) return f;
  }
  return Mesh::null_index;
}

// The face of a zigzag at interior vertex v (null_index if none): v on one curve (exactly two singular
// edges, both valence 3 or both valence 5) whose two edges v-a and v-c bound a face a-v-c. The map puts
// a, v and c on the curve's parameter line (both edges are tagged as lines along the same axis), so the
// triangle is degenerate and both tetrahedra on it are flat in every map, whatever the angle at v.
template <class Mesh>
typename Mesh::Index zigzag_face(const Mesh& mesh, const std::vector<signed char>& edge_class, typename Mesh::Index v)
{
  if(mesh.is_boundary_vertex(v)) return Mesh::null_index;
  typename Mesh::Index edges[2];
  int degree = 0;
  for(auto e : mesh.vertex_edges(v)) {
    if(!is_singular_class(edge_class[e])) continue;
    if(degree == 2) return Mesh::null_index;
    edges[degree++] = e;
  }
  if(degree != 2 || edge_class[edges[0]] != edge_class[edges[1]] || (edge_class[edges[0]] != 3 && edge_class[edges[0]] != 5))
    return Mesh::null_index;
  return face_of_edges(mesh, edges[0], edges[1]);
}

// The unit axis, in world coordinates, of the quarter turn of interior edge e (holonomy per interior edge,
// read in the frame of the first tetrahedron of its ring).
template <class Mesh>
Eigen::Vector3d quarter_turn_world_axis(const Mesh& mesh, const std::vector<Eigen::Matrix3d>& frames, const std::vector<int>& holonomy,
                                        typename Mesh::Index e)
{
  return (frames[mesh.edge_ring(e)[0]] * octahedral_group().axis(holonomy[e])).normalized();
}

// The smallest |cos| between `axis` and, for each boundary triangle at boundary vertex v, the axis of its
// tetrahedron's frame closest to its normal (the axis the map puts that triangle's plane across): below
// sqrt(1/2), a curve along `axis` lies in one of those planes at v.
template <class Mesh>
double smallest_boundary_axis_cosine(const Mesh& mesh, const std::vector<Eigen::Matrix3d>& frames, typename Mesh::Index v,
                                     const Eigen::Vector3d& axis)
{
  double smallest = 1;
  for(auto b_edge : mesh.vertex_edges(v)) {
    if(!mesh.is_boundary_edge(b_edge)) continue;
    for(auto b : mesh.edge_boundary_triangles(b_edge)) {
      const auto n = mesh.boundary_triangle_normal(b);
      const Eigen::Vector3d normal(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
      const Eigen::Matrix3d& E = frames[mesh.boundary_triangle_tetrahedron(b)];
      smallest = std::min(smallest, std::abs(E.col(closest_local_axis(E, normal)).normalized().dot(axis)));
    }
  }
  return smallest;
}

// Whether a singular curve ends at (or touches) boundary vertex v along a boundary triangle it runs
// alongside: the map puts the three corners of every boundary triangle on an integer plane across the
// frame axis closest to its normal (integer_tags.h) and every quarter-turn edge on an integer line along
// its holonomy axis. At a vertex where both hold, a plane whose axis is not the curve's fixes one of the
// curve's two line coordinates: the whole curve lies in the plane, and every tetrahedron between the
// curve and that patch is flat in every map. A curve must end on faces it crosses (their axis is the
// curve's). `holonomy`: per interior edge, its holonomy (edge_holonomy()); edges of class 3, 5 and jogs
// count (a jog still has a quarter-turn axis); the frame axes are compared in world coordinates, where
// the frames around a curve turn about its axis only.
template <class Mesh>
bool ends_in_boundary_plane(const Mesh& mesh, const std::vector<Eigen::Matrix3d>& frames, const std::vector<signed char>& edge_class,
                            const std::vector<int>& holonomy, typename Mesh::Index v)
{
  if(!mesh.is_boundary_vertex(v)) return false;
  for(auto e : mesh.vertex_edges(v)) {
    const signed char c = edge_class[e];
    if(c != 3 && c != 5 && c != JOG_CLASS) continue;
    if(smallest_boundary_axis_cosine(mesh, frames, v, quarter_turn_world_axis(mesh, frames, holonomy, e)) < std::sqrt(0.5)) return true;
  }
  return false;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_SINGULARITY_REPAIR_EDGE_HOLONOMY_H
