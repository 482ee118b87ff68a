// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_MEDIT_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_MEDIT_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>

#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `mesh` as a MEDIT ASCII `.mesh` file (`MeshVersionFormatted 1`, `Dimension 3`):
/// `Vertices` (reference 0), `Triangles` (the boundary triangles, outward, reference = surface
/// patch + 1, 0 when the input gave no patch) and `Tetrahedra` (positively oriented, reference 1),
/// with 1-based indices: vertex `v` and tetrahedron `t` of the file are `v` and `t` of `mesh`
/// (so the input vertices come first, in input order). `read_MEDIT()` reads it back; tools that
/// only know tetrahedral meshes (CubeCover's `readMESH`) read it as well.
/// \throws Error if the file cannot be written (nothing is left behind then).
template <class Traits>
void write_MEDIT(const std::string& filename, const Tetrahedral_mesh_3<Traits>& mesh)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "MeshVersionFormatted 1\nDimension 3\nVertices\n" << mesh.number_of_vertices() << "\n";
    for(const auto& p : mesh.points()) out << p.x() << " " << p.y() << " " << p.z() << " 0\n";
    out << "Triangles\n" << mesh.number_of_boundary_triangles() << "\n";
    for(Index b = 0; b < mesh.number_of_boundary_triangles(); ++b) {
      const auto& v = mesh.boundary_triangle_vertices(b);
      out << v[0] + 1 << " " << v[1] + 1 << " " << v[2] + 1 << " " << mesh.boundary_triangle_patch(b) + 1 << "\n";
    }
    out << "Tetrahedra\n" << mesh.number_of_tetrahedra() << "\n";
    for(Index t = 0; t < mesh.number_of_tetrahedra(); ++t) {
      const auto& v = mesh.tetrahedron_vertices(t);
      out << v[0] + 1 << " " << v[1] + 1 << " " << v[2] + 1 << " " << v[3] + 1 << " 1\n";
    }
    out << "End\n";
  });
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_MEDIT_H
