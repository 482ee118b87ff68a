// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_READ_VTK_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_READ_VTK_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/text_tokenizer.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_vtk {

// Reads a VTK legacy file: keyword lines are text, data are text (ASCII files) or big-endian
// binary blocks that start right after the keyword line (BINARY files).
class Reader
{
public:
  Reader(const std::string& text, const std::string& source) : m_text(text), m_source(source) {}

  [[noreturn]] void fail(const std::string& problem) const { throw Input_error(m_source, m_token_line, problem); }
  [[noreturn]] void unsupported(const std::string& problem) const
  {
    throw Unsupported_input(m_source, m_token_line, problem);
  }

  bool binary = false;
  std::size_t line() const { return m_token_line; }

  std::string word_or_empty()
  {
    skip_space();
    const std::size_t b = m_pos;
    while(m_pos < m_text.size() && !is_space(m_text[m_pos])) ++m_pos;
    m_token_line = m_line;
    return m_text.substr(b, m_pos - b);
  }
  std::string word(const char* what)
  {
    std::string t = word_or_empty();
    if(t.empty()) fail("unexpected end of file while reading " + std::string(what));
    return t;
  }
  std::string rest_of_line()
  {
    const std::size_t b = m_pos;
    while(m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
    std::string s = m_text.substr(b, m_pos - b);
    if(m_pos < m_text.size()) { ++m_pos; ++m_line; }
    while(!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.pop_back();
    return s;
  }
  bool at_end()
  {
    skip_space();
    return m_pos >= m_text.size();
  }
  long long integer(const char* what)
  {
    const std::string t = word(what);
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if(end != t.c_str() + t.size()) fail("malformed integer '" + t + "' in " + what);
    if(errno == ERANGE) fail("integer '" + t + "' out of range in " + what);
    return v;
  }
  // A count of values that must fit in the rest of the file.
  std::size_t count(const char* what)
  {
    const long long v = integer(what);
    if(v < 0) fail("negative count " + std::to_string(v) + " in " + what);
    if(std::size_t(v) > (m_text.size() - m_pos) / (binary ? 1 : 2) + 1)
      fail("count " + std::to_string(v) + " in " + std::string(what) + " exceeds what the file holds (truncated file?)");
    return std::size_t(v);
  }
  // Whether the line after the current one (blank lines skipped) starts with `w`; reads nothing.
  bool next_line_starts_with(const std::string& w) const
  {
    std::size_t p = m_pos;
    while(p < m_text.size() && m_text[p] != '\n') ++p;
    while(p < m_text.size() && is_space(m_text[p])) ++p;
    return m_text.compare(p, w.size(), w) == 0;
  }
  // Skips a METADATA block: text lines up to an empty line, or up to the next section keyword
  // (writers such as meshio and some VTK versions omit the empty line).
  void skip_metadata()
  {
    static const std::set<std::string> sections = {
      "POINTS", "CELLS", "CELL_TYPES", "OFFSETS", "CONNECTIVITY", "POINT_DATA", "CELL_DATA", "FIELD",
      "SCALARS", "VECTORS", "NORMALS", "TENSORS", "LOOKUP_TABLE", "METADATA", "DATASET", "TEXTURE_COORDINATES"};
    rest_of_line();
    while(m_pos < m_text.size()) {
      const std::size_t pos = m_pos, line = m_line;
      const std::string l = rest_of_line();
      const std::size_t b = l.find_first_not_of(" \t\r");
      if(b == std::string::npos) break;
      if(sections.count(l.substr(b, l.find_first_of(" \t", b) - b)) > 0) { m_pos = pos; m_line = line; break; }
    }
  }

  static std::size_t type_size(const std::string& type)
  {
    static const std::map<std::string, std::size_t> sizes = {
      {"unsigned_char", 1}, {"char", 1}, {"vtktypeint8", 1}, {"vtktypeuint8", 1},
      {"unsigned_short", 2}, {"short", 2}, {"vtktypeint16", 2}, {"vtktypeuint16", 2},
      {"unsigned_int", 4}, {"int", 4}, {"vtktypeint32", 4}, {"vtktypeuint32", 4}, {"float", 4},
      {"unsigned_long", 8}, {"long", 8}, {"vtktypeint64", 8}, {"vtktypeuint64", 8}, {"vtkIdType", 8},
      {"double", 8}, {"vtktypefloat32", 4}, {"vtktypefloat64", 8}};
    const auto it = sizes.find(type);
    return it == sizes.end() ? 0 : it->second;
  }

  // `n` values of the data type `type` (ASCII tokens, or big-endian binary values that start on the
  // line after the keyword line).
  std::vector<double> values(std::size_t n, const std::string& type, const char* what,
                             std::vector<std::size_t>* lines = nullptr)
  {
    std::vector<double> out;
    const std::size_t size = type_size(type);
    if(size == 0) {
      if(binary) unsupported("data type '" + type + "' of " + what + " is not supported in binary files");
      if(type != "bit" && type != "string") fail("unknown data type '" + type + "' in " + what);
    }
    if(!binary) {
      // a count larger than the file ends with "unexpected end of file" at the last line
      out.reserve((std::min)(n, (m_text.size() - m_pos) / 2 + 1));
      for(std::size_t i = 0; i < n; ++i) {
        const std::string t = word(what);
        char* end = nullptr;
        const double d = std::strtod(t.c_str(), &end);
        if(end != t.c_str() + t.size()) fail("malformed number '" + t + "' in " + what);
        out.push_back(d);
        if(lines) lines->push_back(m_token_line);
      }
      return out;
    }
    // the binary block starts after the end of the keyword line
    while(m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
    if(m_pos < m_text.size()) { ++m_pos; ++m_line; }
    if(n > (m_text.size() - m_pos) / size)
      fail(std::string(what) + ": the binary block of " + std::to_string(n) + " values of type " + type +
           " is truncated (the file ends first)");
    out.resize(n);
    unsigned char b[8];
    for(std::size_t i = 0; i < n; ++i) {
      for(std::size_t k = 0; k < size; ++k) b[k] = static_cast<unsigned char>(m_text[m_pos + i * size + k]);
      std::uint64_t u = 0;
      for(std::size_t k = 0; k < size; ++k) u = (u << 8) | b[k];
      double v = 0;
      const bool is_unsigned = type.compare(0, 8, "unsigned") == 0 || type.compare(0, 8, "vtktypeu") == 0;
      if(type == "float" || type == "vtktypefloat32") { std::uint32_t w = std::uint32_t(u); float f; std::memcpy(&f, &w, 4); v = f; }
      else if(type == "double" || type == "vtktypefloat64") { std::memcpy(&v, &u, 8); }
      else if(is_unsigned) { v = double(u); }
      else {
        // sign extension of a two's-complement integer of `size` bytes
        const int shift = int(64 - 8 * size);
        v = double(std::int64_t(u << shift) >> shift);
      }
      out[i] = v;
    }
    m_pos += n * size;
    if(lines) lines->assign(n, m_token_line);
    return out;
  }

  // Integer values (indices, counts, types): every value must be an integer.
  std::vector<long long> integers(std::size_t n, const std::string& type, const char* what,
                                  std::vector<std::size_t>* lines = nullptr)
  {
    const std::vector<double> d = values(n, type, what, lines);
    std::vector<long long> out(d.size());
    for(std::size_t i = 0; i < d.size(); ++i) {
      if(!(std::abs(d[i]) <= 9.0e15) || d[i] != double((long long)d[i]))
        fail(std::string(what) + ": value " + std::to_string(d[i]) + " is not an integer");
      out[i] = (long long)d[i];
    }
    return out;
  }

private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
  void skip_space()
  {
    while(m_pos < m_text.size() && is_space(m_text[m_pos])) {
      if(m_text[m_pos] == '\n') ++m_line;
      ++m_pos;
    }
  }
  const std::string& m_text;
  std::string m_source;
  std::size_t m_pos = 0;
  std::size_t m_line = 1;
  std::size_t m_token_line = 1;
};

// Volume cells that are not tetrahedra, by VTK type (their names for the messages).
inline const char* non_tetrahedral_volume_cell(int type)
{
  switch(type) {
    case 11: return "voxel";
    case 12: return "hexahedron";
    case 13: return "wedge (prism)";
    case 14: return "pyramid";
    case 15: return "pentagonal prism";
    case 16: return "hexagonal prism";
    case 25: return "quadratic hexahedron";
    case 26: return "quadratic wedge";
    case 27: return "quadratic pyramid";
    case 29: return "triquadratic hexahedron";
    case 32: return "biquadratic-quadratic wedge";
    case 33: return "biquadratic-quadratic hexahedron";
    case 42: return "polyhedron";
    case 72: return "Lagrange hexahedron";
    case 73: return "Lagrange wedge";
    case 74: return "Lagrange pyramid";
    case 79: return "Bezier hexahedron";
    case 80: return "Bezier wedge";
    case 81: return "Bezier pyramid";
    default: return nullptr;
  }
}

} // namespace internal_vtk

/// \ingroup PkgHexahedralRemeshingRef
/// Reads a VTK legacy unstructured grid into `soup`: ASCII or BINARY (big-endian), the classic
/// `CELLS` layout or the `OFFSETS`/`CONNECTIVITY` layout of version 5.1 (the default of meshio and
/// of ParaView's legacy export), `METADATA` blocks skipped.
///
/// Tetrahedra: cells of type 10, and the corner nodes (the first four) of quadratic (24), Lagrange
/// (71) and Bezier (78) tetrahedra. Cells of type 5 (triangles; 22, 69: their corners), 3 (lines;
/// 21, 68: their ends) and 1 (vertices) become tagged boundary triangles, feature edges and
/// corners, tagged with the cell array `CellEntityIds` (else `gmsh:geometrical`, `gmsh:physical`
/// or `medit:ref`, as meshio writes them) when the file has one. Volume cells other than
/// tetrahedra (hexahedra, wedges, pyramids, ...) are refused with their counts: dropping them would
/// silently shrink the domain. Other cells (quads, polygons, ...) are ignored.
///
/// Windows line ends are accepted. A count (of points, cells, data values) larger than what the
/// rest of the file can hold is rejected before anything is allocated.
///
/// \param text the content of the file
/// \param source the name of the file, used in error messages
/// \param soup the output (overwritten)
/// \throws Input_error (file, line, problem) for an unreadable, truncated or malformed file, a count
///         larger than the file, a duplicated `POINTS`, `CELLS` or `CELL_TYPES` section, a cell
///         with too few vertices for its type, volume cells other than tetrahedra;
///         Unsupported_input for a dataset other than `UNSTRUCTURED_GRID` or an unknown binary
///         data type.
template <class Point>
void read_VTK(const std::string& text, const std::string& source, Tetrahedral_soup_3<Point>& soup)
{
  internal_vtk::Reader rd(text, source);
  soup = Tetrahedral_soup_3<Point>();
  soup.source = source;

  if(rd.word("the header") != "#") rd.fail("not a VTK legacy file (it must start with '# vtk DataFile Version')");
  const std::string vtk = rd.word("the header");
  if(vtk != "vtk" && vtk != "VTK") rd.fail("not a VTK legacy file (it must start with '# vtk DataFile Version')");
  rd.rest_of_line();
  rd.rest_of_line(); // title
  const std::string format = rd.word("the format (ASCII or BINARY)");
  if(format == "BINARY") rd.binary = true;
  else if(format != "ASCII") rd.fail("expected ASCII or BINARY, found '" + format + "'");
  const std::string dataset = rd.word("DATASET");
  const std::string kind = rd.word("the dataset type");
  if(dataset != "DATASET" || kind != "UNSTRUCTURED_GRID")
    rd.unsupported("only DATASET UNSTRUCTURED_GRID is supported, found '" + dataset + " " + kind + "'");

  std::vector<long long> offsets, connectivity; // cell i: connectivity[offsets[i] .. offsets[i+1])
  std::vector<std::size_t> cell_lines;
  std::vector<long long> cell_types;
  std::vector<long long> cell_entity;
  int entity_priority = 0;
  bool have_points = false, have_cells = false;
  bool in_data = false, data_on_cells = false;
  std::size_t data_count = 0;

  std::vector<std::string> sections_seen;
  auto once = [&](const std::string& key) {
    for(const std::string& k : sections_seen)
      if(k == key) rd.fail("duplicate " + key + " section");
    sections_seen.push_back(key);
  };
  auto take_entity_array = [&](const std::string& name, std::size_t ncomp, std::size_t ntuples,
                               const std::vector<double>& v) {
    if(!data_on_cells || ncomp != 1 || ntuples != offsets.size() - (offsets.empty() ? 0 : 1)) return;
    const int priority = name == "CellEntityIds" ? 4 : name == "gmsh:geometrical" ? 3
                       : name == "gmsh:physical" ? 2 : name == "medit:ref" ? 1 : 0;
    if(priority <= entity_priority) return;
    entity_priority = priority;
    cell_entity.assign(v.size(), 0);
    for(std::size_t i = 0; i < v.size(); ++i) {
      // (found by scripts/fuzz: an id of 1e30 does not convert to an integer)
      if(!(std::abs(v[i]) <= 2147483647.0) || v[i] != std::floor(v[i]))
        rd.fail(name + ": value " + std::to_string(v[i]) + " of cell " + std::to_string(i) + " is not an integer id");
      cell_entity[i] = (long long)v[i];
    }
  };

  while(!rd.at_end()) {
    const std::string key = rd.word("a section keyword");
    if(key == "POINTS" || key == "CELLS" || key == "CELL_TYPES") once(key);
    if(key == "POINTS") {
      const std::size_t n = rd.count("POINTS");
      const std::string type = rd.word("the POINTS type");
      const std::vector<double> xyz = rd.values(3 * n, type, "POINTS");
      soup.points.reserve(n);
      for(std::size_t i = 0; i < n; ++i) soup.points.push_back(Point(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
      have_points = true;
    } else if(key == "CELLS") {
      const std::size_t a = rd.count("CELLS");
      const std::size_t b = rd.count("CELLS size");
      have_cells = true;
      const std::size_t line = rd.line();
      // version 5.x: "CELLS n_offsets n_connectivity" then OFFSETS and CONNECTIVITY arrays
      if(rd.next_line_starts_with("OFFSETS")) {
        rd.word("OFFSETS");
        const std::string type = rd.word("the OFFSETS type");
        offsets = rd.integers(a, type, "OFFSETS");
        if(rd.word("CONNECTIVITY") != "CONNECTIVITY") rd.fail("expected CONNECTIVITY after OFFSETS");
        const std::string ctype = rd.word("the CONNECTIVITY type");
        connectivity = rd.integers(b, ctype, "CONNECTIVITY");
        if(offsets.empty()) offsets.push_back(0);
        if(offsets.front() != 0) rd.fail("OFFSETS must start at 0");
        for(std::size_t i = 1; i < offsets.size(); ++i)
          if(offsets[i] < offsets[i - 1]) rd.fail("OFFSETS must not decrease (cell " + std::to_string(i - 1) + ")");
        if(std::size_t(offsets.back()) != connectivity.size())
          rd.fail("the last offset (" + std::to_string(offsets.back()) + ") differs from the CONNECTIVITY size (" +
                  std::to_string(connectivity.size()) + ")");
      } else {
        // classic layout: for each cell, its vertex count then its vertices (int in binary files)
        std::vector<std::size_t> lines;
        const std::vector<long long> stream = rd.integers(b, "int", "CELLS", &lines);
        offsets.assign(1, 0);
        cell_lines.clear();
        std::size_t k = 0;
        for(std::size_t i = 0; i < a; ++i) {
          if(k >= stream.size())
            rd.fail("CELLS: the size " + std::to_string(b) + " is too small for " + std::to_string(a) + " cells");
          cell_lines.push_back(lines[k]);
          const long long c = stream[k++];
          if(c < 0 || std::size_t(c) > stream.size() - k)
            rd.fail("cell " + std::to_string(i) + " has an invalid vertex count " + std::to_string(c));
          connectivity.insert(connectivity.end(), stream.begin() + std::ptrdiff_t(k),
                              stream.begin() + std::ptrdiff_t(k + std::size_t(c)));
          k += std::size_t(c);
          offsets.push_back((long long)connectivity.size());
        }
        if(k != stream.size()) rd.fail("CELLS: the size " + std::to_string(b) + " does not match the cells");
      }
      if(cell_lines.size() != offsets.size() - 1) cell_lines.assign(offsets.size() - 1, line);
    } else if(key == "CELL_TYPES") {
      const std::size_t n = rd.count("CELL_TYPES");
      const std::size_t ncells = offsets.empty() ? 0 : offsets.size() - 1;
      if(n != ncells)
        rd.fail("CELL_TYPES count " + std::to_string(n) + " differs from CELLS count " + std::to_string(ncells));
      cell_types = rd.integers(n, "int", "CELL_TYPES");
    } else if(key == "CELL_DATA" || key == "POINT_DATA") {
      data_on_cells = key == "CELL_DATA";
      data_count = rd.count(key.c_str());
      in_data = true;
      const std::size_t ncells = offsets.empty() ? 0 : offsets.size() - 1;
      if(data_on_cells && data_count != ncells) rd.fail("CELL_DATA count differs from CELLS count");
    } else if(in_data && key == "SCALARS") {
      const std::string name = rd.word("the array name");
      const std::string type = rd.word("the array type");
      std::string third = rd.word("LOOKUP_TABLE"); // the component count is optional in the format
      long long ncomp = 1;
      if(third != "LOOKUP_TABLE") {
        ncomp = std::atoll(third.c_str());
        if(ncomp < 1 || ncomp > 4) rd.fail("invalid component count '" + third + "'");
        third = rd.word("LOOKUP_TABLE");
      }
      if(third != "LOOKUP_TABLE") rd.fail("expected LOOKUP_TABLE, found '" + third + "'");
      rd.word("the lookup table name");
      const std::vector<double> v = rd.values(data_count * std::size_t(ncomp), type, "a data array");
      take_entity_array(name, std::size_t(ncomp), data_count, v);
    } else if(in_data && key == "LOOKUP_TABLE") {
      rd.word("the lookup table name");
      const std::size_t n = rd.count("LOOKUP_TABLE");
      rd.values(4 * n, rd.binary ? "unsigned_char" : "float", "LOOKUP_TABLE");
    } else if(in_data && key == "COLOR_SCALARS") {
      rd.word("the array name");
      const std::size_t n = rd.count("COLOR_SCALARS");
      rd.values(n * data_count, rd.binary ? "unsigned_char" : "float", "COLOR_SCALARS");
    } else if(in_data && (key == "VECTORS" || key == "NORMALS" || key == "TENSORS" || key == "TENSORS6")) {
      rd.word("the array name");
      const std::string type = rd.word("the array type");
      const std::size_t per = key == "TENSORS" ? 9 : key == "TENSORS6" ? 6 : 3;
      rd.values(per * data_count, type, "a data array");
    } else if(in_data && key == "TEXTURE_COORDINATES") {
      rd.word("the array name");
      const std::size_t dim = rd.count("TEXTURE_COORDINATES");
      const std::string type = rd.word("the array type");
      rd.values(dim * data_count, type, "a data array");
    } else if(key == "FIELD") {
      rd.word("the field name");
      const std::size_t arrays = rd.count("FIELD");
      for(std::size_t a = 0; a < arrays; ++a) {
        std::string name = rd.word("the array name");
        while(name == "METADATA") { rd.skip_metadata(); name = rd.word("the array name"); }
        const std::size_t ncomp = rd.count("FIELD array");
        const std::size_t ntuples = rd.count("FIELD array");
        const std::string type = rd.word("the array type");
        if(ncomp != 0 && ntuples > std::size_t(-1) / ncomp) rd.fail("FIELD array too large");
        const std::vector<double> v = rd.values(ncomp * ntuples, type, "FIELD array");
        if(in_data) take_entity_array(name, ncomp, ntuples, v);
      }
    } else if(key == "METADATA") {
      rd.skip_metadata();
    } else {
      rd.fail("unknown section keyword '" + key + "'");
    }
  }
  if(!have_points) rd.fail("no POINTS section");
  const std::size_t ncells = offsets.empty() ? 0 : offsets.size() - 1;
  if(have_cells && cell_types.size() != ncells) rd.fail("missing CELL_TYPES section");

  std::map<std::string, std::size_t> other_volume_cells;
  for(std::size_t i = 0; i < ncells; ++i) {
    const long long* c = connectivity.data() + offsets[i];
    const std::size_t k = std::size_t(offsets[i + 1] - offsets[i]);
    const int type = int(cell_types[i]);
    const int id = cell_entity.empty() ? 0 : int(cell_entity[i]);
    auto need = [&](std::size_t m, bool exact) {
      if(exact ? k != m : k < m)
        throw Input_error(source, cell_lines[i], "cell " + std::to_string(i) + " of type " + std::to_string(type) +
                          " has " + std::to_string(k) + " vertices instead of " + (exact ? "" : "at least ") +
                          std::to_string(m));
    };
    for(std::size_t j = 0; j < k; ++j)
      if(c[j] < 0 || std::size_t(c[j]) >= soup.points.size())
        throw Input_error(source, cell_lines[i], "cell " + std::to_string(i) + ": vertex index " + std::to_string(c[j]) +
                          " out of range (the file has " + std::to_string(soup.points.size()) + " points)");
    auto v = [&](std::size_t j) { return std::size_t(c[j]); };
    switch(type) {
      case 10: case 24: case 71: case 78:
        need(type == 10 ? 4 : type == 24 ? 10 : 4, type == 10 || type == 24);
        soup.tetrahedra.push_back({v(0), v(1), v(2), v(3)});
        soup.tetrahedron_lines.push_back(cell_lines[i]);
        break;
      case 5: case 22: case 69:
        need(type == 5 ? 3 : type == 22 ? 6 : 3, type != 69);
        soup.triangles.push_back({v(0), v(1), v(2)});
        soup.triangle_patches.push_back(id);
        break;
      case 3: case 21: case 68:
        need(type == 3 ? 2 : type == 21 ? 3 : 2, type != 68);
        soup.feature_edges.push_back({v(0), v(1)});
        soup.feature_edge_curves.push_back(id);
        break;
      case 1: need(1, true); soup.corners.push_back(v(0)); break;
      default:
        if(const char* name = internal_vtk::non_tetrahedral_volume_cell(type)) ++other_volume_cells[name];
        break; // other cells (quads, polygons, ...) are not part of a tetrahedral mesh
    }
  }
  if(!other_volume_cells.empty()) {
    std::string list;
    for(const auto& kv : other_volume_cells)
      list += (list.empty() ? "" : ", ") + std::to_string(kv.second) + " " + kv.first + " cell(s)";
    throw Input_error(source, 0, "the mesh has volume cells other than tetrahedra (" + list + ", with " +
                      std::to_string(soup.tetrahedra.size()) + " tetrahedra); they would be lost and the domain "
                      "would shrink: split them into tetrahedra (e.g. ParaView's Tetrahedralize filter) and retry");
  }
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_READ_VTK_H
