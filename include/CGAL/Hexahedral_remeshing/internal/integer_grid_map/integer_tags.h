// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_INTEGER_TAGS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_INTEGER_TAGS_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/dof_reduction.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/signed_union_find.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Boundary faces on integer planes: in the tetrahedron of each boundary triangle, the coordinate of
// the local axis along the normal is one integer for the three corners of the triangle. Feature
// curves (boundary edges of valence != 2) follow: two faces with different normal axes meet on an
// integer line, in every tetrahedron of the ring through the exact transitions.
template <class Traits>
void tag_boundary_planes(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                         Signed_union_find& uf, std::vector<char>& integer_scalar)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  for(Index b = 0; b < mesh.number_of_boundary_triangles(); ++b) {
    const Index t = mesh.boundary_triangle_tetrahedron(b);
    const auto n = mesh.boundary_triangle_normal(b);
    const Eigen::Vector3d normal(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
    const int k = closest_local_axis(frames[t], normal);
    const auto& bv = mesh.boundary_triangle_vertices(b);
    const std::uint32_t first = map_scalar(t, local_corner(mesh, t, bv[0]), k);
    integer_scalar[first] = 1;
    for(int i = 1; i < 3; ++i) uf.unite(first, map_scalar(t, local_corner(mesh, t, bv[i]), k), 1);
  }
}

// Holonomy of edge e for the loop that starts and ends at ring tetrahedron k (E_tk ~ E_tk G).
template <class Traits>
int holonomy_from(const Tetrahedral_mesh_3<Traits>& mesh, const Matchings& matchings,
                  typename Tetrahedral_mesh_3<Traits>::Index e, std::size_t k)
{
  const Octahedral_group& group = octahedral_group();
  const auto ring = mesh.edge_ring(e);
  const auto faces = mesh.edge_ring_faces(e);
  const std::size_t m = ring.size();
  int G = Octahedral_group::identity_index;
  for(std::size_t j = 0; j < m; ++j) {
    const std::size_t i = (k + j) % m;
    G = group.multiply(matchings.step(mesh, faces[i], ring[i]), G);
  }
  return G;
}

// Singular edges on integer lines: for every tetrahedron t of the ring of a quarter-turn edge (p, q),
// the two coordinates across the local holonomy axis of t are equal at p and q and integer. Every
// ring tetrahedron is tagged because the cut may split the ring into several charts.
template <class Traits>
void tag_singular_lines(const Tetrahedral_mesh_3<Traits>& mesh, const Matchings& matchings,
                        const Singularity_graph& singularities, Signed_union_find& uf,
                        std::vector<char>& integer_scalar)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const Octahedral_group& group = octahedral_group();
  for(Index e = 0; e < mesh.number_of_edges(); ++e) {
    if(singularities.edge_valence[e] != 3 && singularities.edge_valence[e] != 5) continue;
    const auto& ev = mesh.edge_vertices(e);
    const auto ring = mesh.edge_ring(e);
    for(std::size_t k = 0; k < ring.size(); ++k) {
      const int G = holonomy_from(mesh, matchings, e, k);
      if(group.rotation_class(G) != Octahedral_rotation_class::QUARTER_TURN) continue;
      int a;
      group.axis(G).cwiseAbs().maxCoeff(&a);
      const Index t = ring[k];
      const int cp = local_corner(mesh, t, ev[0]), cq = local_corner(mesh, t, ev[1]);
      for(int c = 0; c < 3; ++c) {
        if(c == a) continue;
        integer_scalar[map_scalar(t, cp, c)] = 1;
        uf.unite(map_scalar(t, cp, c), map_scalar(t, cq, c), 1);
      }
    }
  }
}

// The variable reduction of the map: the 12 corner scalars per tetrahedron glued across the uncut
// faces (signed union-find), then the integer tags of boundary planes and singular lines. Returns
// the dofs; `sign_contradictions` receives the scalars forced to x = -x.
template <class Traits>
Map_dofs reduce_map_variables(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                              const Matchings& matchings, const Singularity_graph& singularities,
                              const std::vector<char>& cut, std::size_t& sign_contradictions)
{
  const std::size_t nt = mesh.number_of_tetrahedra();
  Signed_union_find uf(12 * nt);
  sign_contradictions = glue_uncut_faces(mesh, matchings, cut, uf);
  std::vector<char> integer_scalar(12 * nt, 0);
  tag_boundary_planes(mesh, frames, uf, integer_scalar);
  tag_singular_lines(mesh, matchings, singularities, uf, integer_scalar);
  return label_dofs(uf, integer_scalar);
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_INTEGER_TAGS_H
