// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_HEX_CELLS_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_HEX_CELLS_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/hex_vertices.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/map_topology.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/sanitize.h>
#include <CGAL/Hexahedral_remeshing/internal/extraction/transitions.h>

#include <algorithm>
#include <set>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {
namespace extraction {

struct Cell_assembly_report
{
  std::size_t incomplete_cells = 0;     // some corner not found, or two vertices for one corner
  std::size_t missing_corners = 0;      // corners not reached from the cell centre (untraced)
  std::size_t conflicting_corners = 0;  // corners reached as two different hex vertices
  std::size_t duplicate_cells = 0;      // the same 8 vertices found from two centres
  std::size_t inconsistent_walks = 0;   // a tetrahedron reached with two different transitions
  std::size_t truncated_walks = 0;      // walks stopped by the size limit
  std::size_t folded_cells = 0;         // cells next to inverted tetrahedra whose corners are inverted in space
};

// Hex cells from their centres. The cell of centre c (chart of tetrahedron o) is the open cube
// c + (-1/2, 1/2)^3; a walk from o across every face whose parameter bounding box (in o's chart)
// meets the open cube reaches all tetrahedra covering the cube, and carries the transitions so that
// each hex vertex on those tetrahedra is seen in o's chart. The corner c + d, d in {-1/2, 1/2}^3, is
// the hex vertex found at that point. Singular curves lie on integer lines, i.e. on cell edges, so
// the open cube contains none and the walk's transitions do not depend on the path (checked).
// A cell is emitted only with 8 distinct corners, in VTK order of o's chart (positive orientation).
inline void assemble_hex_cells(const Integer_grid_map& map, const Map_topology& topo, const Sanitized_map& sm,
                               const Face_transitions& tr, const Lattice_points& lp,
                               std::vector<std::array<std::uint32_t, 8> >& hexes, std::vector<std::uint32_t>& sources,
                               Cell_assembly_report& report, bool keep_folded = false)
{
  const std::size_t nt = map.tetrahedra.size();
  const auto& S = sm.parameters;
  std::vector<std::uint32_t> stamp(nt, no_tetrahedron);
  std::vector<Rigid_transform> to_centre(nt);
  std::vector<std::uint32_t> queue;
  std::set<std::array<std::uint32_t, 8> > seen;
  // Tetrahedra within two vertex rings of an inverted one: a fold reaches that far around it, and a
  // cell walk that meets none of them sees a locally injective map.
  std::vector<char> inverted(nt, 0);
  for(std::size_t t = 0; t < nt; ++t) inverted[t] = parameter_orientation(S[t]) == CGAL::NEGATIVE;
  for(int ring = 0; ring < 2; ++ring) {
    std::vector<char> vertex_near(map.points.size(), 0);
    for(std::size_t t = 0; t < nt; ++t)
      if(inverted[t])
        for(int k = 0; k < 4; ++k) vertex_near[map.tetrahedra[t][k]] = 1;
    for(std::size_t t = 0; t < nt; ++t)
      for(int k = 0; k < 4; ++k)
        if(vertex_near[map.tetrahedra[t][k]]) inverted[t] = 1;
  }
  const auto& positions = lp.positions;
  static const int vtk_corner[8] = {0, 1, 3, 2, 4, 5, 7, 6}; // VTK vertex i -> corner bits (x | y << 1 | z << 2)
  const std::size_t max_walk = 100000;

  for(std::size_t ci = 0; ci < lp.centres.size(); ++ci) {
    const Chart_point& centre = lp.centres[ci];
    const Eigen::Vector3d& c = centre.x;
    const std::uint32_t mark = std::uint32_t(ci);
    std::array<std::uint32_t, 8> corner;
    corner.fill(no_tetrahedron);
    bool conflict = false, near_inverted = false;
    queue.assign(1, centre.tetrahedron);
    stamp[centre.tetrahedron] = mark;
    to_centre[centre.tetrahedron] = Rigid_transform();
    for(std::size_t q = 0; q < queue.size(); ++q) {
      const std::uint32_t t = queue[q];
      const Rigid_transform M = to_centre[t];
      near_inverted = near_inverted || inverted[t];
      for(std::uint32_t i = lp.per_tetrahedron_begin[t]; i < lp.per_tetrahedron_begin[t + 1]; ++i) {
        const Eigen::Vector3d d = apply(M, lp.copies[i].x) - c;
        if(std::abs(d[0]) != 0.5 || std::abs(d[1]) != 0.5 || std::abs(d[2]) != 0.5) continue;
        const int bits = (d[0] > 0 ? 1 : 0) | (d[1] > 0 ? 2 : 0) | (d[2] > 0 ? 4 : 0);
        if(corner[bits] == no_tetrahedron) corner[bits] = lp.copies[i].id;
        else if(corner[bits] != lp.copies[i].id) conflict = true;
      }
      if(queue.size() >= max_walk) { ++report.truncated_walks; break; }
      for(int f = 0; f < 4; ++f) {
        const std::uint32_t n = topo.neighbor[t][f];
        if(n == no_tetrahedron) continue;
        // does the face meet the open cube? (bounding box test in the centre's chart: conservative)
        bool meets = true;
        Eigen::Vector3d lo, hi;
        for(int k = 0; k < 3; ++k) {
          const Eigen::Vector3d x = apply(M, S[t][face_vertices[f][k]]);
          if(k == 0) { lo = hi = x; } else { lo = lo.cwiseMin(x); hi = hi.cwiseMax(x); }
        }
        for(int a = 0; a < 3 && meets; ++a) meets = lo[a] < c[a] + 0.5 && hi[a] > c[a] - 0.5;
        if(!meets) continue;
        const Rigid_transform Mn = compose(M, tr.to_this[t][f]);
        if(stamp[n] != mark) {
          stamp[n] = mark;
          to_centre[n] = Mn;
          queue.push_back(n);
        } else if(to_centre[n] != Mn) {
          ++report.inconsistent_walks;
        }
      }
    }
    std::size_t missing = 0;
    for(int b = 0; b < 8; ++b) missing += corner[b] == no_tetrahedron;
    std::array<std::uint32_t, 8> sorted = corner;
    std::sort(sorted.begin(), sorted.end());
    const bool distinct = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    if(missing > 0 || conflict || !distinct) {
      ++report.incomplete_cells;
      report.missing_corners += missing;
      report.conflicting_corners += conflict ? 1 : 0;
      continue;
    }
    std::array<std::uint32_t, 8> hex;
    for(int i = 0; i < 8; ++i) hex[i] = corner[vtk_corner[i]];
    // Where the map folds, a lattice point is covered more than once and spurious copies of hex
    // vertices appear (HexEx cancels them with its anti-darts). A cell met by inverted tetrahedra is
    // kept only if every corner is positively oriented in space (exact), so no folded cell is emitted,
    // unless the caller untangles afterwards (`keep_folded`): a folded cell left out is a hole in the
    // mesh, one kept is an inverted hexahedron that the untangling repairs (the shipped cylinder at
    // 583 hexahedra: 11 cells left out made slits reaching 0.24 of the diagonal into the solid; kept,
    // the smoothed mesh is valid, min scaled Jacobian 0.83).
    if(near_inverted) {
      static const int nb[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7}, {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
      bool ok = true;
      for(int i = 0; i < 8 && ok; ++i)
        ok = CGAL::orientation(positions[hex[i]], positions[hex[nb[i][0]]], positions[hex[nb[i][1]]],
                               positions[hex[nb[i][2]]]) == CGAL::POSITIVE;
      if(!ok) {
        ++report.folded_cells;
        if(!keep_folded) continue;
      }
    }
    if(!seen.insert(sorted).second) { ++report.duplicate_cells; continue; }
    hexes.push_back(hex);
    sources.push_back(centre.tetrahedron);
  }
}

} // namespace extraction
} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_EXTRACTION_HEX_CELLS_H
