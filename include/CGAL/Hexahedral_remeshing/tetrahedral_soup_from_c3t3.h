// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRAL_SOUP_FROM_C3T3_H
#define CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRAL_SOUP_FROM_C3T3_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <map>
#include <unordered_map>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Converts the cells of a `Mesh_complex_3_in_triangulation_3` into a soup: every cell in the
/// complex becomes a tetrahedron (whatever its subdomain), the facets in the complex become tagged
/// triangles (one patch id per distinct `Surface_patch_index`, numbered in increasing order), the
/// edges in the complex become feature edges (one curve id per distinct `Curve_index`), and the
/// vertices in the complex (corners) become corners.
///
/// \tparam C3T3 a model of `MeshComplex_3InTriangulation_3`
/// \throws Input_error if the complex has no cell.
template <class C3T3, class Point>
void tetrahedral_soup_from_c3t3(const C3T3& c3t3, Tetrahedral_soup_3<Point>& soup)
{
  typedef typename C3T3::Triangulation Tr;
  typedef typename Tr::Vertex_handle Vertex_handle;
  const std::string source = soup.source.empty() ? std::string("<C3t3>") : soup.source;
  soup = Tetrahedral_soup_3<Point>();
  soup.source = source;
  const Tr& tr = c3t3.triangulation();
  auto construct_point = tr.geom_traits().construct_point_3_object();

  std::unordered_map<Vertex_handle, std::size_t> index;
  auto vertex_index = [&](Vertex_handle v) {
    auto it = index.find(v);
    if(it != index.end()) return it->second;
    const auto& p = construct_point(tr.point(v));
    soup.points.push_back(Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
    index.emplace(v, soup.points.size() - 1);
    return soup.points.size() - 1;
  };
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    soup.tetrahedra.push_back({vertex_index(c->vertex(0)), vertex_index(c->vertex(1)),
                               vertex_index(c->vertex(2)), vertex_index(c->vertex(3))});
  if(soup.tetrahedra.empty()) throw Input_error(source, 0, "the complex has no cells");

  std::map<typename C3T3::Surface_patch_index, int> patch_ids;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    patch_ids.emplace(c3t3.surface_patch_index(*f), 0);
  int next = 0;
  for(auto& p : patch_ids) p.second = next++;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    const int i = f->second;
    soup.triangles.push_back({vertex_index(f->first->vertex((i + 1) % 4)), vertex_index(f->first->vertex((i + 2) % 4)),
                              vertex_index(f->first->vertex((i + 3) % 4))});
    soup.triangle_patches.push_back(patch_ids[c3t3.surface_patch_index(*f)]);
  }

  std::map<typename C3T3::Curve_index, int> curve_ids;
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e)
    curve_ids.emplace(c3t3.curve_index(*e), 0);
  next = 0;
  for(auto& c : curve_ids) c.second = next++;
  for(auto e = c3t3.edges_in_complex_begin(); e != c3t3.edges_in_complex_end(); ++e) {
    const auto& cell = e->first;
    soup.feature_edges.push_back({vertex_index(cell->vertex(e->second)), vertex_index(cell->vertex(e->third))});
    soup.feature_edge_curves.push_back(curve_ids[c3t3.curve_index(*e)]);
  }
  for(auto v = c3t3.vertices_in_complex_begin(); v != c3t3.vertices_in_complex_end(); ++v)
    soup.corners.push_back(vertex_index(v));
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRAL_SOUP_FROM_C3T3_H
