// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_ABAQUS_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_ABAQUS_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/grouped_mesh.h>

#include <algorithm>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_abaqus {

// Data lines of at most 16 entries (the limit of Abaqus and CalculiX).
inline void write_id_lines(std::ostream& out, const std::vector<std::size_t>& ids)
{
  for(std::size_t i = 0; i < ids.size(); ++i)
    out << ids[i] << ((i + 1) % 16 == 0 || i + 1 == ids.size() ? "\n" : ", ");
}

} // namespace internal_abaqus

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `hexes` as an Abaqus / CalculiX input file (`.inp`): `*NODE` (node `v + 1` is vertex `v`),
/// `*ELEMENT, TYPE=C3D8, ELSET=PART` (element `h + 1` is hexahedron `h`; VTK order is C3D8's node
/// order: a positively oriented hexahedron has a positive volume there), and for every surface
/// patch of `hexes.boundary_quadrilaterals` an `*NSET` of its nodes and an element-face based
/// `*SURFACE, TYPE=ELEMENT` (lines `element, S1..S6`), both named after the patch (its name in
/// `patch_names`, made an identifier, else `patch_<id>`; patches of one name form one group); then an `*NSET` `curve_<id>` per feature
/// curve of `hexes.feature_edges`. A mesh without boundary groups is grouped by its own sharp edges
/// (`compute_hexahedral_boundary_groups()` on a copy). The file is written atomically.
/// \throws Error if a hexahedron refers to a missing vertex or the file cannot be written.
inline void write_Abaqus(const std::string& filename, const Hexahedral_mesh_3& hexes)
{
  internal::check_hexahedra_in_range(filename, hexes);
  const internal::Grouped_mesh grouped(hexes);
  const Hexahedral_mesh_3& m = grouped.mesh();
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "** Hexahedral_remeshing: " << m.points.size() << " nodes, " << m.hexahedra.size() << " C3D8 elements, "
        << m.boundary_quadrilaterals.size() << " boundary faces\n*HEADING\nHexahedral mesh\n*NODE\n";
    for(std::size_t v = 0; v < m.points.size(); ++v)
      out << v + 1 << ", " << m.points[v].x() << ", " << m.points[v].y() << ", " << m.points[v].z() << "\n";
    out << "*ELEMENT, TYPE=C3D8, ELSET=PART\n";
    for(std::size_t h = 0; h < m.hexahedra.size(); ++h) {
      out << h + 1;
      for(int i = 0; i < 8; ++i) out << ", " << m.hexahedra[h][i] + 1;
      out << "\n";
    }
    for(const auto& group : grouped.quads_by_name()) {
      const std::string& name = group.first;
      std::set<std::size_t> nodes;
      for(std::size_t i : group.second)
        for(auto v : m.boundary_quadrilaterals[i].vertices) nodes.insert(std::size_t(v) + 1);
      out << "*NSET, NSET=" << name << "\n";
      internal_abaqus::write_id_lines(out, std::vector<std::size_t>(nodes.begin(), nodes.end()));
      out << "*SURFACE, NAME=" << name << ", TYPE=ELEMENT\n";
      for(std::size_t i : group.second)
        out << m.boundary_quadrilaterals[i].hexahedron + 1 << ", S" << int(m.boundary_quadrilaterals[i].face) + 1 << "\n";
    }
    for(const auto& group : grouped.edges_by_curve()) {
      std::set<std::size_t> nodes;
      for(std::size_t i : group.second)
        for(auto v : m.feature_edges[i].vertices) nodes.insert(std::size_t(v) + 1);
      out << "*NSET, NSET=" << grouped.curve_name(group.first) << "\n";
      internal_abaqus::write_id_lines(out, std::vector<std::size_t>(nodes.begin(), nodes.end()));
    }
  });
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_ABAQUS_H
