// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_HEXEX_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_HEXEX_H

#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/Integer_grid_map.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <cstdio>
#include <string>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `map` in libHexEx's `.hexex` text format (see `read_HexEx()`): vertex count, positions,
/// tetrahedron count, then per tetrahedron its 4 vertex ids and the 12 parameters of its corners.
/// Numbers are printed with `%.17g`, so `read_HexEx()` gives back the same doubles bit for bit.
/// The transitions are not written (the format keeps them implicit). The file is written atomically
/// (`write_file_atomically()`): on failure no partial file is left.
/// \throws Error if the file cannot be written or `map` is inconsistent (sizes of `tetrahedra` and
///         `parameters` differ).
inline void write_HexEx(const std::string& file, const Integer_grid_map& map)
{
  if(map.tetrahedra.size() != map.parameters.size())
    throw Error(file + ": integer-grid map with " + std::to_string(map.tetrahedra.size()) + " tetrahedra but " +
                std::to_string(map.parameters.size()) + " parameter sets");
  write_file_atomically(file, [&](std::ostream& out) {
    char buf[40];
    auto num = [&](double d) {
      std::snprintf(buf, sizeof(buf), "%.17g", d);
      out << buf;
    };
    out << map.points.size() << "\n";
    for(const auto& p : map.points) {
      num(p.x()); out << ' '; num(p.y()); out << ' '; num(p.z()); out << '\n';
    }
    out << map.tetrahedra.size() << "\n";
    for(std::size_t t = 0; t < map.tetrahedra.size(); ++t) {
      const auto& tet = map.tetrahedra[t];
      out << tet[0] << ' ' << tet[1] << ' ' << tet[2] << ' ' << tet[3];
      for(int k = 0; k < 4; ++k)
        for(int c = 0; c < 3; ++c) { out << ' '; num(map.parameters[t][k][c]); }
      out << '\n';
    }
  });
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_HEXEX_H
