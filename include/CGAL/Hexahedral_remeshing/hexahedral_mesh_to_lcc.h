// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_TO_LCC_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_TO_LCC_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

namespace internal {

// The patch of every boundary quad as the 2-attribute of its 3-free facet, when `LCC` has 2-attributes
// (their info constructible from an int); faces are found by the positions of their 4 vertices.
template <class LCC>
void set_lcc_patch_attributes(const Hexahedral_mesh_3& hexes, LCC& lcc)
{
  typedef typename LCC::template Attribute_type<2>::type Face_attribute;
  if constexpr(!std::is_same<Face_attribute, CGAL::Void>::value) {
    if(hexes.boundary_quadrilaterals.empty()) return;
    std::map<std::array<double, 3>, Hexahedral_mesh_3::Index> vertex_at;
    for(std::size_t v = 0; v < hexes.points.size(); ++v)
      vertex_at[{ {hexes.points[v].x(), hexes.points[v].y(), hexes.points[v].z()} }] = Hexahedral_mesh_3::Index(v);
    std::map<std::array<Hexahedral_mesh_3::Index, 4>, int> patch_of;
    for(const auto& q : hexes.boundary_quadrilaterals) {
      std::array<Hexahedral_mesh_3::Index, 4> key = q.vertices;
      std::sort(key.begin(), key.end());
      patch_of[key] = q.patch;
    }
    for(auto d = lcc.darts().begin(); d != lcc.darts().end(); ++d) {
      if(!lcc.is_free(d, 3) || lcc.template attribute<2>(d) != nullptr) continue;
      std::array<Hexahedral_mesh_3::Index, 4> key;
      std::size_t k = 0;
      const typename LCC::Dart_handle start = d;
      typename LCC::Dart_handle e = start;
      do {
        const auto& p = lcc.point(e);
        const auto it = vertex_at.find({ {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())} });
        if(it == vertex_at.end() || k == 4) { k = 5; break; }
        key[k++] = it->second;
        e = lcc.beta(e, 1);
      } while(e != start);
      if(k != 4) continue;
      std::sort(key.begin(), key.end());
      const auto found = patch_of.find(key);
      if(found != patch_of.end()) lcc.template set_attribute<2>(start, lcc.template create_attribute<2>(found->second));
    }
  }
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Converts `hexes` into CGAL's volume-mesh structure, a 3D linear cell complex (by default
/// `CGAL::Linear_cell_complex_for_combinatorial_map<3>`, https://doc.cgal.org/5.5.1/Linear_cell_complex/):
/// one `make_hexahedron()` per hexahedron, then `sew3_same_facets()`, which 3-sews the facets with
/// the same points in opposite orientations. The hexahedra are appended to `lcc` (clear it first to
/// get the mesh alone).
///
/// On a valid mesh (`check_hexahedral_mesh()` reports `valid`) the result has one 3-cell per
/// hexahedron, one 0-cell per used vertex and one 3-free facet per boundary quad. Faces are matched
/// by their points, not by the vertex ids: two distinct vertices at the same position (a crack, counted
/// in `Hexahedral_mesh_check::duplicate_vertices`) are glued.
///
/// The VTK order of `hexes` (bottom quad 0..3, `i + 4` above `i`) maps to CGAL's
/// `make_hexahedron(p0, ..., p7)` order (bottom 0..3, top 5, 6, 7, 4 above 0, 1, 2, 3) as
/// `(v0, v1, v2, v3, v7, v4, v5, v6)`.
///
/// When `LCC` has 2-attributes (an items class whose `Attributes` tuple has a
/// `Cell_attribute<Refs, Info>` in position 2, `Info` constructible from an `int`) and `hexes` has its
/// `boundary_quadrilaterals`, every 3-free facet (boundary quad) gets the attribute of its surface
/// patch (the CAD face): the boundary groups of the solver formats, in the complex.
///
/// \tparam LCC a `Linear_cell_complex_for_combinatorial_map` of dimension 3 and ambient dimension 3
///         whose `Point` is constructible from three doubles.
/// \returns one dart per hexahedron, in the order of `hexes.hexahedra` (the dart that
///          `make_hexahedron()` returns, incident to vertex 0).
/// \throws Error if a hexahedron refers to a missing vertex.
template <class LCC>
std::vector<typename LCC::Dart_handle> hexahedral_mesh_to_lcc(const Hexahedral_mesh_3& hexes, LCC& lcc)
{
  static_assert(LCC::dimension == 3 && LCC::ambient_dimension == 3, "a 3D linear cell complex in 3D is required");
  typedef typename LCC::Point Point;
  std::vector<typename LCC::Dart_handle> darts;
  darts.reserve(hexes.hexahedra.size());
  for(std::size_t h = 0; h < hexes.hexahedra.size(); ++h)
    for(auto v : hexes.hexahedra[h])
      if(v >= hexes.points.size())
        throw Error("hexahedral_mesh_to_lcc: hexahedron " + std::to_string(h) + " has vertex index " +
                    std::to_string(v) + " out of range");
  auto point = [&](Hexahedral_mesh_3::Index v) {
    const auto& p = hexes.points[v];
    return Point(p.x(), p.y(), p.z());
  };
  for(const auto& h : hexes.hexahedra)
    darts.push_back(lcc.make_hexahedron(point(h[0]), point(h[1]), point(h[2]), point(h[3]),
                                        point(h[7]), point(h[4]), point(h[5]), point(h[6])));
  lcc.sew3_same_facets();
  internal::set_lcc_patch_attributes(hexes, lcc);
  return darts;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Same as `hexahedral_mesh_to_lcc(hexes, lcc)` into a new
/// `CGAL::Linear_cell_complex_for_combinatorial_map<3>` (points of
/// `CGAL::Exact_predicates_inexact_constructions_kernel`).
inline CGAL::Linear_cell_complex_for_combinatorial_map<3> hexahedral_mesh_to_lcc(const Hexahedral_mesh_3& hexes)
{
  CGAL::Linear_cell_complex_for_combinatorial_map<3> lcc;
  hexahedral_mesh_to_lcc(hexes, lcc);
  return lcc;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_TO_LCC_H
