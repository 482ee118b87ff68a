// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_COMPLEX_ELEMENTS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_COMPLEX_ELEMENTS_H

#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/edge_rings.h>
#include <CGAL/Hexahedral_remeshing/internal/union_find.h>

#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace motorcycle {

// The cells of the complex over the traced mesh: blocks (tetrahedra connected across faces that are
// neither walls nor boundary), patches (wall and boundary faces connected across edges where the
// sheet goes on flat), arcs (chains of the other edges of patch faces: where sheets meet, fold, or
// a curve runs) and nodes (where arcs meet or the patches along an arc change).
struct Complex_elements
{
  std::vector<std::uint32_t> block_of_tetrahedron;
  std::size_t blocks = 0, patches = 0, arcs = 0, nodes = 0;
  std::vector<std::array<std::uint32_t, 2> > arc_edges;  // vertices of every edge on an arc
  std::vector<std::uint32_t> arc_of_edge;                // per arc edge
  std::vector<std::uint32_t> node_vertices;
};

namespace elements_detail {

typedef std::array<std::uint32_t, 3> Face_key;

struct Patch_faces
{
  std::map<Face_key, std::uint32_t> index;
  std::vector<std::pair<std::size_t, int> > face; // a tetrahedron and its face
};

inline Patch_faces patch_faces(const Exact_map_mesh& mesh)
{
  Patch_faces p;
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    for(int f = 0; f < 4; ++f)
      if(mesh.tetrahedra[t].wall[std::size_t(f)] != NOT_A_WALL &&
         p.index.emplace(Exact_map_mesh::face_key(mesh.tetrahedra[t], f), std::uint32_t(p.face.size())).second)
        p.face.emplace_back(t, f);
  return p;
}

// Per edge of a patch face: whether it is on an arc, the patch faces around it.
struct Edge_class
{
  bool arc = false;
  std::vector<std::uint32_t> faces;
};

inline std::map<std::pair<std::uint32_t, std::uint32_t>, Edge_class> classify_edges(const Exact_map_mesh& mesh, const Patch_faces& p)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, Edge_class> edges;
  for(const auto& tf : p.face) {
    const Map_tetrahedron& T = mesh.tetrahedra[tf.first];
    for(int a = 0; a < 4; ++a)
      for(int b = a + 1; b < 4; ++b) {
        if(a == tf.second || b == tf.second) continue;
        std::uint32_t x = T.vertex[std::size_t(a)], y = T.vertex[std::size_t(b)];
        if(x > y) std::swap(x, y);
        auto inserted = edges.emplace(std::make_pair(x, y), Edge_class());
        if(!inserted.second) continue;
        const Edge_ring ring = ring_of_edge(mesh, tf.first, x, y);
        std::vector<const Ring_face*> on_sheets;
        for(const Ring_face& r : ring.faces)
          if(mesh.tetrahedra[r.tet].wall[std::size_t(r.face)] != NOT_A_WALL) {
            on_sheets.push_back(&r);
            inserted.first->second.faces.push_back(p.index.at(Exact_map_mesh::face_key(mesh.tetrahedra[r.tet], r.face)));
          }
        const bool singular = ring.closed && !ring.holonomy.R.is_identity();
        inserted.first->second.arc = !ring.seamless || singular || on_sheets.size() != 2 ||
                                     !coplanar(mesh, *on_sheets[0], *on_sheets[1]);
      }
  }
  return edges;
}

} // namespace elements_detail

inline Complex_elements complex_elements(const Exact_map_mesh& mesh)
{
  using namespace elements_detail;
  Complex_elements c;
  Union_find blocks(mesh.tetrahedra.size());
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    for(std::size_t f = 0; f < 4; ++f)
      if(mesh.tetrahedra[t].wall[f] == NOT_A_WALL) blocks.unite(std::uint32_t(t), std::uint32_t(mesh.tetrahedra[t].neighbor[f]));
  c.block_of_tetrahedron = blocks.labels(c.blocks);

  const Patch_faces p = patch_faces(mesh);
  const auto edges = classify_edges(mesh, p);
  Union_find patches(p.face.size());
  for(const auto& e : edges)
    if(!e.second.arc) patches.unite(e.second.faces[0], e.second.faces[1]);
  const std::vector<std::uint32_t> patch = patches.labels(c.patches);

  // arcs: arc edges joined at vertices with two arc edges along the same patches
  std::map<std::uint32_t, std::vector<std::uint32_t> > at_vertex;
  std::vector<std::set<std::uint32_t> > sides;
  for(const auto& e : edges) {
    if(!e.second.arc) continue;
    const std::uint32_t i = std::uint32_t(c.arc_edges.size());
    c.arc_edges.push_back({{e.first.first, e.first.second}});
    std::set<std::uint32_t> s;
    for(std::uint32_t f : e.second.faces) s.insert(patch[f]);
    sides.push_back(s);
    at_vertex[e.first.first].push_back(i);
    at_vertex[e.first.second].push_back(i);
  }
  Union_find arcs(c.arc_edges.size());
  for(const auto& v : at_vertex) {
    if(v.second.size() == 2 && sides[v.second[0]] == sides[v.second[1]]) arcs.unite(v.second[0], v.second[1]);
    else c.node_vertices.push_back(v.first);
  }
  c.arc_of_edge = arcs.labels(c.arcs);
  c.nodes = c.node_vertices.size();
  return c;
}

} // namespace motorcycle
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_MOTORCYCLE_COMPLEX_COMPLEX_ELEMENTS_H
