// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_REFINE_TETRAHEDRAL_MESH_H
#define CGAL_HEXAHEDRAL_REMESHING_REFINE_TETRAHEDRAL_MESH_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/tetrahedron_subdivision.h>

#include <cmath>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Red refinement of a tetrahedral soup, `rounds` times: every tetrahedron is split 1-to-8 at its edge
/// midpoints (its four corner tetrahedra and the inner octahedron cut along its shortest diagonal, Bey
/// 1995), every tagged boundary triangle 1-to-4 and every feature edge in two, so that the refined
/// soup has the same boundary surface, patches, feature curves and corners. The points of `in` come
/// first, in order (the midpoints follow); each new tetrahedron keeps the source line of its parent.
/// A midpoint is computed in floating point, half the sum of two coordinates, and may be off a plane
/// through its edge by one rounding: the dihedral classes of the refined boundary are those of the input.
///
/// \param in the soup (as a reader or `tetrahedral_soup_from_mesh()` gives it); unchanged
/// \param out receives the refined soup (overwritten; may not be `in`)
/// \param rounds number of refinements, 0 to 4 (a round multiplies the tetrahedra by 8)
/// \throws Error if `rounds` is outside 0..4.
template <class Point>
void refine_tetrahedral_soup(const Tetrahedral_soup_3<Point>& in, Tetrahedral_soup_3<Point>& out, int rounds = 1)
{
  if(rounds < 0 || rounds > 4)
    throw Error("tetrahedron refinement: the number of rounds must be between 0 and 4, got " + std::to_string(rounds));
  out = in;
  for(int k = 0; k < rounds; ++k) {
    Tetrahedral_soup_3<Point> next;
    internal::Tetrahedron_subdivision<Point>(out, next).run();
    out = std::move(next);
  }
}

/// \ingroup PkgHexahedralRemeshingRef
/// The soup of a built mesh: its vertices (those of the input first, as the mesh keeps them), its
/// tetrahedra, its boundary triangles with their input patches, its edges with an input feature curve,
/// its corners, patch names and source. Building it again (`build_tetrahedral_mesh()`) gives the same
/// mesh, up to the order of its tetrahedra' vertices.
template <class Traits>
void tetrahedral_soup_from_mesh(const Tetrahedral_mesh_3<Traits>& mesh, Tetrahedral_soup_3<typename Traits::Point_3>& soup)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  soup = Tetrahedral_soup_3<typename Traits::Point_3>();
  soup.points = mesh.points();
  soup.source = mesh.source();
  soup.patch_names = mesh.surface_patch_names();
  for(Index t = 0; t < mesh.number_of_tetrahedra(); ++t) {
    const auto& tv = mesh.tetrahedron_vertices(t);
    soup.tetrahedra.push_back({std::size_t(tv[0]), std::size_t(tv[1]), std::size_t(tv[2]), std::size_t(tv[3])});
    soup.tetrahedron_lines.push_back(0);
  }
  for(Index b = 0; b < mesh.number_of_boundary_triangles(); ++b) {
    if(mesh.boundary_triangle_patch(b) < 0) continue;
    const auto& bv = mesh.boundary_triangle_vertices(b);
    soup.triangles.push_back({std::size_t(bv[0]), std::size_t(bv[1]), std::size_t(bv[2])});
    soup.triangle_patches.push_back(mesh.boundary_triangle_patch(b));
  }
  for(Index e = 0; e < mesh.number_of_edges(); ++e) {
    if(mesh.edge_curve(e) < 0) continue;
    const auto& ev = mesh.edge_vertices(e);
    soup.feature_edges.push_back({std::size_t(ev[0]), std::size_t(ev[1])});
    soup.feature_edge_curves.push_back(mesh.edge_curve(e));
  }
  for(Index v : mesh.corners()) soup.corners.push_back(std::size_t(v));
}

/// \ingroup PkgHexahedralRemeshingRef
/// Number of red refinement rounds (`refine_tetrahedral_soup()`) for `tetrahedra` tetrahedra of total
/// volume `volume` and hexahedra of edge `h`, with `density` tetrahedra per hexahedron (per volume `h^3`):
/// 0 if `density >= trigger`, else the fewest rounds (at least 1, at most `maximum_rounds`) after which
/// `density * 8^rounds >= minimum`. A frame field on tetrahedra not much finer than the hexahedra places
/// its singular curves and feature sectors at the scale of the tetrahedra: the HexMe mesh of the
/// 10-degree wedge (1.3 tetrahedra per hexahedron after the splits of the build) gives a collapsed map,
/// refined once a valid hex mesh; the MAMBO part B45 (8.2 per hexahedron) two flat hexahedra, refined
/// once a valid mesh. 0 for an invalid size or volume.
inline int tetrahedron_refinement_rounds(std::size_t tetrahedra, double volume, double h, double minimum = 6,
                                         double trigger = 12, int maximum_rounds = 2)
{
  if(!(h > 0) || !std::isfinite(h) || !(volume > 0) || !std::isfinite(volume) || tetrahedra == 0) return 0;
  const double hexahedra = volume / (h * h * h);
  double density = double(tetrahedra) / hexahedra;
  if(density >= trigger) return 0;
  int rounds = 0;
  do {
    density *= 8;
    ++rounds;
  } while(density < minimum && rounds < maximum_rounds);
  return rounds;
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_REFINE_TETRAHEDRAL_MESH_H
