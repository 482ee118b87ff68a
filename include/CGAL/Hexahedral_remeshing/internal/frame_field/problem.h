// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PROBLEM_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PROBLEM_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/frame_field/conjugate_gradients.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The data every frame-field solver shares: the dual graph (interior faces with their two tets and
// a weight), the per-tet faces for gathers, the alignment direction of each constrained tet and the
// frame of each fixed tet (no unknown at all).
// Gathers per tet (instead of scatters per face) keep parallel loops deterministic.
struct Frame_field_problem
{
  typedef std::uint32_t Index;
  static constexpr Index none = Index(-1);

  std::size_t number_of_tets = 0;
  std::vector<std::array<Index, 2> > face_tets;    // interior faces only
  std::vector<double> face_weight;
  std::vector<std::array<Index, 4> > tet_faces;    // interior face slots of each tet (none if boundary)
  std::vector<Index> constrained_direction;        // per tet: index into directions, or none
  std::vector<Eigen::Vector3d> directions;         // unit alignment directions
  std::vector<Index> fixed_frame;                  // per tet: index into fixed_frames, or none
  std::vector<Eigen::Matrix3d> fixed_frames;
  // The tets may be numbered in another order than the mesh's, for locality of memory accesses
  // (see hilbert_order()): mesh_tet[t] is the mesh's index of tet t; empty: the same order.
  std::vector<Index> mesh_tet;

  bool is_fixed(Index t) const { return fixed_frame[t] != none; }
  const Eigen::Matrix3d& frame(Index t) const { return fixed_frames[fixed_frame[t]]; }
  bool is_constrained(Index t) const { return constrained_direction[t] != none; }
  const Eigen::Vector3d& direction(Index t) const { return directions[constrained_direction[t]]; }
};

enum class Face_weighting { UNIFORM, AREA_OVER_DISTANCE };

// Weight of interior face f: its area over the distance of the centroids of its two tets, the
// discretization of the Dirichlet energy that does not depend on the local mesh size.
template <class Traits>
double area_over_distance(const Tetrahedral_mesh_3<Traits>& mesh, typename Tetrahedral_mesh_3<Traits>::Index f)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const auto& v = mesh.face_vertices(f);
  const auto& ft = mesh.face_tetrahedra(f);
  const double area = std::sqrt(CGAL::to_double(CGAL::squared_area(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]))));
  auto centroid = [&](Index t) {
    const auto& tv = mesh.tetrahedron_vertices(t);
    return CGAL::centroid(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]), mesh.point(tv[3]));
  };
  return area / std::sqrt(CGAL::to_double(CGAL::squared_distance(centroid(ft[0]), centroid(ft[1]))));
}

// Scales the weights to mean 1, so that energies are comparable between weightings.
inline void normalize_mean(std::vector<double>& weights)
{
  if(weights.empty()) return;
  double sum = 0;
  for(double w : weights) sum += w;
  const double scale = double(weights.size()) / sum;
  for(double& w : weights) w *= scale;
}

// The tets of `mesh` along a Hilbert curve through their centroids (CGAL::hilbert_sort, median
// policy: deterministic). The solvers' loops over tets gather from the face neighbours; in this order
// the neighbours are mostly close in memory too, which cuts the time of a loop by about a fifth on
// meshes whose own order is not local (TetGen's).
template <class Traits>
std::vector<std::uint32_t> hilbert_order(const Tetrahedral_mesh_3<Traits>& mesh)
{
  typedef CGAL::Simple_cartesian<double> K;
  const std::size_t nt = mesh.number_of_tetrahedra();
  std::vector<K::Point_3> centroids(nt);
  for(std::size_t t = 0; t < nt; ++t) {
    const auto& tv = mesh.tetrahedron_vertices(typename Tetrahedral_mesh_3<Traits>::Index(t));
    double c[3] = {0, 0, 0};
    for(int i = 0; i < 4; ++i) {
      const auto& q = mesh.point(tv[i]);
      c[0] += CGAL::to_double(q.x()) / 4;
      c[1] += CGAL::to_double(q.y()) / 4;
      c[2] += CGAL::to_double(q.z()) / 4;
    }
    centroids[t] = K::Point_3(c[0], c[1], c[2]);
  }
  // the adapter's points are the property map's keys: std::size_t
  std::vector<std::size_t> sorted(nt);
  std::iota(sorted.begin(), sorted.end(), std::size_t(0));
  typedef CGAL::Spatial_sort_traits_adapter_3<K, CGAL::Pointer_property_map<K::Point_3>::type> Sort_traits;
  CGAL::hilbert_sort(sorted.begin(), sorted.end(), Sort_traits(CGAL::make_property_map(centroids)));
  return std::vector<std::uint32_t>(sorted.begin(), sorted.end());
}

// The order the solvers number the tets in when the caller gives none: the Hilbert order on the
// meshes where their loops are memory-bound (those of the multigrid), the mesh's own (empty) below.
template <class Traits>
std::vector<std::uint32_t> default_solver_order(const Tetrahedral_mesh_3<Traits>& mesh)
{
  return mesh.number_of_tetrahedra() >= multigrid_minimum_tets ? hilbert_order(mesh) : std::vector<std::uint32_t>();
}

// rank[t]: the position of mesh tet t in `order` (empty for an empty order, the mesh's own).
// Throws if `order` is not a permutation of the nt tets; `who` names the caller in the message.
inline std::vector<std::uint32_t> ranks_of_order(const std::vector<std::uint32_t>& order, std::size_t nt, const std::string& who)
{
  std::vector<std::uint32_t> rank;
  if(order.empty()) return rank;
  if(order.size() != nt)
    throw Error(who + ": an order of " + std::to_string(order.size()) + " tetrahedra for " + std::to_string(nt));
  const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  rank.assign(nt, none);
  for(std::size_t i = 0; i < nt; ++i) {
    if(order[i] >= nt || rank[order[i]] != none) throw Error(who + ": the order of the tetrahedra is not a permutation");
    rank[order[i]] = std::uint32_t(i);
  }
  return rank;
}

// The interior faces of `mesh`, in the mesh's order or, given rank (mesh tet -> solver tet), by the
// solver's indices of their two tets, so that the loops over faces are local too.
template <class Traits>
std::vector<std::uint32_t> interior_faces_in_order(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<std::uint32_t>& rank)
{
  std::vector<std::uint32_t> faces;
  for(std::uint32_t f = 0; f < mesh.number_of_faces(); ++f)
    if(mesh.face_tetrahedra(f)[1] != Tetrahedral_mesh_3<Traits>::null_index) faces.push_back(f);
  if(rank.empty()) return faces;
  auto key = [&](std::uint32_t f) {
    const auto& ft = mesh.face_tetrahedra(f);
    return std::make_pair((std::min)(rank[ft[0]], rank[ft[1]]), (std::max)(rank[ft[0]], rank[ft[1]]));
  };
  std::sort(faces.begin(), faces.end(), [&](std::uint32_t f, std::uint32_t g) { return key(f) < key(g); });
  return faces;
}

// `order` (optional): the mesh's tets in the order the problem numbers them (a permutation); the
// interior faces are then numbered by their first tet in that order. Indices in the errors are the
// mesh's.
template <class Traits>
Frame_field_problem make_frame_field_problem(const Tetrahedral_mesh_3<Traits>& mesh,
                                             const std::vector<Eigen::Vector3d>& boundary_directions,
                                             Face_weighting weighting,
                                             const std::vector<std::pair<std::size_t, Eigen::Matrix3d> >& fixed = {},
                                             const std::vector<std::uint32_t>& order = {})
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  Frame_field_problem p;
  const std::size_t nt = mesh.number_of_tetrahedra();
  if(boundary_directions.size() != mesh.number_of_boundary_triangles())
    throw Error("frame field: " + std::to_string(boundary_directions.size()) + " boundary directions given for " +
                std::to_string(mesh.number_of_boundary_triangles()) + " boundary triangles");
  p.number_of_tets = nt;
  const std::vector<std::uint32_t> rank = ranks_of_order(order, nt, "frame field"); // mesh tet -> problem tet
  p.mesh_tet.assign(order.begin(), order.end());
  auto to_problem = [&](std::size_t t) { return rank.empty() ? Index(t) : rank[t]; };
  p.tet_faces.assign(nt, {Frame_field_problem::none, Frame_field_problem::none, Frame_field_problem::none,
                          Frame_field_problem::none});
  p.constrained_direction.assign(nt, Frame_field_problem::none);
  p.directions.resize(boundary_directions.size());
  for(std::size_t b = 0; b < boundary_directions.size(); ++b) {
    const double n = boundary_directions[b].norm();
    if(!(n > 0) || !std::isfinite(n)) throw Error("frame field: boundary direction " + std::to_string(b) + " is not a valid vector");
    p.directions[b] = boundary_directions[b] / n;
  }
  std::vector<Index> interior_index(mesh.number_of_faces(), Frame_field_problem::none);
  for(Index f = 0; f < mesh.number_of_faces(); ++f) {
    const auto& ft = mesh.face_tetrahedra(f);
    if(ft[1] != Tetrahedral_mesh_3<Traits>::null_index) continue;
    if(p.constrained_direction[to_problem(ft[0])] != Frame_field_problem::none)
      throw Error("frame field: tetrahedron " + std::to_string(ft[0]) +
                  " has several boundary faces; build the mesh with split_multi_boundary_tetrahedra(true)");
    p.constrained_direction[to_problem(ft[0])] = mesh.face_boundary_triangle(f);
  }
  const std::vector<Index> interior_faces = interior_faces_in_order(mesh, rank);
  p.face_tets.reserve(interior_faces.size());
  p.face_weight.reserve(interior_faces.size());
  for(const Index f : interior_faces) {
    const auto& ft = mesh.face_tetrahedra(f);
    interior_index[f] = Index(p.face_tets.size());
    p.face_tets.push_back({to_problem(ft[0]), to_problem(ft[1])});
    p.face_weight.push_back(weighting == Face_weighting::AREA_OVER_DISTANCE ? area_over_distance(mesh, f) : 1.0);
  }
  if(weighting == Face_weighting::AREA_OVER_DISTANCE) normalize_mean(p.face_weight);
  p.fixed_frame.assign(nt, Frame_field_problem::none);
  for(const auto& tf : fixed) {
    if(tf.first >= nt) throw Error("frame field: fixed frame given for tetrahedron " + std::to_string(tf.first) +
                                   " of a mesh with " + std::to_string(nt));
    const Eigen::Matrix3d& E = tf.second;
    if(!E.allFinite() || (E.transpose() * E - Eigen::Matrix3d::Identity()).norm() > 1e-6 || E.determinant() < 0)
      throw Error("frame field: the fixed frame of tetrahedron " + std::to_string(tf.first) + " is not a rotation");
    const Index t = to_problem(tf.first);
    if(p.fixed_frame[t] != Frame_field_problem::none)
      throw Error("frame field: tetrahedron " + std::to_string(tf.first) + " has several fixed frames");
    if(p.constrained_direction[t] != Frame_field_problem::none) {
      const Eigen::Vector3d c = E.transpose() * p.directions[p.constrained_direction[t]];
      if(c.cwiseAbs().maxCoeff() < 1 - 1e-9)
        throw Error("frame field: the fixed frame of boundary tetrahedron " + std::to_string(tf.first) +
                    " has no axis on its boundary direction");
    }
    p.fixed_frame[t] = Index(p.fixed_frames.size());
    p.fixed_frames.push_back(E);
  }
  for(Index t = 0; t < nt; ++t)
    for(int i = 0; i < 4; ++i) p.tet_faces[to_problem(t)][i] = interior_index[mesh.tetrahedron_face(t, i)];
  return p;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_FRAME_FIELD_PROBLEM_H
