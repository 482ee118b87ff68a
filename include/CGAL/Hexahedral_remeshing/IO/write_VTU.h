// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTU_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTU_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_mesh_validation.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/grouped_mesh.h>

#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_vtu {

template <class Values>
void write_data_array(std::ostream& out, const char* type, const std::string& name, int components, const Values& values)
{
  out << "<DataArray type=\"" << type << "\"";
  if(!name.empty()) out << " Name=\"" << name << "\"";
  if(components != 1) out << " NumberOfComponents=\"" << components << "\"";
  out << " format=\"ascii\">\n";
  std::size_t k = 0;
  for(const auto& v : values) out << v << (++k % 12 == 0 ? "\n" : " ");
  out << "\n</DataArray>\n";
}

} // namespace internal_vtu

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `hexes` as a VTK XML unstructured grid (`.vtu`, ASCII; ParaView's own format): the
/// hexahedra (cell type 12, cells `0..H-1` are the hexahedra `0..H-1`), then the boundary
/// quadrilaterals (cell type 9, outward, in the order of `hexes.boundary_quadrilaterals`). Cell
/// arrays: `dimension` (3 for a hexahedron, 2 for a quad), `patch` (the surface patch of a quad, -1
/// on hexahedra), `scaled_jacobian` (of the hexahedron, for a quad the one of its hexahedron),
/// `source_tetrahedron` (when `hexahedron_source_tetrahedra` is filled, -1 unknown and on quads);
/// point array `tags` (when `vertex_tags` is filled). A mesh without boundary groups is grouped by
/// its own sharp edges. The file is written atomically.
/// \throws Error if a hexahedron refers to a missing vertex or the file cannot be written.
inline void write_VTU(const std::string& filename, const Hexahedral_mesh_3& hexes)
{
  internal::check_hexahedra_in_range(filename, hexes);
  const internal::Grouped_mesh grouped(hexes);
  const Hexahedral_mesh_3& m = grouped.mesh();
  const std::size_t H = m.hexahedra.size(), Q = m.boundary_quadrilaterals.size();
  const std::vector<double> sj = hexahedra_scaled_jacobians(m);
  std::vector<double> coords, jacobians(sj);
  std::vector<long long> connectivity, offsets, dimension(H, 3), patch(H, -1), source;
  std::vector<int> types(H, 12);
  for(const auto& p : m.points)
    for(int d = 0; d < 3; ++d) coords.push_back(p[d]);
  for(const auto& h : m.hexahedra) {
    connectivity.insert(connectivity.end(), h.begin(), h.end());
    offsets.push_back((long long)connectivity.size());
  }
  for(const auto& q : m.boundary_quadrilaterals) {
    connectivity.insert(connectivity.end(), q.vertices.begin(), q.vertices.end());
    offsets.push_back((long long)connectivity.size());
    types.push_back(9);
    dimension.push_back(2);
    patch.push_back(q.patch);
    jacobians.push_back(sj[q.hexahedron]);
  }
  const bool has_source = m.hexahedron_source_tetrahedra.size() == H && H > 0;
  if(has_source) {
    for(auto t : m.hexahedron_source_tetrahedra)
      source.push_back(t == (std::numeric_limits<Hexahedral_mesh_3::Index>::max)() ? -1 : (long long)t);
    source.resize(H + Q, -1);
  }
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << m.points.size()
        << "\" NumberOfCells=\"" << H + Q << "\">\n";
    if(m.vertex_tags.size() == m.points.size() && !m.points.empty()) {
      out << "<PointData>\n";
      std::vector<int> tags(m.vertex_tags.begin(), m.vertex_tags.end());
      internal_vtu::write_data_array(out, "Int32", "tags", 1, tags);
      out << "</PointData>\n";
    }
    out << "<CellData Scalars=\"scaled_jacobian\">\n";
    internal_vtu::write_data_array(out, "Float64", "scaled_jacobian", 1, jacobians);
    internal_vtu::write_data_array(out, "Int32", "dimension", 1, dimension);
    internal_vtu::write_data_array(out, "Int32", "patch", 1, patch);
    if(has_source) internal_vtu::write_data_array(out, "Int64", "source_tetrahedron", 1, source);
    out << "</CellData>\n<Points>\n";
    internal_vtu::write_data_array(out, "Float64", "", 3, coords);
    out << "</Points>\n<Cells>\n";
    internal_vtu::write_data_array(out, "Int64", "connectivity", 1, connectivity);
    internal_vtu::write_data_array(out, "Int64", "offsets", 1, offsets);
    internal_vtu::write_data_array(out, "UInt8", "types", 1, types);
    out << "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  });
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_VTU_H
