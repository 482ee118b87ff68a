// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_BOUNDARY_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_BOUNDARY_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

/// \ingroup PkgHexahedralRemeshingRef
/// Writes the boundary surface of `mesh` as a VTK legacy ASCII unstructured grid of triangles (cell
/// type 5), readable by ParaView: cell `i` is boundary triangle `i`, oriented outward, and carries
/// the values of `cell_arrays` (one value or vector per boundary triangle). Only the boundary
/// vertices are written; the point array `vertex` gives their index in `mesh`.
/// \throws Error if the file cannot be written or an array does not have one entry per boundary triangle.
template <class Traits>
void write_VTK_boundary(const std::string& filename, const Tetrahedral_mesh_3<Traits>& mesh,
                        const std::vector<VTK_array>& cell_arrays = {})
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  const std::size_t nb = mesh.number_of_boundary_triangles();
  for(const VTK_array& a : cell_arrays) // checked before the file is opened: no partial output
    if((a.components != 1 && a.components != 3) || a.values.size() != nb * std::size_t(a.components))
      throw Error(filename + ": data array '" + a.name + "' does not have one entry per boundary triangle");
  std::vector<Index> local(mesh.number_of_vertices(), Tetrahedral_mesh_3<Traits>::null_index);
  VTK_array vertex;
  vertex.name = "vertex";
  for(Index b = 0; b < nb; ++b)
    for(Index v : mesh.boundary_triangle_vertices(b))
      if(local[v] == Tetrahedral_mesh_3<Traits>::null_index) {
        local[v] = Index(vertex.values.size());
        vertex.values.push_back(double(v));
      }
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "# vtk DataFile Version 2.0\nHexahedral_remeshing boundary triangles\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << vertex.values.size() << " double\n";
    for(double v : vertex.values) {
      const auto& p = mesh.point(Index(v));
      out << p.x() << " " << p.y() << " " << p.z() << "\n";
    }
    out << "CELLS " << nb << " " << 4 * nb << "\n";
    for(Index b = 0; b < nb; ++b) {
      const auto& v = mesh.boundary_triangle_vertices(b);
      out << "3 " << local[v[0]] << " " << local[v[1]] << " " << local[v[2]] << "\n";
    }
    out << "CELL_TYPES " << nb << "\n";
    for(std::size_t b = 0; b < nb; ++b) out << "5\n";
    internal_vtk_writer::write_arrays(out, "CELL_DATA", nb, cell_arrays, filename);
    internal_vtk_writer::write_arrays(out, "POINT_DATA", vertex.values.size(), {vertex}, filename);
  });
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_BOUNDARY_H
