// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Where the seamless map folds, and so which stage must change for it to open: a tetrahedron that the
// constraints flatten in every map (structurally_flat.h) needs another field or another mesh; one at a
// defect of the field's graph needs the repair; the others are where the constraints leave room that the
// untangling did not find.
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_FOLD_CAUSES_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_FOLD_CAUSES_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// Per vertex: 1 if it is an end of a jog (`jog_edges`) or of an improper edge, a dangling end or a zipper.
template <class Traits>
std::vector<char> field_defect_vertices(const Tetrahedral_mesh_3<Traits>& mesh, const Singularity_graph& g,
                                        const std::vector<std::uint32_t>& jog_edges)
{
  std::vector<char> at(mesh.number_of_vertices(), 0);
  for(std::uint32_t e : jog_edges)
    for(auto v : mesh.edge_vertices(e)) at[v] = 1;
  for(std::uint32_t e = 0; e < mesh.number_of_edges(); ++e)
    if(!mesh.is_boundary_edge(e) && g.edge_valence[e] == 0)
      for(auto v : mesh.edge_vertices(e)) at[v] = 1;
  for(std::uint32_t v : g.dangling_vertices) at[v] = 1;
  for(std::uint32_t v : g.zipper_vertices) at[v] = 1;
  return at;
}

// Each folded tetrahedron of the seamless map in the first class that fits: flat in every map with a
// boundary face (two boundary lines or planes the constraints make one), flat in every map inside (three
// corners on one singular line), a corner at a defect of the field, a corner on the boundary, inside.
// `flat`: structurally_flat_tetrahedra(); `Causes`: Seamless_fold_causes.
template <class Traits, class Causes>
Causes classify_seamless_folds(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<std::uint32_t>& folds,
                               const std::vector<char>& flat, const std::vector<char>& defect_vertex)
{
  Causes c;
  for(std::uint32_t t : folds) {
    const auto& tv = mesh.tetrahedron_vertices(t);
    bool boundary_face = false, boundary_vertex = false, at_defect = false;
    for(int i = 0; i < 4; ++i) {
      boundary_face = boundary_face || mesh.is_boundary_face(mesh.tetrahedron_face(t, i));
      boundary_vertex = boundary_vertex || mesh.is_boundary_vertex(tv[i]);
      at_defect = at_defect || defect_vertex[tv[i]] != 0;
    }
    if(flat[t]) ++(boundary_face ? c.structural_at_boundary : c.structural_inside);
    else if(at_defect) ++c.at_field_defects;
    else if(boundary_vertex) ++c.at_boundary;
    else ++c.inside;
  }
  return c;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_SEAMLESS_FOLD_CAUSES_H
