// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_JOG_REFINEMENT_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_JOG_REFINEMENT_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/field_diagnostics.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The edges that close a singular jog: the third edge (a, c) of a face whose two other edges (a, b),
// (b, c) are singular (valence 3 or 5), if it is interior and regular and if the curve goes on
// through b along its holonomy axis w (the axis of (a, b) in world coordinates): (b - a).w and
// (c - b).w of one sign. The map puts both singular edges on one integer line, so the face's three
// corners are collinear and the tetrahedra of the face are flat in every map (structurally_flat.h);
// with the edge split, the new vertex is free and no face has three corners on the line. Where the
// curve doubles back (b not between a and c on the line), the opened tetrahedra would be inverted
// (measured on HexMe i01c: 77 -> 154 inverted tetrahedra with every such edge split): left flat.
template <class Traits>
std::vector<std::uint32_t> jog_chords(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames,
                                      const Singularity_graph& g)
{
  const std::size_t ne = mesh.number_of_edges();
  auto singular = [&](std::uint32_t e) { return !mesh.is_boundary_edge(e) && (g.edge_valence[e] == 3 || g.edge_valence[e] == 5); };
  auto goes_on = [&](std::uint32_t ab, std::uint32_t bc) {
    const auto& e1 = mesh.edge_vertices(ab);
    const auto& e2 = mesh.edge_vertices(bc);
    const std::uint32_t b = (e1[0] == e2[0] || e1[0] == e2[1]) ? e1[0] : e1[1];
    const std::uint32_t a = e1[0] == b ? e1[1] : e1[0], c = e2[0] == b ? e2[1] : e2[0];
    const Eigen::Vector3d w = frames[*mesh.edge_ring(ab).begin()] * octahedral_group().axis(g.edge_holonomy[ab]);
    return (vertex_point(mesh, b) - vertex_point(mesh, a)).dot(w) * (vertex_point(mesh, c) - vertex_point(mesh, b)).dot(w) > 0;
  };
  std::vector<char> chord(ne, 0);
  for(std::uint32_t f = 0; f < mesh.number_of_faces(); ++f) {
    const auto& v = mesh.face_vertices(f);
    const std::array<std::uint32_t, 3> e = {{mesh.find_edge(v[1], v[2]), mesh.find_edge(v[2], v[0]), mesh.find_edge(v[0], v[1])}};
    std::array<std::uint32_t, 3> order = e;
    std::partition(order.begin(), order.end(), singular);
    if(!singular(order[0]) || !singular(order[1]) || singular(order[2]) || mesh.is_boundary_edge(order[2])) continue;
    if(goes_on(order[0], order[1])) chord[order[2]] = 1;
  }
  std::vector<std::uint32_t> chords;
  for(std::uint32_t e = 0; e < ne; ++e)
    if(chord[e]) chords.push_back(e);
  return chords;
}

// A field on a refined copy of a mesh: the tetrahedra of the copy come from `origin` in the input mesh.
template <class Traits>
struct Refined_field
{
  Tetrahedral_mesh_3<Traits> mesh;
  std::vector<Eigen::Matrix3d> frames;
  Matchings matchings;
  Singularity_graph singularities;
  std::vector<std::uint32_t> origin;
};

// Splits the edges `chords` of `mesh` at their midpoints, one after the other (every tetrahedron of
// an edge's ring into two, each keeping its orientation), as a soup; origin[t]: the input tetrahedron.
template <class Traits>
Tetrahedral_soup_3<typename Traits::Point_3> split_edges(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<std::uint32_t>& chords,
                                                         std::vector<std::uint32_t>& origin)
{
  Tetrahedral_soup_3<typename Traits::Point_3> soup;
  soup.source = mesh.source();
  soup.points = mesh.points();
  std::vector<std::vector<std::uint32_t> > vertex_tets(soup.points.size());
  for(std::uint32_t t = 0; t < mesh.number_of_tetrahedra(); ++t) {
    const auto& tv = mesh.tetrahedron_vertices(t);
    soup.tetrahedra.push_back({{tv[0], tv[1], tv[2], tv[3]}});
    origin.push_back(t);
    for(auto v : tv) vertex_tets[v].push_back(t);
  }
  for(std::uint32_t e : chords) {
    const std::size_t a = mesh.edge_vertices(e)[0], c = mesh.edge_vertices(e)[1];
    const std::size_t m = soup.points.size();
    soup.points.push_back(CGAL::midpoint(soup.points[a], soup.points[c]));
    vertex_tets.emplace_back();
    std::vector<std::uint32_t> ring;
    for(std::uint32_t t : vertex_tets[a])
      if(std::count(soup.tetrahedra[t].begin(), soup.tetrahedra[t].end(), c)) ring.push_back(t);
    for(std::uint32_t t : ring) {
      std::array<std::size_t, 4> copy = soup.tetrahedra[t];
      std::replace(soup.tetrahedra[t].begin(), soup.tetrahedra[t].end(), c, m); // t keeps a
      std::replace(copy.begin(), copy.end(), a, m);                              // the copy keeps c
      const std::uint32_t u = std::uint32_t(soup.tetrahedra.size());
      soup.tetrahedra.push_back(copy);
      origin.push_back(origin[t]);
      auto& at_c = vertex_tets[c];
      at_c.erase(std::remove(at_c.begin(), at_c.end(), t), at_c.end());
      for(std::size_t v : copy) vertex_tets[v].push_back(u);
      vertex_tets[m].push_back(t);
    }
  }
  return soup;
}

// The field of `mesh` carried to the copy of `mesh` with the jog chords split: every tetrahedron
// keeps its origin's frame; a face inside an input tetrahedron gets the identity matching, a face
// inside an input face that face's matching (taken from the side of the copy's first tetrahedron);
// the singularity graph is recomputed (the input's singular edges keep their holonomy; the new edges
// are regular). Returns false if there is no chord.
template <class Traits>
bool refine_jogs(const Tetrahedral_mesh_3<Traits>& mesh, const std::vector<Eigen::Matrix3d>& frames, const Matchings& matchings,
                 const Singularity_graph& singularities, Refined_field<Traits>& out)
{
  const std::vector<std::uint32_t> chords = jog_chords(mesh, frames, singularities);
  if(chords.empty()) return false;
  std::vector<std::uint32_t> origin;
  const auto soup = split_edges(mesh, chords, origin);
  build_tetrahedral_mesh(soup, out.mesh,
                         parameters::split_multi_boundary_tetrahedra(
                           false, parameters::split_boundary_chords(false, parameters::coincident_vertices(Coincident_vertices::KEEP))));
  const std::size_t nt = out.mesh.number_of_tetrahedra();
  out.origin.resize(nt);
  out.frames.resize(nt);
  for(std::uint32_t t = 0; t < nt; ++t) {
    out.origin[t] = origin[out.mesh.tetrahedron_input_index(t)];
    out.frames[t] = frames[out.origin[t]];
  }
  out.matchings.face_matching.assign(out.mesh.number_of_faces(), -1);
  out.matchings.face_angle.assign(out.mesh.number_of_faces(), 0.0);
  for(std::uint32_t f = 0; f < out.mesh.number_of_faces(); ++f) {
    if(out.mesh.is_boundary_face(f)) continue;
    const auto& ft = out.mesh.face_tetrahedra(f);
    const std::uint32_t o0 = out.origin[ft[0]], o1 = out.origin[ft[1]];
    out.matchings.face_matching[f] = Octahedral_group::identity_index;
    if(o0 == o1) continue;
    for(int i = 0; i < 4; ++i)
      if(mesh.tetrahedron_neighbor(o0, i) == o1) {
        const auto old = mesh.tetrahedron_face(o0, i);
        out.matchings.face_matching[f] = matchings.step(mesh, old, o0);
        out.matchings.face_angle[f] = matchings.face_angle[old];
      }
  }
  out.singularities = compute_singularity_graph(out.mesh, out.frames, out.matchings);
  return true;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_JOG_REFINEMENT_H
