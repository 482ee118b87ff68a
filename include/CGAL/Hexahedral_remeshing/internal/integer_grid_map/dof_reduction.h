// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_DOF_REDUCTION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_DOF_REDUCTION_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/signed_union_find.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Index of the scalar "coordinate r of corner c of tetrahedron t" among the 12 n corner parameters.
inline std::uint32_t map_scalar(std::uint32_t t, int c, int r) { return 12 * t + 3 * std::uint32_t(c) + std::uint32_t(r); }

// Row r of the signed permutation R: u_t0[r] = sign * u_t1[column].
inline std::pair<int, int> transition_row(int R, int r)
{
  const Octahedral_group& group = octahedral_group();
  for(int c = 0; c < 3; ++c)
    if(group.row_of_column(R, c) == r) return {c, group.sign_of_column(R, c)};
  return {r, 1}; // unreachable for a group element
}

// Local corner of vertex v in tetrahedron t, -1 if absent.
template <class Traits>
int local_corner(const Tetrahedral_mesh_3<Traits>& mesh, typename Tetrahedral_mesh_3<Traits>::Index t,
                 typename Tetrahedral_mesh_3<Traits>::Index v)
{
  const auto& tv = mesh.tetrahedron_vertices(t);
  for(int c = 0; c < 4; ++c)
    if(tv[c] == v) return c;
  return -1;
}

// The rotation of the transition of interior face f: u_t0 = R u_t1 + tau with R = g_f^T (algorithms.md §4).
inline int transition_rotation(const Matchings& matchings, std::size_t f)
{
  return octahedral_group().inverse(matchings.face_matching[f]);
}

// Glues the charts across every uncut interior face (signed union-find of the corner scalars of the
// three shared vertices). Returns the number of sign contradictions (x = -x).
template <class Traits>
std::size_t glue_uncut_faces(const Tetrahedral_mesh_3<Traits>& mesh, const Matchings& matchings,
                             const std::vector<char>& cut, Signed_union_find& uf)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  std::size_t contradictions = 0;
  for(Index f = 0; f < mesh.number_of_faces(); ++f) {
    if(mesh.is_boundary_face(f) || cut[f]) continue;
    const auto& ft = mesh.face_tetrahedra(f);
    const int R = transition_rotation(matchings, f);
    for(Index v : mesh.face_vertices(f)) {
      const int c0 = local_corner(mesh, ft[0], v), c1 = local_corner(mesh, ft[1], v);
      for(int r = 0; r < 3; ++r) {
        const auto [col, sign] = transition_row(R, r);
        if(!uf.unite(map_scalar(ft[0], c0, r), map_scalar(ft[1], c1, col), sign)) ++contradictions;
      }
    }
  }
  return contradictions;
}

// The classes of the union-find numbered 0..number_of_dofs-1, with the sign of every scalar
// (x_scalar = sign * dof) and whether a class carries an integer tag or a contradiction.
struct Map_dofs
{
  std::vector<std::uint32_t> dof;  // per scalar
  std::vector<std::int8_t> sign;   // per scalar
  std::vector<char> integer;       // per dof
  std::vector<char> contradicted;  // per dof
  std::size_t number_of_dofs = 0;
};

inline Map_dofs label_dofs(Signed_union_find& uf, const std::vector<char>& integer_scalar)
{
  Map_dofs d;
  const std::size_t n = uf.size();
  d.dof.resize(n);
  d.sign.resize(n);
  std::vector<std::uint32_t> label(n, std::uint32_t(-1));
  for(std::uint32_t i = 0; i < n; ++i) {
    const auto [root, s] = uf.find(i);
    if(label[root] == std::uint32_t(-1)) {
      label[root] = std::uint32_t(d.number_of_dofs++);
      d.contradicted.push_back(uf.contradicted(root) ? 1 : 0);
      d.integer.push_back(0);
    }
    d.dof[i] = label[root];
    d.sign[i] = std::int8_t(s);
    if(integer_scalar[i]) d.integer[label[root]] = 1;
  }
  return d;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_DOF_REDUCTION_H
