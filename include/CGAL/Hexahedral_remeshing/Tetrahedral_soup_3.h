// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRAL_SOUP_3_H
#define CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRAL_SOUP_3_H

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {

/// \ingroup PkgHexahedralRemeshingRef
/// Raw input of `Tetrahedral_mesh_3`: points, tetrahedra as vertex indices, and optional feature hints
/// (tagged boundary triangles, feature edges, corners) as the readers find them in a file.
/// Nothing is checked here: the checks happen when the mesh is built.
template <class Point>
struct Tetrahedral_soup_3
{
  /// Vertex positions.
  std::vector<Point> points;
  /// Tetrahedra, any orientation (inverted ones are re-oriented when building).
  std::vector<std::array<std::size_t, 4> > tetrahedra;
  /// 1-based line in `source` of each tetrahedron (0 if unknown), used in error messages.
  std::vector<std::size_t> tetrahedron_lines;
  /// Tagged boundary triangles (hints: the boundary itself is recovered from the tetrahedra).
  std::vector<std::array<std::size_t, 3> > triangles;
  /// Surface patch id of each tagged triangle.
  std::vector<int> triangle_patches;
  /// Feature edges (pairs of vertex indices).
  std::vector<std::array<std::size_t, 2> > feature_edges;
  /// Feature curve id of each feature edge.
  std::vector<int> feature_edge_curves;
  /// Corner vertices.
  std::vector<std::size_t> corners;
  /// Names of surface patches given by the input (gmsh physical group names, CAD face names), as
  /// (patch id, name) pairs.
  std::vector<std::pair<int, std::string> > patch_names;
  /// Name of the source (file name) for error messages; empty for in-memory data.
  std::string source;
};

} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_TETRAHEDRAL_SOUP_3_H
