// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_READ_TETRAHEDRAL_MESH_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_READ_TETRAHEDRAL_MESH_H

#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/read_MEDIT.h>
#include <CGAL/Hexahedral_remeshing/IO/read_VTK.h>
#include <CGAL/Hexahedral_remeshing/IO/read_gmsh.h>
#include <CGAL/Hexahedral_remeshing/tetrahedralize_surface.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

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

namespace internal_surface {

// A count announced by a header must fit in the file (CGAL's readers reserve what the header
// says): a hostile header is refused before anything is allocated.
inline void check_count(const std::string& source, double count, std::size_t bytes_per_item, std::size_t size,
                        const char* what)
{
  if(!(count >= 0) || count > double(size) / double(bytes_per_item) + 1)
    throw Input_error(source, 0, std::string("the header announces more ") + what +
                      " than the file can hold (truncated or malformed file)");
}

} // namespace internal_surface

/// \ingroup PkgHexahedralRemeshingRef
/// Reads a polygon surface from the content `text` of a file of extension `ext` (`"off"`,
/// `"obj"`, `"stl"` ASCII or binary, `"ply"`) with CGAL's readers, as a soup of polygons
/// (points are not merged here: see `tetrahedralize_surface()` for the repair).
/// \throws Input_error naming `source` for a malformed, truncated or empty file.
inline void read_surface_soup(const std::string& text, const std::string& ext, const std::string& source,
                              std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& points,
                              std::vector<std::vector<std::size_t> >& polygons)
{
  points.clear();
  polygons.clear();
  if(ext == "off") {
    std::istringstream header(text);
    std::string word;
    header >> word;
    while(header && !word.empty() && word[0] == '#') { std::getline(header, word); header >> word; }
    double nv = 0, nf = 0;
    if(word.find("OFF") != std::string::npos && word.size() <= 5 && (header >> nv >> nf)) {
      internal_surface::check_count(source, nv, 6, text.size(), "vertices");
      internal_surface::check_count(source, nf, 8, text.size(), "faces");
    }
  } else if(ext == "stl") {
    std::size_t b = 0;
    while(b < text.size() && std::isspace(static_cast<unsigned char>(text[b]))) ++b;
    if(text.compare(b, 5, "solid") != 0 && text.size() >= 84) {
      std::uint32_t n = 0;
      std::memcpy(&n, text.data() + 80, 4);
      if(84 + 50 * std::uint64_t(n) > text.size())
        throw Input_error(source, 0, "binary STL: the header announces " + std::to_string(n) +
                          " triangles but the file is " + std::to_string(text.size()) + " bytes (truncated file?)");
    }
  }
  bool ok = false;
  try {
    std::istringstream in(text, std::ios::in | std::ios::binary);
    if(ext == "off") ok = CGAL::IO::read_OFF(in, points, polygons);
    else if(ext == "obj") ok = CGAL::IO::read_OBJ(in, points, polygons);
    else if(ext == "stl") ok = CGAL::IO::read_STL(in, points, polygons);
    else if(ext == "ply") ok = CGAL::IO::read_PLY(in, points, polygons);
    else throw Unsupported_input(source, 0, "not a surface format: '" + ext + "'");
  } catch(const Input_error&) {
    throw;
  } catch(const std::exception&) {
    ok = false;
  }
  if(!ok)
    throw Input_error(source, 0, "cannot read a polygon surface from this file (malformed " + ext +
                      " file); check that it is a valid " + ext + " file");
  if(polygons.empty()) throw Input_error(source, 0, "the file has no faces (empty surface)");
}

/// \ingroup PkgHexahedralRemeshingRef
/// Reads `filename` into a soup of tetrahedra, choosing the reader from the extension:
/// - `.vtk`: VTK legacy unstructured grid (`read_VTK()`);
/// - `.mesh`: MEDIT (`read_MEDIT()`);
/// - `.msh`: gmsh mesh (`read_gmsh()`);
/// - `.step`, `.stp`, `.brep`, `.iges`, `.igs`: CAD part meshed with gmsh (`read_CAD()`, named
///   parameter `mesh_size`);
/// - `.off`, `.obj`, `.stl`, `.ply`: closed surface, repaired, checked and tetrahedralized with
///   TetGen (see `tetrahedralize_surface()` for the checks and the named parameters).
/// \throws Input_error naming the file, the problem and what to do; Unsupported_input for an
///         unknown extension.
template <class Point, class NamedParameters = CGAL::parameters::Default_named_parameters>
void read_tetrahedral_soup(const std::string& filename, Tetrahedral_soup_3<Point>& soup,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string ext = file_extension(filename);
  if(ext == "vtk") {
    read_VTK(Hexahedral_remeshing::internal::Text_tokenizer::read_file(filename), filename, soup);
  } else if(ext == "mesh") {
    read_MEDIT(Hexahedral_remeshing::internal::Text_tokenizer::read_file(filename), filename, soup);
  } else if(ext == "msh") {
    read_gmsh(filename, soup, np);
  } else if(ext == "step" || ext == "stp" || ext == "brep" || ext == "iges" || ext == "igs") {
    read_CAD(filename, soup, np);
  } else if(ext == "off" || ext == "obj" || ext == "stl" || ext == "ply") {
    const std::string text = Hexahedral_remeshing::internal::Text_tokenizer::read_file(filename);
    std::vector<Hexahedral_remeshing::internal::Surface_kernel::Point_3> points;
    std::vector<std::vector<std::size_t> > polygons;
    read_surface_soup(text, ext, filename, points, polygons);
    Hexahedral_remeshing::internal::Checked_surface surface;
    Hexahedral_remeshing::internal::surface_from_polygon_soup(points, polygons, filename, surface);
    soup = Tetrahedral_soup_3<Point>();
    soup.source = filename;
    tetrahedralize_checked_surface(surface, soup, np);
  } else {
    throw Unsupported_input(filename, 0, "unknown file extension '" + ext +
                            "' (supported: .vtk, .mesh, .msh, .step, .stp, .brep, .iges, .igs, .off, .obj, .stl, .ply)");
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
