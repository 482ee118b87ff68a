// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_3_H
#define CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_3_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cstdint>
#include <limits>
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

  /// Number of vertices.
  std::size_t number_of_vertices() const { return points.size(); }
  /// Number of hexahedra.
  std::size_t number_of_hexahedra() const { return hexahedra.size(); }
  /// Removes everything.
  void clear()
  {
    points.clear(); hexahedra.clear(); vertex_locations.clear(); vertex_tags.clear();
    hexahedron_source_tetrahedra.clear();
  }
};

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_HEXAHEDRAL_MESH_3_H
