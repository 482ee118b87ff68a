// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_3_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_3_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Where a hex vertex lies on the tetrahedral mesh it was extracted from: a simplex of the
/// tetrahedron `tetrahedron`, of dimension `dimension` (0 vertex, 1 edge, 2 face, 3 interior), given
/// by its local vertices `local_vertices[0..dimension]` (0..3 in that tetrahedron).
struct Hexahedral_vertex_location
{
  /// The tetrahedron (of the map or of the tetrahedral mesh); `null` if unknown.
  std::uint32_t tetrahedron = (std::numeric_limits<std::uint32_t>::max)();
  /// Dimension of the simplex (0..3), -1 if unknown.
  int dimension = -1;
  /// Local vertices (0..3) of the simplex in `tetrahedron`; the first `dimension + 1` are used.
  std::array<std::uint8_t, 4> local_vertices{ {0, 1, 2, 3} };
};

/// \ingroup PkgHexahedralRemeshingRef
/// A boundary quadrilateral of a hexahedral mesh: face `face` of hexahedron `hexahedron`, with the
/// surface patch of the input it lies on. The faces of a hexahedron are numbered as the faces
/// S1..S6 of Abaqus' and CalculiX's `C3D8` element (`face` 0 is S1): in VTK order, 0 = (0 1 2 3),
/// 1 = (4 5 6 7), 2 = (0 1 5 4), 3 = (1 2 6 5), 4 = (2 3 7 6), 5 = (3 0 4 7).
struct Hexahedral_boundary_quadrilateral
{
  /// The 4 vertices, counter-clockwise seen from outside the mesh.
  std::array<std::uint32_t, 4> vertices{ {0, 0, 0, 0} };
  /// The hexahedron the quadrilateral bounds.
  std::uint32_t hexahedron = 0;
  /// Local face (0..5, see above) of `hexahedron`.
  std::uint8_t face = 0;
  /// Surface patch: the CAD face (STEP, BREP, IGES, `.msh` entity tag), the patch of a C3t3 or of a
  /// tagged MEDIT/VTK input, or a region between sharp edges numbered from 0; -1 if unknown.
  int patch = -1;
};

/// \ingroup PkgHexahedralRemeshingRef
/// A hex edge on a feature curve of the input (a sharp edge: where two surface patches meet).
struct Hexahedral_feature_edge
{
  /// The 2 vertices.
  std::array<std::uint32_t, 2> vertices{ {0, 0} };
  /// The feature curve: the CAD curve (entity tag), the curve id of the input, or, without them, a
  /// number per pair of patches that meet; -1 if unknown.
  int curve = -1;
};

/// \ingroup PkgHexahedralRemeshingRef
/// A hexahedral mesh: points, hexahedra as 8 vertex indices in VTK order, and the provenance of every
/// vertex and hexahedron when the mesh was extracted from an integer-grid map.
///
/// VTK order (`VTK_HEXAHEDRON`, also MEDIT's and gmsh's): vertices 0..3 are the bottom quad, 4..7 the
/// top quad with `i + 4` above `i`; in a hex's own parameter chart they are
/// `(0,0,0) (1,0,0) (1,1,0) (0,1,0) (0,0,1) (1,0,1) (1,1,1) (0,1,1)`, so that a positively oriented
/// hexahedron has a positive volume. Optional arrays are either empty or of full size.
struct Hexahedral_mesh_3
{
  /// Point type.
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point_3;
  /// Index of a vertex or hexahedron.
  typedef std::uint32_t Index;

  /// Bits of `vertex_tags`.
  enum Vertex_tag : std::uint8_t {
    /// On the boundary surface.
    BOUNDARY = 1,
    /// On a feature curve of the input.
    FEATURE_CURVE = 2,
    /// On a corner of the input.
    CORNER = 4
  };

  /// Vertex positions (model units).
  std::vector<Point_3> points;
  /// Hexahedra, 8 vertex indices each, VTK order.
  std::vector<std::array<Index, 8> > hexahedra;
  /// Per vertex: the simplex of the source tetrahedral mesh it lies on (optional).
  std::vector<Hexahedral_vertex_location> vertex_locations;
  /// Per vertex: an OR of `Vertex_tag` bits (optional).
  std::vector<std::uint8_t> vertex_tags;
  /// Per hexahedron: the tetrahedron of the source mesh that contains its centre (optional).
  std::vector<Index> hexahedron_source_tetrahedra;
  /// The boundary quadrilaterals with their surface patch (optional; filled by
  /// `hexahedral_remeshing()` and `compute_hexahedral_boundary_groups()`), sorted by patch, then
  /// hexahedron and face. Solver formats write one boundary group per patch.
  std::vector<Hexahedral_boundary_quadrilateral> boundary_quadrilaterals;
  /// The hex edges on feature curves with their curve (optional, filled with `boundary_quadrilaterals`).
  std::vector<Hexahedral_feature_edge> feature_edges;
  /// Names of surface patches given by the input (CAD face names, physical group names), as
  /// (patch, name) pairs sorted by patch; a patch without a name is written `patch_<id>`.
  std::vector<std::pair<int, std::string> > patch_names;

  /// Number of vertices.
  std::size_t number_of_vertices() const { return points.size(); }
  /// Number of hexahedra.
  std::size_t number_of_hexahedra() const { return hexahedra.size(); }
  /// Removes everything.
  void clear()
  {
    points.clear(); hexahedra.clear(); vertex_locations.clear(); vertex_tags.clear();
    hexahedron_source_tetrahedra.clear(); boundary_quadrilaterals.clear(); feature_edges.clear(); patch_names.clear();
  }
};

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_3_H
