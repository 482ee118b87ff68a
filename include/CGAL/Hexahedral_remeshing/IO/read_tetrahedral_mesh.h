// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_READ_TETRAHEDRAL_MESH_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_READ_TETRAHEDRAL_MESH_H

#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/read_MEDIT.h>
#include <CGAL/Hexahedral_remeshing/IO/read_VTK.h>
#include <CGAL/Hexahedral_remeshing/tetrahedralize_surface.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

/// \ingroup PkgHexahedralRemeshingRef
/// Lower-case extension of `filename` without the dot (`"vtk"`, `"mesh"`, ...).
inline std::string file_extension(const std::string& filename)
{
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::string();
  std::string ext = filename.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Reads `filename` into a soup of tetrahedra, choosing the reader from the extension:
/// `.vtk` (VTK legacy ASCII unstructured grid), `.mesh` (MEDIT), or a closed surface
/// `.off`, `.obj`, `.stl`, `.ply` read with CGAL and tetrahedralized with TetGen
/// (see `tetrahedralize_surface()` for the named parameters).
/// \throws Input_error naming the file and the problem; Unsupported_input for an unknown extension.
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
void read_tetrahedral_soup(const std::string& filename, Tetrahedral_soup_3<Point>& soup,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string ext = file_extension(filename);
  if(ext == "vtk") {
    read_VTK(Hexahedral_remeshing::internal::Text_tokenizer::read_file(filename), filename, soup);
  } else if(ext == "mesh") {
    read_MEDIT(Hexahedral_remeshing::internal::Text_tokenizer::read_file(filename), filename, soup);
  } else if(ext == "off" || ext == "obj" || ext == "stl" || ext == "ply") {
    {
      std::ifstream probe(filename);
      if(!probe) throw Input_error(filename, 0, "cannot open file for reading");
    }
    CGAL::Surface_mesh<Point> surface;
    bool ok = false;
    try {
      ok = CGAL::IO::read_polygon_mesh(filename, surface);
    } catch(std::exception&) {
      ok = false;
    }
    if(!ok || surface.number_of_faces() == 0)
      throw Input_error(filename, 0, "cannot read a polygon surface from this file (malformed or empty)");
    soup.source = filename;
    tetrahedralize_surface(surface, soup, np);
  } else {
    throw Unsupported_input(filename, 0, "unknown file extension '" + ext +
                            "' (supported: .vtk, .mesh, .off, .obj, .stl, .ply)");
  }
}

/// \ingroup PkgHexahedralRemeshingRef
/// Reads `filename` (see `read_tetrahedral_soup()`) and builds `mesh` from it
/// (see `build_tetrahedral_mesh()`); `np` is passed to both.
template <class Traits, class NamedParameters = CGAL::parameters::Default_named_parameters>
void read_tetrahedral_mesh(const std::string& filename, Tetrahedral_mesh_3<Traits>& mesh,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  Tetrahedral_soup_3<typename Traits::Point_3> soup;
  read_tetrahedral_soup(filename, soup, np);
  build_tetrahedral_mesh(soup, mesh, np);
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_READ_TETRAHEDRAL_MESH_H
