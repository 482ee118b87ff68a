// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_GMSH_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_GMSH_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/internal/hexahedral_mesh/grouped_mesh.h>
#include <CGAL/Hexahedral_remeshing/internal/isolated_call.h>

#include <gmsh.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

namespace internal_gmsh_writer {

// The model of the file: one discrete volume with the hexahedra, one discrete surface per patch with
// its quads, one discrete curve per feature curve with its line elements, each in a physical group.
inline void build_model(const internal::Grouped_mesh& grouped)
{
  const Hexahedral_mesh_3& m = grouped.mesh();
  gmsh::model::add("hexahedral_mesh");
  const int volume = gmsh::model::addDiscreteEntity(3);
  std::vector<std::size_t> node_tags(m.points.size());
  std::vector<double> coords;
  coords.reserve(3 * m.points.size());
  for(std::size_t v = 0; v < m.points.size(); ++v) {
    node_tags[v] = v + 1;
    for(int d = 0; d < 3; ++d) coords.push_back(m.points[v][d]);
  }
  gmsh::model::mesh::addNodes(3, volume, node_tags, coords);
  std::vector<std::size_t> tags, nodes;
  for(std::size_t h = 0; h < m.hexahedra.size(); ++h) {
    tags.push_back(h + 1);
    for(auto v : m.hexahedra[h]) nodes.push_back(std::size_t(v) + 1);
  }
  gmsh::model::mesh::addElementsByType(volume, 5, tags, nodes);
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {volume}), "part");
  std::size_t next = m.hexahedra.size() + 1;
  std::map<std::string, std::vector<int> > surfaces_by_name;
  for(const auto& group : grouped.quads_by_patch()) {
    const int surface = gmsh::model::addDiscreteEntity(2);
    tags.clear(); nodes.clear();
    for(std::size_t i : group.second) {
      tags.push_back(next++);
      for(auto v : m.boundary_quadrilaterals[i].vertices) nodes.push_back(std::size_t(v) + 1);
    }
    gmsh::model::mesh::addElementsByType(surface, 3, tags, nodes);
    surfaces_by_name[grouped.patch_name(group.first)].push_back(surface);
  }
  for(const auto& named : surfaces_by_name)
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, named.second), named.first);
  for(const auto& group : grouped.edges_by_curve()) {
    const int curve = gmsh::model::addDiscreteEntity(1);
    tags.clear(); nodes.clear();
    for(std::size_t i : group.second) {
      tags.push_back(next++);
      for(auto v : m.feature_edges[i].vertices) nodes.push_back(std::size_t(v) + 1);
    }
    gmsh::model::mesh::addElementsByType(curve, 1, tags, nodes);
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {curve}), grouped.curve_name(group.first));
  }
}

} // namespace internal_gmsh_writer

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `hexes` as a gmsh mesh file, format 4.1 ASCII, through the gmsh library: the hexahedra
/// (element type 5, node `v + 1` is vertex `v`, element `h + 1` hexahedron `h`; VTK order is
/// gmsh's) in a volume entity with the physical group `part`; the boundary quadrilaterals (type 3)
/// in one surface entity per surface patch, in a physical group per patch name (as in
/// `write_Abaqus()`: patches of one name form one group); the feature edges (type 1) in one curve entity and physical group per
/// feature curve (`curve_<id>`). A mesh without boundary groups is grouped by its own sharp edges.
/// gmsh runs in a child process; the file is written to a temporary name and renamed.
/// \throws Error if a hexahedron refers to a missing vertex or the file cannot be written.
inline void write_gmsh(const std::string& filename, const Hexahedral_mesh_3& hexes)
{
  internal::check_hexahedra_in_range(filename, hexes);
  const internal::Grouped_mesh grouped(hexes);
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target = fs::is_symlink(filename, ec) ? fs::weakly_canonical(filename, ec) : fs::path(filename);
  // gmsh chooses the format from the extension: the temporary name keeps it
  const std::string tmp = target.string() + ".tmp.msh";
  try {
    internal::run_isolated([&]() {
      gmsh::initialize(0, nullptr, false);
      gmsh::option::setNumber("General.Terminal", 0);
      internal_gmsh_writer::build_model(grouped);
      gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
      gmsh::option::setNumber("Mesh.Binary", 0);
      gmsh::write(tmp);
      gmsh::finalize();
      return std::string();
    }, filename, "gmsh");
  } catch(const std::exception& e) {
    std::remove(tmp.c_str());
    throw Error(filename + ": cannot write the gmsh file: " + e.what());
  }
  if(!fs::exists(tmp, ec) || std::rename(tmp.c_str(), target.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw Error(filename + ": cannot write the gmsh file");
  }
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_GMSH_H
