// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_INTEGER_GRID_MAP_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_INTEGER_GRID_MAP_H

#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

/// \ingroup PkgHexahedralRemeshingRef
/// Writes an integer-grid map as a VTK legacy ASCII unstructured grid of "exploded" tetrahedra
/// (cell type 10): every tetrahedron gets its own 4 points (point `4 t + i` is corner `i` of
/// tetrahedron `t`), so the per-tetrahedron parameters, which jump across the faces with a
/// transition, are stored without averaging. Arrays: point data `uvw` (the parameters of each corner
/// in its tetrahedron's chart, in hex edges) and cell data `parameter_volume` (the signed volume of the
/// tetrahedron in parameter space: negative for an inverted tetrahedron, 0 for a degenerate one),
/// followed by the caller's per-tetrahedron `cell_arrays`. In ParaView, a Contour filter on a
/// component of `uvw` at integer values (or a color map with discrete bands) shows the grid lines.
/// The file is written atomically (`write_file_atomically()`).
/// \throws Error if `map.parameters` does not have one entry per tetrahedron, a vertex index is out of
///         range, an array has a wrong size, or the file cannot be written (nothing is left behind).
inline void write_VTK_integer_grid_map(const std::string& filename, const Integer_grid_map& map,
                                       const std::vector<VTK_array>& cell_arrays = {})
{
  const std::size_t n = map.tetrahedra.size();
  if(map.parameters.size() != n)
    throw Error(filename + ": the map has " + std::to_string(map.parameters.size()) + " parameter sets for " +
                std::to_string(n) + " tetrahedra");
  for(std::size_t t = 0; t < n; ++t)
    for(auto v : map.tetrahedra[t])
      if(v >= map.points.size())
        throw Error(filename + ": tetrahedron " + std::to_string(t) + " has vertex index " + std::to_string(v) +
                    " out of range");

  std::vector<VTK_array> cells;
  VTK_array volume;
  volume.name = "parameter_volume";
  volume.values.resize(n);
  for(std::size_t t = 0; t < n; ++t) {
    const auto& u = map.parameters[t];
    Eigen::Matrix3d J;
    J << u[1] - u[0], u[2] - u[0], u[3] - u[0];
    volume.values[t] = J.determinant() / 6.;
  }
  cells.push_back(std::move(volume));
  cells.insert(cells.end(), cell_arrays.begin(), cell_arrays.end());
  std::vector<VTK_array> points(1);
  points[0].name = "uvw";
  points[0].components = 3;
  points[0].values.reserve(12 * n);
  for(const auto& u : map.parameters)
    for(int i = 0; i < 4; ++i)
      for(int d = 0; d < 3; ++d)
        points[0].values.push_back(u[i][d]);

  write_file_atomically(filename, [&](std::ostream& out) {
    out << "# vtk DataFile Version 2.0\nHexahedral_remeshing integer-grid map (exploded tetrahedra)\nASCII\n"
           "DATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << 4 * n << " double\n";
    for(const auto& tet : map.tetrahedra)
      for(int i = 0; i < 4; ++i) {
        const auto& p = map.points[tet[i]];
        out << p.x() << " " << p.y() << " " << p.z() << "\n";
      }
    out << "CELLS " << n << " " << 5 * n << "\n";
    for(std::size_t t = 0; t < n; ++t)
      out << "4 " << 4 * t << " " << 4 * t + 1 << " " << 4 * t + 2 << " " << 4 * t + 3 << "\n";
    out << "CELL_TYPES " << n << "\n";
    for(std::size_t t = 0; t < n; ++t)
      out << "10\n";
    internal_vtk_writer::write_arrays(out, "CELL_DATA", n, cells, filename);
    internal_vtk_writer::write_arrays(out, "POINT_DATA", 4 * n, points, filename);
  });
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_INTEGER_GRID_MAP_H
