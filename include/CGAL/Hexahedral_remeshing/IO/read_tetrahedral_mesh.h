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
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <filesystem>
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

// OFF reader of our own: CGAL's OFF scanner converts negative indices to unsigned (undefined
// behaviour, found by scripts/fuzz). Vertex lines may carry normals and colours, face lines a
// colour after the indices: the rest of each line is ignored. Binary OFF is not supported.
inline void read_OFF(const std::string& text, const std::string& source,
                     std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& points,
                     std::vector<std::vector<std::size_t> >& polygons)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 P;
  std::size_t pos = 0, line_number = 0, current = 0;
  std::vector<std::string> words;
  // the words of the next line that has any (comments removed); false at the end of the text
  auto next_line = [&]() -> bool {
    while(pos < text.size()) {
      std::size_t end = text.find('\n', pos);
      if(end == std::string::npos) end = text.size();
      std::string l = text.substr(pos, end - pos);
      pos = end + 1;
      current = ++line_number;
      const std::size_t hash = l.find('#');
      if(hash != std::string::npos) l.erase(hash);
      words.clear();
      std::istringstream in(l);
      std::string w;
      while(in >> w) words.push_back(w);
      if(!words.empty()) return true;
    }
    return false;
  };
  auto fail = [&](const std::string& problem) { throw Input_error(source, current, problem); };
  auto number = [&](const std::string& w, const char* what) {
    char* end = nullptr;
    const double d = std::strtod(w.c_str(), &end);
    if(w.empty() || end != w.c_str() + w.size()) fail("malformed number '" + w + "' in " + what);
    return d;
  };
  auto integer = [&](const std::string& w, const char* what) {
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(w.c_str(), &end, 10);
    if(w.empty() || end != w.c_str() + w.size() || errno == ERANGE) fail("malformed integer '" + w + "' in " + what);
    return v;
  };
  if(!next_line()) fail("empty file");
  std::size_t first = 0;
  const std::string& head = words[0];
  if(head.size() >= 3 && head.compare(head.size() - 3, 3, "OFF") == 0) {
    if(head.find_first_of("n4") != std::string::npos && head.find_first_of("n4") < head.size() - 3)
      throw Unsupported_input(source, current, "only 3D OFF files are supported ('" + head + "')");
    if(words.size() > 1 && words[1] == "BINARY")
      throw Unsupported_input(source, current, "binary OFF files are not supported; convert the file to ASCII");
    first = 1;
  }
  if(words.size() <= first) { if(!next_line()) fail("missing vertex and face counts"); first = 0; }
  if(words.size() < first + 2) fail("expected the vertex and face counts");
  const long long nv = integer(words[first], "the vertex count"), nf = integer(words[first + 1], "the face count");
  if(nv < 0 || nf < 0) fail("negative count");
  internal_surface::check_count(source, double(nv), 6, text.size(), "vertices");
  internal_surface::check_count(source, double(nf), 8, text.size(), "faces");
  points.reserve(std::size_t(nv));
  for(long long i = 0; i < nv; ++i) {
    if(!next_line()) fail("unexpected end of file: " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    if(words.size() < 3) fail("vertex " + std::to_string(i) + ": expected 3 coordinates");
    points.push_back(P(number(words[0], "a vertex"), number(words[1], "a vertex"), number(words[2], "a vertex")));
  }
  polygons.reserve(std::size_t(nf));
  for(long long f = 0; f < nf; ++f) {
    if(!next_line()) fail("unexpected end of file: " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const long long k = integer(words[0], "a face");
    if(k < 3 || std::size_t(k) > words.size() - 1)
      fail("face " + std::to_string(f) + ": invalid vertex count " + words[0]);
    std::vector<std::size_t> poly;
    for(long long j = 1; j <= k; ++j) {
      const long long v = integer(words[std::size_t(j)], "a face");
      if(v < 0 || v >= nv)
        fail("face " + std::to_string(f) + ": vertex index " + std::to_string(v) + " out of range (the file has " +
             std::to_string(nv) + " vertices)");
      poly.push_back(std::size_t(v));
    }
    polygons.push_back(std::move(poly));
  }
}

} // namespace internal_surface

/// \ingroup PkgHexahedralRemeshingRef
/// Reads a polygon surface from the content `text` of a file of extension `ext` (`"off"`,
/// `"obj"`, `"stl"` ASCII or binary, `"ply"`) as a soup of polygons: OFF with a strict reader of
/// this package (colours and normals ignored), the others with CGAL's readers. Points are not
/// merged here: see `tetrahedralize_surface()` for the repair.
/// \throws Input_error naming `source` for a malformed, truncated or empty file (a count in a
///         header larger than the file is refused before anything is allocated).
inline void read_surface_soup(const std::string& text, const std::string& ext, const std::string& source,
                              std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& points,
                              std::vector<std::vector<std::size_t> >& polygons)
{
  points.clear();
  polygons.clear();
  if(ext == "off") {
    internal_surface::read_OFF(text, source, points, polygons);
    if(polygons.empty()) throw Input_error(source, 0, "the file has no faces (empty surface)");
    return;
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
    if(ext == "obj") ok = CGAL::IO::read_OBJ(in, points, polygons);
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
  // a directory opens as a stream that reads nothing: it would be reported as an empty file
  std::error_code ec;
  if(std::filesystem::is_directory(filename, ec)) throw Input_error(filename, 0, "is a directory, not a file");
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
