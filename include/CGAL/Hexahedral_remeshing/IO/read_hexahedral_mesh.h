// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_READ_HEXAHEDRAL_MESH_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_READ_HEXAHEDRAL_MESH_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/text_tokenizer.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_hex_reader {

typedef Hexahedral_remeshing::internal::Text_tokenizer Tokenizer;

inline Hexahedral_mesh_3::Point_3 read_point(Tokenizer& tk, const char* what, std::size_t i)
{
  const double x = tk.next_double(what), y = tk.next_double(what), z = tk.next_double(what);
  if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    tk.fail("vertex " + std::to_string(i) + " has a non-finite coordinate");
  return Hexahedral_mesh_3::Point_3(x, y, z);
}

inline void finish(Tokenizer& tk, Hexahedral_mesh_3& hexes, const std::vector<std::size_t>& hex_lines)
{
  if(hexes.hexahedra.empty())
    tk.fail("the file has no hexahedron");
  for(std::size_t h = 0; h < hexes.hexahedra.size(); ++h)
    for(auto v : hexes.hexahedra[h])
      if(v >= hexes.points.size())
        throw Input_error(tk.source(), hex_lines[h], "hexahedron " + std::to_string(h) + ": vertex index " +
                          std::to_string(v) + " out of range (the file has " + std::to_string(hexes.points.size()) +
                          " vertices)");
}

} // namespace internal_hex_reader

/// \ingroup PkgHexahedralRemeshingRef
/// Reads the hexahedra of a MEDIT ASCII `.mesh` file (as written by `write_MEDIT()` for a
/// `Hexahedral_mesh_3`, HexaLab or gmsh): `Vertices` (x y z ref) and `Hexahedra` (8 indices, 1-based,
/// VTK order, ref). When every vertex reference is in 0..7 they are read as the
/// `Hexahedral_mesh_3::Vertex_tag` bits into `vertex_tags`, otherwise `vertex_tags` stays empty. The
/// blocks `Edges`, `Triangles`, `Quadrilaterals`, `Tetrahedra`, `Prisms`, `Pyramids`, `Corners`,
/// `Ridges`, `RequiredVertices` and `RequiredEdges` are skipped, as are `#` comments.
///
/// \param text the content of the file
/// \param source the name of the file, used in error messages
/// \param hexes the output (overwritten)
/// \throws Input_error (file, line, problem) for a truncated or malformed file, a count larger than
///         the file, a non-finite coordinate, an index below 1 or above the number of vertices, no
///         `Vertices` block or no hexahedron; Unsupported_input for an unknown keyword (binary
///         `.meshb` content) or a 2D mesh.
inline void read_hexahedral_mesh_MEDIT(const std::string& text, const std::string& source, Hexahedral_mesh_3& hexes)
{
  internal_hex_reader::Tokenizer tk(text, source);
  hexes.clear();
  bool have_vertices = false, ended = false, tags_fit = true;
  std::vector<std::size_t> hex_lines;
  std::vector<long long> refs;

  while(!ended && !tk.at_end()) {
    const std::string key = tk.next("a keyword");
    if(key[0] == '#') { tk.rest_of_line(); continue; }
    if(key == "MeshVersionFormatted") {
      tk.next_integer("MeshVersionFormatted");
    } else if(key == "Dimension") {
      const long long d = tk.next_integer("Dimension");
      if(d != 3) tk.unsupported("only 3D meshes are supported (Dimension " + std::to_string(d) + ")");
    } else if(key == "Vertices") {
      if(have_vertices) tk.fail("duplicate Vertices block");
      const std::size_t n = tk.next_count("Vertices", 4);
      hexes.points.reserve(n);
      refs.reserve(n);
      for(std::size_t i = 0; i < n; ++i) {
        hexes.points.push_back(internal_hex_reader::read_point(tk, "Vertices", i));
        refs.push_back(tk.next_integer("Vertices reference"));
        tags_fit = tags_fit && refs.back() >= 0 && refs.back() <= 7;
      }
      have_vertices = true;
    } else if(key == "Hexahedra") {
      const std::size_t n = tk.next_count("Hexahedra", 9);
      hexes.hexahedra.reserve(hexes.hexahedra.size() + n);
      for(std::size_t i = 0; i < n; ++i) {
        std::array<Hexahedral_mesh_3::Index, 8> h;
        for(int k = 0; k < 8; ++k) {
          const long long v = tk.next_integer("Hexahedra");
          if(v < 1 || v > (long long)(std::numeric_limits<Hexahedral_mesh_3::Index>::max)())
            tk.fail("invalid vertex index " + std::to_string(v) + " in Hexahedra (indices are 1-based)");
          h[k] = Hexahedral_mesh_3::Index(v - 1);
        }
        hex_lines.push_back(tk.line());
        tk.next_integer("Hexahedra reference");
        hexes.hexahedra.push_back(h);
      }
    } else if(key == "Edges" || key == "Triangles" || key == "Quadrilaterals" || key == "Tetrahedra" ||
              key == "Prisms" || key == "Pyramids" || key == "Corners" || key == "Ridges" ||
              key == "RequiredVertices" || key == "RequiredEdges") {
      const std::size_t per = key == "Edges" ? 3 : key == "Triangles" ? 4 : key == "Quadrilaterals" ? 5
                            : key == "Tetrahedra" ? 5 : key == "Prisms" ? 7 : key == "Pyramids" ? 6 : 1;
      const std::size_t n = tk.next_count(key.c_str(), per);
      for(std::size_t i = 0; i < n * per; ++i) tk.next_integer(key.c_str());
    } else if(key == "End") {
      ended = true;
    } else {
      tk.unsupported("unsupported MEDIT keyword '" + key + "'");
    }
  }
  if(!have_vertices) tk.fail("no Vertices block");
  internal_hex_reader::finish(tk, hexes, hex_lines);
  if(tags_fit)
    hexes.vertex_tags.assign(refs.begin(), refs.end());
}

/// \ingroup PkgHexahedralRemeshingRef
/// Reads the hexahedra (cell type 12, VTK order) of a VTK legacy ASCII unstructured grid, as written by
/// `write_VTK()` for a `Hexahedral_mesh_3`. Other cell types are ignored. The point array `tags`
/// (integers 0..7) fills `vertex_tags` and the cell array `source_tetrahedron` fills
/// `hexahedron_source_tetrahedra` (-1 = unknown); other arrays are skipped.
///
/// \param text the content of the file
/// \param source the name of the file, used in error messages
/// \param hexes the output (overwritten)
/// \throws Input_error (file, line, problem) for a truncated or malformed file, a count larger than
///         the file, a non-finite coordinate, a cell of type 12 without 8 vertices, an index out of
///         range, a `tags` or `source_tetrahedron` value out of range, a duplicated section, no
///         hexahedron; Unsupported_input for a binary file or a dataset other than `UNSTRUCTURED_GRID`.
inline void read_hexahedral_mesh_VTK(const std::string& text, const std::string& source, Hexahedral_mesh_3& hexes)
{
  internal_hex_reader::Tokenizer tk(text, source);
  hexes.clear();

  if(tk.next("the header") != "#") tk.fail("not a VTK legacy file (it must start with '# vtk DataFile Version')");
  const std::string vtk = tk.next("the header");
  if(vtk != "vtk" && vtk != "VTK") tk.fail("not a VTK legacy file (it must start with '# vtk DataFile Version')");
  tk.rest_of_line();
  tk.next_or_empty();  // the title line
  tk.rest_of_line();
  const std::string format = tk.next("the format (ASCII or BINARY)");
  if(format == "BINARY") tk.unsupported("binary VTK files are not supported; convert it to ASCII");
  if(format != "ASCII") tk.fail("expected ASCII or BINARY, found '" + format + "'");
  const std::string dataset = tk.next("DATASET"), kind = tk.next("the dataset type");
  if(dataset != "DATASET" || kind != "UNSTRUCTURED_GRID")
    tk.unsupported("only DATASET UNSTRUCTURED_GRID is supported, found '" + dataset + " " + kind + "'");

  std::vector<std::vector<std::uint32_t> > cells;
  std::vector<std::size_t> cell_lines;
  std::vector<int> cell_types;
  std::vector<double> tags, sources;
  bool have_points = false, have_cells = false, have_types = false, in_data = false, on_cells = false;
  std::size_t data_count = 0;

  while(!tk.at_end()) {
    const std::string key = tk.next("a section keyword");
    if(key == "POINTS") {
      if(have_points) tk.fail("duplicate POINTS section");
      const std::size_t n = tk.next_count("POINTS", 3);
      tk.next("the POINTS type");
      hexes.points.reserve(n);
      for(std::size_t i = 0; i < n; ++i)
        hexes.points.push_back(internal_hex_reader::read_point(tk, "POINTS", i));
      have_points = true;
    } else if(key == "CELLS") {
      if(have_cells) tk.fail("duplicate CELLS section");
      const std::size_t n = tk.next_count("CELLS", 2);
      tk.next_count("CELLS size", 0);
      cells.resize(n);
      cell_lines.resize(n);
      for(std::size_t i = 0; i < n; ++i) {
        const long long k = tk.next_integer("CELLS");
        cell_lines[i] = tk.line();
        if(k < 0 || k > 64) tk.fail("cell " + std::to_string(i) + " has an invalid vertex count " + std::to_string(k));
        cells[i].resize(std::size_t(k));
        for(long long j = 0; j < k; ++j) {
          const long long v = tk.next_integer("CELLS");
          if(v < 0 || v > (long long)(std::numeric_limits<std::uint32_t>::max)())
            tk.fail("cell " + std::to_string(i) + ": vertex index " + std::to_string(v) + " out of range");
          cells[i][std::size_t(j)] = std::uint32_t(v);
        }
      }
      have_cells = true;
    } else if(key == "CELL_TYPES") {
      if(have_types) tk.fail("duplicate CELL_TYPES section");
      const std::size_t n = tk.next_count("CELL_TYPES", 1);
      if(n != cells.size())
        tk.fail("CELL_TYPES count " + std::to_string(n) + " differs from CELLS count " + std::to_string(cells.size()));
      cell_types.resize(n);
      for(std::size_t i = 0; i < n; ++i) cell_types[i] = int(tk.next_integer("CELL_TYPES"));
      have_types = true;
    } else if(key == "CELL_DATA" || key == "POINT_DATA") {
      on_cells = (key == "CELL_DATA");
      data_count = tk.next_count(key.c_str(), 1);
      in_data = true;
      if(on_cells && data_count != cells.size()) tk.fail("CELL_DATA count differs from CELLS count");
      if(!on_cells && data_count != hexes.points.size()) tk.fail("POINT_DATA count differs from POINTS count");
    } else if(in_data && key == "SCALARS") {
      const std::string name = tk.next("the array name");
      tk.next("the array type");
      std::string third = tk.next("LOOKUP_TABLE");
      long long components = 1;
      if(third != "LOOKUP_TABLE") {
        components = std::atoll(third.c_str());
        if(components < 1 || components > 4) tk.fail("invalid component count '" + third + "'");
        third = tk.next("LOOKUP_TABLE");
      }
      if(third != "LOOKUP_TABLE") tk.fail("expected LOOKUP_TABLE, found '" + third + "'");
      tk.next("the lookup table name");
      std::vector<double>* target = nullptr;
      if(components == 1 && !on_cells && name == "tags") target = &tags;
      if(components == 1 && on_cells && name == "source_tetrahedron") target = &sources;
      for(std::size_t i = 0; i < data_count * std::size_t(components); ++i) {
        const double d = tk.next_double(name.c_str());
        if(target) target->push_back(d);
      }
    } else if(in_data && (key == "VECTORS" || key == "NORMALS" || key == "TENSORS")) {
      tk.next("the array name");
      tk.next("the array type");
      for(std::size_t i = 0; i < (key == "TENSORS" ? 9 : 3) * data_count; ++i) tk.next("a data array");
    } else if(in_data && key == "FIELD") {
      tk.next("the field name");
      const std::size_t arrays = tk.next_count("FIELD", 1);
      for(std::size_t a = 0; a < arrays; ++a) {
        tk.next("the array name");
        const std::size_t components = tk.next_count("FIELD array", 0);
        const std::size_t tuples = tk.next_count("FIELD array", 0);
        tk.next("the array type");
        if(tuples != 0 && components > (std::numeric_limits<std::size_t>::max)() / tuples)
          tk.fail("FIELD array too large");
        for(std::size_t i = 0; i < components * tuples; ++i) tk.next("FIELD array");
      }
    } else {
      tk.fail("unknown section keyword '" + key + "'");
    }
  }
  if(!have_points) tk.fail("no POINTS section");
  if(cell_types.size() != cells.size()) tk.fail("missing CELL_TYPES section");

  std::vector<std::size_t> hex_lines;
  std::vector<Hexahedral_mesh_3::Index> hex_sources;
  for(std::size_t i = 0; i < cells.size(); ++i) {
    if(cell_types[i] != 12)
      continue;
    if(cells[i].size() != 8)
      throw Input_error(source, cell_lines[i], "cell " + std::to_string(i) + " of type 12 has " +
                        std::to_string(cells[i].size()) + " vertices instead of 8");
    std::array<Hexahedral_mesh_3::Index, 8> h;
    std::copy(cells[i].begin(), cells[i].end(), h.begin());
    hexes.hexahedra.push_back(h);
    hex_lines.push_back(cell_lines[i]);
    if(!sources.empty()) {
      const double s = sources[i];
      if(s == -1.)
        hex_sources.push_back((std::numeric_limits<Hexahedral_mesh_3::Index>::max)());
      else if(s >= 0. && s < 4294967295. && s == std::floor(s))
        hex_sources.push_back(Hexahedral_mesh_3::Index(s));
      else
        throw Input_error(source, 0, "source_tetrahedron of cell " + std::to_string(i) + " is not a tetrahedron index");
    }
  }
  internal_hex_reader::finish(tk, hexes, hex_lines);
  hexes.hexahedron_source_tetrahedra = hex_sources;
  for(std::size_t v = 0; v < tags.size(); ++v)
    if(!(tags[v] >= 0. && tags[v] <= 7. && tags[v] == std::floor(tags[v])))
      throw Input_error(source, 0, "tags of point " + std::to_string(v) + " is not a tag (integer 0..7)");
  hexes.vertex_tags.assign(tags.begin(), tags.end());
}

/// \ingroup PkgHexahedralRemeshingRef
/// Reads `filename` into `hexes` with `read_hexahedral_mesh_MEDIT()` for a `.mesh` file or
/// `read_hexahedral_mesh_VTK()` for a `.vtk` one (case-insensitive extension).
/// \throws Input_error if the file cannot be read or is malformed (see the readers);
///         Unsupported_input for another extension.
inline void read_hexahedral_mesh(const std::string& filename, Hexahedral_mesh_3& hexes)
{
  const std::size_t dot = filename.find_last_of('.');
  const std::size_t slash = filename.find_last_of("/\\");
  std::string ext;
  if(dot != std::string::npos && (slash == std::string::npos || dot > slash))
    ext = filename.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(ext != "mesh" && ext != "vtk")
    throw Unsupported_input(filename, 0, "unknown extension for a hexahedral mesh (use .mesh or .vtk)");
  const std::string text = internal::Text_tokenizer::read_file(filename);
  if(ext == "mesh")
    read_hexahedral_mesh_MEDIT(text, filename, hexes);
  else
    read_hexahedral_mesh_VTK(text, filename, hexes);
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_READ_HEXAHEDRAL_MESH_H
