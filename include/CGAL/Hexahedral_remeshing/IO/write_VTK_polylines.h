// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_POLYLINES_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_POLYLINES_H

#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

/// \ingroup PkgHexahedralRemeshingRef
/// Writes polylines as a VTK legacy ASCII polygonal data set (`DATASET POLYDATA` with `LINES`),
/// readable by ParaView, with optional per-polyline (cell) and per-point data arrays.
/// \param filename the output file (written atomically)
/// \param points the positions of the points
/// \param polylines each polyline as a sequence of indices into `points`, at least two (a closed
///        polyline repeats its first index at the end)
/// \param cell_arrays arrays with one value or vector per polyline
/// \param point_arrays arrays with one value or vector per point
/// \throws Error if the file cannot be written, an index is out of range, a polyline has fewer than
///         two points or an array has a wrong size; nothing is written then.
inline void write_VTK_polylines(const std::string& filename, const std::vector<std::array<double, 3> >& points,
                                const std::vector<std::vector<std::size_t> >& polylines,
                                const std::vector<VTK_array>& cell_arrays = {},
                                const std::vector<VTK_array>& point_arrays = {})
{
  std::size_t size = 0;
  for(const auto& line : polylines) {
    if(line.size() < 2) throw Error(filename + ": a polyline needs at least two points");
    for(std::size_t i : line)
      if(i >= points.size()) throw Error(filename + ": polyline point index " + std::to_string(i) + " out of range");
    size += line.size() + 1;
  }
  auto check = [&](const std::vector<VTK_array>& arrays, std::size_t n) {
    for(const VTK_array& a : arrays)
      if((a.components != 1 && a.components != 3) || a.values.size() != n * std::size_t(a.components))
        throw Error(filename + ": data array '" + a.name + "' has a wrong size");
  };
  check(cell_arrays, polylines.size());
  check(point_arrays, points.size());
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "# vtk DataFile Version 2.0\nHexahedral_remeshing polylines\nASCII\nDATASET POLYDATA\n";
    out << "POINTS " << points.size() << " double\n";
    for(const auto& p : points) out << p[0] << " " << p[1] << " " << p[2] << "\n";
    out << "LINES " << polylines.size() << " " << size << "\n";
    for(const auto& line : polylines) {
      out << line.size();
      for(std::size_t i : line) out << " " << i;
      out << "\n";
    }
    // empty data sections confuse some readers: only written when there are elements
    if(!polylines.empty()) internal_vtk_writer::write_arrays(out, "CELL_DATA", polylines.size(), cell_arrays, filename);
    if(!points.empty()) internal_vtk_writer::write_arrays(out, "POINT_DATA", points.size(), point_arrays, filename);
  });
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_POLYLINES_H
