// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_HEXAHEDRAL_MESH_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_HEXAHEDRAL_MESH_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/IO/write_Abaqus.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTU.h>
#include <CGAL/Hexahedral_remeshing/IO/write_gmsh.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_hex_writer {

// A file that refers to missing vertices is worse than no file: reject before writing.
inline void check_writable(const std::string& filename, const Hexahedral_mesh_3& hexes)
{
  internal::check_hexahedra_in_range(filename, hexes);
  if(!hexes.vertex_tags.empty() && hexes.vertex_tags.size() != hexes.points.size())
    throw Error(filename + ": vertex_tags has " + std::to_string(hexes.vertex_tags.size()) + " values for " +
                std::to_string(hexes.points.size()) + " vertices");
  if(!hexes.hexahedron_source_tetrahedra.empty() &&
     hexes.hexahedron_source_tetrahedra.size() != hexes.hexahedra.size())
    throw Error(filename + ": hexahedron_source_tetrahedra has " +
                std::to_string(hexes.hexahedron_source_tetrahedra.size()) + " values for " +
                std::to_string(hexes.hexahedra.size()) + " hexahedra");
}

} // namespace internal_hex_writer

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `hexes` as a MEDIT ASCII `.mesh` file (`MeshVersionFormatted 1`, `Dimension 3`):
/// `Vertices` (x y z, reference = the `Hexahedral_mesh_3::Vertex_tag` bits, 0 without tags) and
/// `Hexahedra` (8 indices, 1-based, in VTK order, which is MEDIT's; reference 1), the boundary
/// `Quadrilaterals` (outward; reference = their surface patch, 0 if unknown) and the feature `Edges`
/// (reference = their curve + 1). A mesh without boundary groups is grouped by its own sharp edges
/// (`compute_hexahedral_boundary_groups()` on a copy). Vertex `v` and hexahedron `h` of the file
/// are `v` and `h` of `hexes`. HexaLab (hexalab.net) and gmsh open it;
/// `read_hexahedral_mesh()` reads it back. The file is written atomically (`write_file_atomically()`).
/// \throws Error if a hexahedron refers to a missing vertex, an optional array has a wrong size, or
///         the file cannot be written (nothing is left behind then).
inline void write_MEDIT(const std::string& filename, const Hexahedral_mesh_3& hexes)
{
  internal_hex_writer::check_writable(filename, hexes);
  const internal::Grouped_mesh grouped(hexes);
  const Hexahedral_mesh_3& m = grouped.mesh();
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "MeshVersionFormatted 1\nDimension 3\nVertices\n" << hexes.points.size() << "\n";
    for(std::size_t v = 0; v < hexes.points.size(); ++v) {
      const auto& p = hexes.points[v];
      out << p.x() << " " << p.y() << " " << p.z() << " " << (hexes.vertex_tags.empty() ? 0 : int(hexes.vertex_tags[v]))
          << "\n";
    }
    out << "Hexahedra\n" << hexes.hexahedra.size() << "\n";
    for(const auto& h : hexes.hexahedra) {
      for(int i = 0; i < 8; ++i)
        out << h[i] + 1 << " ";
      out << "1\n";
    }
    if(!m.boundary_quadrilaterals.empty()) {
      out << "Quadrilaterals\n" << m.boundary_quadrilaterals.size() << "\n";
      for(const auto& q : m.boundary_quadrilaterals)
        out << q.vertices[0] + 1 << " " << q.vertices[1] + 1 << " " << q.vertices[2] + 1 << " " << q.vertices[3] + 1 << " "
            << (q.patch < 0 ? 0 : q.patch) << "\n";
    }
    if(!m.feature_edges.empty()) {
      out << "Edges\n" << m.feature_edges.size() << "\n";
      for(const auto& e : m.feature_edges)
        out << e.vertices[0] + 1 << " " << e.vertices[1] + 1 << " " << (e.curve < 0 ? 0 : e.curve + 1) << "\n";
    }
    out << "End\n";
  });
}

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `hexes` as a VTK legacy ASCII unstructured grid of hexahedra (cell type 12,
/// `VTK_HEXAHEDRON`) for ParaView. Vertex `v` and cell `h` of the file are `v` and `h` of `hexes`.
/// Arrays: point data `tags` (the `Hexahedral_mesh_3::Vertex_tag` bits, when `vertex_tags` is
/// filled), cell data `scaled_jacobian` (always, see `hexahedron_scaled_jacobian()`) and
/// `source_tetrahedron` (when `hexahedron_source_tetrahedra` is filled; -1 for an unknown source),
/// followed by the caller's `cell_arrays` and `point_arrays`. The file is written atomically.
/// \throws Error if a hexahedron refers to a missing vertex, an array has a wrong size, or the file
///         cannot be written (nothing is left behind then).
inline void write_VTK(const std::string& filename, const Hexahedral_mesh_3& hexes,
                      const std::vector<VTK_array>& cell_arrays = {}, const std::vector<VTK_array>& point_arrays = {})
{
  internal_hex_writer::check_writable(filename, hexes);
  std::vector<VTK_array> cells, points;
  VTK_array sj;
  sj.name = "scaled_jacobian";
  sj.values = hexahedra_scaled_jacobians(hexes);
  cells.push_back(std::move(sj));
  if(!hexes.hexahedron_source_tetrahedra.empty()) {
    VTK_array src;
    src.name = "source_tetrahedron";
    for(auto t : hexes.hexahedron_source_tetrahedra)
      src.values.push_back(t == (std::numeric_limits<Hexahedral_mesh_3::Index>::max)() ? -1. : double(t));
    cells.push_back(std::move(src));
  }
  cells.insert(cells.end(), cell_arrays.begin(), cell_arrays.end());
  if(!hexes.vertex_tags.empty()) {
    VTK_array tags;
    tags.name = "tags";
    tags.values.assign(hexes.vertex_tags.begin(), hexes.vertex_tags.end());
    points.push_back(std::move(tags));
  }
  points.insert(points.end(), point_arrays.begin(), point_arrays.end());

  write_file_atomically(filename, [&](std::ostream& out) {
    out << "# vtk DataFile Version 2.0\nHexahedral_remeshing hexahedral mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << hexes.points.size() << " double\n";
    for(const auto& p : hexes.points)
      out << p.x() << " " << p.y() << " " << p.z() << "\n";
    const std::size_t n = hexes.hexahedra.size();
    out << "CELLS " << n << " " << 9 * n << "\n";
    for(const auto& h : hexes.hexahedra) {
      out << "8";
      for(int i = 0; i < 8; ++i)
        out << " " << h[i];
      out << "\n";
    }
    out << "CELL_TYPES " << n << "\n";
    for(std::size_t h = 0; h < n; ++h)
      out << "12\n";
    internal_vtk_writer::write_arrays(out, "CELL_DATA", n, cells, filename);
    internal_vtk_writer::write_arrays(out, "POINT_DATA", hexes.points.size(), points, filename);
  });
}

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `hexes` by the extension of `filename` (case-insensitive): `.mesh` `write_MEDIT()` (HexaLab,
/// gmsh), `.vtk` `write_VTK()` (ParaView), `.vtu` `write_VTU()` (ParaView), `.inp` `write_Abaqus()`
/// (Abaqus, CalculiX), `.msh` `write_gmsh()` (gmsh 4.1, and the solvers that read it). Every format
/// but legacy `.vtk` carries the boundary groups.
/// \throws Error for another extension, or as the writer called.
inline void write_hexahedral_mesh(const std::string& filename, const Hexahedral_mesh_3& hexes)
{
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  std::string ext;
  if(dot != std::string::npos && (slash == std::string::npos || dot > slash))
    ext = filename.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(ext == "mesh")
    write_MEDIT(filename, hexes);
  else if(ext == "vtk")
    write_VTK(filename, hexes);
  else if(ext == "vtu")
    write_VTU(filename, hexes);
  else if(ext == "inp")
    write_Abaqus(filename, hexes);
  else if(ext == "msh")
    write_gmsh(filename, hexes);
  else
    throw Error(filename + ": unknown extension for a hexahedral mesh (use .mesh, .vtk, .vtu, .inp or .msh)");
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_HEXAHEDRAL_MESH_H
