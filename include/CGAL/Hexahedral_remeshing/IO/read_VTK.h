// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_READ_VTK_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_READ_VTK_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/text_tokenizer.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_vtk {

// Skips the values of one data array of a POINT_DATA / CELL_DATA section.
inline void skip_values(Hexahedral_remeshing::internal::Text_tokenizer& tk, std::size_t count, const char* what)
{
  for(std::size_t i = 0; i < count; ++i) tk.next(what);
}

} // namespace internal_vtk

/// \ingroup PkgHexahedralRemeshingRef
/// Reads a VTK legacy ASCII unstructured grid (as gmsh writes it) into `soup`.
///
/// Cells of type 10 are the tetrahedra; cells of type 5 (triangles), 3 (lines) and 1 (vertices)
/// become tagged boundary triangles, feature edges and corners, tagged with the `CellEntityIds`
/// cell array when the file has one. Other cell types are ignored. Binary files are rejected with
/// `Unsupported_input`.
///
/// Windows line ends are accepted. A count (of points, cells, data values) larger than what the
/// rest of the file can hold is rejected before anything is allocated.
///
/// \param text the content of the file
/// \param source the name of the file, used in error messages
/// \param soup the output (overwritten)
/// \throws Input_error (file, line, problem) for an unreadable, truncated or malformed file, a count
///         larger than the file, a duplicated `POINTS`, `CELLS` or `CELL_TYPES` section, a
///         `CellEntityIds` array whose size differs from the number of cells;
///         Unsupported_input for a binary file or a dataset other than `UNSTRUCTURED_GRID`.
template <class Point>
void read_VTK(const std::string& text, const std::string& source, Tetrahedral_soup_3<Point>& soup)
{
  using Hexahedral_remeshing::internal::Text_tokenizer;
  Text_tokenizer tk(text, source);
  soup = Tetrahedral_soup_3<Point>();
  soup.source = source;

  const std::string magic = tk.next("the header");
  if(magic != "#") tk.fail("not a VTK legacy file (it must start with '# vtk DataFile Version')");
  const std::string vtk = tk.next("the header");
  if(vtk != "vtk" && vtk != "VTK") tk.fail("not a VTK legacy file (it must start with '# vtk DataFile Version')");
  tk.rest_of_line();
  tk.next_or_empty(); // first word of the title line
  tk.rest_of_line();
  const std::string format = tk.next("the format (ASCII or BINARY)");
  if(format == "BINARY") tk.unsupported("binary VTK files are not supported; convert it to ASCII (e.g. with meshio or ParaView)");
  if(format != "ASCII") tk.fail("expected ASCII or BINARY, found '" + format + "'");
  const std::string dataset = tk.next("DATASET");
  const std::string kind = tk.next("the dataset type");
  if(dataset != "DATASET" || kind != "UNSTRUCTURED_GRID")
    tk.unsupported("only DATASET UNSTRUCTURED_GRID is supported, found '" + dataset + " " + kind + "'");

  std::vector<std::vector<std::size_t> > cells;
  std::vector<std::size_t> cell_lines;
  std::vector<int> cell_types, cell_entity;
  bool have_points = false;
  bool in_data = false, data_on_cells = false;
  std::size_t data_count = 0;

  std::vector<std::string> sections_seen;
  auto once = [&](const std::string& key) {
    for(const std::string& k : sections_seen)
      if(k == key) tk.fail("duplicate " + key + " section");
    sections_seen.push_back(key);
  };

  while(!tk.at_end()) {
    const std::string key = tk.next("a section keyword");
    if(key == "POINTS" || key == "CELLS" || key == "CELL_TYPES") once(key);
    if(key == "POINTS") {
      const std::size_t n = tk.next_count("POINTS", 3);
      tk.next("the POINTS type");
      soup.points.reserve(n);
      for(std::size_t i = 0; i < n; ++i) {
        const double x = tk.next_double("POINTS"), y = tk.next_double("POINTS"), z = tk.next_double("POINTS");
        soup.points.push_back(Point(x, y, z));
      }
      have_points = true;
    } else if(key == "CELLS") {
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
          if(v < 0) tk.fail("cell " + std::to_string(i) + ": negative vertex index " + std::to_string(v));
          cells[i][std::size_t(j)] = std::size_t(v);
        }
      }
    } else if(key == "CELL_TYPES") {
      const std::size_t n = tk.next_count("CELL_TYPES", 1);
      if(n != cells.size())
        tk.fail("CELL_TYPES count " + std::to_string(n) + " differs from CELLS count " + std::to_string(cells.size()));
      cell_types.resize(n);
      for(std::size_t i = 0; i < n; ++i) cell_types[i] = int(tk.next_integer("CELL_TYPES"));
    } else if(key == "CELL_DATA" || key == "POINT_DATA") {
      data_on_cells = key == "CELL_DATA";
      data_count = tk.next_count(key.c_str(), 1);
      in_data = true;
      if(data_on_cells && data_count != cells.size()) tk.fail("CELL_DATA count differs from CELLS count");
    } else if(in_data && key == "SCALARS") {
      const std::string name = tk.next("the array name");
      tk.next("the array type");
      std::string third = tk.next("LOOKUP_TABLE"); // the component count is optional in the format
      long long ncomp = 1;
      if(third != "LOOKUP_TABLE") {
        ncomp = std::atoll(third.c_str());
        if(ncomp < 1 || ncomp > 4) tk.fail("invalid component count '" + third + "'");
        third = tk.next("LOOKUP_TABLE");
      }
      if(third != "LOOKUP_TABLE") tk.fail("expected LOOKUP_TABLE, found '" + third + "'");
      tk.next("the lookup table name");
      if(data_on_cells && name == "CellEntityIds" && ncomp == 1) {
        cell_entity.resize(data_count);
        for(std::size_t i = 0; i < data_count; ++i) cell_entity[i] = int(tk.next_integer("CellEntityIds"));
      } else {
        internal_vtk::skip_values(tk, data_count * std::size_t(ncomp), "a data array");
      }
    } else if(in_data && (key == "VECTORS" || key == "NORMALS" || key == "TENSORS")) {
      tk.next("the array name");
      tk.next("the array type");
      internal_vtk::skip_values(tk, (key == "TENSORS" ? 9 : 3) * data_count, "a data array");
    } else if(in_data && key == "FIELD") {
      tk.next("the field name");
      const std::size_t arrays = tk.next_count("FIELD", 1);
      for(std::size_t a = 0; a < arrays; ++a) {
        tk.next("the array name");
        const std::size_t ncomp = tk.next_count("FIELD array", 0);
        const std::size_t ntuples = tk.next_count("FIELD array", 0);
        tk.next("the array type");
        internal_vtk::skip_values(tk, ncomp * ntuples, "FIELD array");
      }
    } else if(key == "METADATA") {
      // metadata blocks end with an empty line: not written by gmsh; treat as unsupported
      tk.unsupported("VTK METADATA blocks are not supported");
    } else {
      tk.fail("unknown section keyword '" + key + "'");
    }
  }
  if(!have_points) tk.fail("no POINTS section");
  if(cell_types.size() != cells.size()) tk.fail("missing CELL_TYPES section");
  if(!cell_entity.empty() && cell_entity.size() != cells.size())
    tk.fail("CellEntityIds has " + std::to_string(cell_entity.size()) + " values for " +
            std::to_string(cells.size()) + " cells");

  for(std::size_t i = 0; i < cells.size(); ++i) {
    const std::vector<std::size_t>& c = cells[i];
    const int id = cell_entity.empty() ? 0 : cell_entity[i];
    auto expect = [&](std::size_t k) {
      if(c.size() != k)
        throw Input_error(source, cell_lines[i], "cell " + std::to_string(i) + " of type " + std::to_string(cell_types[i]) +
                          " has " + std::to_string(c.size()) + " vertices instead of " + std::to_string(k));
    };
    for(std::size_t v : c)
      if(v >= soup.points.size())
        throw Input_error(source, cell_lines[i], "cell " + std::to_string(i) + ": vertex index " + std::to_string(v) +
                          " out of range (the file has " + std::to_string(soup.points.size()) + " points)");
    switch(cell_types[i]) {
      case 10: expect(4); soup.tetrahedra.push_back({c[0], c[1], c[2], c[3]}); soup.tetrahedron_lines.push_back(cell_lines[i]); break;
      case 5: expect(3); soup.triangles.push_back({c[0], c[1], c[2]}); soup.triangle_patches.push_back(id); break;
      case 3: expect(2); soup.feature_edges.push_back({c[0], c[1]}); soup.feature_edge_curves.push_back(id); break;
      case 1: expect(1); soup.corners.push_back(c[0]); break;
      default: break; // other cells (quads, hexes, ...) are not part of a tetrahedral mesh
    }
  }
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_READ_VTK_H
