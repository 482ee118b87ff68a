// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_BOUNDARY_GROUPS_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_BOUNDARY_GROUPS_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_smoothing.h>
#include <CGAL/Hexahedral_remeshing/internal/hex_smoothing/reference_features.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/boundary_groups.h>

#include <set>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Counts of the boundary groups of a hexahedral mesh (`compute_hexahedral_boundary_groups()`).
struct Hexahedral_boundary_groups_report
{
  /// Boundary quadrilaterals (quads used by one hexahedron).
  std::size_t boundary_quadrilaterals = 0;
  /// Distinct surface patches among them.
  std::size_t patches = 0;
  /// Hex edges where two patches meet.
  std::size_t feature_edges = 0;
  /// Distinct feature curves among them.
  std::size_t curves = 0;
};

namespace internal {

inline Hexahedral_boundary_groups_report boundary_groups_report(const Hexahedral_mesh_3& hexes)
{
  Hexahedral_boundary_groups_report r;
  std::set<int> patches, curves;
  for(const auto& q : hexes.boundary_quadrilaterals) patches.insert(q.patch);
  for(const auto& e : hexes.feature_edges) curves.insert(e.curve);
  r.boundary_quadrilaterals = hexes.boundary_quadrilaterals.size();
  r.patches = patches.size();
  r.feature_edges = hexes.feature_edges.size();
  r.curves = curves.size();
  return r;
}

inline Patch_surface patch_surface(const Hexahedral_smoothing_reference& reference, const std::vector<int>& triangle_patch)
{
  Patch_surface s;
  for(const auto& t : reference.triangles)
    s.triangles.emplace_back(reference.points[t[0]], reference.points[t[1]], reference.points[t[2]]);
  s.triangle_patch = triangle_patch;
  return s;
}

} // namespace internal

/// \ingroup PkgHexahedralRemeshingRef
/// Fills `hexes.boundary_quadrilaterals` and `hexes.feature_edges` from the tetrahedral mesh the hex
/// mesh was made from: every boundary quadrilateral gets the surface patch of the input it lies on
/// (the CAD face for STEP, BREP, IGES and `.msh` input, the patch of a C3t3 or of a tagged MEDIT or
/// VTK input), and, when the input has no patches or a single unnamed one (boundary triangles without
/// tags, as in the MAMBO VTK files: one group for the whole boundary is no group a solver can load), the
/// region between sharp edges it lies in (edges whose dihedral angle differs from flat by more than
/// `sharp_angle` degrees, and the input's feature curves), numbered from 0. A quad takes the patch most of five of its points (its centre,
/// and halfway from the centre to each corner) are closest to. Every hex edge between quads of two
/// patches is a feature edge, with the input's feature curve nearest to its midpoint (within a
/// quarter of its length; an input with a single curve id has none), else a number per pair of patches. The names of the input's patches
/// (`surface_patch_names()`: gmsh physical groups, named CAD faces) go to `hexes.patch_names`.
///
/// \param hexes the hexahedral mesh, in the model units of `mesh` (positions as they are final)
/// \param mesh the tetrahedral mesh of the solid
/// \param sharp_angle in degrees, for an input without patches
/// \returns the counts of quads, patches, feature edges and curves.
template <class Traits>
Hexahedral_boundary_groups_report compute_hexahedral_boundary_groups(Hexahedral_mesh_3& hexes,
                                                                     const Tetrahedral_mesh_3<Traits>& mesh,
                                                                     double sharp_angle = 30.)
{
  typedef std::uint32_t Id;
  Hexahedral_smoothing_reference reference = make_hexahedral_smoothing_reference(mesh);
  std::vector<int> triangle_patch(mesh.number_of_boundary_triangles(), -1);
  const bool input_patches = mesh.number_of_surface_patches() > 1 || !mesh.surface_patch_names().empty();
  if(input_patches)
    for(std::size_t b = 0; b < triangle_patch.size(); ++b) triangle_patch[b] = mesh.boundary_triangle_patch(Id(b));
  else
    triangle_patch = internal::reference_patches(reference, sharp_angle * CGAL_PI / 180., false);
  internal::Patch_surface surface = internal::patch_surface(reference, triangle_patch);
  // a single curve id (line cells without tags, as in the MAMBO files) names no curve: the edges are
  // numbered per pair of patches instead
  for(Id e : mesh.boundary_edges()) {
    if(mesh.edge_curve(e) < 0 || mesh.number_of_feature_curves() < 2) continue;
    const auto& ev = mesh.edge_vertices(e);
    surface.segments.emplace_back(reference.points[ev[0]], reference.points[ev[1]]);
    surface.segment_curve.push_back(mesh.edge_curve(e));
  }
  internal::assign_boundary_groups(hexes, surface);
  hexes.patch_names.clear();
  if(input_patches) hexes.patch_names = mesh.surface_patch_names();
  return internal::boundary_groups_report(hexes);
}

/// \ingroup PkgHexahedralRemeshingRef
/// As above, with a smoothing reference (a triangle surface with its feature polylines, e.g. read
/// from a surface file by `hexmesh smooth`) as the surface: patches are the regions between its
/// sharp edges (`sharp_angle` degrees) and its feature polylines, numbered from 0; feature curve `i`
/// is polyline `i`.
inline Hexahedral_boundary_groups_report compute_hexahedral_boundary_groups(Hexahedral_mesh_3& hexes,
                                                                            const Hexahedral_smoothing_reference& reference,
                                                                            double sharp_angle = 30.)
{
  Hexahedral_smoothing_reference copy = reference;
  const std::vector<int> triangle_patch = internal::reference_patches(copy, sharp_angle * CGAL_PI / 180., false);
  internal::Patch_surface surface = internal::patch_surface(reference, triangle_patch);
  for(std::size_t i = 0; i < reference.feature_polylines.size(); ++i)
    for(std::size_t k = 0; k + 1 < reference.feature_polylines[i].size(); ++k) {
      surface.segments.emplace_back(reference.feature_polylines[i][k], reference.feature_polylines[i][k + 1]);
      surface.segment_curve.push_back(int(i));
    }
  internal::assign_boundary_groups(hexes, surface);
  return internal::boundary_groups_report(hexes);
}

/// \ingroup PkgHexahedralRemeshingRef
/// As above, with the hex mesh's own boundary as the surface (no input at hand, e.g. a hex mesh
/// extracted from a `.hexex` map or read from a file): patches are the regions of boundary quads
/// between hex edges whose dihedral angle differs from flat by more than `sharp_angle` degrees.
inline Hexahedral_boundary_groups_report compute_hexahedral_boundary_groups(Hexahedral_mesh_3& hexes,
                                                                            double sharp_angle = 30.)
{
  Hexahedral_smoothing_reference own;
  own.points = hexes.points;
  for(const auto& q : internal::boundary_quadrilaterals_of(hexes)) {
    own.triangles.push_back({ {q.vertices[0], q.vertices[1], q.vertices[2]} });
    own.triangles.push_back({ {q.vertices[0], q.vertices[2], q.vertices[3]} });
  }
  return compute_hexahedral_boundary_groups(hexes, own, sharp_angle);
}

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_BOUNDARY_GROUPS_H
