// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

/// \ingroup PkgHexahedralRemeshingRef
/// A named data array attached to the points or the cells of a VTK output: `components` is 1
/// (`SCALARS`) or 3 (`VECTORS`), `values` holds `components` doubles per element.
struct VTK_array
{
  /// Name of the array in the file (no whitespace).
  std::string name;
  /// Number of components per element: 1 (written as `SCALARS`) or 3 (`VECTORS`).
  int components = 1;
  /// The values, `components` consecutive doubles per element, in element order.
  std::vector<double> values;
};

/// \ingroup PkgHexahedralRemeshingRef
/// Writes a file atomically: `write(out)` writes the content to `filename.tmp`, which is renamed
/// to `filename` on success. On any failure (the file cannot be created, a write fails, the disk is
/// full, `write` throws) the temporary file is removed and `filename` is left as it was: a
/// failure never leaves a partial output file.
/// \throws Error if the file cannot be written; an exception thrown by `write` is propagated.
template <class Writer>
void write_file_atomically(const std::string& filename, const Writer& write)
{
  // A symbolic link is followed (the file it points to is replaced, the link kept); a device or a
  // FIFO (/dev/null, /dev/stdout, a pipe) cannot be replaced by a renamed file: it is written directly.
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target = fs::is_symlink(filename, ec) ? fs::weakly_canonical(filename, ec) : fs::path(filename);
  const fs::file_status status = fs::status(target, ec);
  if(fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status)) {
    std::ofstream out(target);
    if(!out) throw Error(filename + ": cannot open file for writing");
    out << std::setprecision(17);
    write(out);
    out.flush();
    if(!out) throw Error(filename + ": write error");
    return;
  }
  const std::string tmp = target.string() + ".tmp";
  {
    std::ofstream out(tmp);
    if(!out) throw Error(filename + ": cannot open file for writing");
    out << std::setprecision(17);
    try {
      write(out);
      out.flush();
    } catch(...) {
      out.close();
      std::remove(tmp.c_str());
      throw;
    }
    if(!out) { out.close(); std::remove(tmp.c_str()); throw Error(filename + ": write error"); }
    out.close();
    if(!out) { std::remove(tmp.c_str()); throw Error(filename + ": write error"); }
  }
  if(std::rename(tmp.c_str(), target.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error(filename + ": cannot rename the temporary output file");
  }
}

namespace internal_vtk_writer {
inline void write_arrays(std::ostream& out, const char* section, std::size_t n, const std::vector<VTK_array>& arrays,
                         const std::string& filename)
{
  if(arrays.empty()) return;
  out << section << " " << n << "\n";
  for(const VTK_array& a : arrays) {
    if((a.components != 1 && a.components != 3) || a.values.size() != n * std::size_t(a.components))
      throw Error(filename + ": data array '" + a.name + "' has a wrong size");
    if(a.components == 1) out << "SCALARS " << a.name << " double 1\nLOOKUP_TABLE default\n";
    else out << "VECTORS " << a.name << " double\n";
    for(std::size_t i = 0; i < n; ++i) {
      for(int c = 0; c < a.components; ++c) out << (c ? " " : "") << a.values[i * a.components + c];
      out << "\n";
    }
  }
}
} // namespace internal_vtk_writer

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `mesh` as a VTK legacy ASCII unstructured grid of tetrahedra (cell type 10), readable by
/// ParaView, with optional per-cell and per-point data arrays. Vertex `v` of the file is vertex
/// `v` of the mesh, so input vertices keep their indices.
/// \throws Error if the file cannot be written.
template <class Traits>
void write_VTK(const std::string& filename, const Tetrahedral_mesh_3<Traits>& mesh,
               const std::vector<VTK_array>& cell_arrays = {}, const std::vector<VTK_array>& point_arrays = {})
{
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "# vtk DataFile Version 2.0\nHexahedral_remeshing tetrahedral mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << mesh.number_of_vertices() << " double\n";
    for(const auto& p : mesh.points()) out << p.x() << " " << p.y() << " " << p.z() << "\n";
    const std::size_t nt = mesh.number_of_tetrahedra();
    out << "CELLS " << nt << " " << 5 * nt << "\n";
    for(std::size_t t = 0; t < nt; ++t) {
      const auto& v = mesh.tetrahedron_vertices(typename Tetrahedral_mesh_3<Traits>::Index(t));
      out << "4 " << v[0] << " " << v[1] << " " << v[2] << " " << v[3] << "\n";
    }
    out << "CELL_TYPES " << nt << "\n";
    for(std::size_t t = 0; t < nt; ++t) out << "10\n";
    internal_vtk_writer::write_arrays(out, "CELL_DATA", nt, cell_arrays, filename);
    internal_vtk_writer::write_arrays(out, "POINT_DATA", mesh.number_of_vertices(), point_arrays, filename);
  });
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTK_H
